// asm/lit_span.h: the single-pass lit span kernel (texture and light combined while drawing,
// no surface cache; issue 4), contract, scalar reference and its own dispatch.
//
// For k = 0 .. n-1, with the stepping of asm/surface_span.h (16.16, 32-bit wrap-around):
//   u_0 = u, du_0 = du, u_{k+1} = u_k + du_k, du_{k+1} = du_k + ddu      (likewise v)
//   U = u_k >> 16, V = v_k >> 16                      (surface texel of this mip)
//   dest[k] = colormap[(shade(U, V) & 0xff00) + tex(U, V)]
// where, with B = 16 >> mip and S = 2 * (4 - mip):
//   tex(U, V)   = texels[((V + toff) mod tex_height) * tex_width + (U + soff) mod tex_width]
//                 (positive modulo)
//   shade(U, V) = num >> S,
//   num         = (g00 (B - fx) + g10 fx) (B - fy) + (g01 (B - fx) + g11 fx) fy
//   gx = U / B, fx = U % B, gy = V / B, fy = V % B,
//   gAB = grid[(gy + B') * grid_width + gx + A']   (A', B' in {0, 1})
// That is engine/render/surface_math.h's shade_at() and texture_texel() at the texel the
// cached path's surface_span kernel would read, so for the same (u, v) the output equals the
// cached path's pixel byte for byte (asm/surface_block.h builds the same shade per texel).
//
// Contract (the caller guarantees; the engine's walker clamps u, v so it holds):
//   n >= 0, any length (the engine passes runs of at most 16);
//   mip in 0..3; 1 <= width, height <= 4096 (the surface: the face's extents >> mip);
//   for every k < n: 0 <= u_k < width << 16 and 0 <= v_k < height << 16;
//   grid: (height - 1) / B + 2 rows of grid_width >= (width - 1) / B + 2 entries, each
//   <= 0x3fff (a shade: colormap row 0..63 in the high byte);
//   tex_width, tex_height in 1..4096; soff, toff any value with |soff|, |toff| <= 2^20;
//   texels: tex_width * tex_height bytes; colormap: 64 rows of 256 bytes;
//   dest: n bytes, must not overlap the inputs; no alignment needed anywhere.
// Only the n destination bytes are written; nothing outside the inputs is read.
//
// Variants (lit_span.cpp, lit_span_avx2.cpp), all writing the reference's bytes (tests/asm):
//   scalar  the reference: plain modulo, the shade evaluated as written above;
//   fast    scalar code: power-of-two masks or an exact reciprocal multiply for the wrap
//           (constants prepared once per surface); the bilinear light on packed pairs, both
//           grid columns of a row in one 64-bit word (grid_wide), blended vertically at
//           once, then horizontally by one 64-bit multiply. The tuned choice on x86-64
//           without AVX2 and on armv7;
//   avx2    8 pixels per step, texel, light and colormap read by gathers;
//   avx2s   8 pixels' addresses and weights in AVX2 lanes, the loads and the blend scalar
//           (fast's packed pairs). The tuned choice on x86-64 with AVX2;
//   neon    NEON lanes (aarch64, armv7 with NEON) for the positions, texel indices and the
//           light of a group of 8 pixels lying in one grid cell (loaded once: num from the
//           cell's corner differences by widening multiply-adds), the reference's formula
//           per pixel for a group that does not; texel and colormap loads by the core. On
//           aarch64 a full 16-pixel run with a power-of-two texture of at most 2^16 texels
//           is one asm block (asm/lit_span_a64.h: two cells a group, the lane's chosen);
//           such runs that move more than a cell a group (mips above 0) another
//           (asm/lit_span_a64win.h: a 3 x 3-cell window a group, corners by tbl), and the
//           rest of those a per-pixel kernel (packed indices and weights a pixel, fast's
//           packed-pair blend). The tuned
//           choice on aarch64 (on armv7, fast: see lit_span.cpp).
// Dispatch: lit_span_active() is the scalar reference while simd::force_scalar() is on,
// otherwise the tuned choice, fixed at first use (bench/lit_span_bench measures them).
// Nothing here allocates.
#pragma once
#include <cstdint>

namespace sb::simd {

// What one surface's spans read. Filled once per surface; plain data, no ownership: every
// pointer must stay valid for the draw (the grid lives in the caller's frame arena).
struct LitSpanSource {
  const uint8_t* texels = nullptr;  // the mip's texels, row-major, stride = tex_width
  int tex_width = 0, tex_height = 0;
  int soff = 0, toff = 0;           // texture offset of surface texel (0, 0): texture_mins >> mip
  const uint16_t* grid = nullptr;   // the face's light grid (shades), row-major
  int grid_width = 0;
  int mip = 0;
  int width = 0, height = 0;        // surface size in texels of this mip (for checks only)
  const uint8_t* colormap = nullptr;

  // Derived, filled by lit_span_prepare() once per surface. The tuned variant needs them
  // (it falls back to the scalar reference while `prepared` is false); the reference ignores
  // them. grid_wide: the grid widened to 32-bit entries, same layout (two neighbours are
  // read as one 64-bit word).
  const uint32_t* grid_wide = nullptr;
  uint32_t soff_mod = 0, toff_mod = 0;  // soff mod tex_width, toff mod tex_height (positive)
  uint64_t s_recip = 0, t_recip = 0;    // ceil(2^32 / tex_width), ceil(2^32 / tex_height)
  // soff_mod, toff_mod, tex_width - 1, tex_height - 1, tex_width (16-bit; the aarch64 neon
  // variant's wrap of power-of-two textures), 1 for a power-of-two texture of at most 2^16
  // texels (else 0), 1 for a power-of-two texture (else 0), then on aarch64 the window
  // block's limits (lit_span_prepare; asm/lit_span_a64win.h), elsewhere a zero.
  uint16_t wrap16[8] = {};
  bool prepared = false;
};

using LitSpanFn = void (*)(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du,
                           int32_t dv, int32_t ddu, int32_t ddv);

// Scalar reference.
void lit_span_scalar(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                     int32_t ddu, int32_t ddv);
// Scalar, tuned: same bytes as the reference.
void lit_span_fast(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv);
// AVX2 with gathers (asm/lit_span_avx2.cpp; x86-64 only, call only where the CPU has AVX2:
// lit_span_variant() says). Same bytes as the reference.
void lit_span_avx2(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv);
// AVX2 lane arithmetic for addresses and weights, scalar loads (no gathers). Same rules.
void lit_span_avx2s(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                    int32_t ddu, int32_t ddv);
bool lit_span_avx2_compiled();
// NEON lane arithmetic for addresses and weights, core loads (asm/lit_span_neon.cpp; where
// NEON is compiled in). Same bytes as the reference.
void lit_span_neon(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv);
bool lit_span_neon_compiled();

// Fills src's derived fields from the others: wide (grid_count entries of caller memory, the
// frame arena in the engine; grid_count = the grid's rows x grid_width) gets the grid widened.
void lit_span_prepare(LitSpanSource& src, int grid_count, uint32_t* wide);

// The variant the engine uses (see above). Read it once per surface, not per span.
LitSpanFn lit_span_active();
const char* lit_span_active_name();

// Every variant compiled in, scalar first (tests and benchmarks). supported = CPU runs it.
struct LitSpanVariant {
  const char* name;
  LitSpanFn fn;
  bool supported;
};
int lit_span_variant_count();
LitSpanVariant lit_span_variant(int i);

}  // namespace sb::simd
