// asm/sse2.cpp: SSE2 variants (the x86-64 baseline: always available there).
// SSE2 has no gather and no 32-bit multiply, so: the lanes' coordinates and addresses are
// computed four at a time (pmaddwd does the row multiply: both factors fit 16 bits), the
// texel and colormap loads stay scalar, and stores are vector where the output is.
//
// Sections: 1. surface span  2. surface block builder  3. z span  4. palette expansion
#include "asm/variants.h"

#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstring>

namespace sb::simd::detail {
namespace {

inline __m128i add32(__m128i a, __m128i b) { return _mm_add_epi32(a, b); }

// ---------------------------------------------------------------- 1. surface span

// Lanes k = 0..3 of a + k d + k (k - 1) / 2 dd (mod 2^32).
inline __m128i lanes4(uint32_t a, uint32_t d, uint32_t dd) {
  return _mm_setr_epi32(int32_t(a), int32_t(a + d), int32_t(a + 2 * d + dd), int32_t(a + 3 * d + 3 * dd));
}

void surface_span_sse2(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, int width, int,
                       int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  const uint32_t du_ = uint32_t(du), dv_ = uint32_t(dv), ddu_ = uint32_t(ddu), ddv_ = uint32_t(ddv);
  // Advancing four pixels: u_{k+4} = u_k + 4 du_k + 6 dd, 4 du_{k+4} = 4 du_k + 16 dd.
  __m128i U = lanes4(uint32_t(u), du_, ddu_), V = lanes4(uint32_t(v), dv_, ddv_);
  __m128i DU = lanes4(4 * du_, 4 * ddu_, 0), DV = lanes4(4 * dv_, 4 * ddv_, 0);
  const __m128i CU = _mm_set1_epi32(int32_t(6 * ddu_)), CV = _mm_set1_epi32(int32_t(6 * ddv_));
  const __m128i EU = _mm_set1_epi32(int32_t(16 * ddu_)), EV = _mm_set1_epi32(int32_t(16 * ddv_));
  const __m128i W = _mm_set1_epi32(width);  // pmaddwd pairs (v >> 16, 0) with (width, 0)
  // Addresses leave the vector two at a time through 64-bit moves (no store and reload).
  auto next = [&]() {
    const __m128i a = add32(_mm_madd_epi16(_mm_srli_epi32(V, 16), W), _mm_srli_epi32(U, 16));
    U = add32(U, add32(DU, CU));
    V = add32(V, add32(DV, CV));
    DU = add32(DU, EU);
    DV = add32(DV, EV);
    return a;
  };
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const __m128i a = next();
    const uint64_t lo = uint64_t(_mm_cvtsi128_si64(a)), hi = uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(a, a)));
    dest[k] = texels[uint32_t(lo)];
    dest[k + 1] = texels[lo >> 32];
    dest[k + 2] = texels[uint32_t(hi)];
    dest[k + 3] = texels[hi >> 32];
  }
  if (k < n) {
    alignas(16) uint32_t addr[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(addr), next());
    for (int i = 0; k < n; ++i, ++k) dest[k] = texels[addr[i]];
  }
}

// ---------------------------------------------------------------- 2. surface block builder
// asm/surface_block_x86.h (shared with asm/avx2.cpp).

#include "asm/surface_block_x86.h"

void surface_block_sse2(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width, int tex_height,
                        int mip, int soff, int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  surface_block_x86(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap, out);
}

// ---------------------------------------------------------------- 3. z span

void z_span_sse2(uint16_t* __restrict z, int n, uint32_t zi, uint32_t step) {
  int k = 0;
  if (n >= 8) {
    __m128i z0 = lanes4(zi, step, 0);
    __m128i z1 = add32(z0, _mm_set1_epi32(int32_t(4 * step)));
    const __m128i s8 = _mm_set1_epi32(int32_t(8 * step));
    for (; k + 8 <= n; k += 8) {
      // srai keeps the high half as a signed 16-bit value: packs is then exact.
      const __m128i out = _mm_packs_epi32(_mm_srai_epi32(z0, 16), _mm_srai_epi32(z1, 16));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(z + k), out);
      z0 = add32(z0, s8);
      z1 = add32(z1, s8);
    }
    zi += uint32_t(k) * step;
  }
  for (; k < n; ++k) {
    z[k] = uint16_t(zi >> 16);
    zi += step;
  }
}

