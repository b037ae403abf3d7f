// asm/neon_block_a53m1.h: mip 1's group entry and row loop for in-order cores (the neon_a53 table,
// kInOrder in asm/neon.cpp's surface_block_groups), used by asm/neon_block_a53g.h's SB_A53_GROUPS.
// Registers and operands as in asm/neon_block_a53.h, and %[q] (free at mip 1) a row pointer.
// Orders from bench/order_search.py (bench/mca_a53_block/band16w1.s, head1.s, exit1.s): the band
// against qemu's translation-block cuts (--qcuts: bench/count.sh times each cut piece).
// Only asm/neon_block_a53g.h includes this.
#pragma once

// The group's entry: SB_A53_HEAD01 at mip 1 (numerators from row 0 (v0) of the table at x11, the
// first band's step from row 1 (v8), row 2 preloaded into v8), the first pair's rows (v21, v26;
// rp stepped a pair), d one pair back, then the first pair's NEON run (SB_PAIR_LOOP_16_PRO:
// SB_BAND_16W1's lines before 2: but the stores), interleaved.
#define SB_A53_HEAD1 \
    "ldr q0, [x11]\n\t" \
    "add x10, x11, %[w]\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x9, x10, %[w]\n\t" \
    "ldr %[q], [%[rp], #8]\n\t" \
    "ldr q8, [x10]\n\t" \
    "smull2 v23.4s, %[wa].8h, v0.h[0]\n\t" \
    "smull v22.4s, %[wa].4h, v0.h[0]\n\t" \
    "smull2 v20.4s, %[wb].8h, v0.h[1]\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "smull v19.4s, %[wb].4h, v0.h[1]\n\t" \
    "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
    "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
    "smlal v22.4s, %[wc].4h, v0.h[1]\n\t" \
    "smlal2 v23.4s, %[wc].8h, v0.h[1]\n\t" \
    "smull v18.4s, %[wb].4h, v8.h[1]\n\t" \
    "smlal2 v20.4s, %[wd].8h, v0.h[2]\n\t" \
    "smlal v19.4s, %[wd].4h, v0.h[2]\n\t" \
    "smull2 v29.4s, %[wb].8h, v8.h[1]\n\t" \
    "smlal v16.4s, %[wc].4h, v8.h[1]\n\t" \
    "shl v23.4s, v23.4s, #3\n\t" \
    "shl v22.4s, v22.4s, #3\n\t" \
    "shl v20.4s, v20.4s, #3\n\t" \
    "smlal2 v17.4s, %[wc].8h, v8.h[1]\n\t" \
    "smlal2 v29.4s, %[wd].8h, v8.h[2]\n\t" \
    "shl v19.4s, v19.4s, #3\n\t" \
    "smlal v18.4s, %[wd].4h, v8.h[2]\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "ldr q26, [%[q], %[goff]]\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "fmov x0, d0\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "fmov x2, d1\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x4, d2\n\t" \
    "ldr q8, [x9]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "sub %[d], %[d], %[w], lsl #1\n\t"

