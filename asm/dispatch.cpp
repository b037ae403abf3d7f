// asm/dispatch.cpp: choosing the variant of each kernel once, and the scalar override.
//
// The tuned table takes, per kernel, the variant that measured fastest on the machines we
// have (bench/asm_bench.cpp prints the figures) among those the CPU supports. x86-64: CPU detection with __builtin_cpu_supports (a compiler
// builtin: no OS header). ARM: NEON is a build-time property (aarch64 always; armv7 when
// the build enables it), so the choice is made by the compiler; on aarch64 Linux the core
// type (/proc/cpuinfo's CPU parts) picks the in-order block builder (neon_a53).
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "asm/variants.h"

namespace sb::simd {
namespace detail {

const Kernels kScalar = {"scalar", surface_span_scalar, surface_block_scalar, z_span_scalar, expand_palette_scalar,
                         alias_span_scalar, surface_span_persp_scalar, surface_spans_persp_scalar};

namespace {

// In-order Arm cores (the surface block builder's neon_a53 loop is for them): Cortex-A53
// (part 0xd03), A35 (0xd04), A55 (0xd05), A510 (0xd46), A520 (0xd80), implementer 0x41.
bool in_order_part(unsigned implementer, unsigned part) {
  return implementer == 0x41 && (part == 0xd03 || part == 0xd04 || part == 0xd05 || part == 0xd46 || part == 0xd80);
}

}  // namespace

// Every "CPU part" line must name an in-order core (with the "CPU implementer" line before
// it), so a big.LITTLE system keeps the out-of-order loop; no "CPU part" line (x86, an
// emulator that hides it): false. Lines longer than the buffer are read in pieces; a piece
// counts only at the start of a line.
bool cpuinfo_in_order(std::FILE* f) {
  char line[256];
  unsigned implementer = 0;
  int parts = 0;
  bool all = true, at_start = true;
  while (std::fgets(line, sizeof line, f)) {
    const bool start = at_start;
    at_start = std::strchr(line, '\n') != nullptr;
    const char* colon = std::strchr(line, ':');
    if (!start || !colon) continue;
    if (std::strncmp(line, "CPU implementer", 15) == 0) implementer = unsigned(std::strtoul(colon + 1, nullptr, 0));
    if (std::strncmp(line, "CPU part", 8) == 0) {
      ++parts;
      all = all && in_order_part(implementer, unsigned(std::strtoul(colon + 1, nullptr, 0)));
    }
  }
  return parts > 0 && all;
}

namespace {

#if defined(SB_SIMD_X86)
bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}
#endif

#if defined(SB_SIMD_NEON_INORDER)
// On Linux, /proc/cpuinfo read through cpuinfo_in_order (no OS header in asm/; MIDR_EL1
// would need getauxval's HWCAP_CPUID first). Unreadable: false.
bool cpu_in_order() {
#if defined(__linux__)
  std::FILE* f = std::fopen("/proc/cpuinfo", "r");
  if (!f) return false;
  const bool r = cpuinfo_in_order(f);
  std::fclose(f);
  return r;
#else
  return false;
#endif
}
#endif

struct Choice {
  Kernels tuned;
  char line[192];
};

Choice make_choice() {
  Choice c{kScalar, {}};
  c.tuned.name = "tuned";
  c.tuned.surface_span_persp = surface_span_persp_fast;  // portable C++: every target
  c.tuned.surface_spans_persp = surface_spans_persp_fast;
#if defined(SB_SIMD_X86)
  // The span kernel stays scalar: SSE2 loses to it on 16-pixel runs (its lane setup costs
  // more than it saves), and AVX2, 1.2x faster on full 16-pixel runs in asm_bench, made
  // whole frames (starbow_bench, lq_e1m1 1080p) no faster or slower: real spans are often
  // shorter than a run. Gathers (kAvx2Gather) measured slower than scalar loads on every
  // kernel on this Intel machine.
  c.tuned.surface_block = kSse2.surface_block;
  c.tuned.z_span = kSse2.z_span;
  c.tuned.expand_palette = kSse2.expand_palette;
  const char *span = "scalar", *block = "sse2", *z = "sse2", *pal = "sse2";
  c.tuned.alias_span = kSse2.alias_span;  // asm_bench: faster than scalar on every span length
  const char* alias = "sse2";
  if (cpu_has_avx2()) {
    c.tuned.surface_block = kAvx2.surface_block;
    c.tuned.z_span = kAvx2.z_span;
    block = z = "avx2";
  }
#elif defined(SB_SIMD_HAVE_NEON)
  // surface_span: the NEON table's surface_span_fast beats scalar on 16-pixel runs on
  // aarch64 (Cortex-A53 model 6.6 against 15.5 cycles/pixel, A72 3.6 against 5.3) and on
  // armhf (Cortex-A9 model 5.3 against 6.7; bench/counts.md).
  c.tuned.surface_span = kNeon.surface_span;
  const char* span = "fast";
  c.tuned.surface_block = kNeon.surface_block;
  c.tuned.z_span = kNeon.z_span;
  c.tuned.expand_palette = kNeon.expand_palette;
  const char *block = "neon", *z = "neon", *pal = "neon";
#if defined(SB_SIMD_NEON_INORDER)
  // In-order cores: the builder's row loops with a short NEON run (Cortex-A53 model 72
  // against 82 cycles per 32 texels at mips 0-1; the Cortex-A57 model prefers neon's, 62
  // against 68).
  if (cpu_in_order()) {
    c.tuned.surface_block = kNeonInOrder.surface_block;
    block = "neon_a53";
  }
#endif
  c.tuned.alias_span = kNeon.alias_span;
  const char* alias = "neon";
#else
  const char *span = "scalar", *block = "scalar", *z = "scalar", *pal = "scalar";
  const char* alias = "scalar";
#endif
  std::snprintf(c.line, sizeof c.line, "surface_span=%s surface_block=%s z_span=%s expand_palette=%s alias_span=%s "
                "surface_span_persp=fast surface_spans_persp=fast", span, block, z, pal, alias);
  return c;
}

const Choice& choice() {
  static const Choice c = make_choice();  // once, at first use
  return c;
}

// STARBOW_SCALAR=1 in the environment starts with the scalar references forced (for
// benchmarks of whole frames before the host has a console variable for it).
bool env_forces_scalar() {
  const char* e = std::getenv("STARBOW_SCALAR");
  return e && e[0] && !(e[0] == '0' && e[1] == 0);
}

std::atomic<bool> g_forced{env_forces_scalar()};
std::atomic<const Kernels*> g_override{nullptr};

}  // namespace
}  // namespace detail

