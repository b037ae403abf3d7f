// asm/span_persp_a64pair48.h: aarch64 only: short_samples2 (asm/span_persp_a64pair.h) for a
// pair of second-order spans of 17 .. 48 pixels each (two or three runs: samples 0 .. 3 used),
// short_samples48. Internal: included by asm/span_persp_fast.cpp after
// asm/span_persp_a64pair.h (anonymous namespace: internal linkage).
//
// Why: short_samples2 computes five samples a span (sample 4 for the four-run spans), the
// curve factors c23 and zs23's lane 1 (z_3 + z_4): a span of two or three runs reads none of
// them (short_rest's k = 1, 2 paths: persp_few_k1 / persp_few_k2 read S01, S23, c01, zs01's
// lane 1 or zs23's lane 0, zh). The pairs of the persp32 row (and of the engine's batches:
// bench/span_hist.md, 17-48 px spans in pairs) take this block; short_samples2 stays the
// pairs' block where a span has four runs.
//
// The block: short_samples2's lines (bench/mca_a53_p32i: ss_out.py) with
// - span b's S44 and c23 stores taken out (stp q13, q4 -> str q4 of zs01; str q28 dropped),
// - zs23 = trn1 / trn2 (z_2 + z_3 sums, z_3 + z_4 sums) replaced by their lane 0 alone (mov
//   v1 for span a: lane 1 then span b's z_2 + z_3, never read; dup v22.2d, v8.d[1] for span
//   b), so that z_4 is unread,
// - then every line whose result nothing reads dropped (bench/mca_a53_few/dce.py, live out
//   v5 v19 v9 v1 v3 v31 and the core outputs): sample 4's reciprocal steps (frecpe, frecps,
//   the fused steps), its divide in the fallback, its [u, v] products, conversions and
//   clamps, span a's S44 and c23 (227 -> 214 lines),
// - the next pair's test for n = 17 .. 48 (n - 17 - 32 negative: #32 for #48), so the loop of
//   these pairs goes on only while both next spans have two or three runs.
// The divide fallback's test still covers sample 4's depth (its lanes computed for it): a
// lane more can only take the divide path more often, whose results are exact for every lane.
// Outputs: outa in registers (S01 v5, S23 v19, zs01 v9, zs23 v1 (lane 0), c01 v3), outb
// stored (S01, S23, zs01, zs23 (lane 0 meaningful), c01; S44 and c23 left unwritten), the rest
// as short_samples2's. A53 model as two blocks (head to b.ne, tail from 2:), llvm-mca as loops:
// 162 + 70 -> 159 + 62 cycles (A57 95 + 48 -> 82 + 40) in short_samples2's order; then the head
// (to b.ne 2f) searched as qemu cuts it in pairs48_a64 (bench/order_search.py, the compiler's 11
// lines first, the page cut after 126 lines: 173 -> 166 cycles) and the tail (from 2:, with
// the compiler's 7 lines after it: 71 -> 63, A57 43 -> 40); bench/mca_a53_p32i/s48_s.s, spliced
// with ss_in.py (README there).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_a64pair.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
SB_INLINE void short_samples48(const PerspSpan& a, int na, const PerspSpan& b, int nb, ShortSamples& outa,
                               ShortSamples& outb, const PerspItem* it, const PerspItem* end, const PerspItem*& next,
                               int& runs_a, int& last_a, float64x2_t& zh_ab, float64x2_t& zh_mem) {
  uint64_t t_h, t_n0, t_n1, t_s1, t_z0, t_z1;
  register int32x4_t rS01 __asm__("v5");
  register int32x4_t rS23 __asm__("v19");
  register float64x2_t rzs01 __asm__("v9");
  register float64x2_t rzs23 __asm__("v1");
  register float64x2_t rc01 __asm__("v3");
  register float64x2_t rdz __asm__("v31");
  __asm__ volatile(
// BEGIN short_samples48
        "add x7, %[it], #264\n\t"
        "ldr q18, [%[kc], #16]\n\t"
        "ldr d31, [%[pa], #8]\n\t"
        "add x12, %[pb], #48\n\t"
        "ldr d4, [%[pa]]\n\t"
        "add %w[ra], %w[na], #15\n\t"
        "cmp %[end], x7\n\t"
        "asr %w[ra], %w[ra], #4\n\t"
        "ldr d0, [%[pa], #48]\n\t"
        "add x7, %[it], #176\n\t"
        "ldr d21, [%[pa], #16]\n\t"
        "csel x7, x7, %[it], hi\n\t"
        "ldr d2, [%[oa]]\n\t"
        "add x6, %[pa], #32\n\t"
        "ldr d7, [%[oa], #16]\n\t"
        "ldr q16, [%[kc]]\n\t"
        "cset %w[h], hi\n\t"
        "ld1 {v4.d}[1], [%[pb]]\n\t"
        "add x15, %[ob], #16\n\t"
        "ld1 {v0.d}[1], [x12]\n\t"
        "add x14, %[ob], #8\n\t"
        "ld1 {v2.d}[1], [%[ob]]\n\t"
        "add x9, %[pb], #8\n\t"
        "ldr d5, [%[oa], #8]\n\t"
        "add x8, %[pa], #56\n\t"
        "ldrb %w[s1], [x7, #168]\n\t"
        "ld1 {v7.d}[1], [x15]\n\t"
        "fadd v6.2d, v0.2d, v16.2d\n\t"
        "ldr %[z0], [x7, #24]\n\t"
        "sub %w[la], %w[na], %w[ra], lsl #4\n\t"
        "ld1 {v5.d}[1], [x14]\n\t"
        "add %w[la], %w[la], #16\n\t"
        "ldr %[z1], [x7, #112]\n\t"
        "ld1 {v31.d}[1], [x9]\n\t"
        "mov v1.16b, v4.16b\n\t"
        "fadd v17.2d, v6.2d, v16.2d\n\t"
        "mov v13.16b, v4.16b\n\t"
        "mov v11.16b, v4.16b\n\t"
        "fadd v8.2d, v0.2d, v2.2d\n\t"
        "mov v10.16b, v4.16b\n\t"
        "fadd v12.2d, v6.2d, v5.2d\n\t"
        "fadd v14.2d, v17.2d, v7.2d\n\t"
        "ldp q20, q9, [%[kc], #64]\n\t"
        "mov v22.16b, v18.16b\n\t"
        "fmla v1.2d, v31.2d, v8.2d\n\t"
        "fmla v10.2d, v31.2d, v0.2d\n\t"
        "fmla v11.2d, v31.2d, v6.2d\n\t"
        "fmla v4.2d, v31.2d, v14.2d\n\t"
        "fmla v13.2d, v31.2d, v12.2d\n\t"
        "mov v25.16b, v18.16b\n\t"
        "add x11, %[pb], #40\n\t"
        "fmaxnm v10.2d, v10.2d, v9.2d\n\t"
        "fmaxnm v11.2d, v11.2d, v9.2d\n\t"
        "fmaxnm v1.2d, v1.2d, v9.2d\n\t"
        "fmaxnm v13.2d, v13.2d, v9.2d\n\t"
        "mov v23.16b, v18.16b\n\t"
        "fmaxnm v4.2d, v4.2d, v9.2d\n\t"
        "frecpe v27.2d, v10.2d\n\t"
        "frecpe v28.2d, v11.2d\n\t"
        "frecpe v29.2d, v1.2d\n\t"
        "ld1 {v21.d}[1], [x6]\n\t"
        "frecpe v30.2d, v13.2d\n\t"
        "ldr %w[n0], [x7, #8]\n\t"
        "mov v24.16b, v18.16b\n\t"
        "frecps v2.2d, v10.2d, v27.2d\n\t"
        "frecps v5.2d, v11.2d, v28.2d\n\t"
        "frecps v17.2d, v1.2d, v29.2d\n\t"
        "frecps v7.2d, v13.2d, v30.2d\n\t"
        "ldp q19, q3, [%[kc], #32]\n\t"
        "add x10, %[pb], #32\n\t"
        "fmul v27.2d, v27.2d, v2.2d\n\t"
        "fmul v28.2d, v28.2d, v5.2d\n\t"
        "fmul v29.2d, v29.2d, v17.2d\n\t"
        "fmul v30.2d, v30.2d, v7.2d\n\t"
        "frecps v2.2d, v10.2d, v27.2d\n\t"
        "frecps v5.2d, v11.2d, v28.2d\n\t"
        "frecps v17.2d, v1.2d, v29.2d\n\t"
        "frecps v7.2d, v13.2d, v30.2d\n\t"
        "fmax v16.2d, v10.2d, v11.2d\n\t"
        "fmul v27.2d, v27.2d, v2.2d\n\t"
        "fmul v28.2d, v28.2d, v5.2d\n\t"
        "fmax v2.2d, v1.2d, v13.2d\n\t"
        "fmul v29.2d, v29.2d, v17.2d\n\t"
        "orr v9.16b, v13.16b, v19.16b\n\t"
        "fmul v30.2d, v30.2d, v7.2d\n\t"
        "orr v7.16b, v1.16b, v19.16b\n\t"
        "orr v5.16b, v10.16b, v19.16b\n\t"
        "fmax v16.2d, v16.2d, v2.2d\n\t"
        "orr v17.16b, v11.16b, v19.16b\n\t"
        "fmls v24.2d, v1.2d, v29.2d\n\t"
        "fmls v23.2d, v11.2d, v28.2d\n\t"
        "fmls v22.2d, v10.2d, v27.2d\n\t"
        "fmls v25.2d, v13.2d, v30.2d\n\t"
        "fmax v16.2d, v16.2d, v4.2d\n\t"
        "orr v2.16b, v4.16b, v19.16b\n\t"
        "uminp v19.4s, v5.4s, v17.4s\n\t"
        "ldrb %w[fl], [x7, #80]\n\t"
        "fmla v29.2d, v29.2d, v24.2d\n\t"
        "fmla v27.2d, v27.2d, v22.2d\n\t"
        "fmla v28.2d, v28.2d, v23.2d\n\t"
        "fmla v30.2d, v30.2d, v25.2d\n\t"
        "mov v23.16b, v18.16b\n\t"
        "cmhs v16.2d, v16.2d, v3.2d\n\t"
        "mov v25.16b, v18.16b\n\t"
        "uminp v22.4s, v7.4s, v9.4s\n\t"
        "mov v24.16b, v18.16b\n\t"
        "mov v3.16b, v18.16b\n\t"
        "ldr d9, [%[pb], #24]\n\t"
        "ldr d17, [%[pb], #16]\n\t"
        "uminp v26.4s, v2.4s, v16.4s\n\t"
        "umax v19.4s, v19.4s, v22.4s\n\t"
        "fmls v25.2d, v1.2d, v29.2d\n\t"
        "fmls v23.2d, v10.2d, v27.2d\n\t"
        "fmls v24.2d, v11.2d, v28.2d\n\t"
        "umax v19.4s, v19.4s, v26.4s\n\t"
        "ldr %w[n1], [x7, #96]\n\t"
        "ld1 {v17.d}[1], [x10]\n\t"
        "mov v2.16b, v21.16b\n\t"
        "mov v16.16b, v21.16b\n\t"
        "fmls v3.2d, v13.2d, v30.2d\n\t"
        "fmla v28.2d, v28.2d, v24.2d\n\t"
        "fmla v27.2d, v27.2d, v23.2d\n\t"
        "fmla v29.2d, v29.2d, v25.2d\n\t"
        "mov v24.16b, v17.16b\n\t"
        "add x7, %[pa], #40\n\t"
        "ld1 {v9.d}[1], [x11]\n\t"
        "ldr d7, [%[pa], #24]\n\t"
        "mov v23.16b, v17.16b\n\t"
        "umaxv s19, v19.4s\n\t"
        "mov v18.16b, v21.16b\n\t"
        "mov v25.16b, v17.16b\n\t"
        "ld1 {v7.d}[1], [x7]\n\t"
        "mov v22.16b, v21.16b\n\t"
        "mov v26.16b, v17.16b\n\t"
        "fmov w6, s19\n\t"
        "fmla v30.2d, v30.2d, v3.2d\n\t"
        "fmla v24.2d, v9.2d, v8.d[1]\n\t"
        "fmla v2.2d, v7.2d, v6.d[0]\n\t"
        "fmla v18.2d, v7.2d, v12.d[0]\n\t"
        "fmla v22.2d, v7.2d, v8.d[0]\n\t"
        "fmla v16.2d, v7.2d, v0.d[0]\n\t"
        "fmla v25.2d, v9.2d, v12.d[1]\n\t"
        "fmla v23.2d, v9.2d, v6.d[1]\n\t"
        "fmla v26.2d, v9.2d, v0.d[1]\n\t"
        "add x13, %[pb], #56\n\t"
        "cmn w6, #1\n\t"
        "b.ne 2f\n\t"
        "ldr q3, [%[kc], #16]\n\t"
        "fdiv v27.2d, v3.2d, v10.2d\n\t"
        "fdiv v28.2d, v3.2d, v11.2d\n\t"
        "fdiv v29.2d, v3.2d, v1.2d\n\t"
        "fdiv v30.2d, v3.2d, v13.2d\n\t"
        "2:\n\t"
        "sub %w[n1], %w[n1], #17\n\t"
        "sub %w[n0], %w[n0], #17\n\t"
        "fmul v16.2d, v16.2d, v27.d[0]\n\t"
        "fmul v22.2d, v22.2d, v29.d[0]\n\t"
        "fmul v14.2d, v31.2d, v20.2d\n\t"
        "fadd v6.2d, v28.2d, v29.2d\n\t"
        "fmul v2.2d, v2.2d, v28.d[0]\n\t"
        "fmul v24.2d, v24.2d, v29.d[1]\n\t"
        "fcvtzu v16.2d, v16.2d, #16\n\t"
        "fadd v0.2d, v27.2d, v28.2d\n\t"
        "fadd v8.2d, v29.2d, v30.2d\n\t"
        "fmul v26.2d, v26.2d, v27.d[1]\n\t"
        "fcvtzu v22.2d, v22.2d, #16\n\t"
        "fmul v18.2d, v18.2d, v30.d[0]\n\t"
        "fcvtzu v2.2d, v2.2d, #16\n\t"
        "fcvtzu v24.2d, v24.2d, #16\n\t"
        "uqxtn v5.2s, v16.2d\n\t"
        "fcvtzu v26.2d, v26.2d, #16\n\t"
        "uqxtn v19.2s, v22.2d\n\t"
        "fmul v23.2d, v23.2d, v28.d[1]\n\t"
        "trn1 v9.2d, v0.2d, v6.2d\n\t"
        "fmul v25.2d, v25.2d, v30.d[1]\n\t"
        "uqxtn2 v5.4s, v2.2d\n\t"
        "fcvtzu v18.2d, v18.2d, #16\n\t"
        "uqxtn v11.2s, v24.2d\n\t"
        "uqxtn v10.2s, v26.2d\n\t"
        "fcvtzu v23.2d, v23.2d, #16\n\t"
        "fcvtzu v25.2d, v25.2d, #16\n\t"
        "trn2 v4.2d, v0.2d, v6.2d\n\t"
        "uqxtn2 v19.4s, v18.2d\n\t"
        "ld1r {v2.2d}, [x8]\n\t"
        "tst %[z0], #0x7fffffffffffffff\n\t"
        "uqxtn2 v10.4s, v23.2d\n\t"
        "ld1r {v18.2d}, [x13]\n\t"
        "uqxtn2 v11.4s, v25.2d\n\t"
        "mov v1.16b, v8.16b\n\t"
        "fmov v20.2d, #0.5\n\t"
        "umin v19.4s, v19.4s, v2.4s\n\t"
        "umin v10.4s, v10.4s, v18.4s\n\t"
        "umin v5.4s, v5.4s, v2.4s\n\t"
        "umin v11.4s, v11.4s, v18.4s\n\t"
        "fmul v27.2d, v4.2d, v14.d[1]\n\t"
        "fmul v3.2d, v9.2d, v14.d[0]\n\t"
        "fmul v31.2d, v31.2d, v20.2d\n\t"
        "dup v22.2d, v8.d[1]\n\t"
        "stp q10, q11, [%[out], #0]\n\t"
        "and %w[fl], %w[fl], %w[s1]\n\t"
        "str q4, [%[out], #48]\n\t"
        "sub %[n1], %[n1], #32\n\t"
        "sub %[n0], %[n0], #32\n\t"
        "lsl %[z1], %[z1], #1\n\t"
        "ccmp %[z1], #0, #4, ne\n\t"
        "and %w[fl], %w[fl], %w[h]\n\t"
        "and %[n0], %[n0], %[n1]\n\t"
        "lsr %[n0], %[n0], #63\n\t"
        "and %w[fl], %w[fl], %w[n0]\n\t"
        "ccmp %w[fl], #0, #4, ne\n\t"
        "stp q22, q27, [%[out], #64]\n\t"
        "add %[n1], %[it], #176\n\t"
        "str q31, %[zb]\n\t"
        "csel %[fl], %[n1], xzr, ne"
// END short_samples48
      : "=&w"(rS01), "=&w"(rS23), "=&w"(rzs01), "=&w"(rzs23), "=&w"(rc01), [fl] "=&r"(next), [h] "=&r"(t_h),
        [n0] "=&r"(t_n0), [n1] "=&r"(t_n1), [s1] "=&r"(t_s1), [z0] "=&r"(t_z0), [z1] "=&r"(t_z1), [ra] "=&r"(runs_a),
        [la] "=&r"(last_a), "=&w"(rdz), [zb] "=m"(zh_mem)
      : [pa] "r"(&a), [pb] "r"(&b), [out] "r"(&outb), [kc] "r"(&kPairConsts), [oa] "r"(&kShortOffsets.at[na]),
        [ob] "r"(&kShortOffsets.at[nb]), [it] "r"(it), [end] "r"(end), [na] "r"(na)
      : "memory", "cc", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x13", "x14", "x15", "v0", "v2", "v4", "v6",
        "v7", "v8", "v10", "v11", "v12", "v13", "v14", "v16", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25",
        "v26", "v27", "v28", "v29", "v30");
  outa.S01 = rS01, outa.S23 = rS23;
  outa.zs01 = rzs01, outa.zs23 = rzs23, outa.c01 = rc01;
  zh_ab = rdz;
}
void batch_from(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
// Pairs of 17 .. 48 px spans as the first items of the batch's items left (batch_from: it[0],
// it[1] pair48_a64): short_samples48, then each span's rest without the four-run path, pair
// after pair while the block's next-pair test (both 17 .. 48 px) holds; then the items left by
// batch_from, reached with a tail branch (as persp_lin_a64 returns). Such pairs after other
// items stay spans_range's (short_samples2): a test in its loop moved its code against qemu's
// 4 KiB page cuts (persp64, A53 8.70 -> 8.79; inlined there 9.07). Page-aligned: its blocks
// do not move with the code before it.
__attribute__((noinline, aligned(4096))) void pairs48_a64(const PerspItem* it, const PerspItem* end,
                                                          const uint8_t* texels, int width) {
  ShortSamples sb;  // span b's samples (stored by the block)
  float64x2_t zhm;  // zh_ab as the block stores it
  // the block uses every vector register: d8 .. d15 saved once here, at entry
  __asm__ volatile("" ::: "v8", "v9", "v10", "v11", "v12", "v13", "v14", "v15");
  for (;;) {
    ShortSamples q;
    int runs, last;  // span a's, from the block
    float64x2_t zh2;
    const PerspItem* nx;
    short_samples48(it[0].span, it[0].n, it[1].span, it[1].n, q, sb, it, end, nx, runs, last, zh2, zhm);
    double zh = vgetq_lane_f64(zh2, 0);
#pragma GCC unroll 1
    for (int j = 0; j < 2; ++j, ++it) {
      short_rest<true, false, true>(it->dest, runs, last, texels, width, zh, q.S01, q.S23, q.S44, q.zs01, q.zs23,
                                    q.c01, q.c23);
      const int nb = it[1 - j].n;  // span b's n (span b itself after it: never past the pair)
      q = sb, runs = (nb + 15) >> 4, last = nb - 16 * (runs - 1), zh = vgetq_lane_f64(zhm, 1);
    }
    if (!nx) break;
    it = nx;
  }
  return batch_from(it, end, texels, width);
}
#endif

}  // namespace
}  // namespace sb::simd
