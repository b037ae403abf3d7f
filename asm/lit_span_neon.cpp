// asm/lit_span_neon.cpp: the "neon" variant of the single-pass lit span kernel (contract:
// asm/lit_span.h). Built with NEON (aarch64, and armv7 with STARBOW_ARM_NEON); elsewhere an
// empty stub says it is not compiled.
//
// 8 pixels a step. NEON lanes step u and v (second order) and compute each pixel's grid
// index gi = (V >> log B) * grid_width + (U >> log B), its texel index ti = t * tex_width + s
// (the wrap by a mask, or by the exact reciprocal multiply of the "fast" variant), and fx, fy.
// They are packed two words a pixel (gi | fy << 24, ti | fx << 24: gi and ti stay below 2^24
// under the contract, fx and fy below 16) and stored interleaved, so one 64-bit core load
// brings a pixel's four values. The light is then the "fast" variant's packed-pair blend on
// grid_wide, the texel and colormap loads are core loads, and the 8 bytes go out as one
// 64-bit store.
#include "asm/lit_span.h"

#include <cstring>

#if defined(SB_SIMD_HAVE_NEON)
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "SB_SIMD_HAVE_NEON is set but this file is not compiled for NEON"
#endif
#include <arm_neon.h>

#include "asm/lit_span_a64.h"
#include "asm/lit_span_a64win.h"

