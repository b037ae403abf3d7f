// asm/neon_block_mip2f.h: the mip-2 lean path's most common shape in assembly (AArch64,
// neon_a53): 16 x 16 textures (mip 2 of the 64 x 64 ones), surface widths 64..512 a multiple
// of 64, heights 4..512 a multiple of 4 with (h / 4 + 3) w <= kA53TableBytes, row offsets a
// multiple of 4. Only asm/neon_block_mip2l.h includes this (at its end, with its loop macros
// still defined); the assembly entry surface_block_neon_inorder (asm/neon_block_mip3l.h)
// branches here (SB_M2L_SYM) on mip 2, and every other shape goes on, arguments untouched, to
// the C++ lean path (SB_M2L_CXX), which takes these shapes too and computes the same bytes.
//
// The same work as the C++ path in one function without GCC's frame, argument copies and
// shape branches: the test (one block), the frame, the 16 rows laid out by one block
// (m2l_rows16x16's loads and lookups) and stored up to the surface's height, the grid table T
// (m2l_cols2<true>'s passes: two 8-entry columns and the single entry after them, w / 64
// passes; a pass's single entry is the next pass's first, written twice with the same value),
// then SB_M2L_GROUPS with the loops' operands in fixed registers (the ones GCC gave the C++
// path's), and the epilogue.
#pragma once

#include "asm/neon_block_a53g.h"

#if defined(__aarch64__)

static_assert(sb::simd::detail::kA53TableBytes == 16384 && sb::simd::detail::kM2LMaxHeight == 512,
              "asm/neon_block_mip2f.h's frame and tests assume these");

// Frame (28672 bytes, sp 16-aligned): [sp, 16) the groups' state (rows' start, outputs' end),
// [16, 128) the saved x19-x28, d8-d10, x30, L = sp + 128 (the laid-out rows: 512 + 12 + 2 rows
// at most, 8416 bytes), T = sp + 12288 (16384 bytes, to the frame's end).
#define SB_M2F_FRAME "#7, lsl #12"
#define SB_M2F_L "#128"
#define SB_M2F_T "#3, lsl #12"

#undef SB_M2L_D
#undef SB_M2L_RP
#undef SB_M2L_Q
#undef SB_M2L_ETE
#undef SB_M2L_T0
#undef SB_M2L_CM
#undef SB_M2L_W
#undef SB_M2L_J0
#undef SB_M2L_J1
#undef SB_M2L_WT
#undef SB_M2L_WT4
#define SB_M2L_D "x17"
#define SB_M2L_RP "x14"
#define SB_M2L_Q "x13"
#define SB_M2L_ETE "x27"
#define SB_M2L_T0 "x28"
#define SB_M2L_CM "x16"
#define SB_M2L_W "x15"
#define SB_M2L_J0 "v30"
#define SB_M2L_J1 "v31"
#define SB_M2L_WT "v9"
#define SB_M2L_WT4 "v10"

// B's results stored (at the next pair's start and the group's exit): SB_M2F_B loads each
// output half's lanes 0-3 and 4-7 to two registers (two lane-load chains of four, not one of
// eight: the Cortex-A57 model runs such a chain serially, 8 cycles a lane): the D half to v0
// (lanes 0-3), v1 (4-7), D + 8's to v2, v3, x8's to v4, v5 and x8 + 8's to v6, v7, so each 16
// bytes is one st4 of lane 0 (element i of the four registers in turn).
#define SB_M2F_BSTORE \
  "st4 {v0.s, v1.s, v2.s, v3.s}[0], [x17]\n\t" \
  "st4 {v4.s, v5.s, v6.s, v7.s}[0], [x8]\n\t"

