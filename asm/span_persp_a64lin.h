// asm/span_persp_a64lin.h: aarch64 only, persp_short_lin: persp_short_inl<false> (linear
// steps, 17 .. 64 pixels; asm/span_persp_a64short.h) as one asm block for the samples and the
// full runs' steps, then the runs drawn by short_pass (asm/span_persp_a64pass.h). Internal:
// included by asm/span_persp_a64short.h (it uses asm/span_persp_run.h's runs).
//
// The block (written from bench/mca_a53_persp/lin_setup.s by bench/to_inline.py):
// - positions as the walker computes them (asm/span_walk.h: px += 16 per run, each sample one
//   addition from its run's start): [P_0, P_1] = [P_0, P_0] + [0, 16], samples 2, 3 at
//   [P_0, P_1] + [o_0, o_1], sample 4 at ((P_0 + 16) + 16) + o_2, with o_j = min(32,
//   n - 16 j - 1) from kShortLinPos's row n (no integer-to-double conversion on the way);
// - depths, reciprocals (Newton, the divide fallback) and the [u, v] products exactly as
//   persp_short_inl's second-order block (see the proof there): the same bits;
// - to_fixed: fcvtzu #16 of min(uv z, [umax, vmax] 2^-16) (the clamp at 0 folded into the
//   unsigned conversion, NaN -> 0; the limit exact: ucvtf of a 32-bit integer; truncation is
//   monotone, so this is min(fcvtzu(uv z), umax) as the vector code's uqxtn / umin: the same
//   value, AsmSpanPersp.MinBeforeFixedPointMatchesTheWalker), each lane moved to an integer
//   register;
// - the full runs' steps steps16_packed (delta / 16 truncated per component, packed v 2^32 +
//   sign-extended u), the samples packed (v 2^32 + u) and the last run's step (k and s from
//   n before the branch, its raw delta picked by csel, sdiv) in integer registers
//   (AsmSpanPersp.ShortLinearSetupMatchesTheWalkersParts). (The paired block,
//   asm/span_persp_a64lin2.h, divides by the row's magic(s) instead: see ShortLinPos.)
// Registers are fixed (the .s file's names), the outputs where short_pass takes its first
// pass (x13, x9, x23, x24) and, for the second pass, in registers short_pass keeps.
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "asm/span_persp.h"
#include "asm/span_persp_run.h"
#include "asm/span_persp_a64pass.h"

