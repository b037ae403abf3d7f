// asm/neon_block_a64.h: the AArch64 assembly text of the surface block builder's loops
// (asm/neon.cpp, surface_block_groups), as macros: the pair loops of mips 0-2 for
// out-of-order cores (the neon table) and mip 3's loop (both tables).
// Operand names and register roles are described there; only asm/neon.cpp includes this.
#pragma once

#define SB_PAIR_LOOP(T0, TOP, MID, A, E1, E2, E3, E4, BR) \
    "stp x19, x23, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "2:\n\t" T0 \
    "add v28.4s, v23.4s, v18.4s\n\t" \
    "ushr v2.4s, v23.4s, #8\n\t" \
    "add v26.4s, v21.4s, v16.4s\n\t" \
    "add v27.4s, v22.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v29.4s\n\t" \
    "tbl v0.16b, {v20.16b, v21.16b}, %[i0].16b\n\t" \
    "ushr v6.4s, v28.4s, #8\n\t" \
    "tbl v1.16b, {v20.16b, v21.16b, v22.16b}, %[i1].16b\n\t" \
    "tbx v2.16b, {v20.16b}, %[i2].16b\n\t" \
    "tbl v3.16b, {v19.16b, v20.16b}, %[i3].16b\n\t" \
    "tbl v4.16b, {v25.16b, v26.16b}, %[i0].16b\n\t" \
    "tbl v5.16b, {v25.16b, v26.16b, v27.16b}, %[i1].16b\n\t" \
    "tbx v6.16b, {v25.16b}, %[i2].16b\n\t" \
    "tbl v7.16b, {v24.16b, v25.16b}, %[i3].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x3, v1.d[1]\n\t" TOP \
    "fmov x4, d2\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "add v21.4s, v26.4s, v16.4s\n\t" \
    "add v22.4s, v27.4s, v17.4s\n\t" \
    "add v23.4s, v28.4s, v18.4s\n\t" \
    "add v19.4s, v24.4s, v29.4s\n\t" MID \
    "fmov x19, d4\n\t" \
    "fmov x20, v4.d[1]\n\t" \
    "fmov x21, d5\n\t" \
    "fmov x22, v5.d[1]\n\t" \
    "fmov x23, d6\n\t" \
    "fmov x24, v6.d[1]\n\t" \
    "fmov x25, d7\n\t" \
    "fmov x26, v7.d[1]\n\t" \
    "add x10, %[cm], x1, lsr #32\n\t" \
    "ldrb w1, [%[cm], w1, uxtw]\n\t" \
    "add x9, %[cm], x0, lsr #32\n\t" \
    "ldrb w0, [%[cm], w0, uxtw]\n\t" \
    "add x11, %[cm], x2, lsr #32\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x30, %[cm], x5, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x18, %[cm], x4, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x12, %[cm], x3, lsr #32\n\t" \
    "ldrb w4, [%[cm], w4, uxtw]\n\t" \
    "adds %[q], %[q], #2\n\t" \
    "ldrb w2, [%[cm], w2, uxtw]\n\t" \
    "orr x1, x1, x10, lsl #8\n\t" \
    "ldrb w3, [%[cm], w3, uxtw]\n\t" \
    "add x10, %[cm], x7, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x0, x0, x9, lsl #8\n\t" \
    "ldrb w30, [x30]\n\t" \
    "add x9, %[cm], x6, lsr #32\n\t" \
    "ldrb w7, [%[cm], w7, uxtw]\n\t" \
    "ldrb w6, [%[cm], w6, uxtw]\n\t" \
    "orr x4, x4, x18, lsl #8\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x18, %[cm], x23, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x0, x0, x1, lsl #16\n\t" \
    "ldrb w11, [x11]\n\t" \
    "ldrb w12, [x12]\n\t" \
    "orr x7, x7, x10, lsl #8\n\t" \
    "ldr q20, [x8, %[goff]]\n\t" \
    "orr x6, x6, x9, lsl #8\n\t" \
    "ldrb w5, [%[cm], w5, uxtw]\n\t" \
    "add x9, %[cm], x19, lsr #32\n\t" \
    "ldrb w19, [%[cm], w19, uxtw]\n\t" \
    "add x10, %[cm], x20, lsr #32\n\t" \
    "ldrb w20, [%[cm], w20, uxtw]\n\t" \
    "orr x3, x3, x12, lsl #8\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "orr x2, x2, x11, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x12, %[cm], x22, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x11, %[cm], x21, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x5, x5, x30, lsl #8\n\t" \
    "ldrb w23, [%[cm], w23, uxtw]\n\t" \
    "orr x19, x19, x9, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x9, %[cm], x25, lsr #32\n\t" \
    "ldrb w22, [%[cm], w22, uxtw]\n\t" \
    "add x30, %[cm], x24, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "orr x20, x20, x10, lsl #8\n\t" \
    "ldrb w24, [%[cm], w24, uxtw]\n\t" \
    "add x10, %[cm], x26, lsr #32\n\t" \
    "ldrb w25, [%[cm], w25, uxtw]\n\t" \
    "orr x6, x6, x7, lsl #16\n\t" \
    "ldrb w26, [%[cm], w26, uxtw]\n\t" \
    "orr x4, x4, x5, lsl #16\n\t" \
    "ldrb w30, [x30]\n\t" \
    "orr x2, x2, x3, lsl #16\n\t" \
    "ldrb w21, [%[cm], w21, uxtw]\n\t" \
    "orr x22, x22, x12, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x23, x23, x18, lsl #8\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x4, x4, x6, lsl #32\n\t" \
    "ldr q25, [x8, %[goff]]\n\t" \
    "orr x24, x24, x30, lsl #8\n\t" \
    "orr x21, x21, x11, lsl #8\n\t" \
    A \
    "orr x25, x25, x9, lsl #8\n\t" \
    "orr x26, x26, x10, lsl #8\n\t" \
    "orr x0, x0, x2, lsl #32\n\t" \
    "orr x23, x23, x24, lsl #16\n\t" \
    "orr x19, x19, x20, lsl #16\n\t" \
    E1 \
    "orr x21, x21, x22, lsl #16\n\t" \
    "orr x25, x25, x26, lsl #16\n\t" \
    "stp x0, x4, [%[d]]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "orr x19, x19, x21, lsl #32\n\t" \
    E2 \
    "orr x23, x23, x25, lsl #32\n\t" \
    E3 \
    E4 \
    BR

