// asm/alias_span_v7.h: the ARMv7 (Thumb-2 + NEON) span of alias_span_neon
// (asm/alias_span_simd.cpp), whole groups of 8 pixels, as one asm statement. Internal: included
// by asm/alias_span_simd.cpp only. The loop body's order was searched for the Cortex-A9 model
// (bench/mca_a9_alias/README.md: edit body_in.s there and search again, then copy the result
// between BEGIN and END with bench/mca_a9_alias/inline.py).
//
// One group of 8 pixels an iteration, from the lane state at its first pixel (q8 .. q11: s, t,
// light, z for lanes 0 .. 3; q12 .. q15 the steps of 4 pixels): the z test and the z buffer's
// new contents (one load, one store), the 8 skin offsets and colormap rows interleaved into a
// 64-byte buffer, then the 8 texels fetched by core loads (the contract keeps every lane in
// range), packed into two words and blended into dest under the visibility mask. The groups
// start at pixels 0, r, r + 8, .., n - 8 (r = n % 8, or 8): when r < 8 the first two overlap,
// which draws the same bytes again (a drawn pixel's z now equals its own z, so it passes again
// and draws the same texel; a hidden one stays hidden). After group 0 the state and the
// pointers are set to pixel r once.
//
// Contract: n >= 8; a is the span (asm/alias_span.h's contract for all n pixels); w is the
// skin width; dest, zbuf, skin and colormap as there.
#pragma once
#if defined(__arm__) && !defined(__aarch64__)
#include <cstddef>
#include <cstdint>

#include "asm/alias_span.h"

