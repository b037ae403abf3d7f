// asm/neon_palette.h: expand_palette_neon (asm/palette_expand.h's contract), section 4 of
// asm/neon.cpp, kept apart for the file's size. Only asm/neon.cpp includes this (the
// definition is internal to it).
#pragma once
#include <arm_neon.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace sb::simd::detail {
namespace {

#if !defined(__aarch64__)
// Scales 2 .. 4 on ARMv7: one asm loop each, 4 source pixels an iteration, every output row
// stored in the loop (no second pass copying the first output row to the others): the indices
// as one core load, the colours by core loads, the output words built in d registers by vdup
// (c, c) or, at scale 3, one vmov (a, b) from two core registers, each row stored by vst1 of up
// to four d registers, the pointer walking down the S rows and back by register
// post-increments (bench/mca_a53_palette/gen_scales.py --v7 writes the naive bodies,
// order_search.py --arch=armv7 searched their order for the Cortex-A9 model). Returns the
// pixels done (a multiple of 4).
template <int S>
int expand_rows_v7(const uint8_t* s, int width, const uint32_t* palette, uint32_t* d, ptrdiff_t dst_stride) {
  static_assert(S >= 2 && S <= 4);
  const int n = width & -4;
  if (n == 0) return 0;
  const uint8_t* sp = s;
  const uint8_t* const end = s + n;
  uint32_t* p = d;
  const ptrdiff_t st = dst_stride * ptrdiff_t(sizeof(uint32_t));  // bytes
  const ptrdiff_t group = 16 * S;                                // one row's bytes of 4 pixels
  // Between rows: from the row's last store to the next row (scale 2: one 32-byte store a row;
  // 3 and 4: the first store post-increments by 32 itself). After the last row: to the next
  // group's first row.
  const ptrdiff_t next_row = S == 2 ? st : st - 32;
  const ptrdiff_t next_group = group - (S == 2 ? 0 : 32) - (S - 1) * st;
  if constexpr (S == 2) {
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_v7_scale2
        "ldr r3, [%[s]], #4\n\t"
        "uxtb r4, r3\n\t"
        "ubfx r5, r3, #8, #8\n\t"
        "ubfx r6, r3, #16, #8\n\t"
        "ldr r4, [%[pal], r4, lsl #2]\n\t"
        "vdup.32 d16, r4\n\t"
        "ldr r5, [%[pal], r5, lsl #2]\n\t"
        "lsrs r3, r3, #24\n\t"
        "cmp %[s], %[e]\n\t"
        "ldr r6, [%[pal], r6, lsl #2]\n\t"
        "vdup.32 d17, r5\n\t"
        "ldr r3, [%[pal], r3, lsl #2]\n\t"
        "vdup.32 d18, r6\n\t"
        "vdup.32 d19, r3\n\t"
        "vst1.32 {d16-d19}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]], %[ng]\n\t"
        // END palette_v7_scale2
        "bne 1b\n\t"
        : [p] "+r"(p), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette), [nr] "r"(next_row), [ng] "r"(next_group)
        : "r3", "r4", "r5", "r6", "d16", "d17", "d18", "d19", "cc", "memory");
  } else if constexpr (S == 3) {
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_v7_scale3
        "ldr r3, [%[s]], #4\n\t"
        "uxtb r4, r3\n\t"
        "ubfx r5, r3, #8, #8\n\t"
        "ubfx r6, r3, #16, #8\n\t"
        "ldr r4, [%[pal], r4, lsl #2]\n\t"
        "ldr r5, [%[pal], r5, lsl #2]\n\t"
        "ldr r6, [%[pal], r6, lsl #2]\n\t"
        "lsrs r3, r3, #24\n\t"
        "ldr r3, [%[pal], r3, lsl #2]\n\t"
        "vdup.32 d16, r4\n\t"
        "vmov d17, r4, r5\n\t"
        "vdup.32 d18, r5\n\t"
        "vdup.32 d19, r6\n\t"
        "vmov d20, r6, r3\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vdup.32 d21, r3\n\t"
        "vst1.32 {d20-d21}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vst1.32 {d20-d21}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vst1.32 {d20-d21}, [%[p]], %[ng]\n\t"
        "cmp %[s], %[e]\n\t"
        // END palette_v7_scale3
        "bne 1b\n\t"
        : [p] "+r"(p), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette), [nr] "r"(next_row), [ng] "r"(next_group)
        : "r3", "r4", "r5", "r6", "d16", "d17", "d18", "d19", "d20", "d21", "cc", "memory");
  } else {
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_v7_scale4
        "ldr r3, [%[s]], #4\n\t"
        "uxtb r4, r3\n\t"
        "ubfx r5, r3, #8, #8\n\t"
        "ubfx r6, r3, #16, #8\n\t"
        "ldr r4, [%[pal], r4, lsl #2]\n\t"
        "ldr r5, [%[pal], r5, lsl #2]\n\t"
        "lsrs r3, r3, #24\n\t"
        "ldr r6, [%[pal], r6, lsl #2]\n\t"
        "ldr r3, [%[pal], r3, lsl #2]\n\t"
        "vdup.32 q8, r4\n\t"
        "vdup.32 q9, r5\n\t"
        "vdup.32 q10, r6\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vdup.32 q11, r3\n\t"
        "vst1.32 {d20-d23}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vst1.32 {d20-d23}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "vst1.32 {d20-d23}, [%[p]], %[nr]\n\t"
        "vst1.32 {d16-d19}, [%[p]]!\n\t"
        "cmp %[s], %[e]\n\t"
        "vst1.32 {d20-d23}, [%[p]], %[ng]\n\t"
        // END palette_v7_scale4
        "bne 1b\n\t"
        : [p] "+r"(p), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette), [nr] "r"(next_row), [ng] "r"(next_group)
        : "r3", "r4", "r5", "r6", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "cc", "memory");
  }
  return n;
}
#endif