// A band (four pairs of rows, 8 x 16 texels) an iteration: three plain pairs (asm/neon_block_a53.h's
// SB_PAIR_LOOP_16 without its counter) and the band end (SB_PAIR_LOOP_16W1), no branch between,
// so the band end's extra work shares the plain pairs' idle slots. Lane 0 of each output half by
// `ldr b` (the whole register written: no lane chain from pair to pair), the pairs' row pointers
// by offsets from rp (one step a band; the odd row's pointer in %[q]), lane addresses in x9-x12,
// x18-x26 (least recently freed first). Entered at 2: (in the first pair, after its NEON run);
// x30 steps a table row towards 0 at the band end, which ends the group.
#define SB_BAND_16W1 \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "fmov x0, d0\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x4, d2\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "2:\n\t" \
    "ror x9, x0, #32\n\t" \
    "add x10, %[cm], w0, uxth\n\t" \
    "ror x11, x2, #32\n\t" \
    "add x19, %[cm], x0, lsr #48\n\t" \
    "ror x18, x4, #32\n\t" \
    "add x20, %[cm], w6, uxth\n\t" \
    "add x12, %[cm], w2, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x23, %[cm], w9, uxth\n\t" \
    "ror x22, x6, #32\n\t" \
    "add x21, %[cm], w4, uxth\n\t" \
    "ldr b4, [x10]\n\t" \
    "add x24, %[cm], w18, uxth\n\t" \
    "ldr b7, [x20]\n\t" \
    "add x10, %[cm], x9, lsr #48\n\t" \
    "ldr b5, [x12]\n\t" \
    "add x26, %[cm], w22, uxth\n\t" \
    "ldr b6, [x21]\n\t" \
    "add x21, %[cm], x18, lsr #48\n\t" \
    "add x9, %[cm], x11, lsr #48\n\t" \
    "add x25, %[cm], w11, uxth\n\t" \
    "ld1 {v4.b}[1], [x10]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ldr %[q], [%[rp], #8]\n\t" \
    "add x20, %[cm], x22, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x21]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v5.b}[1], [x9]\n\t" \
    "ror x10, x5, #32\n\t" \
    "ld1 {v4.b}[2], [x23]\n\t" \
    "add x9, %[cm], x6, lsr #48\n\t" \
    "ldr q26, [%[q], %[goff]]\n\t" \
    "add x11, %[cm], x2, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x20]\n\t" \
    "add x22, %[cm], w3, uxth\n\t" \
    "ld1 {v5.b}[2], [x25]\n\t" \
    "add x25, %[cm], w18, uxth\n\t" \
    "ld1 {v4.b}[3], [x19]\n\t" \
    "add x23, %[cm], w1, uxth\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x19, %[cm], w10, uxth\n\t" \
    "ld1 {v7.b}[2], [x26]\n\t" \
    "ror x20, x1, #32\n\t" \
    "add x21, %[cm], x4, lsr #48\n\t" \
    "ror x24, x7, #32\n\t" \
    "ld1 {v4.b}[4], [x23]\n\t" \
    "add x26, %[cm], x10, lsr #48\n\t" \
    "ld1 {v5.b}[3], [x11]\n\t" \
    "add x12, %[cm], w5, uxth\n\t" \
    "ld1 {v7.b}[3], [x9]\n\t" \
    "add x23, %[cm], x18, lsr #48\n\t" \
    "ld1 {v6.b}[3], [x21]\n\t" \
    "add x11, %[cm], w24, uxth\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x18, %[cm], w7, uxth\n\t" \
    "ld1 {v5.b}[4], [x22]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "add x21, %[cm], x20, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x12]\n\t" \
    "add x9, %[cm], x24, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x18]\n\t" \
    "add x10, %[cm], w20, uxth\n\t" \
    "ld1 {v4.b}[5], [x21]\n\t" \
    "add x12, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x23]\n\t" \
    "add x24, %[cm], x5, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x26]\n\t" \
    "add x22, %[cm], x1, lsr #48\n\t" \
    "ld1 {v7.b}[5], [x9]\n\t" \
    "ld1 {v4.b}[6], [x10]\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "ld1 {v6.b}[6], [x19]\n\t" \
    "add x20, %[cm], x3, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x25]\n\t" \
    "ld1 {v7.b}[6], [x11]\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "ld1 {v4.b}[7], [x22]\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "ld1 {v5.b}[7], [x20]\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "ld1 {v7.b}[7], [x12]\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "ror x23, x0, #32\n\t" \
    "add x26, %[cm], w0, uxth\n\t" \
    "add x9, %[cm], w6, uxth\n\t" \
    "ld1 {v6.b}[7], [x24]\n\t" \
    "add x18, %[cm], w2, uxth\n\t" \
    "ror x19, x4, #32\n\t" \
    "add x25, %[cm], w4, uxth\n\t" \
    "ror x21, x2, #32\n\t" \
    "add x10, %[cm], x0, lsr #48\n\t" \
    "ldr b4, [x26]\n\t" \
    "ror x11, x6, #32\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "add x24, %[cm], w23, uxth\n\t" \
    "ldr x8, [%[rp], #16]\n\t" \
    "add x22, %[cm], w21, uxth\n\t" \
    "ldr b6, [x25]\n\t" \
    "add x20, %[cm], w11, uxth\n\t" \
    "ldr b7, [x9]\n\t" \
    "add x9, %[cm], x21, lsr #48\n\t" \
    "add x26, %[cm], x23, lsr #48\n\t" \
    "add x25, %[cm], x19, lsr #48\n\t" \
    "add x12, %[cm], w19, uxth\n\t" \
    "ror x21, x5, #32\n\t" \
    "ldr b5, [x18]\n\t" \
    "ld1 {v4.b}[1], [x26]\n\t" \
    "ldr %[q], [%[rp], #24]\n\t" \
    "add x23, %[cm], x11, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x25]\n\t" \
    "add x26, %[cm], w3, uxth\n\t" \
    "ld1 {v5.b}[1], [x9]\n\t" \
    "add x11, %[cm], x2, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x24]\n\t" \
    "ld1 {v7.b}[1], [x23]\n\t" \
    "add x25, %[cm], w5, uxth\n\t" \
    "ld1 {v6.b}[2], [x12]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ld1 {v5.b}[2], [x22]\n\t" \
    "add x19, %[cm], w1, uxth\n\t" \
    "ld1 {v4.b}[3], [x10]\n\t" \
    "add x24, %[cm], x4, lsr #48\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x9, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x20]\n\t" \
    "ror x22, x7, #32\n\t" \
    "ror x23, x1, #32\n\t" \
    "add x10, %[cm], w21, uxth\n\t" \
    "ld1 {v5.b}[3], [x11]\n\t" \
    "add x12, %[cm], x21, lsr #48\n\t" \
    "ld1 {v6.b}[3], [x24]\n\t" \
    "add x24, %[cm], w7, uxth\n\t" \
    "ld1 {v4.b}[4], [x19]\n\t" \
    "add x21, %[cm], x18, lsr #48\n\t" \
    "ld1 {v7.b}[3], [x9]\n\t" \
    "add x20, %[cm], w18, uxth\n\t" \
    "ld1 {v5.b}[4], [x26]\n\t" \
    "add x9, %[cm], x23, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x25]\n\t" \
    "add x19, %[cm], x22, lsr #48\n\t" \
    "ldr q26, [%[q], %[goff]]\n\t" \
    "add x11, %[cm], w23, uxth\n\t" \
    "ld1 {v7.b}[4], [x24]\n\t" \
    "add x23, %[cm], x3, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x9]\n\t" \
    "add x25, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x21]\n\t" \
    "ld1 {v6.b}[5], [x12]\n\t" \
    "add x18, %[cm], w22, uxth\n\t" \
    "ld1 {v7.b}[5], [x19]\n\t" \
    "add x22, %[cm], x1, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x11]\n\t" \
    "ld1 {v5.b}[6], [x20]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v6.b}[6], [x10]\n\t" \
    "add x26, %[cm], x5, lsr #48\n\t" \
    "ld1 {v7.b}[6], [x18]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v4.b}[7], [x22]\n\t" \
    "ld1 {v5.b}[7], [x23]\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "ld1 {v7.b}[7], [x25]\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "fmov x0, d0\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "ld1 {v6.b}[7], [x26]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "fmov x2, d1\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "add x9, %[cm], w0, uxth\n\t" \
    "add x12, %[cm], w2, uxth\n\t" \
    "ror x11, x4, #32\n\t" \
    "ror x24, x2, #32\n\t" \
    "add x18, %[cm], w4, uxth\n\t" \
    "ldr x8, [%[rp], #32]\n\t" \
    "ror x21, x0, #32\n\t" \
    "ror x19, x6, #32\n\t" \
    "add x22, %[cm], w24, uxth\n\t" \
    "ldr b4, [x9]\n\t" \
    "add x20, %[cm], w6, uxth\n\t" \
    "ldr b6, [x18]\n\t" \
    "add x10, %[cm], x0, lsr #48\n\t" \
    "add x26, %[cm], w11, uxth\n\t" \
    "add x25, %[cm], w19, uxth\n\t" \
    "add x9, %[cm], x21, lsr #48\n\t" \
    "ldr b7, [x20]\n\t" \
    "add x18, %[cm], x11, lsr #48\n\t" \
    "ldr b5, [x12]\n\t" \
    "add x20, %[cm], x24, lsr #48\n\t" \
    "add x23, %[cm], w21, uxth\n\t" \
    "add x21, %[cm], x19, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "add x11, %[cm], w1, uxth\n\t" \
    "ld1 {v6.b}[1], [x18]\n\t" \
    "ror x9, x5, #32\n\t" \
    "ldr %[q], [%[rp], #40]\n\t" \
    "add x19, %[cm], w3, uxth\n\t" \
    "ld1 {v7.b}[1], [x21]\n\t" \
    "ror x21, x1, #32\n\t" \
    "ld1 {v5.b}[1], [x20]\n\t" \
    "add x24, %[cm], x2, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x23]\n\t" \
    "ror x12, x3, #32\n\t" \
    "ldr q26, [%[q], %[goff]]\n\t" \
    "add x18, %[cm], x6, lsr #48\n\t" \
    "ld1 {v5.b}[2], [x22]\n\t" \
    "add x20, %[cm], w7, uxth\n\t" \
    "ld1 {v6.b}[2], [x26]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x22, %[cm], x4, lsr #48\n\t" \
    "ld1 {v4.b}[3], [x10]\n\t" \
    "ld1 {v5.b}[3], [x24]\n\t" \
    "add x25, %[cm], x9, lsr #48\n\t" \
    "ror x23, x7, #32\n\t" \
    "add x26, %[cm], w9, uxth\n\t" \
    "ld1 {v7.b}[3], [x18]\n\t" \
    "add x24, %[cm], w21, uxth\n\t" \
    "add x9, %[cm], w5, uxth\n\t" \
    "add x10, %[cm], w12, uxth\n\t" \
    "ld1 {v6.b}[3], [x22]\n\t" \
    "add x22, %[cm], w23, uxth\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x18, %[cm], x12, lsr #48\n\t" \
    "ld1 {v4.b}[4], [x11]\n\t" \
    "add x12, %[cm], x21, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x19]\n\t" \
    "add x11, %[cm], x23, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x9]\n\t" \
    "add x9, %[cm], x5, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x20]\n\t" \
    "ld1 {v4.b}[5], [x12]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v5.b}[5], [x18]\n\t" \
    "add x19, %[cm], x7, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x25]\n\t" \
    "add x23, %[cm], x1, lsr #48\n\t" \
    "ld1 {v7.b}[5], [x11]\n\t" \
    "add x21, %[cm], x3, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x24]\n\t" \
    "ld1 {v5.b}[6], [x10]\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "ld1 {v6.b}[6], [x26]\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "smull2 v29.4s, %[wb].8h, v8.h[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "ld1 {v5.b}[7], [x21]\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "ld1 {v4.b}[7], [x23]\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "ld1 {v7.b}[6], [x22]\n\t" \
    "fmov x4, d2\n\t" \
    "ld1 {v6.b}[7], [x9]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "fmov x6, d3\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
    "smull v18.4s, %[wb].4h, v8.h[1]\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "smlal2 v17.4s, %[wc].8h, v8.h[1]\n\t" \
    "stp d4, d5, [%[d]]\n\t" \
    "add x25, %[cm], w0, uxth\n\t" \
    "ror x12, x4, #32\n\t" \
    "ror x11, x6, #32\n\t" \
    "ld1 {v7.b}[7], [x19]\n\t" \
    "ror x18, x2, #32\n\t" \
    "ror x20, x0, #32\n\t" \
    "ldr b4, [x25]\n\t" \
    "smlal v16.4s, %[wc].4h, v8.h[1]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "add x9, %[cm], w6, uxth\n\t" \
    "add x24, %[cm], w2, uxth\n\t" \
    "add x22, %[cm], x20, lsr #48\n\t" \
    "add x21, %[cm], w18, uxth\n\t" \
    "add x10, %[cm], w4, uxth\n\t" \
    "ldr x8, [%[rp], #48]\n\t" \
    "add x19, %[cm], w12, uxth\n\t" \
    "ldr b5, [x24]\n\t" \
    "add x25, %[cm], x18, lsr #48\n\t" \
    "add x24, %[cm], x12, lsr #48\n\t" \
    "add x23, %[cm], w11, uxth\n\t" \
    "ldr b6, [x10]\n\t" \
    "add x10, %[cm], x11, lsr #48\n\t" \
    "ldr b7, [x9]\n\t" \
    "add x9, %[cm], x0, lsr #48\n\t" \
    "ldr %[q], [%[rp], #56]\n\t" \
    "ror x11, x5, #32\n\t" \
    "ld1 {v5.b}[1], [x25]\n\t" \
    "add %[rp], %[rp], #64\n\t" \
    "ld1 {v4.b}[1], [x22]\n\t" \
    "add x26, %[cm], w20, uxth\n\t" \
    "ld1 {v7.b}[1], [x10]\n\t" \
    "ld1 {v6.b}[1], [x24]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "smlal v18.4s, %[wd].4h, v8.h[2]\n\t" \
    "smlal2 v29.4s, %[wd].8h, v8.h[2]\n\t" \
    "ld1 {v4.b}[2], [x26]\n\t" \
    "add x12, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x23]\n\t" \
    "add x25, %[cm], x2, lsr #48\n\t" \
    "ld1 {v5.b}[2], [x21]\n\t" \
    "ror x22, x1, #32\n\t" \
    "ld1 {v6.b}[2], [x19]\n\t" \
    "add x26, %[cm], w11, uxth\n\t" \
    "ror x24, x3, #32\n\t" \
    "add x20, %[cm], w3, uxth\n\t" \
    "ld1 {v7.b}[3], [x12]\n\t" \
    "add x18, %[cm], x4, lsr #48\n\t" \
    "ld1 {v5.b}[3], [x25]\n\t" \
    "add x12, %[cm], x22, lsr #48\n\t" \
    "ld1 {v4.b}[3], [x9]\n\t" \
    "add x23, %[cm], w7, uxth\n\t" \
    "ldr q26, [%[q], %[goff]]\n\t" \
    "ror x10, x7, #32\n\t" \
    "add x21, %[cm], w22, uxth\n\t" \
    "add x22, %[cm], w1, uxth\n\t" \
    "ldr q8, [%[ete], x30]\n\t" \
    "add x19, %[cm], w5, uxth\n\t" \
    "ld1 {v6.b}[3], [x18]\n\t" \
    "add x9, %[cm], w24, uxth\n\t" \
    "ld1 {v7.b}[4], [x23]\n\t" \
    "ld1 {v4.b}[4], [x22]\n\t" \
    "add x25, %[cm], x24, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x20]\n\t" \
    "add x24, %[cm], x11, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x19]\n\t" \
    "add x11, %[cm], x10, lsr #48\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x22, %[cm], w10, uxth\n\t" \
    "ld1 {v4.b}[5], [x12]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "ld1 {v5.b}[5], [x25]\n\t" \
    "ld1 {v6.b}[5], [x24]\n\t" \
    "add x20, %[cm], x7, lsr #48\n\t" \
    "ld1 {v7.b}[5], [x11]\n\t" \
    "ld1 {v4.b}[6], [x21]\n\t" \
    "add x18, %[cm], x1, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x9]\n\t" \
    "add x19, %[cm], x3, lsr #48\n\t" \
    "ld1 {v6.b}[6], [x26]\n\t" \
    "add x23, %[cm], x5, lsr #48\n\t" \
    "ld1 {v7.b}[6], [x22]\n\t" \
    "ld1 {v4.b}[7], [x18]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v5.b}[7], [x19]\n\t" \
    "adds x30, x30, %[w]\n\t" \
    "ld1 {v6.b}[7], [x23]\n\t" \
    "ld1 {v7.b}[7], [x20]\n\t" \
    "b.ne 1b\n\t"

// The group exit: asm/neon_block_a53g.h's SB_A53_EXIT("x30", "4") reordered (bench/order_search.py --mem:
// 17 -> 14 cycles); flags ne while groups remain.
#define SB_A53_EXIT1 \
    "stp d4, d5, [%[d]]\n\t" \
    "add %[ete], %[ete], #4\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "ldp x6, x7, [sp, #32]\n\t" \
    "ldp x0, x11, [sp]\n\t" \
    "add %[goff], %[goff], x7\n\t" \
    "ldr x5, [sp, #48]\n\t" \
    "cmp %[goff], x6\n\t" \
    "sub x4, %[goff], x6\n\t" \
    "add x11, x11, #4\n\t" \
    "add x0, x0, #16\n\t" \
    "ldp x30, %[rp], [sp, #16]\n\t" \
    "csel %[goff], x4, %[goff], cs\n\t" \
    "cmp x0, x5\n\t" \
    "mov %[d], x0\n\t" \
    "stp x0, x11, [sp]\n\t"
