// asm/avx2.cpp: AVX2 variants. This file alone is compiled with -mavx2 (asm/CMakeLists.txt);
// the dispatcher calls into it only after __builtin_cpu_supports("avx2") said yes, so the
// rest of the program stays baseline x86-64.
//
// Gathers read 32 bits per lane. To never read past a table's end, lanes whose index is
// within 3 bytes of the end read the last whole word instead and shift the wanted byte down
// (vpsrlvd); lanes beyond a span's end are masked off.
//
// Sections: 1. shared helpers  2. surface span  3. surface block builder  4. z span
//           5. palette expansion
#include "asm/variants.h"

#if defined(__AVX2__)
#include <immintrin.h>

#include <cstring>

namespace sb::simd::detail {
namespace {

// ---------------------------------------------------------------- 1. helpers

inline __m256i add32(__m256i a, __m256i b) { return _mm256_add_epi32(a, b); }

// Bytes table[idx] of eight lanes (low byte of each lane; the rest is garbage), reading no
// byte outside table[0 .. size - 1]; size >= 4; lanes with a zero mask are not read.
inline __m256i gather_bytes(const uint8_t* table, __m256i idx, int32_t size, __m256i lanes_on) {
  const __m256i clamped = _mm256_min_epi32(idx, _mm256_set1_epi32(size - 4));
  const __m256i shift = _mm256_slli_epi32(_mm256_sub_epi32(idx, clamped), 3);
  const __m256i g = _mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int*>(table),
                                                clamped, lanes_on, 1);
  return _mm256_srlv_epi32(g, shift);
}

// Low bytes of sixteen lanes (a: 0..7, b: 8..15) in order.
inline __m128i pack_low_bytes(__m256i a, __m256i b) {
  const __m256i pick = _mm256_setr_epi8(0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
                                        0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1);
  const __m256i pick_hi = _mm256_setr_epi8(-1, -1, -1, -1, 0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1,
                                           -1, -1, -1, -1, 0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1);
  // Per 128-bit half: [a bytes | b bytes]; then words 0, 4, 1, 5 = a0-3 a4-7 b0-3 b4-7.
  const __m256i m = _mm256_or_si256(_mm256_shuffle_epi8(a, pick), _mm256_shuffle_epi8(b, pick_hi));
  return _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(m, _mm256_setr_epi32(0, 4, 1, 5, 2, 3, 6, 7)));
}

inline void store_bytes(uint8_t* d, __m128i v, int m) {
  if (m >= 16) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(d), v);
  } else {
    alignas(16) uint8_t tmp[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(tmp), v);
    std::memcpy(d, tmp, size_t(m));
  }
}

// Lanes k = 0..7 of a + k d + k (k - 1) / 2 dd (mod 2^32).
inline __m256i lanes8(uint32_t a, uint32_t d, uint32_t dd) {
  const __m256i k = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i t = _mm256_setr_epi32(0, 0, 1, 3, 6, 10, 15, 21);
  return add32(_mm256_set1_epi32(int32_t(a)),
               add32(_mm256_mullo_epi32(k, _mm256_set1_epi32(int32_t(d))),
                     _mm256_mullo_epi32(t, _mm256_set1_epi32(int32_t(dd)))));
}

// ---------------------------------------------------------------- 2. surface span