// The loop's B stores and pair A (SB_M2F_BSTORE and SB_M2L_A_BODY's work) in the order searched
// with SB_M2F_B; a group's first pair A still runs SB_M2L_A_BODY (its stores are SB_M2F_B's).
#define SB_M2F_LOOPA \
  "st4 {v0.s, v1.s, v2.s, v3.s}[0], [x17]\n\t" \
  "add v27.4s, v22.4s, v16.4s\n\t" \
  "add v28.4s, v23.4s, v17.4s\n\t" \
  "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b\n\t" \
  "add v25.4s, v20.4s, v29.4s\n\t" \
  "add v24.4s, v19.4s, v18.4s\n\t" \
  "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b\n\t" \
  "add v22.4s, v27.4s, v16.4s\n\t" \
  "st4 {v4.s, v5.s, v6.s, v7.s}[0], [x8]\n\t" \
  "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b\n\t" \
  "fmov x1, v0.d[1]\n\t" \
  "add v23.4s, v28.4s, v17.4s\n\t" \
  "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b\n\t" \
  "fmov x0, d0\n\t" \
  "fmov x3, v1.d[1]\n\t" \
  "add v19.4s, v24.4s, v18.4s\n\t" \
  "add v20.4s, v25.4s, v29.4s\n\t" \
  "fmov x4, d2\n\t" \
  "fmov x6, d3\n\t" \
  "fmov x2, d1\n\t" \
  "fmov x5, v2.d[1]\n\t" \
  "fmov x7, v3.d[1]\n\t" \
  "ldr q8, [x27, x13]\n\t" \
  "add x9, x16, w0, uxth\n\t" \
  "ror x10, x0, #32\n\t" \
  "add x12, x16, w2, uxth\n\t" \
  "ror x21, x4, #32\n\t" \
  "ror x18, x2, #32\n\t" \
  "add x0, x16, x0, lsr #48\n\t" \
  "add x11, x16, w10, uxth\n\t" \
  "add x23, x16, w6, uxth\n\t" \
  "add x20, x16, w4, uxth\n\t" \
  "ldr b5, [x12]\n\t" \
  "ror x24, x6, #32\n\t" \
  "ldr b4, [x9]\n\t" \
  "add x22, x16, w21, uxth\n\t" \
  "ldr b7, [x23]\n\t" \
  "add x21, x16, x21, lsr #48\n\t" \
  "add x19, x16, w18, uxth\n\t" \
  "add x18, x16, x18, lsr #48\n\t" \
  "add x25, x16, w24, uxth\n\t" \
  "add x12, x16, w3, uxth\n\t" \
  "add x10, x16, x10, lsr #48\n\t" \
  "add x24, x16, x24, lsr #48\n\t" \
  "ldr b6, [x20]\n\t" \
  "add x2, x16, x2, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x18]\n\t" \
  "add x6, x16, x6, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x10]\n\t" \
  "ror x10, x1, #32\n\t" \
  "ld1 {v7.b}[1], [x24]\n\t" \
  "add x4, x16, x4, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "ror x18, x3, #32\n\t" \
  "ldr q21, [x14]\n\t" \
  "add x9, x16, w1, uxth\n\t" \
  "ld1 {v4.b}[2], [x11]\n\t" \
  "ror x21, x5, #32\n\t" \
  "ld1 {v5.b}[2], [x19]\n\t" \
  "add x20, x16, w5, uxth\n\t" \
  "ld1 {v6.b}[2], [x22]\n\t" \
  "ror x24, x7, #32\n\t" \
  "ld1 {v7.b}[2], [x25]\n\t" \
  "add x19, x16, w18, uxth\n\t" \
  "ldr q26, [x14, #16]\n\t" \
  "add x23, x16, w7, uxth\n\t" \
  "ld1 {v4.b}[3], [x0]\n\t" \
  "add x11, x16, w10, uxth\n\t" \
  "ld1 {v5.b}[3], [x2]\n\t" \
  "add x10, x16, x10, lsr #48\n\t" \
  "ld1 {v6.b}[3], [x4]\n\t" \
  "add x25, x16, w24, uxth\n\t" \
  "ld1 {v7.b}[3], [x6]\n\t" \
  "add x22, x16, w21, uxth\n\t" \
  "ld1 {v4.b}[4], [x9]\n\t" \
  "add x21, x16, x21, lsr #48\n\t" \
  "ld1 {v5.b}[4], [x12]\n\t" \
  "add x18, x16, x18, lsr #48\n\t" \
  "ld1 {v6.b}[4], [x20]\n\t" \
  "add x5, x16, x5, lsr #48\n\t" \
  "ld1 {v7.b}[4], [x23]\n\t" \
  "add x24, x16, x24, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x10]\n\t" \
  "add x17, x17, x15, lsl #1\n\t" \
  "ld1 {v5.b}[5], [x18]\n\t" \
  "ld1 {v6.b}[5], [x21]\n\t" \
  "add x14, x14, #32\n\t" \
  "ld1 {v7.b}[5], [x24]\n\t" \
  "add x3, x16, x3, lsr #48\n\t" \
  "ld1 {v4.b}[6], [x11]\n\t" \
  "add x1, x16, x1, lsr #48\n\t" \
  "ld1 {v5.b}[6], [x19]\n\t" \
  "ld1 {v6.b}[6], [x22]\n\t" \
  "add x7, x16, x7, lsr #48\n\t" \
  "ld1 {v7.b}[6], [x25]\n\t" \
  "add x8, x17, x15\n\t" \
  "ld1 {v4.b}[7], [x1]\n\t" \
  "ld1 {v5.b}[7], [x3]\n\t" \
  "ld1 {v6.b}[7], [x5]\n\t" \
  "ld1 {v7.b}[7], [x7]\n\t"

