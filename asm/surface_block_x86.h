// asm/surface_block_x86.h: internal to asm/: the x86 surface block builder, shared by
// asm/sse2.cpp (SSE2) and asm/avx2.cpp (the same source compiled with -mavx2: VEX encoding).
// Include it inside an anonymous namespace after <emmintrin.h> and <cstring>, and after
// asm/variants.h (wrap, kMaxBlockColumns, surface_block_scalar): each file gets its own
// internal copy, so the AVX2 instance can never stand in for the SSE2 one at link time.
//
// As the NEON builder (asm/neon.cpp, section 2): sixteen lanes (16 >> LB blocks side by side)
// walked down their B rows, the light numerators in 32-bit lanes scaled by 4^mip so that the
// colormap row is byte 2 of every lane, stepped by one vector add per four texels and row.
// The lanes' first numerators come from pmaddwd of grid pairs (g00, g10) with weight pairs
// (B - fx, fx). Indices ((num >> 8) & ~0xff) | texel leave the vector two at a time (64-bit
// moves); the sixteen colormap loads are independent and are packed into two 64-bit stores.

// dst[x] = row[(c0 + x) mod tw] for x < n (a multiple of 16); writes up to n + 15 (and at
// least 32 bytes must be writable).
inline void tile_row(uint8_t* dst, const uint8_t* row, int tw, int c0, int n) {
  int d;  // a period of the run, >= 16
  if (tw >= 16) {
    const int a = tw - c0 < n ? tw - c0 : n;
    std::memcpy(dst, row + c0, size_t(a));
    if (a < n) std::memcpy(dst + a, row, size_t(c0 < n - a ? c0 : n - a));
    d = tw;
  } else {
    d = tw * ((16 + tw - 1) / tw);
    for (int k = 0, c = c0; k < d; ++k) {
      dst[k] = row[c];
      if (++c == tw) c = 0;
    }
  }
  for (int x = d; x < n; x += 16)
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + x), _mm_loadu_si128(reinterpret_cast<const __m128i*>(dst + x - d)));
}

constexpr int kTileBytes = 16 * (kMaxBlockColumns * 16 + 32);  // B runs of the widest surface

