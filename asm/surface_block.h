// asm/surface_block.h: the surface block builder (texture x light grid -> lit surface
// through the colormap), contract and scalar reference. Variants: asm/kernels.h.
//
// With B = 16 >> mip (light block size in texels of this mip) and S = 2 * (4 - mip):
//   out[y * width + x] = colormap[((num(x, y) >> S) & 0xff00) + tex(x, y)]
//   tex(x, y) = texels[((y + toff) mod tex_height) * tex_width + (x + soff) mod tex_width]
//               (positive modulo)
//   num(x, y) = (g00 (B - fx) + g10 fx) (B - fy) + (g01 (B - fx) + g11 fx) fy
//   gx = x / B, fx = x % B, gy = y / B, fy = y % B,
//   gAB = grid[(gy + B) * grid_width + gx + A]   (A, B in {0, 1})
// which is engine/render/surface_math.h's shade_at() bilinear light, row = shade >> 8.
//
// Contract:
//   mip in 0..3; width, height >= 0 and multiples of B (0 draws nothing);
//   tex_width, tex_height >= B and multiples of B; soff, toff multiples of B (any sign);
//   grid: (height / B + 1) rows of grid_width >= width / B + 1 entries, each <= 0x3fff
//   (a shade: colormap row 0..63 in the high byte);
//   colormap: 64 rows of 256 bytes (exactly 16384 bytes are enough; gathers clamp);
//   texels: tex_width * tex_height bytes; out: width * height bytes, row stride = width;
//   no alignment needed anywhere; out must not overlap the inputs.
// Tuned variants handle width / B <= kMaxBlockColumns (256: every face extent up to 4096)
// and fall back to the scalar reference beyond.
#pragma once
#include <cstdint>

namespace sb::simd {

constexpr int kMaxBlockColumns = 256;

using SurfaceBlockFn = void (*)(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                                int tex_height, int mip, int soff, int toff, int width, int height,
                                const uint8_t* colormap, uint8_t* out);

// Scalar reference (asm/scalar.cpp): block by block, light numerators stepped per texel.
void surface_block_scalar(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                          int tex_height, int mip, int soff, int toff, int width, int height,
                          const uint8_t* colormap, uint8_t* out);

}  // namespace sb::simd
