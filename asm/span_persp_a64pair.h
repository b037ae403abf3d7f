// asm/span_persp_a64pair.h: aarch64 only: two short second-order spans' samples in one asm
// block (short_samples2), for the batch entry (surface_spans_persp_fast in
// asm/span_persp_fast.cpp): each span's rest is then persp_short_inl's (short_rest,
// asm/span_persp_a64short.h). Internal: included by asm/span_persp_fast.cpp after
// asm/span_persp_arm.h (anonymous namespace: internal linkage).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp.h"
#include "asm/span_persp_a64short.h"
#include "asm/span_persp_run.h"
#include "asm/span_walk.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
// ShortSamples (asm/span_persp_a64short.h): what persp_short_inl's sample block gives.
static_assert(sizeof(ShortSamples) == 112 && offsetof(ShortSamples, S44) == 32 && offsetof(ShortSamples, zs01) == 48 &&
                  offsetof(ShortSamples, zs23) == 64 && offsetof(ShortSamples, c01) == 80 &&
                  offsetof(ShortSamples, c23) == 96,
              "short_samples2's stores");
static_assert(offsetof(PerspSpan, zi0) == 0 && offsetof(PerspSpan, dzi) == 8 && offsetof(PerspSpan, uz0) == 16 &&
                  offsetof(PerspSpan, duz) == 24 && offsetof(PerspSpan, vz0) == 32 && offsetof(PerspSpan, dvz) == 40 &&
                  offsetof(PerspSpan, px0) == 48 && offsetof(PerspSpan, umax) == 56 && offsetof(PerspSpan, vmax) == 60,
              "short_samples2's loads");
// The next pair's test (short_samples2's core work): item fields at these offsets (next
// items at it + 2 (176), it + 3 (264): n at 8, second_order at 80, dzi at 24 from an item);
// the n range 17 .. kShortMax as n - 17 < 48 in 32 bits (the 64-bit difference with 48 negative).
static_assert(sizeof(PerspItem) == 88 && offsetof(PerspItem, n) == 8 && offsetof(PerspItem, span) == 16 &&
                  offsetof(PerspSpan, second_order) == 64 && sizeof(PerspItem::span.second_order) == 1 &&
                  kShortMax - 16 == 48,
              "short_samples2's next-pair test");
// The block's constants (two lanes each): 16 (run to run), 1 (the Newton steps' 1 - b y),
// the significand test's mask (the high word's sign and exponent bits), 2^1000's bits (the
// range test), -1/16 (zck), kMinZi.
struct alignas(16) PairConsts {
  double k16[2], one[2];
  uint64_t mask[2], big[2];
  double kq[2], kmin[2];
};
static_assert(offsetof(PairConsts, one) == 16 && offsetof(PairConsts, mask) == 32 && offsetof(PairConsts, big) == 48 &&
              offsetof(PairConsts, kq) == 64 && offsetof(PairConsts, kmin) == 80);
constexpr PairConsts kPairConsts = {{16.0, 16.0},
                                    {1.0, 1.0},
                                    {0xfff0000000000000, 0xfff0000000000000},
                                    {0x7e70000000000000, 0x7e70000000000000},
                                    {-0.0625, -0.0625},
                                    {span_walk::kMinZi, span_walk::kMinZi}};
static_assert(__builtin_bit_cast(uint64_t, 0x1p1000) == 0x7e70000000000000);
// Per span length n (17 .. 64 used), the sample offsets persp_short_inl's block converts:
// o_0 = min(32, n - 1), o_1 = min(32, n - 17), o_2 = n - 33 (sample j + 2 at P_j + o_j).
struct alignas(32) ShortOffsets {
  double o[4];
};
struct ShortOffsetTable {
  ShortOffsets at[65];
  constexpr ShortOffsetTable() : at{} {
    for (int n = 0; n < 65; ++n)
      at[n] = ShortOffsets{{double(n - 1 < 32 ? n - 1 : 32), double(n - 17 < 32 ? n - 17 : 32), double(n - 33), 0.0}};
  }
};
constexpr ShortOffsetTable kShortOffsets;
static_assert(sizeof(ShortOffsets) == 32 && kShortOffsets.at[64].o[0] == 32.0 && kShortOffsets.at[40].o[1] == 23.0 &&
              kShortOffsets.at[17].o[2] == -16.0);

