// asm/neon_block_mip3l.h: the mip-3 surface block builder's lean path on AArch64 (the
// neon_a53 variant): textures whose width divides 16 (a power of two <= 16: mip 3 of the
// 64- and 128-wide textures) and whose height is a power of two <= 64, surfaces whose width
// is a multiple of 16. Only asm/neon.cpp includes this (after asm/neon_block_mip3.h, whose
// band loop it runs, reordered, with its own texel row reads).
//
// Every group reads the same 16 laid-out bytes of a texture row (byte k: texel (c0 + k) mod
// tw), so the th rows are laid out once, in texture order, 16 bytes each: buf + 16 t holds
// texture row t, buf aligned to twice the buffer's size P = 16 th. The band loop reads its
// two texel rows at x5 and x5 + 16 and steps x5 by 32 and back by P at the end (x5 & ~P: the
// rows start at an even row, so a band's pair never straddles the end): no row pointers, no
// per-row tiling. One 16-byte load covers 16 / tw texture rows, each laid out by one table
// lookup (indices (c0 + k) mod tw + j tw): every read stays inside the texture.
#pragma once
#include <arm_neon.h>

#include <cstdint>

#include "asm/neon_block_mip3.h"
#include "asm/variants.h"

namespace sb::simd::detail {
namespace {

#if defined(__aarch64__)

// The band loop (asm/neon_block_mip3.h's SB_MIP3_BAND0..2 and SB_MIP3_ENTRY, same
// registers and method) with the texel rows read at x5 and x5 + 16, x5 += 32 wrapped by
// x28 = ~P, reordered by bench/order_search.py (Cortex-A53 model: 72 -> 70
// cycles a band); the entry copy is band 0 without the previous band's stores, after the
// group's grid rows 0-2 (v16-v18, v19 = g + g1 of row 0, v20 of row 1, v22 = row 2's entries
// 1..8, x3 = row 3), the first texel rows (v24, v25 at t0, x5 = the next band's) and the
// band count x30 from the frame, the whole reordered the same way (87 -> 82 cycles).
#define SB_MIP3L_BAND0 \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q16, [x3]\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "add x24, x0, x24\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "add x16, x0, x16\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "add x25, x0, x25\n\t" \
  "add x22, x0, x22\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x16]\n\t" \
  "add x21, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x17]\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[5], [x18]\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v7.b}[5], [x19]\n\t" \
  "add x23, x0, x13, lsr #48\n\t" \
  "ld1 {v4.b}[6], [x20]\n\t" \
  "add x16, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[6], [x21]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "add x1, x1, x2\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3L_BAND1 \
  "uhadd v2.8h, v17.8h, v18.8h\n\t" \
  "ushr v1.8h, v20.8h, #1\n\t" \
  "add v3.8h, v20.8h, v21.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "bif v24.16b, v17.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q17, [x3]\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "add x24, x0, x24\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "add x16, x0, x16\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "add x25, x0, x25\n\t" \
  "add x22, x0, x22\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x16]\n\t" \
  "add x21, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x17]\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[5], [x18]\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v7.b}[5], [x19]\n\t" \
  "add x23, x0, x13, lsr #48\n\t" \
  "ld1 {v4.b}[6], [x20]\n\t" \
  "add x16, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[6], [x21]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "add x1, x1, x2\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3L_BAND2 \
  "uhadd v2.8h, v18.8h, v16.8h\n\t" \
  "ushr v1.8h, v21.8h, #1\n\t" \
  "add v3.8h, v21.8h, v19.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "bif v24.16b, v18.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q18, [x3]\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v20.8h, v17.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "add x24, x0, x24\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "add x16, x0, x16\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "add x25, x0, x25\n\t" \
  "add x22, x0, x22\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x16]\n\t" \
  "add x21, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x17]\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[5], [x18]\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v7.b}[5], [x19]\n\t" \
  "add x23, x0, x13, lsr #48\n\t" \
  "ld1 {v4.b}[6], [x20]\n\t" \
  "add x16, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[6], [x21]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "add x1, x1, x2\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3L_ENTRY \
  "add x9, x6, x4\n\t" \
  "ldr q16, [x6]\n\t" \
  "add x8, x6, x10\n\t" \
  "ldur q22, [x6, #2]\n\t" \
  "ldr q17, [x9]\n\t" \
  "ldur q23, [x9, #2]\n\t" \
  "ldr q18, [x8]\n\t" \
  "ldp x5, x30, [sp, #24]\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "add v20.8h, v17.8h, v23.8h\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "cmp x30, #4\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x5, x5, #32\n\t" \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "ldur q22, [x8, #2]\n\t" \
  "and x5, x5, x28\n\t" \
  "add x3, x6, x11\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "ldr q16, [x3]\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x24, x0, x24\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "add x16, x0, x16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "add x23, x0, x23\n\t" \
  "add x22, x0, x22\n\t" \
  "add x24, x0, x24\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "add x25, x0, x25\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "add x16, x0, x16\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x16]\n\t" \
  "add x21, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x17]\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[5], [x18]\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v7.b}[5], [x19]\n\t" \
  "add x23, x0, x13, lsr #48\n\t" \
  "ld1 {v4.b}[6], [x20]\n\t" \
  "add x16, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[6], [x21]\n\t" \
  "add x5, x5, #32\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "ld1 {v5.b}[6], [x22]\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t"

