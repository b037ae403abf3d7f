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
//
// Per texel, num = g00 w00 + g10 w10 + g01 w01 + g11 w11 with the bilinear weights
// w00 = (B - fx)(B - fy), w10 = fx (B - fy), w01 = (B - fx) fy, w11 = fx fy: the same
// integer as the scalar builder's stepped numerator. Grid pairs (g00, g10) and weight pairs
// (w00, w10) sit in 16-bit halves of 32-bit lanes, so one pmaddwd gives g00 w00 + g10 w10.
// The surface is walked a row at a time in chunks of 16 texels (chunks start on block
// boundaries, so a lane's fx depends only on its index), split where the texture wraps.

template <int kMip>
void surface_block_rows(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                        int toff, int width, int height, const uint8_t* __restrict colormap,
                        uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, S = 2 * (4 - kMip);
  const int bw = width / B, bh = height / B;
  // (g[bx], g[bx + 1]) of the block row's top (p0) and bottom (p1) grid rows; zero padding
  // for the lanes of a final partial chunk.
  alignas(16) uint32_t p0[kMaxBlockColumns + 16], p1[kMaxBlockColumns + 16];
  __m128i A[4];  // lanes k = 4j + i: (B - fx) | fx << 16, fx = k % B
  for (int j = 0; j < 4; ++j) {
    auto pat = [](int k) { return int32_t((B - k % B) | (k % B) << 16); };
    A[j] = _mm_setr_epi32(pat(4 * j), pat(4 * j + 1), pat(4 * j + 2), pat(4 * j + 3));
  }
  const __m128i mask = _mm_set1_epi32(0xff00), zero = _mm_setzero_si128();
  const int c0 = wrap(soff, tw);
  alignas(16) uint16_t idx[16];
  alignas(16) uint8_t tmp[16];

  const uint8_t* const tex_end = texels + tw * th;
  uint8_t rowbuf[kRowBufferBytes];
  int ty = wrap(toff, th);  // texture row of surface row y
  for (int by = 0; by < bh; ++by) {
    const uint16_t* g0 = grid + by * grid_width;
    const uint16_t* g1 = g0 + grid_width;
    for (int bx = 0; bx < bw; ++bx) {
      p0[bx] = uint32_t(g0[bx]) | uint32_t(g0[bx + 1]) << 16;
      p1[bx] = uint32_t(g1[bx]) | uint32_t(g1[bx + 1]) << 16;
    }
    for (int bx = bw; bx < bw + 16; ++bx) p0[bx] = p1[bx] = 0;
    for (int fy = 0; fy < B; ++fy) {
      const int y = by * B + fy;
      const __m128i wt = _mm_set1_epi16(int16_t(B - fy)), wb = _mm_set1_epi16(int16_t(fy));
      __m128i W0[4], W1[4];
      for (int j = 0; j < 4; ++j) {
        W0[j] = _mm_mullo_epi16(A[j], wt);
        W1[j] = _mm_mullo_epi16(A[j], wb);
      }
      const uint8_t* trow = texels + ty * tw;
      if (++ty == th) ty = 0;
      uint8_t* drow = out + y * width;
      const uint8_t* row_end;
      const uint8_t* texrow = texel_row(trow, c0, tw, width, tex_end, rowbuf, &row_end);
      {
        constexpr int x = 0;
        const int len = width;
        for (int i = 0; i < len; i += 16) {
          const int m = len - i < 16 ? len - i : 16;
          const int bx0 = (x + i) >> LB;
          __m128i row[4];
          for (int j = 0; j < 4; ++j) {
            __m128i e0, e1;
            if constexpr (LB == 1) {
              e0 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p0 + bx0 + 2 * j));
              e1 = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p1 + bx0 + 2 * j));
              e0 = _mm_unpacklo_epi32(e0, e0);
              e1 = _mm_unpacklo_epi32(e1, e1);
            } else {
              e0 = _mm_set1_epi32(int32_t(p0[bx0 + ((4 * j) >> LB)]));
              e1 = _mm_set1_epi32(int32_t(p1[bx0 + ((4 * j) >> LB)]));
            }
            const __m128i num = add32(_mm_madd_epi16(e0, W0[j]), _mm_madd_epi16(e1, W1[j]));
            row[j] = _mm_and_si128(_mm_srli_epi32(num, S), mask);
          }
          const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(texels16(texrow + i, m, row_end, tmp)));
          // Rows are at most 0x3f00: the signed pack is exact.
          _mm_store_si128(reinterpret_cast<__m128i*>(idx),
                          _mm_add_epi16(_mm_packs_epi32(row[0], row[1]), _mm_unpacklo_epi8(t, zero)));
          _mm_store_si128(reinterpret_cast<__m128i*>(idx + 8),
                          _mm_add_epi16(_mm_packs_epi32(row[2], row[3]), _mm_unpackhi_epi8(t, zero)));
          lookup_n(drow + x + i, colormap, idx, m);
        }
      }
    }
  }
}

void surface_block_sse2(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width, int tex_height,
                        int mip, int soff, int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  if (width <= 0 || height <= 0) return;
  if (width / (16 >> mip) > kMaxBlockColumns || mip < 0 || mip > 3) {
    surface_block_scalar(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap,
                         out);
    return;
  }
  switch (mip) {
    case 0: return surface_block_rows<0>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 1: return surface_block_rows<1>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 2: return surface_block_rows<2>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    default: return surface_block_rows<3>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
  }
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

void expand_palette_sse2(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  const size_t row_bytes = size_t(width) * size_t(scale) * sizeof(uint32_t);
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
    } else if (scale == 2) {
      for (; x + 4 <= width; x += 4) {
        const __m128i c = _mm_setr_epi32(int32_t(palette[s[x]]), int32_t(palette[s[x + 1]]),
                                         int32_t(palette[s[x + 2]]), int32_t(palette[s[x + 3]]));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(d + 2 * x), _mm_unpacklo_epi32(c, c));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(d + 2 * x + 4), _mm_unpackhi_epi32(c, c));
      }
      for (; x < width; ++x) d[2 * x] = d[2 * x + 1] = palette[s[x]];
    } else {
      // Each pixel: ceil(scale / 4) stores of four copies; the last store may spill into
      // the following pixels' squares, which are written afterwards. Pixels whose stores
      // would pass the row's end are written exactly.
      const int q = (scale + 3) / 4;
      for (; x * scale + 4 * q <= width * scale; ++x) {
        const __m128i c = _mm_set1_epi32(int32_t(palette[s[x]]));
        uint32_t* p = d + x * scale;
        for (int i = 0; i < q; ++i) _mm_storeu_si128(reinterpret_cast<__m128i*>(p + 4 * i), c);
      }
      for (; x < width; ++x) {
        const uint32_t c = palette[s[x]];
        for (int i = 0; i < scale; ++i) d[x * scale + i] = c;
      }
    }
    for (int j = 1; j < scale; ++j) std::memcpy(d + j * dst_stride, d, row_bytes);
  }
}

}  // namespace

const Kernels kSse2 = {"sse2", surface_span_sse2, surface_block_sse2, z_span_sse2, expand_palette_sse2, alias_span_sse2,
                        surface_span_persp_fast};

}  // namespace sb::simd::detail

#endif  // __SSE2__