namespace sb::simd {
namespace {

// c mod size for c < 2^13 by the exact reciprocal recip = ceil(2^32 / size) (see
// lit_span.cpp): its low word in recip, and one (all-ones) in one when size is 1 (recip 2^32).
inline uint32x4_t wrap_recip(uint32x4_t c, uint32x2_t recip, uint32x4_t one, uint32x4_t size) {
  const uint32x4_t q = vcombine_u32(vshrn_n_u64(vmull_u32(vget_low_u32(c), recip), 32),
                                    vshrn_n_u64(vmull_u32(vget_high_u32(c), recip), 32));
  return vmlsq_u32(c, vaddq_u32(q, vandq_u32(c, one)), size);
}

// The per-pixel light (the "fast" variant's packed-pair blend on grid_wide, whatever the
// cells): for steps that cross cells within a group of 8 (mips above 0 at about a texel a
// pixel), where the one-cell path would fall back per lane. NEON lanes for the indices and
// weights, packed two words a pixel (gi | fy << 24, ti | fx << 24).
template <int kMip, bool kPow2>
void lit_span_neon_pp_t(uint8_t* __restrict dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                     uint32_t dv, uint32_t ddu, uint32_t ddv) {
  constexpr int kLog = 4 - kMip;
  constexpr int kShift = 2 * kLog;
  constexpr uint32_t kB = 1u << kLog;
  static constexpr uint32_t kLane[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static constexpr uint32_t kTri[8] = {0, 0, 1, 3, 6, 10, 15, 21};      // k (k - 1) / 2
  static constexpr uint32_t kInc[8] = {28, 36, 44, 52, 60, 68, 76, 84};  // 8 k + 28
  // Lanes 0..3 ([0]) and 4..7 ([1]) of u_k, v_k and their steps to pixel k + 8
  // (u_{k+8} - u_k = 8 du + (8 k + 28) ddu, which grows by 64 ddu a step).
  uint32x4_t uu[2], vv[2], iu[2], iv[2];
#pragma GCC unroll 2
  for (int h = 0; h < 2; ++h) {
    const uint32x4_t lane = vld1q_u32(kLane + 4 * h), tri = vld1q_u32(kTri + 4 * h), inc = vld1q_u32(kInc + 4 * h);
    uu[h] = vmlaq_n_u32(vmlaq_n_u32(vdupq_n_u32(u), lane, du), tri, ddu);
    vv[h] = vmlaq_n_u32(vmlaq_n_u32(vdupq_n_u32(v), lane, dv), tri, ddv);
    iu[h] = vmlaq_n_u32(vdupq_n_u32(8 * du), inc, ddu);
    iv[h] = vmlaq_n_u32(vdupq_n_u32(8 * dv), inc, ddv);
  }
  const uint32x4_t iiu = vdupq_n_u32(64 * ddu), iiv = vdupq_n_u32(64 * ddv);
  const uint32x4_t frac = vdupq_n_u32(kB - 1), gw = vdupq_n_u32(uint32_t(src.grid_width));
  const uint32x4_t so = vdupq_n_u32(src.soff_mod), to = vdupq_n_u32(src.toff_mod);
  const uint32x4_t tw = vdupq_n_u32(uint32_t(src.tex_width)), th = vdupq_n_u32(uint32_t(src.tex_height));
  const uint32x4_t smask = vsubq_u32(tw, vdupq_n_u32(1)), tmask = vsubq_u32(th, vdupq_n_u32(1));
  (void)smask;  // used by the power-of-two wrap only
  (void)tmask;
  const uint32x2_t srec = vdup_n_u32(uint32_t(src.s_recip)), trec = vdup_n_u32(uint32_t(src.t_recip));
  const uint32x4_t sone = vdupq_n_u32(src.s_recip >> 32 ? ~0u : 0u), tone = vdupq_n_u32(src.t_recip >> 32 ? ~0u : 0u);
  (void)srec;  // used by the other wrap only
  (void)trec;
  (void)sone;
  (void)tone;
  const uint32_t* __restrict grid = src.grid_wide;
  const uint32_t* __restrict grid1 = grid + src.grid_width;  // row gy + 1
  const uint8_t* __restrict texels = src.texels;
  const uint8_t* __restrict cm = src.colormap;
  alignas(16) uint64_t rec[8];  // per pixel: gi | fy << 24, ti | fx << 24
  for (int k = 0; k < n; k += 8) {
#pragma GCC unroll 2
    for (int h = 0; h < 2; ++h) {
      const uint32x4_t U = vshrq_n_u32(uu[h], 16), V = vshrq_n_u32(vv[h], 16);
      const uint32x4_t gi = vmlaq_u32(vshrq_n_u32(U, kLog), vshrq_n_u32(V, kLog), gw);
      uint32x4_t s = vaddq_u32(U, so), t = vaddq_u32(V, to);
      if constexpr (kPow2) {
        s = vandq_u32(s, smask);
        t = vandq_u32(t, tmask);
      } else {
        s = wrap_recip(s, srec, sone, tw);
        t = wrap_recip(t, trec, tone, th);
      }
      uint32x4x2_t p;
      p.val[0] = vsliq_n_u32(gi, vandq_u32(V, frac), 24);
      p.val[1] = vsliq_n_u32(vmlaq_u32(s, t, tw), vandq_u32(U, frac), 24);
      vst2q_u32(reinterpret_cast<uint32_t*>(rec + 4 * h), p);
      uu[h] = vaddq_u32(uu[h], iu[h]);
      vv[h] = vaddq_u32(vv[h], iv[h]);
      iu[h] = vaddq_u32(iu[h], iiu);
      iv[h] = vaddq_u32(iv[h], iiv);
    }
    // Lanes past n hold indices outside the contract: never dereferenced.
    const int m = n - k < 8 ? n - k : 8;
    uint64_t out = 0;
    auto pixel = [&](int j) {
      const uint64_t r = rec[j];
      const uint32_t gi = uint32_t(r) & 0xffffffu, fy = uint32_t(r) >> 24;
      const uint32_t ti = uint32_t(r >> 32) & 0xffffffu, fx = uint32_t(r >> 56);
      uint64_t p0, p1;
      std::memcpy(&p0, grid + gi, 8);
      std::memcpy(&p1, grid1 + gi, 8);
      // The "fast" variant's blend: both grid columns vertically at once, then horizontally
      // by one multiply with fx | (B - fx) << 32 (asm/lit_span.cpp, Weights).
      const uint64_t pv = (p0 << kLog) + (p1 - p0) * fy;
      const uint32_t num = uint32_t((pv * (uint64_t(fx) | uint64_t(kB - fx) << 32)) >> 32);
      return cm[((num >> kShift) & 0xff00u) + texels[ti]];
    };
    if (m == 8) {
#pragma GCC unroll 8
      for (int j = 0; j < 8; ++j) out |= uint64_t(pixel(j)) << (8 * j);
      std::memcpy(dest + k, &out, 8);
    } else {
      for (int j = 0; j < m; ++j) dest[k + j] = pixel(j);
    }
  }
}

// The high halves of a's and b's lanes (u >> 16 of 16.16 values below 2^28) as 8 lanes.
inline uint16x8_t high_halves(uint32x4_t a, uint32x4_t b) {
#if defined(__aarch64__)
  return vuzp2q_u16(vreinterpretq_u16_u32(a), vreinterpretq_u16_u32(b));
#else
  return vuzpq_u16(vreinterpretq_u16_u32(a), vreinterpretq_u16_u32(b)).val[1];
#endif
}

// True when every lane of m is all ones.
inline bool all_ones(uint16x8_t m) {
#if defined(__aarch64__)
  return vminvq_u16(m) == 0xffffu;
#else
  const uint16x4_t x = vand_u16(vget_low_u16(m), vget_high_u16(m));
  return vget_lane_u64(vreinterpret_u64_u16(x), 0) == ~uint64_t(0);
#endif
}

inline int32x4_t mlal_high_lane0(int32x4_t acc, int16x8_t a, int16x4_t c) {
#if defined(__aarch64__)
  return vmlal_high_lane_s16(acc, a, c, 0);
#else
  return vmlal_lane_s16(acc, vget_high_s16(a), c, 0);
#endif
}
inline int32x4_t mlal_high_lane1(int32x4_t acc, int16x8_t a, int16x4_t c) {
#if defined(__aarch64__)
  return vmlal_high_lane_s16(acc, a, c, 1);
#else
  return vmlal_lane_s16(acc, vget_high_s16(a), c, 1);
#endif
}
inline int32x4_t mlal_high_lane2(int32x4_t acc, int16x8_t a, int16x4_t c) {
#if defined(__aarch64__)
  return vmlal_high_lane_s16(acc, a, c, 2);
#else
  return vmlal_lane_s16(acc, vget_high_s16(a), c, 2);
#endif
}

// Lane j of kTail + 8 - m is all ones for j >= m: the lanes past the run, which the
// one-cell test ignores.
alignas(16) constexpr uint16_t kTail[16] = {0, 0, 0, 0, 0, 0, 0, 0,
                                             0xffff, 0xffff, 0xffff, 0xffff, 0xffff, 0xffff, 0xffff, 0xffff};

template <int kMip, bool kPow2>
void lit_span_neon_t(uint8_t* __restrict dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                     uint32_t dv, uint32_t ddu, uint32_t ddv) {
  constexpr int kLog = 4 - kMip;
  constexpr int kShift = 2 * kLog;
  constexpr uint32_t kB = 1u << kLog;
  static constexpr uint32_t kLane[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static constexpr uint32_t kTri[8] = {0, 0, 1, 3, 6, 10, 15, 21};      // k (k - 1) / 2
  static constexpr uint32_t kInc[8] = {28, 36, 44, 52, 60, 68, 76, 84};  // 8 k + 28
  // Lanes 0..3 ([0]) and 4..7 ([1]) of u_k, v_k and their steps to pixel k + 8
  // (u_{k+8} - u_k = 8 du + (8 k + 28) ddu, which grows by 64 ddu a step).
  uint32x4_t uu[2], vv[2], iu[2], iv[2];
#pragma GCC unroll 2
  for (int h = 0; h < 2; ++h) {
    const uint32x4_t lane = vld1q_u32(kLane + 4 * h), tri = vld1q_u32(kTri + 4 * h), inc = vld1q_u32(kInc + 4 * h);
    uu[h] = vmlaq_n_u32(vmlaq_n_u32(vdupq_n_u32(u), lane, du), tri, ddu);
    vv[h] = vmlaq_n_u32(vmlaq_n_u32(vdupq_n_u32(v), lane, dv), tri, ddv);
    iu[h] = vmlaq_n_u32(vdupq_n_u32(8 * du), inc, ddu);
    iv[h] = vmlaq_n_u32(vdupq_n_u32(8 * dv), inc, ddv);
  }
  const uint32x4_t iiu = vdupq_n_u32(64 * ddu), iiv = vdupq_n_u32(64 * ddv);
  // Lane 0 (u, v) in core registers, stepped like the lanes.
  uint32_t u8 = 8 * du + 28 * ddu, v8 = 8 * dv + 28 * ddv;
  const uint32_t u64 = 64 * ddu, v64 = 64 * ddv;
  const uint16x8_t frac = vdupq_n_u16(uint16_t(kB - 1));
  // U + soff_mod < 8192: the wrap's sums fit 16-bit lanes.
  const uint16x8_t so = vdupq_n_u16(uint16_t(src.soff_mod)), to = vdupq_n_u16(uint16_t(src.toff_mod));
  const uint16x8_t smask = vdupq_n_u16(uint16_t(src.tex_width - 1)), tmask = vdupq_n_u16(uint16_t(src.tex_height - 1));
  const uint16x4_t tw16 = vdup_n_u16(uint16_t(src.tex_width));
  const uint32x4_t so32 = vdupq_n_u32(src.soff_mod), to32 = vdupq_n_u32(src.toff_mod);
  const uint32x4_t tw = vdupq_n_u32(uint32_t(src.tex_width)), th = vdupq_n_u32(uint32_t(src.tex_height));
  const uint32x2_t srec = vdup_n_u32(uint32_t(src.s_recip)), trec = vdup_n_u32(uint32_t(src.t_recip));
  const uint32x4_t sone = vdupq_n_u32(src.s_recip >> 32 ? ~0u : 0u), tone = vdupq_n_u32(src.t_recip >> 32 ? ~0u : 0u);
  (void)smask, (void)tmask, (void)tw16, (void)so32, (void)to32, (void)tw, (void)th, (void)srec, (void)trec;
  (void)sone, (void)tone;
  const uint16_t* __restrict grid = src.grid;
  const int gw = src.grid_width;
  const uint8_t* __restrict texels = src.texels;
  const uint8_t* __restrict cm = src.colormap;
  alignas(16) uint32_t rec[16];  // per pixel: texel index, shade >> 8
  for (int k = 0; k < n; k += 8) {
    const int m = n - k < 8 ? n - k : 8;
    const uint16x8_t U = high_halves(uu[0], uu[1]), V = high_halves(vv[0], vv[1]);
    const uint16x8_t fx = vandq_u16(U, frac), fy = vandq_u16(V, frac);
    const uint16x8_t gx = vshrq_n_u16(U, kLog), gy = vshrq_n_u16(V, kLog);
    // Texel indices (32-bit: up to 4096 x 4096 texels).
    uint32x4_t ti_lo, ti_hi;
    if constexpr (kPow2) {
      const uint16x8_t s = vandq_u16(vaddq_u16(U, so), smask), t = vandq_u16(vaddq_u16(V, to), tmask);
      ti_lo = vmlal_u16(vmovl_u16(vget_low_u16(s)), vget_low_u16(t), tw16);
      ti_hi = vmlal_u16(vmovl_u16(vget_high_u16(s)), vget_high_u16(t), tw16);
    } else {
      const uint32x4_t s0 = wrap_recip(vaddq_u32(vshrq_n_u32(uu[0], 16), so32), srec, sone, tw);
      const uint32x4_t s1 = wrap_recip(vaddq_u32(vshrq_n_u32(uu[1], 16), so32), srec, sone, tw);
      const uint32x4_t t0 = wrap_recip(vaddq_u32(vshrq_n_u32(vv[0], 16), to32), trec, tone, th);
      const uint32x4_t t1 = wrap_recip(vaddq_u32(vshrq_n_u32(vv[1], 16), to32), trec, tone, th);
      ti_lo = vmlaq_u32(s0, t0, tw);
      ti_hi = vmlaq_u32(s1, t1, tw);
    }
#pragma GCC unroll 2
    for (int h = 0; h < 2; ++h) {
      uu[h] = vaddq_u32(uu[h], iu[h]);
      vv[h] = vaddq_u32(vv[h], iv[h]);
      iu[h] = vaddq_u32(iu[h], iiu);
      iv[h] = vaddq_u32(iv[h], iiv);
    }
    // Lane 0's cell (tracked in core registers: no lane move on the way to the loads) gives
    // every lane's light when the group lies in one cell; the test below patches the rest.
    // num = B^2 g00 + B fx (g10 - g00) + B fy (g01 - g00) + fx fy (g11 - g10 - g01 + g00)
    // for the cell (gx, gy), the three differences in 16-bit lanes (|.| <= 2 * 0x3fff),
    // widened by the multiply.
    auto one_cell = [&](uint32_t cgx, uint32_t cgy, int32x4_t& lo, int32x4_t& hi) {
      const int16x8_t bfx = vreinterpretq_s16_u16(vshlq_n_u16(fx, kLog));
      const int16x8_t bfy = vreinterpretq_s16_u16(vshlq_n_u16(fy, kLog));
      const int16x8_t fxy = vreinterpretq_s16_u16(vmulq_u16(fx, fy));
      const uint16_t* g = grid + size_t(cgy) * size_t(gw) + cgx;
      const int g00 = g[0], g10 = g[1], g01 = g[gw], g11 = g[gw + 1];
      const uint64_t packed = uint64_t(uint16_t(g10 - g00)) | uint64_t(uint16_t(g01 - g00)) << 16 |
                              uint64_t(uint16_t(g11 - g10 - g01 + g00)) << 32;
      const int16x4_t c = vreinterpret_s16_u64(vcreate_u64(packed));
      const int32x4_t c0 = vdupq_n_s32(g00 << kShift);
      lo = vmlal_lane_s16(vmlal_lane_s16(vmlal_lane_s16(c0, vget_low_s16(bfx), c, 0), vget_low_s16(bfy), c, 1),
                          vget_low_s16(fxy), c, 2);
      hi = mlal_high_lane2(mlal_high_lane1(mlal_high_lane0(c0, bfx, c), bfy, c), fxy, c);
    };
    // The reference's formula per pixel (lanes past the run left 0), into rec's light words.
    auto per_lane = [&]() {
      alignas(16) uint16_t us[8], vs[8];
      vst1q_u16(us, U);
      vst1q_u16(vs, V);
      for (int j = 0; j < m; ++j) {
        const int fxj = us[j] & int(kB - 1), fyj = vs[j] & int(kB - 1);
        const uint16_t* gj = grid + size_t(vs[j] >> kLog) * size_t(gw) + (us[j] >> kLog);
        const int num = (gj[0] * int(kB - fxj) + gj[1] * fxj) * int(kB - fyj) +
                        (gj[gw] * int(kB - fxj) + gj[gw + 1] * fxj) * fyj;
        rec[2 * j + 1] = uint32_t(num) >> (kShift + 8);
      }
    };
    auto store = [&](int32x4_t lo, int32x4_t hi) {
      uint32x4x2_t p;
      p.val[0] = ti_lo;
      p.val[1] = vshrq_n_u32(vreinterpretq_u32_s32(lo), kShift + 8);
      vst2q_u32(rec, p);
      p.val[0] = ti_hi;
      p.val[1] = vshrq_n_u32(vreinterpretq_u32_s32(hi), kShift + 8);
      vst2q_u32(rec + 8, p);
    };
    int32x4_t num_lo, num_hi;
#if defined(__aarch64__)
    // Lane 0's cell (tracked in core registers: no lane move on the way to the loads) gives
    // every lane's light when the group lies in one cell; the test below patches the rest.
    const uint32_t U0 = u >> 16, V0 = v >> 16;
    u += u8;
    v += v8;
    u8 += u64;
    v8 += v64;
    one_cell(U0 >> kLog, V0 >> kLog, num_lo, num_hi);
    store(num_lo, num_hi);
    // Every lane in lane 0's cell (lanes past the run ignored)? Otherwise the reference's
    // formula per pixel.
    uint16x8_t same = vandq_u16(vceqq_u16(gx, vdupq_n_u16(uint16_t(U0 >> kLog))),
                                vceqq_u16(gy, vdupq_n_u16(uint16_t(V0 >> kLog))));
    if (m < 8) same = vorrq_u16(same, vld1q_u16(kTail + 8 - m));
    if (__builtin_expect(!all_ones(same), 0)) per_lane();
#else
    // ARMv7 (fewer core registers: tracking lane 0 in them spills): lane moves, and the
    // light computed only for a group in one cell.
    (void)u8, (void)v8, (void)u64, (void)v64;
    const uint32_t gx0 = vgetq_lane_u16(gx, 0), gy0 = vgetq_lane_u16(gy, 0);
    uint16x8_t same = vandq_u16(vceqq_u16(gx, vdupq_n_u16(uint16_t(gx0))), vceqq_u16(gy, vdupq_n_u16(uint16_t(gy0))));
    if (m < 8) same = vorrq_u16(same, vld1q_u16(kTail + 8 - m));
    if (all_ones(same)) {
      one_cell(gx0, gy0, num_lo, num_hi);
      store(num_lo, num_hi);
    } else {
      store(vdupq_n_s32(0), vdupq_n_s32(0));
      per_lane();
    }
#endif
    // Lanes past n hold indices outside the contract: never dereferenced.
    auto pixel = [&](int j) {
      uint64_t r;
      std::memcpy(&r, rec + 2 * j, 8);
      const uint32_t t = texels[uint32_t(r)];
      // r >> 24 = (shade >> 8) << 8 | ti >> 24, and ti < 2^24.
      return cm[t + uint32_t(r >> 24)];
    };
    if (m == 8) {
      uint64_t out = 0;
#pragma GCC unroll 8
      for (int j = 0; j < 8; ++j) out |= uint64_t(pixel(j)) << (8 * j);
      std::memcpy(dest + k, &out, 8);
    } else {
      for (int j = 0; j < m; ++j) dest[k + j] = pixel(j);
    }
  }
}

// Out of line: compiled on its own it keeps its loop in registers (inlined into
// neon_general it spilled: lit16m2 A53 39.3 against 34.5 cycles a pixel).
template <bool kPow2>
__attribute__((noinline)) void neon_pp_by_mip(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du, uint32_t dv,
                    uint32_t ddu, uint32_t ddv) {
  switch (src.mip) {
    case 0: return lit_span_neon_pp_t<0, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 1: return lit_span_neon_pp_t<1, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 2: return lit_span_neon_pp_t<2, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    default: return lit_span_neon_pp_t<3, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}

// Whether a group of 8 pixels from here most likely stays within one cell or crosses one
// edge (the one-cell path and lit16_block's cells A / B hold it): it moves less than a cell,
// 8 (|du| + |dv| + 16 (|ddu| + |ddv|)) < B texels, with x ^ (x >> 31) for |x| (one less for
// negative x). A guess only: both check the cells. ARMv7: always (the per-pixel kernel's
// 64-bit blend is slow there: lit16m2 Cortex-A9 62 against 44 cycles a pixel).
inline bool few_cells(const LitSpanSource& src, uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
#if defined(__aarch64__)
  auto mag = [](uint32_t x) { return uint64_t(x ^ uint32_t(int32_t(x) >> 31)); };
  return mag(du) + mag(dv) + 16 * (mag(ddu) + mag(ddv)) < (uint64_t(0x20000) >> src.mip);
#else
  (void)src, (void)du, (void)dv, (void)ddu, (void)ddv;
  return true;
#endif
}

template <bool kPow2>
void neon_by_mip(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du, uint32_t dv,
                 uint32_t ddu, uint32_t ddv) {
  switch (src.mip) {
    case 0: return lit_span_neon_t<0, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 1: return lit_span_neon_t<1, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 2: return lit_span_neon_t<2, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    default: return lit_span_neon_t<3, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}

#if defined(__aarch64__) && defined(__GNUC__)
// The groups of a 16-pixel run that lit16_block flagged (bit 0: pixels 0-7, bit 1: 8-15),
// by the general path. Out of line: rare, and the block's caller stays small. The run's
// arguments come from the block's frame.
__attribute__((noinline)) void redo_groups(unsigned redo, const LitA64Frame& fr) {
  uint8_t* dest = fr.dest;
  const LitSpanSource& src = *fr.src;
  const uint32_t u = fr.args[0], v = fr.args[1], du = fr.args[2], dv = fr.args[3], ddu = fr.args[4], ddv = fr.args[5];
  if (redo & 1) neon_pp_by_mip<true>(dest, 8, src, u, v, du, dv, ddu, ddv);
  // u_{k+8} = u_k + 8 du_k + 28 ddu, du_{k+8} = du_k + 8 ddu.
  if (redo & 2)
    neon_pp_by_mip<true>(dest + 8, 8, src, u + 8 * du + 28 * ddu, v + 8 * dv + 28 * ddv, du + 8 * ddu, dv + 8 * ddv,
                         ddu, ddv);
}

void neon_rest(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du, uint32_t dv,
               uint32_t ddu, uint32_t ddv);

// One 16-pixel run (the engine's full runs) by lit16_block, flagged groups again by the
// general path. The run's arguments wait in the frame (stored before the block, read
// only for a redo), so no callee-saved register holds them across the block.
__attribute__((always_inline)) inline void run16_block(uint8_t* dest, const LitSpanSource& src, uint32_t u, uint32_t v,
                                                       uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  LitA64Frame fr;
  std::memcpy(fr.wrap, src.wrap16, sizeof fr.wrap);
  fr.dest = dest;
  fr.src = &src;
  fr.args[0] = u, fr.args[1] = v, fr.args[2] = du, fr.args[3] = dv, fr.args[4] = ddu, fr.args[5] = ddv;
  const unsigned redo = lit16_block(dest, src, fr, kLitA64Tab[src.mip & 3], u, v, du, dv, ddu, ddv);
  if (__builtin_expect(redo != 0, 0)) redo_groups(redo, fr);
}

// run16_block out of line, with lit_span_neon's arguments (n unused): reached by a bare
// branch with the arguments in place. noipa: GCC's clone without n needed them moved again.
__attribute__((noipa)) void run16_go(uint8_t* dest, int /*n*/, const LitSpanSource& src, uint32_t u, uint32_t v,
                                     uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  run16_block(dest, src, u, v, du, dv, ddu, ddv);
}

// The run win16_block flagged, by the per-pixel kernel (the run's arguments from the
// frame). Out of line: rare, and win16_go stays small.
__attribute__((noinline)) void redo_win(const LitA64Frame& fr) {
  neon_pp_by_mip<true>(fr.dest, 16, *fr.src, fr.args[0], fr.args[1], fr.args[2], fr.args[3], fr.args[4], fr.args[5]);
}

// A 16-pixel run that moves more than a cell a group, with a texture lit16_block takes:
// win16_block (asm/lit_span_a64win.h) when its groups likely span at most 3 cells a way
// (window_steps; else the per-pixel kernel), unless the surface is too small (fewer than 3
// cells a way: no window fits) or too large (cells beyond 255: the block's byte-wide
// ranges; both wrap16[7] = 0); a flagged run again by the per-pixel kernel. lit_span_neon's
// arguments (n unused), reached by a branch from run16. The run's arguments wait in the
// frame (read only for a redo), so nothing lives across the block.
__attribute__((noipa)) void win16_go(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v,
                                     uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  // wrap16[7]: (limx << 8 | limy) + 1, 0 where no window fits (lit_span_prepare).
  const uint32_t lim = src.wrap16[7];
  if (lim == 0 || !window_steps(src, du, dv, ddu, ddv))
    return neon_pp_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
  LitA64Frame fr;
  std::memcpy(fr.wrap, src.wrap16, sizeof fr.wrap);
  fr.dest = dest;
  fr.src = &src;
  fr.args[0] = u, fr.args[1] = v, fr.args[2] = du, fr.args[3] = dv, fr.args[4] = ddu, fr.args[5] = ddv;
  if (__builtin_expect(win16_block(dest, src, fr, kLitA64Tab[src.mip & 3], u, v, du, dv, ddu, ddv, (lim - 1) >> 8,
                                   (lim - 1) & 0xff) != 0,
                       0))
    redo_win(fr);
}

// The entry's 16-pixel runs: the block when the run moves less than a cell a group and the
// texture suits it (wrap16[5]: lit_span_prepare's "power-of-two texture of at most 2^16
// texels"), else the per-pixel kernel or neon_rest. Frameless: the tests and the branches
// only (with them in lit_span_neon, GCC held the arguments in other registers and saved
// x29 / x30: lit16 A53 21.23 against 20.3).
__attribute__((noipa)) void run16(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                                  uint32_t dv, uint32_t ddu, uint32_t ddv) {
  if (__builtin_expect(few_cells(src, du, dv, ddu, ddv), 1)) {
    if (__builtin_expect(src.wrap16[5] != 0, 1)) return run16_go(dest, n, src, u, v, du, dv, ddu, ddv);
    return neon_rest(dest, n, src, u, v, du, dv, ddu, ddv);
  }
  // Groups over at most 3 x 3 cells: the window block (win16_go tests it), else straight to
  // the per-pixel kernel (wrap16[6]: power-of-two texture).
  if (src.wrap16[5] != 0) return win16_go(dest, n, src, u, v, du, dv, ddu, ddv);
  if (src.wrap16[6] != 0) return neon_pp_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
  return neon_pp_by_mip<false>(dest, n, src, u, v, du, dv, ddu, ddv);
}

// Longer runs: 16 pixels at a time, the rest (n mod 16) by the general path.
__attribute__((noinline)) void runs16(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v,
                                      uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  for (; n >= 16; n -= 16, dest += 16) {
    if (few_cells(src, du, dv, ddu, ddv))
      run16_block(dest, src, u, v, du, dv, ddu, ddv);
    else
      neon_pp_by_mip<true>(dest, 16, src, u, v, du, dv, ddu, ddv);
    // u_{k+16} = u_k + 16 du_k + 120 ddu, du_{k+16} = du_k + 16 ddu.
    u += 16 * du + 120 * ddu;
    v += 16 * dv + 120 * ddv;
    du += 16 * ddu;
    dv += 16 * ddv;
  }
  if (n > 0) {
    if (few_cells(src, du, dv, ddu, ddv))
      neon_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
    else
      neon_pp_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}
#endif

inline bool is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

// Every case but aarch64's 16-pixel runs. Out of line: the entry stays small.
__attribute__((noinline)) void neon_general(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v,
                                            uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  const bool few = few_cells(src, du, dv, ddu, ddv);
  if (is_pow2(src.tex_width) && is_pow2(src.tex_height)) {
#if defined(__aarch64__) && defined(__GNUC__)
    // Power-of-two textures of at most 2^16 texels (lit16_block's 16-bit texel indices):
    // full 16-pixel runs by the asm block (asm/lit_span_a64.h).
    if (n > 16 && src.tex_width * src.tex_height <= 65536) return runs16(dest, n, src, u, v, du, dv, ddu, ddv);
#endif
    if (few) return neon_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
    return neon_pp_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
  if (few) return neon_by_mip<false>(dest, n, src, u, v, du, dv, ddu, ddv);
  neon_pp_by_mip<false>(dest, n, src, u, v, du, dv, ddu, ddv);
}

#if defined(__aarch64__) && defined(__GNUC__)
// aarch64: every run but the block's (a prepared source, n > 0): the per-pixel kernel for
// short runs that move more than a cell a group, else neon_general.
__attribute__((noinline)) void neon_rest(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v,
                                         uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  if (!few_cells(src, du, dv, ddu, ddv) && n <= 16) {  // wrap16[6]: power-of-two texture
    if (src.wrap16[6] != 0) return neon_pp_by_mip<true>(dest, n, src, u, v, du, dv, ddu, ddv);
    return neon_pp_by_mip<false>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
  neon_general(dest, n, src, u, v, du, dv, ddu, ddv);
}
#endif

}  // namespace

bool lit_span_neon_compiled() { return true; }

void lit_span_neon(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  if (!src.prepared) return lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
#if defined(__aarch64__) && defined(__GNUC__)
  // The engine's full runs: run16 tests the rest.
  if (n == 16)
    return run16(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
  neon_rest(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
#else
  neon_general(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
#endif
}

}  // namespace sb::simd

#else

namespace sb::simd {
bool lit_span_neon_compiled() { return false; }
void lit_span_neon(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
}
}  // namespace sb::simd

#endif