// The column loop over n >= 1 groups (16 texels wide, bh >= 1 bands): group k writes d + 16 k
// (row stride w) from grid entries 8 k.. of rows g0 + 16 k bytes (row stride gst), texel rows
// from t0 (buf + 16 t0 = surface row 0's, x28 = ~P: above). The bands leave x6 (grid row 0),
// x7 (groups left) and x29 (saved, then (2 bh - 1) w - 16: the next group's output from the
// last row's) alone; the rest of the groups' state lives in a stack frame: [sp] the saved
// x29, (unused), t0, bands, (unused), rows 2 and 3's offsets (clamped to bh).
__attribute__((always_inline)) inline void mip3_columns_p16(const uint8_t* cm, uint8_t* d, int64_t w,
                                                            const uint16_t* g0, int64_t gst, int64_t bh,
                                                            const uint8_t* t0, int64_t notp, int64_t n) {
  register const uint8_t* x0 asm("x0") = cm;
  register uint8_t* x1 asm("x1") = d;
  register int64_t x2 asm("x2") = w;
  register int64_t x4 asm("x4") = gst;
  register const uint16_t* x6 asm("x6") = g0;
  register int64_t x10 asm("x10") = n;
  const int64_t r2 = bh >= 2 ? 2 * gst : gst;  // (bh >= 1; selects, not multiplies)
  register int64_t x11 asm("x11") = bh >= 3 ? r2 + gst : r2;
  register const uint8_t* x12 asm("x12") = t0;
  register int64_t x28 asm("x28") = notp;
  register int64_t x13 asm("x13") = bh;
  register int64_t x14 asm("x14") = r2;
  asm volatile(
      "sub sp, sp, #64\n\t"
      "str x29, [sp]\n\t"
      "lsl x29, x13, #1\n\t"
      "sub x29, x29, #1\n\t"
      "mul x29, x29, x2\n\t"
      "sub x29, x29, #16\n\t"
      "stp x12, x13, [sp, #24]\n\t"
      "stp x14, x11, [sp, #48]\n\t"
      "mov x7, x10\n\t"
      "mov x10, x14\n\t"
      "movi v31.8h, #0xff\n\t"
      "mov x27, #0xffff\n\t"
      "b 3f\n\t"
      ".p2align 11\n\t"  // (band loop, group exit and entry: about 1.9 KiB, then never straddle a page)
      "1:\n\t" SB_MIP3L_BAND1 "b.eq 9f\n\t" SB_MIP3L_BAND2 "b.eq 9f\n\t" SB_MIP3L_BAND0 "b.ne 1b\n\t"
      "9:\n\t"
      "stp d4, d5, [x1]\n\t"
      "add x1, x1, x2\n\t"
      "stp d6, d7, [x1]\n\t"
      "sub x1, x1, x29\n\t"
      "add x6, x6, #16\n\t"
      "subs x7, x7, #1\n\t"
      "ldp x10, x11, [sp, #48]\n\t"
      "b.eq 8f\n"
      "3:\n\t"  // (a group enters with x1, x6, x7, x10, x11 set; the bands keep x6, x7, x29)
      SB_MIP3L_ENTRY "b.ne 1b\n\t"
      "b 9b\n"
      "8:\n\t"
      "ldr x29, [sp]\n\t"
      "add sp, sp, #64\n\t"
      : "+r"(x1), "+r"(x6), "+r"(x10), "+r"(x11), "+r"(x12), "+r"(x13), "+r"(x14)
      : "r"(x0), "r"(x2), "r"(x4), "r"(x28)
      : "x3", "x5", "x7", "x8", "x9", "x15", "x16", "x17", "x18", "x19", "x20", "x21", "x22", "x23", "x24", "x25",
        "x26", "x27", "x30", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", "v19", "v20",
        "v21", "v22", "v23", "v24", "v25", "v31", "cc", "memory");
}

