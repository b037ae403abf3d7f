// asm/neon_block_a32.h: the ARMv7 (Thumb-2 + NEON) assembly text of the surface block
// builder's strip loops (asm/neon.cpp, surface_block_groups: full groups), as macros, and
// the per-strip set-up functions they read (first numerators, band deltas, mip 3's grid
// rows). The operand names (%[sa], %[d], %[dp], ...) and register roles are the ones
// described there; only asm/neon.cpp includes this, and its asm statements expand these.
#pragma once
#include <arm_neon.h>

#include <cstdint>

#include "asm/neon_block_util.h"

#if !defined(__aarch64__)
namespace sb::simd::detail {
namespace {

// out[0..3] = the numerators of a full group's first row: g's entries weighted by bx, fx
// (16 lanes each; (B - fx) << (4 + mip) and fx << (4 + mip), <= 256). Reads four entries at
// g and g + 1 (mips 0-1: past the group's, inside the grid as g is never its last row).
template <int LB>
__attribute__((noinline)) void first_numerators(const uint16_t* g, const uint16_t* bx, const uint16_t* fx,
                                                uint32x4_t* out) {
  if constexpr (LB == 1) {
    static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
  } else {  // quarter q: entries j = 4 q >> LB and j + 1 as scalars (lanes of d0 and d1)
    asm volatile(
        "vld1.16 {d0}, [%[g]]!\n\t"
        "sub %[g], %[g], #6\n\t"
        "vld1.16 {d1}, [%[g]]\n\t"
        "vld1.16 {d16-d19}, [%[bx]]\n\t"
        "vld1.16 {d20-d23}, [%[fx]]\n\t"
        "vmull.u16 q2, d16, d0[%c[j0]]\n\t"
        "vmull.u16 q3, d17, d0[%c[j1]]\n\t"
        "vmull.u16 q12, d18, d0[%c[j2]]\n\t"
        "vmull.u16 q13, d19, d0[%c[j3]]\n\t"
        "vmlal.u16 q2, d20, d1[%c[j0]]\n\t"
        "vmlal.u16 q3, d21, d1[%c[j1]]\n\t"
        "vmlal.u16 q12, d22, d1[%c[j2]]\n\t"
        "vmlal.u16 q13, d23, d1[%c[j3]]\n\t"
        "vst1.32 {d4-d7}, [%[o]:128]!\n\t"
        "vst1.32 {d24-d27}, [%[o]:128]\n\t"
        : [g] "+r"(g), [o] "+r"(out)
        : [bx] "r"(bx), [fx] "r"(fx), [j0] "i"(0), [j1] "i"(4 >> LB), [j2] "i"(8 >> LB), [j3] "i"(12 >> LB)
        : "d0", "d1", "d4", "d5", "d6", "d7", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24",
          "d25", "d26", "d27", "memory");
  }
}

// band_deltas' bands one at a time (the rest after its two-band passes).
template <int LB>
__attribute__((noinline)) void band_deltas_one(const uint16_t* g, int gw, int n, const uint16_t* bxp,
                                               const uint16_t* fxp, uint32x4_t* D) {
  const int16x4_t bx0 = vreinterpret_s16_u16(vld1_u16(bxp)), bx1 = vreinterpret_s16_u16(vld1_u16(bxp + 4));
  const int16x4_t bx2 = vreinterpret_s16_u16(vld1_u16(bxp + 8)), bx3 = vreinterpret_s16_u16(vld1_u16(bxp + 12));
  const int16x4_t fx0 = vreinterpret_s16_u16(vld1_u16(fxp)), fx1 = vreinterpret_s16_u16(vld1_u16(fxp + 4));
  const int16x4_t fx2 = vreinterpret_s16_u16(vld1_u16(fxp + 8)), fx3 = vreinterpret_s16_u16(vld1_u16(fxp + 12));
  auto put = [&](int16x4_t a0, int16x4_t a1, int16x4_t a2, int16x4_t a3, int16x4_t c0, int16x4_t c1,
                 int16x4_t c2, int16x4_t c3, uint32x4_t* o) __attribute__((always_inline)) {
    // quarter q: v_j bx + v_j+1 fx (a: v_j, c: v_j+1 in every lane)
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 0), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a0, bx0), c0, fx0)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 1), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a1, bx1), c1, fx1)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 2), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a2, bx2), c2, fx2)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 3), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a3, bx3), c3, fx3)));
  };
  for (int b = 0; b < n; ++b, g += gw, D += 4) {
    if constexpr (LB == 1) {
      static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
    } else if constexpr (LB == 2) {  // quarter q: v_q, v_q+1
      const int16x4_t a = vreinterpret_s16_u16(vsub_u16(vld1_u16(g + gw), vld1_u16(g)));
      const int16x4_t c = vreinterpret_s16_u16(vsub_u16(vld1_u16(g + gw + 1), vld1_u16(g + 1)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 0),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx0, a, 0), fx0, c, 0)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 1),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx1, a, 1), fx1, c, 1)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 2),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx2, a, 2), fx2, c, 2)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 3),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx3, a, 3), fx3, c, 3)));
    } else {  // v_0 .. v_2 (mip 0: v_0, v_1) by scalar loads
      const int16x4_t v0 = vdup_n_s16(int16_t(g[gw] - g[0])), v1 = vdup_n_s16(int16_t(g[gw + 1] - g[1]));
      if constexpr (LB == 3) {
        const int16x4_t v2 = vdup_n_s16(int16_t(g[gw + 2] - g[2]));
        put(v0, v0, v1, v1, v1, v1, v2, v2, D);
      } else {
        put(v0, v0, v0, v0, v1, v1, v1, v1, D);
      }
    }
  }
}