void surface_span_avx2_gather(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, int width, int height,
                       int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  const int32_t size = width * height;
  if (size < 4) {
    surface_span_scalar(dest, n, texels, width, height, u, v, du, dv, ddu, ddv);
    return;
  }
  const uint32_t du_ = uint32_t(du), dv_ = uint32_t(dv), ddu_ = uint32_t(ddu), ddv_ = uint32_t(ddv);
  // Lanes 0..7 and 8..15; advancing 16 pixels: u_{k+16} = u_k + 16 du_k + 120 dd,
  // 16 du_{k+16} = 16 du_k + 256 dd. Lanes 8..15 are lanes 0..7 advanced 8 pixels.
  __m256i U0 = lanes8(uint32_t(u), du_, ddu_), V0 = lanes8(uint32_t(v), dv_, ddv_);
  const __m256i DU8 = lanes8(8 * du_, 8 * ddu_, 0), DV8 = lanes8(8 * dv_, 8 * ddv_, 0);
  __m256i U1 = add32(U0, add32(DU8, _mm256_set1_epi32(int32_t(28 * ddu_))));
  __m256i V1 = add32(V0, add32(DV8, _mm256_set1_epi32(int32_t(28 * ddv_))));
  __m256i DU16 = add32(DU8, DU8), DV16 = add32(DV8, DV8);
  const __m256i CU = _mm256_set1_epi32(int32_t(120 * ddu_)), CV = _mm256_set1_epi32(int32_t(120 * ddv_));
  const __m256i EU = _mm256_set1_epi32(int32_t(256 * ddu_)), EV = _mm256_set1_epi32(int32_t(256 * ddv_));
  const __m256i W = _mm256_set1_epi32(width);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i all = _mm256_set1_epi32(-1);
  // u_{k+16} - u_k for lanes 8..15 equals lanes 0..7's advance plus 8 * 16 dd of step growth.
  const __m256i DU16b = add32(DU16, _mm256_set1_epi32(int32_t(128 * ddu_)));
  const __m256i DV16b = add32(DV16, _mm256_set1_epi32(int32_t(128 * ddv_)));
  __m256i dU1 = DU16b, dV1 = DV16b;
  for (int done = 0; done < n; done += 16) {
    const int m = n - done;
    const __m256i a0 = add32(_mm256_madd_epi16(_mm256_srli_epi32(V0, 16), W), _mm256_srli_epi32(U0, 16));
    const __m256i a1 = add32(_mm256_madd_epi16(_mm256_srli_epi32(V1, 16), W), _mm256_srli_epi32(U1, 16));
    __m256i on0 = all, on1 = all;
    if (m < 16) {
      on0 = _mm256_cmpgt_epi32(_mm256_set1_epi32(m), lane);
      on1 = _mm256_cmpgt_epi32(_mm256_set1_epi32(m - 8), lane);
    }
    const __m256i t0 = gather_bytes(texels, a0, size, on0);
    const __m256i t1 = gather_bytes(texels, a1, size, on1);
    store_bytes(dest + done, pack_low_bytes(t0, t1), m);
    U0 = add32(U0, add32(DU16, CU));
    V0 = add32(V0, add32(DV16, CV));
    U1 = add32(U1, add32(dU1, CU));
    V1 = add32(V1, add32(dV1, CV));
    DU16 = add32(DU16, EU);
    DV16 = add32(DV16, EV);
    dU1 = add32(dU1, EU);
    dV1 = add32(dV1, EV);
  }
}

// Without gathers: eight lanes' addresses per vector, taken out four at a time through
// 64-bit moves, scalar texel loads.
void surface_span_avx2(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, int width, int,
                       int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  const uint32_t du_ = uint32_t(du), dv_ = uint32_t(dv), ddu_ = uint32_t(ddu), ddv_ = uint32_t(ddv);
  // Advancing eight pixels: u_{k+8} = u_k + 8 du_k + 28 dd, 8 du_{k+8} = 8 du_k + 64 dd.
  __m256i U = lanes8(uint32_t(u), du_, ddu_), V = lanes8(uint32_t(v), dv_, ddv_);
  __m256i DU = lanes8(8 * du_, 8 * ddu_, 0), DV = lanes8(8 * dv_, 8 * ddv_, 0);
  const __m256i CU = _mm256_set1_epi32(int32_t(28 * ddu_)), CV = _mm256_set1_epi32(int32_t(28 * ddv_));
  const __m256i EU = _mm256_set1_epi32(int32_t(64 * ddu_)), EV = _mm256_set1_epi32(int32_t(64 * ddv_));
  const __m256i W = _mm256_set1_epi32(width);
  auto next = [&]() {
    const __m256i a = add32(_mm256_madd_epi16(_mm256_srli_epi32(V, 16), W), _mm256_srli_epi32(U, 16));
    U = add32(U, add32(DU, CU));
    V = add32(V, add32(DV, CV));
    DU = add32(DU, EU);
    DV = add32(DV, EV);
    return a;
  };
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    const __m256i a = next();
    const __m128i lo = _mm256_castsi256_si128(a), hi = _mm256_extracti128_si256(a, 1);
    const uint64_t a0 = uint64_t(_mm_cvtsi128_si64(lo)), a1 = uint64_t(_mm_extract_epi64(lo, 1));
    const uint64_t a2 = uint64_t(_mm_cvtsi128_si64(hi)), a3 = uint64_t(_mm_extract_epi64(hi, 1));
    dest[k] = texels[uint32_t(a0)];
    dest[k + 1] = texels[a0 >> 32];
    dest[k + 2] = texels[uint32_t(a1)];
    dest[k + 3] = texels[a1 >> 32];
    dest[k + 4] = texels[uint32_t(a2)];
    dest[k + 5] = texels[a2 >> 32];
    dest[k + 6] = texels[uint32_t(a3)];
    dest[k + 7] = texels[a3 >> 32];
  }
  if (k < n) {
    alignas(32) uint32_t addr[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(addr), next());
    for (int i = 0; k < n; ++i, ++k) dest[k] = texels[addr[i]];
  }
}

