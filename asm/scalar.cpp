// asm/scalar.cpp: the scalar references of every kernel (see each kernel's header for the
// contract). These are the definitions the tuned variants must match byte for byte, so
// they are written for clarity first and speed second.

#include "asm/alias_span.h"
#include "asm/palette_expand.h"
#include "asm/surface_block.h"
#include "asm/surface_span.h"
#include "asm/z_span.h"

namespace sb::simd {

void surface_span_scalar(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, int width, int,
                         int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  // Unsigned arithmetic: the recurrence wraps modulo 2^32 (defined), as the contract says.
  uint32_t uu = uint32_t(u), vv = uint32_t(v), duu = uint32_t(du), dvv = uint32_t(dv);
  const uint32_t dduu = uint32_t(ddu), ddvv = uint32_t(ddv);
  const uint32_t w = uint32_t(width);
  for (int k = 0; k < n; ++k) {
    dest[k] = texels[(vv >> 16) * w + (uu >> 16)];
    uu += duu;
    vv += dvv;
    duu += dduu;
    dvv += ddvv;
  }
}

namespace {
inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}
}  // namespace

void surface_block_scalar(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                          int tex_height, int mip, int soff, int toff, int width, int height,
                          const uint8_t* colormap, uint8_t* out) {
  // Block by block: within a block the light numerators are stepped, not re-evaluated:
  //   left(fy)  = g00 (B - fy) + g01 fy   (steps by g01 - g00 per row)
  //   right(fy) = g10 (B - fy) + g11 fy   (steps by g11 - g10 per row)
  //   num(fx)   = left B + (right - left) fx = left (B - fx) + right fx
  const int b = 16 >> mip, shift = 2 * (4 - mip);
  const int tw = tex_width, th = tex_height;
  const int bw = width / b, bh = height / b;
  for (int by = 0; by < bh; ++by) {
    const uint16_t* grow = grid + by * grid_width;
    const int trow = wrap(by * b + toff, th);
    uint8_t* drow = out + by * b * width;
    for (int bx = 0; bx < bw; ++bx) {
      const int32_t g00 = grow[bx], g10 = grow[bx + 1];
      const int32_t g01 = grow[bx + grid_width], g11 = grow[bx + grid_width + 1];
      int32_t left = g00 * b, right = g10 * b;
      const int32_t left_step = g01 - g00, right_step = g11 - g10;
      const uint8_t* src = texels + trow * tw + wrap(bx * b + soff, tw);
      uint8_t* dst = drow + bx * b;
      for (int fy = 0; fy < b; ++fy) {
        int32_t num = left * b;
        const int32_t step = right - left;
        for (int fx = 0; fx < b; ++fx) {
          dst[fx] = colormap[((num >> shift) & 0xff00) + src[fx]];
          num += step;
        }
        left += left_step;
        right += right_step;
        src += tw;
        dst += width;
      }
    }
  }
}

void z_span_scalar(uint16_t* __restrict z, int n, uint32_t zi, uint32_t step) {
  for (int k = 0; k < n; ++k) {
    z[k] = uint16_t(zi >> 16);
    zi += step;
  }
}

void expand_palette_scalar(const uint8_t* src, ptrdiff_t src_stride, int width, int height,
                           const uint32_t* palette, uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  // Each output row written from the source row (no copy of a written row: every variant
  // writes each output row once, so all of their work is in their own code).
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    for (int j = 0; j < scale; ++j) {
      uint32_t* d = dst + (ptrdiff_t(y) * scale + j) * dst_stride;
      if (scale == 1) {
        for (int x = 0; x < width; ++x) d[x] = palette[s[x]];
      } else {
        for (int x = 0; x < width; ++x) {
          const uint32_t c = palette[s[x]];
          for (int i = 0; i < scale; ++i) d[x * scale + i] = c;
        }
      }
    }
  }
}

}  // namespace sb::simd

// ---------------------------------------------------------------- alias-model span

namespace sb::simd {

void alias_span_scalar(uint8_t* __restrict dest, uint16_t* __restrict zbuf, int n, const uint8_t* __restrict skin,
                       int skin_width, const uint8_t* __restrict colormap, const AliasSpan& span) {
  // Unsigned: the contract keeps every value exact, and unsigned steps are defined anyway.
  uint32_t s = uint32_t(span.s), t = uint32_t(span.t), l = uint32_t(span.light), z = span.zi;
  const uint32_t ds = uint32_t(span.ds), dt = uint32_t(span.dt), dl = uint32_t(span.dlight);
  const uint32_t dz = uint32_t(span.dzi), w = uint32_t(skin_width);
  for (int k = 0; k < n; ++k) {
    const uint16_t zz = uint16_t(z >> 16);
    if (zz >= zbuf[k]) {
      dest[k] = colormap[((l >> 16) << 8) + skin[(t >> 16) * w + (s >> 16)]];
      zbuf[k] = zz;
    }
    s += ds;
    t += dt;
    l += dl;
    z += dz;
  }
}

}  // namespace sb::simd