// SB_M2L_B (same registers and work, but the output halves' lanes as SB_M2F_BSTORE takes them)
// in the order searched with SB_M2F_LOOPA for the loop without a block break between A and B
// (qemu then cuts the pair after 133 instructions, 33 into B): bench/order_search.py --qcuts=0
// --a57=0.05 on the whole loop, qemu_cuts.py knowing st4 (bench/mca_a53_block/README.md).
#define SB_M2F_B \
  "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b\n\t" \
  "add v27.4s, v22.4s, v16.4s\n\t" \
  "add v28.4s, v23.4s, v17.4s\n\t" \
  "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b\n\t" \
  "add v24.4s, v19.4s, v18.4s\n\t" \
  "add v25.4s, v20.4s, v29.4s\n\t" \
  "stp d4, d5, [x17]\n\t" \
  "add v22.4s, v27.4s, v16.4s\n\t" \
  "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b\n\t" \
  "add v23.4s, v28.4s, v17.4s\n\t" \
  "fmov x0, d0\n\t" \
  "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b\n\t" \
  "add v19.4s, v24.4s, v18.4s\n\t" \
  "smull v16.4s, v9.4h, v8.h[0]\n\t" \
  "add v20.4s, v25.4s, v29.4s\n\t" \
  "fmov x1, v0.d[1]\n\t" \
  "fmov x2, d1\n\t" \
  "smull v17.4s, v9.4h, v8.h[1]\n\t" \
  "fmov x6, d3\n\t" \
  "fmov x3, v1.d[1]\n\t" \
  "fmov x4, d2\n\t" \
  "smull v29.4s, v9.4h, v8.h[3]\n\t" \
  "smull v18.4s, v9.4h, v8.h[2]\n\t" \
  "fmov x5, v2.d[1]\n\t" \
  "fmov x7, v3.d[1]\n\t" \
  "smlal2 v17.4s, v9.8h, v8.h[2]\n\t" \
  "stp d6, d7, [x8]\n\t" \
  "adds x13, x13, x15\n\t" \
  "ror x24, x6, #32\n\t" \
  "add x20, x16, w4, uxth\n\t" \
  "add x9, x16, w0, uxth\n\t" \
  "ror x10, x0, #32\n\t" \
  "ror x21, x4, #32\n\t" \
  "add x12, x16, w2, uxth\n\t" \
  "add x23, x16, w6, uxth\n\t" \
  "ldr q26, [x14, #16]\n\t" \
  "add x11, x16, w10, uxth\n\t" \
  "ror x18, x2, #32\n\t" \
  "add x10, x16, x10, lsr #48\n\t" \
  "ldr b0, [x9]\n\t" \
  "add x22, x16, w21, uxth\n\t" \
  "ldr b6, [x23]\n\t" \
  "add x25, x16, w24, uxth\n\t" \
  "ldr b2, [x12]\n\t" \
  "add x21, x16, x21, lsr #48\n\t" \
  "add x19, x16, w18, uxth\n\t" \
  "add x18, x16, x18, lsr #48\n\t" \
  "ldr b4, [x20]\n\t" \
  "add x24, x16, x24, lsr #48\n\t" \
  "ld1 {v0.b}[1], [x10]\n\t" \
  "ror x10, x1, #32\n\t" \
  "add x23, x16, w7, uxth\n\t" \
  "add x12, x16, w3, uxth\n\t" \
  "ld1 {v2.b}[1], [x18]\n\t" \
  "add x0, x16, x0, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x21]\n\t" \
  "add x2, x16, x2, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x24]\n\t" \
  "add x4, x16, x4, lsr #48\n\t" \
  "ld1 {v0.b}[2], [x11]\n\t" \
  "ror x21, x5, #32\n\t" \
  "ld1 {v2.b}[2], [x19]\n\t" \
  "add x20, x16, w5, uxth\n\t" \
  "ld1 {v4.b}[2], [x22]\n\t" \
  "add x9, x16, w1, uxth\n\t" \
  "add x6, x16, x6, lsr #48\n\t" \
  "ror x24, x7, #32\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x22, x16, w21, uxth\n\t" \
  "ld1 {v2.b}[3], [x2]\n\t" \
  "add x11, x16, w10, uxth\n\t" \
  "ld1 {v0.b}[3], [x0]\n\t" \
  "ror x18, x3, #32\n\t" \
  "ld1 {v4.b}[3], [x4]\n\t" \
  "add x25, x16, w24, uxth\n\t" \
  "ld1 {v6.b}[3], [x6]\n\t" \
  "add x10, x16, x10, lsr #48\n\t" \
  "ldr q21, [x14]\n\t" \
  "add x19, x16, w18, uxth\n\t" \
  "ldr b1, [x9]\n\t" \
  "add x21, x16, x21, lsr #48\n\t" \
  "ldr b5, [x20]\n\t" \
  "add x18, x16, x18, lsr #48\n\t" \
  "ldr b3, [x12]\n\t" \
  "add x24, x16, x24, lsr #48\n\t" \
  "ldr b7, [x23]\n\t" \
  "add x5, x16, x5, lsr #48\n\t" \
  "ld1 {v1.b}[1], [x10]\n\t" \
  "add x3, x16, x3, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x21]\n\t" \
  "ld1 {v3.b}[1], [x18]\n\t" \
  "smlal2 v16.4s, v9.8h, v8.h[1]\n\t" \
  "ld1 {v7.b}[1], [x24]\n\t" \
  "ld1 {v5.b}[2], [x22]\n\t" \
  "add x1, x16, x1, lsr #48\n\t" \
  "ld1 {v3.b}[2], [x19]\n\t" \
  "add x7, x16, x7, lsr #48\n\t" \
  "ld1 {v1.b}[2], [x11]\n\t" \
  "ld1 {v7.b}[2], [x25]\n\t" \
  "smlal2 v18.4s, v9.8h, v8.h[3]\n\t" \
  "smlal2 v29.4s, v9.8h, v8.h[4]\n\t" \
  "ld1 {v5.b}[3], [x5]\n\t" \
  "ld1 {v1.b}[3], [x1]\n\t" \
  "ld1 {v7.b}[3], [x7]\n\t" \
  "add x17, x17, x15, lsl #1\n\t" \
  "ld1 {v3.b}[3], [x3]\n\t" \
  "add x14, x14, #32\n\t" \
  "add x8, x17, x15\n\t" \
  "b.ne 1b\n\t"