// ---------------------------------------------------------------- 3. surface block builder
// Eight lanes at a time with pmaddwd light (per texel, as the SSE2 builder did before it
// moved to asm/surface_block_x86.h), the colormap read by gathers (kGather: the avx2g table)
// or by scalar loads of stored indices (kept for comparison; the avx2 table uses
// asm/surface_block_x86.h).

template <int kMip, bool kGather>
void surface_block_rows(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                        int toff, int width, int height, const uint8_t* colormap, uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, S = 2 * (4 - kMip);
  const int bw = width / B, bh = height / B;
  alignas(32) uint32_t p0[kMaxBlockColumns + 16], p1[kMaxBlockColumns + 16];
  __m256i A[2];  // lanes k = 8j + i: (B - fx) | fx << 16, fx = k % B
  for (int j = 0; j < 2; ++j) {
    alignas(32) int32_t pat[8];
    for (int i = 0; i < 8; ++i) pat[i] = int32_t((B - (8 * j + i) % B) | ((8 * j + i) % B) << 16);
    A[j] = _mm256_load_si256(reinterpret_cast<const __m256i*>(pat));
  }
  // Which p entry (relative to the group's first) each lane of a group reads.
  const __m256i spread = LB == 1   ? _mm256_setr_epi32(0, 0, 1, 1, 2, 2, 3, 3)
                         : LB == 2 ? _mm256_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1)
                                   : _mm256_setzero_si256();
  const __m256i mask = _mm256_set1_epi32(0xff00), all = _mm256_set1_epi32(-1);
  const int c0 = wrap(soff, tw);
  alignas(16) uint8_t tmp[16];
  alignas(32) uint16_t idx[16];

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
      const __m256i wt = _mm256_set1_epi16(int16_t(B - fy)), wb = _mm256_set1_epi16(int16_t(fy));
      const __m256i W00 = _mm256_mullo_epi16(A[0], wt), W01 = _mm256_mullo_epi16(A[0], wb);
      const __m256i W10 = _mm256_mullo_epi16(A[1], wt), W11 = _mm256_mullo_epi16(A[1], wb);
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
          constexpr int kSecond = 8 >> LB;  // p offset of lanes 8..15
          __m256i e00, e01, e10, e11;  // e<group><top/bottom>
          if constexpr (LB >= 3) {
            e00 = _mm256_set1_epi32(int32_t(p0[bx0]));
            e01 = _mm256_set1_epi32(int32_t(p1[bx0]));
            e10 = _mm256_set1_epi32(int32_t(p0[bx0 + kSecond]));
            e11 = _mm256_set1_epi32(int32_t(p1[bx0 + kSecond]));
          } else {
            auto load4 = [](const uint32_t* p) {
              return _mm256_castsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(p)));
            };
            e00 = _mm256_permutevar8x32_epi32(load4(p0 + bx0), spread);
            e01 = _mm256_permutevar8x32_epi32(load4(p1 + bx0), spread);
            e10 = _mm256_permutevar8x32_epi32(load4(p0 + bx0 + kSecond), spread);
            e11 = _mm256_permutevar8x32_epi32(load4(p1 + bx0 + kSecond), spread);
          }
          const __m256i num0 = add32(_mm256_madd_epi16(e00, W00), _mm256_madd_epi16(e01, W01));
          const __m256i num1 = add32(_mm256_madd_epi16(e10, W10), _mm256_madd_epi16(e11, W11));
          const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(texels16(texrow + i, m, row_end, tmp)));
          const __m256i i0 = add32(_mm256_and_si256(_mm256_srli_epi32(num0, S), mask), _mm256_cvtepu8_epi32(t));
          const __m256i i1 = add32(_mm256_and_si256(_mm256_srli_epi32(num1, S), mask),
                                   _mm256_cvtepu8_epi32(_mm_srli_si128(t, 8)));
          if constexpr (kGather) {
            const __m256i r0 = gather_bytes(colormap, i0, 64 * 256, all);
            const __m256i r1 = gather_bytes(colormap, i1, 64 * 256, all);
            store_bytes(drow + x + i, pack_low_bytes(r0, r1), m);
          } else {
            // Indices fit 16 bits: pack (per 128-bit half, then put the halves in order).
            const __m256i p = _mm256_permute4x64_epi64(_mm256_packus_epi32(i0, i1), 0xd8);
            _mm256_store_si256(reinterpret_cast<__m256i*>(idx), p);
            lookup_n(drow + x + i, colormap, idx, m);
          }
        }
      }
    }
  }
}

