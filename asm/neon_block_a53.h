// asm/neon_block_a53.h: the AArch64 assembly text of the surface block builder's row loops
// for in-order cores (the neon_a53 table, kInOrder in asm/neon.cpp's surface_block_groups:
// mips 0-2), as macros. Operand names and register roles are described there (and the
// instruction orders' search in bench/mca_a53_block); only asm/neon.cpp includes this.
#pragma once

// In-order cores (Cortex-A53 model): llvm-mca writes results back in program order, so core
// instructions after a NEON one wait for it and the NEON run costs its length in full; this
// loop keeps it short (20 instructions for two rows). The indices leave as 16-bit lanes, four a
// 64-bit move (x0-x3 the even row, x4-x7 the odd one, texels 4i..4i + 3 in xi). Each index
// becomes an address (cm + lane; every loop of this file: lanes 0 and 3 of xi by uxth and
// lsr #48, lanes 2 and 1 from `ror xT, xi, #32` by uxth and lsr #48, 5 ops a word, no mask)
// and its colormap byte is loaded straight into an output
// lane (ld1 lane), no packing: v4 / v5 the even row's bytes 0-7 / 8-15, v6 / v7 the odd row's,
// four chains taken in turn (a lane load waits for the previous one into its register). Rows
// are stored in the next iteration (d: the even row, first; x8: the odd, after the NEON run);
// the loop is entered at 2: after SB_PAIR_LOOP_16_PRO, the instructions before it but the
// stores. Numerators {N2, N3, T, N0, N1}: v19-v23 (even row), v24-v28 (odd); steps v16-v18, v29
// as in the loop below; x26 is a temporary of SB_PAIR_LOOP_16W0 / W1 (no loop reads a
// mask). (Orders from bench/order_search.py, every loop of this
// file.)
#define SB_PAIR_LOOP_16_PRO \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x0, d0\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t"

#define SB_PAIR_LOOP_16 \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "fmov x0, d0\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "2:\n\t" \
    "ror x20, x2, #32\n\t" \
    "ror x18, x0, #32\n\t" \
    "add x9, %[cm], w0, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x10, %[cm], w2, uxth\n\t" \
    "ror x22, x4, #32\n\t" \
    "add x12, %[cm], w6, uxth\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "add x11, %[cm], w4, uxth\n\t" \
    "ror x24, x6, #32\n\t" \
    "add x21, %[cm], w20, uxth\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "add x23, %[cm], w22, uxth\n\t" \
    "ld1 {v4.b}[0], [x9]\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "ld1 {v6.b}[0], [x11]\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "ld1 {v7.b}[0], [x12]\n\t" \
    "add x22, %[cm], x22, lsr #48\n\t" \
    "ld1 {v5.b}[0], [x10]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x20, %[cm], x20, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x18]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ld1 {v6.b}[1], [x22]\n\t" \
    "ror x22, x3, #32\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v5.b}[1], [x20]\n\t" \
    "ld1 {v4.b}[2], [x19]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "ror x19, x5, #32\n\t" \
    "ld1 {v5.b}[2], [x21]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "ld1 {v6.b}[2], [x23]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ror x18, x1, #32\n\t" \
    "ror x23, x7, #32\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x21, %[cm], w19, uxth\n\t" \
    "add x24, %[cm], w22, uxth\n\t" \
    "add x19, %[cm], x19, lsr #48\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x22, %[cm], x22, lsr #48\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x20, %[cm], w18, uxth\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "add x25, %[cm], w23, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "add x23, %[cm], x23, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v5.b}[5], [x22]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x19]\n\t" \
    "ld1 {v7.b}[5], [x23]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x20]\n\t" \
    "ld1 {v5.b}[6], [x24]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v6.b}[6], [x21]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "subs %[q], %[q], #1\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "b.ne 1b\n\t"

