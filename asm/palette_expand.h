// asm/palette_expand.h: 8-bit frame -> 32-bit pixels through a 256-entry palette, scaled by
// an integer factor (each source pixel becomes a scale x scale square), for presentation.
//
//   dst[(y * scale + j) * dst_stride + x * scale + i] = palette[src[y * src_stride + x]]
//   for 0 <= x < width, 0 <= y < height, 0 <= i, j < scale
//
// Contract: width, height >= 0; 1 <= scale <= 16; src_stride >= width (bytes);
// dst_stride >= width * scale (in uint32_t pixels); palette: 256 entries (any pixel format:
// the words are copied); no alignment needed; dst must not overlap src or palette.
#pragma once
#include <cstddef>
#include <cstdint>

namespace sb::simd {

using ExpandPaletteFn = void (*)(const uint8_t* src, ptrdiff_t src_stride, int width, int height,
                                 const uint32_t* palette, uint32_t* dst, ptrdiff_t dst_stride, int scale);

void expand_palette_scalar(const uint8_t* src, ptrdiff_t src_stride, int width, int height,
                           const uint32_t* palette, uint32_t* dst, ptrdiff_t dst_stride, int scale);

}  // namespace sb::simd
