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

// The table pass's registers: grid entries at s0, s1 = s0 + 16 bytes, s2 = s0 + 32 (rows g1 =
// 2 gw bytes apart), T at o0, o1, o2 (rows e1 = w bytes apart), n4 four-row steps.
#undef SB_M2L_TB_E1
#undef SB_M2L_TB_E2
#undef SB_M2L_TB_E3
#undef SB_M2L_TB_E4
#undef SB_M2L_TB_G1
#undef SB_M2L_TB_G2
#undef SB_M2L_TB_G3
#undef SB_M2L_TB_G4
#undef SB_M2L_TB_N4
#undef SB_M2L_TB_O0
#undef SB_M2L_TB_O1
#undef SB_M2L_TB_O2
#undef SB_M2L_TB_S0
#undef SB_M2L_TB_S1
#undef SB_M2L_TB_S2
#define SB_M2L_TB_S0 "x3"
#define SB_M2L_TB_S1 "x4"
#define SB_M2L_TB_S2 "x5"
#define SB_M2L_TB_O0 "x6"
#define SB_M2L_TB_O1 "x7"
#define SB_M2L_TB_O2 "x8"
#define SB_M2L_TB_N4 "x20"
#define SB_M2L_TB_G1 "x22"
#define SB_M2L_TB_G2 "x23"
#define SB_M2L_TB_G3 "x24"
#define SB_M2L_TB_G4 "x25"
#define SB_M2L_TB_E1 "x15"
#define SB_M2L_TB_E2 "x26"
#define SB_M2L_TB_E3 "x27"
#define SB_M2L_TB_E4 "x28"

