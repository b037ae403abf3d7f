// asm/lit_span_avx2.cpp: the AVX2 variant of the single-pass lit span kernel (contract:
// asm/lit_span.h), 8 pixels per step with gathers. Compiled with -mavx2 on x86-64 only
// (asm/CMakeLists.txt); lit_span.cpp calls it only after checking the CPU.
//
// Per 8 pixels: u, v of the 8 pixels as lanes (stepped by adds: lane k of the next 8 is
// lane k of these plus 8 du + (28 + 8k) ddu, that increment growing by 64 ddu per step;
// 32-bit wrap-around like the recurrence); the light pair of each grid row by one 32-bit
// gather (two neighbouring uint16), blended horizontally by vpmaddwd with (B - fx, fx) and
// vertically by one 32-bit multiply; the wrap by a mask or, for other sizes, an exactly
// rounded float quotient; the texel and the colormap entry by 32-bit gathers whose
// addresses are clamped 4 bytes before the end of their arrays (then shifted), so nothing
// outside the inputs is read. Lanes past n repeat the step's first pixel.
#include "asm/lit_span.h"

#if defined(__x86_64__) && defined(__AVX2__)
#include <immintrin.h>

#include <cstring>

namespace sb::simd {

namespace {

// 32-bit gathers of bytes base[idx] (idx < size, size >= 4), read without passing the end.
inline __m256i gather_bytes(const uint8_t* base, __m256i idx, int size) {
  const __m256i clamped = _mm256_min_epi32(idx, _mm256_set1_epi32(size - 4));
  const __m256i shift = _mm256_slli_epi32(_mm256_sub_epi32(idx, clamped), 3);
  const __m256i words = _mm256_i32gather_epi32(reinterpret_cast<const int*>(base), clamped, 1);
  return _mm256_and_si256(_mm256_srlv_epi32(words, shift), _mm256_set1_epi32(0xff));
}

// c mod size for 0 <= c < 8192, 1 <= size <= 4096: q = trunc((c + 0.5) / size) in float is
// floor(c / size) exactly (the float error stays below 2^-10 / size, the distance of
// (c + 0.5) / size from an integer is at least 0.5 / size).
inline __m256i mod_float(__m256i c, __m256 inv, __m256i size) {
  const __m256 x = _mm256_add_ps(_mm256_cvtepi32_ps(c), _mm256_set1_ps(0.5f));
  const __m256i q = _mm256_cvttps_epi32(_mm256_mul_ps(x, inv));
  return _mm256_sub_epi32(c, _mm256_madd_epi16(q, size));  // q, size < 2^15: one 16x16 product
}

template <int kMip, bool kPow2>
void lit_span_avx2_t(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                     uint32_t dv, uint32_t ddu, uint32_t ddv) {
  constexpr int kLog = 4 - kMip;
  constexpr int kShift = 2 * kLog;
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i tri = _mm256_setr_epi32(0, 0, 1, 3, 6, 10, 15, 21);  // k (k - 1) / 2
  const __m256i inc_k = _mm256_setr_epi32(28, 36, 44, 52, 60, 68, 76, 84);  // 28 + 8 k
  const __m256i vdu = _mm256_set1_epi32(int(du)), vdv = _mm256_set1_epi32(int(dv));
  const __m256i vddu = _mm256_set1_epi32(int(ddu)), vddv = _mm256_set1_epi32(int(ddv));
  __m256i uu = _mm256_add_epi32(_mm256_set1_epi32(int(u)),
                                _mm256_add_epi32(_mm256_mullo_epi32(lane, vdu), _mm256_mullo_epi32(tri, vddu)));
  __m256i vv = _mm256_add_epi32(_mm256_set1_epi32(int(v)),
                                _mm256_add_epi32(_mm256_mullo_epi32(lane, vdv), _mm256_mullo_epi32(tri, vddv)));
  __m256i iu = _mm256_add_epi32(_mm256_slli_epi32(vdu, 3), _mm256_mullo_epi32(inc_k, vddu));
  __m256i iv = _mm256_add_epi32(_mm256_slli_epi32(vdv, 3), _mm256_mullo_epi32(inc_k, vddv));
  const __m256i iiu = _mm256_slli_epi32(vddu, 6), iiv = _mm256_slli_epi32(vddv, 6);

  const __m256i frac = _mm256_set1_epi32((1 << kLog) - 1);
  const __m256i bsize = _mm256_set1_epi32(1 << kLog);
  const __m256i gw = _mm256_set1_epi32(src.grid_width);
  const __m256i so = _mm256_set1_epi32(int(src.soff_mod)), to = _mm256_set1_epi32(int(src.toff_mod));
  const __m256i tw = _mm256_set1_epi32(src.tex_width), th = _mm256_set1_epi32(src.tex_height);
  const __m256i smask = _mm256_set1_epi32(src.tex_width - 1), tmask = _mm256_set1_epi32(src.tex_height - 1);
  const __m256 sinv = _mm256_set1_ps(1.0f / float(src.tex_width)), tinv = _mm256_set1_ps(1.0f / float(src.tex_height));
  const __m256i row_mask = _mm256_set1_epi32(0xff00);
  const int tex_size = src.tex_width * src.tex_height;
  const int* grid = reinterpret_cast<const int*>(src.grid);

  for (int k = 0; k < n; k += 8) {
    const int left = n - k;
    __m256i cu = uu, cv = vv;
    if (left < 8) {  // lanes past n: the first pixel of this step again (always valid)
      const __m256i off = _mm256_cmpgt_epi32(lane, _mm256_set1_epi32(left - 1));
      cu = _mm256_blendv_epi8(cu, _mm256_permutevar8x32_epi32(cu, _mm256_setzero_si256()), off);
      cv = _mm256_blendv_epi8(cv, _mm256_permutevar8x32_epi32(cv, _mm256_setzero_si256()), off);
    }
    const __m256i U = _mm256_srli_epi32(cu, 16), V = _mm256_srli_epi32(cv, 16);
    const __m256i fx = _mm256_and_si256(U, frac), fy = _mm256_and_si256(V, frac);
    const __m256i gi = _mm256_add_epi32(_mm256_madd_epi16(_mm256_srli_epi32(V, kLog), gw), _mm256_srli_epi32(U, kLog));
    // g[gi] | g[gi + 1] << 16 and the same one grid row down (gi + 1 < the row's end).
    const __m256i p0 = _mm256_i32gather_epi32(grid, gi, 2);
    const __m256i p1 = _mm256_i32gather_epi32(grid, _mm256_add_epi32(gi, gw), 2);
    // (B - fx) | fx << 16 = B + (fx << 16) - fx
    const __m256i wx = _mm256_add_epi32(bsize, _mm256_sub_epi32(_mm256_slli_epi32(fx, 16), fx));
    const __m256i top = _mm256_madd_epi16(p0, wx);     // g00 (B - fx) + g10 fx
    const __m256i bottom = _mm256_madd_epi16(p1, wx);  // g01 (B - fx) + g11 fx
    const __m256i num = _mm256_add_epi32(_mm256_slli_epi32(top, kLog),
                                         _mm256_mullo_epi32(_mm256_sub_epi32(bottom, top), fy));
    const __m256i row = _mm256_and_si256(_mm256_srli_epi32(num, kShift), row_mask);

    __m256i s = _mm256_add_epi32(U, so), t = _mm256_add_epi32(V, to);
    if constexpr (kPow2) {
      s = _mm256_and_si256(s, smask);
      t = _mm256_and_si256(t, tmask);
    } else {
      s = mod_float(s, sinv, tw);
      t = mod_float(t, tinv, th);
    }
    const __m256i texel = gather_bytes(src.texels, _mm256_add_epi32(_mm256_madd_epi16(t, tw), s), tex_size);
    const __m256i color = gather_bytes(src.colormap, _mm256_add_epi32(row, texel), 64 * 256);

    // 8 dwords (each <= 255) to 8 bytes.
    const __m256i w16 = _mm256_packus_epi32(color, color);
    const __m256i b8 = _mm256_packus_epi16(w16, w16);
    const uint64_t bytes = uint64_t(uint32_t(_mm_cvtsi128_si32(_mm256_castsi256_si128(b8)))) |
                           (uint64_t(uint32_t(_mm_cvtsi128_si32(_mm256_extracti128_si256(b8, 1)))) << 32);
    if (left >= 8) {
      std::memcpy(dest + k, &bytes, 8);
    } else {
      for (int i = 0; i < left; ++i) dest[k + i] = uint8_t(bytes >> (8 * i));
      break;
    }
    uu = _mm256_add_epi32(uu, iu);
    vv = _mm256_add_epi32(vv, iv);
    iu = _mm256_add_epi32(iu, iiu);
    iv = _mm256_add_epi32(iv, iiv);
  }
}

// "avx2s": the same lane arithmetic for the addresses and weights, stored to the stack; the
// loads and the light blend then run scalar per pixel (the "fast" variant's packed-pair
// blend on grid_wide). No gathers: they are slow on some x86 cores.
template <int kLog>
struct PairWeights {
  uint64_t w[16];
  constexpr PairWeights() : w() {
    for (int fx = 0; fx < (1 << kLog); ++fx) w[fx] = uint64_t(fx) | (uint64_t((1 << kLog) - fx) << 32);
  }
};

template <int kMip, bool kPow2>
void lit_span_avx2s_t(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du,
                      uint32_t dv, uint32_t ddu, uint32_t ddv) {
  constexpr int kLog = 4 - kMip;
  constexpr int kShift = 2 * kLog;
  static constexpr PairWeights<kLog> kW{};
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i tri = _mm256_setr_epi32(0, 0, 1, 3, 6, 10, 15, 21);
  const __m256i inc_k = _mm256_setr_epi32(28, 36, 44, 52, 60, 68, 76, 84);
  const __m256i vdu = _mm256_set1_epi32(int(du)), vdv = _mm256_set1_epi32(int(dv));
  const __m256i vddu = _mm256_set1_epi32(int(ddu)), vddv = _mm256_set1_epi32(int(ddv));
  __m256i uu = _mm256_add_epi32(_mm256_set1_epi32(int(u)),
                                _mm256_add_epi32(_mm256_mullo_epi32(lane, vdu), _mm256_mullo_epi32(tri, vddu)));
  __m256i vv = _mm256_add_epi32(_mm256_set1_epi32(int(v)),
                                _mm256_add_epi32(_mm256_mullo_epi32(lane, vdv), _mm256_mullo_epi32(tri, vddv)));
  __m256i iu = _mm256_add_epi32(_mm256_slli_epi32(vdu, 3), _mm256_mullo_epi32(inc_k, vddu));
  __m256i iv = _mm256_add_epi32(_mm256_slli_epi32(vdv, 3), _mm256_mullo_epi32(inc_k, vddv));
  const __m256i iiu = _mm256_slli_epi32(vddu, 6), iiv = _mm256_slli_epi32(vddv, 6);
  const __m256i frac = _mm256_set1_epi32((1 << kLog) - 1);
  const __m256i gw = _mm256_set1_epi32(src.grid_width);
  const __m256i so = _mm256_set1_epi32(int(src.soff_mod)), to = _mm256_set1_epi32(int(src.toff_mod));
  const __m256i tw = _mm256_set1_epi32(src.tex_width), th = _mm256_set1_epi32(src.tex_height);
  const __m256i smask = _mm256_set1_epi32(src.tex_width - 1), tmask = _mm256_set1_epi32(src.tex_height - 1);
  const __m256 sinv = _mm256_set1_ps(1.0f / float(src.tex_width)), tinv = _mm256_set1_ps(1.0f / float(src.tex_height));
  const uint32_t* __restrict grid = src.grid_wide;
  const size_t gws = size_t(src.grid_width);
  const uint8_t* __restrict texels = src.texels;
  const uint8_t* __restrict cm = src.colormap;
  alignas(32) uint32_t gi_a[8], fx_a[8], fy_a[8], ti_a[8];

  for (int k = 0; k < n; k += 8) {
    const __m256i U = _mm256_srli_epi32(uu, 16), V = _mm256_srli_epi32(vv, 16);
    const __m256i gi = _mm256_add_epi32(_mm256_madd_epi16(_mm256_srli_epi32(V, kLog), gw), _mm256_srli_epi32(U, kLog));
    __m256i s = _mm256_add_epi32(U, so), t = _mm256_add_epi32(V, to);
    if constexpr (kPow2) {
      s = _mm256_and_si256(s, smask);
      t = _mm256_and_si256(t, tmask);
    } else {
      s = mod_float(s, sinv, tw);
      t = mod_float(t, tinv, th);
    }
    _mm256_store_si256(reinterpret_cast<__m256i*>(gi_a), gi);
    _mm256_store_si256(reinterpret_cast<__m256i*>(fx_a), _mm256_and_si256(U, frac));
    _mm256_store_si256(reinterpret_cast<__m256i*>(fy_a), _mm256_and_si256(V, frac));
    _mm256_store_si256(reinterpret_cast<__m256i*>(ti_a), _mm256_add_epi32(_mm256_madd_epi16(t, tw), s));
    // Lanes past n hold addresses outside the contract: never dereferenced.
    const int m = n - k < 8 ? n - k : 8;
    for (int j = 0; j < m; ++j) {
      const uint32_t* g = grid + gi_a[j];
      uint64_t p0, p1;
      std::memcpy(&p0, g, 8);
      std::memcpy(&p1, g + gws, 8);
      const uint64_t pv = (p0 << kLog) + (p1 - p0) * fy_a[j];
      const uint32_t num = uint32_t((pv * kW.w[fx_a[j]]) >> 32);
      dest[k + j] = cm[((num >> kShift) & 0xff00u) + texels[ti_a[j]]];
    }
    uu = _mm256_add_epi32(uu, iu);
    vv = _mm256_add_epi32(vv, iv);
    iu = _mm256_add_epi32(iu, iiu);
    iv = _mm256_add_epi32(iv, iiv);
  }
}

template <bool kPow2>
void by_mip_s(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du, uint32_t dv,
              uint32_t ddu, uint32_t ddv) {
  switch (src.mip) {
    case 0: return lit_span_avx2s_t<0, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 1: return lit_span_avx2s_t<1, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 2: return lit_span_avx2s_t<2, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    default: return lit_span_avx2s_t<3, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}

template <bool kPow2>
void by_mip(uint8_t* dest, int n, const LitSpanSource& src, uint32_t u, uint32_t v, uint32_t du, uint32_t dv,
            uint32_t ddu, uint32_t ddv) {
  switch (src.mip) {
    case 0: return lit_span_avx2_t<0, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 1: return lit_span_avx2_t<1, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    case 2: return lit_span_avx2_t<2, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
    default: return lit_span_avx2_t<3, kPow2>(dest, n, src, u, v, du, dv, ddu, ddv);
  }
}

inline bool is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

}  // namespace

bool lit_span_avx2_compiled() { return true; }

void lit_span_avx2(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  // Needs the prepared constants, and textures of at least 4 texels (the clamped gathers).
  if (!src.prepared || src.tex_width * src.tex_height < 4) {
    return lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
  }
  if (is_pow2(src.tex_width) && is_pow2(src.tex_height)) {
    by_mip<true>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
  } else {
    by_mip<false>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
  }
}

void lit_span_avx2s(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                    int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  if (!src.prepared) return lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
  if (is_pow2(src.tex_width) && is_pow2(src.tex_height)) {
    by_mip_s<true>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
  } else {
    by_mip_s<false>(dest, n, src, uint32_t(u), uint32_t(v), uint32_t(du), uint32_t(dv), uint32_t(ddu), uint32_t(ddv));
  }
}

}  // namespace sb::simd

#else

namespace sb::simd {
bool lit_span_avx2_compiled() { return false; }
void lit_span_avx2(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                   int32_t ddu, int32_t ddv) {
  lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
}
void lit_span_avx2s(uint8_t* dest, int n, const LitSpanSource& src, int32_t u, int32_t v, int32_t du, int32_t dv,
                    int32_t ddu, int32_t ddv) {
  lit_span_scalar(dest, n, src, u, v, du, dv, ddu, ddv);
}
}  // namespace sb::simd

#endif