// D[4 b .. 4 b + 3], b < n: the row step of the band between grid rows g + b gw and
// g + (b + 1) gw (a full group: its G + 1 entries inside each row), from the rows'
// difference (|difference| < 2^14); bxp, fxp: the row-step weights of the 16 lanes.
// Two bands a pass in assembly (d0-d7, d16-d31: no callee-saved registers to keep); over:
// bands whose four-entry reads (mips 0-1) stay inside the grid.
template <int LB>
__attribute__((noinline)) void band_deltas(const uint16_t* g, int gw, int n, int over, const uint16_t* bxp,
                                           const uint16_t* fxp, uint32x4_t* D) {
  static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
  if constexpr (LB == 2) {  // two bands a pass: quarter q from lane q of a (v_j) and c (v_j+1)
    if (n >= 2) {
      const uint16_t *g1 = g + gw, *g2 = g1 + gw, *h0 = g + 1, *h1 = g1 + 1, *h2 = g2 + 1;
      int k = n >> 1;
      asm volatile(
          "vld1.16 {d16-d19}, [%[bx]]\n\t"
          "vld1.16 {d20-d23}, [%[fx]]\n\t"
          "1:\n\t"
          "vld1.16 {d24}, [%[g0]], %[st]\n\t"
          "vld1.16 {d25}, [%[g1]], %[st]\n\t"
          "vld1.16 {d26}, [%[g2]], %[st]\n\t"
          "vld1.16 {d27}, [%[h0]], %[st]\n\t"
          "vld1.16 {d28}, [%[h1]], %[st]\n\t"
          "vld1.16 {d29}, [%[h2]], %[st]\n\t"
          "vsub.i16 d0, d25, d24\n\t"
          "vsub.i16 d2, d26, d25\n\t"
          "vsub.i16 d1, d28, d27\n\t"
          "vsub.i16 d3, d29, d28\n\t"
          "vmull.s16 q2, d16, d0[0]\n\t"
          "vmull.s16 q3, d17, d0[1]\n\t"
          "vmull.s16 q12, d18, d0[2]\n\t"
          "vmull.s16 q13, d19, d0[3]\n\t"
          "vmull.s16 q14, d16, d2[0]\n\t"
          "vmull.s16 q15, d17, d2[1]\n\t"
          "vmlal.s16 q2, d20, d1[0]\n\t"
          "vmlal.s16 q3, d21, d1[1]\n\t"
          "vmlal.s16 q12, d22, d1[2]\n\t"
          "vmlal.s16 q13, d23, d1[3]\n\t"
          "vmlal.s16 q14, d20, d3[0]\n\t"
          "vmlal.s16 q15, d21, d3[1]\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "vmull.s16 q2, d18, d2[2]\n\t"
          "vmull.s16 q3, d19, d2[3]\n\t"
          "vst1.32 {d24-d27}, [%[D]:128]!\n\t"
          "vmlal.s16 q2, d22, d3[2]\n\t"
          "vmlal.s16 q3, d23, d3[3]\n\t"
          "vst1.32 {d28-d31}, [%[D]:128]!\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "subs %[k], %[k], #1\n\t"
          "bne 1b\n\t"
          : [g0] "+r"(g), [g1] "+r"(g1), [g2] "+r"(g2), [h0] "+r"(h0), [h1] "+r"(h1), [h2] "+r"(h2), [D] "+r"(D),
            [k] "+r"(k)
          : [st] "r"(4 * gw), [bx] "r"(bxp), [fx] "r"(fxp)
          : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7",
            "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29",
            "d30", "d31", "cc", "memory");
      n &= 1;
    }
  }
  if constexpr (LB >= 3) {  // two bands a pass; reads four entries a row (up to two past the group's)
    const int pairs = (n < over ? n : over) >> 1;
    if (pairs > 0) {
      const uint16_t* g1 = g + gw;
      const uint16_t* g2 = g1 + gw;
      int k = pairs;
      asm volatile(
          "vld1.16 {d16-d19}, [%[bx]]\n\t"
          "vld1.16 {d20-d23}, [%[fx]]\n\t"
          "1:\n\t"
          "vld1.16 {d24}, [%[g0]], %[st]\n\t"
          "vld1.16 {d25}, [%[g1]], %[st]\n\t"
          "vld1.16 {d26}, [%[g2]], %[st]\n\t"
          "vsub.i16 d0, d25, d24\n\t"
          "vsub.i16 d1, d26, d25\n\t"
          "vmull.s16 q2, d16, d0[0]\n\t"
          "vmull.s16 q3, d17, d0[0]\n\t"
          "vmull.s16 q12, d18, d0[%c[la]]\n\t"
          "vmull.s16 q13, d19, d0[%c[la]]\n\t"
          "vmull.s16 q14, d16, d1[0]\n\t"
          "vmull.s16 q15, d17, d1[0]\n\t"
          "vmull.s16 q1, d18, d1[%c[la]]\n\t"
          "vmlal.s16 q2, d20, d0[1]\n\t"
          "vmlal.s16 q3, d21, d0[1]\n\t"
          "vmlal.s16 q12, d22, d0[%c[lc]]\n\t"
          "vmlal.s16 q13, d23, d0[%c[lc]]\n\t"
          "vmlal.s16 q14, d20, d1[1]\n\t"
          "vmlal.s16 q15, d21, d1[1]\n\t"
          "vmlal.s16 q1, d22, d1[%c[lc]]\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "vmull.s16 q2, d19, d1[%c[la]]\n\t"
          "vst1.32 {d24-d27}, [%[D]:128]!\n\t"
          "vmlal.s16 q2, d23, d1[%c[lc]]\n\t"
          "vst1.32 {d28-d31}, [%[D]:128]!\n\t"
          "vst1.32 {d2-d5}, [%[D]:128]!\n\t"
          "subs %[k], %[k], #1\n\t"
          "bne 1b\n\t"
          : [g0] "+r"(g), [g1] "+r"(g1), [g2] "+r"(g2), [D] "+r"(D), [k] "+r"(k)
          : [st] "r"(4 * gw), [bx] "r"(bxp), [fx] "r"(fxp), [la] "i"(LB == 3 ? 1 : 0), [lc] "i"(LB == 3 ? 2 : 1)
          : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7",
            "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29",
            "d30", "d31", "cc", "memory");
      n -= 2 * pairs;
    }
  }
  if (n > 0) band_deltas_one<LB>(g, gw, n, bxp, fxp, D);
}

