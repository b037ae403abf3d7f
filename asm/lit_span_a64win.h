// asm/lit_span_a64win.h: aarch64 only: one full 16-pixel run of the single-pass lit span
// kernel (contract: asm/lit_span.h) whose 8-pixel groups cross several light cells (mips
// above 0 at about a texel a pixel: the runs lit16_block leaves to the per-pixel kernel), as
// one asm block, win16_block. Internal: included by lit_span_neon.cpp only (anonymous
// namespace: internal linkage). Power-of-two textures of at most 2^16 texels only.
//
// Each group takes its light from a window of 3 x 3 cells, 4 x 4 grid entries from
// (ox, oy) = (min gx, min gy) of its lanes, clamped to (limx, limy) = ((width - 1) / B - 2,
// (height - 1) / B - 2) so every entry read is inside the grid the contract gives (its last
// column / row a pixel reads is (width - 1) / B + 1 / (height - 1) / B + 1). The ranges
// come from pairwise byte maxima over [gx | gy] and their complements (cells < 256: the
// caller checks), so the test max gx - ox <= 2, max gy - oy <= 2 is exact whatever the
// steps. The window's four rows (8 bytes each) are a two-register tbl table; each lane's
// corners come by tbl on byte indices 2 l | (2 l + 1) << 8 (l = 4 (gy - oy) + gx - ox; g10,
// g01, g11 at + 0x0202, + 0x0808, + 0x0a0a), and
//   num = B^2 g00 + B fx (g10 - g00) + B fy (g01 - g00) + fx fy (g11 - g10 - g01 + g00)
// is the reference's numerator exactly (the differences fit 16 bits: |.| <= 2 * 0x3fff),
// by a widening multiply and widening multiply-adds per lane. The positions, texel indices,
// weights, the light's shift and the core's pixel loads are lit16_block's (asm/lit_span_a64.h:
// the same frame and table). A group that spans more than 3 cells a way flags the run, which
// the caller then draws again by the per-pixel kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "asm/lit_span.h"
#include "asm/lit_span_a64.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)

// Whether a run's 8-pixel groups most likely span at most 3 cells each way (the window
// kernel's case): 8 (|d| + 16 |dd|) < 2.5 B texels along u and along v. A guess only
// (the kernel checks every group): beyond it most groups would take the per-pixel formula.
inline bool window_steps(const LitSpanSource& src, uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  auto mag = [](uint32_t x) { return uint64_t(x ^ uint32_t(int32_t(x) >> 31)); };
  const uint64_t lim = uint64_t(0x50000) >> src.mip;
  return mag(du) + 16 * mag(ddu) < lim && mag(dv) + 16 * mag(ddv) < lim;
}

