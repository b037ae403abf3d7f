// asm/neon_block_mip3.h: the surface block builder at mip 3 on AArch64 (asm/surface_block.h's
// contract), its own function: 2x2-texel blocks, eight to a 16-texel group, a band (two rows)
// per loop pass. Only asm/neon.cpp includes this (after asm/neon_block_util.h).
//
// Method. With g = grid row b's entries of the group's blocks j = 0..7 (g1: entries 1..8) and
// S = g + g1 (< 2^15), the colormap rows (asm/surface_block.h, B = 2, S = 2) of band b are
//   top row    (y = 2b):     even texels hi(g),             odd texels hi(S >> 1)
//   bottom row (y = 2b + 1): even texels hi(uhadd(g, h)),   odd texels (S + S') >> 10
// (h, S': grid row b + 1; hi = the high byte of a 16-bit lane; every sum fits 16 bits and the
// halving add is exact, so these equal the reference's num >> 10). A texel pair of a row is
// one 16-bit lane of the texel vector, so each index texel | row << 8 is one byte merge:
// bif (even texel under hi(g)), trn2 (odd texel beside a high byte), bit (even texel into
// the halving sum), trn2 after a byte shift by 2 (bottom odd). Four vectors of eight 16-bit
// indices a band leave by eight 64-bit moves (x8-x15); each index becomes an address
// (cm + lane: add uxth, and + add, add lsr #48) and its colormap byte is loaded straight into
// its output lane (ld1 lane: no packing; v4 / v5 row 0's bytes 0-7 / 8-15, v6 / v7 row 1's).
//
// Pipelining (for in-order cores: llvm-mca's Cortex-A53 model writes results back in
// program order, so the NEON run is one block per band and its inputs must be ready): band b
// finds its texels (v24, v25) loaded by band b - 1, and S of grid rows b + 1 and b + 2's
// entries loaded two bands ahead: grid rows rotate through v16-v18 (g) and v19-v21 (S), so
// the loop is three band copies (SB_MIP3_BAND0..2); v22 = entries 1..8 of the next row.
// Each band stores the previous band's rows first (v4-v7); the first band of a column runs
// a copy without those stores (SB_MIP3_ENTRY), the last band's rows are stored after the loop.
// The grid row read by band b is row b + 3 clamped to the last (x3 stops advancing when
// fewer than four bands are left: x30 = bands left). Registers: x0 cm, x1 output, x2 its
// stride, x3 / x4 grid row pointer / stride (bytes), x5 texel row pointers (two a band),
// x28 the group's texel offset, x27 = 0xffff, v31 = 0x00ff lanes, x30 bands left; x6-x26
// scratch. The instruction order came from a list schedule for the A53 model's issue rules
// (an ALU op then a load per cycle) and a local search scored by llvm-mca (A53, then A57).
#pragma once
#include <arm_neon.h>

#include <cstdint>
#include <cstring>

#include "asm/neon_block_util.h"
#include "asm/variants.h"

namespace sb::simd::detail {
namespace {

#if defined(__aarch64__)

#define SB_MIP3_BAND0 \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "ldp x6, x7, [x5], #16\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q16, [x3]\n\t" \
  "add x1, x1, x2\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x10, d1\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x6, x28]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x7, x28]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "add x16, x0, x16\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "add x22, x0, x22\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
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
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3_BAND1 \
  "uhadd v2.8h, v17.8h, v18.8h\n\t" \
  "ushr v1.8h, v20.8h, #1\n\t" \
  "add v3.8h, v20.8h, v21.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "ldp x6, x7, [x5], #16\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "bif v24.16b, v17.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q17, [x3]\n\t" \
  "add x1, x1, x2\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x10, d1\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x6, x28]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x7, x28]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "add x16, x0, x16\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "add x22, x0, x22\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
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
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3_BAND2 \
  "uhadd v2.8h, v18.8h, v16.8h\n\t" \
  "ushr v1.8h, v21.8h, #1\n\t" \
  "add v3.8h, v21.8h, v19.8h\n\t" \
  "stp d4, d5, [x1]\n\t" \
  "add x1, x1, x2\n\t" \
  "ldp x6, x7, [x5], #16\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "bif v24.16b, v18.16b, v31.16b\n\t" \
  "stp d6, d7, [x1]\n\t" \
  "ldr q18, [x3]\n\t" \
  "add x1, x1, x2\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x10, d1\n\t" \
  "add v20.8h, v17.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x6, x28]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x7, x28]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "add x16, x0, x16\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "add x22, x0, x22\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
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
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

