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
#include "asm/alias_span_a64.h"
#include "asm/alias_span_v7.h"

namespace sb::simd::detail {

void alias_span_neon(uint8_t* __restrict dest, uint16_t* __restrict zbuf, int n, const uint8_t* __restrict skin,
                     int skin_width, const uint8_t* __restrict colormap, const AliasSpan& a) {
  const uint32_t s = uint32_t(a.s), t = uint32_t(a.t), l = uint32_t(a.light), z = a.zi;
  const uint32_t w = uint32_t(skin_width);
  if (n < 8) return alias_tail(dest, zbuf, 0, n, skin, w, colormap, s, t, l, z, a);
#if defined(__aarch64__)
  // One asm statement, software pipelined (asm/alias_span_a64.h).
  alias_span_a64(dest, zbuf, n, skin, colormap, a, w);
#else
  // One asm statement (asm/alias_span_v7.h).
  alias_span_v7(dest, zbuf, n, skin, colormap, a, w);
#endif
}

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