// Mip 3 (B = 2): for up to ng full groups (as many as fit before tab_end; returns how many),
// grid rows r = 0..nb from g (group k's nine entries at g + 8 k), 32 bytes a row: the group's
// entries p_j and sums s_j = p_j + p_j+1 (j < 8, 16 bits), group after group. A band's lanes
// 2j, 2j + 1 have numerators 4 p_j, 2 s_j (row 0) and 2 (p_j + q_j), s_j + t_j (row 1; q, t:
// the next grid row's), each < 2^16 (entries < 2^14): the row is their bits 10-15 (see the
// strip's assembly).
__attribute__((noinline)) int grid_rows3(const uint16_t* g, int gw, int nb, int ng, uint8_t* tab,
                                         const uint8_t* tab_end) {
  int k = 0;
  for (; k < ng && tab + 32 * nb + 64 <= tab_end; ++k, g += 8) {  // (the strip reads a row past)
    const uint16_t *g0 = g, *g1 = g + 1;
    int n = nb - 1;  // rows 0..nb, two a pass
    asm volatile(
        "1:\n\t"
        "vld1.16 {d16-d17}, [%[g0]], %[st]\n\t"
        "vld1.16 {d18-d19}, [%[g1]], %[st]\n\t"
        "vld1.16 {d20-d21}, [%[g0]], %[st]\n\t"
        "vld1.16 {d22-d23}, [%[g1]], %[st]\n\t"
        "vadd.i16 q9, q8, q9\n\t"
        "vadd.i16 q11, q10, q11\n\t"
        "subs %[n], %[n], #2\n\t"
        "vst1.16 {d16-d19}, [%[o]:128]!\n\t"
        "vst1.16 {d20-d23}, [%[o]:128]!\n\t"
        "bge 1b\n\t"
        "cmn %[n], #1\n\t"
        "bne 2f\n\t"
        "vld1.16 {d16-d17}, [%[g0]]\n\t"
        "vld1.16 {d18-d19}, [%[g1]]\n\t"
        "vadd.i16 q9, q8, q9\n\t"
        "vst1.16 {d16-d19}, [%[o]:128]!\n"
        "2:\n\t"
        : [g0] "+r"(g0), [g1] "+r"(g1), [n] "+r"(n), [o] "+r"(tab)
        : [st] "r"(2 * gw)
        : "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "cc", "memory");
  }
  return k;
}

}  // namespace
}  // namespace sb::simd::detail
#endif