#if defined(__aarch64__)
// Scales 2 .. 4 on aarch64: one asm loop each, G = 16 (scale 2) or 8 source pixels an iteration,
// every output row stored in the loop (bench/mca_a53_palette/gen_scales.py writes the naive
// bodies, bench/order_search.py searched their order for the Cortex-A53 model; README there).
// Scales 2 and 3: each colour doubled to a 64-bit (c, c) by one orr, scale 3's pairs of colours
// a, b as (a, a) (a, b) (b, b), stored by stp; scale 4: (c, c, c, c) by dup, stored as q pairs.
// Returns the pixels done (a multiple of G).
template <int S>
int expand_rows_a64(const uint8_t* s, int width, const uint32_t* palette, uint32_t* d, ptrdiff_t dst_stride) {
  constexpr int kG = S == 2 ? 16 : 8;
  const int n = width & -kG;
  if (n == 0) return 0;
  const uint8_t* sp = s;
  uint32_t* r0 = d;
  uint32_t* r1 = d + dst_stride;
  uint32_t* const end = d + ptrdiff_t(n) * S;
  if constexpr (S == 2) {
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_scale2
        "ldp x4, x14, [%[s]], #16\n\t"
        "ubfx x5, x4, #24, #8\n\t"
        "ubfx x7, x4, #40, #8\n\t"
        "ubfx x6, x4, #32, #8\n\t"
        "and x1, x4, #0xff\n\t"
        "ubfx x8, x4, #48, #8\n\t"
        "ubfx x3, x4, #16, #8\n\t"
        "ubfx x2, x4, #8, #8\n\t"
        "lsr x4, x4, #56\n\t"
        "ubfx x15, x14, #32, #8\n\t"
        "ldr w6, [%[pal], x6, lsl #2]\n\t"
        "ubfx x17, x14, #48, #8\n\t"
        "ubfx x11, x14, #8, #8\n\t"
        "ubfx x13, x14, #24, #8\n\t"
        "ubfx x16, x14, #40, #8\n\t"
        "ubfx x12, x14, #16, #8\n\t"
        "ldr w2, [%[pal], x2, lsl #2]\n\t"
        "and x10, x14, #0xff\n\t"
        "ldr w15, [%[pal], x15, lsl #2]\n\t"
        "orr x6, x6, x6, lsl #32\n\t"
        "ldr w7, [%[pal], x7, lsl #2]\n\t"
        "ldr w5, [%[pal], x5, lsl #2]\n\t"
        "lsr x14, x14, #56\n\t"
        "ldr w3, [%[pal], x3, lsl #2]\n\t"
        "ldr w4, [%[pal], x4, lsl #2]\n\t"
        "ldr w1, [%[pal], x1, lsl #2]\n\t"
        "ldr w10, [%[pal], x10, lsl #2]\n\t"
        "orr x2, x2, x2, lsl #32\n\t"
        "ldr w11, [%[pal], x11, lsl #2]\n\t"
        "orr x5, x5, x5, lsl #32\n\t"
        "ldr w8, [%[pal], x8, lsl #2]\n\t"
        "orr x7, x7, x7, lsl #32\n\t"
        "ldr w17, [%[pal], x17, lsl #2]\n\t"
        "orr x1, x1, x1, lsl #32\n\t"
        "ldr w13, [%[pal], x13, lsl #2]\n\t"
        "ldr w12, [%[pal], x12, lsl #2]\n\t"
        "orr x3, x3, x3, lsl #32\n\t"
        "ldr w14, [%[pal], x14, lsl #2]\n\t"
        "orr x11, x11, x11, lsl #32\n\t"
        "stp x1, x2, [%[r0], #0]\n\t"
        "orr x8, x8, x8, lsl #32\n\t"
        "ldr w16, [%[pal], x16, lsl #2]\n\t"
        "orr x10, x10, x10, lsl #32\n\t"
        "orr x17, x17, x17, lsl #32\n\t"
        "orr x13, x13, x13, lsl #32\n\t"
        "orr x4, x4, x4, lsl #32\n\t"
        "orr x15, x15, x15, lsl #32\n\t"
        "stp x3, x5, [%[r0], #16]\n\t"
        "orr x16, x16, x16, lsl #32\n\t"
        "stp x6, x7, [%[r0], #32]\n\t"
        "orr x12, x12, x12, lsl #32\n\t"
        "stp x8, x4, [%[r0], #48]\n\t"
        "orr x14, x14, x14, lsl #32\n\t"
        "stp x10, x11, [%[r0], #64]\n\t"
        "stp x12, x13, [%[r0], #80]\n\t"
        "stp x15, x16, [%[r0], #96]\n\t"
        "stp x17, x14, [%[r0], #112]\n\t"
        "stp x1, x2, [%[r1], #0]\n\t"
        "add %[r0], %[r0], #128\n\t"
        "stp x3, x5, [%[r1], #16]\n\t"
        "stp x6, x7, [%[r1], #32]\n\t"
        "cmp %[e], %[r0]\n\t"
        "stp x8, x4, [%[r1], #48]\n\t"
        "stp x10, x11, [%[r1], #64]\n\t"
        "stp x12, x13, [%[r1], #80]\n\t"
        "stp x15, x16, [%[r1], #96]\n\t"
        "stp x17, x14, [%[r1], #112]\n\t"
        "add %[r1], %[r1], #128\n\t"
        // END palette_scale2
        "b.ne 1b\n\t"
        : [r0] "+r"(r0), [r1] "+r"(r1), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette)
        : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17",
          "cc", "memory");
  } else if constexpr (S == 3) {
    uint32_t* r2 = d + 2 * dst_stride;
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_scale3
        "ldr x17, [%[s]], #8\n\t"
        "ubfx x3, x17, #16, #8\n\t"
        "and x1, x17, #0xff\n\t"
        "ubfx x2, x17, #8, #8\n\t"
        "ubfx x4, x17, #24, #8\n\t"
        "ubfx x6, x17, #40, #8\n\t"
        "ldr w3, [%[pal], x3, lsl #2]\n\t"
        "ubfx x7, x17, #48, #8\n\t"
        "ubfx x5, x17, #32, #8\n\t"
        "lsr x17, x17, #56\n\t"
        "ldr w1, [%[pal], x1, lsl #2]\n\t"
        "ldr w2, [%[pal], x2, lsl #2]\n\t"
        "ldr w4, [%[pal], x4, lsl #2]\n\t"
        "ldr w5, [%[pal], x5, lsl #2]\n\t"
        "ldr w17, [%[pal], x17, lsl #2]\n\t"
        "ldr w6, [%[pal], x6, lsl #2]\n\t"
        "orr x10, x3, x4, lsl #32\n\t"
        "ldr w7, [%[pal], x7, lsl #2]\n\t"
        "orr x8, x1, x2, lsl #32\n\t"
        "orr x1, x1, x1, lsl #32\n\t"
        "orr x3, x3, x3, lsl #32\n\t"
        "orr x2, x2, x2, lsl #32\n\t"
        "orr x11, x5, x6, lsl #32\n\t"
        "orr x4, x4, x4, lsl #32\n\t"
        "orr x12, x7, x17, lsl #32\n\t"
        "orr x5, x5, x5, lsl #32\n\t"
        "orr x6, x6, x6, lsl #32\n\t"
        "stp x1, x8, [%[r0], #0]\n\t"
        "orr x7, x7, x7, lsl #32\n\t"
        "stp x2, x3, [%[r0], #16]\n\t"
        "orr x17, x17, x17, lsl #32\n\t"
        "stp x10, x4, [%[r0], #32]\n\t"
        "stp x5, x11, [%[r0], #48]\n\t"
        "stp x6, x7, [%[r0], #64]\n\t"
        "stp x12, x17, [%[r0], #80]\n\t"
        "add %[r0], %[r0], #96\n\t"
        "stp x1, x8, [%[r1], #0]\n\t"
        "stp x2, x3, [%[r1], #16]\n\t"
        "stp x10, x4, [%[r1], #32]\n\t"
        "stp x5, x11, [%[r1], #48]\n\t"
        "stp x6, x7, [%[r1], #64]\n\t"
        "stp x12, x17, [%[r1], #80]\n\t"
        "stp x1, x8, [%[r2], #0]\n\t"
        "stp x2, x3, [%[r2], #16]\n\t"
        "stp x10, x4, [%[r2], #32]\n\t"
        "stp x5, x11, [%[r2], #48]\n\t"
        "cmp %[e], %[r0]\n\t"
        "stp x6, x7, [%[r2], #64]\n\t"
        "add %[r1], %[r1], #96\n\t"
        "stp x12, x17, [%[r2], #80]\n\t"
        "add %[r2], %[r2], #96\n\t"
        // END palette_scale3
        "b.ne 1b\n\t"
        : [r0] "+r"(r0), [r1] "+r"(r1), [r2] "+r"(r2), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette)
        : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17",
          "cc", "memory");
  } else {
    uint32_t* r2 = d + 2 * dst_stride;
    uint32_t* r3 = d + 3 * dst_stride;
    __asm__ volatile(
        "1:\n\t"
        // BEGIN palette_scale4
        "ldr x17, [%[s]], #8\n\t"
        "ubfx x2, x17, #8, #8\n\t"
        "and x1, x17, #0xff\n\t"
        "ubfx x6, x17, #40, #8\n\t"
        "ubfx x4, x17, #24, #8\n\t"
        "ubfx x3, x17, #16, #8\n\t"
        "ubfx x7, x17, #48, #8\n\t"
        "ubfx x5, x17, #32, #8\n\t"
        "ldr w1, [%[pal], x1, lsl #2]\n\t"
        "lsr x17, x17, #56\n\t"
        "ldr w2, [%[pal], x2, lsl #2]\n\t"
        "ldr w4, [%[pal], x4, lsl #2]\n\t"
        "ldr w5, [%[pal], x5, lsl #2]\n\t"
        "ldr w17, [%[pal], x17, lsl #2]\n\t"
        "ldr w3, [%[pal], x3, lsl #2]\n\t"
        "dup v0.4s, w1\n\t"
        "dup v1.4s, w2\n\t"
        "dup v3.4s, w4\n\t"
        "ldr w6, [%[pal], x6, lsl #2]\n\t"
        "ldr w7, [%[pal], x7, lsl #2]\n\t"
        "dup v2.4s, w3\n\t"
        "dup v7.4s, w17\n\t"
        "dup v4.4s, w5\n\t"
        "dup v5.4s, w6\n\t"
        "dup v6.4s, w7\n\t"
        "stp q0, q1, [%[r0], #0]\n\t"
        "stp q2, q3, [%[r0], #32]\n\t"
        "stp q4, q5, [%[r0], #64]\n\t"
        "stp q6, q7, [%[r0], #96]\n\t"
        "stp q0, q1, [%[r1], #0]\n\t"
        "stp q2, q3, [%[r1], #32]\n\t"
        "stp q4, q5, [%[r1], #64]\n\t"
        "add %[r0], %[r0], #128\n\t"
        "stp q6, q7, [%[r1], #96]\n\t"
        "stp q0, q1, [%[r2], #0]\n\t"
        "cmp %[e], %[r0]\n\t"
        "stp q2, q3, [%[r2], #32]\n\t"
        "stp q4, q5, [%[r2], #64]\n\t"
        "stp q6, q7, [%[r2], #96]\n\t"
        "add %[r2], %[r2], #128\n\t"
        "stp q0, q1, [%[r3], #0]\n\t"
        "stp q2, q3, [%[r3], #32]\n\t"
        "add %[r1], %[r1], #128\n\t"
        "stp q4, q5, [%[r3], #64]\n\t"
        "stp q6, q7, [%[r3], #96]\n\t"
        "add %[r3], %[r3], #128\n\t"
        // END palette_scale4
        "b.ne 1b\n\t"
        : [r0] "+r"(r0), [r1] "+r"(r1), [r2] "+r"(r2), [r3] "+r"(r3), [s] "+r"(sp)
        : [e] "r"(end), [pal] "r"(palette)
        : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17",
          "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "cc", "memory");
  }
  return n;
}
#endif

