// asm/lit_span.cpp: the single-pass lit span kernel (contract: asm/lit_span.h), its scalar
// reference, the tuned scalar variant and the kernel's dispatch.
//
// Kept apart from scalar.cpp / dispatch.cpp / kernels.h's table so that this kernel can be
// added, measured and removed on its own; it follows the same rules (variant chosen once,
// force_scalar() honoured, byte-identical variants checked in tests/asm).
#include "asm/lit_span.h"

#include <cstring>

#include "asm/kernels.h"

namespace sb::simd {

namespace {

inline int pos_mod(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

// ---------------------------------------------------------------- scalar reference

void lit_span_scalar(uint8_t* __restrict dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du,
                     int32_t dv, int32_t ddu, int32_t ddv) {
  // Written for clarity: the formula of the header, pixel by pixel. Unsigned arithmetic
  // for the stepping, so it wraps modulo 2^32 as the contract says.
  uint32_t uu = uint32_t(u), vv = uint32_t(v), duu = uint32_t(du), dvv = uint32_t(dv);
  const uint32_t dduu = uint32_t(ddu), ddvv = uint32_t(ddv);
  const int b = 16 >> src.mip, shift = 2 * (4 - src.mip);
  const int gw = src.grid_width;
  for (int k = 0; k < n; ++k) {
    const int U = int(uu >> 16), V = int(vv >> 16);
    const int gx = U / b, fx = U % b, gy = V / b, fy = V % b;
    const uint16_t* g = src.grid + gy * gw + gx;
    const int32_t g00 = g[0], g10 = g[1], g01 = g[gw], g11 = g[gw + 1];
    const int32_t num = (g00 * (b - fx) + g10 * fx) * (b - fy) + (g01 * (b - fx) + g11 * fx) * fy;
    const int shade = num >> shift;
    const int s = pos_mod(U + src.soff, src.tex_width), t = pos_mod(V + src.toff, src.tex_height);
    const uint8_t texel = src.texels[t * src.tex_width + s];
    dest[k] = src.colormap[(shade & 0xff00) + texel];
    uu += duu;
    vv += dvv;
    duu += dduu;
    dvv += ddvv;
  }
}

// ---------------------------------------------------------------- tuned scalar

namespace {

// The wrap of one axis without a divide: c = U + off_mod, so 0 <= c < 4096 + 4096. Power
// of two: a mask. Otherwise q = (c * recip) >> 32 with recip = ceil(2^32 / size) is
// floor(c / size) exactly, because c * size < 2^32 keeps the rounding error of recip below
// 1 / size (see the header's ranges).
template <bool kPow2>
inline uint32_t wrap_axis(uint32_t c, uint32_t size, uint32_t mask, uint64_t recip) {
  if constexpr (kPow2) {
    (void)size;
    (void)recip;
    return c & mask;
  } else {
    (void)mask;
    return c - size * uint32_t((uint64_t(c) * recip) >> 32);
  }
}

// Horizontal weights as one 64-bit word: fx in the low half, B - fx in the high half. For a
// packed pair p = a + b 2^32 (a, b < 2^22), (p * w) mod 2^64 >> 32 = a (B - fx) + b fx:
// the low product a fx < 2^26 never carries into bit 32 and b (B - fx) 2^64 drops out.
template <int kLog>
struct Weights {
  uint64_t w[16];
  constexpr Weights() : w() {
    for (int fx = 0; fx < (1 << kLog); ++fx) w[fx] = uint64_t(fx) | (uint64_t((1 << kLog) - fx) << 32);
  }
};

template <int kMip, bool kPow2>
void lit_span_fast_t(uint8_t* __restrict dest, int n, const LitSpanSource& src, uint32_t uu, uint32_t vv,
                     uint32_t duu, uint32_t dvv, uint32_t dduu, uint32_t ddvv) {
  constexpr int kLog = 4 - kMip;           // log2 B
  constexpr uint32_t kFrac = (1u << kLog) - 1;
  constexpr int kShift = 2 * kLog;
  static constexpr Weights<kLog> kW{};
  const uint32_t so = src.soff_mod, ssz = uint32_t(src.tex_width), sm = ssz - 1;
  const uint32_t to = src.toff_mod, tsz = uint32_t(src.tex_height), tm = tsz - 1;
  const uint64_t sr = src.s_recip, tr = src.t_recip;
  const uint8_t* __restrict texels = src.texels;
  const uint8_t* __restrict cm = src.colormap;
  const uint32_t* __restrict grid = src.grid_wide;
  const size_t gw = size_t(src.grid_width);
  const uint32_t tw = uint32_t(src.tex_width);
  for (int k = 0; k < n; ++k) {
    const uint32_t U = uu >> 16, V = vv >> 16;
    const uint32_t fx = U & kFrac, fy = V & kFrac;
    // Columns gx and gx + 1 of grid rows gy and gy + 1, each row's pair as one word.
    const uint32_t* g = grid + (V >> kLog) * gw + (U >> kLog);
    uint64_t p0, p1;
    std::memcpy(&p0, g, 8);
    std::memcpy(&p1, g + gw, 8);
    // Both columns blended vertically at once (exact: each half stays below 2^22), then
    // horizontally by one multiply: num = the reference's numerator.
    const uint64_t pv = (p0 << kLog) + (p1 - p0) * fy;
    const uint32_t num = uint32_t((pv * kW.w[fx]) >> 32);
    const uint32_t s = wrap_axis<kPow2>(U + so, ssz, sm, sr);
    const uint32_t t = wrap_axis<kPow2>(V + to, tsz, tm, tr);
    dest[k] = cm[((num >> kShift) & 0xff00u) + texels[t * tw + s]];
    uu += duu;
    vv += dvv;
    duu += dduu;
    dvv += ddvv;
  }
}

template <bool kPow2>
void lit_span_fast_mip(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                       uint32_t dv, uint32_t ddu, uint32_t ddv) {
  switch (src.mip) {
    case 0: return lit_span_fast_t<0, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 1: return lit_span_fast_t<1, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 2: return lit_span_fast_t<2, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    default: return lit_span_fast_t<3, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}

inline bool is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

}  // namespace

// On ARMv7 this is the tuned single-pass kernel and its eight loops (2.1 KB) sit in one 4 KiB page:
// qemu ends a translation block at a page end, so where the code before it grew by a few
// hundred bytes a loop was cut in two and timed worse (count row lit16m2 fast, A9 34.17 -> 34.70
// with the same instructions).
#if defined(__arm__) && !defined(__aarch64__)
__attribute__((aligned(4096)))
#endif
void lit_span_fast(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  if (!src.prepared) return lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
  if (is_pow2(src.tex_width) && is_pow2(src.tex_height)) {
    lit_span_fast_mip<true>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu),
                            uint32_t(ddv));
  } else {
    lit_span_fast_mip<false>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu),
                             uint32_t(ddv));
  }
}

