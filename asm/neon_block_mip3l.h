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

#include "asm/neon_block_mip2l.h"
#include "asm/neon_block_mip3.h"
#include "asm/variants.h"

#if defined(__aarch64__)
namespace sb::simd::detail {
// The neon_a53 surface_block (asm/surface_block.h's contract): assembly below.
void surface_block_neon_inorder(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                                int tex_height, int mip, int soff, int toff, int width, int height,
                                const uint8_t* colormap, uint8_t* out);
}  // namespace sb::simd::detail
#endif

namespace sb::simd::detail {
namespace {

#if defined(__aarch64__)

// The band loop (asm/neon_block_mip3.h's SB_MIP3_BAND0..2 and SB_MIP3_ENTRY, same registers
// and method) with the texel rows read at x5 and x5 + 16, x5 += 32 wrapped by x28 = ~P, and
// lanes 1-2 of an index word xW by one rotation: after lanes 0 (uxth) and 3 (lsr #48) are
// taken, `ror xW, xW, #32` puts lane 2 in bits 0-15 and lane 1 in bits 48-63 (5 address ops a
// word, no mask register); lane addresses in x16-x24 (x25, x27 unused). Reordered by
// bench/order_search.py (Cortex-A53 model: 68 cycles a band). The entry copy is band 0 without
// the previous band's stores, after the group's grid rows 0-2 (v16-v18, v19 = g + g1 of row 0,
// v20 of row 1, v22 = row 2's entries 1..8, x3 = row 3), the first texel rows (v24, v25 at t0,
// x5 = the next band's) and the band count x30 from the frame (81 cycles). SB_MIP3L_FAST: the
// fast path's straight block (see below), from SB_MIP3L_PRO, the eight row loads at 8 k &
// x13, SB_MIP3L_TBL8, SB_MIP3L_ST8 with w4 = 8, SB_MIP3L_STATE and SB_MIP3L_ENTRY, reordered
// by the same search against qemu's block cut (136 cycles).
#define SB_MIP3L_BAND0 \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "cmp x30, #4\n\t" \
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
  "fmov x9, v24.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "add x18, x0, w10, uxth\n\t" \
  "add x19, x0, x8, lsr #48\n\t" \
  "add x20, x0, w13, uxth\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "add x22, x0, w14, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x16, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "add x17, x0, w11, uxth\n\t" \
  "ld1 {v5.b}[0], [x21]\n\t" \
  "add x21, x0, w15, uxth\n\t" \
  "ld1 {v7.b}[0], [x20]\n\t" \
  "add x20, x0, x11, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x18]\n\t" \
  "add x18, x0, x10, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x22]\n\t" \
  "add x22, x0, x13, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x17]\n\t" \
  "add x17, x0, x9, lsr #48\n\t" \
  "ld1 {v7.b}[1], [x21]\n\t" \
  "ror x8, x8, #32\n\t" \
  "add x21, x0, x14, lsr #48\n\t" \
  "ror x12, x12, #32\n\t" \
  "ld1 {v4.b}[6], [x19]\n\t" \
  "ror x9, x9, #32\n\t" \
  "ld1 {v6.b}[6], [x16]\n\t" \
  "ror x10, x10, #32\n\t" \
  "ld1 {v5.b}[6], [x17]\n\t" \
  "add x16, x0, x15, lsr #48\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x17, x0, w8, uxth\n\t" \
  "ror x15, x15, #32\n\t" \
  "add x19, x0, w12, uxth\n\t" \
  "ld1 {v7.b}[6], [x22]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v6.b}[7], [x21]\n\t" \
  "ror x13, x13, #32\n\t" \
  "ld1 {v4.b}[7], [x18]\n\t" \
  "add x18, x0, x12, lsr #48\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "ror x14, x14, #32\n\t" \
  "ld1 {v7.b}[7], [x16]\n\t" \
  "add x16, x0, w13, uxth\n\t" \
  "ror x11, x11, #32\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[7], [x20]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "ld1 {v6.b}[4], [x19]\n\t" \
  "add x19, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[4], [x17]\n\t" \
  "add x17, x0, x13, lsr #48\n\t" \
  "add x23, x0, w14, uxth\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v5.b}[4], [x21]\n\t" \
  "add x21, x0, x8, lsr #48\n\t" \
  "ld1 {v7.b}[4], [x16]\n\t" \
  "add x16, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[5], [x20]\n\t" \
  "ld1 {v6.b}[5], [x23]\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v5.b}[5], [x19]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v7.b}[5], [x16]\n\t" \
  "add x16, x0, x14, lsr #48\n\t" \
  "ld1 {v4.b}[2], [x21]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x19, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[2], [x18]\n\t" \
  "ld1 {v5.b}[2], [x22]\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[3], [x24]\n\t" \
  "ld1 {v6.b}[3], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v5.b}[3], [x19]\n\t" \
  "add x3, x3, x26\n\t" \
  "ld1 {v7.b}[3], [x17]\n\t" \
  "add x1, x1, x2\n\t"

#define SB_MIP3L_BAND1 \
  "uhadd v2.8h, v17.8h, v18.8h\n\t" \
  "ushr v1.8h, v20.8h, #1\n\t" \
  "add v3.8h, v20.8h, v21.8h\n\t" \
  "cmp x30, #4\n\t" \
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
  "fmov x9, v24.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "add x18, x0, w10, uxth\n\t" \
  "add x19, x0, x8, lsr #48\n\t" \
  "add x20, x0, w13, uxth\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "add x22, x0, w14, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x16, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "add x17, x0, w11, uxth\n\t" \
  "ld1 {v5.b}[0], [x21]\n\t" \
  "add x21, x0, w15, uxth\n\t" \
  "ld1 {v7.b}[0], [x20]\n\t" \
  "add x20, x0, x11, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x18]\n\t" \
  "add x18, x0, x10, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x22]\n\t" \
  "add x22, x0, x13, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x17]\n\t" \
  "add x17, x0, x9, lsr #48\n\t" \
  "ld1 {v7.b}[1], [x21]\n\t" \
  "ror x8, x8, #32\n\t" \
  "add x21, x0, x14, lsr #48\n\t" \
  "ror x12, x12, #32\n\t" \
  "ld1 {v4.b}[6], [x19]\n\t" \
  "ror x9, x9, #32\n\t" \
  "ld1 {v6.b}[6], [x16]\n\t" \
  "ror x10, x10, #32\n\t" \
  "ld1 {v5.b}[6], [x17]\n\t" \
  "add x16, x0, x15, lsr #48\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x17, x0, w8, uxth\n\t" \
  "ror x15, x15, #32\n\t" \
  "add x19, x0, w12, uxth\n\t" \
  "ld1 {v7.b}[6], [x22]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v6.b}[7], [x21]\n\t" \
  "ror x13, x13, #32\n\t" \
  "ld1 {v4.b}[7], [x18]\n\t" \
  "add x18, x0, x12, lsr #48\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "ror x14, x14, #32\n\t" \
  "ld1 {v7.b}[7], [x16]\n\t" \
  "add x16, x0, w13, uxth\n\t" \
  "ror x11, x11, #32\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[7], [x20]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "ld1 {v6.b}[4], [x19]\n\t" \
  "add x19, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[4], [x17]\n\t" \
  "add x17, x0, x13, lsr #48\n\t" \
  "add x23, x0, w14, uxth\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v5.b}[4], [x21]\n\t" \
  "add x21, x0, x8, lsr #48\n\t" \
  "ld1 {v7.b}[4], [x16]\n\t" \
  "add x16, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[5], [x20]\n\t" \
  "ld1 {v6.b}[5], [x23]\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v5.b}[5], [x19]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v7.b}[5], [x16]\n\t" \
  "add x16, x0, x14, lsr #48\n\t" \
  "ld1 {v4.b}[2], [x21]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x19, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[2], [x18]\n\t" \
  "ld1 {v5.b}[2], [x22]\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[3], [x24]\n\t" \
  "ld1 {v6.b}[3], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v5.b}[3], [x19]\n\t" \
  "add x3, x3, x26\n\t" \
  "ld1 {v7.b}[3], [x17]\n\t" \
  "add x1, x1, x2\n\t"

#define SB_MIP3L_BAND2 \
  "uhadd v2.8h, v18.8h, v16.8h\n\t" \
  "ushr v1.8h, v21.8h, #1\n\t" \
  "add v3.8h, v21.8h, v19.8h\n\t" \
  "cmp x30, #4\n\t" \
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
  "fmov x9, v24.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v20.8h, v17.8h, v22.8h\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x17, x0, w12, uxth\n\t" \
  "add x18, x0, w10, uxth\n\t" \
  "add x19, x0, x8, lsr #48\n\t" \
  "add x20, x0, w13, uxth\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "add x22, x0, w14, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x16, x0, x12, lsr #48\n\t" \
  "ld1 {v6.b}[0], [x17]\n\t" \
  "add x17, x0, w11, uxth\n\t" \
  "ld1 {v5.b}[0], [x21]\n\t" \
  "add x21, x0, w15, uxth\n\t" \
  "ld1 {v7.b}[0], [x20]\n\t" \
  "add x20, x0, x11, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x18]\n\t" \
  "add x18, x0, x10, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x22]\n\t" \
  "add x22, x0, x13, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x17]\n\t" \
  "add x17, x0, x9, lsr #48\n\t" \
  "ld1 {v7.b}[1], [x21]\n\t" \
  "ror x8, x8, #32\n\t" \
  "add x21, x0, x14, lsr #48\n\t" \
  "ror x12, x12, #32\n\t" \
  "ld1 {v4.b}[6], [x19]\n\t" \
  "ror x9, x9, #32\n\t" \
  "ld1 {v6.b}[6], [x16]\n\t" \
  "ror x10, x10, #32\n\t" \
  "ld1 {v5.b}[6], [x17]\n\t" \
  "add x16, x0, x15, lsr #48\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x17, x0, w8, uxth\n\t" \
  "ror x15, x15, #32\n\t" \
  "add x19, x0, w12, uxth\n\t" \
  "ld1 {v7.b}[6], [x22]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v6.b}[7], [x21]\n\t" \
  "ror x13, x13, #32\n\t" \
  "ld1 {v4.b}[7], [x18]\n\t" \
  "add x18, x0, x12, lsr #48\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "ror x14, x14, #32\n\t" \
  "ld1 {v7.b}[7], [x16]\n\t" \
  "add x16, x0, w13, uxth\n\t" \
  "ror x11, x11, #32\n\t" \
  "add x22, x0, x9, lsr #48\n\t" \
  "ld1 {v5.b}[7], [x20]\n\t" \
  "add x20, x0, w10, uxth\n\t" \
  "ld1 {v6.b}[4], [x19]\n\t" \
  "add x19, x0, w11, uxth\n\t" \
  "ld1 {v4.b}[4], [x17]\n\t" \
  "add x17, x0, x13, lsr #48\n\t" \
  "add x23, x0, w14, uxth\n\t" \
  "add x24, x0, x10, lsr #48\n\t" \
  "ld1 {v5.b}[4], [x21]\n\t" \
  "add x21, x0, x8, lsr #48\n\t" \
  "ld1 {v7.b}[4], [x16]\n\t" \
  "add x16, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[5], [x20]\n\t" \
  "ld1 {v6.b}[5], [x23]\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v5.b}[5], [x19]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v7.b}[5], [x16]\n\t" \
  "add x16, x0, x14, lsr #48\n\t" \
  "ld1 {v4.b}[2], [x21]\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x19, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[2], [x18]\n\t" \
  "ld1 {v5.b}[2], [x22]\n\t" \
  "ld1 {v7.b}[2], [x17]\n\t" \
  "add x17, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[3], [x24]\n\t" \
  "ld1 {v6.b}[3], [x16]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v5.b}[3], [x19]\n\t" \
  "add x3, x3, x26\n\t" \
  "ld1 {v7.b}[3], [x17]\n\t" \
  "add x1, x1, x2\n\t"

#define SB_MIP3L_ENTRY \
  "add x9, x6, x4\n\t" \
  "ldr q16, [x6]\n\t" \
  "ldur q22, [x6, #2]\n\t" \
  "ldr q17, [x9]\n\t" \
  "add x8, x6, x10\n\t" \
  "ldur q23, [x9, #2]\n\t" \
  "ldp x5, x30, [sp, #24]\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "ldr q18, [x8]\n\t" \
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
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "fmov x12, d2\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "fmov x14, d3\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "add x17, x0, w8, uxth\n\t" \
  "add x19, x0, w12, uxth\n\t" \
  "add x18, x0, w13, uxth\n\t" \
  "add x16, x0, w10, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "add x20, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[0], [x17]\n\t" \
  "add x17, x0, w14, uxth\n\t" \
  "ld1 {v6.b}[0], [x19]\n\t" \
  "add x22, x0, x8, lsr #48\n\t" \
  "ld1 {v5.b}[0], [x21]\n\t" \
  "add x19, x0, w11, uxth\n\t" \
  "ld1 {v7.b}[0], [x18]\n\t" \
  "add x18, x0, x12, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x16]\n\t" \
  "add x16, x0, x10, lsr #48\n\t" \
  "ld1 {v6.b}[1], [x17]\n\t" \
  "add x21, x0, x11, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x19]\n\t" \
  "add x19, x0, x9, lsr #48\n\t" \
  "ror x8, x8, #32\n\t" \
  "add x17, x0, x13, lsr #48\n\t" \
  "ld1 {v7.b}[1], [x20]\n\t" \
  "ror x12, x12, #32\n\t" \
  "ld1 {v4.b}[6], [x22]\n\t" \
  "ror x9, x9, #32\n\t" \
  "ld1 {v5.b}[6], [x19]\n\t" \
  "add x19, x0, x14, lsr #48\n\t" \
  "ld1 {v6.b}[6], [x18]\n\t" \
  "add x18, x0, x15, lsr #48\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x20, x0, w8, uxth\n\t" \
  "ld1 {v7.b}[6], [x17]\n\t" \
  "add x22, x0, w12, uxth\n\t" \
  "ld1 {v4.b}[7], [x16]\n\t" \
  "ror x15, x15, #32\n\t" \
  "ror x13, x13, #32\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v6.b}[7], [x19]\n\t" \
  "ror x14, x14, #32\n\t" \
  "ld1 {v5.b}[7], [x21]\n\t" \
  "add x16, x0, w9, uxth\n\t" \
  "ld1 {v7.b}[7], [x18]\n\t" \
  "ror x11, x11, #32\n\t" \
  "ld1 {v4.b}[4], [x20]\n\t" \
  "add x17, x0, w13, uxth\n\t" \
  "add x19, x0, x12, lsr #48\n\t" \
  "add x18, x0, w14, uxth\n\t" \
  "ror x10, x10, #32\n\t" \
  "add x21, x0, x9, lsr #48\n\t" \
  "add x20, x0, x13, lsr #48\n\t" \
  "add x24, x0, w11, uxth\n\t" \
  "ld1 {v6.b}[4], [x22]\n\t" \
  "add x23, x0, w10, uxth\n\t" \
  "ld1 {v5.b}[4], [x16]\n\t" \
  "ldr q16, [x3]\n\t" \
  "add x16, x0, w15, uxth\n\t" \
  "ld1 {v7.b}[4], [x17]\n\t" \
  "ld1 {v4.b}[5], [x23]\n\t" \
  "add x17, x0, x8, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x18]\n\t" \
  "ld1 {v5.b}[5], [x24]\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v7.b}[5], [x16]\n\t" \
  "add x16, x0, x10, lsr #48\n\t" \
  "ld1 {v4.b}[2], [x17]\n\t" \
  "add x17, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[2], [x19]\n\t" \
  "add x18, x0, x14, lsr #48\n\t" \
  "ld1 {v5.b}[2], [x21]\n\t" \
  "ld1 {v7.b}[2], [x20]\n\t" \
  "add x19, x0, x15, lsr #48\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v4.b}[3], [x16]\n\t" \
  "add x3, x3, x26\n\t" \
  "ld1 {v5.b}[3], [x17]\n\t" \
  "ld1 {v7.b}[3], [x19]\n\t" \
  "ld1 {v6.b}[3], [x18]\n\t" \
  "and x5, x5, x28\n\t"

#define SB_MIP3L_FAST \
  "ldp x16, x17, [sp, #16]\n\t" \
  "sub sp, sp, #3248\n\t" \
  "lsl w13, w4, #3\n\t" \
  "dup v1.16b, w6\n\t" \
  "stp x19, x20, [sp, #64]\n\t" \
  "sub w13, w13, #8\n\t" \
  "stp x21, x22, [sp, #80]\n\t" \
  "mov x22, x2\n\t" \
  "stp x23, x24, [sp, #96]\n\t" \
  "stp x26, x28, [sp, #112]\n\t" \
  "sub w12, w3, #1\n\t" \
  "stp x29, x30, [sp, #144]\n\t" \
  "ldr q0, .Lsb_m3l_iota\n\t" \
  "movi v31.8h, #255\n\t" \
  "add x21, sp, #2207\n\t" \
  "dup v2.16b, w12\n\t" \
  "add v0.16b, v0.16b, v1.16b\n\t" \
  "ldr d16, [x22]\n\t" \
  "and x12, x13, #24\n\t" \
  "and x8, x13, #8\n\t" \
  "and x15, x13, #0xffffffffffffffef\n\t" \
  "and x11, x13, #16\n\t" \
  "and x21, x21, #0xfffffffffffff800\n\t" \
  "ldr d23, [x22, x13]\n\t" \
  "and x23, x13, #48\n\t" \
  "and x14, x13, #32\n\t" \
  "ldr d17, [x22, x8]\n\t" \
  "and v0.16b, v0.16b, v2.16b\n\t" \
  "ldr d19, [x22, x12]\n\t" \
  "mov w4, #8\n\t" \
  "ldr d22, [x22, x23]\n\t" \
  "ldr d20, [x22, x14]\n\t" \
  "mov x19, x21\n\t" \
  "ldr d18, [x22, x11]\n\t" \
  "ldr d21, [x22, x15]\n\t" \
  "tbl v16.16b, {v16.16b}, v0.16b\n\t" \
  "tbl v17.16b, {v17.16b}, v0.16b\n\t" \
  "tbl v19.16b, {v19.16b}, v0.16b\n\t" \
  "tbl v18.16b, {v18.16b}, v0.16b\n\t" \
  "tbl v20.16b, {v20.16b}, v0.16b\n\t" \
  "tbl v22.16b, {v22.16b}, v0.16b\n\t" \
  "tbl v21.16b, {v21.16b}, v0.16b\n\t" \
  "tbl v23.16b, {v23.16b}, v0.16b\n\t" \
  "stp q16, q17, [x19]\n\t" \
  "lsl w28, w4, #4\n\t" \
  "stp q18, q19, [x19, #32]\n\t" \
  "sub w13, w4, #1\n\t" \
  "stp q20, q21, [x19, #64]\n\t" \
  "and w7, w7, w13\n\t" \
  "asr w13, w10, #1\n\t" \
  "cmp w13, #2\n\t" \
  "ubfiz x4, x1, #1, #32\n\t" \
  "add x14, x4, x4\n\t" \
  "add x12, x21, x7, lsl #4\n\t" \
  "csel x14, x14, x4, ge\n\t" \
  "cmp w13, #3\n\t" \
  "sxtw x2, w9\n\t" \
  "stp q22, q23, [x19, #96]\n\t" \
  "add x11, x14, x4\n\t" \
  "csel x11, x11, x14, ge\n\t" \
  "lsl x29, x13, #1\n\t" \
  "sub x29, x29, #1\n\t" \
  "stp x12, x13, [sp, #24]\n\t" \
  "mul x29, x29, x2\n\t" \
  "stp x14, x11, [sp, #48]\n\t" \
  "mov x6, x0\n\t" \
  "lsr w7, w9, #4\n\t" \
  "sub x29, x29, #16\n\t" \
  "add x9, x6, x4\n\t" \
  "mov x10, x14\n\t" \
  "ldur q22, [x6, #2]\n\t" \
  "add x19, x19, #128\n\t" \
  "ldr q16, [x6]\n\t" \
  "mvn x28, x28\n\t" \
  "ldr q17, [x9]\n\t" \
  "ldur q23, [x9, #2]\n\t" \
  "add x3, x6, x11\n\t" \
  "add x8, x6, x10\n\t" \
  "ldp x5, x30, [sp, #24]\n\t" \
  "mov x0, x16\n\t" \
  "add v19.8h, v16.8h, v22.8h\n\t" \
  "add v20.8h, v17.8h, v23.8h\n\t" \
  "ldr q24, [x5]\n\t" \
  "uhadd v2.8h, v16.8h, v17.8h\n\t" \
  "ldr q18, [x8]\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "ushr v1.8h, v19.8h, #1\n\t" \
  "add v3.8h, v19.8h, v20.8h\n\t" \
  "add x5, x5, #32\n\t" \
  "ldur q22, [x8, #2]\n\t" \
  "and x5, x5, x28\n\t" \
  "bit v2.16b, v25.16b, v31.16b\n\t" \
  "trn2 v1.16b, v24.16b, v1.16b\n\t" \
  "ushr v3.16b, v3.16b, #2\n\t" \
  "bif v24.16b, v16.16b, v31.16b\n\t" \
  "mov x1, x17\n\t" \
  "fmov x13, v2.d[1]\n\t" \
  "fmov x10, d1\n\t" \
  "trn2 v3.16b, v25.16b, v3.16b\n\t" \
  "fmov x8, d24\n\t" \
  "fmov x9, v24.d[1]\n\t" \
  "fmov x11, v1.d[1]\n\t" \
  "fmov x12, d2\n\t" \
  "add v21.8h, v18.8h, v22.8h\n\t" \
  "fmov x14, d3\n\t" \
  "fmov x15, v3.d[1]\n\t" \
  "ldr q16, [x3]\n\t" \
  "cmp x30, #4\n\t" \
  "add x16, x0, w8, uxth\n\t" \
  "add x18, x0, x8, lsr #48\n\t" \
  "add x23, x0, x9, lsr #48\n\t" \
  "add x17, x0, w13, uxth\n\t" \
  "add x20, x0, w14, uxth\n\t" \
  "add x21, x0, w15, uxth\n\t" \
  "ld1 {v4.b}[0], [x16]\n\t" \
  "add x16, x0, w9, uxth\n\t" \
  "add x19, x0, w10, uxth\n\t" \
  "add x22, x0, w12, uxth\n\t" \
  "ldr q24, [x5]\n\t" \
  "ld1 {v6.b}[0], [x22]\n\t" \
  "add x22, x0, w11, uxth\n\t" \
  "ld1 {v5.b}[0], [x16]\n\t" \
  "add x16, x0, x11, lsr #48\n\t" \
  "ld1 {v7.b}[0], [x17]\n\t" \
  "add x17, x0, x12, lsr #48\n\t" \
  "ld1 {v4.b}[1], [x19]\n\t" \
  "ror x11, x11, #32\n\t" \
  "ld1 {v6.b}[1], [x20]\n\t" \
  "add x20, x0, x10, lsr #48\n\t" \
  "ld1 {v5.b}[1], [x22]\n\t" \
  "add x22, x0, x13, lsr #48\n\t" \
  "ror x10, x10, #32\n\t" \
  "ror x8, x8, #32\n\t" \
  "ld1 {v7.b}[1], [x21]\n\t" \
  "ror x12, x12, #32\n\t" \
  "ld1 {v4.b}[6], [x18]\n\t" \
  "ror x9, x9, #32\n\t" \
  "ld1 {v6.b}[6], [x17]\n\t" \
  "ror x13, x13, #32\n\t" \
  "ldr q25, [x5, #16]\n\t" \
  "add x17, x0, w8, uxth\n\t" \
  "ld1 {v7.b}[6], [x22]\n\t" \
  "add x18, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[7], [x20]\n\t" \
  "add x19, x0, x14, lsr #48\n\t" \
  "ld1 {v5.b}[6], [x23]\n\t" \
  "add x20, x0, w12, uxth\n\t" \
  "ror x14, x14, #32\n\t" \
  "add x21, x0, w9, uxth\n\t" \
  "ld1 {v7.b}[7], [x18]\n\t" \
  "ror x15, x15, #32\n\t" \
  "ld1 {v6.b}[7], [x19]\n\t" \
  "add x5, x5, #32\n\t" \
  "ld1 {v4.b}[4], [x17]\n\t" \
  "add x17, x0, w13, uxth\n\t" \
  "ldur q22, [x3, #2]\n\t" \
  "add x18, x0, w14, uxth\n\t" \
  "ld1 {v5.b}[7], [x16]\n\t" \
  "add x19, x0, x9, lsr #48\n\t" \
  "ld1 {v6.b}[4], [x20]\n\t" \
  "add x16, x0, w11, uxth\n\t" \
  "ld1 {v7.b}[4], [x17]\n\t" \
  "add x17, x0, w10, uxth\n\t" \
  "add x20, x0, w15, uxth\n\t" \
  "csel x26, x4, xzr, ge\n\t" \
  "ld1 {v5.b}[4], [x21]\n\t" \
  "add x21, x0, x8, lsr #48\n\t" \
  "add x22, x0, x13, lsr #48\n\t" \
  "add x23, x0, x12, lsr #48\n\t" \
  "ld1 {v4.b}[5], [x17]\n\t" \
  "add x17, x0, x11, lsr #48\n\t" \
  "ld1 {v6.b}[5], [x18]\n\t" \
  "add x18, x0, x14, lsr #48\n\t" \
  "ld1 {v5.b}[5], [x16]\n\t" \
  "ld1 {v7.b}[5], [x20]\n\t" \
  "add x16, x0, x10, lsr #48\n\t" \
  "ld1 {v4.b}[2], [x21]\n\t" \
  "ld1 {v6.b}[2], [x23]\n\t" \
  "ld1 {v5.b}[2], [x19]\n\t" \
  "add x3, x3, x26\n\t" \
  "ld1 {v7.b}[2], [x22]\n\t" \
  "add x19, x0, x15, lsr #48\n\t" \
  "ld1 {v4.b}[3], [x16]\n\t" \
  "ld1 {v6.b}[3], [x18]\n\t" \
  "subs x30, x30, #1\n\t" \
  "ld1 {v5.b}[3], [x17]\n\t" \
  "and x5, x5, x28\n\t" \
  "ld1 {v7.b}[3], [x19]\n\t"

// Texture layout: row t (tw bytes at x22 + tw t) goes to x19 + 16 t, byte k its texel
// (soff + k) mod tw (a table lookup by v0 of the row loaded into the low tw bytes of vN).
// Eight rows by LD ("ldr d" ...) at offsets 0, O1..O7 into v16-v23, their lookups, stores.
#define SB_MIP3L_LD8(LD, O1, O2, O3, O4, O5, O6, O7) \
  LD "16, [x22]\n\t" \
  LD "17, [x22, #" O1 "]\n\t" \
  LD "18, [x22, #" O2 "]\n\t" \
  LD "19, [x22, #" O3 "]\n\t" \
  LD "20, [x22, #" O4 "]\n\t" \
  LD "21, [x22, #" O5 "]\n\t" \
  LD "22, [x22, #" O6 "]\n\t" \
  LD "23, [x22, #" O7 "]\n\t"
#define SB_MIP3L_TBL8 \
  "tbl v16.16b, {v16.16b}, v0.16b\n\t" \
  "tbl v17.16b, {v17.16b}, v0.16b\n\t" \
  "tbl v18.16b, {v18.16b}, v0.16b\n\t" \
  "tbl v19.16b, {v19.16b}, v0.16b\n\t" \
  "tbl v20.16b, {v20.16b}, v0.16b\n\t" \
  "tbl v21.16b, {v21.16b}, v0.16b\n\t" \
  "tbl v22.16b, {v22.16b}, v0.16b\n\t" \
  "tbl v23.16b, {v23.16b}, v0.16b\n\t"
#define SB_MIP3L_ST8 \
  "stp q16, q17, [x19]\n\t" \
  "stp q18, q19, [x19, #32]\n\t" \
  "stp q20, q21, [x19, #64]\n\t" \
  "stp q22, q23, [x19, #96]\n\t" \
  "add x19, x19, #128\n\t"
// All th rows of a texture tw = 2 TW wide (O1..O7: TW, 2 TW, .. 7 TW... as text), eight a
// step (th >= 8) or two, x20 = the texture's end; then on to the state set-up.
#define SB_MIP3L_LAY(ID, LD, O1, O2, O3, O4, O5, O6, O7, O8) \
  "cmp w4, #8\n\t" \
  "b.lo .Lsb_m3l_s" ID "\n" \
  ".Lsb_m3l_b" ID ":\n\t" \
  SB_MIP3L_LD8(LD, O1, O2, O3, O4, O5, O6, O7) \
  "add x22, x22, #" O8 "\n\t" \
  SB_MIP3L_TBL8 SB_MIP3L_ST8 \
  "cmp x22, x20\n\t" \
  "b.ne .Lsb_m3l_b" ID "\n\t" \
  "b .Lsb_m3l_laid\n" \
  ".Lsb_m3l_s" ID ":\n\t" \
  LD "16, [x22]\n\t" \
  LD "17, [x22, #" O1 "]\n\t" \
  "add x22, x22, #" O2 "\n\t" \
  "tbl v16.16b, {v16.16b}, v0.16b\n\t" \
  "tbl v17.16b, {v17.16b}, v0.16b\n\t" \
  "stp q16, q17, [x19], #32\n\t" \
  "cmp x22, x20\n\t" \
  "b.ne .Lsb_m3l_s" ID "\n\t" \
  "b .Lsb_m3l_laid\n"
// The lean path's frame and the lookup v0 (see below); x21 = buf, x19 = x21, x22 = texels.
#define SB_MIP3L_PRO \
  "ldp x16, x17, [sp, #16]\n\t" \
  "sub sp, sp, #3248\n\t" \
  "stp x19, x20, [sp, #64]\n\t" \
  "stp x21, x22, [sp, #80]\n\t" \
  "stp x23, x24, [sp, #96]\n\t" \
  "stp x26, x28, [sp, #112]\n\t" \
  "stp x29, x30, [sp, #144]\n\t" \
  "ldr q0, .Lsb_m3l_iota\n\t" \
  "dup v1.16b, w6\n\t" \
  "sub w12, w3, #1\n\t" \
  "dup v2.16b, w12\n\t" \
  "add v0.16b, v0.16b, v1.16b\n\t" \
  "and v0.16b, v0.16b, v2.16b\n\t" \
  "add x21, sp, #2207\n\t" \
  "and x21, x21, #-2048\n\t" \
  "mov x19, x21\n\t" \
  "mov x22, x2\n\t"
// The groups' state and registers (see below) from the arguments, rows laid out P = 16 w4
// bytes (w4: th, or 8 on the fast path, whose rows repeat every th), x21 = buf.
#define SB_MIP3L_STATE \
  "lsl w28, w4, #4\n\t" \
  "mvn x28, x28\n\t" \
  "sub w13, w4, #1\n\t" \
  "and w7, w7, w13\n\t" \
  "add x12, x21, x7, lsl #4\n\t" \
  "asr w13, w10, #1\n\t" \
  "stp x12, x13, [sp, #24]\n\t" \
  "ubfiz x4, x1, #1, #32\n\t" \
  "add x14, x4, x4\n\t" \
  "cmp w13, #2\n\t" \
  "csel x14, x14, x4, ge\n\t" \
  "add x11, x14, x4\n\t" \
  "cmp w13, #3\n\t" \
  "csel x11, x11, x14, ge\n\t" \
  "stp x14, x11, [sp, #48]\n\t" \
  "sxtw x2, w9\n\t" \
  "lsl x29, x13, #1\n\t" \
  "sub x29, x29, #1\n\t" \
  "mul x29, x29, x2\n\t" \
  "sub x29, x29, #16\n\t" \
  "mov x6, x0\n\t" \
  "mov x0, x16\n\t" \
  "mov x1, x17\n\t" \
  "lsr w7, w9, #4\n\t" \
  "mov x10, x14\n\t" \
  "movi v31.8h, #0xff\n\t"

// The neon_a53 variant's surface_block (asm/surface_block.h's contract), all in assembly:
// mips 0-1 and the mip-3 shapes the lean path does not take go on to surface_block_inorder
// (asm/neon.cpp) with the arguments untouched, mip 2 to asm/neon_block_mip2f.h (SB_M2L_SYM:
// its 16 x 16 block, else the lean C++ path of asm/neon_block_mip2l.h, which goes on there for
// the shapes it does not take). The lean path: mip 3, texture width 2..16 and
// height 2..64 powers of two with tw th >= 16, surface width 16..512 a multiple of 16, height
// > 0. Its frame: [sp, 64) the groups' state (t0 at 24, bands at 32, rows 2 and 3's offsets at
// 48, 56), [64, 160) the saved x19-x24, x26, x28, x29, x30, then the buffer of laid-out rows
// aligned to 2048 (>= twice its size P = 16 th <= 1024). The column loop over the n = width /
// 16 groups: group k writes out + 16 k (row stride w) from grid entries 8 k.. (row stride gst
// = 2 gw bytes), texel rows from t0 = buf + 16 (toff mod th), x28 = ~P; the bands keep x6
// (grid row 0), x7 (groups left) and x29 ((2 bh - 1) w - 16: the next group's output from the
// last row's). Textures 8 wide and at most 8 tall (mip 3 of 64-wide textures up to 64 tall)
// take one straight block (SB_MIP3L_FAST: frame, eight rows laid out, texture row k mod th,
// state) into the first group's entry: no branch between, so an in-order core overlaps their
// latencies. Its own section: its 4 KiB alignment leaves the rest of .text where it was.
#define SB_MIP3L_SYM "_ZN2sb4simd6detail26surface_block_neon_inorderEPKtiPKhiiiiiiiS5_Ph"
#define SB_MIP3L_REST "_ZN2sb4simd6detail21surface_block_inorderEPKtiPKhiiiiiiiS5_Ph"
asm(".pushsection .text.sb_neon_a53_block, \"ax\", %progbits\n\t"
    ".p2align 6\n\t"
    ".globl " SB_MIP3L_SYM "\n\t"
    ".hidden " SB_MIP3L_SYM "\n\t"
    ".type " SB_MIP3L_SYM ", %function\n" SB_MIP3L_SYM ":\n\t"
    "cmp w5, #3\n\t"
    "b.ne .Lsb_m3l_mip012\n\t"
    // w9 = width, w10 = height. The fast path: tw = 8, th 2, 4 or 8, width 16..512 a multiple
    // of 16, height > 0 (every bit of w11 clear).
    "ldr w9, [sp]\n\t"
    "ldr w10, [sp, #8]\n\t"
    "eor w14, w3, #8\n\t"
    "sub w12, w4, #2\n\t"
    "sub w13, w4, #1\n\t"
    "and w12, w12, #0xfffffff9\n\t"  // th - 2 in 0, 2, 4, 6
    "sub w11, w9, #16\n\t"
    "and w13, w13, w4\n\t"          // th a power of two
    "and w11, w11, #0xfffffe0f\n\t"  // width - 16 in 0..496, a multiple of 16
    "cmp w10, #0\n\t"
    "orr w12, w12, w14\n\t"
    "orr w11, w11, w13\n\t"
    "orr w11, w11, w12\n\t"
    "ccmp w11, #0, #0, gt\n\t"
    "b.eq .Lsb_m3l_fast\n\t"
    // The lean path's other shapes (every bit of w11 clear): tw 2..16 and th 2..64 powers of
    // two, tw th >= 16.
    "sub w11, w9, #16\n\t"
    "sub w12, w3, #1\n\t"
    "sub w13, w4, #1\n\t"
    "mul w15, w3, w4\n\t"
    "and w11, w11, #0xfffffe0f\n\t"
    "and w12, w12, w3\n\t"
    "and w13, w13, w4\n\t"
    "orr w11, w11, w12\n\t"
    "and w12, w3, #0xffffffe1\n\t"  // tw <= 16 (and even)
    "orr w11, w11, w13\n\t"
    "and w13, w4, #0xffffff81\n\t"  // th <= 64 (and even)
    "orr w11, w11, w12\n\t"
    "orr w11, w11, w13\n\t"
    "cmp w15, #15\n\t"          // (also: neither is 0)
    "ccmp w10, #0, #4, hi\n\t"  // height > 0
    "ccmp w11, #0, #0, gt\n\t"
    "b.ne " SB_MIP3L_REST "\n\t"
    SB_MIP3L_PRO
    "add x20, x2, w15, uxtw\n\t"
    "cmp w3, #8\n\t"
    "b.ne .Lsb_m3l_tw\n\t"
    SB_MIP3L_LAY("8", "ldr d", "8", "16", "24", "32", "40", "48", "56", "64")
    ".Lsb_m3l_tw:\n\t"
    "cmp w3, #16\n\t"
    "b.eq .Lsb_m3l_tw16\n\t"
    "cmp w3, #4\n\t"
    "b.eq .Lsb_m3l_tw4\n\t"
    SB_MIP3L_LAY("2", "ldr h", "2", "4", "6", "8", "10", "12", "14", "16")
    ".Lsb_m3l_tw4:\n\t"
    SB_MIP3L_LAY("4", "ldr s", "4", "8", "12", "16", "20", "24", "28", "32")
    ".Lsb_m3l_tw16:\n\t"
    SB_MIP3L_LAY("16", "ldr q", "16", "32", "48", "64", "80", "96", "112", "128")
    ".Lsb_m3l_laid:\n\t"
    SB_MIP3L_STATE
    "b 3f\n\t"
    ".p2align 12\n\t"  // (band loop, group exit, epilogue, fast set-up and entry: about 2.3 KiB)
    "1:\n\t" SB_MIP3L_BAND1 "b.eq 9f\n\t" SB_MIP3L_BAND2 "b.eq 9f\n\t" SB_MIP3L_BAND0 "b.ne 1b\n\t"
    "9:\n\t"  // (the last band's rows; the next group)
    "add x8, x1, x2\n\t"
    "stp d4, d5, [x1]\n\t"
    "sub x1, x8, x29\n\t"
    "ldp x10, x11, [sp, #48]\n\t"
    "add x6, x6, #16\n\t"
    "subs x7, x7, #1\n\t"
    "stp d6, d7, [x8]\n\t"
    "b.ne 3f\n\t"
    "ldp x19, x20, [sp, #64]\n\t"
    "ldp x21, x22, [sp, #80]\n\t"
    "ldp x23, x24, [sp, #96]\n\t"
    "ldp x26, x28, [sp, #112]\n\t"
    "ldp x29, x30, [sp, #144]\n\t"
    "add sp, sp, #3248\n\t"
    "ret\n"
    ".Lsb_m3l_fast:\n\t" SB_MIP3L_FAST "b.ne 1b\n\t"
    "b 9b\n"
    "3:\n\t"  // (a group enters with x1, x6, x7, x10, x11 set; the bands keep x6, x7, x29)
    SB_MIP3L_ENTRY "b.ne 1b\n\t"
    "b 9b\n\t"
    ".Lsb_m3l_mip012:\n\t"  // (mip 2: SB_M2L_SYM, asm/neon_block_mip2f.h; it goes on to REST itself)
    "cmp w5, #2\n\t"
    "b.eq " SB_M2L_SYM "\n\t"
    "b " SB_MIP3L_REST "\n\t"
    ".p2align 4\n"
    ".Lsb_m3l_iota:\n\t"
    ".byte 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15\n\t"
    ".size " SB_MIP3L_SYM ", .-" SB_MIP3L_SYM "\n\t"
    ".popsection");

#undef SB_MIP3L_LD8  // (SB_MIP3L_REST: asm/neon.cpp names surface_block_inorder so)
#undef SB_MIP3L_TBL8
#undef SB_MIP3L_ST8
#undef SB_MIP3L_LAY
#undef SB_MIP3L_PRO
#undef SB_MIP3L_STATE
#undef SB_MIP3L_BAND0
#undef SB_MIP3L_BAND1
#undef SB_MIP3L_BAND2
#undef SB_MIP3L_ENTRY
#undef SB_MIP3L_FAST

#endif  // __aarch64__

}  // namespace
}  // namespace sb::simd::detail