const Kernels& active() {
  if (const Kernels* k = detail::g_override.load(std::memory_order_relaxed)) return *k;
  return detail::g_forced.load(std::memory_order_relaxed) ? detail::kScalar : detail::choice().tuned;
}

const Kernels& scalar_kernels() { return detail::kScalar; }

void force_scalar(bool on) { detail::g_forced.store(on, std::memory_order_relaxed); }
bool scalar_forced() { return detail::g_forced.load(std::memory_order_relaxed); }
void override_active(const Kernels* k) { detail::g_override.store(k, std::memory_order_relaxed); }

int variant_count() {
  int n = 2;  // scalar, tuned
#if defined(SB_SIMD_X86)
  n += 3;
#endif
#if defined(SB_SIMD_HAVE_NEON)
  n += 1;
#endif
#if defined(SB_SIMD_NEON_INORDER)
  n += 1;
#endif
  return n;
}

Variant variant(int i) {
  if (i == 0) return {&detail::kScalar, true};
#if defined(SB_SIMD_X86)
  if (i == 1) return {&detail::kSse2, true};
  if (i == 2) return {&detail::kAvx2, detail::cpu_has_avx2()};
  if (i == 3) return {&detail::kAvx2Gather, detail::cpu_has_avx2()};
  i -= 3;
#endif
#if defined(SB_SIMD_HAVE_NEON)
  if (i == 1) return {&detail::kNeon, true};
  i -= 1;
#endif
#if defined(SB_SIMD_NEON_INORDER)
  if (i == 1) return {&detail::kNeonInOrder, true};  // (any aarch64 core runs it)
  i -= 1;
#endif
  if (i == 1) return {&detail::choice().tuned, true};
  return {nullptr, false};
}

const char* describe_active() {
  return detail::g_forced.load(std::memory_order_relaxed) ? "all scalar (forced)" : detail::choice().line;
}

}  // namespace sb::simd