// Spans a and b (na, nb = 17 .. kShortMax pixels, both second order with dzi != 0): outa,
// outb = what persp_short_inl<true>'s sample block computes for each (the same bits). One
// asm block, each vector [span a's value, span b's value] of one sample k = 0 .. 4: positions
// P_0 (px0), P_1 = P_0 + 16, P_2 = P_1 + 16, sample 2 at P_0 + o_0, 3 at P_1 + o_1, 4 at P_2 + o_2
// (o_j from kShortOffsets: the single block's integer offsets converted); zi = zrow + zix
// pos (fmla); b = max(zi, kMinZi) (fmaxnm); the reciprocal as the single block's, lane by
// lane (frecpe, two frecps steps, two fused steps: asm/span_persp_a64short.h's proof), with
// the divide (1 / b, every lane) when some lane's b has a significand of all ones or b >=
// 2^1000: per lane b's high word OR 0xfff00000 and its low word both all ones (uminp of the
// words, umax over the five vectors, umaxv), the range by fmax of the five (positive: the
// bits order as the values) compared with 2^1000's bits. Each span's [u, v] per sample
// (uvrow + uvx pos, fmla by the position's lane), times z (by lane), fcvtzu #16, uqxtn /
// uqxtn2 into S01, S23, S44, umin with [umax, vmax]; zs01 = [z_0 + z_1, z_1 + z_2], zs23 =
// [z_2 + z_3, z_3 + z_4] (the sums of the pair vectors, then trn1 / trn2 to each span), c =
// zs (dzi * -1/16) by lane. Ordered for the in-order A53 (bench/mca_a53_pair: gen_pair.py,
// vsched.py, order_search.py; lines 0 .. 159 (to b.ne 2f) last searched as the loop head's qemu
// blocks cut them in the page-aligned spans_range, the compiler's 15 lines first,
// loop_r1f_s.s; lines 167 .. 241 (from 2:) with the compiler's 6 lines after them,
// loop_r2f_s.s); the accumulators are loaded (ldr d, ld1 lane), not copied.
// With it (this pair's items: it[0] = a's, it[1] = b's) and end, next = the loop's next pair:
// it + 2 if it + 3 < end and it[2], it[3] both pairable_a64 (n 17 .. kShortMax, second_order,
// dzi's bits other than the sign not all 0), else null (the chain ends); without branches: x7
// = it + 2, or it again when fewer than two items follow (read again, never past end); the
// fields loaded at the block's start (among its loads), tested after its last NEON
// instruction (core work between NEON instructions waits for their writebacks on the A53).
// zh_mem: zh_ab stored (span b's zh, loaded at its set-up: no NEON lane move in the tail).
// runs_a, last_a = span a's runs = (na + 15) >> 4 and last = na - 16 (runs - 1) (short_rest's),
// among the block's first loads. zh_ab = [a's dzi, b's dzi] * 0.5 (short_rest's zh, the same
// bits as a multiply after the block; v31: the dzi lanes as the block loads them, multiplied
// in its tail once zck's product has read them; the spans' rests take their zh from it, span
// a's lane 0 where steps_k3v_pass takes it: no copy before that block).
// Span a's samples are left in registers (outa: for its short_rest straight after the block,
// no store and load back), span b's stored (outb). The register names are bench/mca_a53_pair's
// order's (pair_cur.s) renamed (v1 -> v16, v3 -> v5, v4 -> v7, v5 -> v4, v7 -> v17, v9 -> v12,
// v12 -> v1, v16 -> v20, v17 -> v9, v20 -> v3, then v15 <-> v31): span a's outputs where steps_k3v_pass takes
// them (S01 v5, S23 v19, S44 v7, c01 v3, c23 v16, zs23 v1; the loop still moves two).
SB_INLINE void short_samples2(const PerspSpan& a, int na, const PerspSpan& b, int nb, ShortSamples& outa,
                              ShortSamples& outb, const PerspItem* it, const PerspItem* end, const PerspItem*& next,
                              int& runs_a, int& last_a, float64x2_t& zh_ab, float64x2_t& zh_mem) {
  uint64_t t_h, t_n0, t_n1, t_s1, t_z0, t_z1;
  register int32x4_t rS01 __asm__("v5");
  register int32x4_t rS23 __asm__("v19");
  register int32x4_t rS44 __asm__("v7");
  register float64x2_t rzs01 __asm__("v9");
  register float64x2_t rzs23 __asm__("v1");
  register float64x2_t rc01 __asm__("v3");
  register float64x2_t rc23 __asm__("v16");
  register float64x2_t rdz __asm__("v31");
  __asm__ volatile(
// BEGIN short_samples2
        "ldr q18, [%[kc], #16]\n\t"
        "add x12, %[pb], #48\n\t"
        "ldr d31, [%[pa], #8]\n\t"
        "add x9, %[pb], #8\n\t"
        "ldr d2, [%[oa]]\n\t"
        "add x7, %[it], #264\n\t"
        "ldr d4, [%[pa]]\n\t"
        "add %w[ra], %w[na], #15\n\t"
        "cmp %[end], x7\n\t"
        "asr %w[ra], %w[ra], #4\n\t"
        "ldr d0, [%[pa], #48]\n\t"
        "add x7, %[it], #176\n\t"
        "ldr d21, [%[pa], #16]\n\t"
        "add x6, %[pa], #32\n\t"
        "ldr d7, [%[oa], #16]\n\t"
        "sub %w[la], %w[na], %w[ra], lsl #4\n\t"
        "ldr q16, [%[kc]]\n\t"
        "csel x7, x7, %[it], hi\n\t"
        "ld1 {v4.d}[1], [%[pb]]\n\t"
        "add x15, %[ob], #16\n\t"
        "ld1 {v0.d}[1], [x12]\n\t"
        "add x14, %[ob], #8\n\t"
        "ld1 {v2.d}[1], [%[ob]]\n\t"
        "ldr d5, [%[oa], #8]\n\t"
        "ld1 {v7.d}[1], [x15]\n\t"
        "ldrb %w[s1], [x7, #168]\n\t"
        "fadd v6.2d, v0.2d, v16.2d\n\t"
        "mov v1.16b, v4.16b\n\t"
        "ldr %x[z0], [x7, #24]\n\t"
        "cset %w[h], hi\n\t"
        "ld1 {v5.d}[1], [x14]\n\t"
        "ld1 {v31.d}[1], [x9]\n\t"
        "ldr %x[z1], [x7, #112]\n\t"
        "fadd v17.2d, v6.2d, v16.2d\n\t"
        "mov v13.16b, v4.16b\n\t"
        "mov v11.16b, v4.16b\n\t"
        "fadd v8.2d, v0.2d, v2.2d\n\t"
        "mov v10.16b, v4.16b\n\t"
        "fadd v12.2d, v6.2d, v5.2d\n\t"
        "fadd v14.2d, v17.2d, v7.2d\n\t"
        "ldp q20, q9, [%[kc], #64]\n\t"
        "fmla v1.2d, v31.2d, v8.2d\n\t"
        "fmla v10.2d, v31.2d, v0.2d\n\t"
        "fmla v11.2d, v31.2d, v6.2d\n\t"
        "fmla v4.2d, v31.2d, v14.2d\n\t"
        "fmla v13.2d, v31.2d, v12.2d\n\t"
        "mov v25.16b, v18.16b\n\t"
        "ldp q19, q3, [%[kc], #32]\n\t"
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
        "frecpe v30.2d, v13.2d\n\t"
        "mov v24.16b, v18.16b\n\t"
        "frecpe v15.2d, v4.2d\n\t"
        "frecps v2.2d, v10.2d, v27.2d\n\t"
        "frecps v5.2d, v11.2d, v28.2d\n\t"
        "mov v22.16b, v18.16b\n\t"
        "frecps v17.2d, v1.2d, v29.2d\n\t"
        "frecps v7.2d, v13.2d, v30.2d\n\t"
        "frecps v9.2d, v4.2d, v15.2d\n\t"
        "fmul v27.2d, v27.2d, v2.2d\n\t"
        "mov v26.16b, v18.16b\n\t"
        "fmul v28.2d, v28.2d, v5.2d\n\t"
        "fmul v29.2d, v29.2d, v17.2d\n\t"
        "fmul v30.2d, v30.2d, v7.2d\n\t"
        "fmax v16.2d, v10.2d, v11.2d\n\t"
        "fmul v15.2d, v15.2d, v9.2d\n\t"
        "frecps v2.2d, v10.2d, v27.2d\n\t"
        "frecps v5.2d, v11.2d, v28.2d\n\t"
        "frecps v17.2d, v1.2d, v29.2d\n\t"
        "frecps v7.2d, v13.2d, v30.2d\n\t"
        "ldr %w[n0], [x7, #8]\n\t"
        "frecps v9.2d, v4.2d, v15.2d\n\t"
        "fmul v27.2d, v27.2d, v2.2d\n\t"
        "fmul v28.2d, v28.2d, v5.2d\n\t"
        "fmul v29.2d, v29.2d, v17.2d\n\t"
        "fmax v2.2d, v1.2d, v13.2d\n\t"
        "fmul v30.2d, v30.2d, v7.2d\n\t"
        "orr v5.16b, v10.16b, v19.16b\n\t"
        "orr v7.16b, v1.16b, v19.16b\n\t"
        "fmul v15.2d, v15.2d, v9.2d\n\t"
        "orr v17.16b, v11.16b, v19.16b\n\t"
        "fmax v16.2d, v16.2d, v2.2d\n\t"
        "fmls v24.2d, v1.2d, v29.2d\n\t"
        "fmls v22.2d, v10.2d, v27.2d\n\t"
        "fmls v23.2d, v11.2d, v28.2d\n\t"
        "fmls v25.2d, v13.2d, v30.2d\n\t"
        "fmls v26.2d, v4.2d, v15.2d\n\t"
        "orr v9.16b, v13.16b, v19.16b\n\t"
        "fmax v16.2d, v16.2d, v4.2d\n\t"
        "orr v2.16b, v4.16b, v19.16b\n\t"
        "uminp v19.4s, v5.4s, v17.4s\n\t"
        "fmla v29.2d, v29.2d, v24.2d\n\t"
        "fmla v28.2d, v28.2d, v23.2d\n\t"
        "fmla v30.2d, v30.2d, v25.2d\n\t"
        "fmla v15.2d, v15.2d, v26.2d\n\t"
        "fmla v27.2d, v27.2d, v22.2d\n\t"
        "mov v23.16b, v18.16b\n\t"
        "cmhs v16.2d, v16.2d, v3.2d\n\t"
        "mov v5.16b, v18.16b\n\t"
        "mov v24.16b, v18.16b\n\t"
        "uminp v22.4s, v7.4s, v9.4s\n\t"
        "mov v25.16b, v18.16b\n\t"
        "ldr d9, [%[pb], #24]\n\t"
        "add %w[la], %w[la], #16\n\t"
        "add x10, %[pb], #32\n\t"
        "ldr d17, [%[pb], #16]\n\t"
        "mov v3.16b, v18.16b\n\t"
        "uminp v26.4s, v2.4s, v16.4s\n\t"
        "umax v19.4s, v19.4s, v22.4s\n\t"
        "fmls v23.2d, v10.2d, v27.2d\n\t"
        "fmls v5.2d, v4.2d, v15.2d\n\t"
        "fmls v25.2d, v1.2d, v29.2d\n\t"
        "fmls v24.2d, v11.2d, v28.2d\n\t"
        "fmls v3.2d, v13.2d, v30.2d\n\t"
        "umax v19.4s, v19.4s, v26.4s\n\t"
        "ld1 {v17.d}[1], [x10]\n\t"
        "ldr %w[n1], [x7, #96]\n\t"
        "ldrb %w[fl], [x7, #80]\n\t"
        "fmla v29.2d, v29.2d, v25.2d\n\t"
        "fmla v27.2d, v27.2d, v23.2d\n\t"
        "fmla v28.2d, v28.2d, v24.2d\n\t"
        "mov v24.16b, v17.16b\n\t"
        "ld1 {v21.d}[1], [x6]\n\t"
        "add x7, %[pa], #40\n\t"
        "ld1 {v9.d}[1], [x11]\n\t"
        "ldr d7, [%[pa], #24]\n\t"
        "umaxv s19, v19.4s\n\t"
        "mov v23.16b, v17.16b\n\t"
        "mov v2.16b, v21.16b\n\t"
        "mov v25.16b, v17.16b\n\t"
        "ld1 {v7.d}[1], [x7]\n\t"
        "mov v18.16b, v21.16b\n\t"
        "mov v16.16b, v21.16b\n\t"
        "fmov w6, s19\n\t"
        "mov v22.16b, v21.16b\n\t"
        "mov v26.16b, v17.16b\n\t"
        "fmla v2.2d, v7.2d, v6.d[0]\n\t"
        "fmla v21.2d, v7.2d, v14.d[0]\n\t"
        "fmla v25.2d, v9.2d, v12.d[1]\n\t"
        "fmla v15.2d, v15.2d, v5.2d\n\t"
        "fmla v16.2d, v7.2d, v0.d[0]\n\t"
        "fmla v22.2d, v7.2d, v8.d[0]\n\t"
        "fmla v18.2d, v7.2d, v12.d[0]\n\t"
        "fmla v23.2d, v9.2d, v6.d[1]\n\t"
        "fmla v24.2d, v9.2d, v8.d[1]\n\t"
        "fmla v26.2d, v9.2d, v0.d[1]\n\t"
        "fmla v17.2d, v9.2d, v14.d[1]\n\t"
        "fmla v30.2d, v30.2d, v3.2d\n\t"
        "add x13, %[pb], #56\n\t"
        "cmn w6, #1\n\t"
        "add x8, %[pa], #56\n\t"
        "b.ne 2f\n\t"
        "ldr q3, [%[kc], #16]\n\t"
        "fdiv v27.2d, v3.2d, v10.2d\n\t"
        "fdiv v28.2d, v3.2d, v11.2d\n\t"
        "fdiv v29.2d, v3.2d, v1.2d\n\t"
        "fdiv v30.2d, v3.2d, v13.2d\n\t"
        "fdiv v15.2d, v3.2d, v4.2d\n\t"
        "2:\n\t"
        "fmul v18.2d, v18.2d, v30.d[0]\n\t"
        "fadd v12.2d, v30.2d, v15.2d\n\t"
        "fmul v16.2d, v16.2d, v27.d[0]\n\t"
        "fmul v21.2d, v21.2d, v15.d[0]\n\t"
        "fmul v22.2d, v22.2d, v29.d[0]\n\t"
        "fadd v6.2d, v28.2d, v29.2d\n\t"
        "fmul v24.2d, v24.2d, v29.d[1]\n\t"
        "fadd v8.2d, v29.2d, v30.2d\n\t"
        "fcvtzu v16.2d, v16.2d, #16\n\t"
        "fmul v2.2d, v2.2d, v28.d[0]\n\t"
        "fcvtzu v18.2d, v18.2d, #16\n\t"
        "fadd v0.2d, v27.2d, v28.2d\n\t"
        "fcvtzu v22.2d, v22.2d, #16\n\t"
        "fcvtzu v21.2d, v21.2d, #16\n\t"
        "fmul v26.2d, v26.2d, v27.d[1]\n\t"
        "fcvtzu v2.2d, v2.2d, #16\n\t"
        "uqxtn v5.2s, v16.2d\n\t"
        "fcvtzu v24.2d, v24.2d, #16\n\t"
        "uqxtn v19.2s, v22.2d\n\t"
        "uqxtn v7.2s, v21.2d\n\t"
        "fmul v17.2d, v17.2d, v15.d[1]\n\t"
        "trn1 v1.2d, v8.2d, v12.2d\n\t"
        "fmul v23.2d, v23.2d, v28.d[1]\n\t"
        "uqxtn2 v5.4s, v2.2d\n\t"
        "fmul v25.2d, v25.2d, v30.d[1]\n\t"
        "fcvtzu v26.2d, v26.2d, #16\n\t"
        "trn1 v9.2d, v0.2d, v6.2d\n\t"
        "ld1r {v2.2d}, [x8]\n\t"
        "uqxtn2 v7.4s, v21.2d\n\t"
        "fcvtzu v17.2d, v17.2d, #16\n\t"
        "fcvtzu v23.2d, v23.2d, #16\n\t"
        "uqxtn v10.2s, v26.2d\n\t"
        "uqxtn v11.2s, v24.2d\n\t"
        "fcvtzu v25.2d, v25.2d, #16\n\t"
        "trn2 v22.2d, v8.2d, v12.2d\n\t"
        "uqxtn2 v19.4s, v18.2d\n\t"
        "uqxtn v13.2s, v17.2d\n\t"
        "uqxtn2 v10.4s, v23.2d\n\t"
        "ld1r {v18.2d}, [x13]\n\t"
        "fmul v14.2d, v31.2d, v20.2d\n\t"
        "uqxtn2 v11.4s, v25.2d\n\t"
        "fmov v20.2d, #0.5\n\t"
        "umin v19.4s, v19.4s, v2.4s\n\t"
        "trn2 v4.2d, v0.2d, v6.2d\n\t"
        "uqxtn2 v13.4s, v17.2d\n\t"
        "fmul v28.2d, v22.2d, v14.d[1]\n\t"
        "umin v10.4s, v10.4s, v18.4s\n\t"
        "umin v11.4s, v11.4s, v18.4s\n\t"
        "fmul v31.2d, v31.2d, v20.2d\n\t"
        "fmul v27.2d, v4.2d, v14.d[1]\n\t"
        "umin v13.4s, v13.4s, v18.4s\n\t"
        "umin v7.4s, v7.4s, v2.4s\n\t"
        "fmul v3.2d, v9.2d, v14.d[0]\n\t"
        "stp q10, q11, [%[out], #0]\n\t"
        "tst %x[z0], #0x7fffffffffffffff\n\t"
        "and %w[fl], %w[fl], %w[s1]\n\t"
        "sub %w[n1], %w[n1], #17\n\t"
        "stp q13, q4, [%[out], #32]\n\t"
        "sub %w[n0], %w[n0], #17\n\t"
        "stp q22, q27, [%[out], #64]\n\t"
        "sub %x[n1], %x[n1], #48\n\t"
        "sub %x[n0], %x[n0], #48\n\t"
        "lsl %x[z1], %x[z1], #1\n\t"
        "str q28, [%[out], #96]\n\t"
        "and %x[n0], %x[n0], %x[n1]\n\t"
        "ccmp %x[z1], #0, #4, ne\n\t"
        "lsr %x[n0], %x[n0], #63\n\t"
        "and %w[fl], %w[fl], %w[h]\n\t"
        "and %w[fl], %w[fl], %w[n0]\n\t"
        "add %x[n1], %[it], #176\n\t"
        "ccmp %w[fl], #0, #4, ne\n\t"
        "umin v5.4s, v5.4s, v2.4s\n\t"
        "str q31, %[zb]\n\t"
        "csel %x[fl], %x[n1], xzr, ne\n\t"
        "fmul v16.2d, v1.2d, v14.d[0]"
// END short_samples2
      : "=&w"(rS01), "=&w"(rS23), "=&w"(rS44), "=&w"(rzs01), "=&w"(rzs23), "=&w"(rc01), "=&w"(rc23), [fl] "=&r"(next),
        [h] "=&r"(t_h), [n0] "=&r"(t_n0), [n1] "=&r"(t_n1), [s1] "=&r"(t_s1), [z0] "=&r"(t_z0), [z1] "=&r"(t_z1),
        [ra] "=&r"(runs_a), [la] "=&r"(last_a), "=&w"(rdz), [zb] "=m"(zh_mem)
      : [pa] "r"(&a), [pb] "r"(&b), [out] "r"(&outb), [kc] "r"(&kPairConsts), [oa] "r"(&kShortOffsets.at[na]),
        [ob] "r"(&kShortOffsets.at[nb]), [it] "r"(it), [end] "r"(end), [na] "r"(na)
      : "memory", "cc", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x13", "x14", "x15", "v0", "v2", "v4", "v6",
        "v8", "v10", "v11", "v12", "v13", "v14", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26",
        "v27", "v28", "v29", "v30", "v15");
  outa.S01 = rS01, outa.S23 = rS23, outa.S44 = rS44;
  outa.zs01 = rzs01, outa.zs23 = rzs23, outa.c01 = rc01, outa.c23 = rc23;
  zh_ab = rdz;
}
#endif

}  // namespace
}  // namespace sb::simd
