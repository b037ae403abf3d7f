// asm/neon.cpp: NEON variants for aarch64 and for armv7 with NEON (armhf: this file alone
// is compiled with -mfpu=neon when STARBOW_ARM_NEON is on; see asm/CMakeLists.txt).
// NEON has no gather: the lanes' coordinates, light and addresses are computed in vectors,
// the texel and colormap loads are scalar, and stores are vector where the output is.
//
// Sections: 1. surface span  2. surface block builder  3. z span  4. palette expansion
#include "asm/variants.h"

#if defined(SB_SIMD_HAVE_NEON)
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "SB_SIMD_HAVE_NEON is set but this file is not compiled for NEON"
#endif
#include <arm_neon.h>

#include <cstring>

namespace sb::simd::detail {
namespace {

// Lanes k = 0..3 of a + k d + k (k - 1) / 2 dd (mod 2^32).
inline uint32x4_t lanes4(uint32_t a, uint32_t d, uint32_t dd) {
  const uint32_t v[4] = {a, a + d, a + 2 * d + dd, a + 3 * d + 3 * dd};
  return vld1q_u32(v);
}

// ---------------------------------------------------------------- 1. surface span

void surface_span_neon(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, int width, int,
                       int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  if (n <= 0) return;
  const uint32_t du_ = uint32_t(du), dv_ = uint32_t(dv), ddu_ = uint32_t(ddu), ddv_ = uint32_t(ddv);
  // Advancing four pixels: u_{k+4} = u_k + 4 du_k + 6 dd, 4 du_{k+4} = 4 du_k + 16 dd.
  uint32x4_t U = lanes4(uint32_t(u), du_, ddu_), V = lanes4(uint32_t(v), dv_, ddv_);
  uint32x4_t DU = lanes4(4 * du_, 4 * ddu_, 0), DV = lanes4(4 * dv_, 4 * ddv_, 0);
  const uint32x4_t CU = vdupq_n_u32(6 * ddu_), CV = vdupq_n_u32(6 * ddv_);
  const uint32x4_t EU = vdupq_n_u32(16 * ddu_), EV = vdupq_n_u32(16 * ddv_);
  const uint32x4_t W = vdupq_n_u32(uint32_t(width));
  for (int done = 0; done < n; done += 16) {
    uint32x4_t a[4];
    for (int j = 0; j < 4; ++j) {
      a[j] = vmlaq_u32(vshrq_n_u32(U, 16), vshrq_n_u32(V, 16), W);
      U = vaddq_u32(U, vaddq_u32(DU, CU));
      V = vaddq_u32(V, vaddq_u32(DV, CV));
      DU = vaddq_u32(DU, EU);
      DV = vaddq_u32(DV, EV);
    }
    uint8_t* d = dest + done;
    const int m = n - done;
    if (m >= 16) {
      uint8x16_t px = vdupq_n_u8(0);
#define SB_LANE(j, i) px = vsetq_lane_u8(texels[vgetq_lane_u32(a[j], i)], px, 4 * j + i)
      SB_LANE(0, 0); SB_LANE(0, 1); SB_LANE(0, 2); SB_LANE(0, 3);
      SB_LANE(1, 0); SB_LANE(1, 1); SB_LANE(1, 2); SB_LANE(1, 3);
      SB_LANE(2, 0); SB_LANE(2, 1); SB_LANE(2, 2); SB_LANE(2, 3);
      SB_LANE(3, 0); SB_LANE(3, 1); SB_LANE(3, 2); SB_LANE(3, 3);
#undef SB_LANE
      vst1q_u8(d, px);
    } else {
      uint32_t addr[16];
      for (int j = 0; j < 4; ++j) vst1q_u32(addr + 4 * j, a[j]);
      for (int k = 0; k < m; ++k) d[k] = texels[addr[k]];
    }
  }
}

// ---------------------------------------------------------------- 2. surface block builder
//
// Sixteen lanes at a time: 16 >> LB blocks side by side (one block at mip 0, eight at mip 3)
// walked down their B rows, the light numerators in 32-bit lanes stepped by a per-lane delta
// (one vector add per four texels and row). The numerators are kept scaled by 4^mip,
//   n(fx, fy) = (B T(fx) + fy (U(fx) - T(fx))) << 2 mip,  T = g00 (B - fx) + g10 fx,
//   U = g01 (B - fx) + g11 fx,
// so the colormap row (num >> (S + 8)) is byte 2 of every lane at every mip (n < 2^22: byte 3
// is zero). One table lookup per four lanes makes 32-bit indices texel | row << 8; they leave
// the vector two at a time (64-bit lane moves) and the colormap bytes are read by sixteen
// independent scalar loads, packed four to a word, one store per word: an in-order core
// always has another load to issue instead of waiting on one.
// Texture rows are laid out wrapped first ("tiled": surface column x reads run[x]); rows that
// need no wrap are read in place. Every texture row once per call when the texture is shorter
// than the surface (rows repeat) and fits the buffer, else each band's B rows.


// Lanes k = 0..7 (half 0) or 8..15 (half 1) of g[k >> LB].
template <int LB>
inline uint16x8_t spread(const uint16_t* g, int half) {
  if constexpr (LB == 4) {
    return vdupq_n_u16(g[0]);
  } else if constexpr (LB == 3) {
    return vdupq_n_u16(g[half]);
  } else if constexpr (LB == 2) {
    return vcombine_u16(vdup_n_u16(g[2 * half]), vdup_n_u16(g[2 * half + 1]));
  } else {
    const uint16x4_t x = vld1_u16(g + 4 * half);
    const uint16x4x2_t z = vzip_u16(x, x);
    return vcombine_u16(z.val[0], z.val[1]);
  }
}

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
    d = tw;
    while (d < 16) d += tw;  // (no divide)
    for (int k = 0, c = c0; k < d; ++k) {
      dst[k] = row[c];
      if (++c == tw) c = 0;
    }
  }
  for (int x = d; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
}

constexpr int kTileBytes = 16 * (kMaxBlockColumns * 16 + 32);  // B runs of the widest surface

template <int kMip>
void surface_block_groups(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                          int toff, int width, int height, const uint8_t* __restrict colormap,
                          uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, G = 16 / B;
  const int bw = width / B, bh = height / B;
  const int n16 = (width + 15) & ~15, stride = n16 + 16, groups = n16 / 16;
  const int c0 = wrap(soff, tw);
  int t0b = wrap(toff, th);  // texture row of the current band's first row
  alignas(16) uint8_t buf[kTileBytes];  // 64 KiB of stack
  const uint8_t* const tex_end = texels + tw * th;
  // Texture row t's run: in place when it needs no wrap (and 16-lane reads stay inside).
  auto in_place = [&](int t) { return c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end; };
  const bool all_rows = th < height && th * stride <= kTileBytes;
  if (all_rows)
    for (int t = 0; t < th; ++t)
      if (!in_place(t)) tile_row(buf + t * stride, texels + t * tw, tw, c0, n16);

  // Per-lane constants: fx, B - fx (for halves 0 and 1), the index tables.
  uint16_t fxs[16], bfx[16];
  for (int k = 0; k < 16; ++k) {
    fxs[k] = uint16_t(k % B);
    bfx[k] = uint16_t(B - k % B);
  }
  const uint16x8_t FX[2] = {vld1q_u16(fxs), vld1q_u16(fxs + 8)};
  const uint16x8_t BX[2] = {vld1q_u16(bfx), vld1q_u16(bfx + 8)};
  // Lanes 4j..4j+3: num >> 8 is (fraction, row, 0, 0) bytewise; its byte 0 becomes the texel.
  uint8x16_t IDX[4];
  for (int j = 0; j < 4; ++j) {
    uint8_t b[16];
    for (int l = 0; l < 4; ++l) {
      b[4 * l] = uint8_t(4 * j + l);
      b[4 * l + 1] = b[4 * l + 2] = b[4 * l + 3] = 0xff;
    }
    IDX[j] = vld1q_u8(b);
  }

  // The band's two grid rows with zero padding (lanes past the surface read zeros).
  uint16_t r0[kMaxBlockColumns + 32], r1[kMaxBlockColumns + 32];
  const int cols = bw + 1;
  for (int k = cols; k < kMaxBlockColumns + 32; ++k) r0[k] = r1[k] = 0;
  for (int by = 0; by < bh; ++by) {
    std::memcpy(r0, grid + by * grid_width, size_t(cols) * 2);
    std::memcpy(r1, grid + (by + 1) * grid_width, size_t(cols) * 2);
    const int tb = t0b;  // the band's first texture row (B | th: no wrap inside the band)
    if ((t0b += B) == th) t0b = 0;
    const uint8_t* run[B + 1];
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
    run[B] = run[0];
    uint8_t* const band = out + by * B * width;
    for (int g = 0; g < groups; ++g) {
      uint32x4_t num[4], delta[4];
#pragma GCC unroll 2
      for (int h = 0; h < 2; ++h) {
        const uint16x8_t e00 = spread<LB>(r0 + g * G, h), e10 = spread<LB>(r0 + g * G + 1, h);
        const uint16x8_t e01 = spread<LB>(r1 + g * G, h), e11 = spread<LB>(r1 + g * G + 1, h);
        const uint32x4_t tl = vmlal_u16(vmull_u16(vget_low_u16(e00), vget_low_u16(BX[h])), vget_low_u16(e10),
                                        vget_low_u16(FX[h]));
        const uint32x4_t th_ = vmlal_u16(vmull_u16(vget_high_u16(e00), vget_high_u16(BX[h])),
                                         vget_high_u16(e10), vget_high_u16(FX[h]));
        const uint32x4_t ul = vmlal_u16(vmull_u16(vget_low_u16(e01), vget_low_u16(BX[h])), vget_low_u16(e11),
                                        vget_low_u16(FX[h]));
        const uint32x4_t uh = vmlal_u16(vmull_u16(vget_high_u16(e01), vget_high_u16(BX[h])),
                                        vget_high_u16(e11), vget_high_u16(FX[h]));
        num[2 * h] = vshlq_n_u32(tl, 4 + kMip);
        num[2 * h + 1] = vshlq_n_u32(th_, 4 + kMip);
        if constexpr (kMip == 0) {
          delta[2 * h] = vsubq_u32(ul, tl);
          delta[2 * h + 1] = vsubq_u32(uh, th_);
        } else {
          delta[2 * h] = vshlq_n_u32(vsubq_u32(ul, tl), 2 * kMip);
          delta[2 * h + 1] = vshlq_n_u32(vsubq_u32(uh, th_), 2 * kMip);
        }
      }
      const int m = width - 16 * g;  // lanes on the surface (16 but in the last group)
      uint8_t* d = band + 16 * g;
      // Software-pipelined: row fy + 1's indices are formed while row fy's colormap loads are
      // in flight (run[B] is a readable row: the extra indices after the last row are unused).
      uint64x1_t q[8];  // lanes 2i, 2i + 1
      auto indices = [&](const uint8_t* src) {
        const uint8x16_t t = vld1q_u8(src + 16 * g);
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          const uint8x16_t x = vreinterpretq_u8_u32(vshrq_n_u32(num[j], 8));
#if defined(__aarch64__)
          const uint64x2_t v = vreinterpretq_u64_u8(vqtbx1q_u8(x, t, IDX[j]));
          q[2 * j] = vget_low_u64(v);
          q[2 * j + 1] = vget_high_u64(v);
#else  // d-register halves: no recombination into a q register
          uint8x8x2_t tt;
          tt.val[0] = vget_low_u8(t);
          tt.val[1] = vget_high_u8(t);
          q[2 * j] = vreinterpret_u64_u8(vtbx2_u8(vget_low_u8(x), tt, vget_low_u8(IDX[j])));
          q[2 * j + 1] = vreinterpret_u64_u8(vtbx2_u8(vget_high_u8(x), tt, vget_high_u8(IDX[j])));
#endif
          num[j] = vaddq_u32(num[j], delta[j]);
        }
      };
      indices(run[0]);
      for (int fy = 0; fy < B; ++fy, d += width) {
        uint64_t p[8];
#pragma GCC unroll 8
        for (int i = 0; i < 8; ++i) p[i] = vget_lane_u64(q[i], 0);
        indices(run[fy + 1]);
        uint32_t w[4];
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j)
          w[j] = uint32_t(colormap[uint32_t(p[2 * j])]) | uint32_t(colormap[p[2 * j] >> 32]) << 8 |
                 uint32_t(colormap[uint32_t(p[2 * j + 1])]) << 16 | uint32_t(colormap[p[2 * j + 1] >> 32]) << 24;
        if (m >= 16) {
          const uint64_t lo = w[0] | uint64_t(w[1]) << 32, hi = w[2] | uint64_t(w[3]) << 32;
          std::memcpy(d, &lo, 8);
          std::memcpy(d + 8, &hi, 8);
        } else {
          std::memcpy(d, w, size_t(m));
        }
      }
    }
  }
}

