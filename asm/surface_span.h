// asm/surface_span.h: the lit-surface span kernel (the inner loop of the world's span
// drawer), contract and scalar reference. Variants: asm/kernels.h.
//
//   dest[k] = texels[(v_k >> 16) * width + (u_k >> 16)]                  k = 0 .. n-1
//   u_0 = u, du_0 = du, u_{k+1} = u_k + du_k, du_{k+1} = du_k + ddu     (likewise v)
//
// u, v are 16.16 fixed point texel coordinates, du, dv the per-pixel steps, ddu, ddv the
// per-pixel change of the steps (the second-order term; 0 for Quake's linear stepping).
// Arithmetic is 32-bit two's complement with wrap-around (the vector variants compute
// u_k = u + k du + k (k - 1) / 2 ddu, which equals the recurrence modulo 2^32).
//
// Contract (the caller guarantees; the engine's walker does by construction):
//   n >= 0, any length (the engine passes runs of at most 16);
//   1 <= width, height <= 32767;
//   for every k < n: 0 <= u_k < width << 16 and 0 <= v_k < height << 16;
//   texels: width * height bytes, row-major, row stride = width; no alignment needed;
//   dest: n bytes, no alignment, must not overlap texels.
// Only the n destination bytes are written; no texel outside the surface is read (the
// gather variants mask their lanes beyond n and clamp their 4-byte reads to the surface).
#pragma once
#include <cstdint>

namespace sb::simd {

using SurfaceSpanFn = void (*)(uint8_t* dest, int n, const uint8_t* texels, int width, int height, int32_t u,
                               int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv);

// Scalar reference (asm/scalar.cpp).
void surface_span_scalar(uint8_t* dest, int n, const uint8_t* texels, int width, int height, int32_t u, int32_t v,
                         int32_t du, int32_t dv, int32_t ddu, int32_t ddv);

// Tuned, portable C++ (asm/span_persp_fast.cpp, beside the whole-span drawer whose runs it
// shares): each 16 pixels one straight-line, software-pipelined block (u and v packed in one
// 64-bit register on 64-bit targets, texels gathered into words on ARM); the rest two
// pixels per step. In the NEON table: on every modelled ARM core it beats the lane-based
// NEON loop, which loses to scalar code on 16-pixel runs (moving lanes to core registers
// costs more than the vector arithmetic saves).
void surface_span_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int height, int32_t u, int32_t v,
                       int32_t du, int32_t dv, int32_t ddu, int32_t ddv);

}  // namespace sb::simd
