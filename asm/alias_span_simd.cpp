// asm/alias_span_simd.cpp: the vector variants of the alias-model span drawer
// (asm/alias_span.h): SSE2 on x86-64 (the baseline there), NEON on aarch64 and on armv7
// built with NEON (this file gets -mfpu=neon there, like asm/neon.cpp).
//
// Neither instruction set gathers, so both do the same split, 8 pixels per step:
//   vector: the 8 z values, the z test against the z buffer and the z buffer's new contents
//           (one load, one store), the 8 skin offsets (t >> 16) * width + (s >> 16) and the
//           8 colormap rows;
//   scalar: the skin and colormap loads and the byte stores of the visible pixels (all 8
//           unconditionally when all are visible; none at all when all are hidden).
// The last n % 8 pixels and spans shorter than 24 take a scalar loop that keeps s, t and
// light, z in two 64-bit registers (see alias_tail).
#include "asm/alias_span.h"
#include "asm/variants.h"

#if defined(__SSE2__) || defined(SB_SIMD_HAVE_NEON)

namespace sb::simd::detail {
namespace {

// Spans shorter than this take the scalar loop only (the vector setup costs more there).
constexpr int kAliasVectorMin = 24;

// The scalar loop from pixel k on (the state already advanced to pixel k), with two
// quantities in each 64-bit register: st = t * 2^32 + s and lz = l * 2^32 + z, stepped by
// dt * 2^32 + ds and dl * 2^32 + dz (the low steps sign-extended). Every s_k, z_k lies in
// 0 .. 2^32 - 1 and every t_k, l_k >= 0 (the contract), so these are the exact integers
// t_k 2^32 + s_k and l_k 2^32 + z_k: the low halves never borrow from or carry into the
// high ones wrongly. Two adds per pixel instead of four, and no register spills on x86-64.
inline void alias_tail(uint8_t* __restrict dest, uint16_t* __restrict zbuf, int k, int n,
                       const uint8_t* __restrict skin, uint32_t w, const uint8_t* __restrict colormap, uint32_t s,
                       uint32_t t, uint32_t l, uint32_t z, const AliasSpan& a) {
  uint64_t st = (uint64_t(t) << 32) + s, lz = (uint64_t(l) << 32) + z;
  const uint64_t dst = (uint64_t(uint32_t(a.dt)) << 32) + uint64_t(int64_t(a.ds));
  const uint64_t dlz = (uint64_t(uint32_t(a.dlight)) << 32) + uint64_t(int64_t(a.dzi));
  for (; k < n; ++k) {
    const uint16_t zz = uint16_t(lz >> 16);
    if (zz >= zbuf[k]) {
      const uint32_t off = uint32_t(st >> 48) * w + (uint32_t(st) >> 16);
      dest[k] = colormap[(uint32_t(lz >> 48) << 8) + skin[off]];
      zbuf[k] = zz;
    }
    st += dst;
    lz += dlz;
  }
}

// Texel fetch + colormap of 8 lanes whose skin offsets and row offsets (row * 256) are in
// off[0..7] and row[0..7]; stores lane j when bit j of `hidden` is clear.
inline void alias_store8(uint8_t* __restrict d, const uint8_t* __restrict skin, const uint8_t* __restrict colormap,
                         const uint32_t* off, const uint32_t* row, unsigned hidden) {
  if (hidden == 0) {
#pragma GCC unroll 8
    for (int j = 0; j < 8; ++j) d[j] = colormap[row[j] + skin[off[j]]];
    return;
  }
  for (int j = 0; j < 8; ++j)
    if (!((hidden >> j) & 1u)) d[j] = colormap[row[j] + skin[off[j]]];
}

}  // namespace
}  // namespace sb::simd::detail

#endif

// ---------------------------------------------------------------- SSE2

#if defined(__SSE2__)
#include <emmintrin.h>