template <int kMip>
void surface_block_groups(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                          int toff, int width, int height, const uint8_t* __restrict colormap,
                          uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, G = 16 / B;
  const int bw = width / B, bh = height / B;
  const int n16 = (width + 15) & ~15, stride = n16 + 16, groups = n16 / 16;
  const int c0 = wrap(soff, tw), t0 = wrap(toff, th);
  alignas(16) uint8_t buf[kTileBytes];  // 64 KiB of stack
  const uint8_t* const tex_end = texels + tw * th;
  auto in_place = [&](int t) { return c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end; };
  const bool all_rows = th < height && th * stride <= kTileBytes;
  if (all_rows)
    for (int t = 0; t < th; ++t)
      if (!in_place(t)) tile_row(buf + t * stride, texels + t * tw, tw, c0, n16);

  // Lanes k = 4j + i: weight pairs (B - fx, fx) << (4 + mip) for the first numerator (the
  // scaled B T, at most 256 per weight: pmaddwd's signed factors stay exact) and << 2 mip for
  // the row step (U - T).
  __m128i A0[4], A1[4];
  for (int j = 0; j < 4; ++j) {
    auto pat = [](int k, int s) { return int32_t((B - k % B) << s | (k % B) << (16 + s)); };
    A0[j] = _mm_setr_epi32(pat(4 * j, 4 + kMip), pat(4 * j + 1, 4 + kMip), pat(4 * j + 2, 4 + kMip),
                           pat(4 * j + 3, 4 + kMip));
    A1[j] = _mm_setr_epi32(pat(4 * j, 2 * kMip), pat(4 * j + 1, 2 * kMip), pat(4 * j + 2, 2 * kMip),
                           pat(4 * j + 3, 2 * kMip));
  }
  const __m128i keep = _mm_set1_epi32(int32_t(0xffffff00u)), zero = _mm_setzero_si128();
  // (g[bx], g[bx + 1]) of the band's top (p0) and bottom (p1) grid rows, zero padded.
  // Each grid row's pairs are made once: a band's bottom row is the next band's top.
  alignas(16) uint32_t pa[kMaxBlockColumns + 16], pb[kMaxBlockColumns + 16];
  uint32_t *p0 = pa, *p1 = pb;
  for (int bx = bw; bx < bw + 16; ++bx) pa[bx] = pb[bx] = 0;
  for (int by = 0; by < bh; ++by) {
    const uint16_t* g1 = grid + (by + 1) * grid_width;
    auto pairs = [&](const uint16_t* g, uint32_t* p) {
      int bx = 0;
      for (; bx + 8 <= bw; bx += 8) {  // reads g[bx .. bx + 8]: inside the row (bw + 1 entries)
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g + bx));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(g + bx + 1));
        _mm_store_si128(reinterpret_cast<__m128i*>(p + bx), _mm_unpacklo_epi16(a, b));
        _mm_store_si128(reinterpret_cast<__m128i*>(p + bx + 4), _mm_unpackhi_epi16(a, b));
      }
      for (; bx < bw; ++bx) p[bx] = uint32_t(g[bx]) | uint32_t(g[bx + 1]) << 16;
    };
    if (by == 0) {
      pairs(grid, p0);
    } else {
      uint32_t* const s = p0;
      p0 = p1;
      p1 = s;
    }
    pairs(g1, p1);
    const int tb = (t0 + by * B) % th;  // the band's first texture row (B | th: no wrap inside)
    const uint8_t* run[B];
    for (int fy = 0; fy < B; ++fy) {
      const int t = tb + fy;
      if (in_place(t)) {
        run[fy] = texels + t * tw + c0;
      } else if (all_rows) {
        run[fy] = buf + t * stride;
      } else {
        tile_row(buf + fy * stride, texels + t * tw, tw, c0, n16);
        run[fy] = buf + fy * stride;
      }
    }
    uint8_t* const band = out + by * B * width;
    for (int g = 0; g < groups; ++g) {
      const int bx0 = g * G;
      __m128i num[4], delta[4];
#pragma GCC unroll 4
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
        num[j] = _mm_madd_epi16(e0, A0[j]);
        delta[j] = _mm_sub_epi32(_mm_madd_epi16(e1, A1[j]), _mm_madd_epi16(e0, A1[j]));
      }
      const int m = width - 16 * g;  // lanes on the surface (16 but in the last group)
      uint8_t* d = band + 16 * g;
      for (int fy = 0; fy < B; ++fy, d += width) {
        const __m128i t = _mm_loadu_si128(reinterpret_cast<const __m128i*>(run[fy] + 16 * g));
        const __m128i lo = _mm_unpacklo_epi8(t, zero), hi = _mm_unpackhi_epi8(t, zero);
        const __m128i t32[4] = {_mm_unpacklo_epi16(lo, zero), _mm_unpackhi_epi16(lo, zero),
                                _mm_unpacklo_epi16(hi, zero), _mm_unpackhi_epi16(hi, zero)};
        uint64_t p[8];
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          const __m128i idx = _mm_or_si128(_mm_and_si128(_mm_srli_epi32(num[j], 8), keep), t32[j]);
          num[j] = _mm_add_epi32(num[j], delta[j]);
          p[2 * j] = uint64_t(_mm_cvtsi128_si64(idx));
          p[2 * j + 1] = uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(idx, idx)));
        }
        uint64_t w[2];
#pragma GCC unroll 2
        for (int h = 0; h < 2; ++h) {
          uint64_t v = 0;
#pragma GCC unroll 4
          for (int i = 0; i < 4; ++i) {
            const uint64_t x = p[4 * h + i];
            v |= uint64_t(colormap[uint32_t(x)]) << (16 * i) | uint64_t(colormap[x >> 32]) << (16 * i + 8);
          }
          w[h] = v;
        }
        if (m >= 16) {
          std::memcpy(d, w, 16);
        } else {
          std::memcpy(d, w, size_t(m));
        }
      }
    }
  }
}

inline void surface_block_x86(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                              int tex_height, int mip, int soff, int toff, int width, int height,
                              const uint8_t* colormap, uint8_t* out) {
  if (width <= 0 || height <= 0) return;
  if (width / (16 >> mip) > kMaxBlockColumns || mip < 0 || mip > 3) {
    surface_block_scalar(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap,
                         out);
    return;
  }
  switch (mip) {
    case 0: return surface_block_groups<0>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 1: return surface_block_groups<1>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 2: return surface_block_groups<2>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    default: return surface_block_groups<3>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
  }
}
