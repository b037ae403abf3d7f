// asm/lit_span_a64.h: aarch64 only: one full 16-pixel run of the single-pass lit span kernel
// (contract: asm/lit_span.h) as one asm block, lit16_block, for asm/lit_span_neon.cpp.
// Internal: included by lit_span_neon.cpp only (anonymous namespace: internal linkage).
//
// The block takes power-of-two textures of at most 2^16 texels only. Each 8-pixel group
// takes its light from cell A (its first pixel's) and, when its last pixel's cell B
// differs (then a branch to the cells-B part), B for the lanes outside A. That is exact
// when every pixel is in A or B: the group's steps keep their sign (its first and last
// steps agree) and A, B are at most one column or one row apart, not both. Otherwise the
// block returns the group's flag and the caller draws the group again by the general path
// (about 1% of lit16's groups).
//
// NEON lanes: the 16 positions (16.16, second order) from the lane tables, U and V as
// 16-bit lanes, the texel index ((V + toff) & tmask) * tex_width + ((U + soff) & smask) in
// 16-bit lanes, and the light of a cell:
//   num = B^2 g00 + B fx (g10 - g00) + B fy (g01 - g00) + fx fy (g11 - g10 - g01 + g00),
// exactly the reference's numerator (the three differences fit 16 bits: |.| <= 2 * 0x3fff),
// by widening multiply-adds by lane. The 16 texel indices and the 16 (num >> S + 8) << 8
// are stored as two 16-bit arrays (the indices first, so the texel loads can start before
// the light is done); the core then loads each texel and colormap[texel + (num >> S + 8) << 8]
// and merges 8 bytes into a word. The core computes the cells' corners and the tests
// meanwhile.
//
// Generated: bench/mca_a53_lit/gen_lit16.py writes the block in dependency order,
// bench/mca_a53_lit/sched3.sh list-schedules its three parts for the Cortex-A53 model
// (bench/order_search.py may refine them), bench/mca_a53_lit/regalloc.py gives its core
// values registers again in that order (fewest callee-saved: x19-x26 for 26 values live at
// most), bench/to_inline.py writes it below (commands: bench/mca_a53_lit/README.md).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/lit_span.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
// Per mip: pixel numbers j, j (j - 1) / 2 (u32), B - 1 and log B (u16 lanes), -(S + 8)
// (u32 lanes: ushl by a negative count shifts right), then 16 + log B and S for the core;
// win: 514, 2056, B^2 (u16 lanes: win16_block's multipliers, asm/lit_span_a64win.h).
struct alignas(16) LitA64Tab {
  uint32_t lane[16], tri[16];
  uint16_t frac[8], logb[8];
  int32_t nshift[4];
  uint32_t l16, s;
  uint32_t pad[2];
  uint16_t win[8];
};
static_assert(offsetof(LitA64Tab, tri) == 64 && offsetof(LitA64Tab, frac) == 128 &&
                  offsetof(LitA64Tab, nshift) == 160 && offsetof(LitA64Tab, l16) == 176 &&
                  offsetof(LitA64Tab, win) == 192,
              "lit16_block's and win16_block's table offsets");

constexpr LitA64Tab lit_a64_tab(int mip) {
  LitA64Tab t{};
  const int lg = 4 - mip;
  for (int j = 0; j < 16; ++j) {
    t.lane[j] = uint32_t(j);
    t.tri[j] = uint32_t(j * (j - 1) / 2);
  }
  for (int j = 0; j < 8; ++j) {
    t.frac[j] = uint16_t((1 << lg) - 1);
    t.logb[j] = uint16_t(lg);
  }
  for (int j = 0; j < 4; ++j) t.nshift[j] = -(2 * lg + 8);
  t.l16 = uint32_t(16 + lg);
  t.s = uint32_t(2 * lg);
  t.win[0] = 514;
  t.win[1] = 2056;
  t.win[2] = uint16_t(1 << (2 * lg));
  return t;
}
alignas(16) constexpr LitA64Tab kLitA64Tab[4] = {lit_a64_tab(0), lit_a64_tab(1), lit_a64_tab(2), lit_a64_tab(3)};

