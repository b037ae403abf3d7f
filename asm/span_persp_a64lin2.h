// asm/span_persp_a64lin2.h: aarch64 only, two neighbouring linear spans of 17 .. 64 pixels
// each (persp_short_lin's, asm/span_persp_a64lin.h) with their set-ups in one asm block:
// the two spans' latency chains (positions, depths, Newton reciprocals) interleave, so the
// pair pays them about once. Internal: included by asm/span_persp_a64short.h.
//
// The block (written from bench/mca_a53_lin2/pair.s by bench/to_inline.py) computes, for each
// span, exactly what short_lin_setup's block computes (see its comment; the same operations
// on the same values, so the same bits):
// - positions [P_0, P_1] = [P_0, P_0] + [0, 16], samples 2, 3 at [P_0, P_1] + [o_0, o_1],
//   sample 4 at ((P_0 + 16) + 16) + o_2 (both spans' sample 4 in the two lanes of one vector);
// - depths max(zi0 + dzi pos, kMinZi) (fused), Newton reciprocals (frecpe, two frecps steps,
//   two fused refinements), the divides on the fallback branch for both spans when either
//   span's test fails (the test of short_lin_setup over all ten depths);
// - [u, v] = [uz0, vz0] + [duz, dvz] pos (fused), times the reciprocal, min with [umax,
//   vmax] 2^-16, fcvtzu #16.
// Span a's samples go to the core registers and on through short_lin_setup's integer steps
// (the same instructions, the outputs in the same registers, but for the last run's two
// quotients: the row's magic(s) and smulh instead of sdiv, the same values; see ShortLinPos
// in asm/span_persp_a64lin.h); span b's converted samples are stored to buf (ten uint64:
// [u, v] of samples 0 .. 4), for short_lin_finish after span a is drawn
// (AsmSpanPerspBatch.PairedLinearSetupMatchesTwoSingleSetups checks both against
// short_lin_setup, every output).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp.h"
#include "asm/span_persp_a64lin.h"