void lit_span_prepare(LitSpanSource& src, int grid_count, uint32_t* wide) {
  for (int i = 0; i < grid_count; ++i) wide[i] = src.grid[i];
  src.grid_wide = wide;
  src.soff_mod = uint32_t(pos_mod(src.soff, src.tex_width));
  src.toff_mod = uint32_t(pos_mod(src.toff, src.tex_height));
  src.s_recip = ((uint64_t(1) << 32) + uint64_t(src.tex_width) - 1) / uint64_t(src.tex_width);
  src.t_recip = ((uint64_t(1) << 32) + uint64_t(src.tex_height) - 1) / uint64_t(src.tex_height);
  const uint32_t wrap[5] = {src.soff_mod, src.toff_mod, uint32_t(src.tex_width - 1), uint32_t(src.tex_height - 1),
                            uint32_t(src.tex_width)};
  for (int i = 0; i < 8; ++i) src.wrap16[i] = i < 5 ? uint16_t(wrap[i]) : 0;
  const bool pow2 = (src.tex_width & (src.tex_width - 1)) == 0 && (src.tex_height & (src.tex_height - 1)) == 0;
  src.wrap16[5] = pow2 && src.tex_width * src.tex_height <= 65536 ? 1 : 0;
  src.wrap16[6] = pow2 ? 1 : 0;
#if defined(__aarch64__)
  // asm/lit_span_a64win.h's window (aarch64 only): the origin's largest column / row
  // (limx, limy) = ((width - 1) / B - 2, (height - 1) / B - 2) as (limx << 8 | limy) + 1 when
  // both are in 0..253 (at least 3 cells a way, cells below 256), else 0.
  const int cx = (src.width - 1) >> (4 - src.mip), cy = (src.height - 1) >> (4 - src.mip);
  if (cx >= 2 && cx <= 255 && cy >= 2 && cy <= 255) src.wrap16[7] = uint16_t(((cx - 2) << 8 | (cy - 2)) + 1);
#endif
  src.prepared = true;
}

