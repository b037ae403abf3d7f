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

namespace sb::simd {
namespace {

// c mod size for c < 2^13 by the exact reciprocal recip = ceil(2^32 / size) (see
// lit_span.cpp): its low word in recip, and one (all-ones) in one when size is 1 (recip 2^32).
inline uint32x4_t wrap_recip(uint32x4_t c, uint32x2_t recip, uint32x4_t one, uint32x4_t size) {
  const uint32x4_t q = vcombine_u32(vshrn_n_u64(vmull_u32(vget_low_u32(c), recip), 32),
                                    vshrn_n_u64(vmull_u32(vget_high_u32(c), recip), 32));
  return vmlsq_u32(c, vaddq_u32(q, vandq_u32(c, one)), size);
}

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
  alignas(16) uint64_t rec[8];
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

inline bool is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

}  // namespace

bool lit_span_neon_compiled() { return true; }

void lit_span_neon(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  if (!src.prepared) return lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
  if (is_pow2(src.tex_width) && is_pow2(src.tex_height)) {
    neon_by_mip<true>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu),
                      uint32_t(ddv));
  } else {
    neon_by_mip<false>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu),
                       uint32_t(ddv));
  }
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
