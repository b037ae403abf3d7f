// asm/neon_block_mip2l.h: the mip-2 surface block builder's lean path on AArch64 (the neon_a53
// variant): textures 4, 8, 16 or 32 wide (mip 2 of the 16- to 128-wide textures), any height,
// surfaces whose width is a multiple of 16, up to kM2LMaxHeight rows, whose grid table fits
// kA53TableBytes. Only asm/neon.cpp includes this (after asm/neon_block_a53.h and
// asm/neon_block_a53g.h, whose band loop and grid table it uses); the assembly entry
// surface_block_neon_inorder (asm/neon_block_mip3l.h) branches on mip 2 to asm/neon_block_mip2f.h's
// 16 x 16 block in assembly (included at the end), which comes here for the other shapes; the
// shapes this does not take go on to surface_block_inorder (the general surface_block_groups<2>, whose
// set-up (texture runs, run pointers, strips, the group state's copies) this skips).
//
// Every group reads the same 16 bytes of a texture row (byte k: texel (c0 + k) mod tw; 32 wide:
// the even groups so, the odd ones (c0 + 16 + k) mod tw, a second buffer), so the surface's
// rows are laid out once, in surface order, 16 bytes each: L + 16 y holds the texels of surface
// row y (texture row (t0 + y) mod th; the th distinct rows by one table lookup each, the rest
// copies). The band loop (SB_PAIR16_A / B with their row pointer loads replaced by reads at rp
// and rp + 16, rp += 32 a pair) then needs no run pointers; two rows past the surface are read
// (never used). Grid: asm/neon_block_a53g.h's table T (row 0, then the bands' differences,
// width bytes a row), group g at byte 8 g.
#pragma once
#include <arm_neon.h>

#include <cstdint>
#include <cstring>

#include "asm/neon_block_a53.h"
#include "asm/neon_block_a53g.h"
#include "asm/variants.h"