// ---------------------------------------------------------------- dispatch

namespace {

bool cpu_has_avx2() {
#if defined(__x86_64__)
  __builtin_cpu_init();  // a compiler builtin: no OS header
  return __builtin_cpu_supports("avx2") != 0;
#else
  return false;
#endif
}

struct Table {
  LitSpanVariant v[4];
  int count;
  int tuned;
};

// The tuned choice, made once: "avx2s" where the CPU has AVX2, "neon" on aarch64, else "fast". On this
// machine's Xeon (bench/lit_span_bench, ns per pixel in 16-pixel runs, 64x64 texture, mip 0):
// scalar 14.8, fast 4.8, avx2 (4 gathers per 8 pixels) 7.5, avx2s 3.6; the cached path's
// surface_span 1.9. The gather variant is listed for tests and benchmarks but not chosen.
const Table& table() {
  static const Table t = [] {
    Table r{{{"scalar", lit_span_scalar, true}, {"fast", lit_span_fast, true}, {}, {}}, 2, 1};
    if (lit_span_neon_compiled()) {
      r.v[r.count++] = {"neon", lit_span_neon, true};
#if defined(__aarch64__)
      // bench/counts.md lit16: neon 20.6 against fast 38.7 cycles/px (Cortex-A53 model),
      // 11.5 against 26.5 (A72); lit16m2 (mip 2): 33.5 against 38.7, 15.9 against 26.5.
      // On armv7, fast stays: lit16 34.3 against neon's 33.3 (Cortex-A9 model), lit16m2
      // 34.2 against 44.4; and neon's per-group lane moves to core registers (the one-cell
      // test, lane 0's cell) stall a real Cortex-A9 for many cycles, which llvm-mca does
      // not model.
      r.tuned = r.count - 1;
#endif
    }
    if (lit_span_avx2_compiled()) {
      r.v[r.count++] = {"avx2", lit_span_avx2, cpu_has_avx2()};
      r.v[r.count++] = {"avx2s", lit_span_avx2s, cpu_has_avx2()};
      if (r.v[r.count - 1].supported) r.tuned = r.count - 1;
    }
    return r;
  }();
  return t;
}

}  // namespace

LitSpanFn lit_span_active() { return scalar_forced() ? table().v[0].fn : table().v[table().tuned].fn; }

const char* lit_span_active_name() { return scalar_forced() ? table().v[0].name : table().v[table().tuned].name; }

int lit_span_variant_count() { return table().count; }

LitSpanVariant lit_span_variant(int i) {
  if (i < 0 || i >= lit_span_variant_count()) return {nullptr, nullptr, false};
  return table().v[i];
}

}  // namespace sb::simd