#define SB_PAIR_LOOP_N \
    "stp x19, x23, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "2:\n\t" \
    "add v28.4s, v23.4s, v18.4s\n\t" \
    "ushr v2.4s, v23.4s, #8\n\t" \
    "add v26.4s, v21.4s, v16.4s\n\t" \
    "add v27.4s, v22.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v29.4s\n\t" \
    "tbl v0.16b, {v20.16b, v21.16b}, %[i0].16b\n\t" \
    "ushr v6.4s, v28.4s, #8\n\t" \
    "tbl v1.16b, {v20.16b, v21.16b, v22.16b}, %[i1].16b\n\t" \
    "tbx v2.16b, {v20.16b}, %[i2].16b\n\t" \
    "tbl v3.16b, {v19.16b, v20.16b}, %[i3].16b\n\t" \
    "tbl v4.16b, {v25.16b, v26.16b}, %[i0].16b\n\t" \
    "tbl v5.16b, {v25.16b, v26.16b, v27.16b}, %[i1].16b\n\t" \
    "tbx v6.16b, {v25.16b}, %[i2].16b\n\t" \
    "tbl v7.16b, {v24.16b, v25.16b}, %[i3].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "add v21.4s, v26.4s, v16.4s\n\t" \
    "add v22.4s, v27.4s, v17.4s\n\t" \
    "add v23.4s, v28.4s, v18.4s\n\t" \
    "add v19.4s, v24.4s, v29.4s\n\t" \
    "fmov x19, d4\n\t" \
    "fmov x20, v4.d[1]\n\t" \
    "fmov x21, d5\n\t" \
    "fmov x22, v5.d[1]\n\t" \
    "fmov x23, d6\n\t" \
    "fmov x24, v6.d[1]\n\t" \
    "fmov x25, d7\n\t" \
    "fmov x26, v7.d[1]\n\t" \
    "add x11, %[cm], x2, lsr #32\n\t" \
    "ldrb w2, [%[cm], w2, uxtw]\n\t" \
    "add x9, %[cm], x0, lsr #32\n\t" \
    "ldrb w0, [%[cm], w0, uxtw]\n\t" \
    "add x10, %[cm], x1, lsr #32\n\t" \
    "ldrb w1, [%[cm], w1, uxtw]\n\t" \
    "add x12, %[cm], x3, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x18, %[cm], x4, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "subs %[q], %[q], #1\n\t" \
    "ldrb w10, [x10]\n\t" \
    "ldrb w4, [%[cm], w4, uxtw]\n\t" \
    "orr x2, x2, x11, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x11, %[cm], x7, lsr #32\n\t" \
    "ldrb w7, [%[cm], w7, uxtw]\n\t" \
    "orr x1, x1, x10, lsl #8\n\t" \
    "ldrb w3, [%[cm], w3, uxtw]\n\t" \
    "orr x0, x0, x9, lsl #8\n\t" \
    "ldrb w18, [x18]\n\t" \
    "add x10, %[cm], x6, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x9, %[cm], x5, lsr #32\n\t" \
    "ldrb w6, [%[cm], w6, uxtw]\n\t" \
    "orr x3, x3, x12, lsl #8\n\t" \
    "ldrb w5, [%[cm], w5, uxtw]\n\t" \
    "add x12, %[cm], x22, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x4, x4, x18, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x7, x7, x11, lsl #8\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x11, %[cm], x21, lsr #32\n\t" \
    "ldrb w21, [%[cm], w21, uxtw]\n\t" \
    "orr x6, x6, x10, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x10, %[cm], x20, lsr #32\n\t" \
    "ldrb w20, [%[cm], w20, uxtw]\n\t" \
    "orr x5, x5, x9, lsl #8\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x9, %[cm], x19, lsr #32\n\t" \
    "ldrb w19, [%[cm], w19, uxtw]\n\t" \
    "add x18, %[cm], x23, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x0, x0, x1, lsl #16\n\t" \
    "ldrb w22, [%[cm], w22, uxtw]\n\t" \
    "orr x21, x21, x11, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x11, %[cm], x26, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x20, x20, x10, lsl #8\n\t" \
    "ldrb w26, [%[cm], w26, uxtw]\n\t" \
    "add x10, %[cm], x25, lsr #32\n\t" \
    "ldrb w25, [%[cm], w25, uxtw]\n\t" \
    "orr x19, x19, x9, lsl #8\n\t" \
    "ldr q20, [x8, %[goff]]\n\t" \
    "add x9, %[cm], x24, lsr #32\n\t" \
    "ldrb w23, [%[cm], w23, uxtw]\n\t" \
    "orr x2, x2, x3, lsl #16\n\t" \
    "ldrb w24, [%[cm], w24, uxtw]\n\t" \
    "orr x4, x4, x5, lsl #16\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x6, x6, x7, lsl #16\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x0, x0, x2, lsl #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "orr x19, x19, x20, lsl #16\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "orr x25, x25, x10, lsl #8\n\t" \
    "orr x23, x23, x18, lsl #8\n\t" \
    "orr x24, x24, x9, lsl #8\n\t" \
    "orr x22, x22, x12, lsl #8\n\t" \
    "orr x4, x4, x6, lsl #32\n\t" \
    "orr x26, x26, x11, lsl #8\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ldr q25, [x8, %[goff]]\n\t" \
    "orr x21, x21, x22, lsl #16\n\t" \
    "orr x23, x23, x24, lsl #16\n\t" \
    "orr x25, x25, x26, lsl #16\n\t" \
    "stp x0, x4, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "orr x19, x19, x21, lsl #32\n\t" \
    "orr x23, x23, x25, lsl #32\n\t" \
    "b.ne 1b\n\t"

