// asm/lit_span_a64.h: aarch64 only: one full 16-pixel run of the single-pass lit span kernel
// (contract: asm/lit_span.h) as one asm block, lit16_block, for asm/lit_span_neon.cpp.
// Internal: included by lit_span_neon.cpp only (anonymous namespace: internal linkage).
//
// The block takes power-of-two textures of at most 2^16 texels only and assumes each 8-pixel group of the run lies
// in one light-grid cell: it draws the 16 bytes with that cell's light and returns nonzero
// when the assumption may not hold (a group's first and last pixels in different cells, or
// a step that changes sign within a group, so the ends do not bound the group); the caller
// then draws the run again by the general path. With a pixel stepping about a texel or
// less, a 16-texel cell (mip 0) holds most groups.
//
// NEON lanes: the 16 positions (16.16, second order) from the lane tables, U and V as
// 16-bit lanes, the texel index ((V + toff) & tmask) * tex_width + ((U + soff) & smask) in
// 16-bit lanes, and the light of the group's cell:
//   num = B^2 g00 + B fx (g10 - g00) + B fy (g01 - g00) + fx fy (g11 - g10 - g01 + g00),
// exactly the reference's numerator (the three differences fit 16 bits: |.| <= 2 * 0x3fff),
// by widening multiply-adds by lane. The 16 texel indices and the 16 (num >> S + 8) << 8
// are stored as two 16-bit arrays (the indices first, so the texel loads can start before
// the light is done); the core then loads each texel and colormap[texel + (num >> S + 8) << 8]
// and merges 8 bytes into a word. The core computes
// the two cells' corners and the one-cell tests meanwhile.
//
// Generated: bench/mca_a53_lit/gen_lit16.py writes the block in dependency order,
// bench/order_search.py orders it for the Cortex-A53 model, bench/to_inline.py writes it
// below (commands: bench/mca_a53_lit/README.md).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/lit_span.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
// Per mip: pixel numbers j, j (j - 1) / 2 (u32), B - 1 and log B (u16 lanes), -(S + 8)
// (u32 lanes: ushl by a negative count shifts right), then 16 + log B and S for the core.
struct alignas(16) LitA64Tab {
  uint32_t lane[16], tri[16];
  uint16_t frac[8], logb[8];
  int32_t nshift[4];
  uint32_t l16, s;
};
static_assert(offsetof(LitA64Tab, tri) == 64 && offsetof(LitA64Tab, frac) == 128 &&
                  offsetof(LitA64Tab, nshift) == 160 && offsetof(LitA64Tab, l16) == 176,
              "lit16_block's table offsets");

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
  return t;
}
alignas(16) constexpr LitA64Tab kLitA64Tab[4] = {lit_a64_tab(0), lit_a64_tab(1), lit_a64_tab(2), lit_a64_tab(3)};

// The block's stack frame: the 16 texel indices, the 16 (num >> S + 8) << 8, then
// soff_mod, toff_mod, tex_width - 1, tex_height - 1, tex_width (LitSpanSource::wrap16).
struct alignas(16) LitA64Frame {
  uint16_t ti[16], light[16];
  uint16_t wrap[8];
};
static_assert(offsetof(LitA64Frame, wrap) == 64, "lit16_block's frame offsets");

