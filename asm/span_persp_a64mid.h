// asm/span_persp_a64mid.h: aarch64 only, persp_short_inl's second-order path for four runs
// (49 .. 64 pixels): short_steps_k3i computes every run's steps, the last run's last_dd
// included, in one asm block, and persp_mid_k3 draws the span from them. Internal: included
// by asm/span_persp_a64short.h (it uses asm/span_persp_arm.h's kRecipSteps, asm/span_persp_run.h's
// draw_run and Run16, asm/span_persp_a64pass.h's short_pass).
#pragma once
#include <cstdint>

#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64pass.h"
#endif

namespace sb::simd {
namespace {

#if defined(__aarch64__)
// The block's constants: 120 (4 lanes), 2^25 (4 lanes), the deltas' double bias 2^52 + 2^51
// (2 lanes), 1e9 (last_steps' |ddf| < 1e9 range, 2 lanes): two ldp.
alignas(16) constexpr uint64_t kMidConsts[8] = {
    0x0000007800000078, 0x0000007800000078, 0x0200000002000000, 0x0200000002000000,
    0x4338000000000000, 0x4338000000000000, 0x41cdcd6500000000, 0x41cdcd6500000000};
static_assert(__builtin_bit_cast(uint64_t, 1e9) == 0x41cdcd6500000000);
static_assert(__builtin_bit_cast(uint64_t, 6755399441055744.0) == 0x4338000000000000);
// The first pass's arguments (short_pass, run a and run b: runs 0 and 1) in the registers
// short_pass takes them in; the second pass's (runs 2 and 3) stored: st = {c_uv, luv, c_d,
// c_dd, ld, ldd} (run 2's packed start, step and second-order step, then run 3's, the last run).
struct MidFirst {
  uint64_t a_uv, a_d, a_dd, b_uv, b_d, b_dd;
};
// Four runs, second order, from the samples S01 = [u_0, v_0, u_1, v_1], S23, S44 (sample 4
// twice), the full runs' curve factors c01, c23, zs23 = [z_2 + z_3, z_3 + z_4], s = max(1,
// last - 1) (the last run's steps), zc (the span's dzi). Per full run j (0, 1, 2), lane by
// lane, what short_steps_k3 computes (asm/span_persp_a64short.h: delta, ddf, dd, steps16_dd's
// 32-bit form); the packing as Run16's (x & (2^64 - 2^32)) + sext(x mod 2^32) of each [du,
// dv] lane x. The last run (3): last_steps' vector part (div_steps' quotient q, lin =
// trunc(q), ddf = (q curve) -2, dd = trunc(ddf) & (|ddf| < 1e9), curve = (zc / 2)(z_3 +
// z_4)), the lanes [lin_u, lin_v, dd_u, dd_v] moved to core registers by one uzp1 and two
// moves, then last_steps_ddi's integer last_dd (asm/span_persp_arm.h: T = s (s - 1) / 2,
// which is steps (steps - 1) / 2 for steps = last - 1 >= 0; dd kept iff steps > 1, that is
// s > 1) and the packing of its results. One asm block, fixed registers, the order from
// bench/order_search.py on bench/mca_a53_p64/steps_k3i.s (its integer tail runs beside the
// vector work). AsmSpanPersp.FourRunSpansMatchOnExtremeGradients (lengths 49 .. 64) and
// MatchesTheRunWalkerOnShortSpans check it against the walker.
SB_INLINE MidFirst short_steps_k3i(int32x4_t S01, int32x4_t S23, int32x4_t S44, float64x2_t c01, float64x2_t c23,
                                   float64x2_t zs23, int s, double zc, uint64_t (&st)[6]) {
  register int32x4_t rS44 __asm__("v7") = S44;
  register int32x4_t rS01 __asm__("v5") = S01;
  register int32x4_t rS23 __asm__("v19") = S23;
  register float64x2_t rc01 __asm__("v3") = c01;
  register float64x2_t rc23 __asm__("v16") = c23;
  register float64x2_t rzs __asm__("v1") = zs23;
  register double rsd __asm__("v30") = double(s);
  register double rzc __asm__("v31") = zc * 0.5;
  uint64_t ra_uv, ra_d, ra_dd, rb_uv, rb_d, rb_dd;
  __asm__(
// BEGIN short_steps_k3i
      "ext v0.16b, v5.16b, v19.16b, #8\n\t"
      "ld1r {v6.2d}, [%[y]]\n\t"
      "ext v7.16b, v19.16b, v7.16b, #8\n\t"
      "ldp q17, q2, [%[kp], #32]\n\t"
      "sub v0.4s, v0.4s, v5.4s\n\t"
      "sub v7.4s, v7.4s, v19.4s\n\t"
      "cmp %w[s], #1\n\t"
      "saddw v21.2d, v17.2d, v0.2s\n\t"
      "saddw2 v22.2d, v17.2d, v0.4s\n\t"
      "saddw2 v4.2d, v17.2d, v7.4s\n\t"
      "ldp q18, q20, [%[kp]]\n\t"
      "saddw v23.2d, v17.2d, v7.2s\n\t"
      "fsub v21.2d, v21.2d, v17.2d\n\t"
      "fsub v22.2d, v22.2d, v17.2d\n\t"
      "fsub v4.2d, v4.2d, v17.2d\n\t"
      "fmul d31, d31, v1.d[1]\n\t"
      "sshr v24.4s, v0.4s, #31\n\t"
      "fsub v23.2d, v23.2d, v17.2d\n\t"
      "fmul v21.2d, v21.2d, v3.d[0]\n\t"
      "fmul v1.2d, v4.2d, v6.2d\n\t"
      "abs v27.4s, v7.4s\n\t"
      "sshr v25.4s, v7.4s, #31\n\t"
      "fmul v22.2d, v22.2d, v3.d[1]\n\t"
      "fmul v23.2d, v23.2d, v16.d[0]\n\t"
      "abs v26.4s, v0.4s\n\t"
      "fcvtzs v21.2d, v21.2d\n\t"
      "fmls v4.2d, v1.2d, v30.d[0]\n\t"
      "fcvtzs v23.2d, v23.2d\n\t"
      "ushr v17.4s, v26.4s, #4\n\t"
      "fcvtzs v22.2d, v22.2d\n\t"
      "sqxtn v21.2s, v21.2d\n\t"
      "ushr v28.4s, v27.4s, #4\n\t"
      "mov v16.16b, v27.16b\n\t"
      "sqxtn v23.2s, v23.2d\n\t"
      "fmla v1.2d, v4.2d, v6.2d\n\t"
      "eor v17.16b, v17.16b, v24.16b\n\t"
      "mov v3.16b, v26.16b\n\t"
      "fmov v6.2d, #-2.0\n\t"
      "sqxtn2 v21.4s, v22.2d\n\t"
      "abs v29.4s, v23.4s\n\t"
      "fcvtzs v4.2d, v1.2d\n\t"
      "fmul v1.2d, v1.2d, v31.d[0]\n\t"
      "eor v31.16b, v23.16b, v25.16b\n\t"
      "eor v30.16b, v21.16b, v24.16b\n\t"
      "eor v28.16b, v28.16b, v25.16b\n\t"
      "umin v29.4s, v29.4s, v20.4s\n\t"
      "abs v22.4s, v21.4s\n\t"
      "fmul v1.2d, v1.2d, v6.2d\n\t"
      "sub v31.4s, v31.4s, v25.4s\n\t"
      "sub v30.4s, v30.4s, v24.4s\n\t"
      "sub v17.4s, v17.4s, v24.4s\n\t"
      "mul v29.4s, v29.4s, v18.4s\n\t"
      "umin v22.4s, v22.4s, v20.4s\n\t"
      "facgt v6.2d, v2.2d, v1.2d\n\t"
      "mls v16.4s, v31.4s, v18.s[0]\n\t"
      "mls v3.4s, v30.4s, v18.s[0]\n\t"
      "fcvtzs v1.2d, v1.2d\n\t"
      "cmhs v29.4s, v27.4s, v29.4s\n\t"
      "mul v22.4s, v22.4s, v18.4s\n\t"
      "sub v28.4s, v28.4s, v25.4s\n\t"
      "ushr v16.4s, v16.4s, #4\n\t"
      "fmov %[a_uv], d5\n\t"
      "ushr v3.4s, v3.4s, #4\n\t"
      "and v23.16b, v23.16b, v29.16b\n\t"
      "cmhs v22.4s, v26.4s, v22.4s\n\t"
      "eor v16.16b, v16.16b, v25.16b\n\t"
      "eor v3.16b, v3.16b, v24.16b\n\t"
      "and v6.16b, v1.16b, v6.16b\n\t"
      "sub v16.4s, v16.4s, v25.4s\n\t"
      "and v21.16b, v21.16b, v22.16b\n\t"
      "movi v26.2d, #0xffffffff00000000\n\t"
      "sub v3.4s, v3.4s, v24.4s\n\t"
      "mov %[b_uv], v5.d[1]\n\t"
      "str q19, [%[st]]\n\t"
      "bit v28.16b, v16.16b, v29.16b\n\t"
      "shl v24.2d, v21.2d, #32\n\t"
      "bit v17.16b, v3.16b, v22.16b\n\t"
      "and v16.16b, v21.16b, v26.16b\n\t"
      "zip1 v27.2d, v28.2d, v23.2d\n\t"
      "uzp1 v4.4s, v4.4s, v6.4s\n\t"
      "shl v3.2d, v17.2d, #32\n\t"
      "and v2.16b, v17.16b, v26.16b\n\t"
      "shl v25.2d, v27.2d, #32\n\t"
      "and v27.16b, v27.16b, v26.16b\n\t"
      "ssra v16.2d, v24.2d, #32\n\t"
      "ssra v2.2d, v3.2d, #32\n\t"
      "fmov x3, d4\n\t"
      "mov x5, v4.d[1]\n\t"
      "ssra v27.2d, v25.2d, #32\n\t"
      "mov %[b_dd], v16.d[1]\n\t"
      "mov x1, v7.d[1]\n\t"
      "sub %w[a_d], %w[s], #1\n\t"
      "mov %[b_d], v2.d[1]\n\t"
      "mul %w[a_dd], %w[s], %w[a_d]\n\t"
      "csetm w14, hi\n\t"
      "lsr x2, x1, #32\n\t"
      "lsr %w[a_dd], %w[a_dd], #1\n\t"
      "lsr x6, x5, #32\n\t"
      "and w5, w5, w14\n\t"
      "and w6, w6, w14\n\t"
      "asr w8, w2, #31\n\t"
      "eor w15, w2, w8\n\t"
      "asr w12, w6, #31\n\t"
      "asr w11, w5, #31\n\t"
      "asr w7, w1, #31\n\t"
      "eor w16, w5, w11\n\t"
      "lsr x4, x3, #32\n\t"
      "eor w20, w4, w8\n\t"
      "eor w17, w6, w12\n\t"
      "eor w19, w3, w7\n\t"
      "sub w15, w15, w8\n\t"
      "sub w17, w17, w12\n\t"
      "sub w16, w16, w11\n\t"
      "sub w19, w19, w7\n\t"
      "eor w14, w1, w7\n\t"
      "eor w11, w5, w7\n\t"
      "sub w20, w20, w8\n\t"
      "sub w14, w14, w7\n\t"
      "eor w12, w6, w8\n\t"
      "sub w11, w11, w7\n\t"
      "sub w12, w12, w8\n\t"
      "msub w1, %w[s], w19, w14\n\t"
      "umsubl x17, w17, %w[a_dd], x15\n\t"
      "str q27, [%[st], #16]\n\t"
      "cmp %w[s], w1, lsl #1\n\t"
      "msub w2, %w[s], w20, w15\n\t"
      "mul w12, %w[a_d], w12\n\t"
      "mul w11, %w[a_d], w11\n\t"
      "cset w1, hi\n\t"
      "cmp %w[s], w2, lsl #1\n\t"
      "umsubl x16, w16, %w[a_dd], x14\n\t"
      "sub w20, w20, w12, asr #1\n\t"
      "sub w19, w19, w11, asr #1\n\t"
      "cset w2, hi\n\t"
      "and w1, w1, w11\n\t"
      "cmp x16, #0\n\t"
      "and w2, w2, w12\n\t"
      "sub w19, w19, w1\n\t"
      "sub w20, w20, w2\n\t"
      "eor w19, w19, w7\n\t"
      "eor w20, w20, w8\n\t"
      "csel w5, wzr, w5, lt\n\t"
      "sub w19, w19, w7\n\t"
      "csel w3, w3, w19, lt\n\t"
      "cmp x17, #0\n\t"
      "sub w20, w20, w8\n\t"
      "csel w6, wzr, w6, lt\n\t"
      "csel w4, w4, w20, lt\n\t"
      "lsl x11, x4, #32\n\t"
      "lsl x12, x6, #32\n\t"
      "add x12, x12, w5, sxtw\n\t"
      "add x11, x11, w3, sxtw\n\t"
      "fmov %[a_dd], d16\n\t"
      "fmov %[a_d], d2\n\t"
      "stp x11, x12, [%[st], #32]"
// END short_steps_k3i
      : [a_uv] "=&r"(ra_uv), [a_d] "=&r"(ra_d), [a_dd] "=&r"(ra_dd), [b_uv] "=&r"(rb_uv), [b_d] "=&r"(rb_d),
        [b_dd] "=&r"(rb_dd), "+&w"(rS44), "+&w"(rc01), "+&w"(rc23), "+&w"(rzs), "+&w"(rsd), "+&w"(rzc), "=m"(st)
      : "w"(rS01), "w"(rS23), [kp] "r"(kMidConsts), [y] "r"(&kRecipSteps[s]), [s] "r"(s), [st] "r"(st),
        "m"(kMidConsts), "m"(kRecipSteps)
      : "cc", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x11", "x12", "x14", "x15", "x16", "x17", "x19", "x20",
        "v0", "v2", "v4", "v6", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29");
  return MidFirst{ra_uv, ra_d, ra_dd, rb_uv, rb_d, rb_dd};
}
// Draws a second-order span of 49 .. 64 pixels (4 runs; last = n - 48 pixels in the last
// run) from the sample block's results (persp_short_inl): runs 0, 1 as one short_pass, then
// runs 2, 3 as one more (last == 16) or run 2 by Run16 and the last run by draw_run.
SB_INLINE void persp_mid_k3(uint8_t* dest, int last, const uint8_t* texels, int width, int32x4_t S01, int32x4_t S23,
                            int32x4_t S44, float64x2_t c01, float64x2_t c23, float64x2_t zs23, double zc) {
  uint64_t st[6];
  const MidFirst f = short_steps_k3i(S01, S23, S44, c01, c23, zs23, last > 2 ? last - 1 : 1, zc, st);
  short_pass<true>(dest, texels, uint64_t(width), f.a_uv, f.a_d, f.a_dd, f.b_uv, f.b_d, f.b_dd);
  if (last == 16) {
    short_pass<true>(dest + 32, texels, uint64_t(width), st[0], st[2], st[3], st[1], st[4], st[5]);
    return;
  }
  const uint32_t w = uint32_t(width);
  Run16<true> run(st[0], st[2], st[3], typename Run16<true>::Packed{});
  run.draw(dest + 32, texels, w);
  // draw_run takes the last run's steps unpacked: du = the low half, dv = (x - sext(du)) >> 32.
  auto lo = [](uint64_t x) { return uint32_t(x); };
  auto hi = [](uint64_t x) { return uint32_t((x - uint64_t(int64_t(int32_t(uint32_t(x))))) >> 32); };
  draw_run(dest + 48, last, texels, w, lo(st[1]), uint32_t(st[1] >> 32), lo(st[4]), hi(st[4]), lo(st[5]), hi(st[5]));
}
#endif

}  // namespace
}  // namespace sb::simd
