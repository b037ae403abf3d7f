// asm/span_persp_a64tiny.h: aarch64 only: the batch entry's second-order spans of 1 .. 16
// pixels (asm/span_persp_a64tiny.cpp: two neighbouring ones at a time in 2-lane vectors),
// for asm/span_persp_fast.cpp: batch_from's runs of them, persp_fast<true>'s lone ones.
#pragma once
#include <cstdint>

#include "asm/span_persp.h"

namespace sb::simd {

#if defined(__aarch64__) && defined(__GNUC__)
// A batch item tiny_curve_run_a64 draws: 1 <= n <= 16, second order, dzi != 0 on its bits
// (NaN and the infinities are non-zero; an integer load, no FP compare).
inline bool tiny_curve_a64(const PerspItem& x) {
  uint64_t bits;
  __asm__("ldr %x0, %1" : "=r"(bits) : "m"(x.span.dzi));
  return (uint32_t(x.n) - 1u < 16u) & x.span.second_order & ((bits << 1) != 0);
}
// Draws items from it on while they are second-order (second_order, dzi != 0 on its bits)
// spans of 1 .. 16 pixels (it is one); returns the first item that is not one (or end). The
// bytes are surface_span_persp_scalar's for each item (asm/span_persp.h's contract).
const PerspItem* tiny_curve_run_a64(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
// One such span (1 <= n <= 16, second order, dzi != 0): SurfaceSpanPerspFn's bytes.
void tiny_one_a64(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p);
#endif

}  // namespace sb::simd