// The band's last pair: the next band's step weighed after its NEON run from its grid row
// differences (v8, loaded a band ahead: entries e[0..] of the group's first block, lanes 0 / 1
// for quarters 0-1, 0 / 1 (mip 0) or 1 / 2 (mip 1) for quarters 2-3), then the one after
// next loaded from ete + x30 (asm/neon_block_a53g.h's table) and x30 stepped a table row (w
// bytes) towards 0, which ends the group. la, lb: the lanes of quarters 2-3 (W0 mip 0, W1 mip 1).
#define SB_PAIR_LOOP_16W(la, lb) \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x2, d1\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull2 v29.4s, %[wb].8h, v8.h[" la "]\n\t" \
    "fmov x0, d0\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "smull v18.4s, %[wb].4h, v8.h[" la "]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "smlal2 v29.4s, %[wd].8h, v8.h[" lb "]\n\t" \
    "fmov x6, d3\n\t" \
    "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "ror x22, x4, #32\n\t" \
    "ror x20, x2, #32\n\t" \
    "ror x24, x6, #32\n\t" \
    "add x9, %[cm], w0, uxth\n\t" \
    "ror x18, x0, #32\n\t" \
    "smlal v18.4s, %[wd].4h, v8.h[" lb "]\n\t" \
    "smlal v16.4s, %[wc].4h, v8.h[1]\n\t" \
    "smlal2 v17.4s, %[wc].8h, v8.h[1]\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "add x10, %[cm], w2, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x11, %[cm], w4, uxth\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "add x12, %[cm], w6, uxth\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "add x21, %[cm], w20, uxth\n\t" \
    "ld1 {v5.b}[0], [x10]\n\t" \
    "add x23, %[cm], w22, uxth\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "ld1 {v4.b}[0], [x9]\n\t" \
    "add x9, %[cm], w3, uxth\n\t" \
    "ld1 {v6.b}[0], [x11]\n\t" \
    "add x22, %[cm], x22, lsr #48\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x20, %[cm], x20, lsr #48\n\t" \
    "ld1 {v7.b}[0], [x12]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x18]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x22]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v5.b}[1], [x20]\n\t" \
    "add x26, %[cm], w1, uxth\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ld1 {v4.b}[2], [x19]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "ror x24, x5, #32\n\t" \
    "ld1 {v6.b}[2], [x23]\n\t" \
    "add x10, %[cm], w5, uxth\n\t" \
    "ror x12, x1, #32\n\t" \
    "ld1 {v5.b}[2], [x21]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "ror x20, x3, #32\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "add x11, %[cm], w7, uxth\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x19, %[cm], w24, uxth\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "ror x21, x7, #32\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "add x18, %[cm], w12, uxth\n\t" \
    "add x12, %[cm], x12, lsr #48\n\t" \
    "add x22, %[cm], w20, uxth\n\t" \
    "ld1 {v7.b}[4], [x11]\n\t" \
    "add x20, %[cm], x20, lsr #48\n\t" \
    "ld1 {v4.b}[4], [x26]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x9]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x10]\n\t" \
    "add x23, %[cm], w21, uxth\n\t" \
    "ldr q8, [%[ete], x30]\n\t" \
    "add x21, %[cm], x21, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x12]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x20]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x24]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "mov %[q], %[hp1]\n\t" \
    "ld1 {v4.b}[6], [x18]\n\t" \
    "ld1 {v5.b}[6], [x22]\n\t" \
    "ld1 {v6.b}[6], [x19]\n\t" \
    "ld1 {v7.b}[6], [x23]\n\t" \
    "adds x30, x30, %[w]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "b.ne 1b\n\t"

#define SB_PAIR_LOOP_16W0 SB_PAIR_LOOP_16W("0", "1")
#define SB_PAIR_LOOP_16W1 SB_PAIR_LOOP_16W("1", "2")