namespace sb::simd::detail {

void alias_span_sse2(uint8_t* __restrict dest, uint16_t* __restrict zbuf, int n, const uint8_t* __restrict skin,
                     int skin_width, const uint8_t* __restrict colormap, const AliasSpan& a) {
  uint32_t s = uint32_t(a.s), t = uint32_t(a.t), l = uint32_t(a.light), z = a.zi;
  const uint32_t ds = uint32_t(a.ds), dt = uint32_t(a.dt), dl = uint32_t(a.dlight), dz = uint32_t(a.dzi);
  const uint32_t w = uint32_t(skin_width);
  int k = 0;
  if (n >= kAliasVectorMin) {
    auto lanes = [](uint32_t x, uint32_t d) {
      return _mm_setr_epi32(int32_t(x), int32_t(x + d), int32_t(x + 2 * d), int32_t(x + 3 * d));
    };
    auto four = [](uint32_t d) { return _mm_set1_epi32(int32_t(4 * d)); };
    __m128i S0 = lanes(s, ds), T0 = lanes(t, dt), L0 = lanes(l, dl), Z0 = lanes(z, dz);
    __m128i S1 = _mm_add_epi32(S0, four(ds)), T1 = _mm_add_epi32(T0, four(dt));
    __m128i L1 = _mm_add_epi32(L0, four(dl)), Z1 = _mm_add_epi32(Z0, four(dz));
    const __m128i S8 = four(2 * ds), T8 = four(2 * dt), L8 = four(2 * dl), Z8 = four(2 * dz);
    // pmaddwd on (s >> 16 | (t >> 16) << 16) x (1 | width << 16) = s + t * width: every
    // factor fits 15 bits (the contract), so the signed 16-bit multiply is exact.
    const __m128i W = _mm_set1_epi32(int32_t((w << 16) | 1u));
    const __m128i high = _mm_set1_epi32(int32_t(0xffff0000u)), rows = _mm_set1_epi32(0xff00);
    const __m128i flip = _mm_set1_epi16(int16_t(0x8000));
    alignas(16) uint32_t off[8], row[8];
    for (; k + 8 <= n; k += 8) {
      // srai keeps each high half as a signed 16-bit value, so packs is exact.
      const __m128i zn = _mm_packs_epi32(_mm_srai_epi32(Z0, 16), _mm_srai_epi32(Z1, 16));
      const __m128i zo = _mm_loadu_si128(reinterpret_cast<const __m128i*>(zbuf + k));
      // Unsigned old > new as a signed compare with the sign bits flipped: hidden lanes.
      const __m128i hid = _mm_cmpgt_epi16(_mm_xor_si128(zo, flip), _mm_xor_si128(zn, flip));
      const unsigned hmask = unsigned(_mm_movemask_epi8(_mm_packs_epi16(hid, hid))) & 0xffu;
      if (hmask != 0xffu) {
        _mm_storeu_si128(reinterpret_cast<__m128i*>(zbuf + k),
                         _mm_or_si128(_mm_and_si128(hid, zo), _mm_andnot_si128(hid, zn)));
        const __m128i o0 = _mm_madd_epi16(_mm_or_si128(_mm_srli_epi32(S0, 16), _mm_and_si128(T0, high)), W);
        const __m128i o1 = _mm_madd_epi16(_mm_or_si128(_mm_srli_epi32(S1, 16), _mm_and_si128(T1, high)), W);
        _mm_store_si128(reinterpret_cast<__m128i*>(off), o0);
        _mm_store_si128(reinterpret_cast<__m128i*>(off + 4), o1);
        _mm_store_si128(reinterpret_cast<__m128i*>(row), _mm_and_si128(_mm_srli_epi32(L0, 8), rows));
        _mm_store_si128(reinterpret_cast<__m128i*>(row + 4), _mm_and_si128(_mm_srli_epi32(L1, 8), rows));
        alias_store8(dest + k, skin, colormap, off, row, hmask);
      }
      S0 = _mm_add_epi32(S0, S8);
      S1 = _mm_add_epi32(S1, S8);
      T0 = _mm_add_epi32(T0, T8);
      T1 = _mm_add_epi32(T1, T8);
      L0 = _mm_add_epi32(L0, L8);
      L1 = _mm_add_epi32(L1, L8);
      Z0 = _mm_add_epi32(Z0, Z8);
      Z1 = _mm_add_epi32(Z1, Z8);
    }
    s += uint32_t(k) * ds;
    t += uint32_t(k) * dt;
    l += uint32_t(k) * dl;
    z += uint32_t(k) * dz;
  }
  alias_tail(dest, zbuf, k, n, skin, w, colormap, s, t, l, z, a);
}

}  // namespace sb::simd::detail

#endif  // __SSE2__

// ---------------------------------------------------------------- NEON

#if defined(SB_SIMD_HAVE_NEON)
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "SB_SIMD_HAVE_NEON is set but this file is not compiled for NEON"
#endif
#include <arm_neon.h>

#include "asm/alias_span_a64.h"