// Draws dest[0..15] (see above); bit 0 / bit 1 of the result: pixels 0-7 / 8-15 must be
// drawn again. Power-of-two textures of at most 2^16 texels only.
inline unsigned lit16_block(uint8_t* dest, const LitSpanSource& src, LitA64Frame& fr, const LitA64Tab& tab,
                            uint32_t u32, uint32_t v32, uint32_t du32, uint32_t dv32, uint32_t ddu32,
                            uint32_t ddv32) {
  uint64_t u = u32, v = v32, du = du32, dv = dv32, ddu = ddu32, ddv = ddv32;
  const uint64_t gw2 = uint64_t(src.grid_width) * 2;
  const LitA64Tab* tp = &tab;
  asm volatile(
      // BEGIN lit16_block
      "fmov s5, %w[du]\n\t"
      "dup v24.4s, %w[u]\n\t"
      "dup v28.4s, %w[v]\n\t"
      "dup v25.4s, %w[u]\n\t"
      "dup v29.4s, %w[v]\n\t"
      "dup v26.4s, %w[u]\n\t"
      "mov v5.s[1], %w[dv]\n\t"
      "dup v30.4s, %w[v]\n\t"
      "dup v27.4s, %w[u]\n\t"
      "dup v31.4s, %w[v]\n\t"
      "ldp q16, q17, [%[tab]]\n\t"
      "mov v5.s[2], %w[ddu]\n\t"
      "ldp q18, q19, [%[tab], #32]\n\t"
      "ldp q20, q21, [%[tab], #64]\n\t"
      "ldp q22, q23, [%[tab], #96]\n\t"
      "add x13, %[fr], #64\n\t"
      "ldr q4, [%[fr], #64]\n\t"
      "mov v5.s[3], %w[ddv]\n\t"
      "ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [x13]\n\t"
      "ldp w15, w16, [%[tab], #176]\n\t"
      "add w17, %w[ddu], %w[ddu], lsl #1\n\t"
      "add w22, %w[du], %w[ddu], lsl #3\n\t"
      "add w27, %w[ddv], %w[ddv], lsl #1\n\t"
      "mov x14, %[fr]\n\t"
      "mla v24.4s, v16.4s, v5.s[0]\n\t"
      "mla v28.4s, v16.4s, v5.s[1]\n\t"
      "mla v25.4s, v17.4s, v5.s[0]\n\t"
      "mla v29.4s, v17.4s, v5.s[1]\n\t"
      "mla v26.4s, v18.4s, v5.s[0]\n\t"
      "mla v30.4s, v18.4s, v5.s[1]\n\t"
      "mla v27.4s, v19.4s, v5.s[0]\n\t"
      "mla v31.4s, v19.4s, v5.s[1]\n\t"
      "mla v24.4s, v20.4s, v5.s[2]\n\t"
      "mla v28.4s, v20.4s, v5.s[3]\n\t"
      "mla v25.4s, v21.4s, v5.s[2]\n\t"
      "mla v29.4s, v21.4s, v5.s[3]\n\t"
      "mla v26.4s, v22.4s, v5.s[2]\n\t"
      "mla v30.4s, v22.4s, v5.s[3]\n\t"
      "mla v27.4s, v23.4s, v5.s[2]\n\t"
      "mla v31.4s, v23.4s, v5.s[3]\n\t"
      "uzp2 v6.8h, v24.8h, v25.8h\n\t"
      "uzp2 v16.8h, v28.8h, v29.8h\n\t"
      "uzp2 v7.8h, v26.8h, v27.8h\n\t"
      "uzp2 v17.8h, v30.8h, v31.8h\n\t"
      "dup v18.8h, v6.h[0]\n\t"
      "dup v19.8h, v16.h[0]\n\t"
      "ldp q30, q31, [%[tab], #128]\n\t"
      "dup v20.8h, v7.h[0]\n\t"
      "dup v21.8h, v17.h[0]\n\t"
      "eor v18.16b, v18.16b, v6.16b\n\t"
      "eor v19.16b, v19.16b, v16.16b\n\t"
      "eor v20.16b, v20.16b, v7.16b\n\t"
      "eor v21.16b, v21.16b, v17.16b\n\t"
      "orr v18.16b, v18.16b, v19.16b\n\t"
      "add v19.8h, v7.8h, v0.8h\n\t"
      "orr v20.16b, v20.16b, v21.16b\n\t"
      "add v21.8h, v17.8h, v1.8h\n\t"
      "cmhi v24.8h, v18.8h, v30.8h\n\t"
      "add v18.8h, v6.8h, v0.8h\n\t"
      "and v23.16b, v19.16b, v2.16b\n\t"
      "and v19.16b, v16.16b, v30.16b\n\t"
      "cmhi v25.8h, v20.8h, v30.8h\n\t"
      "add v20.8h, v16.8h, v1.8h\n\t"
      "and v21.16b, v21.16b, v3.16b\n\t"
      "and v22.16b, v18.16b, v2.16b\n\t"
      "and v18.16b, v6.16b, v30.16b\n\t"
      "and v20.16b, v20.16b, v3.16b\n\t"
      "mla v23.8h, v21.8h, v4.h[4]\n\t"
      "and v21.16b, v17.16b, v30.16b\n\t"
      "mul v5.8h, v18.8h, v19.8h\n\t"
      "ushl v18.8h, v18.8h, v31.8h\n\t"
      "ushl v19.8h, v19.8h, v31.8h\n\t"
      "mla v22.8h, v20.8h, v4.h[4]\n\t"
      "and v20.16b, v7.16b, v30.16b\n\t"
      "add w20, %w[du], w17\n\t"
      "add w24, w22, w17\n\t"
      "add w26, w22, w17, lsl #1\n\t"
      "sub w23, w22, %w[ddu]\n\t"
      "add w19, %w[du], w17, lsl #1\n\t"
      "add w28, %w[dv], w27, lsl #1\n\t"
      "mul v30.8h, v20.8h, v21.8h\n\t"
      "ushl v20.8h, v20.8h, v31.8h\n\t"
      "ushl v21.8h, v21.8h, v31.8h\n\t"
      "ldr q31, [%[tab], #160]\n\t"
      "st1 {v22.8h, v23.8h}, [x14], #32\n\t"
      "eor w26, w26, w22\n\t"
      "add w13, %w[dv], w27\n\t"
      "lsl w21, w20, #3\n\t"
      "lsl w25, w24, #3\n\t"
      "eor w19, w19, %w[du]\n\t"
      "eor w28, w28, %w[dv]\n\t"
      "sub w21, w21, w20\n\t"
      "sub w25, w25, w24\n\t"
      "add w20, %w[dv], %w[ddv], lsl #3\n\t"
      "lsl %w[tab], w13, #3\n\t"
      "add w21, %w[u], w21\n\t"
      "add w24, w20, w27\n\t"
      "add w22, w20, w27, lsl #1\n\t"
      "sub %w[ddu], w20, %w[ddv]\n\t"
      "sub %w[tab], %w[tab], w13\n\t"
      "lsr w27, %w[v], w15\n\t"
      "orr w13, w19, w28\n\t"
      "lsl w17, w24, #3\n\t"
      "eor w22, w22, w20\n\t"
      "madd x20, x27, %[gw2], %[grid]\n\t"
      "sub w17, w17, w24\n\t"
      "add %w[tab], %w[v], %w[tab]\n\t"
      "lsr w24, %w[u], w15\n\t"
      "orr %w[ddv], w26, w22\n\t"
      "lsr %w[u], w21, w15\n\t"
      "add w23, w21, w23\n\t"
      "add x20, x20, x24, lsl #1\n\t"
      "add %w[ddu], %w[tab], %w[ddu]\n\t"
      "lsr %w[v], %w[tab], w15\n\t"
      "sub w21, %w[u], w24\n\t"
      "add w25, w23, w25\n\t"
      "ldrh w19, [x20]\n\t"
      "ldrh w28, [x20, #2]\n\t"
      "add x20, x20, %[gw2]\n\t"
      "sub %w[tab], %w[v], w27\n\t"
      "add w17, %w[ddu], w17\n\t"
      "ldrh w22, [x20, #2]\n\t"
      "ldrh w26, [x20]\n\t"
      "madd x20, %[v], %[gw2], %[grid]\n\t"
      "sub w22, w22, w28\n\t"
      "sub w26, w26, w19\n\t"
      "sub w28, w28, w19\n\t"
      "add x20, x20, %[u], lsl #1\n\t"
      "lsl w19, w19, w16\n\t"
      "sub w22, w22, w26\n\t"
      "bfi w28, w26, #16, #16\n\t"
      "ldrh w26, [x20]\n\t"
      "dup v16.4s, w19\n\t"
      "dup v17.4s, w19\n\t"
      "bfi x28, x22, #32, #16\n\t"
      "ldrh w22, [x20, #2]\n\t"
      "add x20, x20, %[gw2]\n\t"
      "fmov d6, x28\n\t"
      "ldrh w19, [x20, #2]\n\t"
      "ldrh w28, [x20]\n\t"
      "add w20, w21, #1\n\t"
      "sub w19, w19, w22\n\t"
      "sub w28, w28, w26\n\t"
      "sub w22, w22, w26\n\t"
      "cmp w20, #2\n\t"
      "lsl w26, w26, w16\n\t"
      "lsr w20, w25, w15\n\t"
      "sub w19, w19, w28\n\t"
      "smlal v16.4s, v18.4h, v6.h[0]\n\t"
      "dup v26.4s, w26\n\t"
      "dup v27.4s, w26\n\t"
      "smlal2 v17.4s, v18.8h, v6.h[0]\n\t"
      "cset %w[du], hi\n\t"
      "smlal v16.4s, v19.4h, v6.h[1]\n\t"
      "smlal2 v17.4s, v19.8h, v6.h[1]\n\t"
      "smlal v16.4s, v5.4h, v6.h[2]\n\t"
      "smlal2 v17.4s, v5.8h, v6.h[2]\n\t"
      "ushl v16.4s, v16.4s, v31.4s\n\t"
      "ushl v17.4s, v17.4s, v31.4s\n\t"
      "bfi w22, w28, #16, #16\n\t"
      "add w28, %w[tab], #1\n\t"
      "bfi x22, x19, #32, #16\n\t"
      "lsr w19, w23, w15\n\t"
      "cmp w28, #2\n\t"
      "uzp1 v16.8h, v16.8h, v17.8h\n\t"
      "fmov d0, x22\n\t"
      "cinc %w[du], %w[du], hi\n\t"
      "cmp w21, #0\n\t"
      "lsr w22, %w[ddu], w15\n\t"
      "lsr w28, w17, w15\n\t"
      "ldp w25, w17, [x14, #-32]\n\t"
      "ccmp %w[tab], #0, #4, ne\n\t"
      "madd x26, x22, %[gw2], %[grid]\n\t"
      "madd x21, x28, %[gw2], %[grid]\n\t"
      "smlal v26.4s, v18.4h, v0.h[0]\n\t"
      "smlal2 v27.4s, v18.8h, v0.h[0]\n\t"
      "cinc %w[du], %w[du], ne\n\t"
      "add x26, x26, x19, lsl #1\n\t"
      "add x21, x21, x20, lsl #1\n\t"
      "smlal v26.4s, v19.4h, v0.h[1]\n\t"
      "smlal2 v27.4s, v19.8h, v0.h[1]\n\t"
      "ldrh %w[u], [x26]\n\t"
      "ldrh w24, [x26, #2]\n\t"
      "orr %w[du], %w[du], w13, lsr #31\n\t"
      "ldrh %w[tab], [x21]\n\t"
      "ldrh w13, [x21, #2]\n\t"
      "add x26, x26, %[gw2]\n\t"
      "add x21, x21, %[gw2]\n\t"
      "smlal v26.4s, v5.4h, v0.h[2]\n\t"
      "smlal2 v27.4s, v5.8h, v0.h[2]\n\t"
      "ldrh w27, [x26, #2]\n\t"
      "ldrh %w[ddu], [x21, #2]\n\t"
      "ldrh %w[v], [x26]\n\t"
      "ldrh w23, [x21]\n\t"
      "sub w26, w20, w19\n\t"
      "and w19, w17, #0xffff\n\t"
      "ushl v26.4s, v26.4s, v31.4s\n\t"
      "ushl v27.4s, v27.4s, v31.4s\n\t"
      "ldrb w19, [%[tex], x19]\n\t"
      "sub w27, w27, w24\n\t"
      "sub %w[ddu], %w[ddu], w13\n\t"
      "sub %w[v], %w[v], %w[u]\n\t"
      "sub w23, w23, %w[tab]\n\t"
      "sub w24, w24, %w[u]\n\t"
      "sub w13, w13, %w[tab]\n\t"
      "lsl %w[u], %w[u], w16\n\t"
      "lsl %w[tab], %w[tab], w16\n\t"
      "sub w27, w27, %w[v]\n\t"
      "sub %w[ddu], %w[ddu], w23\n\t"
      "bfi w24, %w[v], #16, #16\n\t"
      "dup v1.4s, %w[u]\n\t"
      "dup v3.4s, %w[u]\n\t"
      "dup v28.4s, %w[tab]\n\t"
      "dup v29.4s, %w[tab]\n\t"
      "uzp1 v26.8h, v26.8h, v27.8h\n\t"
      "sub %w[v], w28, w22\n\t"
      "add %[u], %[fr], #32\n\t"
      "bfi w13, w23, #16, #16\n\t"
      "ldp w16, w23, [x14, #-24]\n\t"
      "and %w[tab], w25, #0xffff\n\t"
      "bfi x24, x27, #32, #16\n\t"
      "add w27, w26, #1\n\t"
      "bfi x13, %[ddu], #32, #16\n\t"
      "bsl v24.16b, v26.16b, v16.16b\n\t"
      "fmov d7, x24\n\t"
      "fmov d2, x13\n\t"
      "ldrb %w[tab], [%[tex], %[tab]]\n\t"
      "cmp w27, #2\n\t"
      "add w24, %w[v], #1\n\t"
      "shl v24.8h, v24.8h, #8\n\t"
      "smlal v1.4s, v20.4h, v7.h[0]\n\t"
      "smlal2 v3.4s, v20.8h, v7.h[0]\n\t"
      "smlal v28.4s, v20.4h, v2.h[0]\n\t"
      "smlal2 v29.4s, v20.8h, v2.h[0]\n\t"
      "smlal v1.4s, v21.4h, v7.h[1]\n\t"
      "smlal2 v3.4s, v21.8h, v7.h[1]\n\t"
      "smlal v28.4s, v21.4h, v2.h[1]\n\t"
      "smlal2 v29.4s, v21.8h, v2.h[1]\n\t"
      "smlal v1.4s, v30.4h, v7.h[2]\n\t"
      "smlal2 v3.4s, v30.8h, v7.h[2]\n\t"
      "smlal v28.4s, v30.4h, v2.h[2]\n\t"
      "smlal2 v29.4s, v30.8h, v2.h[2]\n\t"
      "ushl v1.4s, v1.4s, v31.4s\n\t"
      "ushl v3.4s, v3.4s, v31.4s\n\t"
      "ushl v28.4s, v28.4s, v31.4s\n\t"
      "ushl v29.4s, v29.4s, v31.4s\n\t"
      "cset %w[dv], hi\n\t"
      "cmp w24, #2\n\t"
      "uzp1 v1.8h, v1.8h, v3.8h\n\t"
      "uzp1 v28.8h, v28.8h, v29.8h\n\t"
      "cinc %w[dv], %w[dv], hi\n\t"
      "cmp w26, #0\n\t"
      "lsr w20, w25, #16\n\t"
      "lsr w28, w17, #16\n\t"
      "and w22, w16, #0xffff\n\t"
      "and w24, w23, #0xffff\n\t"
      "bsl v25.16b, v28.16b, v1.16b\n\t"
      "ldrb w20, [%[tex], x20]\n\t"
      "ldrb w28, [%[tex], x28]\n\t"
      "ldrb w22, [%[tex], x22]\n\t"
      "ldrb w24, [%[tex], x24]\n\t"
      "shl v25.8h, v25.8h, #8\n\t"
      "ccmp %w[v], #0, #4, ne\n\t"
      "lsr w27, w16, #16\n\t"
      "lsr w26, w23, #16\n\t"
      "ldp w16, w23, [x14, #-8]\n\t"
      "st1 {v24.8h, v25.8h}, [%[u]], #32\n\t"
      "ldrb w27, [%[tex], x27]\n\t"
      "ldrb w26, [%[tex], x26]\n\t"
      "cinc %w[dv], %w[dv], ne\n\t"
      "ldp w15, w21, [%[u], #-32]\n\t"
      "ldp %w[ddu], w13, [%[u], #-24]\n\t"
      "orr %w[dv], %w[dv], %w[ddv], lsr #31\n\t"
      "ldp %w[v], %w[ddv], [x14, #-16]\n\t"
      "ldp w25, w17, [%[u], #-16]\n\t"
      "add %w[tab], %w[tab], w15, uxth\n\t"
      "add w20, w20, w15, lsr #16\n\t"
      "add w19, w19, w21, uxth\n\t"
      "add w28, w28, w21, lsr #16\n\t"
      "add w22, w22, %w[ddu], uxth\n\t"
      "add w27, w27, %w[ddu], lsr #16\n\t"
      "add w24, w24, w13, uxth\n\t"
      "add w26, w26, w13, lsr #16\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "ldrb w20, [%[cm], x20]\n\t"
      "ldrb w19, [%[cm], x19]\n\t"
      "ldrb w28, [%[cm], x28]\n\t"
      "ldrb w22, [%[cm], x22]\n\t"
      "ldrb w27, [%[cm], x27]\n\t"
      "ldrb w24, [%[cm], x24]\n\t"
      "ldrb w26, [%[cm], x26]\n\t"
      "orr %[tab], %[tab], x20, lsl #8\n\t"
      "orr x19, x19, x28, lsl #8\n\t"
      "orr x22, x22, x27, lsl #8\n\t"
      "and %w[ddu], %w[v], #0xffff\n\t"
      "and w20, %w[ddv], #0xffff\n\t"
      "and w27, w16, #0xffff\n\t"
      "orr x24, x24, x26, lsl #8\n\t"
      "orr %[tab], %[tab], x19, lsl #16\n\t"
      "and w19, w23, #0xffff\n\t"
      "ldp w15, w21, [%[u], #-8]\n\t"
      "ldrb %w[ddu], [%[tex], %[ddu]]\n\t"
      "orr x22, x22, x24, lsl #16\n\t"
      "ldrb w20, [%[tex], x20]\n\t"
      "ldrb w27, [%[tex], x27]\n\t"
      "ldrb w19, [%[tex], x19]\n\t"
      "add %w[ddu], %w[ddu], w25, uxth\n\t"
      "orr %[tab], %[tab], x22, lsl #32\n\t"
      "lsr w13, %w[v], #16\n\t"
      "lsr w28, %w[ddv], #16\n\t"
      "lsr w26, w16, #16\n\t"
      "lsr w24, w23, #16\n\t"
      "ldrb w13, [%[tex], x13]\n\t"
      "ldrb w28, [%[tex], x28]\n\t"
      "ldrb w26, [%[tex], x26]\n\t"
      "ldrb w24, [%[tex], x24]\n\t"
      "add w13, w13, w25, lsr #16\n\t"
      "add w20, w20, w17, uxth\n\t"
      "add w28, w28, w17, lsr #16\n\t"
      "add w27, w27, w15, uxth\n\t"
      "add w26, w26, w15, lsr #16\n\t"
      "add w19, w19, w21, uxth\n\t"
      "add w24, w24, w21, lsr #16\n\t"
      "ldrb %w[ddu], [%[cm], %[ddu]]\n\t"
      "ldrb w13, [%[cm], x13]\n\t"
      "ldrb w20, [%[cm], x20]\n\t"
      "ldrb w28, [%[cm], x28]\n\t"
      "ldrb w27, [%[cm], x27]\n\t"
      "ldrb w26, [%[cm], x26]\n\t"
      "ldrb w19, [%[cm], x19]\n\t"
      "ldrb w24, [%[cm], x24]\n\t"
      "orr %[ddu], %[ddu], x13, lsl #8\n\t"
      "orr x20, x20, x28, lsl #8\n\t"
      "orr x27, x27, x26, lsl #8\n\t"
      "orr x19, x19, x24, lsl #8\n\t"
      "orr %[ddu], %[ddu], x20, lsl #16\n\t"
      "orr x27, x27, x19, lsl #16\n\t"
      "orr %[ddu], %[ddu], x27, lsl #32\n\t"
      "stp %[tab], %[ddu], [%[dest]]"
      // END lit16_block
      : [u] "+r"(u), [v] "+r"(v), [du] "+r"(du), [dv] "+r"(dv), [ddu] "+r"(ddu), [ddv] "+r"(ddv), [tab] "+r"(tp)
      : [tex] "r"(src.texels), [cm] "r"(src.colormap), [grid] "r"(src.grid), [gw2] "r"(gw2), [dest] "r"(dest),
        [fr] "r"(&fr)
      : "x13", "x14", "x15", "x16", "x17", "x19", "x20", "x21", "x22", "x23", "x24", "x25", "x26", "x27", "x28", "v0",
        "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24",
        "v25", "v26", "v27", "v28", "v29", "v30", "v31", "cc", "memory");
  return (du != 0 ? 1u : 0u) | (dv != 0 ? 2u : 0u);
}
#endif

}  // namespace
}  // namespace sb::simd