namespace sb::simd::detail {

// The set-up loads AliasSpan's fields as two q registers: s, t, light, zi | ds, dt, dlight, dzi.
static_assert(offsetof(AliasSpan, s) == 0 && offsetof(AliasSpan, t) == 4 && offsetof(AliasSpan, light) == 8 &&
              offsetof(AliasSpan, zi) == 12 && offsetof(AliasSpan, ds) == 16 && offsetof(AliasSpan, dt) == 20 &&
              offsetof(AliasSpan, dlight) == 24 && offsetof(AliasSpan, dzi) == 28);

[[gnu::always_inline]] inline void alias_span_v7(uint8_t* dest, uint16_t* zbuf, int n, const uint8_t* skin,
                                                 const uint8_t* colormap, const AliasSpan& a, uint32_t w) {
  alignas(16) uint64_t buf[8];  // lane j: skin offset in the low word, colormap row offset in the high
  static constexpr uint16_t kIndex[4] = {0, 1, 2, 3};
  const uint32_t r = uint32_t(n) & 7;  // 0: the groups end at n - 1 without an overlap
  register uint8_t* d asm("r0") = dest;
  register uint16_t* zb asm("r1") = zbuf;
  register uint64_t* bp asm("r2") = buf;
  register uint32_t groups asm("r3") = 1 + (uint32_t(n) - (r ? r : 8)) / 8;
  register uint32_t k asm("r4") = w;  // the skin width, then the state's first pixel
  register const uint16_t* ix asm("r5") = kIndex;
  register const uint8_t* sk asm("r10") = skin;
  register const uint8_t* cm asm("r11") = colormap;
  register const AliasSpan* ap asm("r12") = &a;
  register uint32_t fix asm("lr") = r;  // nonzero until the state has moved to pixel r
  __asm__ volatile(
      "vld1.16 {d6}, [r5]\n\t"  // lane indices 0 .. 3
      "vdup.16 d7, r4\n\t"      // w in d7[0] (vmlal's scalar)
      "vld1.32 {d0-d3}, [r12]\n\t"
      "mov r4, #0\n\t"
      "vdup.32 q12, d2[0]\n\t"  // the steps of 4 pixels
      "vdup.32 q13, d2[1]\n\t"
      "vdup.32 q14, d3[0]\n\t"
      "vdup.32 q15, d3[1]\n\t"
      "vshl.i32 q12, q12, #2\n\t"
      "vshl.i32 q13, q13, #2\n\t"
      "vshl.i32 q14, q14, #2\n\t"
      "vshl.i32 q15, q15, #2\n\t"
      "1:\n\t"  // the lane state at pixel r4
      "vld1.32 {d0-d3}, [r12]\n\t"
      "vmovl.u16 q2, d6\n\t"
      "vdup.32 q4, r4\n\t"
      "vadd.i32 q2, q2, q4\n\t"
      "vdup.32 q8, d0[0]\n\t"
      "vdup.32 q9, d0[1]\n\t"
      "vdup.32 q10, d1[0]\n\t"
      "vdup.32 q11, d1[1]\n\t"
      "vmla.i32 q8, q2, d2[0]\n\t"
      "vmla.i32 q9, q2, d2[1]\n\t"
      "vmla.i32 q10, q2, d3[0]\n\t"
      "vmla.i32 q11, q2, d3[1]\n\t"
      "2:\n\t"
      // BEGIN alias_v7_body
      "vadd.i32 q0, q8, q12\n\t"
      "vadd.i32 q2, q11, q15\n\t"
      "vadd.i32 q1, q9, q13\n\t"
      "vld1.16 {d10-d11}, [r1]\n\t"
      "vshrn.i32 d8, q11, #16\n\t"
      "vshrn.i32 d9, q2, #16\n\t"
      "vshrn.i32 d4, q9, #16\n\t"
      "vshr.u32 q7, q0, #16\n\t"
      "vcge.u16 q6, q4, q5\n\t"
      "subs r3, r3, #1\n\t"
      "vshrn.i32 d5, q1, #16\n\t"
      "vadd.i32 q0, q10, q14\n\t"
      "vmlal.u16 q7, d5, d7[0]\n\t"
      "vbit q5, q4, q6\n\t"
      "vst1.16 {d10-d11}, [r1]!\n\t"
      "vshr.u32 q5, q10, #16\n\t"
      "vshr.u32 q4, q8, #16\n\t"
      "vmlal.u16 q4, d4, d7[0]\n\t"
      "vshr.u32 q1, q0, #16\n\t"
      "vmov q0, q7\n\t"
      "vshl.i32 q5, q5, #8\n\t"
      "vst2.32 {d8-d11}, [r2:128]!\n\t"
      "vshl.i32 q1, q1, #8\n\t"
      "vst2.32 {d0-d3}, [r2:128]\n\t"
      "ldrd r4, r5, [r2, #-32]\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r6, [r11, r5]\n\t"
      "ldrd r4, r5, [r2, #-24]\n\t"
      "vmovn.i16 d12, q6\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r6, r6, r5, lsl #8\n\t"
      "ldrd r4, r5, [r2, #-16]\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r6, r6, r5, lsl #16\n\t"
      "ldrd r4, r5, [r2, #-8]\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "vadd.i32 q9, q9, q13\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r6, r6, r5, lsl #24\n\t"
      "ldrd r4, r5, [r2, #0]\n\t"
      "vmov r8, r9, d12\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r7, [r11, r5]\n\t"
      "ldrd r4, r5, [r2, #8]\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r7, r7, r5, lsl #8\n\t"
      "ldrd r4, r5, [r2, #16]\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "vadd.i32 q10, q10, q14\n\t"
      "vadd.i32 q8, q8, q12\n\t"
      "add r5, r5, r4\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r7, r7, r5, lsl #16\n\t"
      "ldrd r4, r5, [r2, #24]\n\t"
      "vadd.i32 q8, q8, q12\n\t"
      "vadd.i32 q11, q11, q15\n\t"
      "ldrb r4, [r10, r4]\n\t"
      "add r5, r5, r4\n\t"
      "ldr r4, [r0]\n\t"
      "sub r2, r2, #32\n\t"
      "eor r6, r6, r4\n\t"
      "vadd.i32 q9, q9, q13\n\t"
      "ldrb r5, [r11, r5]\n\t"
      "orr r7, r7, r5, lsl #24\n\t"
      "ldr r5, [r0, #4]\n\t"
      "eor r7, r7, r5\n\t"
      "and r6, r6, r8\n\t"
      "eor r6, r6, r4\n\t"
      "vadd.i32 q11, q11, q15\n\t"
      "and r7, r7, r9\n\t"
      "eor r7, r7, r5\n\t"
      "str r7, [r0, #4]\n\t"
      "vadd.i32 q10, q10, q14\n\t"
      "str r6, [r0], #8\n\t"
      // END alias_v7_body
      "beq 3f\n\t"  // the last group drawn
      "cmp lr, #0\n\t"
      "beq 2b\n\t"
      // after group 0, when n % 8 != 0: on from pixel r (dest and zbuf back by 8 - r)
      "mov r4, lr\n\t"
      "sub r5, lr, #8\n\t"
      "add r0, r0, r5\n\t"
      "add r1, r1, r5, lsl #1\n\t"
      "mov lr, #0\n\t"
      "b 1b\n\t"
      "3:\n\t"
      : "+r"(d), "+r"(zb), "+r"(bp), "+r"(groups), "+r"(k), "+r"(ix), "+r"(fix)
      : "r"(sk), "r"(cm), "r"(ap), "m"(a), "m"(kIndex)
      : "r6", "r7", "r8", "r9", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12",
        "d13", "d14", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27",
        "d28", "d29", "d30", "d31", "cc", "memory");
}

}  // namespace sb::simd::detail

#endif