namespace sb::simd {
namespace {

// [0, 16], then per span length n = 17 .. 64 (row n - 17): o_0, o_1, o_2 (the offsets of
// samples 2, 3, 4 from P_0, P_1, P_2) and the bits of magic(s), s = max(last - 1, 1) =
// max((n - 1) & 15, 1) (the paired block's last-run steps, read by integer loads).
// magic(s) = floor(2^35 / s) + 1: the last run's steps trunc(d / s) for |d| < 2^31 as
// floor(d magic(s) / 2^35) + (d < 0) (smulh of d 2^29, no sdiv: the A57 model's takes ~19
// cycles); exact: magic(s) s - 2^35 is in (0, s], so the error |d| (magic(s) s - 2^35) /
// (s 2^35) stays under 1 / s, the least distance of an inexact d / s from the integers
// (Granlund and Montgomery's bound; AsmSpanPerspBatch.PairedLinearSetupMatchesTwoSingleSetups).
struct ShortLinPos {
  double zero_sixteen[2];
  double row[48][4];
};
constexpr uint64_t short_lin_magic(int s) { return (uint64_t(1) << 35) / uint64_t(s) + 1; }
constexpr ShortLinPos make_short_lin_pos() {
  ShortLinPos t{{0.0, 16.0}, {}};
  for (int n = 17; n <= 64; ++n) {
    auto o = [n](int j) { return double(n - 16 * j - 1 < 32 ? n - 16 * j - 1 : 32); };
    t.row[n - 17][0] = o(0);
    t.row[n - 17][1] = o(1);
    t.row[n - 17][2] = o(2);
    const int s = (n - 1) & 15;
    t.row[n - 17][3] = std::bit_cast<double>(short_lin_magic(s > 0 ? s : 1));
  }
  return t;
}
alignas(16) constexpr ShortLinPos kShortLinPos = make_short_lin_pos();
static_assert(offsetof(ShortLinPos, row) == 16 && sizeof(ShortLinPos::row[0]) == 32,
              "lin_setup.s: row n at base + 32 n - 528");
static_assert(offsetof(PerspSpan, zi0) == 0 && offsetof(PerspSpan, dzi) == 8 && offsetof(PerspSpan, uz0) == 16 &&
                  offsetof(PerspSpan, duz) == 24 && offsetof(PerspSpan, vz0) == 32 && offsetof(PerspSpan, dvz) == 40 &&
                  offsetof(PerspSpan, px0) == 48 && offsetof(PerspSpan, umax) == 56 && offsetof(PerspSpan, vmax) == 60,
              "lin_setup.s: PerspSpan offsets");

// The block's results for a linear span of n = 17 .. 64 pixels: the packed samples x_j (v 2^32
// + u, j = 0 .. 3; sample 4 stays internal), the full runs' steps d_j = steps16_packed(x_j,
// x_{j+1}) (j = 0 .. 2) and the last run's step ld (k = (n - 1) >> 4, from sample k to k + 1
// in s = max(last - 1, 1) steps; packed as Run16 takes it). Samples past the last (j > k + 1)
// and steps past the full runs are computed but meaningless.
struct ShortLinSetup {
  uint64_t x0, x1, x2, x3, d0, d1, d2, ld;
};
SB_INLINE ShortLinSetup short_lin_setup(int n, const PerspSpan& p) {
  register const PerspSpan* rp __asm__("x4") = &p;
  register uint64_t rn __asm__("x7") = uint64_t(uint32_t(n));
  register const double* rkm __asm__("x2") = &kMinZi;
  register const ShortLinPos* rtab __asm__("x11") = &kShortLinPos;
  register uint64_t rx0 __asm__("x13");  // packed samples 0 .. 3
  register uint64_t rx1 __asm__("x23");
  register uint64_t rx2 __asm__("x19");
  register uint64_t rx3 __asm__("x25");
  register uint64_t rd0 __asm__("x9");  // steps16_packed of samples 0 -> 1, 1 -> 2, 2 -> 3
  register uint64_t rd1 __asm__("x24");
  register uint64_t rd2 __asm__("x20");
  register uint64_t rld __asm__("x28");  // the last run's packed step (see below)
  __asm__ volatile(
// BEGIN lin_setup
        "add x9, x11, x7, lsl #5\n\t"
        "add x10, x4, #48\n\t"
        "ldr q6, [x11]\n\t"
        "fmov d1, #16.0\n\t"
        "ld1r {v28.2d}, [x10]\n\t"
        "sub w22, w7, #1\n\t"
        "ld1r {v31.2d}, [x2]\n\t"
        "and w28, w22, #15\n\t"
        "ld2r {v16.2d, v17.2d}, [x4]\n\t"
        "add x10, x4, #16\n\t"
        "ld1r {v26.2d}, [x4]\n\t"
        "ldp q4, q5, [x9, #-528]\n\t"
        "fadd d2, d28, d1\n\t"
        "fadd v0.2d, v28.2d, v6.2d\n\t"
        "ld2 {v20.2d, v21.2d}, [x10]\n\t"
        "cmp w28, #0\n\t"
        "ld1r {v27.2d}, [x4]\n\t"
        "fadd d3, d2, d1\n\t"
        "ld2 {v22.2d, v23.2d}, [x10]\n\t"
        "fadd v7.2d, v0.2d, v4.2d\n\t"
        "fmla v26.2d, v17.2d, v0.2d\n\t"
        "fmla v20.2d, v21.2d, v0.d[1]\n\t"
        "fadd d3, d3, d5\n\t"
        "ld2 {v24.2d, v25.2d}, [x10]\n\t"
        "fmla v27.2d, v17.2d, v7.2d\n\t"
        "fmla v22.2d, v23.2d, v7.d[0]\n\t"
        "ld2 {v29.2d, v30.2d}, [x10]\n\t"
        "fmaxnm v26.2d, v26.2d, v31.2d\n\t"
        "fmadd d28, d17, d3, d16\n\t"
        "fmla v24.2d, v25.2d, v7.d[1]\n\t"
        "fmaxnm v27.2d, v27.2d, v31.2d\n\t"
        "ld2 {v18.2d, v19.2d}, [x10]\n\t"
        "frecpe v2.2d, v26.2d\n\t"
        "fmov v1.2d, #1.0\n\t"
        "fmaxnm d28, d28, d31\n\t"
        "fmov x9, d27\n\t"
        "fmov x3, d26\n\t"
        "frecps v5.2d, v26.2d, v2.2d\n\t"
        "frecpe v6.2d, v27.2d\n\t"
        "mov x5, v26.d[1]\n\t"
        "frecpe d4, d28\n\t"
        "fmax v31.2d, v26.2d, v27.2d\n\t"
        "mov x8, v27.d[1]\n\t"
        "fmov x10, d28\n\t"
        "fmul v2.2d, v2.2d, v5.2d\n\t"
        "frecps v16.2d, v27.2d, v6.2d\n\t"
        "frecps d17, d28, d4\n\t"
        "fmaxp d31, v31.2d\n\t"
        "add x10, x10, #1\n\t"
        "add x3, x3, #1\n\t"
        "lsl x3, x3, #12\n\t"
        "lsl x10, x10, #12\n\t"
        "add x8, x8, #1\n\t"
        "fmul v6.2d, v6.2d, v16.2d\n\t"
        "fmax d31, d31, d28\n\t"
        "fmul d4, d4, d17\n\t"
        "ldr d21, [x4, #56]\n\t"
        "clz x10, x10\n\t"
        "add x5, x5, #1\n\t"
        "lsl x5, x5, #12\n\t"
        "clz x3, x3\n\t"
        "lsl x8, x8, #12\n\t"
        "frecps v5.2d, v26.2d, v2.2d\n\t"
        "frecps d17, d28, d4\n\t"
        "frecps v16.2d, v27.2d, v6.2d\n\t"
        "clz x8, x8\n\t"
        "add x9, x9, #1\n\t"
        "lsl x9, x9, #12\n\t"
        "fmul v2.2d, v2.2d, v5.2d\n\t"
        "mov v5.16b, v1.16b\n\t"
        "fmul d4, d4, d17\n\t"
        "fmul v6.2d, v6.2d, v16.2d\n\t"
        "mov v16.16b, v1.16b\n\t"
        "clz x9, x9\n\t"
        "clz x5, x5\n\t"
        "orr x3, x3, x5\n\t"
        "orr x9, x9, x8\n\t"
        "fmov x6, d31\n\t"
        "fmsub d17, d28, d4, d1\n\t"
        "fmls v16.2d, v27.2d, v6.2d\n\t"
        "fmls v5.2d, v26.2d, v2.2d\n\t"
        "uxtl v21.2d, v21.2s\n\t"
        "orr x3, x3, x9\n\t"
        "lsr x6, x6, #52\n\t"
        "fmadd d4, d4, d17, d4\n\t"
        "fmla v6.2d, v6.2d, v16.2d\n\t"
        "fmla v2.2d, v2.2d, v5.2d\n\t"
        "mov v5.16b, v1.16b\n\t"
        "mov v16.16b, v1.16b\n\t"
        "add x6, x6, #25\n\t"
        "orr x3, x3, x10\n\t"
        "lsr x6, x6, #5\n\t"
        "fmla v29.2d, v30.2d, v3.d[0]\n\t"
        "fmls v5.2d, v26.2d, v2.2d\n\t"
        "fmls v16.2d, v27.2d, v6.2d\n\t"
        "fmsub d17, d28, d4, d1\n\t"
        "orr x3, x3, x6\n\t"
        "fmla v18.2d, v19.2d, v0.d[0]\n\t"
        "fmla v2.2d, v2.2d, v5.2d\n\t"
        "fmla v6.2d, v6.2d, v16.2d\n\t"
        "fmadd d4, d4, d17, d4\n\t"
        "ucvtf v21.2d, v21.2d, #16\n\t"
        "csinc w28, w28, wzr, ne\n\t"
        "lsr w22, w22, #4\n\t"
        "tbz x3, #6, 2f\n\t"
        "fdiv v2.2d, v1.2d, v26.2d\n\t"
        "fdiv v6.2d, v1.2d, v27.2d\n\t"
        "fdiv d4, d1, d28\n\t"
        "2:\n\t"
        "fmul v18.2d, v18.2d, v2.d[0]\n\t"
        "fmul v20.2d, v20.2d, v2.d[1]\n\t"
        "fmul v29.2d, v29.2d, v4.d[0]\n\t"
        "fmul v24.2d, v24.2d, v6.d[1]\n\t"
        "fmul v22.2d, v22.2d, v6.d[0]\n\t"
        "fmin v18.2d, v18.2d, v21.2d\n\t"
        "fmin v20.2d, v20.2d, v21.2d\n\t"
        "fmin v29.2d, v29.2d, v21.2d\n\t"
        "fmin v24.2d, v24.2d, v21.2d\n\t"
        "fmin v22.2d, v22.2d, v21.2d\n\t"
        "fcvtzu v18.2d, v18.2d, #16\n\t"
        "fcvtzu v20.2d, v20.2d, #16\n\t"
        "fcvtzu v24.2d, v24.2d, #16\n\t"
        "fcvtzu v22.2d, v22.2d, #16\n\t"
        "fcvtzu v29.2d, v29.2d, #16\n\t"
        "fmov x13, d18\n\t"
        "fmov x23, d20\n\t"
        "mov x1, v18.d[1]\n\t"
        "mov x2, v20.d[1]\n\t"
        "mov x5, v24.d[1]\n\t"
        "fmov x19, d22\n\t"
        "fmov x25, d24\n\t"
        "mov x3, v22.d[1]\n\t"
        "mov x6, v29.d[1]\n\t"
        "fmov x4, d29\n\t"
        "sub w9, w23, w13\n\t"
        "sub w20, w25, w19\n\t"
        "sub w15, w5, w3\n\t"
        "sub w12, w3, w2\n\t"
        "sub w24, w19, w23\n\t"
        "sub w10, w2, w1\n\t"
        "asr w14, w24, #31\n\t"
        "cmp w22, #2\n\t"
        "asr w8, w9, #31\n\t"
        "asr w21, w15, #31\n\t"
        "asr w16, w12, #31\n\t"
        "sub w6, w6, w5\n\t"
        "asr w11, w10, #31\n\t"
        "sub w4, w4, w25\n\t"
        "add w10, w10, w11, lsr #28\n\t"
        "csel w4, w20, w4, eq\n\t"
        "asr w17, w20, #31\n\t"
        "add w9, w9, w8, lsr #28\n\t"
        "sbfx x9, x9, #4, #28\n\t"
        "csel w4, w24, w4, lt\n\t"
        "csel w6, w15, w6, eq\n\t"
        "add w15, w15, w21, lsr #28\n\t"
        "csel w6, w12, w6, lt\n\t"
        "add w24, w24, w14, lsr #28\n\t"
        "asr w15, w15, #4\n\t"
        "add w12, w12, w16, lsr #28\n\t"
        "add w20, w20, w17, lsr #28\n\t"
        "orr x19, x19, x3, lsl #32\n\t"
        "asr w10, w10, #4\n\t"
        "sbfx x24, x24, #4, #28\n\t"
        "sbfx x20, x20, #4, #28\n\t"
        "asr w12, w12, #4\n\t"
        "add x9, x9, x10, lsl #32\n\t"
        "sdiv w4, w4, w28\n\t"
        "add x24, x24, x12, lsl #32\n\t"
        "sdiv w6, w6, w28\n\t"
        "add x20, x20, x15, lsl #32\n\t"
        "orr x25, x25, x5, lsl #32\n\t"
        "orr x23, x23, x2, lsl #32\n\t"
        "orr x13, x13, x1, lsl #32\n\t"
        "lsl x6, x6, #32\n\t"
        "add x28, x6, w4, sxtw"
// END lin_setup
      : "=&r"(rx0), "=&r"(rx1), "=&r"(rx2), "=&r"(rx3), "=&r"(rd0), "=&r"(rd1), "=&r"(rd2), "=&r"(rld), "+&r"(rkm),
        "+&r"(rtab), "+&r"(rp)
      : "r"(rn)
      // "memory": the block reads p, kMinZi and kShortLinPos ("m" operands for them left GCC
      // no register for their addresses: an internal compiler error).
      : "cc", "memory", "x1", "x3", "x5", "x6", "x8", "x10", "x12", "x14", "x15", "x16", "x17", "x21", "x22", "v0",
        "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25",
        "v26", "v27", "v28", "v29", "v30", "v31");
  return ShortLinSetup{rx0, rx1, rx2, rx3, rd0, rd1, rd2, rld};
}

// Draws a linear span of n = 17 .. 64 pixels from its set-up r (short_lin_setup2's, or
// short_lin_finish's for the second span of a pair): persp_short_lin's drawing (below; kept
// as its own copy there: the batch loop's code, which inlines it, stays as it was).
SB_INLINE void short_lin_draw(uint8_t* dest, int n, const uint8_t* texels, int width, const ShortLinSetup& r) {
  const uint32_t w = uint32_t(width);
  const int runs = (n + 15) >> 4, last = n - 16 * (runs - 1);
  const uint64_t x0 = r.x0, x1 = r.x1, x2 = r.x2, x3 = r.x3, d0 = r.d0, d1 = r.d1, d2 = r.d2, ld = r.ld;
  // The last run (k = runs - 1) from sample k to k + 1 in s = max(last - 1, 1) steps, in the
  // block: run_steps' delta / s truncating per component (|delta| < 2^31; a one-pixel last
  // run draws no step: any divisor), packed as ld = dv 2^32 + sign-extended du.
  auto go = [&](auto kc) SB_LAMBDA_INLINE {
    constexpr int k = decltype(kc)::value;
    const uint64_t xa = k == 1 ? x1 : (k == 2 ? x2 : x3);
    auto pass = [&](uint8_t* d, uint64_t a_uv, uint64_t a_d, uint64_t b_uv, uint64_t b_d) SB_LAMBDA_INLINE {
      short_pass<false>(d, texels, uint64_t(width), a_uv, a_d, 0, b_uv, b_d, 0);
    };
    if (k == 1) {
      Run16<false> run(x0, d0, 0, typename Run16<false>::Packed{});
      run.draw(dest, texels, w);
    } else {
      if (k == 3 && last == 16) {
        pass(dest, x0, d0, x1, d1);
        pass(dest + 32, x2, d2, x3, ld);
        return;
      }
      pass(dest, x0, d0, x1, d1);
      if (k > 2) {
        Run16<false> run(x2, d2, 0, typename Run16<false>::Packed{});
        run.draw(dest + 32, texels, w);
      }
    }
    dest += 16 * k;
    if (last == 16) {
      Run16<false> run(xa, ld, 0, typename Run16<false>::Packed{});
      run.draw(dest, texels, w);
    } else {
      const uint32_t ldu = uint32_t(ld), ldv = uint32_t((ld - uint64_t(int64_t(int32_t(ldu)))) >> 32);
      draw_last<false>(dest, last, texels, w, uint32_t(xa), uint32_t(xa >> 32), ldu, ldv, 0, 0);
    }
  };
  if (runs == 2) {
    go(std::integral_constant<int, 1>{});
  } else if (runs == 3) {
    go(std::integral_constant<int, 2>{});
  } else {
    go(std::integral_constant<int, 3>{});
  }
}

// Linear spans of 17 .. 64 pixels (the contract of persp_short_inl).
SB_INLINE void persp_short_lin(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  const uint32_t w = uint32_t(width);
  const int runs = (n + 15) >> 4, last = n - 16 * (runs - 1);
  const ShortLinSetup r = short_lin_setup(n, p);
  const uint64_t x0 = r.x0, x1 = r.x1, x2 = r.x2, x3 = r.x3, d0 = r.d0, d1 = r.d1, d2 = r.d2, ld = r.ld;
  // The last run (k = runs - 1) from sample k to k + 1 in s = max(last - 1, 1) steps, in the
  // block: run_steps' delta / s truncating per component (|delta| < 2^31; a one-pixel last
  // run draws no step: any divisor), packed as ld = dv 2^32 + sign-extended du.
  auto go = [&](auto kc) SB_LAMBDA_INLINE {
    constexpr int k = decltype(kc)::value;
    const uint64_t xa = k == 1 ? x1 : (k == 2 ? x2 : x3);
    auto pass = [&](uint8_t* d, uint64_t a_uv, uint64_t a_d, uint64_t b_uv, uint64_t b_d) SB_LAMBDA_INLINE {
      short_pass<false>(d, texels, uint64_t(width), a_uv, a_d, 0, b_uv, b_d, 0);
    };
    if (k == 1) {
      Run16<false> run(x0, d0, 0, typename Run16<false>::Packed{});
      run.draw(dest, texels, w);
    } else {
      if (k == 3 && last == 16) {
        pass(dest, x0, d0, x1, d1);
        pass(dest + 32, x2, d2, x3, ld);
        return;
      }
      pass(dest, x0, d0, x1, d1);
      if (k > 2) {
        Run16<false> run(x2, d2, 0, typename Run16<false>::Packed{});
        run.draw(dest + 32, texels, w);
      }
    }
    dest += 16 * k;
    if (last == 16) {
      Run16<false> run(xa, ld, 0, typename Run16<false>::Packed{});
      run.draw(dest, texels, w);
    } else {
      const uint32_t ldu = uint32_t(ld), ldv = uint32_t((ld - uint64_t(int64_t(int32_t(ldu)))) >> 32);
      draw_last<false>(dest, last, texels, w, uint32_t(xa), uint32_t(xa >> 32), ldu, ldv, 0, 0);
    }
  };
  if (runs == 2) {
    go(std::integral_constant<int, 1>{});
  } else if (runs == 3) {
    go(std::integral_constant<int, 2>{});
  } else {
    go(std::integral_constant<int, 3>{});
  }
}

}  // namespace
}  // namespace sb::simd
