// asm/span_persp_a64few.h: aarch64 only, persp_short_inl's second-order path for two and
// three runs (17 .. 48 pixels): the four-run path's vector steps block (short_steps_k3v /
// steps_k3v_pass, asm/span_persp_a64mid.h) on the span's samples moved down one or two runs,
// so that the block's run 2 is a full run of this span and its run 3 this span's last run.
// Internal: included by asm/span_persp_a64short.h after asm/span_persp_a64mid.h (anonymous
// namespace: internal linkage).
//
// Why: the two- and three-run spans took short_rest's generic steps (a vector block for the
// full runs, then last_steps on the core for the last run, then the runs one by one): on the
// persp32 row (pairs of 17 .. 48 px) those steps blocks were ~240 cycles a span on the A53
// model, against ~134 for steps_k3v_pass with its first pass (32 pixels) inside.
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64mid.h"
#include "asm/span_persp_a64pass.h"
#endif

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
// A partial last run (1 .. 15 pixels) from Run16's packed start x = v 2^32 + u and steps d, dd
// (as steps_k3v_pass returns its second pass's run b): draw_last's chunks without unpacking.
SB_INLINE void draw_last_packed(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w,
                                uint64_t x, uint64_t d, uint64_t dd) {
  TailPos p{x, d, dd};
  auto chunk = [&](auto cc) SB_LAMBDA_INLINE {
    constexpr int C = decltype(cc)::value;
    uint8_t t[C];
    p = tail_load<C, true>(t, texels, w, p);
    tail_store<C>(dest, t);
    dest += C;
  };
  if (n & 8) chunk(std::integral_constant<int, 8>{});
  if (n & 4) chunk(std::integral_constant<int, 4>{});
  if (n & 2) chunk(std::integral_constant<int, 2>{});
  if (n & 1) chunk(std::integral_constant<int, 1>{});
}
// A partial last run (last = 1 .. 15 pixels) at d[48 .. 47 + last] from Run16's packed start
// l_uv and steps l_d, l_dd: runs_k3's chunks (asm/span_persp_a64mid.h) without its run 2 (its
// four stores taken out and every line whose result nothing then reads:
// bench/mca_a53_few/dce.py on runs_k3's block, bench/mca_a53_few/last_k3_dce.s; the chunks
// keep their searched order). d is 48 bytes before the last run (the chunks' addressing).
SB_INLINE void last_chunks(uint8_t* __restrict d, const uint8_t* __restrict tx, uint64_t w, int last, uint64_t l_uv,
                           uint64_t l_d, uint64_t l_dd) {
  register uint64_t r23 __asm__("x23") = l_uv;
  register uint64_t r24 __asm__("x24") = l_d;
  register uint64_t r25 __asm__("x25") = l_dd;
  __asm__ volatile(
// BEGIN last_chunks
      "add x21, x23, x24\n\t"
      "add x22, x25, x24, lsl #1\n\t"
      "lsl x8, x25, #2\n\t"
      "add x5, x22, x25, lsl #1\n\t"
      "lsr w3, w23, #16\n\t"
      "lsr w19, w21, #16\n\t"
      "add x12, %[d], #48\n\t"
      "lsr x2, x23, #48\n\t"
      "lsr x15, x21, #48\n\t"
      "madd w20, w2, %w[w], w3\n\t"
      "madd w17, w15, %w[w], w19\n\t"
      "tbz %w[n], #3, 1f\n\t"
      "add x23, x23, x22\n\t"
      "add x22, x22, x8\n\t"
      "add x21, x21, x5\n\t"
      "lsr w1, w21, #16\n\t"
      "lsr w16, w23, #16\n\t"
      "lsr x25, x23, #48\n\t"
      "add x23, x23, x22\n\t"
      "lsr x11, x21, #48\n\t"
      "madd w6, w25, %w[w], w16\n\t"
      "add x5, x5, x8\n\t"
      "ldrb w14, [%[tx], w17, uxtw]\n\t"
      "madd w4, w11, %w[w], w1\n\t"
      "ldrb w7, [%[tx], w20, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "add x21, x21, x5\n\t"
      "lsr x3, x21, #48\n\t"
      "lsr x24, x23, #48\n\t"
      "add x5, x5, x8\n\t"
      "lsr w2, w23, #16\n\t"
      "lsr w15, w21, #16\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w16, [%[tx], w4, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "orr x19, x7, x14, lsl #8\n\t"
      "lsr w14, w23, #16\n\t"
      "madd w11, w24, %w[w], w2\n\t"
      "madd w1, w3, %w[w], w15\n\t"
      "ldrb w25, [%[tx], w6, uxtw]\n\t"
      "add x5, x5, x8\n\t"
      "lsr x7, x23, #48\n\t"
      "add x22, x22, x8\n\t"
      "lsr w4, w21, #16\n\t"
      "lsr x6, x21, #48\n\t"
      "orr x24, x25, x16, lsl #8\n\t"
      "madd w25, w7, %w[w], w14\n\t"
      "ldrb w3, [%[tx], w11, uxtw]\n\t"
      "madd w16, w6, %w[w], w4\n\t"
      "orr x2, x19, x24, lsl #16\n\t"
      "ldrb w15, [%[tx], w1, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w24, [%[tx], w25, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "ldrb w11, [%[tx], w16, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "lsr w4, w23, #16\n\t"
      "orr x19, x3, x15, lsl #8\n\t"
      "lsr x3, x21, #48\n\t"
      "lsr x6, x23, #48\n\t"
      "orr x1, x24, x11, lsl #8\n\t"
      "lsr w15, w21, #16\n\t"
      "orr x7, x19, x1, lsl #16\n\t"
      "madd w17, w3, %w[w], w15\n\t"
      "madd w20, w6, %w[w], w4\n\t"
      "orr x14, x2, x7, lsl #32\n\t"
      "add x5, x5, x8\n\t"
      "str x14, [x12], #8\n\t"
      "1:\n\t"
      "tbz %w[n], #2, 2f\n\t"
      "add x23, x23, x22\n\t"
      "lsr w16, w23, #16\n\t"
      "lsr x25, x23, #48\n\t"
      "add x21, x21, x5\n\t"
      "lsr x24, x21, #48\n\t"
      "lsr w11, w21, #16\n\t"
      "add x5, x5, x8\n\t"
      "madd w2, w25, %w[w], w16\n\t"
      "madd w7, w24, %w[w], w11\n\t"
      "ldrb w19, [%[tx], w20, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "lsr w16, w21, #16\n\t"
      "ldrb w1, [%[tx], w17, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "ldrb w6, [%[tx], w2, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w4, [%[tx], w7, uxtw]\n\t"
      "lsr x25, x21, #48\n\t"
      "lsr x5, x23, #48\n\t"
      "orr x14, x19, x1, lsl #8\n\t"
      "madd w17, w25, %w[w], w16\n\t"
      "add x22, x22, x8\n\t"
      "orr x3, x6, x4, lsl #8\n\t"
      "lsr w8, w23, #16\n\t"
      "madd w20, w5, %w[w], w8\n\t"
      "orr x15, x14, x3, lsl #16\n\t"
      "str w15, [x12], #4\n\t"
      "2:\n\t"
      "tbz %w[n], #1, 3f\n\t"
      "ldrb w11, [%[tx], w17, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w24, [%[tx], w20, uxtw]\n\t"
      "lsr x1, x23, #48\n\t"
      "lsr w2, w23, #16\n\t"
      "madd w20, w1, %w[w], w2\n\t"
      "orr x19, x24, x11, lsl #8\n\t"
      "strh w19, [x12], #2\n\t"
      "3:\n\t"
      "tbz %w[n], #0, 4f\n\t"
      "ldrb w7, [%[tx], w20, uxtw]\n\t"
      "strb w7, [x12]\n\t"
      "4:"
// END last_chunks
      : "+r"(r23), "+r"(r24), "+r"(r25)
      : [d] "r"(d), [tx] "r"(tx), [w] "r"(w), [n] "r"(last)
      : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x11", "x12", "x14", "x15", "x16", "x17", "x19", "x20", "x21",
        "x22", "memory");
}
// Three runs (33 .. 48 pixels; last = n - 32 = 1 .. 16 pixels in run 2), second order, from
// the sample block's S01 = [u_0, v_0, u_1, v_1], S23 = [u_2, v_2, u_3, v_3], c01 (runs 0, 1's
// curve factors), zs23 = [z_2 + z_3, ...] and zh = zc / 2. steps_k3v_pass with its inputs
// moved: S23' = [S_2, S_2], S44' = [S_3, ..]. The block takes run 1's delta from S23''s low
// half (S_2: as the four-run span's), its run 2 is S_2 - S_2 (a full run of delta 0, unused)
// and its run 3 is S_3 - S_2 from S_2, this span's last run (z_2 + z_3 in zs23'[1]). Its first
// pass draws runs 0 and 1 (S01 and c01 as the four-run span's), its second-pass run b is the
// last run. Then the last run: 16 pixels (full) or draw_last's chunks. The same bits as
// short_rest's k = 2 path: each lane is the four-run block's, which
// AsmSpanPersp.ShortStepsK3vMatchTheirParts checks against steps16_dd and last_steps.
SB_INLINE void persp_few_k2(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01,
                            int32x4_t S23, float64x2_t c01, float64x2_t zs23, double zh) {
  uint64_t st[6];
  bool full;
  const int32x4_t S22 = vreinterpretq_s32_u64(vdupq_laneq_u64(vreinterpretq_u64_s32(S23), 0));
  const int32x4_t S33 = vreinterpretq_s32_u64(vdupq_laneq_u64(vreinterpretq_u64_s32(S23), 1));
  const MidFirst second = steps_k3v_pass(dest, texels, uint64_t(width), S01, S22, S33, c01, c01,
                                         vdupq_laneq_f64(zs23, 0), last - 1, zh, st, full);
  if (full) {
    Run16<true> run(second.b_uv, second.b_d, second.b_dd, Run16<true>::Packed{});
    run.draw(dest + 32, texels, uint32_t(width));
    return;
  }
  last_chunks(dest - 16, texels, uint64_t(width), last, second.b_uv, second.b_d, second.b_dd);
}
// steps_k3v_pass for a two-run span (17 .. 32 pixels): its inputs S01, S23' = S01, S44' = S23
// ([S_2, ..]; read in v5 and v19, where short_rest keeps S01 and S23: the block's lines renamed
// by bench/mca_a53_few/rename_k1.py), c01, c23' = c01, zs23' = zs01 = [.., z_1 + z_2], s =
// last - 1, zh: the first
// pass's run a is run 0 (D01's lanes 0, 1: S_1 - S_0, c01[0]), drawn at dest[0 .. 15]; its run
// 3 is S_2 - S_1 from S_1 (D23's lanes 2, 3; z_1 + z_2), this span's last run, returned packed
// in x23 (start), x24, x25 (steps: Run16's packing); full iff last == 16. The block is
// steps_k3v_pass's with run b's four stores taken out and every line whose result nothing
// then reads (bench/mca_a53_few/dce.py: run b's pixels, D01's lanes 2, 3 where only they
// feed, the second pass's run a), ordered by bench/order_search.py
// (bench/mca_a53_few/k1vp_s.s; bench/mca_a53_few/names.py splices it here).
SB_INLINE void steps_k1v_pass(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint64_t width,
                              int32x4_t S01, int32x4_t S23, float64x2_t c01, float64x2_t zs01, int s, double zh,
                              uint64_t& l_uv, uint64_t& l_d, uint64_t& l_dd, bool& full) {
  uint64_t st[6];
  register uint64_t rb_uv __asm__("x23"), rb_d __asm__("x24"), rb_dd __asm__("x25");
  register int32x4_t rS01 __asm__("v5") = S01;
  register int32x4_t rS23 __asm__("v19") = S23;
  register float64x2_t rc01 __asm__("v3") = c01;
  register float64x2_t rc23 __asm__("v16") = c01;
  register float64x2_t rzs __asm__("v1") = zs01;
  register double rzc __asm__("v31") = zh;
  uint64_t ys = uint32_t(s);
  __asm__ volatile(
// BEGIN steps_k1v_pass
      "ext v7.16b, v5.16b, v19.16b, #8\n\t"
      "fmov x13, d5\n\t"
      "ext v0.16b, v5.16b, v5.16b, #8\n\t"
      "ldp q6, q17, [%[kp], #32]\n\t"
      "str q5, [%[st]]\n\t"
      "add %[y], %[kp], %[y], lsl #7\n\t"
      "sub v7.4s, v7.4s, v5.4s\n\t"
      "sub v0.4s, v0.4s, v5.4s\n\t"
      "ldp q23, q24, [%[y], #128]\n\t"
      "ldp q21, q22, [%[y], #96]\n\t"
      "saddw2 v29.2d, v6.2d, v7.4s\n\t"
      "saddw v26.2d, v6.2d, v0.2s\n\t"
      "saddw v28.2d, v6.2d, v7.2s\n\t"
      "saddw2 v27.2d, v6.2d, v0.4s\n\t"
      "fsub v29.2d, v29.2d, v6.2d\n\t"
      "fmul d31, d31, v1.d[1]\n\t"
      "fsub v26.2d, v26.2d, v6.2d\n\t"
      "fsub v27.2d, v27.2d, v6.2d\n\t"
      "fsub v28.2d, v28.2d, v6.2d\n\t"
      "fmul v30.2d, v29.2d, v24.d[0]\n\t"
      "ldr q25, [%[y], #160]\n\t"
      "fmul v26.2d, v26.2d, v3.d[0]\n\t"
      "fmul v27.2d, v27.2d, v3.d[1]\n\t"
      "fmul v28.2d, v28.2d, v16.d[0]\n\t"
      "fmul d31, d31, v25.d[0]\n\t"
      "fmls v29.2d, v30.2d, v24.d[1]\n\t"
      "fcvtzs v26.2d, v26.2d\n\t"
      "fcvtzs v27.2d, v27.2d\n\t"
      "fcvtzs v28.2d, v28.2d\n\t"
      "ldp q18, q20, [%[y], #64]\n\t"
      "sqxtn v6.2s, v26.2d\n\t"
      "fmla v30.2d, v29.2d, v24.d[0]\n\t"
      "sqxtn v1.2s, v28.2d\n\t"
      "sshr v28.4s, v0.4s, #31\n\t"
      "ldp q2, q4, [%[kp]]\n\t"
      "sqxtn2 v6.4s, v27.2d\n\t"
      "fcvtzs v25.2d, v30.2d\n\t"
      "fmul v30.2d, v30.2d, v31.d[0]\n\t"
      "abs v27.4s, v7.4s\n\t"
      "sshr v29.4s, v7.4s, #31\n\t"
      "ushr v9.4s, v28.4s, #28\n\t"
      "abs v25.2d, v25.2d\n\t"
      "fcvtzs v30.2d, v30.2d\n\t"
      "ushr v31.4s, v27.4s, #4\n\t"
      "add v9.4s, v0.4s, v9.4s\n\t"
      "abs v3.4s, v6.4s\n\t"
      "abs v26.4s, v0.4s\n\t"
      "sqxtn2 v1.4s, v30.2d\n\t"
      "xtn2 v31.4s, v25.2d\n\t"
      "mov v25.16b, v27.16b\n\t"
      "mul v7.4s, v6.4s, v2.s[0]\n\t"
      "umin v3.4s, v3.4s, v4.4s\n\t"
      "abs v0.4s, v1.4s\n\t"
      "mul v4.4s, v20.4s, v1.4s\n\t"
      "mls v25.4s, v18.4s, v31.4s\n\t"
      "sshr v24.4s, v9.4s, #4\n\t"
      "shsub v9.4s, v9.4s, v7.4s\n\t"
      "mul v3.4s, v3.4s, v2.4s\n\t"
      "cmhi v16.4s, v17.4s, v0.4s\n\t"
      "umin v0.4s, v0.4s, v22.4s\n\t"
      "cmhi v25.4s, v23.4s, v25.4s\n\t"
      "sshr v22.4s, v4.4s, #1\n\t"
      "eor v30.16b, v31.16b, v29.16b\n\t"
      "srshr v4.4s, v4.4s, #1\n\t"
      "cmhs v3.4s, v26.4s, v3.4s\n\t"
      "mul v0.4s, v0.4s, v21.4s\n\t"
      "eor v25.16b, v25.16b, v29.16b\n\t"
      "sshr v9.4s, v9.4s, #3\n\t"
      "sub v30.4s, v30.4s, v29.4s\n\t"
      "cmhs v0.4s, v27.4s, v0.4s\n\t"
      "bit v22.16b, v4.16b, v25.16b\n\t"
      "and v6.16b, v6.16b, v3.16b\n\t"
      "bit v24.16b, v9.16b, v3.16b\n\t"
      "and v0.16b, v0.16b, v16.16b\n\t"
      "sub v21.4s, v30.4s, v22.4s\n\t"
      "fmov x10, d6\n\t"
      "fmov x9, d24\n\t"
      "and v1.16b, v1.16b, v0.16b\n\t"
      "bit v30.16b, v21.16b, v0.16b\n\t"
      "and x1, x9, #0xffffffff00000000\n\t"
      "and x2, x10, #0xffffffff00000000\n\t"
      "add x10, x2, w10, sxtw\n\t"
      "lsl x20, x10, #2\n\t"
      "add x9, x1, w9, sxtw\n\t"
      "lsr x1, x13, #48\n\t"
      "stp q30, q1, [%[st], #16]\n\t"
      "add x17, x10, x9, lsl #1\n\t"
      "add x14, x13, x9\n\t"
      "add x19, x17, x10, lsl #1\n\t"
      "add x15, x13, x17\n\t"
      "lsr w9, w13, #16\n\t"
      "lsr x2, x14, #48\n\t"
      "add x17, x17, x20\n\t"
      "lsr w10, w14, #16\n\t"
      "add x13, x15, x17\n\t"
      "lsr x3, x15, #48\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "add x16, x14, x19\n\t"
      "add x19, x19, x20\n\t"
      "lsr w11, w15, #16\n\t"
      "lsr x5, x13, #48\n\t"
      "lsr w9, w13, #16\n\t"
      "add x17, x17, x20\n\t"
      "add x15, x13, x17\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "add x14, x16, x19\n\t"
      "lsr x7, x15, #48\n\t"
      "add x19, x19, x20\n\t"
      "add x13, x15, x17\n\t"
      "lsr x4, x16, #48\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr x6, x14, #48\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "add x16, x14, x19\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "add x19, x19, x20\n\t"
      "add x17, x17, x20\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x8, x16, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "add x15, x13, x17\n\t"
      "add x17, x17, x20\n\t"
      "lsr w9, w13, #16\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "add x14, x16, x19\n\t"
      "lsr x1, x13, #48\n\t"
      "add x13, x15, x17\n\t"
      "lsr x3, x15, #48\n\t"
      "add x19, x19, x20\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr w11, w15, #16\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "add x16, x14, x19\n\t"
      "str w15, [%[d]]\n\t"
      "add x19, x19, x20\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "add x15, x13, x17\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "lsr x2, x14, #48\n\t"
      "lsr w10, w14, #16\n\t"
      "add x14, x16, x19\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "add x19, x19, x20\n\t"
      "lsr x4, x16, #48\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr x6, x14, #48\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x5, x13, #48\n\t"
      "lsr w9, w13, #16\n\t"
      "lsr x7, x15, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "add x16, x14, x19\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "str w15, [%[d], #4]\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "lsr x8, x16, #48\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "lsr w12, w16, #16\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "str w15, [%[d], #8]\n\t"
      "ldr x24, [%[st], #24]\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "str w15, [%[d], #12]\n\t"
      "ldr x25, [%[st], #40]\n\t"
      "and x13, x24, #0xffffffff00000000\n\t"
      "add x24, x13, w24, sxtw\n\t"
      "and x13, x25, #0xffffffff00000000\n\t"
      "add x25, x13, w25, sxtw\n\t"
      "ldr w1, [%[y], #72]\n\t"
      "ldr x23, [%[st], #8]\n\t"
      "cmp w1, #0xf"
// END steps_k1v_pass
      : "=&r"(rb_uv), "=&r"(rb_d), "=&r"(rb_dd), "+&w"(rc01), "+&w"(rc23), "+&w"(rzs), "+&w"(rzc),
        "=@cceq"(full), [y] "+&r"(ys)
      : "w"(rS01), "w"(rS23), [kp] "r"(kMidTable.c), [st] "r"(st), [d] "r"(dest), [tx] "r"(texels), [w] "r"(width)
      : "memory", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17", "x19", "x20", "x21", "x22", "v0", "v2", "v4", "v6", "v7", "v9", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30");
  l_uv = rb_uv, l_d = rb_d, l_dd = rb_dd;
}
// Two runs (17 .. 32 pixels; last = n - 16 = 1 .. 16 pixels in run 1): steps_k1v_pass (run 0
// drawn in it), then the last run: 16 pixels (full) or draw_last's chunks.
SB_INLINE void persp_few_k1(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01,
                            int32x4_t S23, float64x2_t c01, float64x2_t zs01, double zh) {
  uint64_t luv, ld, ldd;
  bool full;
  steps_k1v_pass(dest, texels, uint64_t(width), S01, S23, c01, zs01, last - 1, zh, luv, ld, ldd, full);
  if (full) {
    Run16<true> run(luv, ld, ldd, Run16<true>::Packed{});
    run.draw(dest + 16, texels, uint32_t(width));
    return;
  }
  last_chunks(dest - 32, texels, uint64_t(width), last, luv, ld, ldd);
}
// Two runs (17 .. 32 pixels; last = n - 16 = 1 .. 16 pixels in run 1): short_steps_k3v with
// S23' = S01 (its run 2 is run 0, factor c23' = c01), S44' = S23 (its low half S_2: its run 3
// is run 1, the last, with z_1 + z_2 = zs01[1] in zs23' = zs01); its runs 0, 1 (S01' = S01,
// computed, unused). Then both runs as one short_pass (last == 16) or run 0 and the partial
// last run by runs_k3 (which draws at d + 32: d = dest - 32).
SB_INLINE void persp_few_k1_steps(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01,
                            int32x4_t S23, float64x2_t c01, float64x2_t zs01, double zh) {
  uint64_t st[6];
  (void)short_steps_k3v(S01, S01, S23, c01, c01, zs01, last - 1, zh, st);
  const uint64_t d0 = mid_pack(st[2]), dd0 = mid_pack(st[4]), ld = mid_pack(st[3]), ldd = mid_pack(st[5]);
  if (last == 16) {
    short_pass<true>(dest, texels, uint64_t(width), st[0], d0, dd0, st[1], ld, ldd);
    return;
  }
  runs_k3(dest - 32, texels, uint64_t(width), last, st[0], d0, dd0, st[1], ld, ldd);
}
#endif

}  // namespace
}  // namespace sb::simd
