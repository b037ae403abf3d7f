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
// block's case): 8 (|d| + 16 |dd|) < 2.5 B texels along u and along v. A guess only (the
// block checks every group): beyond it most runs would be flagged and drawn twice.
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
// bench/mca_a53_persp/list_sched.py orders it for the Cortex-A53 model, bench/order_search.py
// refines the order (A53 and A57, at qemu's cuts), bench/mca_a53_lit/regalloc.py gives its
// core values registers again (x19, x20 the only callee-saved), bench/to_inline.py writes it
// below (commands: bench/mca_a53_lit/README.md, "Runs across several cells").
__attribute__((always_inline)) inline unsigned win16_block(uint8_t* dest, const LitSpanSource& src, LitA64Frame& fr,
                                                           const LitA64Tab& tab, uint32_t u32, uint32_t v32,
                                                           uint32_t du32, uint32_t dv32, uint32_t ddu32, uint32_t ddv32,
                                                           uint64_t limx64, uint64_t limy64) {
  // The operands pinned as lit16_block's (asm/lit_span_a64.h): in the registers win16_go's
  // arguments arrive in where they can (dest x0, u..ddu x3-x7, ddv x1 for n), the others in
  // x8-x14. Left to GCC, its choices moved bench/count.sh's A72 figure by up to 1.4 cycles
  // a pixel (where the C++ lines and the block's first qemu block meet).
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
  register uint64_t limx asm("x13") = limx64;
  register uint64_t limy asm("x14") = limy64;
  asm volatile(
      // BEGIN win16_block
      "fmov s5, %w[du]\n\t"
      "dup v31.4s, %w[v]\n\t"
      "dup v25.4s, %w[u]\n\t"
      "dup v30.4s, %w[v]\n\t"
      "dup v28.4s, %w[v]\n\t"
      "dup v29.4s, %w[v]\n\t"
      "mov v5.s[1], %w[dv]\n\t"
      "dup v24.4s, %w[u]\n\t"
      "dup v26.4s, %w[u]\n\t"
      "dup v27.4s, %w[u]\n\t"
      "ldp q18, q19, [%[tab], #32]\n\t"
      "mov v5.s[2], %w[ddu]\n\t"
      "ldp q20, q21, [%[tab], #64]\n\t"
      "add %[u], %[fr], #64\n\t"
      "ldp q16, q17, [%[tab]]\n\t"
      "ld4r {v0.8h, v1.8h, v2.8h, v3.8h}, [%[u]]\n\t"
      "mov v5.s[3], %w[ddv]\n\t"
      "mov %[u], %[fr]\n\t"
      "mov %w[v], #514\n\t"
      "mov %w[du], #256\n\t"
      "ldp q22, q23, [%[tab], #96]\n\t"
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
      "mla v25.4s, v21.4s, v5.s[2]\n\t"
      "uzp2 v17.8h, v30.8h, v31.8h\n\t"
      "mla v26.4s, v22.4s, v5.s[2]\n\t"
      "mla v27.4s, v23.4s, v5.s[2]\n\t"
      "uzp2 v16.8h, v28.8h, v29.8h\n\t"
      "ldp q30, q31, [%[tab], #128]\n\t"
      "mov %w[dv], #256\n\t"
      "add v21.8h, v17.8h, v1.8h\n\t"
      "uzp2 v6.8h, v24.8h, v25.8h\n\t"
      "uzp2 v7.8h, v26.8h, v27.8h\n\t"
      "add v20.8h, v16.8h, v1.8h\n\t"
      "neg v29.8h, v31.8h\n\t"
      "and v21.16b, v21.16b, v3.16b\n\t"
      "add v18.8h, v6.8h, v0.8h\n\t"
      "add v19.8h, v7.8h, v0.8h\n\t"
      "and v20.16b, v20.16b, v3.16b\n\t"
      "ushl v24.8h, v6.8h, v29.8h\n\t"
      "ushl v26.8h, v16.8h, v29.8h\n\t"
      "ushl v25.8h, v7.8h, v29.8h\n\t"
      "ushl v27.8h, v17.8h, v29.8h\n\t"
      "and v23.16b, v19.16b, v2.16b\n\t"
      "ldr q4, [%[fr], #64]\n\t"
      "and v22.16b, v18.16b, v2.16b\n\t"
      "uzp1 v0.16b, v24.16b, v26.16b\n\t"
      "and v18.16b, v6.16b, v30.16b\n\t"
      "uzp1 v1.16b, v25.16b, v27.16b\n\t"
      "mla v22.8h, v20.8h, v4.h[4]\n\t"
      "and v20.16b, v7.16b, v30.16b\n\t"
      "mvn v2.16b, v0.16b\n\t"
      "mvn v3.16b, v1.16b\n\t"
      "mla v23.8h, v21.8h, v4.h[4]\n\t"
      "and v21.16b, v17.16b, v30.16b\n\t"
      "umaxp v0.16b, v0.16b, v1.16b\n\t"
      "and v19.16b, v16.16b, v30.16b\n\t"
      "movi v6.16b, #8\n\t"
      "umaxp v2.16b, v2.16b, v3.16b\n\t"
      "st1 {v22.8h, v23.8h}, [%[u]], #32\n\t"
      "ldr q4, [%[tab], #192]\n\t"
      "mul v30.8h, v20.8h, v21.8h\n\t"
      "ushl v20.8h, v20.8h, v31.8h\n\t"
      "ushl v21.8h, v21.8h, v31.8h\n\t"
      "mul v5.8h, v18.8h, v19.8h\n\t"
      "ushl v18.8h, v18.8h, v31.8h\n\t"
      "umaxp v0.16b, v0.16b, v2.16b\n\t"
      "ushl v19.8h, v19.8h, v31.8h\n\t"
      "movi v29.16b, #2\n\t"
      "add %[ddu], %[fr], #32\n\t"
      "umaxp v0.16b, v0.16b, v0.16b\n\t"
      "ldr q31, [%[tab], #160]\n\t"
      "ldr %[ddv], [%[u], #-32]\n\t"
      "movi v7.16b, #10\n\t"
      "fmov %[fr], d0\n\t"
      "mvn %[tab], %[fr]\n\t"
      "lsr x15, %[fr], #32\n\t"
      "ubfx x17, %[tab], #40, #8\n\t"
      "ubfx x16, %[tab], #32, #8\n\t"
      "cmp w16, %w[limx]\n\t"
      "ubfx x19, %[tab], #48, #8\n\t"
      "add %w[fr], %w[fr], w15\n\t"
      "ldr x15, [%[u], #-24]\n\t"
      "csel w16, w16, %w[limx], lt\n\t"
      "cmp w17, %w[limy]\n\t"
      "lsr %[tab], %[tab], #56\n\t"
      "add %w[fr], %w[fr], #1\n\t"
      "csel w17, w17, %w[limy], lt\n\t"
      "cmp w19, %w[limx]\n\t"
      "and w20, %w[fr], %w[fr], lsr #1\n\t"
      "csel %w[limx], w19, %w[limx], lt\n\t"
      "cmp %w[tab], %w[limy]\n\t"
      "madd x19, x17, %[gw2], %[grid]\n\t"
      "add w17, w16, w17, lsl #2\n\t"
      "orr %w[fr], %w[fr], w20, lsl #2\n\t"
      "csel %w[tab], %w[tab], %w[limy], lt\n\t"
      "lsr %w[limy], w15, #16\n\t"
      "msub %w[du], w17, %w[v], %w[du]\n\t"
      "and w20, %w[ddv], #0xffff\n\t"
      "add x16, x19, x16, lsl #1\n\t"
      "madd %[grid], %[tab], %[gw2], %[grid]\n\t"
      "tst %w[fr], #0xfcfcfcfc\n\t"
      "add %w[tab], %w[limx], %w[tab], lsl #2\n\t"
      "add %[fr], x16, %[gw2]\n\t"
      "ldr d0, [x16]\n\t"
      "add %[grid], %[grid], %[limx], lsl #1\n\t"
      "dup v22.8h, %w[du]\n\t"
      "msub %w[v], %w[tab], %w[v], %w[dv]\n\t"
      "and %w[dv], w15, #0xffff\n\t"
      "ubfx %[tab], x15, #32, #16\n\t"
      "cset %w[du], ne\n\t"
      "ldr d2, [%[grid]]\n\t"
      "ldr %[limx], [%[u], #-16]\n\t"
      "mla v22.8h, v24.8h, v4.h[0]\n\t"
      "ld1 {v0.d}[1], [%[fr]]\n\t"
      "dup v23.8h, %w[v]\n\t"
      "ldrb %w[v], [%[tex], %[dv]]\n\t"
      "add %[dv], %[grid], %[gw2]\n\t"
      "add %[grid], %[fr], %[gw2]\n\t"
      "lsr %w[fr], %w[ddv], #16\n\t"
      "mla v22.8h, v26.8h, v4.h[1]\n\t"
      "ldr d1, [%[grid]]\n\t"
      "mla v23.8h, v25.8h, v4.h[0]\n\t"
      "ld1 {v2.d}[1], [%[dv]]\n\t"
      "add %[grid], %[grid], %[gw2]\n\t"
      "add %[dv], %[dv], %[gw2]\n\t"
      "ldrb %w[fr], [%[tex], %[fr]]\n\t"
      "add v24.8h, v22.8h, v29.8h\n\t"
      "add v26.8h, v22.8h, v7.8h\n\t"
      "mla v23.8h, v27.8h, v4.h[1]\n\t"
      "add v25.8h, v22.8h, v6.8h\n\t"
      "ldr d3, [%[dv]]\n\t"
      "ld1 {v1.d}[1], [%[grid]]\n\t"
      "add %[dv], %[dv], %[gw2]\n\t"
      "add v27.8h, v23.8h, v29.8h\n\t"
      "tbl v26.16b, {v0.16b, v1.16b}, v26.16b\n\t"
      "add v17.8h, v23.8h, v7.8h\n\t"
      "tbl v24.16b, {v0.16b, v1.16b}, v24.16b\n\t"
      "tbl v22.16b, {v0.16b, v1.16b}, v22.16b\n\t"
      "add v16.8h, v23.8h, v6.8h\n\t"
      "tbl v25.16b, {v0.16b, v1.16b}, v25.16b\n\t"
      "ld1 {v3.d}[1], [%[dv]]\n\t"
      "ldr %[u], [%[u], #-8]\n\t"
      "sub v26.8h, v26.8h, v24.8h\n\t"
      "umull v6.4s, v22.4h, v4.h[2]\n\t"
      "sub v24.8h, v24.8h, v22.8h\n\t"
      "tbl v27.16b, {v2.16b, v3.16b}, v27.16b\n\t"
      "tbl v17.16b, {v2.16b, v3.16b}, v17.16b\n\t"
      "tbl v23.16b, {v2.16b, v3.16b}, v23.16b\n\t"
      "sub v25.8h, v25.8h, v22.8h\n\t"
      "umull2 v7.4s, v22.8h, v4.h[2]\n\t"
      "tbl v16.16b, {v2.16b, v3.16b}, v16.16b\n\t"
      "smlal v6.4s, v18.4h, v24.4h\n\t"
      "sub v17.8h, v17.8h, v27.8h\n\t"
      "sub v27.8h, v27.8h, v23.8h\n\t"
      "umull v28.4s, v23.4h, v4.h[2]\n\t"
      "smlal2 v7.4s, v18.8h, v24.8h\n\t"
      "umull2 v29.4s, v23.8h, v4.h[2]\n\t"
      "sub v16.8h, v16.8h, v23.8h\n\t"
      "smlal v6.4s, v19.4h, v25.4h\n\t"
      "sub v26.8h, v26.8h, v25.8h\n\t"
      "smlal v28.4s, v20.4h, v27.4h\n\t"
      "smlal2 v7.4s, v19.8h, v25.8h\n\t"
      "smlal2 v29.4s, v20.8h, v27.8h\n\t"
      "sub v17.8h, v17.8h, v16.8h\n\t"
      "smlal v6.4s, v5.4h, v26.4h\n\t"
      "smlal v28.4s, v21.4h, v16.4h\n\t"
      "smlal2 v7.4s, v5.8h, v26.8h\n\t"
      "smlal2 v29.4s, v21.8h, v16.8h\n\t"
      "ushl v6.4s, v6.4s, v31.4s\n\t"
      "smlal v28.4s, v30.4h, v17.4h\n\t"
      "ushl v7.4s, v7.4s, v31.4s\n\t"
      "smlal2 v29.4s, v30.8h, v17.8h\n\t"
      "lsr %[dv], x15, #48\n\t"
      "ushl v28.4s, v28.4s, v31.4s\n\t"
      "uzp1 v6.8h, v6.8h, v7.8h\n\t"
      "ushl v29.4s, v29.4s, v31.4s\n\t"
      "ubfx %[grid], %[ddv], #32, #16\n\t"
      "ldrb %w[dv], [%[tex], %[dv]]\n\t"
      "lsr %[ddv], %[ddv], #48\n\t"
      "uzp1 v7.8h, v28.8h, v29.8h\n\t"
      "shl v6.8h, v6.8h, #8\n\t"
      "and %w[gw2], %w[limx], #0xffff\n\t"
      "ldrb %w[tab], [%[tex], %[tab]]\n\t"
      "ldrb w15, [%[tex], x20]\n\t"
      "shl v7.8h, v7.8h, #8\n\t"
      "ldrb %w[ddv], [%[tex], %[ddv]]\n\t"
      "ldrb %w[grid], [%[tex], %[grid]]\n\t"
      "ldrb %w[gw2], [%[tex], %[gw2]]\n\t"
      "ldrb %w[limy], [%[tex], %[limy]]\n\t"
      "st1 {v6.8h, v7.8h}, [%[ddu]], #32\n\t"
      "ldr x16, [%[ddu], #-32]\n\t"
      "ldr x17, [%[ddu], #-16]\n\t"
      "ldr x19, [%[ddu], #-24]\n\t"
      "ldr %[ddu], [%[ddu], #-8]\n\t"
      "add %w[fr], %w[fr], w16, lsr #16\n\t"
      "ubfx x20, x16, #32, #16\n\t"
      "add %[ddv], %[ddv], x16, lsr #48\n\t"
      "add w15, w15, w16, uxth\n\t"
      "add %w[v], %w[v], w19, uxth\n\t"
      "add %w[limy], %w[limy], w19, lsr #16\n\t"
      "ldrb %w[fr], [%[cm], %[fr]]\n\t"
      "add %w[grid], %w[grid], w20\n\t"
      "ldrb %w[ddv], [%[cm], %[ddv]]\n\t"
      "ldrb w15, [%[cm], x15]\n\t"
      "ldrb %w[v], [%[cm], %[v]]\n\t"
      "ldrb %w[limy], [%[cm], %[limy]]\n\t"
      "ldrb %w[grid], [%[cm], %[grid]]\n\t"
      "orr %[fr], x15, %[fr], lsl #8\n\t"
      "ubfx x16, %[ddu], #32, #16\n\t"
      "add %[dv], %[dv], x19, lsr #48\n\t"
      "ubfx x15, x19, #32, #16\n\t"
      "orr %[ddv], %[grid], %[ddv], lsl #8\n\t"
      "and %w[grid], %w[u], #0xffff\n\t"
      "add %w[tab], %w[tab], w15\n\t"
      "ldrb %w[dv], [%[cm], %[dv]]\n\t"
      "orr %[ddv], %[fr], %[ddv], lsl #16\n\t"
      "orr %[v], %[v], %[limy], lsl #8\n\t"
      "lsr %w[limy], %w[limx], #16\n\t"
      "ubfx %[fr], %[limx], #32, #16\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "add %w[gw2], %w[gw2], w17, uxth\n\t"
      "ldrb %w[limy], [%[tex], %[limy]]\n\t"
      "ldrb %w[fr], [%[tex], %[fr]]\n\t"
      "ldrb %w[grid], [%[tex], %[grid]]\n\t"
      "orr %[dv], %[tab], %[dv], lsl #8\n\t"
      "ldrb %w[gw2], [%[cm], %[gw2]]\n\t"
      "add %w[tab], %w[limy], w17, lsr #16\n\t"
      "lsr %w[limy], %w[u], #16\n\t"
      "lsr %[limx], %[limx], #48\n\t"
      "ubfx x15, %[u], #32, #16\n\t"
      "lsr %[u], %[u], #48\n\t"
      "ldrb %w[limx], [%[tex], %[limx]]\n\t"
      "ldrb %w[u], [%[tex], %[u]]\n\t"
      "ldrb %w[limy], [%[tex], %[limy]]\n\t"
      "add %w[grid], %w[grid], %w[ddu], uxth\n\t"
      "ldrb %w[tex], [%[tex], x15]\n\t"
      "add %[limx], %[limx], x17, lsr #48\n\t"
      "ubfx x15, x17, #32, #16\n\t"
      "add %w[fr], %w[fr], w15\n\t"
      "add %w[limy], %w[limy], %w[ddu], lsr #16\n\t"
      "ldrb %w[tab], [%[cm], %[tab]]\n\t"
      "add %[u], %[u], %[ddu], lsr #48\n\t"
      "ldrb %w[ddu], [%[cm], %[limx]]\n\t"
      "add %w[tex], %w[tex], w16\n\t"
      "ldrb %w[fr], [%[cm], %[fr]]\n\t"
      "orr %[v], %[v], %[dv], lsl #16\n\t"
      "ldrb %w[dv], [%[cm], %[limy]]\n\t"
      "ldrb %w[u], [%[cm], %[u]]\n\t"
      "ldrb %w[grid], [%[cm], %[grid]]\n\t"
      "orr %[gw2], %[gw2], %[tab], lsl #8\n\t"
      "ldrb %w[tex], [%[cm], %[tex]]\n\t"
      "orr %[ddu], %[fr], %[ddu], lsl #8\n\t"
      "orr %[dv], %[grid], %[dv], lsl #8\n\t"
      "orr %[u], %[tex], %[u], lsl #8\n\t"
      "orr %[v], %[ddv], %[v], lsl #32\n\t"
      "orr %[ddu], %[gw2], %[ddu], lsl #16\n\t"
      "orr %[u], %[dv], %[u], lsl #16\n\t"
      "orr %[u], %[ddu], %[u], lsl #32\n\t"
      "stp %[v], %[u], [%[dest]]"
      // END win16_block
      : [u] "+r"(u), [v] "+r"(v), [du] "+r"(du), [dv] "+r"(dv), [ddu] "+r"(ddu), [ddv] "+r"(ddv), [tab] "+r"(tp),
        [tex] "+r"(tex), [cm] "+r"(cm), [grid] "+r"(grid), [gw2] "+r"(gw2), [dest] "+r"(dp), [fr] "+r"(fp),
        [limx] "+r"(limx), [limy] "+r"(limy)
      :
      : "x15", "x16", "x17", "x19", "x20", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17",
        "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30", "v31", "cc",
        "memory");
  return du;
}

#endif

}  // namespace
}  // namespace sb::simd
