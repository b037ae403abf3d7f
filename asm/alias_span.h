// asm/alias_span.h: the alias-model span drawer (one horizontal span of a z-buffered,
// affinely textured, Gouraud-lit model triangle), contract and scalar reference.
// Variants: asm/kernels.h.
//
// For k = 0 .. n-1, with every quantity stepped linearly from its value at the span's first
// pixel (32-bit two's complement; the contract below keeps every value exact):
//   z_k = zi + k dzi        (16.16 fixed point of the 16-bit z: 1/z * 0x8000, as z_span)
//   s_k = s + k ds,  t_k = t + k dt                  (16.16 skin texel coordinates)
//   l_k = light + k dlight                           (16.16 colormap row, 0 = brightest)
//   if (z_k >> 16) >= zbuf[k]:                       (not farther than what is there)
//     dest[k] = colormap[(l_k >> 16) * 256 + skin[(t_k >> 16) * skin_width + (s_k >> 16)]]
//     zbuf[k] = z_k >> 16
//   else dest[k] and zbuf[k] keep their bytes.
// Equal z draws: the 16-bit z of distant objects is coarse, and a model standing on the floor
// must not lose its feet to the floor it was drawn after (the world is drawn first).
//
// Contract (the caller guarantees; nothing is checked):
//   n >= 0, any length;
//   1 <= skin_width, skin_height <= 32767; skin: skin_width * skin_height bytes, row-major;
//   for EVERY k < n, whether or not the pixel is hidden (vector variants fetch texels for
//   all pixels and discard the hidden ones):
//     0 <= s_k < skin_width << 16,  0 <= t_k < skin_height << 16,
//     0 <= l_k < 64 << 16,          0 <= z_k <= 0xffffffff (computed exactly, no wrap);
//   colormap: 64 rows of 256 bytes; dest: n bytes; zbuf: n uint16_t;
//   no alignment needed anywhere; dest, zbuf, skin and colormap must not overlap.
// Then no byte outside skin, colormap, dest[0 .. n-1] and zbuf[0 .. n-1] is read, and only
// dest[0 .. n-1] and zbuf[0 .. n-1] are written.
#pragma once
#include <cstdint>

namespace sb::simd {

// The span's values at its first pixel and their per-pixel steps (see above for units).
struct AliasSpan {
  int32_t s, t;       // 16.16 skin coordinates
  int32_t light;      // 16.16 colormap row
  uint32_t zi;        // 16.16 of the 16-bit z
  int32_t ds, dt, dlight, dzi;
};

using AliasSpanFn = void (*)(uint8_t* dest, uint16_t* zbuf, int n, const uint8_t* skin, int skin_width,
                             const uint8_t* colormap, const AliasSpan& span);

// Scalar reference (asm/scalar.cpp).
void alias_span_scalar(uint8_t* dest, uint16_t* zbuf, int n, const uint8_t* skin, int skin_width,
                       const uint8_t* colormap, const AliasSpan& span);

}  // namespace sb::simd