void surface_block_neon(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width, int tex_height,
                        int mip, int soff, int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
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

// ---------------------------------------------------------------- 3. z span

void z_span_neon(uint16_t* __restrict z, int n, uint32_t zi, uint32_t step) {
  int k = 0;
  if (n >= 8) {
    uint32x4_t z0 = lanes4(zi, step, 0);
    uint32x4_t z1 = vaddq_u32(z0, vdupq_n_u32(4 * step));
    const uint32x4_t s8 = vdupq_n_u32(8 * step);
    for (; k + 8 <= n; k += 8) {
      vst1q_u16(z + k, vcombine_u16(vshrn_n_u32(z0, 16), vshrn_n_u32(z1, 16)));
      z0 = vaddq_u32(z0, s8);
      z1 = vaddq_u32(z1, s8);
    }
    zi += uint32_t(k) * step;
  }
  for (; k < n; ++k) {
    z[k] = uint16_t(zi >> 16);
    zi += step;
  }
}

// ---------------------------------------------------------------- 4. palette expansion

void expand_palette_neon(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  const size_t row_bytes = size_t(width) * size_t(scale) * sizeof(uint32_t);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    uint32_t* d = dst + ptrdiff_t(y) * scale * dst_stride;
    int x = 0;
    auto four = [&](int at) {
      uint32x4_t c = vdupq_n_u32(palette[s[at]]);
      c = vsetq_lane_u32(palette[s[at + 1]], c, 1);
      c = vsetq_lane_u32(palette[s[at + 2]], c, 2);
      return vsetq_lane_u32(palette[s[at + 3]], c, 3);
    };
    if (scale <= 4) {
      // vst2q/vst3q/vst4q of copies interleave: c0 c0 c1 c1 ..., c0 c0 c0 c1 ...
      for (; x + 4 <= width; x += 4) {
        const uint32x4_t c = four(x);
        uint32_t* p = d + x * scale;
        if (scale == 1) {
          vst1q_u32(p, c);
        } else if (scale == 2) {
          vst2q_u32(p, (uint32x4x2_t{{c, c}}));
        } else if (scale == 3) {
          vst3q_u32(p, (uint32x4x3_t{{c, c, c}}));
        } else {
          vst4q_u32(p, (uint32x4x4_t{{c, c, c, c}}));
        }
      }
    } else {
      const int q = (scale + 3) / 4;  // as in the SSE2 version: spills overwritten later
      for (; x * scale + 4 * q <= width * scale; ++x) {
        const uint32x4_t c = vdupq_n_u32(palette[s[x]]);
        uint32_t* p = d + x * scale;
        for (int i = 0; i < q; ++i) vst1q_u32(p + 4 * i, c);
      }
    }
    for (; x < width; ++x) {
      const uint32_t c = palette[s[x]];
      for (int i = 0; i < scale; ++i) d[x * scale + i] = c;
    }
    for (int j = 1; j < scale; ++j) std::memcpy(d + j * dst_stride, d, row_bytes);
  }
}

}  // namespace

const Kernels kNeon = {"neon", surface_span_neon, surface_block_neon, z_span_neon, expand_palette_neon, alias_span_neon,
                        surface_span_persp_fast};

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