void expand_palette_neon(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  const size_t row_bytes = size_t(width) * size_t(scale) * sizeof(uint32_t);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    uint32_t* d = dst + ptrdiff_t(y) * scale * dst_stride;
    int x = 0;
    if (scale == 1) {
      // Core loads and stores: the indices read 8 or 16 at a time as 64-bit words, the palette
      // words loaded into core registers and stored in pairs. Building vectors by lane
      // inserts cost more than they save here (Cortex-A72 model: 7.6 cycles a pixel).
#if defined(__aarch64__)
      // 16 pixels an iteration, the order searched for the Cortex-A53 model
      // (bench/mca_a53_palette/README.md).
      if (width >= 16) {
        const uint8_t* sp = s;
        uint32_t* dp = d;
        const uint32_t* const end = d + (width & ~15);
        __asm__ volatile(
            "1:\n\t"
            // BEGIN palette_loop16
            "ldp x4, x14, [%[s]], #16\n\t"
            "ubfx x5, x4, #8, #8\n\t"
            "ubfx x3, x14, #40, #8\n\t"
            "ubfx x13, x4, #48, #8\n\t"
            "ubfx x8, x4, #24, #8\n\t"
            "ubfx x7, x4, #32, #8\n\t"
            "ubfx x11, x4, #16, #8\n\t"
            "ubfx x2, x14, #32, #8\n\t"
            "ldr w5, [%[pal], x5, lsl #2]\n\t"
            "ldr w11, [%[pal], x11, lsl #2]\n\t"
            "and x16, x14, #0xff\n\t"
            "ldr w13, [%[pal], x13, lsl #2]\n\t"
            "and x6, x4, #0xff\n\t"
            "ubfx x12, x4, #40, #8\n\t"
            "lsr x4, x4, #56\n\t"
            "ubfx x1, x14, #24, #8\n\t"
            "ubfx x10, x14, #48, #8\n\t"
            "ubfx x17, x14, #16, #8\n\t"
            "ubfx x15, x14, #8, #8\n\t"
            "lsr x14, x14, #56\n\t"
            "ldr w12, [%[pal], x12, lsl #2]\n\t"
            "ldr w6, [%[pal], x6, lsl #2]\n\t"
            "add %[d], %[d], #0x40\n\t"
            "ldr w8, [%[pal], x8, lsl #2]\n\t"
            "ldr w16, [%[pal], x16, lsl #2]\n\t"
            "ldr w7, [%[pal], x7, lsl #2]\n\t"
            "stp w6, w5, [%[d], #-64]\n\t"
            "ldr w10, [%[pal], x10, lsl #2]\n\t"
            "ldr w17, [%[pal], x17, lsl #2]\n\t"
            "stp w11, w8, [%[d], #-56]\n\t"
            "cmp %[e], %[d]\n\t"
            "ldr w4, [%[pal], x4, lsl #2]\n\t"
            "ldr w1, [%[pal], x1, lsl #2]\n\t"
            "stp w7, w12, [%[d], #-48]\n\t"
            "ldr w15, [%[pal], x15, lsl #2]\n\t"
            "ldr w3, [%[pal], x3, lsl #2]\n\t"
            "ldr w2, [%[pal], x2, lsl #2]\n\t"
            "ldr w14, [%[pal], x14, lsl #2]\n\t"
            "stp w13, w4, [%[d], #-40]\n\t"
            "stp w16, w15, [%[d], #-32]\n\t"
            "stp w17, w1, [%[d], #-24]\n\t"
            "stp w2, w3, [%[d], #-16]\n\t"
            "stp w10, w14, [%[d], #-8]\n\t"
            // END palette_loop16
            "b.ne 1b\n\t"
            : [d] "+r"(dp), [s] "+r"(sp)
            : [e] "r"(end), [pal] "r"(palette)
            : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17",
              "cc", "memory");
        x = width & ~15;
      }
#else
      // 8 pixels an iteration in one asm loop, the order searched for the Cortex-A9 model
      // (bench/mca_a53_palette/README.md): the indices by two core loads (rows have no
      // alignment), the colours into core registers, stored by strd (dst is word-aligned).
      if (width >= 8) {
        register uint32_t* p asm("r0") = d;
        register const uint8_t* sp asm("r9") = s;
        register const uint8_t* const e asm("r10") = s + (width & ~7);
        register const uint32_t* const pal asm("r8") = palette;
        __asm__ volatile(
            "1:\n\t"
            // BEGIN palette_v7_scale1
            "ldr r4, [r9, #4]\n\t"
            "ldr r3, [r9], #8\n\t"
            "ubfx r6, r3, #8, #8\n\t"
            "ldr r6, [r8, r6, lsl #2]\n\t"
            "ubfx r1, r3, #16, #8\n\t"
            "uxtb r5, r3\n\t"
            "uxtb r2, r4\n\t"
            "ubfx ip, r4, #8, #8\n\t"
            "ldr ip, [r8, ip, lsl #2]\n\t"
            "ubfx lr, r4, #16, #8\n\t"
            "lsr r4, r4, #24\n\t"
            "ldr r5, [r8, r5, lsl #2]\n\t"
            "strd r5, r6, [r0, #0]\n\t"
            "ldr r1, [r8, r1, lsl #2]\n\t"
            "ldr lr, [r8, lr, lsl #2]\n\t"
            "lsr r3, r3, #24\n\t"
            "ldr r4, [r8, r4, lsl #2]\n\t"
            "ldr r3, [r8, r3, lsl #2]\n\t"
            "strd r1, r3, [r0, #8]\n\t"
            "ldr r2, [r8, r2, lsl #2]\n\t"
            "strd r2, ip, [r0, #16]\n\t"
            "strd lr, r4, [r0, #24]\n\t"
            "cmp r9, r10\n\t"
            "add r0, r0, #32\n\t"
            // END palette_v7_scale1
            "bne 1b\n\t"
            : "+r"(p), "+r"(sp)
            : "r"(e), "r"(pal)
            : "r1", "r2", "r3", "r4", "r5", "r6", "ip", "lr", "cc", "memory");
        x = width & ~7;
      }
#endif
    } else if (scale <= 4) {
#if defined(__aarch64__)
      x = scale == 2   ? expand_rows_a64<2>(s, width, palette, d, dst_stride)
          : scale == 3 ? expand_rows_a64<3>(s, width, palette, d, dst_stride)
                       : expand_rows_a64<4>(s, width, palette, d, dst_stride);
#else
      x = scale == 2   ? expand_rows_v7<2>(s, width, palette, d, dst_stride)
          : scale == 3 ? expand_rows_v7<3>(s, width, palette, d, dst_stride)
                       : expand_rows_v7<4>(s, width, palette, d, dst_stride);
#endif
      for (; x < width; ++x) {
        const uint32_t c = palette[s[x]];
        for (int j = 0; j < scale; ++j)
          for (int i = 0; i < scale; ++i) d[j * dst_stride + x * scale + i] = c;
      }
      continue;  // every row written
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
}  // namespace sb::simd::detail
