// asm/span_persp_a64short.h: the whole-span drawer's aarch64 short-span path (asm/span_persp.h):
// persp_short_inl / persp_short for spans of 17 .. kShortMax pixels, and kShortMax (16
// elsewhere: the long-span code). Internal: included at the end of asm/span_persp_arm.h
// (it uses that file's last_steps and asm/span_persp_run.h's runs), which
// asm/span_persp_fast.cpp includes (anonymous namespace: internal linkage).
#pragma once
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "asm/span_persp.h"
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64pass.h"
#include "asm/span_persp_a64lin.h"
#include "asm/span_persp_a64lin2.h"
#endif
#include "asm/span_persp_a64mid.h"
#include "asm/span_persp_a64few.h"

namespace sb::simd {
namespace {

#if defined(__aarch64__)
// aarch64, short spans (17 .. kShortMax pixels: 2 .. 4 runs; linear steps: persp_short_lin,
// asm/span_persp_a64lin.h, the same samples and reciprocals in one block with the steps):
// every sample's position, depth and reciprocal first (two 2-lane and one scalar, without a
// divide: below), the conversions in vectors; the full runs' steps in vectors, the last
// run's by last_steps; all branch-free, then the runs drawn straight (pairs of runs as one
// short_pass, asm/span_persp_a64pass.h). Positions as the walker computes
// them: P_j = P_{j-1} + 16 (run j's first pixel), sample 1 at P_0 + 16 = P_1, sample j + 2 at
// P_j + min(32, n - 16 j - 1) (16 + end_offset of the pixels after run j). Samples past the
// last one (j > runs) are computed but unused; for a one-pixel last run the last sample is
// unused too (steps 0 whatever the samples: run_steps). Each lane is the long-span vector
// code's operation (see persp_fast): the same bits.
//
// The reciprocals 1 / zi without a divide (fdiv blocks an in-order core for ~30 cycles): for
// b = max(zi, kMinZi) in [2^-30, 2^1000) every value below is normal, so each operation
// rounds with relative error <= u = 2^-53 and everything scales with b's exponent: take b
// in [1, 2), 1/b in (1/2, 1]. Round to nearest (the default FPCR, as the engine runs).
//   y0 = frecpe(b): |b y0 - 1| = e0 < 2^-8.44 (ARM's 256-entry table; the test checks both
//        ends of every interval at every exponent).
//   y <- y frecps(b, y), twice (frecps = RN(2 - b y), fused): with b y = 1 + e the new
//        e' = (1 - e^2)(1 + d1)(1 + d2) - 1, |e'| <= e^2 + 2.01 u: e1 < 2^-16.8, e2 < 2^-33.5.
//   y3 = RN(v), v = y2 + y2 RN(1 - b y2) = (1/b)(1 - e2^2 - e2 d3 (1 + e2)): |v b - 1| <
//        2^-66, so y3 is RN(1/b) or, when a rounding midpoint lies between v and 1/b, the
//        other neighbour of that midpoint.
//   z = RN(y3 + y3 r3), r3 = 1 - b y3 exact (fma: b y3 is a multiple of 2^-105 within 2^-52
//        of 1), and y3 + y3 r3 = 1/b - b eps^2 with eps = 1/b - y3.
// Midpoints in (1/2, 1) are odd multiples of 2^-54 and never 1/b (b m = 1 needs two powers
// of two): |1/b - m| = j 2^-106 / b with j >= 1 an integer; below 1/2 they are 2^-55 from
// it. z = RN(1/b) unless a midpoint lies in [1/b - b eps^2, 1/b):
//   y3 = RN(1/b): |eps| <= 2^-54 and b eps^2 <= 2^-108 b < 2^-106 / b (b < 2): none.
//   y3 above 1/b: z moves away from the midpoint between them, the next one is 2^-53 lower.
//   y3 below 1/b = m + j 2^-106 / b (eps = 2^-54 + j 2^-106 / b, j < 2^40 as |v b - 1| <
//        2^-66): none iff b eps < sqrt(j) 2^-53, i.e. b / 2 + j 2^-53 < sqrt(j): true for
//        j >= 2, and for j = 1 unless b = 2 - 2^-52, a significand of all ones.
// So the block divides when some zi has a significand of all ones ((bits + 1) << 12 = 0)
// or zi >= 2^1000 (its bits compared; +inf too; fmaxnm already made NaN kMinZi): one
// branch, almost never taken. Tests: AsmSpanPersp.ReciprocalWithoutDivide (the same
// operations on 12M inputs: the hard cases next to midpoints, the frecpe table, random) and
// AsmSpanPersp.ShortSpansDivideWhereTheReciprocalCannot (the fallback).
constexpr int kShortMax = 64;
alignas(16) constexpr uint32_t kShortConsts[8] = {120, 120, 120, 120, 1u << 25, 1u << 25, 1u << 25, 1u << 25};
constexpr uint64_t kBiasBits = 0x4338000000000000;  // 2^52 + 2^51 (the deltas' double bias)
constexpr double kOneE9 = 1e9;  // last_steps' |ddf| < 1e9 range
// The rest of persp_short_inl after its sample block (shared with the paired sample block of
// asm/span_persp_a64pair.h): the steps and the runs of a span of n = 17 .. kShortMax pixels
// (runs = (n + 15) / 16 runs, the last one of last = n - 16 (runs - 1) pixels: computed by the
// caller before the sample block, whose NEON results would delay that core work) from its samples S01 = [u_0, v_0, u_1, v_1], S23, S44 ([u_4, v_4] in its low half: only that half
// is read), zs01, zs23 (sums of
// neighbouring samples' z), c01, c23 (the full runs' curve factors) and zh = zc * 0.5 (zc the
// span's dzi). width: an int's value (int64_t: the single-span entry sign-extends it in its
// test's block, so the steps block takes it without a sxtw of its own).
// kLikely4 (persp_short_curve<true>, the single-span entry): runs == 4 as the likely branch.
// kMax3 (the batch loop's pairs of 17 .. 48 px spans, short_samples48): runs is 2 or 3 (the
// four-run path folds away; S44 and c23 are not read).
template <bool kCurve, bool kLikely4 = false, bool kMax3 = false>
SB_INLINE void short_rest(uint8_t* dest, int runs, int last, const uint8_t* texels, int64_t width, double zh,
                          int32x4_t S01, int32x4_t S23, int32x4_t S44, float64x2_t zs01, float64x2_t zs23,
                          float64x2_t c01, float64x2_t c23) {
  const uint32_t w = uint32_t(width);
  // The rest for k = runs - 1 (1, 2, 3) as a constant: the last run's samples and deltas
  // picked without an index. The branch also ends the code block holding the asm block
  // soon after it (under 128 micro-ops: the A72 model's reorder buffer then holds the next
  // span's positions while the divides run).
  auto rest = [&](auto kc) SB_LAMBDA_INLINE {
    constexpr int k = decltype(kc)::value;
    if constexpr (kCurve && k == 3) {  // four runs: asm/span_persp_a64mid.h
      persp_mid_k3(dest, last, texels, width, S01, S23, S44, c01, c23, zs23, zh);
      return;
    }
    if constexpr (kCurve && k == 2) {  // three runs: asm/span_persp_a64few.h
      persp_few_k2(dest, last, texels, width, S01, S23, c01, zs23, zh);
      return;
    }
    if constexpr (kCurve && k == 1) {  // two runs: asm/span_persp_a64few.h
      persp_few_k1(dest, last, texels, width, S01, S23, c01, zs01, zh);
      return;
    }
    // Full runs 0, 1, 2: deltas D01 = [du_0, dv_0, du_1, dv_1], D23 = [du_2, dv_2, du_3, dv_3]
    // (run 3 only as the last run), and the full runs' packed steps dlo (runs 0, 1), dhi
    // (runs 2, 3), ddlo, ddhi (sign-extended du plus dv 2^32: Run16's packing, modulo 2^64).
    int32x4_t D01, D23;
    int64x2_t dlo, dhi, ddlo, ddhi;
    // Deltas as doubles without scvtf (A72 latency 10): the int64 2^52 + 2^51 + x (saddw,
    // |x| < 2^31) is that double's bits, exactly (ulp 1 in [2^52, 2^53)); minus 2^52 + 2^51
    // it is x exactly (x = 0: +0, as scvtf).
    const int64x2_t kBias = vdupq_n_s64(0x4338000000000000);
    auto unbias = [&](int64x2_t b) SB_LAMBDA_INLINE {
      return vsubq_f64(vreinterpretq_f64_s64(b), vreinterpretq_f64_s64(kBias));
    };
    if constexpr (kCurve) {
      // One asm block, the two vectors' chains interleaved for the in-order A53, per lane:
      // ddf = delta (zck (z_a + z_b)) (c01, c23 above; steps16_sel's bits, see persp_fast),
      // dd = cvt_sat(ddf) as fcvtzs to int64 then sqxtn (both saturating, NaN -> 0: the same
      // int32; [du_3, dv_3]'s dd 0), then steps16_dd's 32-bit form: s = delta >> 31, pd =
      // |delta|, pdd = dd mirrored ((dd ^ s) - s); accept = min(|dd|, 2^25) 120 <= pd in
      // uint32 (no wrap: 120 2^25 < 2^32; |dd| >= 2^25 rejects either way, as 120 2^25 >
      // 2^31 > pd); d = accept ? mirror((pd - 120 pdd) >> 4) : mirror(pd >> 4) (both
      // computed, then picked by bit: the pick waits on the test only), dd & accept. Packed:
      // (x & (2^64 - 2^32)) + (x << 32 >> 32, arithmetic) of each 64-bit lane x = [du, dv].
      D23 = S44;
      int64x2_t c01b = vreinterpretq_s64_f64(c01), c23b = vreinterpretq_s64_f64(c23);
      __asm__(
          "ld1r {v17.2d}, [%[kb]]\n\t"
          "ext %[d01].16b, %[s01].16b, %[s23].16b, #8\n\t"
          "ext %[d23].16b, %[s23].16b, %[d23].16b, #8\n\t"
          "ldp q18, q20, [%[kc]]\n\t"
          "sub %[d01].4s, %[d01].4s, %[s01].4s\n\t"
          "sub %[d23].4s, %[d23].4s, %[s23].4s\n\t"
          "saddw v21.2d, v17.2d, %[d01].2s\n\t"
          "saddw2 v22.2d, v17.2d, %[d01].4s\n\t"
          "saddw v23.2d, v17.2d, %[d23].2s\n\t"
          "sshr v24.4s, %[d01].4s, #31\n\t"
          "sshr v25.4s, %[d23].4s, #31\n\t"
          "fsub v21.2d, v21.2d, v17.2d\n\t"
          "fsub v22.2d, v22.2d, v17.2d\n\t"
          "fsub v23.2d, v23.2d, v17.2d\n\t"
          "abs v26.4s, %[d01].4s\n\t"
          "abs v27.4s, %[d23].4s\n\t"
          "fmul v21.2d, v21.2d, %[dlo].d[0]\n\t"
          "fmul v22.2d, v22.2d, %[dlo].d[1]\n\t"
          "fmul v23.2d, v23.2d, %[ddlo].d[0]\n\t"
          "ushr v17.4s, v26.4s, #4\n\t"
          "ushr v28.4s, v27.4s, #4\n\t"
          "fcvtzs v21.2d, v21.2d\n\t"
          "fcvtzs v22.2d, v22.2d\n\t"
          "fcvtzs v23.2d, v23.2d\n\t"
          "eor v17.16b, v17.16b, v24.16b\n\t"
          "eor v28.16b, v28.16b, v25.16b\n\t"
          "sqxtn v21.2s, v21.2d\n\t"
          "sqxtn v23.2s, v23.2d\n\t"
          "sub v17.4s, v17.4s, v24.4s\n\t"
          "sub v28.4s, v28.4s, v25.4s\n\t"
          "sqxtn2 v21.4s, v22.2d\n\t"
          "abs v29.4s, v23.4s\n\t"
          "eor v31.16b, v23.16b, v25.16b\n\t"
          "abs v22.4s, v21.4s\n\t"
          "eor v30.16b, v21.16b, v24.16b\n\t"
          "umin v29.4s, v29.4s, v20.4s\n\t"
          "sub v31.4s, v31.4s, v25.4s\n\t"
          "umin v22.4s, v22.4s, v20.4s\n\t"
          "sub v30.4s, v30.4s, v24.4s\n\t"
          "mul v29.4s, v29.4s, v18.4s\n\t"
          "mov %[dlo].16b, v26.16b\n\t"
          "mul v22.4s, v22.4s, v18.4s\n\t"
          "mov %[ddlo].16b, v27.16b\n\t"
          "mls %[ddlo].4s, v31.4s, v18.s[0]\n\t"
          "mls %[dlo].4s, v30.4s, v18.s[0]\n\t"
          "cmhs v29.4s, v27.4s, v29.4s\n\t"
          "cmhs v22.4s, v26.4s, v22.4s\n\t"
          "ushr %[ddlo].4s, %[ddlo].4s, #4\n\t"
          "ushr %[dlo].4s, %[dlo].4s, #4\n\t"
          "and v23.16b, v23.16b, v29.16b\n\t"
          "and v21.16b, v21.16b, v22.16b\n\t"
          "eor %[ddlo].16b, %[ddlo].16b, v25.16b\n\t"
          "eor %[dlo].16b, %[dlo].16b, v24.16b\n\t"
          "movi v26.2d, #0xffffffff00000000\n\t"
          "shl v27.2d, v23.2d, #32\n\t"
          "sub %[ddlo].4s, %[ddlo].4s, v25.4s\n\t"
          "sub %[dlo].4s, %[dlo].4s, v24.4s\n\t"
          "shl v24.2d, v21.2d, #32\n\t"
          "and %[ddhi].16b, v23.16b, v26.16b\n\t"
          "bit v28.16b, %[ddlo].16b, v29.16b\n\t"
          "bit v17.16b, %[dlo].16b, v22.16b\n\t"
          "and %[ddlo].16b, v21.16b, v26.16b\n\t"
          "ssra %[ddhi].2d, v27.2d, #32\n\t"
          "shl v25.2d, v28.2d, #32\n\t"
          "ssra %[ddlo].2d, v24.2d, #32\n\t"
          "shl v24.2d, v17.2d, #32\n\t"
          "and %[dhi].16b, v28.16b, v26.16b\n\t"
          "and %[dlo].16b, v17.16b, v26.16b\n\t"
          "ssra %[dhi].2d, v25.2d, #32\n\t"
          "ssra %[dlo].2d, v24.2d, #32"
          : [d01] "=&w"(D01), [d23] "+&w"(D23), [dlo] "+&w"(c01b), [ddlo] "+&w"(c23b), [dhi] "=&w"(dhi),
            [ddhi] "=&w"(ddhi)
          : [s01] "w"(S01), [s23] "w"(S23), [kb] "r"(&kBiasBits), [kc] "r"(kShortConsts), "m"(kBiasBits),
            "m"(kShortConsts)
          : "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "v30", "v31");
      dlo = c01b, ddlo = c23b;
    } else {
      D01 = vsubq_s32(vextq_s32(S01, S23, 2), S01);
      D23 = vsubq_s32(vextq_s32(S23, S44, 2), S23);
      // delta / 16 truncated: (delta + (delta < 0 ? 15 : 0)) >> 4.
      auto div16 = [](int32x4_t x) SB_LAMBDA_INLINE {
        return vshrq_n_s32(vreinterpretq_s32_u32(vsraq_n_u32(vreinterpretq_u32_s32(x),
                                                             vreinterpretq_u32_s32(vshrq_n_s32(x, 31)), 28)), 4);
      };
      const int32x4_t d01 = div16(D01), d23 = div16(D23);
      // The full runs' packed steps, for runs 0, 1 and 2, 3.
      const int32x4_t U = vuzp1q_s32(d01, d23), V = vuzp2q_s32(d01, d23);
      dlo = vaddq_s64(vmovl_s32(vget_low_s32(U)), vshll_n_s32(vget_low_s32(V), 32));
      dhi = vaddq_s64(vmovl_high_s32(U), vshll_high_n_s32(V, 32));
      ddlo = ddhi = vdupq_n_s64(0);
    }
    // The full runs' packed starts (a sample's [u, v] lane pair is v 2^32 + u).
    const uint64x2_t st01 = vreinterpretq_u64_s32(S01), st23 = vreinterpretq_u64_s32(S23);
    // The last run's start (sample k: one 64-bit lane, v 2^32 + u) and z_k + z_{k+1}.
    const uint64_t xk = vgetq_lane_u64(k < 2 ? st01 : st23, k & 1);
    const int32_t au = int32_t(uint32_t(xk)), av = int32_t(xk >> 32);
    const double zmk = vgetq_lane_f64(k < 2 ? zs01 : zs23, k & 1);
    RunSteps lu, lv;
    // The last run's deltas from D01, D23 (lanes 2 k - 2, 2 k - 1 of the pair) as doubles
    // (unbias) and as integers: one 64-bit lane move (dv 2^32 + du), split in the integer unit.
    const float64x2_t fd = unbias(k == 1 ? vaddw_high_s32(kBias, D01)
                                         : (k == 2 ? vaddw_s32(kBias, vget_low_s32(D23)) : vaddw_high_s32(kBias, D23)));
    const uint64_t dk = vgetq_lane_u64(vreinterpretq_u64_s32(k == 1 ? D01 : D23), k == 2 ? 0 : 1);
    if constexpr (kCurve) {
      last_steps(last - 1, int32_t(uint32_t(dk)), int32_t(dk >> 32), fd, zh * zmk, &lu, &lv);
    } else {
      // Linear (curve 0): run_steps' {delta / steps, 0} (truncating; |delta| < 2^31), one
      // 32-bit divide each; steps 0 (a one-pixel last run) draws no step: any divisor.
      const int32_t s = last > 2 ? last - 1 : 1;
      lu = RunSteps{int32_t(uint32_t(dk)) / s, 0};
      lv = RunSteps{int32_t(dk >> 32) / s, 0};
    }
    auto full = [&](auto jc) SB_LAMBDA_INLINE {
      constexpr int j = decltype(jc)::value, l = j & 1;
      const uint64_t a0 = vgetq_lane_u64(j < 2 ? st01 : st23, l);
      const uint64_t d0 = uint64_t(vgetq_lane_s64(j < 2 ? dlo : dhi, l));
      const uint64_t dd = uint64_t(vgetq_lane_s64(j < 2 ? ddlo : ddhi, l));
      Run16<kCurve> run(a0, d0, dd, typename Run16<kCurve>::Packed{});
      run.draw(dest + 16 * j, texels, w);
    };
    // Two 16-pixel runs as one pass: the long spans' pipeline without stage work, in one asm
    // block (asm/span_persp_a64pass.h).
    auto pass = [&](uint8_t* d, uint64_t a_uv, uint64_t a_d, uint64_t a_dd, uint64_t b_uv, uint64_t b_d,
                    uint64_t b_dd) SB_LAMBDA_INLINE {
      short_pass<kCurve>(d, texels, uint64_t(width), a_uv, a_d, a_dd, b_uv, b_d, b_dd);
    };
    auto packed = [](const RunSteps& su, const RunSteps& sv) {
      return (uint64_t(uint32_t(sv.d)) << 32) + uint64_t(int64_t(su.d));
    };
    const uint64_t luv = xk;
    const uint64_t ld = packed(lu, lv), ldd = (uint64_t(uint32_t(lv.dd)) << 32) + uint64_t(int64_t(lu.dd));
    if (k == 1) {
      full(std::integral_constant<int, 0>{});
    } else {
      pass(dest, vgetq_lane_u64(st01, 0), uint64_t(vgetq_lane_s64(dlo, 0)), uint64_t(vgetq_lane_s64(ddlo, 0)),
           vgetq_lane_u64(st01, 1), uint64_t(vgetq_lane_s64(dlo, 1)), uint64_t(vgetq_lane_s64(ddlo, 1)));
      if (k == 3 && last == 16) {
        pass(dest + 32, vgetq_lane_u64(st23, 0), uint64_t(vgetq_lane_s64(dhi, 0)), uint64_t(vgetq_lane_s64(ddhi, 0)),
             luv, ld, ldd);
        return;
      }
      if (k > 2) full(std::integral_constant<int, 2>{});
    }
    dest += 16 * k;
    if (last == 16) {
      draw16<kCurve>(dest, texels, w, au, av, lu, lv);
    } else {
      draw_last<kCurve>(dest, last, texels, w, uint32_t(au), uint32_t(av), uint32_t(lu.d), uint32_t(lv.d), uint32_t(lu.dd),
               uint32_t(lv.dd));
    }
  };
  // Four runs first: of the short spans, those hold the most pixels (a branch less for them).
  if (!kMax3 && (kLikely4 ? __builtin_expect(runs == 4, 1) : runs == 4)) {
    rest(std::integral_constant<int, 3>{});
  } else {
    // S01, S23 kept in v5, v19 (where the pair block leaves span a's and steps_k3v_pass takes
    // them) into the shorter spans' paths too: otherwise the compiler copied them to other
    // registers before the runs == 4 test, on the four-run path as well (no code emitted).
    if constexpr (kCurve) {
      register int32x4_t r01 __asm__("v5") = S01;
      register int32x4_t r23 __asm__("v19") = S23;
      register double rzh __asm__("v31") = zh;  // (where short_samples1 leaves it) likewise
      __asm__("" : "+w"(r01), "+w"(r23), "+w"(rzh));
      S01 = r01, S23 = r23, zh = rzh;
    }
    if (runs == 3) {
      rest(std::integral_constant<int, 2>{});
    } else {
      rest(std::integral_constant<int, 1>{});
    }
  }
}
// A short span's samples (persp_short_inl<true>'s sample block), zc its dzi: S01 = [u_0, v_0,
// u_1, v_1], S23, S44 = [u_4, v_4, 0, 0] (short_rest reads its low half only), zs01, zs23, c01,
// c23 (see below); ShortSamples holds them (asm/span_persp_a64pair.h's paired block stores them
// so, S44 there sample 4 twice); zh = zc * 0.5 (short_rest's).
struct alignas(16) ShortSamples {
  int32x4_t S01, S23, S44;
  float64x2_t zs01, zs23, c01, c23;
};
// short_samples1's head: its first load and constant, as their own asm text so that the
// single-span entry does them in its test's block (short_curve_a64, asm/span_persp_fast.cpp:
// the load's latency under the test's, before the branch) and persp_short_curve otherwise
// (short_head_asm): pos = [px0, 0], sixteen = [16.0, 0], zc = dzi (pinned to v0, v1, v31:
// short_samples1's asm takes them there) and idx = n - 17 (kShortOffs's row).
struct ShortHead {
  float64x2_t pos, sixteen;
  double zc;
  uint64_t idx;
};
// kShortOffs.at[n - 17] = {o_0, o_1, o_2, 0} for n = 17 .. 64: the sample offsets o_0 = min(32,
// n - 1), o_1 = min(32, n - 17), o_2 = n - 33 as doubles (short_samples1 loads them: no
// conversions in its block); 32-byte rows (an index shift).
struct alignas(32) ShortOffs1 {
  double o[4];
};
struct ShortOffsTable1 {
  ShortOffs1 at[48];
  constexpr ShortOffsTable1() : at{} {
    for (int n = 17; n <= 64; ++n)
      at[n - 17] = ShortOffs1{{double(n - 1 < 32 ? n - 1 : 32), double(n - 17 < 32 ? n - 17 : 32), double(n - 33), 0.0}};
  }
};
constexpr ShortOffsTable1 kShortOffs;
static_assert(sizeof(ShortOffs1) == 32 && kShortOffs.at[47].o[0] == 32.0 && kShortOffs.at[23].o[1] == 23.0 &&
              kShortOffs.at[0].o[2] == -16.0);
static_assert(offsetof(PerspSpan, px0) == 48 && offsetof(PerspSpan, dzi) == 8);
// n = 17 .. kShortMax.
SB_INLINE void short_head_asm(const PerspSpan& p, int n, ShortHead& h) {
  register float64x2_t r0 __asm__("v0"), r1 __asm__("v1");
  register double r31 __asm__("v31");
  uint64_t t;
  __asm__("ldr d0, [%[p], #48]\n\t"
          "fmov d1, #16.0\n\t"
          "ldr d31, [%[p], #8]\n\t"
          "sub %w[t], %w[n], #17"
          : "=w"(r0), "=w"(r1), "=w"(r31), [t] "=r"(t)
          : [p] "r"(&p), [n] "r"(n), "m"(p));
  h = ShortHead{r0, r1, r31, t};
}
SB_INLINE void short_samples1(const PerspSpan& p, int n, const ShortHead& h, int32x4_t& S01, int32x4_t& S23,
                              int32x4_t& S44, float64x2_t& zs01, float64x2_t& zs23, float64x2_t& c01, float64x2_t& c23,
                              double& zh) {
  // Contract: n = 17 .. kShortMax, h this span's head (h.idx = n - 17 picks kShortOffs's row;
  // AsmSpanPerspBatch.EveryPartialLastRunLengthMatchesOnEveryPath draws every such n through
  // the single entry). One asm block, each operation the vector code's lane operation (the
  // same bits):
  // positions P_0, P_1 = P_0 + 16 ([P_0, P_1] = pA), pB = pA + [o_0, o_1], pC = (P_1 + 16)
  // + o_2 with o_j = min(32, n - 16 j - 1); zi = zrow + zix pos (fmla, fmadd); the
  // [u, v] products uvrow + uvx pos beside the depth chains; the reciprocals 1 / max(zi,
  // kMinZi) (above: zA, zB in 2 lanes, zC scalar, the three chains level by level, the
  // range and all-ones test in their latency gaps; the divides only on the branch), then
  // the samples: to_fixed as fcvtzu #16 of (uv z), uqxtn, umin with [umax, vmax] (the
  // clamp at 0 folded into the unsigned conversion; AsmSpanPersp.UnsignedFixedPoint...).
  // Two samples per vector: S01 = [u_0, v_0, u_1, v_1], S23; S44 = [u_4, v_4, 0, 0] (its users
  // read the low half only: one uqxtn2 fewer in the tail than sample 4 twice). Ordered
  // for the in-order A53 (a consumer after its producer's latency; its model also completes
  // in order, so each latency gap holds work of the same or shorter latency); the
  // accumulators are loaded (ld1r, ld2), not copied, and pA is merged with trn1 (A72:
  // latency 3, an element insert 8); the offsets o are loaded as doubles (kShortOffs, row
  // h.idx), not converted. zck = zc * -1/16 (the runs' steps below) in a gap too,
  // and zh = zc * 0.5 (short_rest's, the same bits as the compiler's multiply): zh is zc on
  // entry (one register, not a copy), multiplied after zck's product has read it.
  // Second order: the sums of neighbouring samples' z, zs01 = [z_0 + z_1, z_1 + z_2], zs23 =
  // [z_2 + z_3, z_3 + z_4] (the last run's z_k + z_{k+1}) and c01 = zs01 zck, c23 = zs23 zck
  // (the full runs' curve factors), also in the block (the conversions' latency gaps).
  // zck = zc * -1/16 (the full runs' curve factors) in v6 once o_2 is read. zc (dzi) in, zc *
  // 0.5 out, in v31 (where steps_k3v_pass takes it: no copy before that block). Caller-saved
  // vector registers but v9 (its callers save d9 already: steps_k3v_pass uses it, spans_range
  // saves d8 .. d15): kMinZi in v5 until the Newton steps take it, the range test's maximum in
  // v4 once o_0, o_1 are read, the B and C reciprocals in v21, v23 (free once their [u, v] rows
  // are multiplied in), the clamp [umax, vmax] in v9 (ldr, dup before the fallback branch: the
  // tail after it, which waits on its results, holds two instructions fewer).
  // Its order: bench/order_search.py on the block as qemu cuts it after the single entry's
  // test (bench/mca_a53_pair/README.md, "the single entry's head").
  register double rzh __asm__("v31") = h.zc;
  register float64x2_t rzs01 __asm__("v0") = h.pos;
  register float64x2_t rzs23 __asm__("v1") = h.sixteen;
  register float64x2_t rc01 __asm__("v3");
  register float64x2_t rc23 __asm__("v16");
  register int32x4_t rS01 __asm__("v5");
  register int32x4_t rS23 __asm__("v19");
  register int32x4_t rS44 __asm__("v7");
  uint64_t t0, t1, t2, t5, t6, t7;
  // BEGIN short_samples1
  __asm__ volatile(
      "adrp %[t1], %[tbl]\n\t"
      "add %[t0], %[p], #16\n\t"
      "add %[t1], %[t1], %[idx], lsl #5\n\t"
      "fadd d2, d0, d1\n\t"
      "ld1r {v26.2d}, [%[p]]\n\t"
      "ld2r {v16.2d, v17.2d}, [%[p]]\n\t"
      "ldr q4, [%[t1], #:lo12:%[tbl]]\n\t"
      "ldr d6, [%[t1], #:lo12:%[tbl]+16]\n\t"
      "trn1 v0.2d, v0.2d, v2.2d\n\t"
      "ld2 {v22.2d, v23.2d}, [%[t0]]\n\t"
      "fadd d3, d2, d1\n\t"
      "mov %[t5], #0xbfb0000000000000\n\t"
      "ld1r {v5.2d}, [%[km]]\n\t"
      "ld1r {v27.2d}, [%[p]]\n\t"
      "fmov v1.2d, #1.0\n\t"
      "fadd v7.2d, v0.2d, v4.2d\n\t"
      "fmla v26.2d, v17.2d, v0.2d\n\t"
      "ld2 {v20.2d, v21.2d}, [%[t0]]\n\t"
      "fadd d3, d3, d6\n\t"
      "fmov d6, %[t5]\n\t"
      "fmla v27.2d, v17.2d, v7.2d\n\t"
      "ld2 {v29.2d, v30.2d}, [%[t0]]\n\t"
      "fmaxnm v26.2d, v26.2d, v5.2d\n\t"
      "fmadd d28, d17, d3, d16\n\t"
      "fmla v22.2d, v23.2d, v7.d[0]\n\t"
      "fmla v20.2d, v21.2d, v0.d[1]\n\t"
      "frecpe v2.2d, v26.2d\n\t"
      "fmaxnm v27.2d, v27.2d, v5.2d\n\t"
      "fmov d18, #0.5\n\t"
      "ld2 {v24.2d, v25.2d}, [%[t0]]\n\t"
      "fmov %[t1], d26\n\t"
      "fmaxnm d28, d28, d5\n\t"
      "mov %[t2], v26.d[1]\n\t"
      "frecps v5.2d, v26.2d, v2.2d\n\t"
      "frecpe v21.2d, v27.2d\n\t"
      "fmax v4.2d, v26.2d, v27.2d\n\t"
      "fmul d6, %d[zh], d6\n\t"
      "fmov %[t7], d27\n\t"
      "fmul %d[zh], %d[zh], d18\n\t"
      "frecpe d23, d28\n\t"
      "mov %[t6], v27.d[1]\n\t"
      "fmul v2.2d, v2.2d, v5.2d\n\t"
      "ld2 {v18.2d, v19.2d}, [%[t0]]\n\t"
      "fmov %[t0], d28\n\t"
      "frecps v16.2d, v27.2d, v21.2d\n\t"
      "fmaxp d4, v4.2d\n\t"
      "frecps d17, d28, d23\n\t"
      "ldr d9, [%[p], #56]\n\t"
      "add %[t1], %[t1], #1\n\t"
      "add %[t0], %[t0], #1\n\t"
      "lsl %[t0], %[t0], #12\n\t"
      "add %[t6], %[t6], #1\n\t"
      "lsl %[t1], %[t1], #12\n\t"
      "fmul v21.2d, v21.2d, v16.2d\n\t"
      "fmul d23, d23, d17\n\t"
      "frecps v5.2d, v26.2d, v2.2d\n\t"
      "fmax d4, d4, d28\n\t"
      "add %[t7], %[t7], #1\n\t"
      "add %[t2], %[t2], #1\n\t"
      "lsl %[t7], %[t7], #12\n\t"
      "clz %[t1], %[t1]\n\t"
      "lsl %[t6], %[t6], #12\n\t"
      "frecps v16.2d, v27.2d, v21.2d\n\t"
      "frecps d17, d28, d23\n\t"
      "clz %[t7], %[t7]\n\t"
      "lsl %[t2], %[t2], #12\n\t"
      "fmul v2.2d, v2.2d, v5.2d\n\t"
      "mov v5.16b, v1.16b\n\t"
      "fmul d23, d23, d17\n\t"
      "fmul v21.2d, v21.2d, v16.2d\n\t"
      "mov v16.16b, v1.16b\n\t"
      "clz %[t6], %[t6]\n\t"
      "clz %[t2], %[t2]\n\t"
      "orr %[t7], %[t7], %[t6]\n\t"
      "orr %[t1], %[t1], %[t2]\n\t"
      "fmov %[t5], d4\n\t"
      "fmls v5.2d, v26.2d, v2.2d\n\t"
      "fmsub d17, d28, d23, d1\n\t"
      "fmls v16.2d, v27.2d, v21.2d\n\t"
      "clz %[t0], %[t0]\n\t"
      "orr %[t1], %[t1], %[t7]\n\t"
      "lsr %[t5], %[t5], #52\n\t"
      "fmla v2.2d, v2.2d, v5.2d\n\t"
      "fmadd d23, d23, d17, d23\n\t"
      "fmla v21.2d, v21.2d, v16.2d\n\t"
      "mov v5.16b, v1.16b\n\t"
      "mov v16.16b, v1.16b\n\t"
      "orr %[t1], %[t1], %[t0]\n\t"
      "add %[t5], %[t5], #0x19\n\t"
      "lsr %[t5], %[t5], #5\n\t"
      "fmla v18.2d, v19.2d, v0.d[0]\n\t"
      "fmls v5.2d, v26.2d, v2.2d\n\t"
      "fmls v16.2d, v27.2d, v21.2d\n\t"
      "fmsub d17, d28, d23, d1\n\t"
      "fmla v29.2d, v30.2d, v3.d[0]\n\t"
      "orr %[t1], %[t1], %[t5]\n\t"
      "fmla v24.2d, v25.2d, v7.d[1]\n\t"
      "fmla v21.2d, v21.2d, v16.2d\n\t"
      "fmadd d23, d23, d17, d23\n\t"
      "fmla v2.2d, v2.2d, v5.2d\n\t"
      "dup v9.2d, v9.d[0]\n\t"
      "tbz %[t1], #6, 2f\n\t"
      "fdiv v2.2d, v1.2d, v26.2d\n\t"
      "fdiv v21.2d, v1.2d, v27.2d\n\t"
      "fdiv d23, d1, d28\n\t"
      "2:\n\t"
      "fmul v18.2d, v18.2d, v2.d[0]\n\t"
      "fmul v22.2d, v22.2d, v21.d[0]\n\t"
      "ext v1.16b, v21.16b, v23.16b, #8\n\t"
      "fmul v29.2d, v29.2d, v23.d[0]\n\t"
      "fmul v20.2d, v20.2d, v2.d[1]\n\t"
      "fmul v24.2d, v24.2d, v21.d[1]\n\t"
      "fcvtzu v18.2d, v18.2d, #16\n\t"
      "ext v0.16b, v2.16b, v21.16b, #8\n\t"
      "fcvtzu v22.2d, v22.2d, #16\n\t"
      "fcvtzu v29.2d, v29.2d, #16\n\t"
      "fcvtzu v20.2d, v20.2d, #16\n\t"
      "uqxtn v5.2s, v18.2d\n\t"
      "fcvtzu v24.2d, v24.2d, #16\n\t"
      "uqxtn v19.2s, v22.2d\n\t"
      "fadd v0.2d, v2.2d, v0.2d\n\t"
      "uqxtn v7.2s, v29.2d\n\t"
      "fadd v1.2d, v21.2d, v1.2d\n\t"
      "uqxtn2 v5.4s, v20.2d\n\t"
      "uqxtn2 v19.4s, v24.2d\n\t"
      "umin v7.2s, v7.2s, v9.2s\n\t"
      "fmul v3.2d, v0.2d, v6.d[0]\n\t"
      "umin v5.4s, v5.4s, v9.4s\n\t"
      "fmul v16.2d, v1.2d, v6.d[0]\n\t"
      "umin v19.4s, v19.4s, v9.4s"
      : "+&w"(rzs01), "+&w"(rzs23), "=&w"(rc01), "=&w"(rc23), "=&w"(rS01), "=&w"(rS23), "=&w"(rS44),
        [t0] "=&r"(t0), [t1] "=&r"(t1), [t2] "=&r"(t2), [t5] "=&r"(t5), [t6] "=&r"(t6), [t7] "=&r"(t7),
        [zh] "+&w"(rzh)
      : [p] "r"(&p), [n] "r"(n), [km] "r"(&kMinZi), [idx] "r"(h.idx), [tbl] "S"(&kShortOffs), "m"(p), "m"(kMinZi)
      : "cc", "v2", "v4", "v6", "v9", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28",
        "v29", "v30");
  // END short_samples1
  zs01 = rzs01, zs23 = rzs23, c01 = rc01, c23 = rc23;
  S01 = rS01, S23 = rS23, S44 = rS44;
  zh = rzh;
}
// persp_short_inl<true>'s span (second order, zc = dzi) with its sample block's head h done
// (short_head_asm, or the single-span entry's test block).
// kSingle (the single-span entry; the batch loop's lone spans keep their code): the four-run
// path laid out as the likely one (the compiler then ends it in its own copy of the epilogue,
// in the last chunk's qemu block, not behind a branch to a shared one), and no value lives
// from before the sample block into the rest in x1 .. x17 or x19 .. x25 (the registers the
// steps block writes; an empty asm clobbers them after the sample block). Without the
// latter the compiler kept kMinZi's address, which it also takes as the base of the rest's
// table addresses, in one of them: the steps block's prefix then reads a register the block
// itself overwrites, and timed as a loop (the A57 model) each run waits on the last one's
// write (A72 +0.18 c/px when the width's sxtw left short_curve_a64's asm).
template <bool kSingle = false>
SB_INLINE void persp_short_curve(uint8_t* dest, int n, const uint8_t* texels, int64_t width, const PerspSpan& p,
                                 const ShortHead& h) {
  const int runs = (n + 15) >> 4, last = n - 16 * (runs - 1);
  int32x4_t S01, S23, S44;
  float64x2_t zs01, zs23, c01, c23;
  double zh;  // zc / 2, from the sample block's spare slots
  short_samples1(p, n, h, S01, S23, S44, zs01, zs23, c01, c23, zh);
  if constexpr (kSingle)
    __asm__ volatile("" ::: "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x13", "x14",
                     "x15", "x16", "x17", "x19", "x20", "x21", "x22", "x23", "x24", "x25");
  short_rest<true, kSingle>(dest, runs, last, texels, width, zh, S01, S23, S44, zs01, zs23, c01, c23);
}
template <bool kCurve>
SB_INLINE void persp_short_inl(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  if constexpr (!kCurve) {
    persp_short_lin(dest, n, texels, width, p);  // asm/span_persp_a64lin.h
  } else {
    // Only second-order spans come here (persp_one_c's curve): zc = dzi, the head's.
    ShortHead h;
    short_head_asm(p, n, h);
    persp_short_curve(dest, n, texels, width, p, h);
  }
}
// The same, out of line (persp_fast's linear instance keeps a call to it); the
// dispatcher (surface_span_persp_fast) inlines persp_short_inl.
template <bool kCurve>
void persp_short(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  persp_short_inl<kCurve>(dest, n, texels, width, p);
}
#else
constexpr int kShortMax = 16;  // elsewhere the long-span code (its overlap wins there)
template <bool kCurve>
void persp_short(uint8_t*, int, const uint8_t*, int, const PerspSpan&) {}
template <bool kCurve>
void persp_short_inl(uint8_t*, int, const uint8_t*, int, const PerspSpan&) {}
#endif

}  // namespace
}  // namespace sb::simd