namespace sb::simd::detail {

namespace {

// One group of 8 pixels from lane values at its first pixel (S, T, L, Z: lanes 0..3 in
// [0], 4..7 in [1]): the z test and the z buffer's new contents (one load, one store), then
// all 8 texels fetched (the contract keeps every lane's coordinates in range, hidden or
// not), packed into one 64-bit word and blended with dest's 8 bytes under the visibility
// mask: a hidden pixel is rewritten with the byte it already holds. A group drawn twice
// over the same pixels gives the same bytes (a drawn pixel's z now equals its own z, so it
// passes again and draws the same texel), which lets the span's last group overlap the one
// before it instead of taking a scalar tail.
[[gnu::always_inline]] inline void alias_group8(uint8_t* __restrict d, uint16_t* __restrict zb,
                                          const uint8_t* __restrict skin, const uint8_t* __restrict colormap,
                                          uint32x4_t S0, uint32x4_t S1, uint32x4_t T0, uint32x4_t T1,
                                          uint32x4_t L0, uint32x4_t L1, uint32x4_t Z0, uint32x4_t Z1,
                                          uint16x4_t w16, uint64_t* __restrict sr) {
  const uint16x8_t zn = vcombine_u16(vshrn_n_u32(Z0, 16), vshrn_n_u32(Z1, 16));
  const uint16x8_t zo = vld1q_u16(zb);
  const uint16x8_t vis = vcgeq_u16(zn, zo);
  vst1q_u16(zb, vbslq_u16(vis, zn, zo));
  const uint64_t m = vget_lane_u64(vreinterpret_u64_u8(vmovn_u16(vis)), 0);
  // Skin offsets (t >> 16) * width + (s >> 16) from 16-bit halves (both < 2^15: the contract)
  // and colormap row offsets (l >> 16) * 256, interleaved by vst2q so one 64-bit load brings
  // lane j's pair to a core register: offset in the low word, row in the high one.
  uint32x4x2_t p0, p1;
  p0.val[0] = vmlal_u16(vshrq_n_u32(S0, 16), vshrn_n_u32(T0, 16), w16);
  p1.val[0] = vmlal_u16(vshrq_n_u32(S1, 16), vshrn_n_u32(T1, 16), w16);
  p0.val[1] = vshlq_n_u32(vshrq_n_u32(L0, 16), 8);
  p1.val[1] = vshlq_n_u32(vshrq_n_u32(L1, 16), 8);
  vst2q_u32(reinterpret_cast<uint32_t*>(sr), p0);
  vst2q_u32(reinterpret_cast<uint32_t*>(sr + 4), p1);
  uint64_t px = 0;
#pragma GCC unroll 8
  for (int j = 0; j < 8; ++j) {
    const uint32_t tex = skin[uint32_t(sr[j])];
    px |= uint64_t(colormap[uint32_t(sr[j] >> 32) + tex]) << (8 * j);
  }
  uint64_t old;
  std::memcpy(&old, d, 8);
  px = (px & m) | (old & ~m);
  std::memcpy(d, &px, 8);
}

}  // namespace

void alias_span_neon(uint8_t* __restrict dest, uint16_t* __restrict zbuf, int n, const uint8_t* __restrict skin,
                     int skin_width, const uint8_t* __restrict colormap, const AliasSpan& a) {
  const uint32_t s = uint32_t(a.s), t = uint32_t(a.t), l = uint32_t(a.light), z = a.zi;
  const uint32_t w = uint32_t(skin_width);
  if (n < 8) return alias_tail(dest, zbuf, 0, n, skin, w, colormap, s, t, l, z, a);
#if defined(__aarch64__)
  // One asm statement, software pipelined (asm/alias_span_a64.h).
  alias_span_a64(dest, zbuf, n, skin, colormap, a, w);
#else
  const uint32_t ds = uint32_t(a.ds), dt = uint32_t(a.dt), dl = uint32_t(a.dlight), dz = uint32_t(a.dzi);
  static constexpr uint32_t kIndex[4] = {0, 1, 2, 3};
  const uint32x4_t idx = vld1q_u32(kIndex);
  const uint16x4_t w16 = vdup_n_u16(uint16_t(w));
  alignas(16) uint64_t sr[8];
  // Lanes 0..3 of each quantity at pixel k from one multiply-add each.
  auto at = [&](uint32_t x, uint32_t d, uint32_t k) { return vmlaq_n_u32(vdupq_n_u32(x + k * d), idx, d); };
  uint32x4_t S0 = at(s, ds, 0), T0 = at(t, dt, 0), L0 = at(l, dl, 0), Z0 = at(z, dz, 0);
  const uint32x4_t S4 = vdupq_n_u32(4 * ds), T4 = vdupq_n_u32(4 * dt), L4 = vdupq_n_u32(4 * dl),
                   Z4 = vdupq_n_u32(4 * dz);
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    const uint32x4_t S1 = vaddq_u32(S0, S4), T1 = vaddq_u32(T0, T4), L1 = vaddq_u32(L0, L4), Z1 = vaddq_u32(Z0, Z4);
    alias_group8(dest + k, zbuf + k, skin, colormap, S0, S1, T0, T1, L0, L1, Z0, Z1, w16, sr);
    S0 = vaddq_u32(S1, S4);
    T0 = vaddq_u32(T1, T4);
    L0 = vaddq_u32(L1, L4);
    Z0 = vaddq_u32(Z1, Z4);
  }
  if (k < n) {  // the last n % 8 pixels: a group ending at pixel n - 1, over pixels already drawn
    const uint32_t b = uint32_t(n - 8);
    S0 = at(s, ds, b), T0 = at(t, dt, b), L0 = at(l, dl, b), Z0 = at(z, dz, b);
    alias_group8(dest + b, zbuf + b, skin, colormap, S0, vaddq_u32(S0, S4), T0, vaddq_u32(T0, T4), L0,
                 vaddq_u32(L0, L4), Z0, vaddq_u32(Z0, Z4), w16, sr);
  }
#endif
}

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
