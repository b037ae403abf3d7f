// asm/z_span.h: the z span fill (16-bit 1/z along a span), contract and scalar reference.
//
//   z[k] = uint16_t(((zi + k * step) mod 2^32) >> 16)        k = 0 .. n-1
//
// zi and step are 16.16 fixed point of the 16-bit z value (1/z * 0x8000 in the engine).
// The caller guarantees that every zi + k step, computed exactly, lies in 0 .. 2^32 - 1
// (then the modular sum is exact; the engine clamps the rare spans that leave that range
// itself). n >= 0, any length; z needs no alignment.
#pragma once
#include <cstdint>

namespace sb::simd {

using ZSpanFn = void (*)(uint16_t* z, int n, uint32_t zi, uint32_t step);

void z_span_scalar(uint16_t* z, int n, uint32_t zi, uint32_t step);

}  // namespace sb::simd