// Arguments: x0 grid, w1 gw, x2 texels, w3 tw, w4 th, w5 mip (2), w6 soff, w7 toff, [sp] width,
// [sp, 8] height, [sp, 16] colormap, [sp, 24] out.
asm(".pushsection .text.sb_neon_a53_m2f, \"ax\", %progbits\n\t"
    ".p2align 6\n\t"
    ".type " SB_M2L_SYM ", %function\n" SB_M2L_SYM ":\n\t"
    // The shape (every bit of w11 clear): tw = th = 16, width - 64 in 0..448 a multiple of 64,
    // height - 4 in 0..508 a multiple of 4, toff a multiple of 4, (h / 4 + 3) w <= 16384.
    "ldr w9, [sp]\n\t"
    "ldr w10, [sp, #8]\n\t"
    "eor w11, w3, #16\n\t"
    "eor w12, w4, #16\n\t"
    "sub w13, w9, #64\n\t"
    "orr w11, w11, w12\n\t"
    "and w13, w13, #0xfffffe3f\n\t"
    "sub w12, w10, #4\n\t"
    "orr w11, w11, w13\n\t"
    "and w12, w12, #0xfffffe03\n\t"
    "lsr w13, w10, #2\n\t"
    "orr w11, w11, w12\n\t"
    "add w13, w13, #3\n\t"
    "and w12, w7, #3\n\t"
    "mul w13, w13, w9\n\t"
    "orr w11, w11, w12\n\t"
    "cmp w13, #4, lsl #12\n\t"
    "ccmp w11, #0, #0, le\n\t"
    "b.ne " SB_M2L_CXX "\n\t"
    // Frame; the 16 rows from t0 = toff mod 16 (four runs of four, wrapping), byte k of each
    // the texel (soff + k) mod 16 (I: .Lsb_m2f_iota2 at soff mod 16), in v16-v31.
    "ldp x16, x17, [sp, #16]\n\t"
    "sub sp, sp, " SB_M2F_FRAME "\n\t"
    "and w7, w7, #15\n\t"
    "and w6, w6, #15\n\t"
    "adr x8, .Lsb_m2f_iota2\n\t"
    "stp x19, x20, [sp, #16]\n\t"
    "add w11, w7, #4\n\t"
    "add w12, w7, #8\n\t"
    "add w13, w7, #12\n\t"
    "stp x21, x22, [sp, #32]\n\t"
    "ubfiz x11, x11, #4, #4\n\t"
    "ubfiz x12, x12, #4, #4\n\t"
    "ubfiz x13, x13, #4, #4\n\t"
    "stp x23, x24, [sp, #48]\n\t"
    "add x7, x2, x7, lsl #4\n\t"
    "add x11, x2, x11\n\t"
    "add x12, x2, x12\n\t"
    "add x13, x2, x13\n\t"
    "ldr q4, [x8, x6]\n\t"
    "ldp q16, q17, [x7]\n\t"
    "ldp q18, q19, [x7, #32]\n\t"
    "ldp q20, q21, [x11]\n\t"
    "ldp q22, q23, [x11, #32]\n\t"
    "ldp q24, q25, [x12]\n\t"
    "ldp q26, q27, [x12, #32]\n\t"
    "ldp q28, q29, [x13]\n\t"
    "ldp q30, q31, [x13, #32]\n\t"
    "stp x25, x26, [sp, #64]\n\t"
    "stp x27, x28, [sp, #80]\n\t"
    "stp d8, d9, [sp, #96]\n\t"
    "str d10, [sp, #112]\n\t"
    "str x30, [sp, #120]\n\t"
    "add x19, sp, " SB_M2F_L "\n\t"
    "add x21, x19, w10, uxtw #4\n\t"
    "tbl v16.16b, {v16.16b}, v4.16b\n\t"
    "tbl v17.16b, {v17.16b}, v4.16b\n\t"
    "tbl v18.16b, {v18.16b}, v4.16b\n\t"
    "tbl v19.16b, {v19.16b}, v4.16b\n\t"
    "tbl v20.16b, {v20.16b}, v4.16b\n\t"
    "tbl v21.16b, {v21.16b}, v4.16b\n\t"
    "tbl v22.16b, {v22.16b}, v4.16b\n\t"
    "tbl v23.16b, {v23.16b}, v4.16b\n\t"
    "tbl v24.16b, {v24.16b}, v4.16b\n\t"
    "tbl v25.16b, {v25.16b}, v4.16b\n\t"
    "tbl v26.16b, {v26.16b}, v4.16b\n\t"
    "tbl v27.16b, {v27.16b}, v4.16b\n\t"
    "tbl v28.16b, {v28.16b}, v4.16b\n\t"
    "tbl v29.16b, {v29.16b}, v4.16b\n\t"
    "tbl v30.16b, {v30.16b}, v4.16b\n\t"
    "tbl v31.16b, {v31.16b}, v4.16b\n"
    // Stored at every row they repeat on, a period (256 bytes) a step, up to 192 bytes past
    // L + 16 h.
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
    "b.lo .Lsb_m2f_lay\n\t"
    // The table: w / 64 passes (x2 left; grid x0, T x1 a pass's start, 32 bytes a pass on),
    // rows 0..nb, nb = h / 4 (x19): row 0, n4 = nb / 4 steps of four rows, nb mod 4 single rows.
    "sbfiz x22, x1, #1, #32\n\t"
    "add x1, sp, " SB_M2F_T "\n\t"
    "mov w15, w9\n\t"
    "lsr w2, w9, #6\n\t"
    "lsr w19, w10, #2\n\t"
    "add x23, x22, x22\n\t"
    "add x24, x23, x22\n\t"
    "add x25, x23, x23\n\t"
    "add x26, x15, x15\n\t"
    "add x27, x26, x15\n\t"
    "add x28, x26, x26\n"
    ".Lsb_m2f_pass:\n\t"
    "lsr x20, x19, #2\n\t"
    "add x4, x0, #16\n\t"
    "add x5, x0, #32\n\t"
    "ldr q0, [x0]\n\t"
    "ldr q16, [x4]\n\t"
    "ldrh w9, [x5]\n\t"
    "mov x3, x0\n\t"
    "mov x6, x1\n\t"
    "add x7, x1, #16\n\t"
    "add x8, x1, #32\n\t"
    "str q0, [x6]\n\t"
    "str q16, [x7]\n\t"
    "strh w9, [x8]\n\t"
    "cbz x20, .Lsb_m2f_t1\n"
    ".Lsb_m2f_t4:\n\t" SB_M2L_STEP4_H
    "b.ne .Lsb_m2f_t4\n"
    ".Lsb_m2f_t1:\n\t"
    "and x21, x19, #3\n\t"
    "cbz x21, .Lsb_m2f_tend\n"
    ".Lsb_m2f_t1l:\n\t"
    "ldr q1, [x3, x22]\n\t"
    "ldr q17, [x4, x22]\n\t"
    "ldrh w10, [x5, x22]\n\t"
    "add x3, x3, x22\n\t"
    "add x4, x4, x22\n\t"
    "add x5, x5, x22\n\t"
    "subs x21, x21, #1\n\t"
    "sub v5.8h, v1.8h, v0.8h\n\t"
    "sub v21.8h, v17.8h, v16.8h\n\t"
    "sub w11, w10, w9\n\t"
    "mov v0.16b, v1.16b\n\t"
    "mov v16.16b, v17.16b\n\t"
    "mov w9, w10\n\t"
    "str q5, [x6, x15]\n\t"
    "str q21, [x7, x15]\n\t"
    "strh w11, [x8, x15]\n\t"
    "add x6, x6, x15\n\t"
    "add x7, x7, x15\n\t"
    "add x8, x8, x15\n\t"
    "b.ne .Lsb_m2f_t1l\n"
    ".Lsb_m2f_tend:\n\t"
    "add x0, x0, #32\n\t"
    "add x1, x1, #32\n\t"
    "subs w2, w2, #1\n\t"
    "b.ne .Lsb_m2f_pass\n\t"
    // The groups' state (SB_M2L_GROUPS' operands): d = out (x17), rp = L, t0 = T, ete = T +
    // (nb + 2) w, q = -nb w, cm (x16), w (x15); [sp]: L, out + w.
    "adr x8, .Lsb_m2f_consts\n\t"
    "add x28, sp, " SB_M2F_T "\n\t"
    "add x14, sp, " SB_M2F_L "\n\t"
    "ldp q30, q31, [x8]\n\t"
    "ldp q9, q10, [x8, #32]\n\t"
    "add x9, x19, #2\n\t"
    "neg x13, x19\n\t"
    "madd x27, x9, x15, x28\n\t"
    "mul x13, x13, x15\n\t"
    "add x30, x17, x15\n\t"
    "stp x14, x30, [sp]\n\t"
    "mov x26, x17\n\t" SB_M2L_LOADS
    "5:\n\t" SB_M2L_HEAD SB_M2L_A_BODY
    "b 3f\n\t"
    ".p2align 6\n"
    "1:\n\t" SB_M2L_A SB_M2L_B
    // The group's exit (the C++ path's, tw != 32).
    "add x28, x28, #8\n\t"
    "stp d4, d5, [x17]\n\t"
    "ldp x14, x30, [sp]\n\t"
    "add x27, x27, #8\n\t"
    "add x13, x28, x15, lsl #1\n\t"
    "ldr q0, [x28]\n\t"
    "sub x13, x13, x27\n\t"
    "ldr q8, [x28, x15]\n\t"
    "add x26, x26, #16\n\t"
    "ldr q21, [x14]\n\t"
    "stp d6, d7, [x8]\n\t"
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
    "ret\n\t"
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
#undef SB_M2F_L
#undef SB_M2F_T

#endif  // __aarch64__
