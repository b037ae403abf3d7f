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
//
// The NEON table's surface_span is the portable surface_span_fast (asm/surface_span.h): a
// lane-based loop (addresses in vectors, each lane moved to a core register for its load)
// lost to scalar code on 16-pixel runs on every modelled core (bench/counts.md).

// ---------------------------------------------------------------- 2. surface block builder
//
// As the SSE2 builder (asm/sse2.cpp, section 2): per texel
//   num = g00 w00 + g10 w10 + g01 w01 + g11 w11 (bilinear weights of fx, fy),
// sixteen texels of a row at a time, here with widening 16 x 16 -> 32-bit multiplies. The
// colormap row (num >> (S + 8), low byte) and the texel interleave into 16-bit indices
// with one vst2q_u8 (little-endian: texel | row << 8).

// Lanes k = 0..7 (half 0) or 8..15 (half 1) of g[bx0 + (k >> LB)].
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

template <int kMip>
void surface_block_rows(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                        int toff, int width, int height, const uint8_t* __restrict colormap,
                        uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, S = 2 * (4 - kMip);
  const int bh = height / B;
  // Copies of the block row's two grid rows with zero padding for partial chunks.
  uint16_t r0[kMaxBlockColumns + 24], r1[kMaxBlockColumns + 24];
  uint16_t fxs[16], bfx[16];  // fx and B - fx of lane k
  for (int k = 0; k < 16; ++k) {
    fxs[k] = uint16_t(k % B);
    bfx[k] = uint16_t(B - k % B);
  }
  const uint16x8_t FX0 = vld1q_u16(fxs), FX1 = vld1q_u16(fxs + 8);
  const uint16x8_t BX0 = vld1q_u16(bfx), BX1 = vld1q_u16(bfx + 8);
  const int cols = width / B + 1;
  const int c0 = wrap(soff, tw);
  alignas(16) uint16_t idx[16];
  uint8_t tmp[16];

  const uint8_t* const tex_end = texels + tw * th;
  uint8_t rowbuf[kRowBufferBytes];
  int ty = wrap(toff, th);  // texture row of surface row y
  for (int by = 0; by < bh; ++by) {
    std::memcpy(r0, grid + by * grid_width, size_t(cols) * 2);
    std::memcpy(r1, grid + (by + 1) * grid_width, size_t(cols) * 2);
    for (int k = cols; k < kMaxBlockColumns + 24; ++k) r0[k] = r1[k] = 0;
    for (int fy = 0; fy < B; ++fy) {
      const int y = by * B + fy;
      const uint16_t wt = uint16_t(B - fy), wb = uint16_t(fy);
      // Weights of halves 0 and 1: w00 = (B - fx) wt, w10 = fx wt, w01 = (B - fx) wb, w11 = fx wb.
      const uint16x8_t w00[2] = {vmulq_n_u16(BX0, wt), vmulq_n_u16(BX1, wt)};
      const uint16x8_t w10[2] = {vmulq_n_u16(FX0, wt), vmulq_n_u16(FX1, wt)};
      const uint16x8_t w01[2] = {vmulq_n_u16(BX0, wb), vmulq_n_u16(BX1, wb)};
      const uint16x8_t w11[2] = {vmulq_n_u16(FX0, wb), vmulq_n_u16(FX1, wb)};
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
          uint16x8_t rows16[2];
          for (int h = 0; h < 2; ++h) {
            const uint16x8_t g00 = spread<LB>(r0 + bx0, h), g10 = spread<LB>(r0 + bx0 + 1, h);
            const uint16x8_t g01 = spread<LB>(r1 + bx0, h), g11 = spread<LB>(r1 + bx0 + 1, h);
            uint32x4_t lo = vmull_u16(vget_low_u16(g00), vget_low_u16(w00[h]));
            lo = vmlal_u16(lo, vget_low_u16(g10), vget_low_u16(w10[h]));
            lo = vmlal_u16(lo, vget_low_u16(g01), vget_low_u16(w01[h]));
            lo = vmlal_u16(lo, vget_low_u16(g11), vget_low_u16(w11[h]));
            uint32x4_t hi = vmull_u16(vget_high_u16(g00), vget_high_u16(w00[h]));
            hi = vmlal_u16(hi, vget_high_u16(g10), vget_high_u16(w10[h]));
            hi = vmlal_u16(hi, vget_high_u16(g01), vget_high_u16(w01[h]));
            hi = vmlal_u16(hi, vget_high_u16(g11), vget_high_u16(w11[h]));
            rows16[h] = vcombine_u16(vshrn_n_u32(lo, S + 8), vshrn_n_u32(hi, S + 8));
          }
          const uint8x16_t rows = vcombine_u8(vmovn_u16(rows16[0]), vmovn_u16(rows16[1]));
          const uint8x16_t t = vld1q_u8(texels16(texrow + i, m, row_end, tmp));
          uint8x16x2_t pair;
          pair.val[0] = t;
          pair.val[1] = rows;
          vst2q_u8(reinterpret_cast<uint8_t*>(idx), pair);
          lookup_n(drow + x + i, colormap, idx, m);
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
    case 0: return surface_block_rows<0>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 1: return surface_block_rows<1>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 2: return surface_block_rows<2>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    default: return surface_block_rows<3>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
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

const Kernels kNeon = {"neon", surface_span_fast, surface_block_neon, z_span_neon, expand_palette_neon, alias_span_neon,
                        surface_span_persp_fast};

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