// Draws dest[0..15] of a run whose groups take their light from a 3 x 3-cell window each
// (see above); nonzero: a group's cells are not all in its window (dest is written anyway:
// the caller draws the run again). Power-of-two textures of at most 2^16 texels only;
// limx = (width - 1) / B - 2 and limy = (height - 1) / B - 2 in 0..253.
// Generated: bench/mca_a53_lit/gen_win16.py writes the block in dependency order,
// bench/mca_a53_persp/list_sched.py orders it for the Cortex-A53 model, bench/to_inline.py
// writes it below (commands: bench/mca_a53_lit/README.md, "Runs across several cells").
__attribute__((always_inline)) inline unsigned win16_block(uint8_t* dest, const LitSpanSource& src, LitA64Frame& fr,
                                                           const LitA64Tab& tab, uint32_t u, uint32_t v, uint32_t du,
                                                           uint32_t dv, uint32_t ddu, uint32_t ddv, uint64_t limx,
                                                           uint64_t limy) {
  const uint8_t* tex = src.texels;
  const uint8_t* cm = src.colormap;
  const uint16_t* grid = src.grid;
  uint64_t gw2 = uint64_t(src.grid_width) * 2;
  uint8_t* dp = dest;
  LitA64Frame* fp = &fr;
  const LitA64Tab* tp = &tab;
  asm volatile(
      // BEGIN win16_block
      "fmov s5, %w[du]\n\t"
      "dup v30.4s, %w[v]\n\t"
      "dup v31.4s, %w[v]\n\t"
      "dup v28.4s, %w[v]\n\t"
      "dup v29.4s, %w[v]\n\t"
      "dup v25.4s, %w[u]\n\t"
      "mov v5.s[1], %w[dv]\n\t"
      "dup v24.4s, %w[u]\n\t"
      "dup v26.4s, %w[u]\n\t"
      "dup v27.4s, %w[u]\n\t"
      "ldp q18, q19, [%[tab], #32]\n\t"
      "mov v5.s[2], %w[ddu]\n\t"
      "ldp q16, q17, [%[tab]]\n\t"
      "ldp q22, q23, [%[tab], #96]\n\t"
      "ldp q20, q21, [%[tab], #64]\n\t"
      "add %[u], %[fr], #64\n\t"
      "ldr q4, [%[fr], #64]\n\t"
      "mov v5.s[3], %w[ddv]\n\t"
      "ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [%[u]]\n\t"
      "ldr %w[u], [%[tab], #180]\n\t"
      "mov %w[v], #1\n\t"
      "mov %w[du], #0x0202\n\t"
      "mov %[dv], %[fr]\n\t"
      "mov %w[ddu], #514\n\t"
      "mla v30.4s, v18.4s, v5.s[1]\n\t"
      "mla v31.4s, v19.4s, v5.s[1]\n\t"
      "mla v28.4s, v16.4s, v5.s[1]\n\t"
      "mla v29.4s, v17.4s, v5.s[1]\n\t"
      "mla v25.4s, v17.4s, v5.s[0]\n\t"
      "mla v24.4s, v16.4s, v5.s[0]\n\t"
      "mla v30.4s, v22.4s, v5.s[3]\n\t"
      "mla v31.4s, v23.4s, v5.s[3]\n\t"
      "mla v26.4s, v18.4s, v5.s[0]\n\t"
      "mla v27.4s, v19.4s, v5.s[0]\n\t"
      "mla v28.4s, v20.4s, v5.s[3]\n\t"
      "mla v29.4s, v21.4s, v5.s[3]\n\t"
      "mla v24.4s, v20.4s, v5.s[2]\n\t"
      "uzp2 v17.8h, v30.8h, v31.8h\n\t"
      "mla v25.4s, v21.4s, v5.s[2]\n\t"
      "mla v26.4s, v22.4s, v5.s[2]\n\t"
      "mla v27.4s, v23.4s, v5.s[2]\n\t"
      "uzp2 v16.8h, v28.8h, v29.8h\n\t"
      "ldp q30, q31, [%[tab], #128]\n\t"
      "add v21.8h, v17.8h, v1.8h\n\t"
      "uzp2 v6.8h, v24.8h, v25.8h\n\t"
      "uzp2 v7.8h, v26.8h, v27.8h\n\t"
      "neg v29.8h, v31.8h\n\t"
      "add v20.8h, v16.8h, v1.8h\n\t"
      "and v21.16b, v21.16b, v3.16b\n\t"
      "add v18.8h, v6.8h, v0.8h\n\t"
      "add v19.8h, v7.8h, v0.8h\n\t"
      "ushl v24.8h, v6.8h, v29.8h\n\t"
      "ushl v25.8h, v7.8h, v29.8h\n\t"
      "ushl v26.8h, v16.8h, v29.8h\n\t"
      "ushl v27.8h, v17.8h, v29.8h\n\t"
      "and v22.16b, v18.16b, v2.16b\n\t"
      "and v23.16b, v19.16b, v2.16b\n\t"
      "and v20.16b, v20.16b, v3.16b\n\t"
      "and v18.16b, v6.16b, v30.16b\n\t"
      "uzp1 v0.16b, v24.16b, v26.16b\n\t"
      "uzp1 v1.16b, v25.16b, v27.16b\n\t"
      "and v19.16b, v16.16b, v30.16b\n\t"
      "mla v23.8h, v21.8h, v4.h[4]\n\t"
      "mla v22.8h, v20.8h, v4.h[4]\n\t"
      "and v20.16b, v7.16b, v30.16b\n\t"
      "mvn v2.16b, v0.16b\n\t"
      "mvn v3.16b, v1.16b\n\t"
      "umaxp v0.16b, v0.16b, v1.16b\n\t"
      "mul v5.8h, v18.8h, v19.8h\n\t"
      "and v21.16b, v17.16b, v30.16b\n\t"
      "ushl v18.8h, v18.8h, v31.8h\n\t"
      "ushl v19.8h, v19.8h, v31.8h\n\t"
      "movi v29.16b, #2\n\t"
      "umaxp v2.16b, v2.16b, v3.16b\n\t"
      "movi v7.16b, #10\n\t"
      "mul v30.8h, v20.8h, v21.8h\n\t"
      "ushl v20.8h, v20.8h, v31.8h\n\t"
      "ushl v21.8h, v21.8h, v31.8h\n\t"
      "movi v6.16b, #8\n\t"
      "umaxp v0.16b, v0.16b, v2.16b\n\t"
      "ldr q31, [%[tab], #160]\n\t"
      "st1 {v22.8h, v23.8h}, [%[dv]], #32\n\t"
      "movk %w[du], #0x0808, lsl #16\n\t"
      "lsl %w[u], %w[v], %w[u]\n\t"
      "mov %w[v], #256\n\t"
      "umaxp v0.16b, v0.16b, v0.16b\n\t"
      "orr %[u], %[du], %[u], lsl #32\n\t"
      "mov %w[du], #256\n\t"
      "fmov %[ddv], d0\n\t"
      "fmov d4, %[u]\n\t"
      "add %[u], %[fr], #32\n\t"
      "mvn %[fr], %[ddv]\n\t"
      "and %w[tab], %w[ddv], #0xff\n\t"
      "ubfx w15, %w[ddv], #8, #8\n\t"
      "ubfx w16, %w[ddv], #16, #8\n\t"
      "ubfx %w[ddv], %w[ddv], #24, #8\n\t"
      "ubfx x17, %[fr], #32, #8\n\t"
      "ubfx x19, %[fr], #40, #8\n\t"
      "ubfx x20, %[fr], #48, #8\n\t"
      "lsr %[fr], %[fr], #56\n\t"
      "cmp w17, %w[limx]\n\t"
      "ldr x21, [%[dv], #-32]\n\t"
      "csel w17, w17, %w[limx], lt\n\t"
      "cmp w19, %w[limy]\n\t"
      "csel w19, w19, %w[limy], lt\n\t"
      "cmp w20, %w[limx]\n\t"
      "sub %w[tab], %w[tab], w17\n\t"
      "csel %w[limx], w20, %w[limx], lt\n\t"
      "cmp %w[fr], %w[limy]\n\t"
      "madd x20, x19, %[gw2], %[grid]\n\t"
      "add w22, w17, w19, lsl #2\n\t"
      "sub w15, w15, w19\n\t"
      "csel %w[fr], %w[fr], %w[limy], lt\n\t"
      "cmp %w[tab], #2\n\t"
      "sub %w[tab], w16, %w[limx]\n\t"
      "ldr %[limy], [%[dv], #-24]\n\t"
      "add x16, x20, x17, lsl #1\n\t"
      "msub %w[v], w22, %w[ddu], %w[v]\n\t"
      "madd %[grid], %[fr], %[gw2], %[grid]\n\t"
      "add w17, %w[limx], %w[fr], lsl #2\n\t"
      "ccmp w15, #2, #2, ls\n\t"
      "ldr d0, [x16]\n\t"
      "dup v22.8h, %w[v]\n\t"
      "msub %w[v], w17, %w[ddu], %w[du]\n\t"
      "ldr %[ddu], [%[dv], #-16]\n\t"
      "add %[du], %[grid], %[limx], lsl #1\n\t"
      "add %[grid], x16, %[gw2]\n\t"
      "sub %w[ddv], %w[ddv], %w[fr]\n\t"
      "ccmp %w[tab], #2, #2, ls\n\t"
      "and %w[fr], w21, #0xffff\n\t"
      "and %w[tab], %w[limy], #0xffff\n\t"
      "ldr d2, [%[du]]\n\t"
      "ld1 {v0.d}[1], [%[grid]]\n\t"
      "mla v22.8h, v24.8h, v4.h[0]\n\t"
      "dup v23.8h, %w[v]\n\t"
      "ldrb %w[v], [%[tex], %[fr]]\n\t"
      "add %[du], %[du], %[gw2]\n\t"
      "add %[grid], %[grid], %[gw2]\n\t"
      "ccmp %w[ddv], #2, #2, ls\n\t"
      "ldrb %w[ddv], [%[tex], %[tab]]\n\t"
      "mla v22.8h, v26.8h, v4.h[1]\n\t"
      "mla v23.8h, v25.8h, v4.h[0]\n\t"
      "ld1 {v2.d}[1], [%[du]]\n\t"
      "ldr d1, [%[grid]]\n\t"
      "add %[du], %[du], %[gw2]\n\t"
      "add %[grid], %[grid], %[gw2]\n\t"
      "lsr %w[fr], w21, #16\n\t"
      "lsr %w[tab], %w[limy], #16\n\t"
      "add v24.8h, v22.8h, v29.8h\n\t"
      "mla v23.8h, v27.8h, v4.h[1]\n\t"
      "add v26.8h, v22.8h, v7.8h\n\t"
      "add v25.8h, v22.8h, v6.8h\n\t"
      "ldr d3, [%[du]]\n\t"
      "ld1 {v1.d}[1], [%[grid]]\n\t"
      "add %[du], %[du], %[gw2]\n\t"
      "ldrb %w[grid], [%[tex], %[fr]]\n\t"
      "add v27.8h, v23.8h, v29.8h\n\t"
      "add v17.8h, v23.8h, v7.8h\n\t"
      "tbl v24.16b, {v0.16b, v1.16b}, v24.16b\n\t"
      "tbl v26.16b, {v0.16b, v1.16b}, v26.16b\n\t"
      "add v16.8h, v23.8h, v6.8h\n\t"
      "tbl v22.16b, {v0.16b, v1.16b}, v22.16b\n\t"
      "tbl v25.16b, {v0.16b, v1.16b}, v25.16b\n\t"
      "ld1 {v3.d}[1], [%[du]]\n\t"
      "ldrb %w[gw2], [%[tex], %[tab]]\n\t"
      "sub v26.8h, v26.8h, v24.8h\n\t"
      "sub v24.8h, v24.8h, v22.8h\n\t"
      "umull v6.4s, v22.4h, v4.h[2]\n\t"
      "tbl v27.16b, {v2.16b, v3.16b}, v27.16b\n\t"
      "tbl v17.16b, {v2.16b, v3.16b}, v17.16b\n\t"
      "tbl v23.16b, {v2.16b, v3.16b}, v23.16b\n\t"
      "umull2 v7.4s, v22.8h, v4.h[2]\n\t"
      "tbl v16.16b, {v2.16b, v3.16b}, v16.16b\n\t"
      "sub v25.8h, v25.8h, v22.8h\n\t"
      "smlal v6.4s, v18.4h, v24.4h\n\t"
      "sub v17.8h, v17.8h, v27.8h\n\t"
      "sub v27.8h, v27.8h, v23.8h\n\t"
      "umull v28.4s, v23.4h, v4.h[2]\n\t"
      "smlal2 v7.4s, v18.8h, v24.8h\n\t"
      "umull2 v29.4s, v23.8h, v4.h[2]\n\t"
      "sub v26.8h, v26.8h, v25.8h\n\t"
      "sub v16.8h, v16.8h, v23.8h\n\t"
      "smlal v6.4s, v19.4h, v25.4h\n\t"
      "smlal v28.4s, v20.4h, v27.4h\n\t"
      "smlal2 v7.4s, v19.8h, v25.8h\n\t"
      "smlal2 v29.4s, v20.8h, v27.8h\n\t"
      "sub v17.8h, v17.8h, v16.8h\n\t"
      "smlal v6.4s, v5.4h, v26.4h\n\t"
      "smlal v28.4s, v21.4h, v16.4h\n\t"
      "smlal2 v7.4s, v5.8h, v26.8h\n\t"
      "smlal2 v29.4s, v21.8h, v16.8h\n\t"
      "ldr %[dv], [%[dv], #-8]\n\t"
      "ushl v6.4s, v6.4s, v31.4s\n\t"
      "smlal v28.4s, v30.4h, v17.4h\n\t"
      "ushl v7.4s, v7.4s, v31.4s\n\t"
      "smlal2 v29.4s, v30.8h, v17.8h\n\t"
      "cset %w[du], hi\n\t"
      "ushl v28.4s, v28.4s, v31.4s\n\t"
      "uzp1 v6.8h, v6.8h, v7.8h\n\t"
      "ushl v29.4s, v29.4s, v31.4s\n\t"
      "ubfx %[fr], x21, #32, #16\n\t"
      "lsr %[tab], x21, #48\n\t"
      "shl v6.8h, v6.8h, #8\n\t"
      "uzp1 v7.8h, v28.8h, v29.8h\n\t"
      "ldrb %w[fr], [%[tex], %[fr]]\n\t"
      "ldrb %w[tab], [%[tex], %[tab]]\n\t"
      "ubfx %[limx], %[limy], #32, #16\n\t"
      "lsr %[limy], %[limy], #48\n\t"
      "shl v7.8h, v7.8h, #8\n\t"
      "ldrb %w[limx], [%[tex], %[limx]]\n\t"
      "ldrb %w[limy], [%[tex], %[limy]]\n\t"
      "and w15, %w[ddu], #0xffff\n\t"
      "st1 {v6.8h, v7.8h}, [%[u]], #32\n\t"
      "ldrb w15, [%[tex], x15]\n\t"
      "ldr x16, [%[u], #-32]\n\t"
      "ldr x17, [%[u], #-24]\n\t"
      "ldr x19, [%[u], #-16]\n\t"
      "ldr %[u], [%[u], #-8]\n\t"
      "add %w[v], %w[v], w16, uxth\n\t"
      "add %w[grid], %w[grid], w16, lsr #16\n\t"
      "ubfx x20, x16, #32, #16\n\t"
      "add %[tab], %[tab], x16, lsr #48\n\t"
      "add %w[ddv], %w[ddv], w17, uxth\n\t"
      "add %w[gw2], %w[gw2], w17, lsr #16\n\t"
      "add %w[fr], %w[fr], w20\n\t"
      "ldrb %w[v], [%[cm], %[v]]\n\t"
      "ldrb %w[grid], [%[cm], %[grid]]\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "ldrb %w[fr], [%[cm], %[fr]]\n\t"
      "ldrb %w[ddv], [%[cm], %[ddv]]\n\t"
      "ldrb %w[gw2], [%[cm], %[gw2]]\n\t"
      "add %[limy], %[limy], x17, lsr #48\n\t"
      "orr %[v], %[v], %[grid], lsl #8\n\t"
      "ubfx %[grid], x17, #32, #16\n\t"
      "orr %[fr], %[fr], %[tab], lsl #8\n\t"
      "and %w[tab], %w[dv], #0xffff\n\t"
      "add w15, w15, w19, uxth\n\t"
      "add %w[grid], %w[limx], %w[grid]\n\t"
      "ldrb %w[limx], [%[cm], %[limy]]\n\t"
      "orr %[ddv], %[ddv], %[gw2], lsl #8\n\t"
      "orr %[v], %[v], %[fr], lsl #16\n\t"
      "lsr %w[gw2], %w[ddu], #16\n\t"
      "ubfx %[fr], %[ddu], #32, #16\n\t"
      "ldrb %w[grid], [%[cm], %[grid]]\n\t"
      "ldrb %w[gw2], [%[tex], %[gw2]]\n\t"
      "ldrb %w[fr], [%[tex], %[fr]]\n\t"
      "ldrb %w[tab], [%[tex], %[tab]]\n\t"
      "orr %[grid], %[grid], %[limx], lsl #8\n\t"
      "ldrb %w[limx], [%[cm], x15]\n\t"
      "add %w[gw2], %w[gw2], w19, lsr #16\n\t"
      "lsr %[ddu], %[ddu], #48\n\t"
      "lsr %w[limy], %w[dv], #16\n\t"
      "ubfx x15, %[dv], #32, #16\n\t"
      "lsr %[dv], %[dv], #48\n\t"
      "ldrb %w[ddu], [%[tex], %[ddu]]\n\t"
      "ldrb %w[limy], [%[tex], %[limy]]\n\t"
      "ldrb w15, [%[tex], x15]\n\t"
      "ldrb %w[dv], [%[tex], %[dv]]\n\t"
      "add %[ddu], %[ddu], x19, lsr #48\n\t"
      "add %w[tex], %w[tab], %w[u], uxth\n\t"
      "ubfx %[tab], x19, #32, #16\n\t"
      "ubfx x16, %[u], #32, #16\n\t"
      "add %w[limy], %w[limy], %w[u], lsr #16\n\t"
      "ldrb %w[gw2], [%[cm], %[gw2]]\n\t"
      "add %w[fr], %w[fr], %w[tab]\n\t"
      "add %w[tab], w15, w16\n\t"
      "add %[u], %[dv], %[u], lsr #48\n\t"
      "ldrb %w[dv], [%[cm], %[ddu]]\n\t"
      "ldrb %w[ddu], [%[cm], %[tex]]\n\t"
      "ldrb %w[tex], [%[cm], %[fr]]\n\t"
      "ldrb %w[fr], [%[cm], %[limy]]\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "ldrb %w[u], [%[cm], %[u]]\n\t"
      "orr %[cm], %[limx], %[gw2], lsl #8\n\t"
      "orr %[dv], %[tex], %[dv], lsl #8\n\t"
      "orr %[ddu], %[ddu], %[fr], lsl #8\n\t"
      "orr %[ddv], %[ddv], %[grid], lsl #16\n\t"
      "orr %[u], %[tab], %[u], lsl #8\n\t"
      "orr %[dv], %[cm], %[dv], lsl #16\n\t"
      "orr %[v], %[v], %[ddv], lsl #32\n\t"
      "orr %[u], %[ddu], %[u], lsl #16\n\t"
      "orr %[u], %[dv], %[u], lsl #32\n\t"
      "stp %[v], %[u], [%[dest]]"
      // END win16_block
      : [u] "+r"(u), [v] "+r"(v), [du] "+r"(du), [dv] "+r"(dv), [ddu] "+r"(ddu), [ddv] "+r"(ddv), [tab] "+r"(tp),
        [tex] "+r"(tex), [cm] "+r"(cm), [grid] "+r"(grid), [gw2] "+r"(gw2), [dest] "+r"(dp), [fr] "+r"(fp),
        [limx] "+r"(limx), [limy] "+r"(limy)
      :
      : "x15", "x16", "x17", "x19", "x20", "x21", "x22", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17",
        "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30", "v31", "cc",
        "memory");
  return du;
}

#endif

}  // namespace
}  // namespace sb::simd