// ---------------------------------------------------------------- 4. palette expansion

}  // namespace

// Scales 3 and 4 (the scale a compile-time constant): one 16-byte store of four copies a pixel
// and row; at scale 3 it spills one word into the next pixel's square, which is written
// afterwards. Pixels whose store would pass the row's end are left to the caller. Returns the
// pixels done.
template <int S>
static int expand_rows_x34(const uint8_t* s, int width, const uint32_t* palette, uint32_t* d, ptrdiff_t dst_stride) {
  int x = 0;
  for (; x * S + 4 <= width * S; ++x) {
    const __m128i c = _mm_set1_epi32(int32_t(palette[s[x]]));
#pragma GCC unroll 4
    for (int j = 0; j < S; ++j) _mm_storeu_si128(reinterpret_cast<__m128i*>(d + j * dst_stride + x * S), c);
  }
  return x;
}

void expand_palette_sse2(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    uint32_t* d = dst + ptrdiff_t(y) * scale * dst_stride;
    int x = 0;
    if (scale == 1) {
      for (; x + 4 <= width; x += 4) {
        const __m128i c = _mm_setr_epi32(int32_t(palette[s[x]]), int32_t(palette[s[x + 1]]),
                                         int32_t(palette[s[x + 2]]), int32_t(palette[s[x + 3]]));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(d + x), c);
      }
      for (; x < width; ++x) d[x] = palette[s[x]];
      continue;
    }
    // Every output row stored from the registers (no copy of a written row).
    if (scale == 2) {
      for (; x + 4 <= width; x += 4) {
        const __m128i c = _mm_setr_epi32(int32_t(palette[s[x]]), int32_t(palette[s[x + 1]]),
                                         int32_t(palette[s[x + 2]]), int32_t(palette[s[x + 3]]));
        const __m128i lo = _mm_unpacklo_epi32(c, c), hi = _mm_unpackhi_epi32(c, c);
        for (int j = 0; j < 2; ++j) {
          uint32_t* p = d + j * dst_stride + 2 * x;
          _mm_storeu_si128(reinterpret_cast<__m128i*>(p), lo);
          _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 4), hi);
        }
      }
    } else if (scale <= 4) {
      x = scale == 3 ? expand_rows_x34<3>(s, width, palette, d, dst_stride)
                     : expand_rows_x34<4>(s, width, palette, d, dst_stride);
    } else {
      // Each pixel: ceil(scale / 4) stores of four copies a row; the last store may spill into
      // the following pixels' squares, which are written afterwards. Pixels whose stores
      // would pass the row's end are written exactly.
      const int q = (scale + 3) / 4;
      for (; x * scale + 4 * q <= width * scale; ++x) {
        const __m128i c = _mm_set1_epi32(int32_t(palette[s[x]]));
        for (int j = 0; j < scale; ++j) {
          uint32_t* p = d + j * dst_stride + x * scale;
          for (int i = 0; i < q; ++i) _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 4 * i), c);
        }
      }
    }
    for (; x < width; ++x) {
      const uint32_t c = palette[s[x]];
      for (int j = 0; j < scale; ++j)
        for (int i = 0; i < scale; ++i) d[j * dst_stride + x * scale + i] = c;
    }
  }
}

namespace {

}  // namespace

const Kernels kSse2 = {"sse2", surface_span_sse2, surface_block_sse2, z_span_sse2, expand_palette_sse2, alias_span_sse2,
                        surface_span_persp_fast, surface_spans_persp_fast};

}  // namespace sb::simd::detail

#endif  // __SSE2__