// Arguments: x0 grid, w1 gw, x2 texels, w3 tw, w4 th, w5 mip (2), w6 soff, w7 toff, [sp] width,
// [sp, 8] height, [sp, 16] colormap, [sp, 24] out.
asm(".pushsection .text.sb_neon_a53_m2f, \"ax\", %progbits\n\t"
    ".p2align 6\n\t"
    ".type " SB_M2L_SYM ", %function\n" SB_M2L_SYM ":\n\t"
    // The shape (every bit of w11 clear): tw = th = 16, width - 64 in 0..448 a multiple of 64,
    // height - 4 in 0..508 a multiple of 4, toff a multiple of 4, (h + 12) w <= 65536 (the
    // table's (h / 4 + 3) w <= 16384). The frame is allocated and the registers saved in the same
    // block, in the test's latency (order searched: Cortex-A53 model 17 cycles); other shapes undo
    // the allocation (.Lsb_m2f_no).
    "ldr w9, [sp]\n\t"
    "ldr w10, [sp, #8]\n\t"
    "ldp x16, x17, [sp, #16]\n\t"
    "eor w11, w3, #16\n\t"
    "sub sp, sp, " SB_M2F_FRAME "\n\t"
    "eor w12, w4, #16\n\t"
    "sub w13, w9, #64\n\t"
    "orr w11, w11, w12\n\t"
    "sub w12, w10, #4\n\t"
    "and w13, w13, #0xfffffe3f\n\t"
    "stp x19, x20, [sp, #16]\n\t"
    "orr w11, w11, w13\n\t"
    "add w13, w10, #12\n\t"
    "and w12, w12, #0xfffffe03\n\t"
    "stp x21, x22, [sp, #32]\n\t"
    "stp x23, x24, [sp, #48]\n\t"
    "mul w13, w13, w9\n\t"
    "orr w11, w11, w12\n\t"
    "stp x25, x26, [sp, #64]\n\t"
    "cmp w13, #16, lsl #12\n\t"
    "stp x27, x28, [sp, #80]\n\t"
    "and w12, w7, #3\n\t"
    "stp d8, d9, [sp, #96]\n\t"
    "orr w11, w11, w12\n\t"
    "str d10, [sp, #112]\n\t"
    "ccmp w11, #0, #0, le\n\t"
    "str x30, [sp, #120]\n\t"
    "b.ne .Lsb_m2f_no\n\t"
    // The 16 rows from t0 = toff mod 16 (four runs of four, wrapping), byte k of each
    // the texel (soff + k) mod 16 (I: .Lsb_m2f_iota2 at soff mod 16), in v16-v31, stored at
    // every row they repeat on, a period (256 bytes) a step, up to 192 bytes past L + 16 h (the
    // first period here; order searched with the table set-up and the constants wt, wt4 in the same
    // block: Cortex-A53 model 54 cycles).
    "and w6, w6, #15\n\t"
    "and w7, w7, #15\n\t"
    "adr x8, .Lsb_m2f_iota2\n\t"
    "add w11, w7, #4\n\t"
    "add w12, w7, #8\n\t"
    "add w13, w7, #12\n\t"
    "ubfiz x12, x12, #4, #4\n\t"
    "ubfiz x13, x13, #4, #4\n\t"
    "add x19, sp, " SB_M2F_L "\n\t"
    "add x7, x2, x7, lsl #4\n\t"
    "ubfiz x11, x11, #4, #4\n\t"
    "add x13, x2, x13\n\t"
    "sbfiz x22, x1, #1, #32\n\t"
    "ldr q4, [x8, x6]\n\t"
    "ldp q16, q17, [x7]\n\t"
    "add x11, x2, x11\n\t"
    "add x12, x2, x12\n\t"
    "ldp q30, q31, [x13, #32]\n\t"
    "ldp q18, q19, [x7, #32]\n\t"
    "tbl v16.16b, {v16.16b}, v4.16b\n\t"
    "ldp q26, q27, [x12, #32]\n\t"
    "ldp q20, q21, [x11]\n\t"
    "ldp q24, q25, [x12]\n\t"
    "tbl v17.16b, {v17.16b}, v4.16b\n\t"
    "tbl v20.16b, {v20.16b}, v4.16b\n\t"
    "tbl v19.16b, {v19.16b}, v4.16b\n\t"
    "tbl v18.16b, {v18.16b}, v4.16b\n\t"
    "ldp q22, q23, [x11, #32]\n\t"
    "ldp q28, q29, [x13]\n\t"
    "tbl v27.16b, {v27.16b}, v4.16b\n\t"
    "stp q16, q17, [x19]\n\t"
    "tbl v22.16b, {v22.16b}, v4.16b\n\t"
    "tbl v21.16b, {v21.16b}, v4.16b\n\t"
    "stp q18, q19, [x19, #32]\n\t"
    "tbl v23.16b, {v23.16b}, v4.16b\n\t"
    "tbl v25.16b, {v25.16b}, v4.16b\n\t"
    "tbl v29.16b, {v29.16b}, v4.16b\n\t"
    "tbl v26.16b, {v26.16b}, v4.16b\n\t"
    "stp q20, q21, [x19, #64]\n\t"
    "tbl v24.16b, {v24.16b}, v4.16b\n\t"
    "tbl v28.16b, {v28.16b}, v4.16b\n\t"
    "stp q22, q23, [x19, #96]\n\t"
    "tbl v30.16b, {v30.16b}, v4.16b\n\t"
    "tbl v31.16b, {v31.16b}, v4.16b\n\t"
    "stp q24, q25, [x19, #128]\n\t"
    "mov w15, w9\n\t"
    "stp q26, q27, [x19, #160]\n\t"
    "add x26, x22, x22\n\t"
    "add x1, sp, " SB_M2F_T "\n\t"
    "adr x3, .Lsb_m2f_consts\n\t"
    "stp q28, q29, [x19, #192]\n\t"
    "add x27, x15, x15\n\t"
    "stp q30, q31, [x19, #224]\n\t"
    "add x21, x19, w10, uxtw #4\n\t"
    "add x19, x19, #256\n\t"
    "ldp q9, q10, [x3, #32]\n\t"
    "cmp x19, x21\n\t"
    "add x28, x27, x27\n\t"
    "add x25, x26, x26\n\t"
    "lsr w2, w9, #6\n\t"
    "lsr w30, w10, #2\n\t"
    "b.cs .Lsb_m2f_laid\n"
    ".Lsb_m2f_lay:\n\t"
    "stp q16, q17, [x19]\n\t"
    "stp q18, q19, [x19, #32]\n\t"
    "stp q20, q21, [x19, #64]\n\t"
    "stp q22, q23, [x19, #96]\n\t"
    "stp q24, q25, [x19, #128]\n\t"
    "stp q26, q27, [x19, #160]\n\t"
    "stp q28, q29, [x19, #192]\n\t"
    "stp q30, q31, [x19, #224]\n\t"
    "add x19, x19, #256\n\t"
    "cmp x19, x21\n\t"
    "b.lo .Lsb_m2f_lay\n"
    ".Lsb_m2f_laid:\n\t"
    // The table: w / 64 passes (w2 left; grid x0, T x1 a pass's start, 32 bytes a pass on) of
    // three columns (entries 0-7 and 8-15 by q registers, 16 by ldrh / strh), rows 0..nb, nb =
    // h / 4 (x30: the link register is in the frame): row 0, n4 = nb / 4 steps of four rows (grid
    // rows at x3-x6, T rows at x7, x8, x23, x24, each a register stepped 4 rows: one stp q and one
    // strh a row), nb mod 4 single rows (x3, x7). Two steps a loop iteration, the previous row
    // alternating between v0, v16, w9 and v4, v20, w13 (no copies), each step's order searched
    // (bench/order_search.py): Cortex-A53 model 41 -> 35 (one step with the copies) -> 32.
    ".Lsb_m2f_pass:\n\t"
    "adr x10, .Lsb_m2f_consts\n\t"
    "ldp q0, q16, [x0]\n\t"
    "add x3, x0, x22\n\t"
    "add x24, x1, x28\n\t"
    "add x7, x1, x15\n\t"
    "ldrh w9, [x0, #32]\n\t"
    "ldp q30, q31, [x10]\n\t"
    "add x4, x0, x26\n\t"
    "add x6, x0, x25\n\t"
    "lsr x20, x30, #2\n\t"
    "stp q0, q16, [x1]\n\t"
    "add x23, x7, x27\n\t"
    "strh w9, [x1, #32]\n\t"
    "add x5, x3, x26\n\t"
    "add x8, x1, x27\n\t"
    "cbz x20, .Lsb_m2f_t1\n"
    ".Lsb_m2f_t4:\n\t"
    "ldrh w10, [x3, #32]\n\t"
    "ldp q1, q17, [x3]\n\t"
    "add x3, x3, x25\n\t"
    "ldrh w11, [x4, #32]\n\t"
    "ldrh w12, [x5, #32]\n\t"
    "ldp q2, q18, [x4]\n\t"
    "ldp q3, q19, [x5]\n\t"
    "add x4, x4, x25\n\t"
    "add x5, x5, x25\n\t"
    "ldrh w13, [x6, #32]\n\t"
    "sub v5.8h, v1.8h, v0.8h\n\t"
    "sub v21.8h, v17.8h, v16.8h\n\t"
    "sub v7.8h, v3.8h, v2.8h\n\t"
    "sub v22.8h, v18.8h, v17.8h\n\t"
    "sub v6.8h, v2.8h, v1.8h\n\t"
    "sub v23.8h, v19.8h, v18.8h\n\t"
    "ldp q4, q20, [x6]\n\t"
    "sub w14, w13, w12\n\t"
    "stp q5, q21, [x7]\n\t"
    "sub w12, w12, w11\n\t"
    "sub w11, w11, w10\n\t"
    "sub w10, w10, w9\n\t"
    "sub v25.8h, v4.8h, v3.8h\n\t"
    "sub v24.8h, v20.8h, v19.8h\n\t"
    "strh w10, [x7, #32]\n\t"
    "add x6, x6, x25\n\t"
    "stp q6, q22, [x8]\n\t"
    "strh w11, [x8, #32]\n\t"
    "stp q7, q23, [x23]\n\t"
    "subs x20, x20, #1\n\t"
    "strh w12, [x23, #32]\n\t"
    "add x8, x8, x28\n\t"
    "stp q25, q24, [x24]\n\t"
    "add x7, x7, x28\n\t"
    "strh w14, [x24, #32]\n\t"
    "add x23, x23, x28\n\t"
    "add x24, x24, x28\n\t"
    "b.eq .Lsb_m2f_t4o\n\t"
    "ldrh w10, [x3, #32]\n\t"
    "ldp q1, q17, [x3]\n\t"
    "add x3, x3, x25\n\t"
    "ldrh w11, [x4, #32]\n\t"
    "ldrh w12, [x5, #32]\n\t"
    "ldp q2, q18, [x4]\n\t"
    "ldp q3, q19, [x5]\n\t"
    "add x4, x4, x25\n\t"
    "add x5, x5, x25\n\t"
    "ldrh w9, [x6, #32]\n\t"
    "sub v5.8h, v1.8h, v4.8h\n\t"
    "sub v21.8h, v17.8h, v20.8h\n\t"
    "sub v7.8h, v3.8h, v2.8h\n\t"
    "sub v22.8h, v18.8h, v17.8h\n\t"
    "sub v6.8h, v2.8h, v1.8h\n\t"
    "sub v23.8h, v19.8h, v18.8h\n\t"
    "ldp q0, q16, [x6]\n\t"
    "sub w14, w9, w12\n\t"
    "stp q5, q21, [x7]\n\t"
    "sub w12, w12, w11\n\t"
    "sub w11, w11, w10\n\t"
    "sub w10, w10, w13\n\t"
    "sub v25.8h, v0.8h, v3.8h\n\t"
    "sub v24.8h, v16.8h, v19.8h\n\t"
    "strh w10, [x7, #32]\n\t"
    "add x6, x6, x25\n\t"
    "stp q6, q22, [x8]\n\t"
    "strh w11, [x8, #32]\n\t"
    "stp q7, q23, [x23]\n\t"
    "subs x20, x20, #1\n\t"
    "strh w12, [x23, #32]\n\t"
    "add x8, x8, x28\n\t"
    "stp q25, q24, [x24]\n\t"
    "add x7, x7, x28\n\t"
    "strh w14, [x24, #32]\n\t"
    "add x23, x23, x28\n\t"
    "add x24, x24, x28\n\t"
    "b.ne .Lsb_m2f_t4\n"
    ".Lsb_m2f_t1:\n\t"
    "and x21, x30, #3\n\t"
    "cbz x21, .Lsb_m2f_tend\n"
    ".Lsb_m2f_t1l:\n\t"
    "ldp q1, q17, [x3]\n\t"
    "ldrh w10, [x3, #32]\n\t"
    "add x3, x3, x22\n\t"
    "subs x21, x21, #1\n\t"
    "sub v5.8h, v1.8h, v0.8h\n\t"
    "sub v21.8h, v17.8h, v16.8h\n\t"
    "sub w11, w10, w9\n\t"
    "mov v0.16b, v1.16b\n\t"
    "mov v16.16b, v17.16b\n\t"
    "mov w9, w10\n\t"
    "stp q5, q21, [x7]\n\t"
    "strh w11, [x7, #32]\n\t"
    "add x7, x7, x15\n\t"
    "b.ne .Lsb_m2f_t1l\n"
    ".Lsb_m2f_tend:\n\t"
    "add x0, x0, #32\n\t"
    "add x1, x1, #32\n\t"
    "subs w2, w2, #1\n\t"
    "b.ne .Lsb_m2f_pass\n\t"
    // The groups' state (SB_M2L_GROUPS' operands): d = out (x17), rp = L, t0 = T, ete = T +
    // (nb + 2) w, q = -nb w, cm (x16), w (x15); [sp]: L, out + w; the first group's
    // SB_M2L_LOADS, SB_M2L_HEAD and SB_M2L_A_BODY with them in one block (130 instructions: qemu
    // does not cut it), order searched (Cortex-A53 model 103 -> 94 cycles; the pass prelude 18 ->
    // 10 with the loads of wt, wt4, j0, j1 and the table set-up moved earlier). The other groups
    // enter at 5.
    "add x9, x30, #2\n\t"
    "add x14, sp, " SB_M2F_L "\n\t"
    "neg x13, x30\n\t"
    "add x30, x17, x15\n\t"
    "add x28, sp, " SB_M2F_T "\n\t"
    "stp x14, x30, [sp]\n\t"
    "mov x26, x17\n\t"
    "ldr q0, [x28]\n\t"
    "madd x27, x9, x15, x28\n\t"
    "ldr q8, [x28, x15]\n\t"
    "mul x13, x13, x15\n\t"
    "ldr q21, [x14]\n\t"
    "ldr q26, [x14, #16]\n\t"
    "add x14, x14, #32\n\t"
    "smull v19.4s, v10.4h, v0.h[2]\n\t"
    "smull v16.4s, v9.4h, v8.h[0]\n\t"
    "smull v23.4s, v10.4h, v0.h[1]\n\t"
    "smull v22.4s, v10.4h, v0.h[0]\n\t"
    "smull v17.4s, v9.4h, v8.h[1]\n\t"
    "smull v18.4s, v9.4h, v8.h[2]\n\t"
    "smull v29.4s, v9.4h, v8.h[3]\n\t"
    "smull v20.4s, v10.4h, v0.h[3]\n\t"
    "smlal2 v23.4s, v10.8h, v0.h[2]\n\t"
    "smlal2 v22.4s, v10.8h, v0.h[1]\n\t"
    "smlal2 v19.4s, v10.8h, v0.h[3]\n\t"
    "smlal2 v16.4s, v9.8h, v8.h[1]\n\t"
    "smlal2 v17.4s, v9.8h, v8.h[2]\n\t"
    "smlal2 v20.4s, v10.8h, v0.h[4]\n\t"
    "smlal2 v29.4s, v9.8h, v8.h[4]\n\t"
    "smlal2 v18.4s, v9.8h, v8.h[3]\n\t"
    "add v27.4s, v22.4s, v16.4s\n\t"
    "add v28.4s, v23.4s, v17.4s\n\t"
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, v30.16b\n\t"
    "add v25.4s, v20.4s, v29.4s\n\t"
    "add v24.4s, v19.4s, v18.4s\n\t"
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, v31.16b\n\t"
    "add v22.4s, v27.4s, v16.4s\n\t"
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, v30.16b\n\t"
    "fmov x1, v0.d[1]\n\t"
    "add v23.4s, v28.4s, v17.4s\n\t"
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, v31.16b\n\t"
    "add v20.4s, v25.4s, v29.4s\n\t"
    "fmov x0, d0\n\t"
    "add v19.4s, v24.4s, v18.4s\n\t"
    "fmov x2, d1\n\t"
    "fmov x5, v2.d[1]\n\t"
    "fmov x4, d2\n\t"
    "fmov x6, d3\n\t"
    "fmov x3, v1.d[1]\n\t"
    "fmov x7, v3.d[1]\n\t"
    "ldr q26, [x14, #16]\n\t"
    "add x9, x16, w0, uxth\n\t"
    "ror x10, x0, #32\n\t"
    "add x12, x16, w2, uxth\n\t"
    "ror x21, x4, #32\n\t"
    "add x0, x16, x0, lsr #48\n\t"
    "add x23, x16, w6, uxth\n\t"
    "ror x18, x2, #32\n\t"
    "add x20, x16, w4, uxth\n\t"
    "add x11, x16, w10, uxth\n\t"
    "ld1 {v5.b}[0], [x12]\n\t"
    "add x22, x16, w21, uxth\n\t"
    "ror x24, x6, #32\n\t"
    "add x19, x16, w18, uxth\n\t"
    "add x18, x16, x18, lsr #48\n\t"
    "add x21, x16, x21, lsr #48\n\t"
    "add x10, x16, x10, lsr #48\n\t"
    "add x25, x16, w24, uxth\n\t"
    "ld1 {v4.b}[0], [x9]\n\t"
    "add x2, x16, x2, lsr #48\n\t"
    "ld1 {v7.b}[0], [x23]\n\t"
    "add x24, x16, x24, lsr #48\n\t"
    "ld1 {v6.b}[0], [x20]\n\t"
    "add x12, x16, w3, uxth\n\t"
    "ld1 {v5.b}[1], [x18]\n\t"
    "add x6, x16, x6, lsr #48\n\t"
    "ld1 {v4.b}[1], [x10]\n\t"
    "ror x10, x1, #32\n\t"
    "ld1 {v7.b}[1], [x24]\n\t"
    "add x9, x16, w1, uxth\n\t"
    "ld1 {v6.b}[1], [x21]\n\t"
    "add x4, x16, x4, lsr #48\n\t"
    "ror x21, x5, #32\n\t"
    "ror x18, x3, #32\n\t"
    "ld1 {v5.b}[2], [x19]\n\t"
    "ror x24, x7, #32\n\t"
    "ld1 {v4.b}[2], [x11]\n\t"
    "sub x17, x26, x15, lsl #1\n\t"
    "ld1 {v6.b}[2], [x22]\n\t"
    "add x20, x16, w5, uxth\n\t"
    "ld1 {v7.b}[2], [x25]\n\t"
    "add x23, x16, w7, uxth\n\t"
    "add x19, x16, w18, uxth\n\t"
    "ld1 {v4.b}[3], [x0]\n\t"
    "add x11, x16, w10, uxth\n\t"
    "ld1 {v5.b}[3], [x2]\n\t"
    "add x10, x16, x10, lsr #48\n\t"
    "ld1 {v6.b}[3], [x4]\n\t"
    "add x25, x16, w24, uxth\n\t"
    "ld1 {v7.b}[3], [x6]\n\t"
    "add x22, x16, w21, uxth\n\t"
    "ld1 {v4.b}[4], [x9]\n\t"
    "add x21, x16, x21, lsr #48\n\t"
    "ld1 {v5.b}[4], [x12]\n\t"
    "add x18, x16, x18, lsr #48\n\t"
    "ld1 {v6.b}[4], [x20]\n\t"
    "add x24, x16, x24, lsr #48\n\t"
    "ld1 {v7.b}[4], [x23]\n\t"
    "add x3, x16, x3, lsr #48\n\t"
    "ld1 {v4.b}[5], [x10]\n\t"
    "add x7, x16, x7, lsr #48\n\t"
    "ld1 {v5.b}[5], [x18]\n\t"
    "add x17, x17, x15, lsl #1\n\t"
    "ld1 {v6.b}[5], [x21]\n\t"
    "ld1 {v7.b}[5], [x24]\n\t"
    "ld1 {v4.b}[6], [x11]\n\t"
    "add x5, x16, x5, lsr #48\n\t"
    "ldr q21, [x14]\n\t"
    "ld1 {v5.b}[6], [x19]\n\t"
    "ld1 {v7.b}[6], [x25]\n\t"
    "add x1, x16, x1, lsr #48\n\t"
    "ldr q8, [x27, x13]\n\t"
    "add x8, x17, x15\n\t"
    "ld1 {v6.b}[6], [x22]\n\t"
    "add x14, x14, #32\n\t"
    "ld1 {v5.b}[7], [x3]\n\t"
    "ld1 {v4.b}[7], [x1]\n\t"
    "ld1 {v7.b}[7], [x7]\n\t"
    "ld1 {v6.b}[7], [x5]\n\t"
    "b 3f\n"
    "5:\n\t" SB_M2L_HEAD SB_M2L_A_BODY
    "b 3f\n\t"
    ".p2align 6\n"
    "1:\n\t" SB_M2F_LOOPA "3:\n\t" SB_M2F_B
    // The group's exit (the C++ path's, tw != 32).
    "add x28, x28, #8\n\t"
    SB_M2F_BSTORE
    "ldp x14, x30, [sp]\n\t"
    "add x27, x27, #8\n\t"
    "add x13, x28, x15, lsl #1\n\t"
    "ldr q0, [x28]\n\t"
    "sub x13, x13, x27\n\t"
    "ldr q8, [x28, x15]\n\t"
    "add x26, x26, #16\n\t"
    "ldr q21, [x14]\n\t"
    "cmp x26, x30\n\t"
    "ldr q26, [x14, #16]\n\t"
    "add x14, x14, #32\n\t"
    "b.ne 5b\n\t"
    "ldp x19, x20, [sp, #16]\n\t"
    "ldp x21, x22, [sp, #32]\n\t"
    "ldp x23, x24, [sp, #48]\n\t"
    "ldp x25, x26, [sp, #64]\n\t"
    "ldp x27, x28, [sp, #80]\n\t"
    "ldp d8, d9, [sp, #96]\n\t"
    "ldr d10, [sp, #112]\n\t"
    "ldr x30, [sp, #120]\n\t"
    "add sp, sp, " SB_M2F_FRAME "\n\t"
    "ret\n"
    ".Lsb_m2f_no:\n\t"  // (not this shape: the frame's allocation undone, nothing else changed yet)
    "add sp, sp, " SB_M2F_FRAME "\n\t"
    "b " SB_M2L_CXX "\n"
    ".Lsb_m2f_t4o:\n\t"  // (the table after an odd number of steps: the last row to v0, v16, w9)
    "mov v0.16b, v4.16b\n\t"
    "mov v16.16b, v20.16b\n\t"
    "mov w9, w13\n\t"
    "b .Lsb_m2f_t1\n\t"
    ".p2align 4\n"
    // kM2LIota2, kM2LTix (J0, J1), kM2LWt (wt, wt4)
    ".Lsb_m2f_iota2:\n\t"
    ".byte 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15\n\t"
    ".byte 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15\n"
    ".Lsb_m2f_consts:\n\t"
    ".byte 0, 18, 1, 22, 2, 26, 3, 30, 4, 34, 5, 38, 6, 42, 7, 46\n\t"
    ".byte 40, 2, 41, 6, 42, 10, 43, 14, 44, 18, 45, 22, 46, 26, 47, 30\n\t"
    ".hword 64, 48, 32, 16, 0, 16, 32, 48\n\t"
    ".hword 256, 192, 128, 64, 0, 64, 128, 192\n\t"
    ".size " SB_M2L_SYM ", .-" SB_M2L_SYM "\n\t"
    ".popsection");

#undef SB_M2F_FRAME
#undef SB_M2F_B
#undef SB_M2F_BSTORE
#undef SB_M2F_LOOPA
#undef SB_M2F_L
#undef SB_M2F_T

#endif  // __aarch64__