#define SB_MIP3_ENTRY \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "ldp x6, x7, [x5], #16\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "ldr q16, [x3]\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x10, d1\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "ldr q24, [x6, x28]\n\t" \
  "add x18, x0, w9, uxth\n\t" \
  "ldr q25, [x7, x28]\n\t" \
  "add x19, x0, w13, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x21, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "and x24, x27, x8, lsr #16\n\t" \
  "ld1 {v5.b}[0], [x18]\n\t" \
  "and x16, x27, x9, lsr #16\n\t" \
  "ld1 {v7.b}[0], [x19]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "and x25, x27, x12, lsr #16\n\t" \
  "add x23, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[1], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "ld1 {v6.b}[1], [x21]\n\t" \
  "and x17, x27, x13, lsr #16\n\t" \
  "add x16, x0, x16\n\t" \
  "and x20, x27, x11, lsr #16\n\t" \
  "and x21, x27, x15, lsr #16\n\t" \
  "add x17, x0, x17\n\t" \
  "and x19, x27, x14, lsr #16\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "and x18, x27, x10, lsr #16\n\t" \
  "ld1 {v7.b}[1], [x23]\n\t" \
  "add x18, x0, x18\n\t" \
  "ld1 {v4.b}[2], [x24]\n\t" \
  "add x19, x0, x19\n\t" \
  "ld1 {v6.b}[2], [x25]\n\t" \
  "add x20, x0, x20\n\t" \
  "ld1 {v5.b}[2], [x16]\n\t" \
  "add x21, x0, x21\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "and x22, x27, x8, lsr #32\n\t" \
  "ld1 {v4.b}[3], [x18]\n\t" \
  "add x22, x0, x22\n\t" \
  "and x24, x27, x9, lsr #32\n\t" \
  "and x23, x27, x12, lsr #32\n\t" \
  "and x25, x27, x13, lsr #32\n\t" \
  "add x23, x0, x23\n\t" \
  "ld1 {v6.b}[3], [x19]\n\t" \
  "add x25, x0, x25\n\t" \
  "ld1 {v5.b}[3], [x20]\n\t" \
  "add x24, x0, x24\n\t" \
  "and x17, x27, x14, lsr #32\n\t" \
  "and x16, x27, x10, lsr #32\n\t" \
  "ld1 {v7.b}[3], [x21]\n\t" \
  "and x18, x27, x11, lsr #32\n\t" \
  "ld1 {v4.b}[4], [x22]\n\t" \
  "and x19, x27, x15, lsr #32\n\t" \
  "ld1 {v6.b}[4], [x23]\n\t" \
  "add x16, x0, x16\n\t" \
  "ld1 {v5.b}[4], [x24]\n\t" \
  "add x17, x0, x17\n\t" \
  "ld1 {v7.b}[4], [x25]\n\t" \
  "add x20, x0, x8, lsr #48\n\t" \
  "add x18, x0, x18\n\t" \
  "add x19, x0, x19\n\t" \
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
  "ld1 {v5.b}[6], [x22]\n\t" \
  "add x25, x0, x14, lsr #48\n\t" \
  "cmp x30, #4\n\t" \
  "ld1 {v7.b}[6], [x23]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x24]\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v6.b}[7], [x25]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v7.b}[7], [x17]\n\t" \
  "add x3, x3, x26\n\t" \

constexpr uint8_t kMip3Iota[32] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15,
                                   16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31};
constexpr int kMip3MaxRows = 512;        // surface rows (4096 / 8: every face extent)
constexpr int kMip3TileBytes = 32768;    // laid-out (wrapped) texture rows, n16 bytes each