// Mip 2, in-order cores: the loop above, a band (two pairs) an iteration: the first pair
// loads the next band's grid row differences (v8, from ete + q: e[0..4] of the group's
// blocks), the second weighs them into the step after its last use of the current one and
// steps q a table row (w bytes) towards 0, which ends the group.
#define SB_PAIR16_A \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "2:\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "ldr q8, [%[ete], %[q]]\n\t" \
    "ror x21, x4, #32\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "add x12, %[cm], w2, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "ror x10, x0, #32\n\t" \
    "add x9, %[cm], w0, uxth\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ror x18, x2, #32\n\t" \
    "add x23, %[cm], w6, uxth\n\t" \
    "ld1 {v5.b}[0], [x12]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ror x24, x6, #32\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x22, %[cm], w21, uxth\n\t" \
    "ld1 {v4.b}[0], [x9]\n\t" \
    "add x11, %[cm], w10, uxth\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x10, %[cm], x10, lsr #48\n\t" \
    "ld1 {v7.b}[0], [x23]\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "add x21, %[cm], x21, lsr #48\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x10]\n\t" \
    "add x12, %[cm], w3, uxth\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ror x10, x1, #32\n\t" \
    "ld1 {v5.b}[1], [x18]\n\t" \
    "add x20, %[cm], w5, uxth\n\t" \
    "ld1 {v6.b}[1], [x21]\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ld1 {v4.b}[2], [x11]\n\t" \
    "ror x21, x5, #32\n\t" \
    "ld1 {v5.b}[2], [x19]\n\t" \
    "add x11, %[cm], w10, uxth\n\t" \
    "ld1 {v6.b}[2], [x22]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "ror x24, x7, #32\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "add x23, %[cm], w7, uxth\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x22, %[cm], w21, uxth\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "ld1 {v6.b}[4], [x20]\n\t" \
    "add x10, %[cm], x10, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x12]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "add x21, %[cm], x21, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x23]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x10]\n\t" \
    "ld1 {v5.b}[5], [x18]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x21]\n\t" \
    "ld1 {v7.b}[5], [x24]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x11]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x19]\n\t" \
    "ld1 {v6.b}[6], [x22]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "b 3f\n\t" \
    "3:\n\t"

#define SB_PAIR16_B \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull v16.4s, %[wt].4h, v8.h[0]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "smull v29.4s, %[wt].4h, v8.h[3]\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x6, d3\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "smull v17.4s, %[wt].4h, v8.h[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "smlal2 v16.4s, %[wt].8h, v8.h[1]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "smull v18.4s, %[wt].4h, v8.h[2]\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "ror x24, x6, #32\n\t" \
    "add x9, %[cm], w0, uxth\n\t" \
    "add x23, %[cm], w6, uxth\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "ror x21, x4, #32\n\t" \
    "adds %[q], %[q], %[w]\n\t" \
    "ror x10, x0, #32\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "ror x18, x2, #32\n\t" \
    "ld1 {v4.b}[0], [x9]\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "add x12, %[cm], w2, uxth\n\t" \
    "add x22, %[cm], w21, uxth\n\t" \
    "add x11, %[cm], w10, uxth\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x10, %[cm], x10, lsr #48\n\t" \
    "ld1 {v7.b}[0], [x23]\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "ld1 {v5.b}[0], [x12]\n\t" \
    "add x21, %[cm], x21, lsr #48\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x10]\n\t" \
    "add x23, %[cm], w7, uxth\n\t" \
    "ror x10, x1, #32\n\t" \
    "add x12, %[cm], w3, uxth\n\t" \
    "ld1 {v5.b}[1], [x18]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x21]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x11]\n\t" \
    "ror x21, x5, #32\n\t" \
    "ld1 {v5.b}[2], [x19]\n\t" \
    "add x20, %[cm], w5, uxth\n\t" \
    "ld1 {v6.b}[2], [x22]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ror x24, x7, #32\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x22, %[cm], w21, uxth\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x11, %[cm], w10, uxth\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x25, %[cm], w24, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x10, %[cm], x10, lsr #48\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "add x19, %[cm], w18, uxth\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x21, %[cm], x21, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x20]\n\t" \
    "add x18, %[cm], x18, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x12]\n\t" \
    "add x24, %[cm], x24, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x23]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x10]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v6.b}[5], [x21]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x18]\n\t" \
    "ld1 {v7.b}[5], [x24]\n\t" \
    "smlal2 v17.4s, %[wt].8h, v8.h[2]\n\t" \
    "ld1 {v6.b}[6], [x22]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x19]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x11]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "smlal2 v29.4s, %[wt].8h, v8.h[4]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "smlal2 v18.4s, %[wt].8h, v8.h[3]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "b.ne 1b\n\t"