namespace sb::simd {
namespace {

// Span a's ShortLinSetup (as short_lin_setup(na, pa)); span b's samples to buf (see above).
SB_INLINE ShortLinSetup short_lin_setup2(int na, const PerspSpan& pa, int nb, const PerspSpan& pb,
                                         uint64_t* buf) {
  register const PerspSpan* rpa __asm__("x4") = &pa;
  register const PerspSpan* rpb __asm__("x0") = &pb;
  register uint64_t rna __asm__("x7") = uint64_t(uint32_t(na));
  register uint64_t rnb __asm__("x27") = uint64_t(uint32_t(nb));
  register uint64_t* rbuf __asm__("x26") = buf;
  register const double* rkm __asm__("x2") = &kMinZi;
  register const ShortLinPos* rtab __asm__("x11") = &kShortLinPos;
  register uint64_t rx0 __asm__("x13");  // span a's outputs, as short_lin_setup's
  register uint64_t rx1 __asm__("x23");
  register uint64_t rx2 __asm__("x19");
  register uint64_t rx3 __asm__("x25");
  register uint64_t rd0 __asm__("x9");
  register uint64_t rd1 __asm__("x24");
  register uint64_t rd2 __asm__("x20");
  register uint64_t rld __asm__("x28");
  __asm__ volatile(
// BEGIN lin_pair
        "add x14, x0, #48\n\t"
        "ld1r {v10.2d}, [x4]\n\t"
        "sub w22, w7, #1\n\t"
        "add x10, x4, #48\n\t"
        "add x9, x11, x7, lsl #5\n\t"
        "fmov v1.2d, #16.0\n\t"
        "ld1r {v3.2d}, [x10]\n\t"
        "add x15, x4, #16\n\t"
        "ld1r {v9.2d}, [x10]\n\t"
        "add x16, x0, #16\n\t"
        "ld1r {v8.2d}, [x14]\n\t"
        "ldr q6, [x11]\n\t"
        "sub x7, x9, #504\n\t"
        "ld1 {v3.d}[1], [x14]\n\t"
        "add x12, x11, x27, lsl #5\n\t"
        "ld2 {v16.d, v17.d}[0], [x4]\n\t"
        "ldp q4, q5, [x9, #-528]\n\t"
        "fadd v0.2d, v9.2d, v6.2d\n\t"
        "fadd v3.2d, v3.2d, v1.2d\n\t"
        "ldp q13, q14, [x12, #-528]\n\t"
        "ldr x7, [x7]\n\t"
        "ld1r {v2.2d}, [x0]\n\t"
        "fadd v15.2d, v8.2d, v6.2d\n\t"
        "zip1 v5.2d, v5.2d, v14.2d\n\t"
        "ld2 {v22.2d, v23.2d}, [x15]\n\t"
        "fadd v3.2d, v3.2d, v1.2d\n\t"
        "fmov v1.2d, #1.0\n\t"
        "ld1r {v11.2d}, [x4]\n\t"
        "ld1r {v12.2d}, [x0]\n\t"
        "fadd v30.2d, v15.2d, v13.2d\n\t"
        "ld2 {v16.d, v17.d}[1], [x0]\n\t"
        "fadd v3.2d, v3.2d, v5.2d\n\t"
        "mov v20.16b, v22.16b\n\t"
        "ld1r {v31.2d}, [x2]\n\t"
        "mov v18.16b, v22.16b\n\t"
        "fadd v7.2d, v0.2d, v4.2d\n\t"
        "mov v21.16b, v22.16b\n\t"
        "fmla v10.2d, v0.2d, v17.d[0]\n\t"
        "ld2 {v28.2d, v29.2d}, [x16]\n\t"
        "fmla v16.2d, v17.2d, v3.2d\n\t"
        "fmla v2.2d, v30.2d, v17.d[1]\n\t"
        "fmla v11.2d, v7.2d, v17.d[0]\n\t"
        "fmla v12.2d, v15.2d, v17.d[1]\n\t"
        "mov v27.16b, v28.16b\n\t"
        "mov v26.16b, v28.16b\n\t"
        "mov v19.16b, v22.16b\n\t"
        "fmaxnm v10.2d, v10.2d, v31.2d\n\t"
        "mov v25.16b, v28.16b\n\t"
        "fmaxnm v2.2d, v2.2d, v31.2d\n\t"
        "fmaxnm v16.2d, v16.2d, v31.2d\n\t"
        "mov v24.16b, v28.16b\n\t"
        "fmaxnm v12.2d, v12.2d, v31.2d\n\t"
        "fmaxnm v11.2d, v11.2d, v31.2d\n\t"
        "fmla v21.2d, v23.2d, v7.d[1]\n\t"
        "fmla v28.2d, v29.2d, v3.d[1]\n\t"
        "fmla v18.2d, v23.2d, v0.d[0]\n\t"
        "fmla v22.2d, v23.2d, v3.d[0]\n\t"
        "fmla v25.2d, v29.2d, v15.d[1]\n\t"
        "fmla v20.2d, v23.2d, v7.d[0]\n\t"
        "fmla v24.2d, v29.2d, v15.d[0]\n\t"
        "fmla v19.2d, v23.2d, v0.d[1]\n\t"
        "fmla v26.2d, v29.2d, v30.d[0]\n\t"
        "fmla v27.2d, v29.2d, v30.d[1]\n\t"
        "frecpe v4.2d, v10.2d\n\t"
        "frecpe v5.2d, v11.2d\n\t"
        "frecpe v13.2d, v12.2d\n\t"
        "frecpe v14.2d, v2.2d\n\t"
        "frecpe v6.2d, v16.2d\n\t"
        "fmax v31.2d, v10.2d, v11.2d\n\t"
        "frecps v9.2d, v10.2d, v4.2d\n\t"
        "frecps v8.2d, v11.2d, v5.2d\n\t"
        "frecps v29.2d, v12.2d, v13.2d\n\t"
        "frecps v23.2d, v2.2d, v14.2d\n\t"
        "frecps v17.2d, v16.2d, v6.2d\n\t"
        "fmax v7.2d, v12.2d, v2.2d\n\t"
        "fmul v4.2d, v4.2d, v9.2d\n\t"
        "fmul v5.2d, v5.2d, v8.2d\n\t"
        "fmul v13.2d, v13.2d, v29.2d\n\t"
        "fmul v14.2d, v14.2d, v23.2d\n\t"
        "fmul v6.2d, v6.2d, v17.2d\n\t"
        "fmax v31.2d, v31.2d, v7.2d\n\t"
        "frecps v9.2d, v10.2d, v4.2d\n\t"
        "frecps v8.2d, v11.2d, v5.2d\n\t"
        "frecps v29.2d, v12.2d, v13.2d\n\t"
        "frecps v23.2d, v2.2d, v14.2d\n\t"
        "frecps v17.2d, v16.2d, v6.2d\n\t"
        "fmax v31.2d, v31.2d, v16.2d\n\t"
        "fmul v4.2d, v4.2d, v9.2d\n\t"
        "fmul v5.2d, v5.2d, v8.2d\n\t"
        "fmul v13.2d, v13.2d, v29.2d\n\t"
        "mov v29.16b, v1.16b\n\t"
        "mov v9.16b, v1.16b\n\t"
        "fmul v14.2d, v14.2d, v23.2d\n\t"
        "mov v8.16b, v1.16b\n\t"
        "mov v23.16b, v1.16b\n\t"
        "fmul v6.2d, v6.2d, v17.2d\n\t"
        "mov v17.16b, v1.16b\n\t"
        "mov x14, v12.d[1]\n\t"
        "fmov x3, d10\n\t"
        "fmls v9.2d, v10.2d, v4.2d\n\t"
        "fmls v8.2d, v11.2d, v5.2d\n\t"
        "fmls v29.2d, v12.2d, v13.2d\n\t"
        "mov x5, v10.d[1]\n\t"
        "fmov x9, d11\n\t"
        "mov x1, v16.d[1]\n\t"
        "fmls v17.2d, v16.2d, v6.2d\n\t"
        "fmls v23.2d, v2.2d, v14.2d\n\t"
        "fmla v4.2d, v4.2d, v9.2d\n\t"
        "fmla v5.2d, v5.2d, v8.2d\n\t"
        "fmla v13.2d, v13.2d, v29.2d\n\t"
        "fmov x10, d16\n\t"
        "fmov x13, d12\n\t"
        "mov x8, v11.d[1]\n\t"
        "mov v8.16b, v1.16b\n\t"
        "mov v9.16b, v1.16b\n\t"
        "fmla v6.2d, v6.2d, v17.2d\n\t"
        "fmla v14.2d, v14.2d, v23.2d\n\t"
        "mov v23.16b, v1.16b\n\t"
        "mov v29.16b, v1.16b\n\t"
        "fmaxp d31, v31.2d\n\t"
        "mov v17.16b, v1.16b\n\t"
        "fmov x17, d2\n\t"
        "mov x19, v2.d[1]\n\t"
        "fmls v9.2d, v10.2d, v4.2d\n\t"
        "fmls v8.2d, v11.2d, v5.2d\n\t"
        "fmls v29.2d, v12.2d, v13.2d\n\t"
        "fmls v23.2d, v2.2d, v14.2d\n\t"
        "fmls v17.2d, v16.2d, v6.2d\n\t"
        "fmov x6, d31\n\t"
        "ldr d0, [x4, #56]\n\t"
        "fmla v4.2d, v4.2d, v9.2d\n\t"
        "fmla v5.2d, v5.2d, v8.2d\n\t"
        "fmla v13.2d, v13.2d, v29.2d\n\t"
        "fmla v14.2d, v14.2d, v23.2d\n\t"
        "fmla v6.2d, v6.2d, v17.2d\n\t"
        "uxtl v0.2d, v0.2s\n\t"
        "ldr d15, [x0, #56]\n\t"
        "add x8, x8, #1\n\t"
        "add x14, x14, #1\n\t"
        "add x13, x13, #1\n\t"
        "add x9, x9, #1\n\t"
        "add x1, x1, #1\n\t"
        "add x5, x5, #1\n\t"
        "add x3, x3, #1\n\t"
        "add x10, x10, #1\n\t"
        "lsl x3, x3, #12\n\t"
        "clz x3, x3\n\t"
        "lsl x13, x13, #12\n\t"
        "lsl x9, x9, #12\n\t"
        "lsl x5, x5, #12\n\t"
        "lsl x10, x10, #12\n\t"
        "lsl x1, x1, #12\n\t"
        "lsl x14, x14, #12\n\t"
        "add x17, x17, #1\n\t"
        "clz x14, x14\n\t"
        "clz x9, x9\n\t"
        "clz x10, x10\n\t"
        "lsl x8, x8, #12\n\t"
        "add x19, x19, #1\n\t"
        "clz x1, x1\n\t"
        "clz x8, x8\n\t"
        "clz x5, x5\n\t"
        "clz x13, x13\n\t"
        "lsl x17, x17, #12\n\t"
        "lsl x19, x19, #12\n\t"
        "lsr x6, x6, #52\n\t"
        "orr x3, x3, x5\n\t"
        "orr x13, x13, x14\n\t"
        "clz x17, x17\n\t"
        "orr x9, x9, x8\n\t"
        "uxtl v15.2d, v15.2s\n\t"
        "ucvtf v0.2d, v0.2d, #16\n\t"
        "orr x10, x10, x1\n\t"
        "add x6, x6, #25\n\t"
        "orr x10, x10, x13\n\t"
        "orr x3, x3, x9\n\t"
        "clz x19, x19\n\t"
        "ucvtf v15.2d, v15.2d, #16\n\t"
        "orr x17, x17, x19\n\t"
        "and w28, w22, #15\n\t"
        "orr x3, x3, x10\n\t"
        "cmp w28, #0\n\t"
        "lsr x6, x6, #5\n\t"
        "orr x17, x17, x6\n\t"
        "orr x3, x3, x17\n\t"
        "lsr w22, w22, #4\n\t"
        "csinc w28, w28, wzr, ne\n\t"
        "tbz x3, #6, 2f\n\t"
        "fdiv v4.2d, v1.2d, v10.2d\n\t"
        "fdiv v5.2d, v1.2d, v11.2d\n\t"
        "fdiv v13.2d, v1.2d, v12.2d\n\t"
        "fdiv v14.2d, v1.2d, v2.2d\n\t"
        "fdiv v6.2d, v1.2d, v16.2d\n\t"
        "2:\n\t"
        "fmul v21.2d, v21.2d, v5.d[1]\n\t"
        "fmul v24.2d, v24.2d, v13.d[0]\n\t"
        "fmul v18.2d, v18.2d, v4.d[0]\n\t"
        "fmul v22.2d, v22.2d, v6.d[0]\n\t"
        "fmul v19.2d, v19.2d, v4.d[1]\n\t"
        "fmul v20.2d, v20.2d, v5.d[0]\n\t"
        "fmul v25.2d, v25.2d, v13.d[1]\n\t"
        "fmul v27.2d, v27.2d, v14.d[1]\n\t"
        "fmul v26.2d, v26.2d, v14.d[0]\n\t"
        "fmul v28.2d, v28.2d, v6.d[1]\n\t"
        "fmin v19.2d, v19.2d, v0.2d\n\t"
        "fmin v22.2d, v22.2d, v0.2d\n\t"
        "fmin v18.2d, v18.2d, v0.2d\n\t"
        "fmin v21.2d, v21.2d, v0.2d\n\t"
        "fmin v20.2d, v20.2d, v0.2d\n\t"
        "fmin v26.2d, v26.2d, v15.2d\n\t"
        "fmin v24.2d, v24.2d, v15.2d\n\t"
        "fmin v28.2d, v28.2d, v15.2d\n\t"
        "fmin v25.2d, v25.2d, v15.2d\n\t"
        "fmin v27.2d, v27.2d, v15.2d\n\t"
        "fcvtzu v20.2d, v20.2d, #16\n\t"
        "fcvtzu v19.2d, v19.2d, #16\n\t"
        "fcvtzu v21.2d, v21.2d, #16\n\t"
        "fcvtzu v18.2d, v18.2d, #16\n\t"
        "fcvtzu v25.2d, v25.2d, #16\n\t"
        "fcvtzu v22.2d, v22.2d, #16\n\t"
        "fcvtzu v24.2d, v24.2d, #16\n\t"
        "fcvtzu v28.2d, v28.2d, #16\n\t"
        "fmov x19, d20\n\t"
        "mov x3, v20.d[1]\n\t"
        "fmov x23, d19\n\t"
        "fcvtzu v27.2d, v27.2d, #16\n\t"
        "fmov x13, d18\n\t"
        "mov x1, v18.d[1]\n\t"
        "fcvtzu v26.2d, v26.2d, #16\n\t"
        "mov x2, v19.d[1]\n\t"
        "fmov x25, d21\n\t"
        "stp q24, q25, [x26]\n\t"
        "fmov x4, d22\n\t"
        "mov x5, v21.d[1]\n\t"
        "mov x6, v22.d[1]\n\t"
        "stp q26, q27, [x26, #32]\n\t"
        "sub w9, w23, w13\n\t"
        "sub w12, w3, w2\n\t"
        "sub w24, w19, w23\n\t"
        "sub w10, w2, w1\n\t"
        "sub w15, w5, w3\n\t"
        "orr x23, x23, x2, lsl #32\n\t"
        "sub w20, w25, w19\n\t"
        "asr w8, w9, #31\n\t"
        "asr w14, w24, #31\n\t"
        "asr w21, w15, #31\n\t"
        "cmp w22, #2\n\t"
        "asr w11, w10, #31\n\t"
        "sub w4, w4, w25\n\t"
        "asr w16, w12, #31\n\t"
        "sub w6, w6, w5\n\t"
        "csel w4, w20, w4, eq\n\t"
        "add w10, w10, w11, lsr #28\n\t"
        "asr w17, w20, #31\n\t"
        "add w9, w9, w8, lsr #28\n\t"
        "sbfx x9, x9, #4, #28\n\t"
        "csel w4, w24, w4, lt\n\t"
        "add w24, w24, w14, lsr #28\n\t"
        "csel w6, w15, w6, eq\n\t"
        "csel w6, w12, w6, lt\n\t"
        "add w15, w15, w21, lsr #28\n\t"
        "add w20, w20, w17, lsr #28\n\t"
        "add w12, w12, w16, lsr #28\n\t"
        "asr w15, w15, #4\n\t"
        "orr x19, x19, x3, lsl #32\n\t"
        "sbfx x24, x24, #4, #28\n\t"
        "asr w10, w10, #4\n\t"
        "sbfiz x8, x4, #29, #32\n\t"
        "sbfx x20, x20, #4, #28\n\t"
        "asr w12, w12, #4\n\t"
        "smulh x8, x8, x7\n\t"
        "sbfiz x21, x6, #29, #32\n\t"
        "add w4, w8, w4, lsr #31\n\t"
        "add x24, x24, x12, lsl #32\n\t"
        "add x9, x9, x10, lsl #32\n\t"
        "str q28, [x26, #64]\n\t"
        "smulh x21, x21, x7\n\t"
        "add x20, x20, x15, lsl #32\n\t"
        "orr x13, x13, x1, lsl #32\n\t"
        "add w6, w21, w6, lsr #31\n\t"
        "orr x25, x25, x5, lsl #32\n\t"
        "lsl x6, x6, #32\n\t"
        "add x28, x6, w4, sxtw"
// END lin_pair
      : "=&r"(rx0), "=&r"(rx1), "=&r"(rx2), "=&r"(rx3), "=&r"(rd0), "=&r"(rd1), "=&r"(rd2), "=&r"(rld), "+&r"(rkm),
        "+&r"(rtab), "+&r"(rpa), "+&r"(rna)
      : "r"(rpb), "r"(rnb), "r"(rbuf)
      // "memory": the block reads pa, pb, kMinZi and kShortLinPos and writes buf.
      : "cc", "memory", "x1", "x3", "x5", "x6", "x8", "x10", "x12", "x14", "x15", "x16", "x17", "x21", "x22", "v0",
        "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8", "v9", "v10", "v11", "v12", "v13", "v14", "v15", "v16", "v17",
        "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30", "v31");
  return ShortLinSetup{rx0, rx1, rx2, rx3, rd0, rd1, rd2, rld};
}

// Span b's ShortLinSetup (nb pixels) from the samples short_lin_setup2 stored to buf: the
// integer steps of short_lin_setup2's block on them (the same instructions; tab is the
// address of kShortLinPos - 504: row nb's magic at tab + 32 nb).
//
// The same block also tests the next pair (lin_pairs_a64's loop test, in the integer
// block's spare slots; from bench/mca_a53_lin2/finish.s, see bench/mca_a53_persp/README.md):
// again = 1 when at least four items are left from it (it + 4 <= end) and it[2], it[3] are
// both lin_short_a64's (16 < n <= 64 = kShortMax, asserted at lin_pairs_a64; second_order
// off or dzi's bits +-0: (-second_order & dzi << 1) == 0, second_order a 0 / 1 byte), else
// 0. it[2], it[3] are read only when it + 4 <= end (else it[0], it[1]: again is 0 then), so
// it[0], it[1] must be readable items. it and end are memory operands (the caller's
// variables, which the compiler keeps on the stack across the drawing anyway): loaded by
// the block, they take no register of their own (with them in registers the compiler
// spilled width around the drawing).
SB_INLINE ShortLinSetup short_lin_finish(int nb, const uint64_t* buf, const PerspItem* const& it,
                                         const PerspItem* const& end, uint32_t& again) {
  static_assert(sizeof(PerspItem) == 88 && offsetof(PerspItem, n) == 8 && offsetof(PerspItem, span) == 16 &&
                    offsetof(PerspSpan, dzi) == 8 && offsetof(PerspSpan, second_order) == 64 &&
                    sizeof(bool) == 1,
                "the test's offsets: it[2] at 176, n +8, dzi +24, second_order +80; it[3] at 264");
  register uint64_t ragain __asm__("x1");
  register uint64_t rx0 __asm__("x13");
  register uint64_t rx1 __asm__("x23");
  register uint64_t rx2 __asm__("x19");
  register uint64_t rx3 __asm__("x25");
  register uint64_t rd0 __asm__("x9");
  register uint64_t rd1 __asm__("x24");
  register uint64_t rd2 __asm__("x20");
  register uint64_t rld __asm__("x28");
  __asm__ volatile(
// BEGIN lin_finish
        "ldr x12, %[itm]\n\t"
        "ldr x14, %[endm]\n\t"
        "ldp x19, x3, [%[buf], #32]\n\t"
        "add x7, %[tab], %[nb], lsl #5\n\t"
        "ldp x4, x6, [%[buf], #64]\n\t"
        "sub w22, %w[nb], #1\n\t"
        "sub x14, x14, x12\n\t"
        "and w28, w22, #15\n\t"
        "cmp x14, #352\n\t"
        "lsr w22, w22, #4\n\t"
        "sub x14, x12, #176\n\t"
        "ldp x23, x2, [%[buf], #16]\n\t"
        "csel x12, x12, x14, ge\n\t"
        "cset w14, lt\n\t"
        "ldp x25, x5, [%[buf], #48]\n\t"
        "ldrb w17, [x12, #256]\n\t"
        "ldrb w21, [x12, #344]\n\t"
        "ldr x8, [x12, #200]\n\t"
        "sub w24, w19, w23\n\t"
        "ldr w11, [x12, #184]\n\t"
        "neg x17, x17\n\t"
        "ldr w16, [x12, #272]\n\t"
        "sub w6, w6, w5\n\t"
        "ldr x15, [x12, #288]\n\t"
        "and x17, x17, x8, lsl #1\n\t"
        "sub w12, w3, w2\n\t"
        "neg x21, x21\n\t"
        "sub w11, w11, #17\n\t"
        "cmp w11, #47\n\t"
        "orr x17, x17, x14\n\t"
        "ldp x13, x14, [%[buf]]\n\t"
        "sub w16, w16, #17\n\t"
        "mov w8, #47\n\t"
        "ccmp w16, w8, #2, ls\n\t"
        "and x21, x21, x15, lsl #1\n\t"
        "orr x17, x17, x21\n\t"
        "ldr x7, [x7]\n\t"
        "sub w10, w2, w14\n\t"
        "sub w9, w23, w13\n\t"
        "ccmp x17, #0, #0, ls\n\t"
        "sub w4, w4, w25\n\t"
        "asr w16, w12, #31\n\t"
        "sub w20, w25, w19\n\t"
        "asr w11, w10, #31\n\t"
        "orr x23, x23, x2, lsl #32\n\t"
        "cset w1, eq\n\t"
        "cmp w28, #0\n\t"
        "asr w8, w9, #31\n\t"
        "orr x13, x13, x14, lsl #32\n\t"
        "sub w15, w5, w3\n\t"
        "orr x25, x25, x5, lsl #32\n\t"
        "csinc w28, w28, wzr, ne\n\t"
        "cmp w22, #2\n\t"
        "asr w21, w15, #31\n\t"
        "add w10, w10, w11, lsr #28\n\t"
        "asr w14, w24, #31\n\t"
        "add w9, w9, w8, lsr #28\n\t"
        "csel w6, w15, w6, eq\n\t"
        "add w15, w15, w21, lsr #28\n\t"
        "asr w15, w15, #4\n\t"
        "csel w6, w12, w6, lt\n\t"
        "sbfiz x21, x6, #29, #32\n\t"
        "csel w4, w20, w4, eq\n\t"
        "csel w4, w24, w4, lt\n\t"
        "orr x19, x19, x3, lsl #32\n\t"
        "asr w17, w20, #31\n\t"
        "sbfiz x8, x4, #29, #32\n\t"
        "add w24, w24, w14, lsr #28\n\t"
        "smulh x8, x8, x7\n\t"
        "add w20, w20, w17, lsr #28\n\t"
        "add w12, w12, w16, lsr #28\n\t"
        "asr w12, w12, #4\n\t"
        "add w4, w8, w4, lsr #31\n\t"
        "sbfx x20, x20, #4, #28\n\t"
        "sbfx x9, x9, #4, #28\n\t"
        "sbfx x24, x24, #4, #28\n\t"
        "smulh x21, x21, x7\n\t"
        "add x20, x20, x15, lsl #32\n\t"
        "add x24, x24, x12, lsl #32\n\t"
        "asr w10, w10, #4\n\t"
        "add w6, w21, w6, lsr #31\n\t"
        "lsl x6, x6, #32\n\t"
        "add x9, x9, x10, lsl #32\n\t"
        "add x28, x6, w4, sxtw"
// END lin_finish
      : "=&r"(rx0), "=&r"(rx1), "=&r"(rx2), "=&r"(rx3), "=&r"(rd0), "=&r"(rd1), "=&r"(rd2), "=&r"(rld),
        "=&r"(ragain)
      : [nb] "r"(nb), [buf] "r"(buf), [tab] "r"(reinterpret_cast<uintptr_t>(&kShortLinPos) - 504), [itm] "m"(it),
        [endm] "m"(end)
      : "cc", "memory", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x14", "x15", "x16", "x17",
        "x21", "x22");
  again = uint32_t(ragain);
  return ShortLinSetup{rx0, rx1, rx2, rx3, rd0, rd1, rd2, rld};
}

// Two linear spans it[0], it[1] of 17 .. 64 pixels each (persp_short_lin's contract for
// each): the same pixels as persp_short_lin(it[0]) then persp_short_lin(it[1]); it += 2
// (before span b's drawing: the add in the finish's block, not in the loop's end). Returns
// short_lin_finish's next-pair test (it + 4 <= end and it[2], it[3] pairable).
SB_INLINE uint32_t persp_short_lin2(const PerspItem*& it, const PerspItem* const& end, const uint8_t* texels,
                                    int width) {
  alignas(16) uint64_t buf[10];
  const int nb = it[1].n;
  short_lin_draw(it[0].dest, it[0].n, texels, width, short_lin_setup2(it[0].n, it[0].span, nb, it[1].span, buf));
  uint32_t again;
  const ShortLinSetup sb = short_lin_finish(nb, buf, it, end, again);
  uint8_t* const destb = it[1].dest;
  it += 2;
  short_lin_draw(destb, nb, texels, width, sb);
  return again;
}

}  // namespace
}  // namespace sb::simd
