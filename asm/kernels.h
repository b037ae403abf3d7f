// asm/kernels.h: SIMD kernels beside their scalar references, and the dispatch that picks
// one variant per kernel once, at the first call of active() (CPU detection on x86-64 with
// __builtin_cpu_supports; NEON is chosen at compile time where the target has it; on aarch64
// Linux the core's MIDR picks neon_a53's block builder on in-order cores).
//
//   kernel          contract               variants (when built and the CPU has them)
//   surface_span    asm/surface_span.h     scalar, sse2, avx2, avx2g (gathers), fast (portable; the neon table)
//   surface_block   asm/surface_block.h    scalar, sse2 and avx2 (asm/surface_block_x86.h), avx2g
//                                          (gathers), neon (aarch64 and armv7 assembly row loops),
//                                          neon_a53 (aarch64: mips 0-1 loop for in-order cores)
//   z_span          asm/z_span.h           scalar, sse2, avx2, neon
//   expand_palette  asm/palette_expand.h   scalar, sse2, avx2 (gathers), neon
//   alias_span      asm/alias_span.h       scalar, sse2, neon (avx2 tables: the sse2 one)
//   surface_span_persp asm/span_persp.h    scalar (reference), fast (portable; every other table)
//   surface_spans_persp asm/span_persp.h   the same per batch: scalar (a loop over the reference),
//                                          fast (every other table; aarch64 pairs short spans)
//   lit_span        asm/lit_span.h         scalar, fast, avx2 (gathers), avx2s (own dispatch: lit_span_active())
// The tuned mix (asm/dispatch.cpp) on x86-64: scalar span (the vector ones did not speed
// up whole frames), avx2 (else sse2) builder and z, sse2 palette and alias span; on ARM:
// neon. Everywhere the fast whole-span drawer: the engine draws lit surfaces through
// surface_spans_persp (one call per batch of a surface's spans), whose scalar reference is
// the per-run walker over surface_span (so force_scalar still means "the references
// everywhere").
//
// Every variant of a kernel writes exactly the bytes its scalar reference writes
// (tests/asm checks it on random and edge inputs).
//
// The engine calls through active(); force_scalar(true) makes active() the scalar table
// (a host console variable can call it so benchmarks compare). The tables are plain data,
// valid for the program's lifetime; nothing here allocates or includes an OS header.
#pragma once
#include "asm/alias_span.h"
#include "asm/lit_span.h"
#include "asm/palette_expand.h"
#include "asm/span_persp.h"
#include "asm/surface_block.h"
#include "asm/surface_span.h"
#include "asm/z_span.h"

namespace sb::simd {

struct Kernels {
  const char* name;  // "scalar", "sse2", "avx2", "neon", or "tuned" for the chosen mix
  SurfaceSpanFn surface_span;
  SurfaceBlockFn surface_block;
  ZSpanFn z_span;
  ExpandPaletteFn expand_palette;
  AliasSpanFn alias_span;
  SurfaceSpanPerspFn surface_span_persp;  // a whole span, the divide inside (asm/span_persp.h)
  SurfaceSpansPerspFn surface_spans_persp;  // a batch of them (one surface's spans)
};

// The table the engine uses: the tuned mix for this CPU, or the scalar one when forced.
const Kernels& active();
const Kernels& scalar_kernels();

// Force the scalar references (true) or return to the tuned choice (false). The program
// starts forced when the environment variable STARBOW_SCALAR is set (and not "0").
void force_scalar(bool on);
bool scalar_forced();

// Benchmarks only: make active() return *k until called again with nullptr (then the tuned
// or forced-scalar choice as before). bench/span_hist.cpp installs a table whose
// surface_spans_persp records every span it is given, then draws it with the tuned one.
void override_active(const Kernels* k);

// Every variant table compiled into this build, scalar first, then the tuned mix
// ("tuned", always supported), for tests and benchmarks. supported = the CPU can run it.
struct Variant {
  const Kernels* kernels;
  bool supported;
};
int variant_count();
Variant variant(int i);

// One line naming the chosen variant of each kernel (logs, benchmark headers).
const char* describe_active();

}  // namespace sb::simd