// The first part of a row, the same for both output forms.
#define SB_ROW7_HEAD \
  "ldr r0, [%[sa]], #4\n\t" \
  "vmov r1, r2, d24\n\t" \
  "add %[d], %[d], %[st]\n\t" \
  "vmov r3, ip, d25\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  "vadd.i32 q4, q4, q8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vadd.i32 q5, q5, q9\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vadd.i32 q6, q6, q10\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vadd.i32 q7, q7, q11\n\t" \
  "orr r3, r3, ip, lsl #8\n\t" \
  "vmov r0, r2, d26\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "vmov ip, lr, d27\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "ldrb lr, [%[cm], lr]\n\t"

#define SB_ROW7 \
  SB_ROW7_HEAD \
  "vshrn.i32 d7, q7, #16\n\t" \
  "str r1, [%[d], #0]\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmov r1, r2, d28\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r3, lr, d29\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vsli.16 q0, q2, #8\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "str r0, [%[d], #4]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "str r1, [%[d], #8]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "str r0, [%[d], #12]\n\t"

// Word-aligned output (the usual case): the same with strd (r8 holds a third word).
#define SB_ROW7A \
  SB_ROW7_HEAD \
  "vmovl.u8 q1, d1\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r8, r2, d28\n\t" \
  "strd r1, r0, [%[d], #0]\n\t" \
  "vmov r3, lr, d29\n\t" \
  "ldrb r8, [%[cm], r8]\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vsli.16 q0, q2, #8\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r8, r8, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r8, r8, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "strd r8, r0, [%[d], #8]\n\t"

// Prologue: row 0's indices (no step) and the first delta. The loop lies inside one
// 512-byte block (no page crossing).
#define SB_STRIP7(ROW, TEST, PD, BD0, BD) \
  "sub %[d], %[d], %[st]\n\t" \
  "ldr r0, [%[sa], #-4]\n\t" \
  "vld1.32 {d8-d11}, [%[dp]:128]!\n\t" \
  "vld1.32 {d12-d15}, [%[dp]:128]!\n\t" \
  PD \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  BD0 \
  "vsli.16 q0, q2, #8\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "b 1f\n\t" \
  ".balign 512\n" \
  "1:\n\t" ROW ROW TEST \
  "ldr r0, [%[sa]]\n\t" \
  "cbz r0, 3f\n\t" \
  BD \
  "b 1b\n\t" \
  "3:\n\t"

#define SB_STRIP7_OPS_(...) \
  : [sa] "+r"(sa), [d] "+r"(d), [dp] "+r"(dp) \
  : [cm] "r"(colormap), [st] "r"(width), [bm] "I"(4 * B - 1) __VA_ARGS__ \
  : "r0", "r1", "r2", "r3", "r8", "ip", "lr", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", \
  "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", \
  "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", \
  "cc", "memory"

// A band ends where srcs is 4 B-aligned.
#define SB_BAND_TEST "tst %[sa], %[bm]\n\tbne 1b\n\t"

// The next band's delta (q8-q11): loaded; at mip 2 weighed from e, e1, w0, w1 (d0-d3,
// free between rows): quarter j is w0 e[j] + w1 e1[j].
#define SB_LD_DELTA "vld1.32 {d16-d19}, [%[dp]:128]!\n\tvld1.32 {d20-d23}, [%[dp]:128]!\n\t"

// (mip 2: after the numerators dp reads the weights, pushed on the stack for the loop as
// no register is left, and the group's first band in etab; then a row of etab a band)
#define SB_EP2 \
  "vld1.16 {d2-d3}, [%[dp]:128]\n\t" \
  "ldr %[dp], [%[dp], #16]\n\t" \
  "sub sp, sp, #16\n\t" \
  "vst1.16 {d2-d3}, [sp]\n\t"

#define SB_DELTA2 \
  "vld1.8 {d0-d1}, [%[dp]], %[st]\n\t" \
  "vld1.16 {d2-d3}, [sp]\n\t" \
  "vmull.s16 q8, d2, d0[0]\n\t" \
  "vmull.s16 q9, d2, d0[1]\n\t" \
  "vmull.s16 q10, d2, d0[2]\n\t" \
  "vmull.s16 q11, d2, d0[3]\n\t" \
  "vmlal.s16 q8, d3, d0[1]\n\t" \
  "vmlal.s16 q9, d3, d0[2]\n\t" \
  "vmlal.s16 q10, d3, d0[3]\n\t" \
  "vmlal.s16 q11, d3, d1[0]\n\t"

// Mip 3: a pass is a band. Row 0's colormap rows: vshr(s, 1) with its low byte replaced
// (vsri) by p >> 8, i.e. 16-bit lanes (2 s >> 10) << 8 | 4 p >> 10; row 1's: vshr(s + t, 2)
// with vhadd(p, q) >> 8 (p, s and q, t: grid_rows3's rows, in q10-q11 and q2-q3 by turns,
// one loaded a pass; row 1's rows made in q8 during row 0's). Each zipped with the
// texels into row << 8 | texel. Slots S1..S8 take the NEON work (x0: the next band's
// row 0, x1: row 1), ZA or ZB the zip (the A9 model pairs them so).
#define SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "ldr r0, [%[sa]], #4\n\t" \
  "vmov r1, r2, d24\n\t" \
  "add %[d], %[d], %[st]\n\t" \
  "vmov r3, ip, d25\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  S1 \
  "ldrb r2, [%[cm], r2]\n\t" \
  S2 \
  "ldrb r3, [%[cm], r3]\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  S3 \
  "orr r1, r1, r2, lsl #8\n\t" \
  S4 \
  "orr r3, r3, ip, lsl #8\n\t" \
  "vmov r0, r2, d26\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "vmov ip, lr, d27\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  S5 \
  "ldrb r2, [%[cm], r2]\n\t" \
  S6 \
  "ldrb ip, [%[cm], ip]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t"

#define SB_ROW3A(S1, S2, S3, S4, S5, S6, S7, S8, ZA, ZB, DLO, DHI) \
  SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "orr r0, r0, r2, lsl #8\n\t" \
  S7 \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r8, r2, d28\n\t" \
  "strd r1, r0, [%[d], #0]\n\t" \
  "vmov r3, lr, d29\n\t" \
  ZA \
  "ldrb r8, [%[cm], r8]\n\t" \
  ZB \
  "ldrb r2, [%[cm], r2]\n\t" \
  S8 \
  "ldrb r3, [%[cm], r3]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r8, r8, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r8, r8, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, " DLO "\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, " DHI "\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "strd r8, r0, [%[d], #8]\n\t"

#define SB_ROW3(S1, S2, S3, S4, S5, S6, S7, S8, ZA, ZB, DLO, DHI) \
  SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "str r1, [%[d], #0]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  S7 \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmov r1, r2, d28\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r3, lr, d29\n\t" \
  ZA \
  "ldrb r1, [%[cm], r1]\n\t" \
  ZB \
  "ldrb r2, [%[cm], r2]\n\t" \
  S8 \
  "ldrb r3, [%[cm], r3]\n\t" \
  "str r0, [%[d], #4]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, " DLO "\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, " DHI "\n\t" \
  "str r1, [%[d], #8]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "str r0, [%[d], #12]\n\t"

#define SB_X1 "", "", "", "", "", "", "", "", "", "vzip.8 q0, q8\n\t", "d16", "d17"

#define SB_X0A \
  "vld1.16 {d20-d23}, [%[dp]:128]!\n\t", "", "vshr.u16 q1, q3, #1\n\t", "vadd.i16 q8, q3, q11\n\t", \
  "vsri.16 q1, q2, #8\n\t", "vhadd.u16 q9, q2, q10\n\t", "vshr.u16 q8, q8, #2\n\t", "vsri.16 q8, q9, #8\n\t", \
  "vzip.8 q0, q1\n\t", "", "d2", "d3"

#define SB_X0B \
  "vld1.16 {d4-d7}, [%[dp]:128]!\n\t", "", "vshr.u16 q1, q11, #1\n\t", "vadd.i16 q8, q11, q3\n\t", \
  "vsri.16 q1, q10, #8\n\t", "vhadd.u16 q9, q10, q2\n\t", "vshr.u16 q8, q8, #2\n\t", "vsri.16 q8, q9, #8\n\t", \
  "vzip.8 q0, q1\n\t", "", "d2", "d3"

#define SB_CALL3(M, ...) M(__VA_ARGS__)

#define SB_STRIP3(ROW) \
  "sub %[d], %[d], %[st]\n\t" \
  "ldr r0, [%[sa], #-4]\n\t" \
  "vld1.16 {d20-d23}, [%[dp]:128]!\n\t" \
  "vld1.16 {d4-d7}, [%[dp]:128]!\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "vshr.u16 q1, q11, #1\n\t" \
  "vadd.i16 q8, q11, q3\n\t" \
  "vhadd.u16 q9, q10, q2\n\t" \
  "vsri.16 q1, q10, #8\n\t" \
  "vshr.u16 q8, q8, #2\n\t" \
  "vzip.8 q0, q1\n\t" \
  "vsri.16 q8, q9, #8\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "b 1f\n\t" \
  ".balign 512\n" \
  "1:\n\t" SB_CALL3(ROW, SB_X1) SB_CALL3(ROW, SB_X0A) \
  "ldr r0, [%[sa]]\n\t" \
  "cmp r0, #0\n\t" \
  "beq 3f\n\t" \
  SB_CALL3(ROW, SB_X1) SB_CALL3(ROW, SB_X0B) \
  "ldr r0, [%[sa]]\n\t" \
  "cmp r0, #0\n\t" \
  "bne 1b\n" \
  "3:\n\t"

#define SB_STRIP3_OPS_ \
  : [sa] "+r"(sa), [d] "+r"(d), [dp] "+r"(dp) \
  : [cm] "r"(colormap), [st] "r"(width) \
  : "r0", "r1", "r2", "r3", "r8", "ip", "lr", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d16", "d17", \
    "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", "cc", \
    "memory"