// The loop over n >= 1 group columns (16 texels wide, bh >= 1 bands): column k writes
// d + 16 k (row stride w) from grid entries 8 k.. of rows g0 + k * 16 bytes (row stride gst)
// and texel rows rp[y] + goff + k gs (rp: rows 0..2 bh + 1). One assembly block: the columns'
// state lives in a stack frame (x0-x30 all serve the band loop): [sp] output, groups left,
// grid row 0, texel offset, gs, rp + 2, bands, then rows 2 and 3's offsets (clamped to bh).
__attribute__((always_inline)) inline void mip3_columns(const uint8_t* cm, uint8_t* d, int64_t w, const uint16_t* g0,
                                                        int64_t gst, int bh, const uint8_t* const* rp, int64_t goff,
                                                        int64_t gs, int64_t n) {
  const int64_t frame[10] = {int64_t(d), n, int64_t(g0), goff, gs, int64_t(rp + 2), bh,
                             (bh < 2 ? bh : 2) * gst, (bh < 3 ? bh : 3) * gst, 0};
  register const uint8_t* x0 asm("x0") = cm;
  register int64_t x2 asm("x2") = w;
  register int64_t x4 asm("x4") = gst;
  register const int64_t* x9 asm("x9") = frame;
  asm volatile(
      "sub sp, sp, #80\n\t"
      "ldp x10, x11, [x9]\n\t"
      "ldp x12, x13, [x9, #16]\n\t"
      "ldp x14, x15, [x9, #32]\n\t"
      "stp x10, x11, [sp]\n\t"
      "stp x12, x13, [sp, #16]\n\t"
      "stp x14, x15, [sp, #32]\n\t"
      "ldp x10, x11, [x9, #48]\n\t"
      "ldr x12, [x9, #64]\n\t"
      "stp x10, x11, [sp, #48]\n\t"
      "str x12, [sp, #64]\n\t"
      "movi v31.8h, #0xff\n\t"
      "mov x27, #0xffff\n\t"
      "ldp x6, x28, [sp, #16]\n\t"
      "ldp x10, x11, [sp, #56]\n\t"
      "ldr x1, [sp]\n"
      "3:\n\t"  // (the next group enters with x1, x6, x28, x10, x11 set)
      "add x7, x6, x4\n\t"
      "ldr q16, [x6]\n\t"
      "add x8, x6, x10\n\t"
      "ldur q22, [x6, #2]\n\t"
      "add x3, x6, x11\n\t"
      "ldr q17, [x7]\n\t"
      "ldur q23, [x7, #2]\n\t"
      "ldr q18, [x8]\n\t"
      "add v19.8h, v16.8h, v22.8h\n\t"
      "ldur q22, [x8, #2]\n\t"
      "add v20.8h, v17.8h, v23.8h\n\t"
      "ldp x5, x30, [sp, #40]\n\t"
      "ldp x6, x7, [x5, #-16]\n\t"
      "ldr q24, [x6, x28]\n\t"
      "ldr q25, [x7, x28]\n\t"
      SB_MIP3_ENTRY "b.eq 9f\n\t"
      "b 1f\n\t"
      ".p2align 11\n\t"  // (the band loop, about 1.3 KiB, then never straddles a page)
      "1:\n\t" SB_MIP3_BAND1 "b.eq 9f\n\t" SB_MIP3_BAND2 "b.eq 9f\n\t" SB_MIP3_BAND0 "b.ne 1b\n\t"
      "9:\n\t"
      "stp d4, d5, [x1]\n\t"
      "add x1, x1, x2\n\t"
      "stp d6, d7, [x1]\n\t"
      "ldp x1, x10, [sp]\n\t"
      "ldp x6, x28, [sp, #16]\n\t"
      "ldr x11, [sp, #32]\n\t"
      "add x1, x1, #16\n\t"
      "add x6, x6, #16\n\t"
      "add x28, x28, x11\n\t"
      "subs x10, x10, #1\n\t"
      "stp x1, x10, [sp]\n\t"
      "stp x6, x28, [sp, #16]\n\t"
      "ldp x10, x11, [sp, #56]\n\t"
      "b.ne 3b\n\t"
      "add sp, sp, #80\n\t"
      : "+r"(x9)
      : "r"(x0), "r"(x2), "r"(x4)
      : "x1", "x3", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17", "x18", "x19",
        "x20", "x21", "x22", "x23", "x24", "x25", "x26", "x27", "x28", "x30", "v0", "v1", "v2", "v3", "v4", "v5",
        "v6", "v7", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v31", "cc", "memory");
}

// A p16 row's 16 laid-out bytes (period[0]: byte k is (c0 + k) mod tw): one table lookup of
// the row's first 16 bytes, or of the texture's last 16 at its end (writes 32 bytes when the
// texture itself is shorter than 16 bytes).
__attribute__((always_inline)) inline void mip3_tile16(uint8_t* o, const uint8_t* r, int tw, int c0,
                                                       const uint8_t* texels, const uint8_t* tex_end,
                                                       const uint8x16_t* period) {
  if (r + 16 <= tex_end) {
    vst1q_u8(o, vqtbl1q_u8(vld1q_u8(r), period[0]));
  } else if (tex_end - 16 >= texels) {
    const uint8_t* const last16 = tex_end - 16;
    vst1q_u8(o, vqtbl1q_u8(vld1q_u8(last16), vaddq_u8(period[0], vdupq_n_u8(uint8_t(r - last16)))));
  } else {
    tile_row(o, r, tw, c0, 16, tex_end, period, texels);
  }
}

// The mip-3 builder (asm/surface_block.h's contract, mip 3, width / 2 <= kMaxBlockColumns).
// Returns false, having written nothing, for shapes it leaves to the general builder:
// surfaces taller than kMip3MaxRows, or wrapped texture rows that do not fit its buffer.
__attribute__((always_inline)) inline bool surface_block_mip3(const uint16_t* grid, int gw, const uint8_t* texels, int tw, int th, int soff,
                               int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  if (height > kMip3MaxRows) return false;
  const int bw = width >> 1, bh = height >> 1, n16 = (width + 15) & ~15;
  auto wrap2 = [](int i, int n) { return (n & (n - 1)) == 0 ? i & (n - 1) : wrap(i, n); };
  const int c0 = wrap2(soff, tw), t0 = wrap2(toff, th);
  const uint8_t* const tex_end = texels + tw * th;
  const int used = th < height ? th : height;  // texture rows read (from t0, cyclically)
  // A row is read in place when it needs no wrap and 16-byte reads of every group stay inside
  // the texture; else it is laid out (tiled) in buf.
  // Widths dividing 16 (powers of two): every 16 bytes of a wrapped row are its first 16, so
  // only those are laid out (one table lookup) and every group reads them (goff = 0).
  const bool p16 = tw <= 16 && (tw & (tw - 1)) == 0;
  const int tile = p16 ? 16 : n16;
  const bool flat = c0 + width <= tw;
  auto in_place = [&](int t) { return flat && texels + t * tw + c0 + n16 <= tex_end; };
  if (!flat && used * tile > kMip3TileBytes) return false;
  alignas(16) uint8_t buf[kMip3TileBytes + 48];
  const uint8_t* rp[kMip3MaxRows + 4];
  uint8x16_t period[2] = {vdupq_n_u8(0), vdupq_n_u8(0)};
  if (p16) {
    period[0] = vandq_u8(vaddq_u8(vld1q_u8(kMip3Iota), vdupq_n_u8(uint8_t(c0))), vdupq_n_u8(uint8_t(tw - 1)));
    period[1] = period[0];
  } else if (tw <= 16) {  // x mod tw = x - tw floor(x m / 2^16), m = ceil(2^16 / tw): exact for x = c0 + k < 47
    const uint16x8_t m = vdupq_n_u16(uint16_t((65536 + tw - 1) / tw)), twv = vdupq_n_u16(uint16_t(tw));
    for (int h = 0; h < 2; ++h) {
      const uint8x16_t x8 = vaddq_u8(vld1q_u8(kMip3Iota + 16 * h), vdupq_n_u8(uint8_t(c0)));
      uint16x8_t x[2] = {vmovl_u8(vget_low_u8(x8)), vmovl_high_u8(x8)};
      for (int i = 0; i < 2; ++i) {
        const uint16x8_t q = vuzp2q_u16(vreinterpretq_u16_u32(vmull_u16(vget_low_u16(x[i]), vget_low_u16(m))),
                                        vreinterpretq_u16_u32(vmull_high_u16(x[i], m)));
        x[i] = vmlsq_u16(x[i], q, twv);
      }
      period[h] = vuzp1q_u8(vreinterpretq_u8_u16(x[0]), vreinterpretq_u8_u16(x[1]));
    }
  }
  {
    int t = t0;
    if (p16 && !flat && used == th) {
      // Every texture row once, from t0 on (buf + 16 k: row (t0 + k) mod th), two a step while
      // 16-byte reads stay inside; then rp[y] = buf + 16 y for y < th, two a step.
      auto tile_run = [&](int k, int first, int n) __attribute__((always_inline)) {
        const uint8_t* r = texels + first * tw;
        int i = 0;
        for (; i + 2 <= n && r + tw + 16 <= tex_end; i += 2, r += 2 * tw) {
          const uint8x16_t a = vqtbl1q_u8(vld1q_u8(r), period[0]), b = vqtbl1q_u8(vld1q_u8(r + tw), period[0]);
          vst1q_u8(buf + 16 * (k + i), a);
          vst1q_u8(buf + 16 * (k + i) + 16, b);
        }
        for (; i < n; ++i, r += tw) mip3_tile16(buf + 16 * (k + i), r, tw, c0, texels, tex_end, period);
      };
      tile_run(0, t0, th - t0);
      if (t0) tile_run(th - t0, 0, t0);
      const uint8_t* p = buf;
      for (int y = 0; y < th; y += 2, p += 32) {  // (th is even; pointer steps: vector adds stall in order)
        rp[y] = p;
        rp[y + 1] = p + 16;
        asm("" : "+r"(p));
      }
    } else if (p16 && !flat) {
      for (int y = 0; y < used; ++y) {
        uint8_t* o = buf + 16 * y;
        mip3_tile16(o, texels + t * tw, tw, c0, texels, tex_end, period);
        rp[y] = o;
        if (++t == th) t = 0;
      }
    } else {
      for (int y = 0; y < used; ++y) {
        const uint8_t* r = texels + t * tw;
        if (in_place(t)) {
          rp[y] = r + c0;
        } else {
          uint8_t* o = buf + y * n16;
          tile_row(o, r, tw, c0, n16, tex_end, period, texels);
          rp[y] = o;
        }
        if (++t == th) t = 0;
      }
    }
    // Rows repeat every th (used = th here when height exceeds it): two pointers a step.
    int y = used;
    for (; y + 7 < height + 2 && used >= 8; y += 8) {  // (eight a step: the loads first)
      const uint64_t* const src = reinterpret_cast<const uint64_t*>(rp + y - used);
      uint64x2_t a = vld1q_u64(src), b = vld1q_u64(src + 2), c = vld1q_u64(src + 4), e = vld1q_u64(src + 6);
      asm("" : "+w"(a), "+w"(b), "+w"(c), "+w"(e));
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y), a);
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y + 2), b);
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y + 4), c);
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y + 6), e);
    }
    for (; y + 3 < height + 2 && used >= 4; y += 4) {
      const uint64x2_t a = vld1q_u64(reinterpret_cast<const uint64_t*>(rp + y - used));
      const uint64x2_t b = vld1q_u64(reinterpret_cast<const uint64_t*>(rp + y - used + 2));
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y), a);
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y + 2), b);
    }
    for (; y + 1 < height + 2 && used >= 2; y += 2)
      vst1q_u64(reinterpret_cast<uint64_t*>(rp + y), vld1q_u64(reinterpret_cast<const uint64_t*>(rp + y - used)));
    for (; y < height + 2; ++y) rp[y] = rp[y >= used ? y - used : 0];  // (read ahead by the last band, unused)
  }
  const int64_t gs = p16 && !flat ? 0 : 16;  // a group's offset step in the rows
  const int64_t gst = 2 * int64_t(gw);
  const int g = width >> 4;  // full groups
  if (g) mip3_columns(colormap, out, width, grid, gst, bh, rp, 0, gs, g);
  if (const int m = width - 16 * g) {
    // The last, partial group: its grid entries zero padded (10 a row), its rows written to
    // a 16-byte-stride buffer, then the surface's m bytes of each.
    constexpr int kPad = 10;
    alignas(16) uint16_t pg[(kMip3MaxRows / 2 + 1) * kPad + 8];
    alignas(16) uint8_t po[kMip3MaxRows * 16];
    const int n = bw + 1 - 8 * g;  // entries inside the grid rows (<= 8)
    for (int r = 0; r <= bh; ++r) {
      const uint16_t* s = grid + r * gw + 8 * g;
      uint16_t* o = pg + r * kPad;
      for (int k = 0; k < kPad; ++k) o[k] = k < n ? s[k] : 0;
    }
    mip3_columns(colormap, po, 16, pg, 2 * kPad, bh, rp, gs * g, 0, 1);
    for (int y = 0; y < height; ++y) std::memcpy(out + y * width + 16 * g, po + 16 * y, size_t(m));
  }
  return true;
}

#endif  // __aarch64__

}  // namespace
}  // namespace sb::simd::detail