#undef SB_MIP3L_BAND0
#undef SB_MIP3L_BAND1
#undef SB_MIP3L_BAND2
#undef SB_MIP3L_ENTRY

// The shapes the lean builder takes (the rest go to surface_block_mip3).
inline bool mip3_p16_fits(int tw, int th, int width) {
  return tw <= 16 && (tw & (tw - 1)) == 0 && th >= 2 && th <= 64 && (th & (th - 1)) == 0 && tw * th >= 16 &&
         (width & 15) == 0;
}

// Lays out the texture's th rows (16 / K wide: K rows a 16-byte load) at buf: the texture's
// tw th bytes (a power of two >= 16) 16, 32, then 64 a step, loads first.
template <int K>
__attribute__((always_inline)) inline void mip3_lay_p16(uint8_t* buf, const uint8_t* texels, int th,
                                                        uint8x16_t period) {
  uint8x16_t idx[K];
#pragma GCC unroll 8
  for (int j = 0; j < K; ++j) idx[j] = vaddq_u8(period, vdupq_n_u8(uint8_t(j * (16 / K))));
  const int bytes = 16 / K * th;
  if (bytes == 16) {
    const uint8x16_t v = vld1q_u8(texels);
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * j, vqtbl1q_u8(v, idx[j]));
    return;
  }
  const uint8_t* const end = texels + bytes;
  const uint8_t* r = texels;
  if (bytes & 32) {
    uint8x16_t a = vld1q_u8(r), b = vld1q_u8(r + 16);
    asm("" : "+w"(a), "+w"(b));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * j, vqtbl1q_u8(a, idx[j]));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * (K + j), vqtbl1q_u8(b, idx[j]));
    r += 32, buf += 32 * K;
  }
  for (; r != end; r += 64, buf += 64 * K) {  // (64 bytes a step: the table lookups' results wait less)
    uint8x16_t a = vld1q_u8(r), b = vld1q_u8(r + 16), c = vld1q_u8(r + 32), e = vld1q_u8(r + 48);
    asm("" : "+w"(a), "+w"(b), "+w"(c), "+w"(e));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * j, vqtbl1q_u8(a, idx[j]));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * (K + j), vqtbl1q_u8(b, idx[j]));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * (2 * K + j), vqtbl1q_u8(c, idx[j]));
#pragma GCC unroll 8
    for (int j = 0; j < K; ++j) vst1q_u8(buf + 16 * (3 * K + j), vqtbl1q_u8(e, idx[j]));
  }
}

// The lean mip-3 builder (asm/surface_block.h's contract at mip 3, width > 0, height > 0,
// mip3_p16_fits(tw, th, width)).
__attribute__((noipa)) void surface_block_mip3_p16(const uint16_t* grid, int gw, const uint8_t* texels, int tw,
                                                   int th, int /*mip*/, int soff, int toff, int width, int height,
                                                   const uint8_t* colormap, uint8_t* out) {
  alignas(2048) uint8_t buf[1024];
  const uint8x16_t period =
      vandq_u8(vaddq_u8(vld1q_u8(kMip3Iota), vdupq_n_u8(uint8_t(soff))), vdupq_n_u8(uint8_t(tw - 1)));
  switch (tw) {
    case 2: mip3_lay_p16<8>(buf, texels, th, period); break;
    case 4: mip3_lay_p16<4>(buf, texels, th, period); break;
    case 8: mip3_lay_p16<2>(buf, texels, th, period); break;
    default: mip3_lay_p16<1>(buf, texels, th, period); break;
  }
  mip3_columns_p16(colormap, out, width, grid, 2 * int64_t(gw), height >> 1, buf + 16 * (toff & (th - 1)),
                   ~int64_t(16 * th), width >> 4);
}

#endif  // __aarch64__

}  // namespace
}  // namespace sb::simd::detail