namespace sb::simd::detail {
namespace {

#if defined(__aarch64__)

constexpr int kM2LMaxHeight = 512;  // surface rows at most (the layout buffer: + 2 rows)
// tw 32's second row buffer at L + kM2LL2Off (past L's (kM2LMaxHeight + 16) rows; an add
// immediate: a multiple of 4096)
#define SB_M2L_L2OFF 12288
#define SB_M2L_STR2(x) #x
#define SB_M2L_STR(x) SB_M2L_STR2(x)
constexpr int kM2LL2Off = SB_M2L_L2OFF;
static_assert(kM2LL2Off >= (kM2LMaxHeight + 16) * 16 && kM2LL2Off % 4096 == 0 && kM2LL2Off < (4096 << 12));
// (asm/neon.cpp's kIota32 and kTix16, and mip 2's row-step weights (4 - k, k) << 4, k = 0..3:
// asm/neon.cpp defines its tables after its includes.)
constexpr uint8_t kM2LIota[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
constexpr uint8_t kM2LIota2[32] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
                                   0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
constexpr uint8_t kM2LTix[2][16] = {{0, 18, 1, 22, 2, 26, 3, 30, 4, 34, 5, 38, 6, 42, 7, 46},
                                    {40, 2, 41, 6, 42, 10, 43, 14, 44, 18, 45, 22, 46, 26, 47, 30}};
constexpr int16_t kM2LWt[2][8] = {{64, 48, 32, 16, 0, 16, 32, 48}, {256, 192, 128, 64, 0, 64, 128, 192}};

// SB_PAIR16_A / B (asm/neon_block_a53.h, same registers) with the texel rows read at rp and
// rp + 16 (rp += 32 a pair) instead of through two run pointers, reordered by
// bench/order_search.py (Cortex-A53 model: A 68 -> 66, B 75 -> 74 cycles;
// bench/mca_a53_block/pair16a_lean.s, pair16b_lean.s).
// The loops' registers by name (expanded where the text is used): the C++ function's asm
// operands here; asm/neon_block_mip2f.h redefines them as fixed registers.
#define SB_M2L_D "%[d]"
#define SB_M2L_RP "%[rp]"
#define SB_M2L_Q "%[q]"
#define SB_M2L_ETE "%[ete]"
#define SB_M2L_T0 "%[t0]"
#define SB_M2L_CM "%[cm]"
#define SB_M2L_W "%[w]"
#define SB_M2L_J0 "%[j0]"
#define SB_M2L_J1 "%[j1]"
#define SB_M2L_WT "%[wt]"
#define SB_M2L_WT4 "%[wt4]"
#define SB_M2L_A \
    "stp d4, d5, [" SB_M2L_D "]\n\t" \
    "stp d6, d7, [x8]\n\t" SB_M2L_A_BODY \
    "b 3f\n\t" \
    "3:\n\t"
// (SB_M2L_A without its stores: also a group's first pair A, straight after its entry)
#define SB_M2L_A_BODY \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, " SB_M2L_J0 ".16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, " SB_M2L_J1 ".16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, " SB_M2L_J0 ".16b\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, " SB_M2L_J1 ".16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "ldr q8, [" SB_M2L_ETE ", " SB_M2L_Q "]\n\t" \
    "ror x10, x0, #32\n\t" \
    "ror x21, x4, #32\n\t" \
    "add x9, " SB_M2L_CM ", w0, uxth\n\t" \
    "add x12, " SB_M2L_CM ", w2, uxth\n\t" \
    "ror x18, x2, #32\n\t" \
    "add x0, " SB_M2L_CM ", x0, lsr #48\n\t" \
    "add x11, " SB_M2L_CM ", w10, uxth\n\t" \
    "add x23, " SB_M2L_CM ", w6, uxth\n\t" \
    "add x20, " SB_M2L_CM ", w4, uxth\n\t" \
    "ldr b5, [x12]\n\t" \
    "ror x24, x6, #32\n\t" \
    "ldr b4, [x9]\n\t" \
    "add x22, " SB_M2L_CM ", w21, uxth\n\t" \
    "ldr b7, [x23]\n\t" \
    "add x21, " SB_M2L_CM ", x21, lsr #48\n\t" \
    "add x10, " SB_M2L_CM ", x10, lsr #48\n\t" \
    "add x19, " SB_M2L_CM ", w18, uxth\n\t" \
    "add x18, " SB_M2L_CM ", x18, lsr #48\n\t" \
    "add x25, " SB_M2L_CM ", w24, uxth\n\t" \
    "ldr b6, [x20]\n\t" \
    "add x24, " SB_M2L_CM ", x24, lsr #48\n\t" \
    "add x2, " SB_M2L_CM ", x2, lsr #48\n\t" \
    "add x12, " SB_M2L_CM ", w3, uxth\n\t" \
    "ld1 {v5.b}[1], [x18]\n\t" \
    "add x6, " SB_M2L_CM ", x6, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x10]\n\t" \
    "ror x10, x1, #32\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "add x4, " SB_M2L_CM ", x4, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x21]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ldr q21, [" SB_M2L_RP "]\n\t" \
    "add x9, " SB_M2L_CM ", w1, uxth\n\t" \
    "ld1 {v4.b}[2], [x11]\n\t" \
    "ror x21, x5, #32\n\t" \
    "ld1 {v5.b}[2], [x19]\n\t" \
    "add x20, " SB_M2L_CM ", w5, uxth\n\t" \
    "ld1 {v6.b}[2], [x22]\n\t" \
    "ror x24, x7, #32\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x19, " SB_M2L_CM ", w18, uxth\n\t" \
    "ldr q26, [" SB_M2L_RP ", #16]\n\t" \
    "add x23, " SB_M2L_CM ", w7, uxth\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "add x11, " SB_M2L_CM ", w10, uxth\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x10, " SB_M2L_CM ", x10, lsr #48\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x25, " SB_M2L_CM ", w24, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x22, " SB_M2L_CM ", w21, uxth\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x21, " SB_M2L_CM ", x21, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x12]\n\t" \
    "add x18, " SB_M2L_CM ", x18, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x20]\n\t" \
    "add x5, " SB_M2L_CM ", x5, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x23]\n\t" \
    "add x24, " SB_M2L_CM ", x24, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x10]\n\t" \
    "ld1 {v5.b}[5], [x18]\n\t" \
    "add x1, " SB_M2L_CM ", x1, lsr #48\n\t" \
    "ld1 {v6.b}[5], [x21]\n\t" \
    "add " SB_M2L_D ", " SB_M2L_D ", " SB_M2L_W ", lsl #1\n\t" \
    "ld1 {v7.b}[5], [x24]\n\t" \
    "ld1 {v4.b}[6], [x11]\n\t" \
    "add x3, " SB_M2L_CM ", x3, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x19]\n\t" \
    "ld1 {v6.b}[6], [x22]\n\t" \
    "add x7, " SB_M2L_CM ", x7, lsr #48\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "add x8, " SB_M2L_D ", " SB_M2L_W "\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "add " SB_M2L_RP ", " SB_M2L_RP ", #32\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t"

#define SB_M2L_B \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, " SB_M2L_J0 ".16b\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, " SB_M2L_J1 ".16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull v16.4s, " SB_M2L_WT ".4h, v8.h[0]\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, " SB_M2L_J1 ".16b\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, " SB_M2L_J0 ".16b\n\t" \
    "smull v29.4s, " SB_M2L_WT ".4h, v8.h[3]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "smlal2 v16.4s, " SB_M2L_WT ".8h, v8.h[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "smull v17.4s, " SB_M2L_WT ".4h, v8.h[1]\n\t" \
    "smull v18.4s, " SB_M2L_WT ".4h, v8.h[2]\n\t" \
    "stp d4, d5, [" SB_M2L_D "]\n\t" \
    "adds " SB_M2L_Q ", " SB_M2L_Q ", " SB_M2L_W "\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "ror x24, x6, #32\n\t" \
    "add x9, " SB_M2L_CM ", w0, uxth\n\t" \
    "add x23, " SB_M2L_CM ", w6, uxth\n\t" \
    "ror x21, x4, #32\n\t" \
    "ror x10, x0, #32\n\t" \
    "ldr q26, [" SB_M2L_RP ", #16]\n\t" \
    "ror x18, x2, #32\n\t" \
    "ldr b4, [x9]\n\t" \
    "add x20, " SB_M2L_CM ", w4, uxth\n\t" \
    "ldr b7, [x23]\n\t" \
    "add x25, " SB_M2L_CM ", w24, uxth\n\t" \
    "add x12, " SB_M2L_CM ", w2, uxth\n\t" \
    "add x11, " SB_M2L_CM ", w10, uxth\n\t" \
    "add x19, " SB_M2L_CM ", w18, uxth\n\t" \
    "add x10, " SB_M2L_CM ", x10, lsr #48\n\t" \
    "add x22, " SB_M2L_CM ", w21, uxth\n\t" \
    "add x18, " SB_M2L_CM ", x18, lsr #48\n\t" \
    "ldr b5, [x12]\n\t" \
    "add x21, " SB_M2L_CM ", x21, lsr #48\n\t" \
    "ldr b6, [x20]\n\t" \
    "add x24, " SB_M2L_CM ", x24, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x10]\n\t" \
    "add x23, " SB_M2L_CM ", w7, uxth\n\t" \
    "add x12, " SB_M2L_CM ", w3, uxth\n\t" \
    "ror x10, x1, #32\n\t" \
    "ld1 {v5.b}[1], [x18]\n\t" \
    "add x0, " SB_M2L_CM ", x0, lsr #48\n\t" \
    "ld1 {v6.b}[1], [x21]\n\t" \
    "add x2, " SB_M2L_CM ", x2, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x24]\n\t" \
    "add x4, " SB_M2L_CM ", x4, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x11]\n\t" \
    "ror x21, x5, #32\n\t" \
    "ld1 {v5.b}[2], [x19]\n\t" \
    "add x20, " SB_M2L_CM ", w5, uxth\n\t" \
    "ld1 {v6.b}[2], [x22]\n\t" \
    "add x6, " SB_M2L_CM ", x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x22, " SB_M2L_CM ", w21, uxth\n\t" \
    "add x9, " SB_M2L_CM ", w1, uxth\n\t" \
    "ror x24, x7, #32\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x11, " SB_M2L_CM ", w10, uxth\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "ror x18, x3, #32\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x25, " SB_M2L_CM ", w24, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x10, " SB_M2L_CM ", x10, lsr #48\n\t" \
    "ldr q21, [" SB_M2L_RP "]\n\t" \
    "add x19, " SB_M2L_CM ", w18, uxth\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x21, " SB_M2L_CM ", x21, lsr #48\n\t" \
    "ld1 {v6.b}[4], [x20]\n\t" \
    "add x18, " SB_M2L_CM ", x18, lsr #48\n\t" \
    "ld1 {v5.b}[4], [x12]\n\t" \
    "add x24, " SB_M2L_CM ", x24, lsr #48\n\t" \
    "ld1 {v7.b}[4], [x23]\n\t" \
    "add x3, " SB_M2L_CM ", x3, lsr #48\n\t" \
    "ld1 {v4.b}[5], [x10]\n\t" \
    "ld1 {v6.b}[5], [x21]\n\t" \
    "add x5, " SB_M2L_CM ", x5, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x18]\n\t" \
    "ld1 {v7.b}[5], [x24]\n\t" \
    "smlal2 v17.4s, " SB_M2L_WT ".8h, v8.h[2]\n\t" \
    "smlal2 v18.4s, " SB_M2L_WT ".8h, v8.h[3]\n\t" \
    "ld1 {v6.b}[6], [x22]\n\t" \
    "add x1, " SB_M2L_CM ", x1, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x19]\n\t" \
    "add " SB_M2L_D ", " SB_M2L_D ", " SB_M2L_W ", lsl #1\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "add x7, " SB_M2L_CM ", x7, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x11]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "smlal2 v29.4s, " SB_M2L_WT ".8h, v8.h[4]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add x8, " SB_M2L_D ", " SB_M2L_W "\n\t" \
    "add " SB_M2L_RP ", " SB_M2L_RP ", #32\n\t" \
    "b.ne 1b\n\t"

// A group's entry (asm/neon_block_a53g.h's SB_A53_HEAD2, the numerators' << 2 in their weights
// wt4): numerators from T's row 0 (v0), the first band's step from row 1 (v8), d = the group's
// output (x26) two rows up; v0, v8 and the first two texel rows (v21, v26, rp stepped) are
// loaded before it (SB_M2L_LOADS: at the previous group's exit, so their latency overlaps its
// stores and state steps).
#define SB_M2L_LOADS \
  "ldr q0, [" SB_M2L_T0 "]\n\t" \
  "ldr q8, [" SB_M2L_T0 ", " SB_M2L_W "]\n\t" \
  "ldr q21, [" SB_M2L_RP "]\n\t" \
  "ldr q26, [" SB_M2L_RP ", #16]\n\t" \
  "add " SB_M2L_RP ", " SB_M2L_RP ", #32\n\t"
#define SB_M2L_HEAD \
  "sub " SB_M2L_D ", x26, " SB_M2L_W ", lsl #1\n\t" \
  "smull v22.4s, " SB_M2L_WT4 ".4h, v0.h[0]\n\t" \
  "smull v23.4s, " SB_M2L_WT4 ".4h, v0.h[1]\n\t" \
  "smull v19.4s, " SB_M2L_WT4 ".4h, v0.h[2]\n\t" \
  "smull v20.4s, " SB_M2L_WT4 ".4h, v0.h[3]\n\t" \
  "smull v16.4s, " SB_M2L_WT ".4h, v8.h[0]\n\t" \
  "smull v17.4s, " SB_M2L_WT ".4h, v8.h[1]\n\t" \
  "smull v18.4s, " SB_M2L_WT ".4h, v8.h[2]\n\t" \
  "smull v29.4s, " SB_M2L_WT ".4h, v8.h[3]\n\t" \
  "smlal2 v22.4s, " SB_M2L_WT4 ".8h, v0.h[1]\n\t" \
  "smlal2 v23.4s, " SB_M2L_WT4 ".8h, v0.h[2]\n\t" \
  "smlal2 v19.4s, " SB_M2L_WT4 ".8h, v0.h[3]\n\t" \
  "smlal2 v20.4s, " SB_M2L_WT4 ".8h, v0.h[4]\n\t" \
  "smlal2 v16.4s, " SB_M2L_WT ".8h, v8.h[1]\n\t" \
  "smlal2 v17.4s, " SB_M2L_WT ".8h, v8.h[2]\n\t" \
  "smlal2 v18.4s, " SB_M2L_WT ".8h, v8.h[3]\n\t" \
  "smlal2 v29.4s, " SB_M2L_WT ".8h, v8.h[4]\n\t"

// The rows from L + 16 TH to e (> L + 16 TH) as repeats of the TH rows at L (TH 4, 8 or 16),
// stored from registers, a period a step (up to 16 TH - 64 bytes past e: the buffer has room).
template <int TH>
inline void m2l_repeat(uint8_t* L, uint8_t* e) {
  uint8_t* o = L + 16 * TH;
  if constexpr (TH == 16) {
    asm volatile(
        "ldp q16, q17, [%[o], #-256]\n\t"
        "ldp q18, q19, [%[o], #-224]\n\t"
        "ldp q20, q21, [%[o], #-192]\n\t"
        "ldp q22, q23, [%[o], #-160]\n\t"
        "ldp q24, q25, [%[o], #-128]\n\t"
        "ldp q26, q27, [%[o], #-96]\n\t"
        "ldp q28, q29, [%[o], #-64]\n\t"
        "ldp q30, q31, [%[o], #-32]\n"
        "1:\n\t"
        "stp q16, q17, [%[o]]\n\t"
        "stp q18, q19, [%[o], #32]\n\t"
        "stp q20, q21, [%[o], #64]\n\t"
        "stp q22, q23, [%[o], #96]\n\t"
        "stp q24, q25, [%[o], #128]\n\t"
        "stp q26, q27, [%[o], #160]\n\t"
        "stp q28, q29, [%[o], #192]\n\t"
        "stp q30, q31, [%[o], #224]\n\t"
        "add %[o], %[o], #256\n\t"
        "cmp %[o], %[e]\n\t"
        "b.lo 1b\n\t"
        : [o] "+r"(o)
        : [e] "r"(e)
        : "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30",
          "v31", "cc", "memory");
  } else if constexpr (TH == 8) {
    asm volatile(
        "ldp q16, q17, [%[o], #-128]\n\t"
        "ldp q18, q19, [%[o], #-96]\n\t"
        "ldp q20, q21, [%[o], #-64]\n\t"
        "ldp q22, q23, [%[o], #-32]\n"
        "1:\n\t"
        "stp q16, q17, [%[o]]\n\t"
        "stp q18, q19, [%[o], #32]\n\t"
        "stp q20, q21, [%[o], #64]\n\t"
        "stp q22, q23, [%[o], #96]\n\t"
        "add %[o], %[o], #128\n\t"
        "cmp %[o], %[e]\n\t"
        "b.lo 1b\n\t"
        : [o] "+r"(o)
        : [e] "r"(e)
        : "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "cc", "memory");
  } else {
    asm volatile(
        "ldp q16, q17, [%[o], #-64]\n\t"
        "ldp q18, q19, [%[o], #-32]\n"
        "1:\n\t"
        "stp q16, q17, [%[o]]\n\t"
        "stp q18, q19, [%[o], #32]\n\t"
        "add %[o], %[o], #64\n\t"
        "cmp %[o], %[e]\n\t"
        "b.lo 1b\n\t"
        : [o] "+r"(o)
        : [e] "r"(e)
        : "v16", "v17", "v18", "v19", "cc", "memory");
  }
}

// 16 x 16 textures (mip 2 of 64 x 64): m2l_rows in one block, every row loaded first (four
// runs of four rows from t0, rows wrapping at 16), 16 lookups, stores from the registers, a
// period a step up to e (up to 192 bytes past e).
inline void m2l_rows16x16(const uint8_t* texels, int t0, uint8x16_t I, uint8_t* L, uint8_t* e) {
  const uint8_t *p0 = texels + 16 * t0, *p1 = texels + 16 * ((t0 + 4) & 15), *p2 = texels + 16 * ((t0 + 8) & 15),
                *p3 = texels + 16 * ((t0 + 12) & 15);
  asm volatile(
      "ldp q16, q17, [%[p0]]\n\t"
      "ldp q18, q19, [%[p0], #32]\n\t"
      "ldp q20, q21, [%[p1]]\n\t"
      "ldp q22, q23, [%[p1], #32]\n\t"
      "ldp q24, q25, [%[p2]]\n\t"
      "ldp q26, q27, [%[p2], #32]\n\t"
      "ldp q28, q29, [%[p3]]\n\t"
      "ldp q30, q31, [%[p3], #32]\n\t"
      "tbl v16.16b, {v16.16b}, %[i].16b\n\t"
      "tbl v17.16b, {v17.16b}, %[i].16b\n\t"
      "tbl v18.16b, {v18.16b}, %[i].16b\n\t"
      "tbl v19.16b, {v19.16b}, %[i].16b\n\t"
      "tbl v20.16b, {v20.16b}, %[i].16b\n\t"
      "tbl v21.16b, {v21.16b}, %[i].16b\n\t"
      "tbl v22.16b, {v22.16b}, %[i].16b\n\t"
      "tbl v23.16b, {v23.16b}, %[i].16b\n\t"
      "tbl v24.16b, {v24.16b}, %[i].16b\n\t"
      "tbl v25.16b, {v25.16b}, %[i].16b\n\t"
      "tbl v26.16b, {v26.16b}, %[i].16b\n\t"
      "tbl v27.16b, {v27.16b}, %[i].16b\n\t"
      "tbl v28.16b, {v28.16b}, %[i].16b\n\t"
      "tbl v29.16b, {v29.16b}, %[i].16b\n\t"
      "tbl v30.16b, {v30.16b}, %[i].16b\n\t"
      "tbl v31.16b, {v31.16b}, %[i].16b\n"
      "1:\n\t"
      "stp q16, q17, [%[o]]\n\t"
      "stp q18, q19, [%[o], #32]\n\t"
      "stp q20, q21, [%[o], #64]\n\t"
      "stp q22, q23, [%[o], #96]\n\t"
      "stp q24, q25, [%[o], #128]\n\t"
      "stp q26, q27, [%[o], #160]\n\t"
      "stp q28, q29, [%[o], #192]\n\t"
      "stp q30, q31, [%[o], #224]\n\t"
      "add %[o], %[o], #256\n\t"
      "cmp %[o], %[e]\n\t"
      "b.lo 1b\n\t"
      : [o] "+r"(L)
      : [e] "r"(e), [i] "w"(I), [p0] "r"(p0), [p1] "r"(p1), [p2] "r"(p2), [p3] "r"(p3)
      : "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30",
        "v31", "cc", "memory");
}

// Surface rows 0..h-1 (texture rows t0, t0 + 1, .. wrapping at th) laid out 16 bytes each at L,
// byte k the texel (c0 + k) mod TW by the lookup I: four texture rows a step (4 TW bytes: one to
// four loads, never past the texture), each stored at every row it repeats on (y, y + th, ..).
// th, t0 and h are multiples of 4 (the contract's, mip 2).
template <int TW>
__attribute__((always_inline)) inline void m2l_rows(const uint8_t* texels, int th, int t0, int h, uint8x16_t I,
                                                    uint8_t* L) {
  const uint8x16_t I1 = vaddq_u8(I, vdupq_n_u8(TW == 16 ? 0 : TW));
  const uint8x16_t I2 = vaddq_u8(I, vdupq_n_u8(TW == 4 ? 8 : 0)), I3 = vaddq_u8(I1, vdupq_n_u8(TW == 4 ? 8 : 0));
  const int n = h < th ? h : th;
  const uint8_t* row = texels + t0 * TW;
  const uint8_t* const end = texels + th * TW;
  uint8_t* const L0 = L;
  uint8_t* const L_end = L + 16 * h;
  const int64_t period = 16 * int64_t(th);
  // (4, 8 or 16 rows: the first copy here, the others by m2l_repeat)
  const bool rep = h > th && th <= 16 && (th & (th - 1)) == 0;
  for (int k = 0; k < n; k += 4, L += 64) {
    uint8x16_t a, b, c, d;
    if constexpr (TW == 16) {
      a = vld1q_u8(row), b = vld1q_u8(row + 16), c = vld1q_u8(row + 32), d = vld1q_u8(row + 48);
    } else if constexpr (TW == 8) {
      a = b = vld1q_u8(row), c = d = vld1q_u8(row + 16);
    } else {
      a = b = c = d = vld1q_u8(row);
    }
    row += 4 * TW;
    if (row == end) row = texels;
    a = vqtbl1q_u8(a, I), b = vqtbl1q_u8(b, I1), c = vqtbl1q_u8(c, I2), d = vqtbl1q_u8(d, I3);
    for (uint8_t* o = L; o < (rep ? L + 64 : L_end); o += period) {
      vst1q_u8(o, a);
      vst1q_u8(o + 16, b);
      vst1q_u8(o + 32, c);
      vst1q_u8(o + 48, d);
    }
  }
  if (!rep) return;
  if (th == 16)
    m2l_repeat<16>(L0, L_end);
  else if (th == 8)
    m2l_repeat<8>(L0, L_end);
  else
    m2l_repeat<4>(L0, L_end);
}

// Two 8-entry columns of asm/neon_block_a53g.h's table T (a53_table's, four rows a step, both
// columns interleaved: Cortex-A53 model 30 cycles for 8 differences against 34), with kH a third
// column of one entry (by core loads: widths a multiple of 64 end on one), in one pass: grid
// entries at s0, s1, s2 (rows gw entries apart) to T at o0, o1, o2 (rows es bytes apart), rows
// 0..nb.
// Four rows of the two columns (SB_M2L_COLS' loop body), without and with the third column
// (_H: order searched by bench/order_search.py, Cortex-A53 model 43 -> 38 cycles).
#define SB_M2L_STEP4 \
      "ldr q1, [%[s0], %[g1]]\n\t" \
      "ldr q2, [%[s0], %[g2]]\n\t" \
      "ldr q3, [%[s0], %[g3]]\n\t" \
      "ldr q4, [%[s0], %[g4]]\n\t" \
      "ldr q17, [%[s1], %[g1]]\n\t" \
      "ldr q18, [%[s1], %[g2]]\n\t" \
      "ldr q19, [%[s1], %[g3]]\n\t" \
      "ldr q20, [%[s1], %[g4]]\n\t" \
      "add %[s0], %[s0], %[g4]\n\t" \
      "add %[s1], %[s1], %[g4]\n\t" \
      "subs %[n4], %[n4], #1\n\t" \
      "sub v5.8h, v1.8h, v0.8h\n\t" \
      "sub v6.8h, v2.8h, v1.8h\n\t" \
      "sub v7.8h, v3.8h, v2.8h\n\t" \
      "sub v21.8h, v17.8h, v16.8h\n\t" \
      "sub v22.8h, v18.8h, v17.8h\n\t" \
      "sub v23.8h, v19.8h, v18.8h\n\t" \
      "sub v24.8h, v20.8h, v19.8h\n\t" \
      "sub v25.8h, v4.8h, v3.8h\n\t" \
      "mov v0.16b, v4.16b\n\t" \
      "mov v16.16b, v20.16b\n\t" \
      "str q5, [%[o0], %[e1]]\n\t" \
      "str q21, [%[o1], %[e1]]\n\t" \
      "str q6, [%[o0], %[e2]]\n\t" \
      "str q22, [%[o1], %[e2]]\n\t" \
      "str q7, [%[o0], %[e3]]\n\t" \
      "str q23, [%[o1], %[e3]]\n\t" \
      "str q25, [%[o0], %[e4]]\n\t" \
      "str q24, [%[o1], %[e4]]\n\t" \
      "add %[o0], %[o0], %[e4]\n\t" \
      "add %[o1], %[o1], %[e4]\n\t"
#define SB_M2L_STEP4_H \
      "ldr q2, [%[s0], %[g2]]\n\t" \
      "ldr q4, [%[s0], %[g4]]\n\t" \
      "ldr q3, [%[s0], %[g3]]\n\t" \
      "ldr q1, [%[s0], %[g1]]\n\t" \
      "ldr q19, [%[s1], %[g3]]\n\t" \
      "add %[s0], %[s0], %[g4]\n\t" \
      "ldrh w12, [%[s2], %[g3]]\n\t" \
      "subs %[n4], %[n4], #1\n\t" \
      "ldrh w13, [%[s2], %[g4]]\n\t" \
      "ldr q17, [%[s1], %[g1]]\n\t" \
      "ldrh w11, [%[s2], %[g2]]\n\t" \
      "ldr q20, [%[s1], %[g4]]\n\t" \
      "ldrh w10, [%[s2], %[g1]]\n\t" \
      "sub v25.8h, v4.8h, v3.8h\n\t" \
      "ldr q18, [%[s1], %[g2]]\n\t" \
      "sub w14, w13, w12\n\t" \
      "sub w12, w12, w11\n\t" \
      "sub w11, w11, w10\n\t" \
      "sub v5.8h, v1.8h, v0.8h\n\t" \
      "sub v6.8h, v2.8h, v1.8h\n\t" \
      "sub v21.8h, v17.8h, v16.8h\n\t" \
      "sub v22.8h, v18.8h, v17.8h\n\t" \
      "sub v24.8h, v20.8h, v19.8h\n\t" \
      "sub v7.8h, v3.8h, v2.8h\n\t" \
      "str q5, [%[o0], %[e1]]\n\t" \
      "str q21, [%[o1], %[e1]]\n\t" \
      "sub v23.8h, v19.8h, v18.8h\n\t" \
      "mov v0.16b, v4.16b\n\t" \
      "mov v16.16b, v20.16b\n\t" \
      "str q6, [%[o0], %[e2]]\n\t" \
      "str q22, [%[o1], %[e2]]\n\t" \
      "str q7, [%[o0], %[e3]]\n\t" \
      "sub w10, w10, w9\n\t" \
      "str q23, [%[o1], %[e3]]\n\t" \
      "str q25, [%[o0], %[e4]]\n\t" \
      "str q24, [%[o1], %[e4]]\n\t" \
      "mov w9, w13\n\t" \
      "strh w10, [%[o2], %[e1]]\n\t" \
      "add %[o0], %[o0], %[e4]\n\t" \
      "strh w11, [%[o2], %[e2]]\n\t" \
      "add %[s1], %[s1], %[g4]\n\t" \
      "strh w12, [%[o2], %[e3]]\n\t" \
      "add %[s2], %[s2], %[g4]\n\t" \
      "strh w14, [%[o2], %[e4]]\n\t" \
      "add %[o1], %[o1], %[e4]\n\t" \
      "add %[o2], %[o2], %[e4]\n\t"
#define SB_M2L_COLS(H0, STEP4, H4) \
  asm volatile( \
      "ldr q0, [%[s0]]\n\t" \
      "ldr q16, [%[s1]]\n\t" H0 \
      "str q0, [%[o0]]\n\t" \
      "str q16, [%[o1]]\n\t" \
      "cbz %[n4], 2f\n" \
      "1:\n\t" \
      STEP4 \
      "b.ne 1b\n" \
      "2:\n\t" \
      "cbz %[n1], 4f\n" \
      "3:\n\t" \
      "ldr q1, [%[s0], %[g1]]\n\t" \
      "ldr q17, [%[s1], %[g1]]\n\t" \
      "add %[s0], %[s0], %[g1]\n\t" \
      "add %[s1], %[s1], %[g1]\n\t" \
      "subs %[n1], %[n1], #1\n\t" \
      "sub v5.8h, v1.8h, v0.8h\n\t" \
      "sub v21.8h, v17.8h, v16.8h\n\t" \
      "mov v0.16b, v1.16b\n\t" \
      "mov v16.16b, v17.16b\n\t" \
      "str q5, [%[o0], %[e1]]\n\t" \
      "str q21, [%[o1], %[e1]]\n\t" H4 \
      "add %[o0], %[o0], %[e1]\n\t" \
      "add %[o1], %[o1], %[e1]\n\t" \
      "b.ne 3b\n" \
      "4:\n\t" \
      : [s0] "+r"(s0), [s1] "+r"(s1), [o0] "+r"(o0), [o1] "+r"(o1), [n4] "+r"(n4), [n1] "+r"(n1), [s2] "+r"(s2), \
        [o2] "+r"(o2) \
      : [g1] "r"(g1), [g2] "r"(g2), [g3] "r"(g3), [g4] "r"(g4), [e1] "r"(es), [e2] "r"(e2), [e3] "r"(e3), \
        [e4] "r"(e4) \
      : "x9", "x10", "x11", "x12", "x13", "x14", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", \
        "v19", "v20", "v21", "v22", "v23", "v24", "v25", "cc", "memory")
template <bool kH>
inline void m2l_cols2(const uint16_t* s0, const uint16_t* s1, int gw, int nb, uint8_t* o0, uint8_t* o1, int64_t es,
                      const uint16_t* s2 = nullptr, uint8_t* o2 = nullptr) {
  const int64_t g1 = 2 * int64_t(gw), g2 = 2 * g1, g3 = 3 * g1, g4 = 4 * g1;
  const int64_t e2 = 2 * es, e3 = 3 * es, e4 = 4 * es;
  int64_t n4 = nb >> 2, n1 = nb & 3;
  if constexpr (kH)
    SB_M2L_COLS("ldrh w9, [%[s2]]\n\t" "strh w9, [%[o2]]\n\t", SB_M2L_STEP4_H, "ldrh w10, [%[s2], %[g1]]\n\t" "add %[s2], %[s2], %[g1]\n\t" "sub w11, w10, w9\n\t" "mov w9, w10\n\t" "strh w11, [%[o2], %[e1]]\n\t" "add %[o2], %[o2], %[e1]\n\t");
  else
    SB_M2L_COLS("", SB_M2L_STEP4, "");
}
#undef SB_M2L_COLS
#undef SB_M2L_STEP4
#undef SB_M2L_STEP4_H

// T's entries 0..ne - 1 (ne >= 8, ne <= gw): columns of 8 in pairs (and a last single entry
// with the last pair), a last column alone by a53_table (the last column ends at entry ne - 1,
// overlapping the one before).
inline void m2l_table(const uint16_t* r, int gw, int nb, int ne, uint8_t* t, int64_t es) {
  int j = 0;
  for (; j + 16 <= ne; j += 16) {
    if (j + 17 == ne) {
      m2l_cols2<true>(r + j, r + j + 8, gw, nb, t + 2 * j, t + 2 * j + 16, es, r + j + 16, t + 2 * j + 32);
      return;
    }
    m2l_cols2<false>(r + j, r + j + 8, gw, nb, t + 2 * j, t + 2 * j + 16, es);
  }
  if (j == ne) return;
  if (ne - j > 8)
    m2l_cols2<false>(r + j, r + ne - 8, gw, nb, t + 2 * j, t + 2 * (ne - 8), es);
  else
    a53_table<2>(r + ne - 8, gw, nb, 8, t + 2 * (ne - 8), es);
}

// 32-wide textures (mip 2 of 128-wide ones): even groups read texels (c0 + k) mod 32 of a row,
// odd groups (c0 + 16 + k) mod 32: surface row y's are laid out at L + 16 y and L2 + 16 y (two
// two-register lookups of the row), two rows a step, rows wrapping at th (m2l_rows' order).
inline void m2l_rows32(const uint8_t* texels, int th, int t0, int h, int c0, uint8_t* L, uint8_t* L2) {
  const uint8x16_t k = vld1q_u8(kM2LIota), m = vdupq_n_u8(31);
  const uint8x16_t I0 = vandq_u8(vaddq_u8(k, vdupq_n_u8(uint8_t(c0))), m);
  const uint8x16_t I1 = vandq_u8(vaddq_u8(k, vdupq_n_u8(uint8_t(c0 + 16))), m);
  const int n = h < th ? h : th;
  const uint8_t* row = texels + 32 * t0;
  const uint8_t* const end = texels + 32 * th;
  const int64_t period = 16 * int64_t(th);
  uint8_t* const L_end = L + 16 * h;
  for (int y = 0; y < n; y += 2, L += 32, L2 += 32) {
    const uint8x16x2_t a = {{vld1q_u8(row), vld1q_u8(row + 16)}}, b = {{vld1q_u8(row + 32), vld1q_u8(row + 48)}};
    row += 64;
    if (row == end) row = texels;
    const uint8x16_t a0 = vqtbl2q_u8(a, I0), a1 = vqtbl2q_u8(a, I1), b0 = vqtbl2q_u8(b, I0), b1 = vqtbl2q_u8(b, I1);
    for (int64_t o = 0; L + o < L_end; o += period) {
      vst1q_u8(L + o, a0);
      vst1q_u8(L + o + 16, b0);
      vst1q_u8(L2 + o, a1);
      vst1q_u8(L2 + o + 16, b1);
    }
  }
}

// The lean path (see the top), entered from asm/neon_block_mip2f.h's assembly (SB_M2L_SYM, the
// target of surface_block_neon_inorder's mip-2 branch) by a branch, under the symbol SB_M2L_CXX,
// with surface_block's arguments; the shapes
// it does not take go on (tail call, arguments untouched) to surface_block_inorder (asm/neon.cpp).
#define SB_M2L_SYM "_ZN2sb4simd6detail23surface_block_mip2_leanEPKtiPKhiiiiiiiS5_Ph"
// (this C++ function's own symbol: asm/neon_block_mip2f.h's assembly is SB_M2L_SYM, and comes here
// for the shapes it does not take)
#define SB_M2L_CXX "_ZN2sb4simd6detail27surface_block_mip2_lean_cxxEPKtiPKhiiiiiiiS5_Ph"
namespace {  // (asm/neon.cpp defines it in this nested unnamed namespace)
__attribute__((noipa, used)) void surface_block_inorder(const uint16_t* grid, int gw, const uint8_t* texels, int tw,
                                                        int th, int mip, int soff, int toff, int width, int height,
                                                        const uint8_t* colormap, uint8_t* out)
    asm("_ZN2sb4simd6detail21surface_block_inorderEPKtiPKhiiiiiiiS5_Ph");
}  // namespace
__attribute__((noipa, used)) void surface_block_mip2_lean(const uint16_t* grid, int gw, const uint8_t* texels, int tw,
                                                          int th, int mip, int soff, int toff, int width, int height,
                                                          const uint8_t* colormap, uint8_t* out) asm(SB_M2L_CXX);
void surface_block_mip2_lean(const uint16_t* grid, int gw, const uint8_t* texels, int tw, int th, int mip, int soff,
                             int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  if ((tw != 4 && tw != 8 && tw != 16 && tw != 32) || (width & 15) || width < 16 || height <= 0 || height > kM2LMaxHeight ||
      ((th | toff | height) & 3) || th <= 0 || ((height >> 2) + 3) * width > kA53TableBytes)
    return surface_block_inorder(grid, gw, texels, tw, th, mip, soff, toff, width, height, colormap, out);
  const int nb = height >> 2;
  alignas(16) uint8_t t[kA53TableBytes];
  // L: the rows (m2l_repeat: up to 12 rows past); L2 = L + kM2LL2Off: tw 32, the odd groups' rows
  alignas(16) uint8_t L[kM2LL2Off + (kM2LMaxHeight + 2) * 16];
  uint8_t* const L2 = L + kM2LL2Off;
  const int c0 = soff & (tw - 1), t0 = (th & (th - 1)) == 0 ? toff & (th - 1) : wrap(toff, th);
  // (byte k: (c0 + k) mod tw, tw 4, 8 or 16 dividing 16: one load of kM2LIota2 at c0 < tw)
  const uint8x16_t I = vandq_u8(vld1q_u8(kM2LIota2 + (c0 & 15)), vdupq_n_u8(uint8_t(tw - 1)));
  if (tw == 16 && th == 16)
    m2l_rows16x16(texels, t0, I, L, L + 16 * height);
  else if (tw == 32)
    m2l_rows32(texels, th, t0, height, c0, L, L2);
  else if (tw == 16)
    m2l_rows<16>(texels, th, t0, height, I, L);
  else if (tw == 8)
    m2l_rows<8>(texels, th, t0, height, I, L);
  else
    m2l_rows<4>(texels, th, t0, height, I, L);
  const int64_t es = width;
  const int ne = 4 * (width >> 4) + 1;  // (one group: 8 entries when the grid rows have them)
  if (ne >= 8 || gw >= 8)
    m2l_table(grid, gw, nb, ne >= 8 ? ne : 8, t, es);
  else
    a53_table<2>(grid, gw, nb, ne, t, es);
  const int16x8_t wt = vld1q_s16(kM2LWt[0]), wt4 = vld1q_s16(kM2LWt[1]);  // (wt4: the numerators', << 2)
  const uint8x16_t J0 = vld1q_u8(kM2LTix[0]), J1 = vld1q_u8(kM2LTix[1]);
  uint8_t* d = out;
  const uint8_t* rp = L;
  const uint8_t* t0r = t;
  const uint8_t* ete = t + (nb + 2) * es;
  int64_t q = -int64_t(nb) * es;
  // x26: the group's output; [sp]: this group's rows (rp's start), dend = d + w, (tw 32) the
  // next group's rows (swapped at each exit; else the same rows, one ldp; ENTRY stores them). The group's exit: T's row-0
  // pointer and ete a group on (8 bytes), q = t0 + 2 w - ete (-nb w), rp = the next group's rows.
#define SB_M2L_GROUPS(ENTRY, EXIT) \
  asm volatile( \
      "add x30, %[d], %[w]\n\t" \
      "stp %[rp], x30, [sp, #-32]!\n\t" ENTRY \
      "mov x26, %[d]\n\t" SB_M2L_LOADS \
      "5:\n\t" SB_M2L_HEAD SB_M2L_A_BODY \
      "b 3f\n\t" \
      ".p2align 6\n" \
      "1:\n\t" SB_M2L_A SB_M2L_B EXIT \
      "b.ne 5b\n\t" \
      "add sp, sp, #32\n\t" \
      : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q), [ete] "+r"(ete), [t0] "+r"(t0r) \
      : [cm] "r"(colormap), [w] "r"(es), [j0] "w"(J0), [j1] "w"(J1), [wt] "w"(wt), [wt4] "w"(wt4) \
      : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20", "x21", \
        "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8", "v16", "v17", \
        "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc", "memory")
  if (tw == 32)
    SB_M2L_GROUPS("add x10, %[rp], #" SB_M2L_STR(SB_M2L_L2OFF) "\n\t"
                  "str x10, [sp, #16]\n\t",
                  "stp d4, d5, [%[d]]\n\t"
                  "stp d6, d7, [x8]\n\t"
                  "ldp x10, x30, [sp]\n\t"
                  "ldr %[rp], [sp, #16]\n\t"
                  "str x10, [sp, #16]\n\t"
                  "str %[rp], [sp]\n\t"
                  "add x26, x26, #16\n\t"
                  "add %[t0], %[t0], #8\n\t"
                  "add %[ete], %[ete], #8\n\t"
                  "add %[q], %[t0], %[w], lsl #1\n\t"
                  "sub %[q], %[q], %[ete]\n\t" SB_M2L_LOADS
                  "cmp x26, x30\n\t");
  else  // (the same steps with one ldp for the rows, order searched: Cortex-A53 model 13 -> 11)
    SB_M2L_GROUPS("", "add %[t0], %[t0], #8\n\t"
                  "stp d4, d5, [%[d]]\n\t"
                  "ldp %[rp], x30, [sp]\n\t"
                  "add %[ete], %[ete], #8\n\t"
                  "add %[q], %[t0], %[w], lsl #1\n\t"
                  "ldr q0, [%[t0]]\n\t"
                  "sub %[q], %[q], %[ete]\n\t"
                  "ldr q8, [%[t0], %[w]]\n\t"
                  "add x26, x26, #16\n\t"
                  "ldr q21, [%[rp]]\n\t"
                  "stp d6, d7, [x8]\n\t"
                  "cmp x26, x30\n\t"
                  "ldr q26, [%[rp], #16]\n\t"
                  "add %[rp], %[rp], #32\n\t");
#undef SB_M2L_GROUPS
}

#include "asm/neon_block_mip2f.h"

#undef SB_M2L_A
#undef SB_M2L_STR
#undef SB_M2L_STR2
#undef SB_M2L_L2OFF
#undef SB_M2L_A_BODY
#undef SB_M2L_B
#undef SB_M2L_HEAD
#undef SB_M2L_LOADS
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
#undef SB_M2L_CXX

#endif  // __aarch64__

}  // namespace
}  // namespace sb::simd::detail