// Mip 2: a band (two pairs of rows) an iteration, q counting -rows + 4 up to 0. The
// band's step from its e, e1 (16 bytes at dte + 4 q): lanes of quarter j
// (4 - fx) e[j] + fx e1[j], << 4 (wt: the weights, low half 4 - fx, high half fx).
// The second pair computes the next band's (after its last use of the step). (The
// branch between the pairs ends a translation block of the qemu block profiler
// there, not inside the second pair's NEON run: its pieces are then one pair each.)
#define SB_WEIGH_STEP \
  "smull v16.4s, %[wt].4h, v0.h[0]\n\t" \
  "smull v17.4s, %[wt].4h, v0.h[1]\n\t" \
  "smull v18.4s, %[wt].4h, v0.h[2]\n\t" \
  "smull v29.4s, %[wt].4h, v0.h[3]\n\t" \
  "smlal2 v16.4s, %[wt].8h, v0.h[4]\n\t" \
  "smlal2 v17.4s, %[wt].8h, v0.h[5]\n\t" \
  "smlal2 v18.4s, %[wt].8h, v0.h[6]\n\t" \
  "smlal2 v29.4s, %[wt].8h, v0.h[7]\n\t"

// Mip 3's loop (asm/neon.cpp, surface_block_groups: "Mip 3 (a band an iteration, ...)"
// describes the registers and the stack frame): every full group of the call, a band an
// iteration, both rows' lights weighed from the grid in the loop.
#define SB_MIP3_LOOP \
  "sub sp, sp, #32\n\t" \
  "stp %[d], x10, [sp]\n\t" \
  "stp %[rp], %[gp], [sp, #16]\n\t" \
  "3:\n\t" \
  "ldr x8, [%[rp]]\n\t" \
  "ldr x10, [%[rp], #8]\n\t" \
  "add x9, %[gp], %[gst]\n\t" \
  "ldr q26, [%[gp]]\n\t" \
  "ldur q27, [%[gp], #2]\n\t" \
  "ldr q0, [x9]\n\t" \
  "ldur q1, [x9, #2]\n\t" \
  "ldr q20, [x8]\n\t" \
  "ldr q25, [x10]\n\t" \
  "add %[gp], x9, %[gst]\n\t" \
  "add %[rp], %[rp], #16\n\t" \
  "cmp %[gp], %[ge]\n\t" \
  "movi v31.8h, #0xff\n\t" \
  "add v19.8h, v26.8h, v27.8h\n\t" \
  "add v18.8h, v26.8h, v26.8h\n\t" \
  "add v29.8h, v0.8h, v1.8h\n\t" \
  "add v28.8h, v0.8h, v0.8h\n\t" \
  "b 1f\n\t" \
  ".p2align 10\n\t"  /* (the loop, 520 bytes, then never straddles a page) */ \
  "1:\n\t" \
  "sub x9, %[gp], %[gst]\n\t" \
  "csel x9, %[gp], x9, lo\n\t" \
  "add v21.8h, v18.8h, v28.8h\n\t" \
  "ushr v0.8h, v18.8h, #1\n\t" \
  "add v22.8h, v19.8h, v29.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "ldr q26, [x9]\n\t" \
  "ldur q27, [x9, #2]\n\t" \
  "ushr v2.8h, v21.8h, #2\n\t" \
  "bit v0.16b, v20.16b, v31.16b\n\t" \
  "ushr v3.8h, v22.8h, #2\n\t" \
  "sri v1.8h, v20.8h, #8\n\t" \
  "mov v18.16b, v28.16b\n\t" \
  "add v28.8h, v26.8h, v26.8h\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "fmov x1, v0.d[1]\n\t" \
  "sri v3.8h, v25.8h, #8\n\t" \
  "fmov x2, d1\n\t" \
  "mov v19.16b, v29.16b\n\t" \
  "fmov x0, d0\n\t" \
  "fmov x3, v1.d[1]\n\t" \
  "fmov x4, d2\n\t" \
  "fmov x6, d3\n\t" \
  "add v29.8h, v26.8h, v27.8h\n\t" \
  "fmov x5, v2.d[1]\n\t" \
  "fmov x7, v3.d[1]\n\t" \
  "ldr x8, [%[rp]]\n\t" \
  "add %[gp], %[gp], %[gst]\n\t" \
  "add x11, %[cm], x0, lsr #48\n\t" \
  "ubfx x12, x2, #16, #16\n\t" \
  "ubfx x18, x2, #32, #16\n\t" \
  "ubfx x21, x4, #32, #16\n\t" \
  "ubfx x24, x6, #32, #16\n\t" \
  "ubfx x26, x1, #16, #16\n\t" \
  "ubfx x9, x0, #16, #16\n\t" \
  "ubfx x20, x4, #16, #16\n\t" \
  "ubfx x10, x0, #32, #16\n\t" \
  "ubfx x30, x1, #32, #16\n\t" \
  "ubfx x23, x6, #16, #16\n\t" \
  "ldrb w12, [%[cm], x12]\n\t" \
  "add x19, %[cm], x2, lsr #48\n\t" \
  "ldrb w18, [%[cm], x18]\n\t" \
  "add x2, %[cm], w2, uxth\n\t" \
  "ldrb w9, [%[cm], x9]\n\t" \
  "add x22, %[cm], x4, lsr #48\n\t" \
  "ldrb w10, [%[cm], x10]\n\t" \
  "add x4, %[cm], w4, uxth\n\t" \
  "ldrb w26, [%[cm], x26]\n\t" \
  "add x0, %[cm], w0, uxth\n\t" \
  "ldrb w2, [x2]\n\t" \
  "ldrb w11, [x11]\n\t" \
  "orr x9, x9, x12, lsl #8\n\t" \
  "ldrb w19, [x19]\n\t" \
  "cmp %[gp], %[ge]\n\t" \
  "ldrb w0, [x0]\n\t" \
  "add x25, %[cm], x6, lsr #48\n\t" \
  "ldrb w4, [x4]\n\t" \
  "orr x10, x10, x18, lsl #8\n\t" \
  "ldrb w30, [%[cm], x30]\n\t" \
  "orr x11, x11, x19, lsl #8\n\t" \
  "ldrb w22, [x22]\n\t" \
  "orr x0, x0, x2, lsl #8\n\t" \
  "ldrb w25, [x25]\n\t" \
  "orr x0, x0, x9, lsl #16\n\t" \
  "ldrb w20, [%[cm], x20]\n\t" \
  "add x12, %[cm], x3, lsr #48\n\t" \
  "ldrb w23, [%[cm], x23]\n\t" \
  "add x9, %[cm], x1, lsr #48\n\t" \
  "ldrb w24, [%[cm], x24]\n\t" \
  "ldrb w21, [%[cm], x21]\n\t" \
  "add x6, %[cm], w6, uxth\n\t" \
  "orr x10, x10, x11, lsl #16\n\t" \
  "add x1, %[cm], w1, uxth\n\t" \
  "ldrb w9, [x9]\n\t" \
  "orr x0, x0, x10, lsl #32\n\t" \
  "orr x22, x22, x25, lsl #8\n\t" \
  "ubfx x18, x5, #16, #16\n\t" \
  "ldrb w12, [x12]\n\t" \
  "orr x21, x21, x24, lsl #8\n\t" \
  "ldrb w6, [x6]\n\t" \
  "orr x21, x21, x22, lsl #16\n\t" \
  "orr x20, x20, x23, lsl #8\n\t" \
  "ubfx x22, x7, #32, #16\n\t" \
  "ubfx x19, x5, #32, #16\n\t" \
  "ubfx x10, x3, #16, #16\n\t" \
  "ubfx x11, x3, #32, #16\n\t" \
  "add x23, %[cm], x7, lsr #48\n\t" \
  "ldrb w19, [%[cm], x19]\n\t" \
  "add x3, %[cm], w3, uxth\n\t" \
  "ldrb w18, [%[cm], x18]\n\t" \
  "orr x4, x4, x6, lsl #8\n\t" \
  "ldrb w1, [x1]\n\t" \
  "orr x4, x4, x20, lsl #16\n\t" \
  "ldrb w11, [%[cm], x11]\n\t" \
  "ldrb w3, [x3]\n\t" \
  "add x20, %[cm], x5, lsr #48\n\t" \
  "ldrb w23, [x23]\n\t" \
  "orr x9, x9, x12, lsl #8\n\t" \
  "ldr q20, [x8]\n\t" \
  "orr x4, x4, x21, lsl #32\n\t" \
  "add x5, %[cm], w5, uxth\n\t" \
  "ubfx x21, x7, #16, #16\n\t" \
  "ldrb w10, [%[cm], x10]\n\t" \
  "add x7, %[cm], w7, uxth\n\t" \
  "ldrb w20, [x20]\n\t" \
  "orr x30, x30, x11, lsl #8\n\t" \
  "ldrb w21, [%[cm], x21]\n\t" \
  "orr x30, x30, x9, lsl #16\n\t" \
  "ldrb w22, [%[cm], x22]\n\t" \
  "orr x26, x26, x10, lsl #8\n\t" \
  "ldrb w7, [x7]\n\t" \
  "orr x1, x1, x3, lsl #8\n\t" \
  "ldrb w5, [x5]\n\t" \
  "orr x20, x20, x23, lsl #8\n\t" \
  "orr x1, x1, x26, lsl #16\n\t" \
  "orr x1, x1, x30, lsl #32\n\t" \
  "orr x18, x18, x21, lsl #8\n\t" \
  "orr x19, x19, x22, lsl #8\n\t" \
  "ldr x8, [%[rp], #8]\n\t" \
  "orr x19, x19, x20, lsl #16\n\t" \
  "orr x5, x5, x7, lsl #8\n\t" \
  "orr x5, x5, x18, lsl #16\n\t" \
  "stp x0, x1, [%[d]]\n\t" \
  "orr x5, x5, x19, lsl #32\n\t" \
  "add %[d], %[d], %[w]\n\t" \
  "ldr q25, [x8]\n\t" \
  "stp x4, x5, [%[d]]\n\t" \
  "add %[rp], %[rp], #16\n\t" \
  "add %[d], %[d], %[w]\n\t" \
  "b.ls 1b\n\t" \
  "ldp %[d], x10, [sp]\n\t" \
  "ldp %[rp], %[gp], [sp, #16]\n\t" \
  "add %[d], %[d], #16\n\t" \
  "add %[gp], %[gp], #16\n\t" \
  "add %[ge], %[ge], #16\n\t" \
  "subs x10, x10, #1\n\t" \
  "stp %[d], x10, [sp]\n\t" \
  "str %[gp], [sp, #24]\n\t" \
  "b.ne 3b\n\t" \
  "add sp, sp, #32\n\t"