// The block's stack frame: the 16 texel indices, the 16 (num >> S + 8) << 8, then
// soff_mod, toff_mod, tex_width - 1, tex_height - 1, tex_width (LitSpanSource::wrap16).
// The caller keeps the run's arguments after them (the block does not read them): read
// back only when a group is drawn again, so no register holds them across the block.
struct alignas(16) LitA64Frame {
  uint16_t ti[16], light[16];
  uint16_t wrap[8];
  uint8_t* dest;
  const LitSpanSource* src;
  uint32_t args[6];  // u, v, du, dv, ddu, ddv
};
static_assert(offsetof(LitA64Frame, wrap) == 64, "lit16_block's frame offsets");

// Draws dest[0..15] (see above); bit 0 / bit 1 of the result: pixels 0-7 / 8-15 must be
// drawn again. Power-of-two textures of at most 2^16 texels only.
// Always inlined (into run16, asm/lit_span_neon.cpp): a call passed four of its ten
// arguments on the stack and saved the callee-saved registers twice (caller and block).
__attribute__((always_inline)) inline unsigned lit16_block(uint8_t* dest, const LitSpanSource& src, LitA64Frame& fr,
                                                           const LitA64Tab& tab, uint32_t u32, uint32_t v32,
                                                           uint32_t du32, uint32_t dv32, uint32_t ddu32,
                                                           uint32_t ddv32) {
  // Every operand is read-write: bench/mca_a53_lit/regalloc.py reuses a dead input's
  // register as scratch (fewer callee-saved clobbers: each pair costs the function an stp
  // and an ldp). The operands are pinned to x0-x12: left free, GCC put some in x27 / x28
  // and saved those too. The pins follow run16's arguments (dest, n, src, u, v, du, dv,
  // ddu in x0-x7, ddv on the stack), so few moves precede the block. u..ddv stay 32-bit
  // (no zero-extending moves): the block reads their entry values as w registers only
  // (bench/mca_a53_lit/regalloc.py checks it) and writes the flags as w registers.
  register uint32_t u asm("x3") = u32;
  register uint32_t v asm("x4") = v32;
  register uint32_t du asm("x5") = du32;
  register uint32_t dv asm("x6") = dv32;
  register uint32_t ddu asm("x7") = ddu32;
  register uint32_t ddv asm("x1") = ddv32;
  register const uint8_t* tex asm("x8") = src.texels;
  register const uint8_t* cm asm("x9") = src.colormap;
  register const uint16_t* grid asm("x10") = src.grid;
  register uint64_t gw2 asm("x11") = uint64_t(src.grid_width) * 2;
  register uint8_t* dp asm("x0") = dest;
  register LitA64Frame* fp asm("x2") = &fr;
  register const LitA64Tab* tp asm("x12") = &tab;
  asm volatile(
      // BEGIN lit16_block
      "fmov s5, %w[du]\n\t"
      "dup v24.4s, %w[u]\n\t"
      "dup v25.4s, %w[u]\n\t"
      "dup v26.4s, %w[u]\n\t"
      "dup v28.4s, %w[v]\n\t"
      "dup v29.4s, %w[v]\n\t"
      "mov v5.s[1], %w[dv]\n\t"
      "ldp q16, q17, [%[tab]]\n\t"
      "add w13, %w[ddv], %w[ddv], lsl #1\n\t"
      "add x14, %[fr], #64\n\t"
      "add w15, %w[ddu], %w[ddu], lsl #1\n\t"
      "dup v31.4s, %w[v]\n\t"
      "dup v27.4s, %w[u]\n\t"
      "mov v5.s[2], %w[ddu]\n\t"
      "ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x14]\n\t"
      "dup v30.4s, %w[v]\n\t"
      "ldp q18, q19, [%[tab], #32]\n\t"
      "add w14, %w[du], w15\n\t"
      "add w16, %w[du], %w[ddu], lsl #3\n\t"
      "add w17, %w[dv], w13\n\t"
      "add w19, %w[du], w15, lsl #1\n\t"
      "mov v5.s[3], %w[ddv]\n\t"
      "ldp q20, q21, [%[tab], #64]\n\t"
      "add w20, w16, w15\n\t"
      "sub %w[ddu], w16, %w[ddu]\n\t"
      "lsl w21, w14, #3\n\t"
      "add w15, w16, w15, lsl #1\n\t"
      "add w22, %w[dv], %w[ddv], lsl #3\n\t"
      "sub w14, w21, w14\n\t"
      "add w21, %w[dv], w13, lsl #1\n\t"
      "mla v24.4s, v16.4s, v5.s[0]\n\t"
      "mla v28.4s, v16.4s, v5.s[1]\n\t"
      "mla v25.4s, v17.4s, v5.s[0]\n\t"
      "mla v29.4s, v17.4s, v5.s[1]\n\t"
      "mla v30.4s, v18.4s, v5.s[1]\n\t"
      "mla v27.4s, v19.4s, v5.s[0]\n\t"
      "mla v31.4s, v19.4s, v5.s[1]\n\t"
      "mla v24.4s, v20.4s, v5.s[2]\n\t"
      "mla v28.4s, v20.4s, v5.s[3]\n\t"
      "mla v25.4s, v21.4s, v5.s[2]\n\t"
      "mla v26.4s, v18.4s, v5.s[0]\n\t"
      "ldp q22, q23, [%[tab], #96]\n\t"
      "eor w15, w15, w16\n\t"
      "add w16, w22, w13\n\t"
      "lsl w23, w16, #3\n\t"
      "lsl w24, w17, #3\n\t"
      "add w14, %w[u], w14\n\t"
      "lsl w25, w20, #3\n\t"
      "sub w17, w24, w17\n\t"
      "sub w20, w25, w20\n\t"
      "add w13, w22, w13, lsl #1\n\t"
      "eor %w[dv], w21, %w[dv]\n\t"
      "sub %w[ddv], w22, %w[ddv]\n\t"
      "add %w[ddu], w14, %w[ddu]\n\t"
      "add w17, %w[v], w17\n\t"
      "add w20, %w[ddu], w20\n\t"
      "sub w16, w23, w16\n\t"
      "eor w13, w13, w22\n\t"
      "eor %w[du], w19, %w[du]\n\t"
      "add %w[ddv], w17, %w[ddv]\n\t"
      "orr w13, w15, w13\n\t"
      "ldp w15, w19, [%[tab], #176]\n\t"
      "eor w21, %w[v], w17\n\t"
      "mla v29.4s, v21.4s, v5.s[3]\n\t"
      "mla v26.4s, v22.4s, v5.s[2]\n\t"
      "uzp2 v6.8h, v24.8h, v25.8h\n\t"
      "mla v27.4s, v23.4s, v5.s[2]\n\t"
      "mla v30.4s, v22.4s, v5.s[3]\n\t"
      "mla v31.4s, v23.4s, v5.s[3]\n\t"
      "uzp2 v16.8h, v28.8h, v29.8h\n\t"
      "ldr q4, [%[fr], #64]\n\t"
      "orr %w[du], %w[du], %w[dv]\n\t"
      "add %w[dv], %w[ddv], w16\n\t"
      "lsr %w[v], %w[v], w15\n\t"
      "eor w16, %w[ddu], w20\n\t"
      "eor w22, %w[u], w14\n\t"
      "uzp2 v7.8h, v26.8h, v27.8h\n\t"
      "uzp2 v17.8h, v30.8h, v31.8h\n\t"
      "add v18.8h, v6.8h, v0.8h\n\t"
      "add v20.8h, v16.8h, v1.8h\n\t"
      "madd x23, %[v], %[gw2], %[grid]\n\t"
      "ldp q30, q31, [%[tab], #128]\n\t"
      "eor w24, %w[ddv], %w[dv]\n\t"
      "orr w21, w22, w21\n\t"
      "lsr w17, w17, w15\n\t"
      "lsr w14, w14, w15\n\t"
      "lsr %w[u], %w[u], w15\n\t"
      "add v19.8h, v7.8h, v0.8h\n\t"
      "add v21.8h, v17.8h, v1.8h\n\t"
      "and v22.16b, v18.16b, v2.16b\n\t"
      "and v20.16b, v20.16b, v3.16b\n\t"
      "and v18.16b, v6.16b, v30.16b\n\t"
      "and v23.16b, v19.16b, v2.16b\n\t"
      "and v21.16b, v21.16b, v3.16b\n\t"
      "and v19.16b, v16.16b, v30.16b\n\t"
      "mla v22.8h, v20.8h, v4.h[4]\n\t"
      "and v20.16b, v7.16b, v30.16b\n\t"
      "orr w16, w16, w24\n\t"
      "add x22, x23, %[u], lsl #1\n\t"
      "lsr w23, %w[dv], w15\n\t"
      "mla v23.8h, v21.8h, v4.h[4]\n\t"
      "mul v5.8h, v18.8h, v19.8h\n\t"
      "and v21.16b, v17.16b, v30.16b\n\t"
      "ldrh %w[dv], [x22, #2]\n\t"
      "ushl v19.8h, v19.8h, v31.8h\n\t"
      "ldrh w24, [x22]\n\t"
      "orr w16, w21, w16\n\t"
      "add x21, x22, %[gw2]\n\t"
      "lsr %w[ddv], %w[ddv], w15\n\t"
      "mul v30.8h, v20.8h, v21.8h\n\t"
      "ushl v21.8h, v21.8h, v31.8h\n\t"
      "ushl v20.8h, v20.8h, v31.8h\n\t"
      "ushl v18.8h, v18.8h, v31.8h\n\t"
      "ldrh w22, [x21, #2]\n\t"
      "lsr %w[ddu], %w[ddu], w15\n\t"
      "ldrh w21, [x21]\n\t"
      "mov x25, %[fr]\n\t"
      "lsr w16, w16, w15\n\t"
      "lsr w15, w20, w15\n\t"
      "ldr q31, [%[tab], #160]\n\t"
      "madd x20, %[ddv], %[gw2], %[grid]\n\t"
      "sub w21, w21, w24\n\t"
      "sub w22, w22, %w[dv]\n\t"
      "add x20, x20, %[ddu], lsl #1\n\t"
      "sub w26, %w[dv], w24\n\t"
      "lsl w24, w24, w19\n\t"
      "bfi w26, w21, #16, #16\n\t"
      "lsr %w[du], %w[du], #31\n\t"
      "lsr %w[dv], w13, #31\n\t"
      "ldrh w13, [x20]\n\t"
      "sub w21, w22, w21\n\t"
      "ldrh w22, [x20, #2]\n\t"
      "add x20, x20, %[gw2]\n\t"
      "dup v27.4s, w24\n\t"
      "dup v26.4s, w24\n\t"
      "ldrh w24, [x20, #2]\n\t"
      "ldrh w20, [x20]\n\t"
      "bfi x26, x21, #32, #16\n\t"
      "sub w21, w24, w22\n\t"
      "sub w20, w20, w13\n\t"
      "fmov d0, x26\n\t"
      "sub w21, w21, w20\n\t"
      "sub w22, w22, w13\n\t"
      "lsl w13, w13, w19\n\t"
      "bfi w22, w20, #16, #16\n\t"
      "bfi x22, x21, #32, #16\n\t"
      "dup v28.4s, w13\n\t"
      "fmov d2, x22\n\t"
      "smlal v26.4s, v18.4h, v0.h[0]\n\t"
      "smlal2 v27.4s, v18.8h, v0.h[0]\n\t"
      "dup v29.4s, w13\n\t"
      "smlal v28.4s, v20.4h, v2.h[0]\n\t"
      "smlal v26.4s, v19.4h, v0.h[1]\n\t"
      "smlal2 v27.4s, v19.8h, v0.h[1]\n\t"
      "smlal2 v29.4s, v20.8h, v2.h[0]\n\t"
      "smlal v28.4s, v21.4h, v2.h[1]\n\t"
      "smlal v26.4s, v5.4h, v0.h[2]\n\t"
      "smlal2 v27.4s, v5.8h, v0.h[2]\n\t"
      "smlal2 v29.4s, v21.8h, v2.h[1]\n\t"
      "smlal v28.4s, v30.4h, v2.h[2]\n\t"
      "ushl v26.4s, v26.4s, v31.4s\n\t"
      "ushl v27.4s, v27.4s, v31.4s\n\t"
      "smlal2 v29.4s, v30.8h, v2.h[2]\n\t"
      "ushl v28.4s, v28.4s, v31.4s\n\t"
      "uzp1 v26.8h, v26.8h, v27.8h\n\t"
      "ushl v29.4s, v29.4s, v31.4s\n\t"
      "uzp1 v27.8h, v28.8h, v29.8h\n\t"
      "st1 {v22.8h, v23.8h}, [x25], #32\n\t"
      "cbz w16, 1f\n\t"
      "madd x13, x17, %[gw2], %[grid]\n\t"
      "dup v0.8h, v6.h[0]\n\t"
      "dup v2.8h, v16.h[0]\n\t"
      "dup v4.8h, v7.h[0]\n\t"
      "madd %[grid], x23, %[gw2], %[grid]\n\t"
      "ldr q29, [%[tab], #128]\n\t"
      "add %[tab], x13, x14, lsl #1\n\t"
      "eor v0.16b, v0.16b, v6.16b\n\t"
      "eor v2.16b, v2.16b, v16.16b\n\t"
      "eor v4.16b, v4.16b, v7.16b\n\t"
      "ldrh w13, [%[tab]]\n\t"
      "ldrh w16, [%[tab], #2]\n\t"
      "add %[tab], %[tab], %[gw2]\n\t"
      "add %[grid], %[grid], x15, lsl #1\n\t"
      "orr v0.16b, v0.16b, v2.16b\n\t"
      "dup v2.8h, v17.h[0]\n\t"
      "ldrh w20, [%[tab], #2]\n\t"
      "ldrh %w[tab], [%[tab]]\n\t"
      "ldrh w21, [%[grid]]\n\t"
      "ldrh w22, [%[grid], #2]\n\t"
      "add %[grid], %[grid], %[gw2]\n\t"
      "cmhi v0.8h, v0.8h, v29.8h\n\t"
      "eor v2.16b, v2.16b, v17.16b\n\t"
      "ldrh %w[gw2], [%[grid], #2]\n\t"
      "ldrh %w[grid], [%[grid]]\n\t"
      "sub w20, w20, w16\n\t"
      "sub %w[tab], %w[tab], w13\n\t"
      "sub w16, w16, w13\n\t"
      "lsl w13, w13, w19\n\t"
      "sub w20, w20, %w[tab]\n\t"
      "sub %w[gw2], %w[gw2], w22\n\t"
      "bfi w16, %w[tab], #16, #16\n\t"
      "sub %w[u], w14, %w[u]\n\t"
      "sub %w[grid], %w[grid], w21\n\t"
      "sub %w[tab], w22, w21\n\t"
      "bfi x16, x20, #32, #16\n\t"
      "dup v22.4s, w13\n\t"
      "dup v23.4s, w13\n\t"
      "fmov d1, x16\n\t"
      "orr v4.16b, v4.16b, v2.16b\n\t"
      "add w13, %w[u], #1\n\t"
      "sub %w[gw2], %w[gw2], %w[grid]\n\t"
      "bfi %w[tab], %w[grid], #16, #16\n\t"
      "sub %w[v], w17, %w[v]\n\t"
      "lsl %w[grid], w21, w19\n\t"
      "smlal v22.4s, v18.4h, v1.h[0]\n\t"
      "smlal2 v23.4s, v18.8h, v1.h[0]\n\t"
      "dup v24.4s, %w[grid]\n\t"
      "dup v25.4s, %w[grid]\n\t"
      "cmhi v4.8h, v4.8h, v29.8h\n\t"
      "smlal v22.4s, v19.4h, v1.h[1]\n\t"
      "smlal2 v23.4s, v19.8h, v1.h[1]\n\t"
      "cmp w13, #2\n\t"
      "add %w[grid], %w[v], #1\n\t"
      "bfi %[tab], %[gw2], #32, #16\n\t"
      "sub %w[ddu], w15, %w[ddu]\n\t"
      "sub %w[ddv], w23, %w[ddv]\n\t"
      "smlal v22.4s, v5.4h, v1.h[2]\n\t"
      "fmov d3, %[tab]\n\t"
      "smlal2 v23.4s, v5.8h, v1.h[2]\n\t"
      "cset %w[gw2], hi\n\t"
      "cmp %w[grid], #2\n\t"
      "add %w[grid], %w[ddu], #1\n\t"
      "add %w[tab], %w[ddv], #1\n\t"
      "smlal v24.4s, v20.4h, v3.h[0]\n\t"
      "smlal2 v25.4s, v20.8h, v3.h[0]\n\t"
      "ushl v22.4s, v22.4s, v31.4s\n\t"
      "ushl v23.4s, v23.4s, v31.4s\n\t"
      "cinc %w[gw2], %w[gw2], hi\n\t"
      "cmp %w[u], #0\n\t"
      "smlal v24.4s, v21.4h, v3.h[1]\n\t"
      "smlal2 v25.4s, v21.8h, v3.h[1]\n\t"
      "uzp1 v22.8h, v22.8h, v23.8h\n\t"
      "ccmp %w[v], #0, #4, ne\n\t"
      "smlal v24.4s, v30.4h, v3.h[2]\n\t"
      "smlal2 v25.4s, v30.8h, v3.h[2]\n\t"
      "bit v26.16b, v22.16b, v0.16b\n\t"
      "cinc %w[u], %w[gw2], ne\n\t"
      "cmp %w[grid], #2\n\t"
      "ushl v24.4s, v24.4s, v31.4s\n\t"
      "ushl v25.4s, v25.4s, v31.4s\n\t"
      "cset %w[v], hi\n\t"
      "cmp %w[tab], #2\n\t"
      "orr %w[du], %w[du], %w[u]\n\t"
      "cinc %w[u], %w[v], hi\n\t"
      "cmp %w[ddu], #0\n\t"
      "uzp1 v24.8h, v24.8h, v25.8h\n\t"
      "ccmp %w[ddv], #0, #4, ne\n\t"
      "cinc %w[u], %w[u], ne\n\t"
      "bit v27.16b, v24.16b, v4.16b\n\t"
      "orr %w[dv], %w[dv], %w[u]\n\t"
      "1:\n\t"
      "shl v27.8h, v27.8h, #8\n\t"
      "shl v26.8h, v26.8h, #8\n\t"
      "ldr %[u], [x25, #-32]\n\t"
      "add %[v], %[fr], #32\n\t"
      "ldr %[ddu], [x25, #-24]\n\t"
      "ldr %[ddv], [x25, #-16]\n\t"
      "ldr %[grid], [x25, #-8]\n\t"
      "st1 {v26.8h, v27.8h}, [%[v]], #32\n\t"
      "and %w[gw2], %w[ddu], #0xffff\n\t"
      "and %w[fr], %w[u], #0xffff\n\t"
      "lsr %[tab], %[ddu], #48\n\t"
      "lsr w13, %w[u], #16\n\t"
      "lsr x14, %[u], #48\n\t"
      "ubfx %[u], %[u], #32, #16\n\t"
      "lsr w15, %w[ddu], #16\n\t"
      "ldrb w13, [%[tex], x13]\n\t"
      "ldrb %w[fr], [%[tex], %[fr]]\n\t"
      "ldr x16, [%[v], #-32]\n\t"
      "ldrb w14, [%[tex], x14]\n\t"
      "ldr x17, [%[v], #-24]\n\t"
      "ldrb w15, [%[tex], x15]\n\t"
      "ldrb %w[gw2], [%[tex], %[gw2]]\n\t"
      "add %w[fr], %w[fr], w16, uxth\n\t"
      "ldrb %w[u], [%[tex], %[u]]\n\t"
      "add x14, x14, x16, lsr #48\n\t"
      "add w13, w13, w16, lsr #16\n\t"
      "ubfx %[ddu], %[ddu], #32, #16\n\t"
      "ubfx x19, x17, #32, #16\n\t"
      "ubfx x16, x16, #32, #16\n\t"
      "ldrb %w[tab], [%[tex], %[tab]]\n\t"
      "add %w[u], %w[u], w16\n\t"
      "ldrb %w[ddu], [%[tex], %[ddu]]\n\t"
      "add %w[gw2], %w[gw2], w17, uxth\n\t"
      "ldrb w13, [%[cm], x13]\n\t"
      "add w15, w15, w17, lsr #16\n\t"
      "ldr x16, [%[v], #-8]\n\t"
      "and w20, %w[ddv], #0xffff\n\t"
      "ldrb %w[u], [%[cm], %[u]]\n\t"
      "ldr %[v], [%[v], #-16]\n\t"
      "add %w[ddu], %w[ddu], w19\n\t"
      "ldrb %w[fr], [%[cm], %[fr]]\n\t"
      "ldrb w14, [%[cm], x14]\n\t"
      "lsr x19, %[ddv], #48\n\t"
      "ldrb %w[gw2], [%[cm], %[gw2]]\n\t"
      "and w21, %w[grid], #0xffff\n\t"
      "ldrb %w[ddu], [%[cm], %[ddu]]\n\t"
      "orr %[fr], %[fr], x13, lsl #8\n\t"
      "ldrb w13, [%[cm], x15]\n\t"
      "orr %[u], %[u], x14, lsl #8\n\t"
      "ldrb w14, [%[tex], x20]\n\t"
      "add %[tab], %[tab], x17, lsr #48\n\t"
      "ldrb w15, [%[tex], x19]\n\t"
      "lsr w17, %w[ddv], #16\n\t"
      "lsr w19, %w[grid], #16\n\t"
      "lsr x20, %[grid], #48\n\t"
      "ubfx %[grid], %[grid], #32, #16\n\t"
      "ubfx %[ddv], %[ddv], #32, #16\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "orr %[gw2], %[gw2], x13, lsl #8\n\t"
      "ldrb w13, [%[tex], x17]\n\t"
      "ubfx x17, %[v], #32, #16\n\t"
      "ldrb w21, [%[tex], x21]\n\t"
      "orr %[ddu], %[ddu], %[tab], lsl #8\n\t"
      "ldrb %w[tab], [%[tex], x19]\n\t"
      "add w13, w13, %w[v], lsr #16\n\t"
      "ldrb %w[ddv], [%[tex], %[ddv]]\n\t"
      "add w14, w14, %w[v], uxth\n\t"
      "ldrb %w[grid], [%[tex], %[grid]]\n\t"
      "add %[v], x15, %[v], lsr #48\n\t"
      "add w15, w21, w16, uxth\n\t"
      "ubfx x19, x16, #32, #16\n\t"
      "ldrb %w[tex], [%[tex], x20]\n\t"
      "add %w[ddv], %w[ddv], w17\n\t"
      "ldrb w13, [%[cm], x13]\n\t"
      "add %w[tab], %w[tab], w16, lsr #16\n\t"
      "ldrb w14, [%[cm], x14]\n\t"
      "add %w[grid], %w[grid], w19\n\t"
      "ldrb %w[v], [%[cm], %[v]]\n\t"
      "ldrb w15, [%[cm], x15]\n\t"
      "add %[tex], %[tex], x16, lsr #48\n\t"
      "ldrb %w[ddv], [%[cm], %[ddv]]\n\t"
      "orr x13, x14, x13, lsl #8\n\t"
      "ldrb %w[grid], [%[cm], %[grid]]\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "orr %[u], %[fr], %[u], lsl #16\n\t"
      "ldrb %w[tex], [%[cm], %[tex]]\n\t"
      "orr %[ddu], %[gw2], %[ddu], lsl #16\n\t"
      "orr %[v], %[ddv], %[v], lsl #8\n\t"
      "orr %[ddv], %[grid], %[tex], lsl #8\n\t"
      "orr %[u], %[u], %[ddu], lsl #32\n\t"
      "orr %[ddu], x15, %[tab], lsl #8\n\t"
      "orr %[v], x13, %[v], lsl #16\n\t"
      "orr %[ddu], %[ddu], %[ddv], lsl #16\n\t"
      "orr %[v], %[v], %[ddu], lsl #32\n\t"
      "stp %[u], %[v], [%[dest]]"
      // END lit16_block
      : [u] "+r"(u), [v] "+r"(v), [du] "+r"(du), [dv] "+r"(dv), [ddu] "+r"(ddu), [ddv] "+r"(ddv), [tab] "+r"(tp),
        [tex] "+r"(tex), [cm] "+r"(cm), [grid] "+r"(grid), [gw2] "+r"(gw2), [dest] "+r"(dp), [fr] "+r"(fp)
      :
      : "x13", "x14", "x15", "x16", "x17", "x19", "x20", "x21", "x22", "x23", "x24", "x25", "x26", "v0",
        "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24",
        "v25", "v26", "v27", "v28", "v29", "v30", "v31", "cc", "memory");
  return (du != 0 ? 1u : 0u) | (dv != 0 ? 2u : 0u);
}
#endif

}  // namespace
}  // namespace sb::simd