template <bool kGather>
void surface_block_any(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int mip,
                       int soff, int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  if (width <= 0 || height <= 0) return;
  if (width / (16 >> mip) > kMaxBlockColumns || mip < 0 || mip > 3) {
    surface_block_scalar(grid, grid_width, texels, tw, th, mip, soff, toff, width, height, colormap, out);
    return;
  }
  switch (mip) {
    case 0: return surface_block_rows<0, kGather>(grid, grid_width, texels, tw, th, soff, toff, width, height, colormap, out);
    case 1: return surface_block_rows<1, kGather>(grid, grid_width, texels, tw, th, soff, toff, width, height, colormap, out);
    case 2: return surface_block_rows<2, kGather>(grid, grid_width, texels, tw, th, soff, toff, width, height, colormap, out);
    default: return surface_block_rows<3, kGather>(grid, grid_width, texels, tw, th, soff, toff, width, height, colormap, out);
  }
}
// Without gathers: asm/surface_block_x86.h's builder (block groups down their rows, indices
// stored and read back, scalar colormap loads) compiled for AVX2 (VEX encoding: no register
// copies).
#include "asm/surface_block_x86.h"
const SurfaceBlockFn surface_block_avx2 = surface_block_x86;
const SurfaceBlockFn surface_block_avx2_gather = surface_block_any<true>;

// ---------------------------------------------------------------- 4. z span

void z_span_avx2(uint16_t* __restrict z, int n, uint32_t zi, uint32_t step) {
  int k = 0;
  if (n >= 16) {
    __m256i z0 = lanes8(zi, step, 0);
    __m256i z1 = add32(z0, _mm256_set1_epi32(int32_t(8 * step)));
    const __m256i s16 = _mm256_set1_epi32(int32_t(16 * step));
    for (; k + 16 <= n; k += 16) {
      // packs works per 128-bit half: [0-3 8-11 | 4-7 12-15]; vpermq puts them in order.
      const __m256i p = _mm256_packs_epi32(_mm256_srai_epi32(z0, 16), _mm256_srai_epi32(z1, 16));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(z + k), _mm256_permute4x64_epi64(p, 0xd8));
      z0 = add32(z0, s16);
      z1 = add32(z1, s16);
    }
    zi += uint32_t(k) * step;
  }
  for (; k < n; ++k) {
    z[k] = uint16_t(zi >> 16);
    zi += step;
  }
}

// ---------------------------------------------------------------- 5. palette expansion

void expand_palette_avx2(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  // Scales 3 and up: one 16-byte store (or more) a pixel and row, as in the SSE2 version.
  if (scale >= 3) return expand_palette_sse2(src, src_stride, width, height, palette, dst, dst_stride, scale);
  const int* pal = reinterpret_cast<const int*>(palette);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    uint32_t* d = dst + ptrdiff_t(y) * scale * dst_stride;
    int x = 0;
    auto gather8 = [&](int at) {
      const __m128i b = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(s + at));
      return _mm256_i32gather_epi32(pal, _mm256_cvtepu8_epi32(b), 4);
    };
    if (scale == 1) {
      for (; x + 8 <= width; x += 8) _mm256_storeu_si256(reinterpret_cast<__m256i*>(d + x), gather8(x));
      for (; x < width; ++x) d[x] = palette[s[x]];
      continue;
    }
    // Scale 2: both output rows stored from the registers (no copy of a written row).
    for (; x + 8 <= width; x += 8) {
      const __m256i c = gather8(x);
      const __m256i lo = _mm256_unpacklo_epi32(c, c), hi = _mm256_unpackhi_epi32(c, c);  // 0 0 1 1 | 4 4 5 5 ...
      const __m256i a = _mm256_permute2x128_si256(lo, hi, 0x20), b = _mm256_permute2x128_si256(lo, hi, 0x31);
      for (int j = 0; j < 2; ++j) {
        uint32_t* p = d + j * dst_stride + 2 * x;
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), a);
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(p + 8), b);
      }
    }
    for (; x < width; ++x) d[2 * x] = d[2 * x + 1] = d[dst_stride + 2 * x] = d[dst_stride + 2 * x + 1] = palette[s[x]];
  }
}

}  // namespace

const Kernels kAvx2 = {"avx2", surface_span_avx2, surface_block_avx2, z_span_avx2, expand_palette_avx2, alias_span_sse2,
                        surface_span_persp_fast, surface_spans_persp_fast};
// The gather versions of the two texel-fetching kernels (slower on the Intel machines
// measured so far; kept for AMD and for the benchmark).
const Kernels kAvx2Gather = {"avx2g", surface_span_avx2_gather, surface_block_avx2_gather, z_span_avx2,
                             expand_palette_avx2, alias_span_sse2, surface_span_persp_fast,
                             surface_spans_persp_fast};

}  // namespace sb::simd::detail

#endif  // __AVX2__
