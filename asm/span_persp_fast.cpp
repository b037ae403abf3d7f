// asm/span_persp_fast.cpp: the tuned whole-span lit-surface drawer (asm/span_persp.h) and
// surface_span_fast (asm/surface_span.h), which shares its runs. Helpers:
// asm/span_persp_run.h (runs, steps, samples), asm/span_persp_arm.h (ARM passes, last
// steps, short spans). The samples' positions are accumulated as the walker
// (asm/span_walk.h) accumulates them.
#include "asm/span_persp.h"

#include "asm/span_persp_arm.h"
#include "asm/span_persp_run.h"
#include "asm/span_persp_a64lin_pass.h"
#include "asm/span_persp_a64long.h"
#include "asm/span_persp_a64longspan.h"
#include "asm/span_persp_a64pair.h"
#include "asm/span_persp_a64pair48.h"
#include "asm/span_persp_a64tiny.h"
#include "asm/span_persp_v7mid.h"
#include "asm/span_persp_v7pass.h"
#include "asm/span_persp_v7one.h"
#include "asm/span_persp_v7five.h"
#include "asm/span_persp_x86short.h"
#include "asm/surface_span.h"

namespace sb::simd {

// ARM: 2 KiB-aligned (the function is ~1.6 KiB on armhf), so no 4 KiB page end falls in it
// whatever the code before it weighs (qemu cuts the blocks bench/count.sh times at page ends:
// the ARMv7 long path's growth once put one in its 16-pixel loop, A9 span1920 4.62 -> 4.78).
#if defined(__arm__) || defined(__aarch64__)
__attribute__((aligned(2048)))
#endif
void surface_span_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int, int32_t u, int32_t v,
                       int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  const uint32_t w = uint32_t(width);
  if (n == 16) return draw16(dest, texels, w, u, v, RunSteps{du, ddu}, RunSteps{dv, ddv});  // the engine's runs
  uint32_t uu = uint32_t(u), vv = uint32_t(v), duu = uint32_t(du), dvv = uint32_t(dv);
  const uint32_t dduu = uint32_t(ddu), ddvv = uint32_t(ddv);
  for (; n >= 16; n -= 16, dest += 16) {
    draw16(dest, texels, w, int32_t(uu), int32_t(vv), RunSteps{int32_t(duu), ddu}, RunSteps{int32_t(dvv), ddv});
    // 16 pixels on (mod 2^32): u += 16 du + 120 ddu, du += 16 ddu.
    uu += 16 * duu + 120 * dduu;
    vv += 16 * dvv + 120 * ddvv;
    duu += 16 * dduu;
    dvv += 16 * ddvv;
  }
  if (n > 0) draw_last<true>(dest, n, texels, w, uu, vv, duu, dvv, dduu, ddvv);
}

namespace {

// ARMv7: persp_fast inlined into surface_span_persp_fast (one function entry per span).
#if defined(__arm__) && !defined(__aarch64__)
#define SB_V7_INLINE inline __attribute__((always_inline))
#define SB_V7_LAMBDA_INLINE __attribute__((always_inline))
#else
#define SB_V7_INLINE
#define SB_V7_LAMBDA_INLINE
#endif

// kCurve false: linear steps (Quake's way: second_order off, or a constant 1/z along the
// row, whose curve factor is 0), the steps delta / 16 and no second-order adds per pixel.
// aarch64: persp_fast_inl, inlined into persp_lin_a64 (below), and persp_fast calling it;
// elsewhere this is persp_fast itself.
#if defined(__aarch64__) && defined(__GNUC__)
#define SB_PERSP_FAST_BODY SB_INLINE void persp_fast_inl
#else
#define SB_PERSP_FAST_BODY SB_V7_INLINE void persp_fast
#endif
// kLong (ARMv7): persp_long_run_v7's instance (the NEON pass; see there).
#if defined(SB_V7_NEON_STEPS)
template <bool kCurve, bool kLong = false>
#else
template <bool kCurve>
#endif
SB_PERSP_FAST_BODY(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  if (n <= 0) return;
  // Long spans. Runs r = 0, 1, ... of 16 pixels; sample j (a run's first pixel, or the
  // span's last one) at pixel offset o_j = min(16 j, n - 1), its position computed as the
  // walker computes it: P_0 + o_1 for j = 1, else P_{j-2} + (o_j - o_{j-2}), where
  // P_r = P_{r-1} + 16 is run r's first pixel, accumulated. `left` = pixels from run r on.
  // The loop draws two runs per pass; the divides for the samples two runs ahead are issued
  // in pairs, their to_fixed and the following runs' steps are done beside the drawing, all
  // branch-free (one block per pass).
  const double zrow = p.zi0, zix = p.dzi, urow = p.uz0, ux = p.duz, vrow = p.vz0, vx = p.dvz;
  const double umaxd = double(p.umax), vmaxd = double(p.vmax);
  double zc = p.second_order ? zix : 0.0;  // (persp_long_run_v7's instance: pinned below)
  const uint32_t w = uint32_t(width);
  const double kUmax = bound16(p.umax), kVmax = bound16(p.vmax);
  auto sample = [&](double px, double z) {
    if constexpr (kFixed16) {  // armhf: to_fixed in the VFP/NEON registers (see min_ufixed16)
      const double qu = min_ufixed16(cvt_ufixed16((urow + ux * px) * z), kUmax);
      const double qv = min_ufixed16(cvt_ufixed16((vrow + vx * px) * z), kVmax);
      return Sample{fixed16_bits_if<kCurve>(qu), fixed16_bits_if<kCurve>(qv), z};
    } else if constexpr (kIntClamp) {
      return Sample{to_fixed_int((urow + ux * px) * z, p.umax), to_fixed_int((vrow + vx * px) * z, p.vmax), z};
    } else {
      return Sample{to_fixed_sel((urow + ux * px) * z, umaxd), to_fixed_sel((vrow + vx * px) * z, vmaxd), z};
    }
  };
  double P = p.px0;
  int left = n;
  double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;
  if (n <= 16) {  // one run, from pixel 0 to pixel n - 1 (one pixel: steps 0, no second sample)
    const double pos1 = P + double(n - 1);
    recip2(zrow + zix * P, zrow + zix * pos1, &z0, &z1);
    const Sample s0 = sample(P, z0), s1 = n > 1 ? sample(pos1, z1) : s0;
    const double curve = zc * 0.5 * (s0.z + s1.z);
    RunSteps su, sv;
    if constexpr (kCurve && kLastSteps) {
      last_steps(n - 1, s0, s1, curve, &su, &sv);
    } else {
      run_steps_uv(n - 1, s0, s1, curve, &su, &sv);
    }
    if (n == 16) {
      draw16<kCurve>(dest, texels, w, s0.u, s0.v, su, sv);
    } else {
      draw_last<kCurve>(dest, n, texels, w, uint32_t(s0.u), uint32_t(s0.v), uint32_t(su.d), uint32_t(sv.d), uint32_t(su.dd),
               uint32_t(sv.dd));
    }
    return;
  }
  // 17 .. kShortMax pixels: persp_short, which surface_span_persp_fast calls directly. The
  // linear instance keeps this (never taken) call: without it GCC scheduled its long-span
  // loop worse (A53 persp1920lin 6.84 -> 7.09).
  if (!kCurve && n <= kShortMax) return persp_short<kCurve>(dest, n, texels, width, p);
  // ARMv7 linear: the four divides first, samples 0 and 1 after (the in-order FP pipe of
  // the modelled Cortex-A9 waits on the first quotient; the other divides issue meanwhile).
  // Elsewhere samples 0 and 1 between (there it schedules better).
#if defined(__arm__) && !defined(__aarch64__)
  constexpr bool kDivFirst = !kCurve;
#else
  constexpr bool kDivFirst = false;
#endif
  // aarch64 linear: the head's samples 0 .. 3 and run 0's steps in the vector block below
  // (the vector loop always runs there: n > kShortMax = 64 > 48; the scalar head here is
  // skipped), the tail's samples r + 2, r + 3 as that loop converted them, and its last
  // steps by sdiv (below).
#if defined(__aarch64__) && defined(__GNUC__)
  constexpr bool kPre = !kCurve;
#else
  constexpr bool kPre = false;
#endif
  // x86-64: the long tail's second-order last-run steps by last_steps (the portable
  // last_steps_q: two double quotients, no branch) instead of run_steps_uv's call and jump
  // table (skylake persp64 7.48 -> 6.86, persp192 5.04 -> 4.97, znver3 6.42 -> 5.63,
  // 4.29 -> 4.03; the long loop's code moved: skylake persp1920 4.03 -> 4.15, znver3 3.43
  // -> 3.36). Not in the one-run path (n <= 16) too: with no call left in persp_fast GCC
  // spilled the loop's values to the red zone (skylake persp192 5.04 -> 5.13).
#if defined(__x86_64__)
  [[maybe_unused]] constexpr bool kX86 = true;
#else
  [[maybe_unused]] constexpr bool kX86 = false;
#endif
  Sample s0{}, s1{};
  double pos2 = 0.0, pos3 = 0.0;
#if defined(__arm__) && !defined(__aarch64__)
  // Samples 0 and 1; armhf second order (kFixed16) keeps their clamped VFP values for the
  // steps below: sample()'s operations.
  double pu0 = 0.0, pv0 = 0.0, pu1 = 0.0, pv1 = 0.0, c0p = 0.0;
  auto samples01 = [&] SB_LAMBDA_INLINE {
    if constexpr (kCurve && kFixed16) {
      // Pinned step by step: the modelled Cortex-A9's in-order FP pipe then overlaps the
      // four chains (GCC interleaved them with the core moves).
      const double P1 = P + double(16);
      const double tu0 = urow + ux * P, tv0 = vrow + vx * P, tu1 = urow + ux * P1, tv1 = vrow + vx * P1;
      pu0 = tu0 * z0, pv0 = tv0 * z0;
      pin7(pu0), pin7(pv0);
      pu1 = tu1 * z1, pv1 = tv1 * z1;
#if defined(SB_V7_NEON_STEPS)
      if constexpr (!kLong) c0p = (zc * -0.0625) * (z0 + z1);
#else
      c0p = (zc * -0.0625) * (z0 + z1);
#endif
      pin7(pu1), pin7(pv1);
      pu0 = cvt_ufixed16(pu0), pv0 = cvt_ufixed16(pv0), pu1 = cvt_ufixed16(pu1), pv1 = cvt_ufixed16(pv1);
#if defined(SB_V7_NEON_STEPS)
      if constexpr (kLong) c0p = (zc * -0.0625) * (z0 + z1);  // after (the pipe waited on it)
#endif
      pu0 = min_ufixed16(pu0, kUmax), pv0 = min_ufixed16(pv0, kVmax);
      pu1 = min_ufixed16(pu1, kUmax), pv1 = min_ufixed16(pv1, kVmax);
      pin7(pu0), pin7(pv0), pin7(pu1), pin7(pv1);
      s0 = Sample{fixed16_bits_v(pu0), fixed16_bits_v(pv0), z0};
      s1 = Sample{fixed16_bits_v(pu1), fixed16_bits_v(pv1), z1};
    } else {
      s0 = sample(P, z0), s1 = sample(P + double(16), z1);
    }
  };
#if defined(SB_V7_NEON_STEPS)
  // persp_long_run_v7's instance: (urow + ux pos) of samples 2 and 3 (tu2 .. tv3 below),
  // computed before their divides (the in-order FP pipe has free slots there).
  double etu2 = 0.0, etv2 = 0.0, etu3 = 0.0, etv3 = 0.0;
#endif
  if (n > 32) {  // ARMv7: the four clamps branch-free, the four divides back to back
    pos2 = P + double(32);
    pos3 = (P + double(16)) + double(n - 17 < 32 ? n - 17 : 32);
    const double zi0 = max_or_lo_sel(zrow + zix * P, kMinZi), zi1 = max_or_lo_sel(zrow + zix * (P + double(16)), kMinZi);
    if constexpr (kCurve && kFixed16) {
      // The divides in this order (volatile asm), samples 2 and 3's depths computed after
      // the first two divides are issued (pinned positions): those start earlier.
      z0 = recip7(zi0), z1 = recip7(zi1);
#if defined(SB_V7_NEON_STEPS)
      // persp_long_run_v7's instance: zc's products (zc / 2, zck) after the first divides
      // (the compiler computed and stored them first, delaying the divides).
      if constexpr (kLong) pin7(zc);
#endif
      double p2 = pos2, p3 = pos3;
      pin7(p2), pin7(p3);
      const double zi2 = max_or_lo_sel(zrow + zix * p2, kMinZi), zi3 = max_or_lo_sel(zrow + zix * p3, kMinZi);
#if defined(SB_V7_NEON_STEPS)
      if constexpr (kLong) {
        etu2 = urow + ux * p2, etv2 = vrow + vx * p2, etu3 = urow + ux * p3, etv3 = vrow + vx * p3;
        pin7(etu2), pin7(etv2), pin7(etu3), pin7(etv3);
      }
#endif
      z2 = recip7(zi2), z3 = recip7(zi3);
    } else {
      const double zi2 = max_or_lo_sel(zrow + zix * pos2, kMinZi), zi3 = max_or_lo_sel(zrow + zix * pos3, kMinZi);
      z0 = 1.0 / zi0, z1 = 1.0 / zi1, z2 = 1.0 / zi2, z3 = 1.0 / zi3;
    }
    samples01();
  } else
#endif
  if constexpr (!kPre) {
  recip2(zrow + zix * P, zrow + zix * (P + double(16)), &z0, &z1);
#if defined(__arm__) && !defined(__aarch64__)
  if constexpr (!kDivFirst) samples01();
#else
  if constexpr (!kDivFirst) s0 = sample(P, z0), s1 = sample(P + double(16), z1);
#endif
  if (n > 32) {  // samples 2 and 3 (o_2 = 32; o_3 - o_1 = min(32, n - 17))
    pos2 = P + double(32);
    pos3 = (P + double(16)) + double(n - 17 < 32 ? n - 17 : 32);
    recip2(zrow + zix * pos2, zrow + zix * pos3, &z2, &z3);
  } else {  // two runs: sample 2 is the last pixel, o_2 - o_0 = n - 1
    pos2 = P + double(n - 1);
    recip2(zrow + zix * pos2, zrow + zix * pos2, &z2, &z3);
  }
  if constexpr (kDivFirst) s0 = sample(P, z0), s1 = sample(P + double(16), z1);
#if defined(SB_V7_NEON_STEPS)
  if constexpr (kLong) etu2 = urow + ux * pos2, etv2 = vrow + vx * pos2, etu3 = urow + ux * pos3, etv3 = vrow + vx * pos3;
#endif
  }
#if defined(SB_V7_NEON_STEPS)
  // persp_long_run_v7's instance: samples 2, 3 converted (below).
  double eq2u = 0.0, eq2v = 0.0, eq3u = 0.0, eq3v = 0.0;
#endif
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__)
  RunSteps su, sv;
  if constexpr (kCurve) {
    // ARMv7: steps16_sel for u and v with ddf = delta (zck (z_0 + z_1)), zck = zc * -1/16,
    // the same bits (see the loop below: one multiply after the conversion, not three), the
    // two chains interleaved step by step (pinned: the modelled Cortex-A9's in-order FP
    // pipe would wait on each step of one chain).
    const double c0 = kFixed16 ? c0p : (zc * -0.0625) * (s0.z + s1.z);
    const int32_t du = s1.u - s0.u, dv = s1.v - s0.v;
    double fu, fv;
    if constexpr (kFixed16) {
      // double(s1.u - s0.u) as double(s1.u) - double(s0.u) (both in [0, 2^31): exact, the
      // same bits), converted from the clamped VFP registers (no trip through the core).
#if defined(SB_V7_NEON_STEPS)
      if constexpr (kLong) {  // the low lanes' int32 difference converted (exact: the same value)
        fu = v7_cvt_lo(v7_sub_lo(pu1, pu0)), fv = v7_cvt_lo(v7_sub_lo(pv1, pv0));
      } else
#endif
      fu = ufixed16_f64(pu1) - ufixed16_f64(pu0), fv = ufixed16_f64(pv1) - ufixed16_f64(pv0);
    } else {
      fu = double(du), fv = double(dv);
    }
    pin7(fu), pin7(fv);
#if defined(SB_V7_NEON_STEPS)
    // persp_long_run_v7's instance: samples 2 and 3 converted (cq2u .. cq3v, tu2 .. tv3
    // below) step by step between these steps' dependent operations (the in-order FP pipe
    // waits on each of them otherwise); tu2 .. tv3 computed before the divides.
    if constexpr (kLong) {
      eq2u = etu2 * z2, eq2v = etv2 * z2, eq3u = etu3 * z3, eq3v = etv3 * z3;
      pin7(eq2u), pin7(eq2v), pin7(eq3u), pin7(eq3v);
    }
#endif
    fu = fu * c0, fv = fv * c0;
    pin7(fu), pin7(fv);
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kLong) {
      eq2u = cvt_ufixed16(eq2u), eq2v = cvt_ufixed16(eq2v), eq3u = cvt_ufixed16(eq3u), eq3v = cvt_ufixed16(eq3v);
      pin7(eq2u), pin7(eq2v), pin7(eq3u), pin7(eq3v);
    }
#endif
    steps16_dd_uv_ordered(du, cvt_sat(fu), dv, cvt_sat(fv), &su, &sv);
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kLong) {
      eq2u = min_ufixed16(eq2u, kUmax), eq2v = min_ufixed16(eq2v, kVmax);
      eq3u = min_ufixed16(eq3u, kUmax), eq3v = min_ufixed16(eq3v, kVmax);
    }
#endif
  } else {
    su = steps16<kCurve>(s0.u, s1.u, 0.0), sv = steps16<kCurve>(s0.v, s1.v, 0.0);
  }
#else
  RunSteps su = steps16<kCurve>(s0.u, s1.u, zc * 0.5 * (s0.z + s1.z));
  RunSteps sv = steps16<kCurve>(s0.v, s1.v, zc * 0.5 * (s0.z + s1.z));
#endif
  // Two runs per pass while runs r + 1 and r + 2 are full and not the last (their steps are
  // over 16 pixels): left > 48. Samples r + 4 and r + 5 are then at o_{r+4} - o_{r+2} =
  // min(32, left - 33) and o_{r+5} - o_{r+3} = min(32, left - 49) past P_{r+2}, P_{r+3}.
  // In the loop, ddf = -2 (delta / 16 * curve) with curve = zc / 2 * (z_a + z_b) is computed
  // as delta * (zck * (z_a + z_b)), zck = zc * -1/16: the same bits. Scaling by a power of
  // two is exact and commutes with rounding, so zck (z_a + z_b) = -curve / 8 and both ddf
  // are -round(delta * curve) / 8, whenever no value is subnormal or infinite.
  // Subnormal (|zc| < 2^-1018, or a product below 2^-1022): |ddf| < 1 either way, dd = 0.
  // Overflow: curve infinite makes ddf infinite with the sign delta * -zc, and then
  // |delta zck (z_a + z_b)| > DBL_MAX / 8 saturates to the same int32 (delta != 0); for
  // delta = 0 the walker's NaN gives dd = 0 or INT32_MIN, both rejected or 0 by
  // steps16_dd, which then returns {0, 0} like dd = 0 does. A product overflowing later
  // (delta / 16 * curve, or the * -2) overflows in both forms at the same rounding point.
  const double zck = zc * -0.0625;
  // (urow + ux * pos) of samples 2 and 3: the first half of sample(), one pass ahead.
#if defined(SB_V7_NEON_STEPS)
  double tu2 = etu2, tv2 = etv2, tu3 = etu3, tv3 = etv3;
  if constexpr (!kLong) tu2 = urow + ux * pos2, tv2 = vrow + vx * pos2, tu3 = urow + ux * pos3, tv3 = vrow + vx * pos3;
#else
  double tu2 = urow + ux * pos2, tv2 = vrow + vx * pos2, tu3 = urow + ux * pos3, tv3 = vrow + vx * pos3;
#endif
  // The runs' register state set up in the group before them (the second run's only on
  // 64-bit targets: armhf runs out of registers).
#if defined(SB_SPAN_PACKED)
  constexpr bool kEarlyB = true;
#else
  constexpr bool kEarlyB = false;
#endif
  Run16<kCurve> run_a(s0.u, s0.v, su, sv), run_b = run_a;
#if defined(SB_V7_NEON_STEPS)
  // ARMv7 second order: samples r + 2 and r + 3 enter each pass converted and clamped
  // (sample()'s operations: cvt_ufixed16, min_ufixed16 of (urow + ux pos) z), the next pass's
  // converted in its second run; so the first run starts its steps' chains at once.
  // cd1u, cd1v: v7_sub_lo(cq2, cq1), cq1 being sample r + 1 (its delta for run r + 1's steps),
  // each pass's computed by the pass before (so sample r + 1 itself is not carried).
  double cq2u = 0.0, cq2v = 0.0, cq3u = 0.0, cq3v = 0.0, cd1u = 0.0, cd1v = 0.0;
  if constexpr (kCurve && kLong) {
    cq2u = eq2u, cq2v = eq2v, cq3u = eq3u, cq3v = eq3v;  // converted above
    cd1u = v7_sub_lo(cq2u, pu1), cd1v = v7_sub_lo(cq2v, pv1);
  }
#endif
  Sample t2{}, t3{};
  // aarch64 linear (kPre): run r packed (start, step) as the asm leaves it (below), for the tail.
  [[maybe_unused]] uint64_t run_a0 = 0, run_d0 = 0;
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_fast_a64vec.inc"  // the aarch64 vector pipeline (see there)
#endif
  // One pass. kFull (ARMv7 second order, left >= 81): both offsets are 32 (no integer min,
  // no conversion; linear spans keep one loop: the split moved their 64-px case the wrong way).
#if !defined(__x86_64__)
  auto pass = [&](auto full) SB_LAMBDA_INLINE {
    constexpr bool kFull = decltype(full)::value;
#else
  while (left > 48) {  // x86-64: the loop written out (its scheduling as before the split)
    constexpr bool kFull = false;
#endif
    const double P1 = P + double(16), P2 = P1 + double(16), P3 = P2 + double(16);
    const double pos4 = P2 + (kFull ? 32.0 : double(left - 33 < 32 ? left - 33 : 32));
    const double pos5 = P3 + (kFull ? 32.0 : double(left - 49 < 32 ? left - 49 : 32));
    // Software-pipelined setup: samples 2 and 3 (their divides issued a pass earlier), the
    // steps of runs r + 1 (needed by the second run of this pass) and r + 2 (the next pass),
    // and the divides for samples 4 and 5, one dependent operation per pixel group. Each
    // operation is sample()'s / steps16's, in their order.
    double sum1, sum2, c1 = 0.0, c2 = 0.0, zi4, zi5, tu4, tv4, tu5, tv5;
    double qu2, qv2, qu3, qv3, fu1 = 0.0, fv1 = 0.0, fu2 = 0.0, fv2 = 0.0;
    int32_t s2u = 0, s2v = 0, s3u = 0, s3v = 0;
    int32_t iu1 = 0, iv1 = 0, iu2 = 0, iv2 = 0;
    RunSteps u1{}, v1{}, u2{}, v2{};
    double z4, z5;
#if defined(SB_V7_NEON_STEPS)
#include "asm/span_persp_fast_v7pass.inc"  // kV7N, stage_n, stage_a7 (see there)
#define SB_CURVE_NOT_V7N (kCurve && !kV7N)
#else
#define SB_CURVE_NOT_V7N kCurve
#endif
    auto stage_a = [&](auto g) SB_V7_LAMBDA_INLINE {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        qu2 = tu2 * z2, qv2 = tv2 * z2, qu3 = tu3 * z3, qv3 = tv3 * z3;
        sum1 = s1.z + z2, sum2 = z2 + z3;
        zi4 = zrow + zix * pos4, zi5 = zrow + zix * pos5;
      } else if constexpr (G == 1) {
        if constexpr (kFixed16) {  // armhf: usat32(trunc(q 2^16)) in place (see min_ufixed16)
          qu2 = cvt_ufixed16(qu2), qv2 = cvt_ufixed16(qv2), qu3 = cvt_ufixed16(qu3), qv3 = cvt_ufixed16(qv3);
        } else {
          qu2 = qu2 * 65536.0, qv2 = qv2 * 65536.0, qu3 = qu3 * 65536.0, qv3 = qv3 * 65536.0;
        }
        if constexpr (kCurve) c1 = zck * sum1, c2 = zck * sum2;
      } else if constexpr (G == 2) {
        if constexpr (!kFixed16) {
          qu2 = max_or_lo(qu2, 0.0), qv2 = max_or_lo(qv2, 0.0), qu3 = max_or_lo(qu3, 0.0), qv3 = max_or_lo(qv3, 0.0);
        }
      } else if constexpr (G == 3) {
        if constexpr (kFixed16) {
          qu2 = min_ufixed16(qu2, kUmax), qv2 = min_ufixed16(qv2, kVmax);
          qu3 = min_ufixed16(qu3, kUmax), qv3 = min_ufixed16(qv3, kVmax);
        } else {
          qu2 = min_hi(qu2, umaxd), qv2 = min_hi(qv2, vmaxd), qu3 = min_hi(qu3, umaxd), qv3 = min_hi(qv3, vmaxd);
        }
        recip2(zi4, zi5, &z4, &z5);
      } else if constexpr (G == 4) {
        if constexpr (kFixed16) {  // the clamped values' bits
          s2u = fixed16_bits_if<kCurve>(qu2), s2v = fixed16_bits_if<kCurve>(qv2);
          s3u = fixed16_bits_if<kCurve>(qu3), s3v = fixed16_bits_if<kCurve>(qv3);
        } else {
          s2u = int32_t(qu2), s2v = int32_t(qv2), s3u = int32_t(qu3), s3v = int32_t(qv3);
        }
      } else if constexpr (G == 5) {
        if constexpr (kCurve) {
          fu1 = double(s2u - s1.u), fv1 = double(s2v - s1.v);
        } else {
          u1 = {(s2u - s1.u) / 16, 0}, v1 = {(s2v - s1.v) / 16, 0};
        }
      } else if constexpr (G == 6) {
        if constexpr (kCurve) fu1 = fu1 * c1, fv1 = fv1 * c1;
      } else if constexpr (G == 7) {
        if constexpr (kCurve) iu1 = cvt_sat(fu1), iv1 = cvt_sat(fv1);
      } else if constexpr (G == 8) {
        if constexpr (kCurve) steps16_dd_uv(s2u - s1.u, iu1, s2v - s1.v, iv1, &u1, &v1);  // u, v interleaved
      } else if constexpr (G == 9) {
        if constexpr (kEarlyB) run_b = Run16<kCurve>(s1.u, s1.v, u1, v1);  // the second run's setup
      }
    };
    auto stage_b = [&](auto g) SB_V7_LAMBDA_INLINE {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        if constexpr (!kCurve) u2 = {(s3u - s2u) / 16, 0}, v2 = {(s3v - s2v) / 16, 0};
        tu4 = urow + ux * pos4, tv4 = vrow + vx * pos4, tu5 = urow + ux * pos5, tv5 = vrow + vx * pos5;
      } else if constexpr (G == 1) {
        if constexpr (SB_CURVE_NOT_V7N) fu2 = double(s3u - s2u), fv2 = double(s3v - s2v);
      } else if constexpr (G == 3) {
        if constexpr (SB_CURVE_NOT_V7N) fu2 = fu2 * c2, fv2 = fv2 * c2;
      } else if constexpr (G == 5) {
        if constexpr (SB_CURVE_NOT_V7N) iu2 = cvt_sat(fu2), iv2 = cvt_sat(fv2);
      } else if constexpr (G == 8) {
        if constexpr (SB_CURVE_NOT_V7N) steps16_dd_uv(s3u - s2u, iu2, s3v - s2v, iv2, &u2, &v2);
      } else if constexpr (G == 9) {
#if defined(SB_V7_NEON_STEPS)
        if constexpr (kV7N) {  // u2, v2 from the lanes; sample r + 3's bits (read from here on only)
          stage_n(std::integral_constant<int, 29>{});
          s3u = fixed16_bits_v(cq3u), s3v = fixed16_bits_v(cq3v);
        }
#endif
        run_a = Run16<kCurve>(s2u, s2v, u2, v2);  // the next pass's first run, set up here
      }
    };
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kV7N) {  // stage_n beside stage_a and stage_b (after each slot's work)
      run_a.draw(dest, texels, w, [&](auto g) SB_V7_LAMBDA_INLINE {
        stage_a7(g);
        stage_n(g);
      });
    } else
#endif
    {
      run_a.draw(dest, texels, w, stage_a);
    }
    group_end();
    {
      if constexpr (!kEarlyB) run_b = Run16<kCurve>(s1.u, s1.v, u1, v1);
#if defined(SB_V7_NEON_STEPS)
      if constexpr (kV7N) {
        run_b.draw(dest + 16, texels, w, [&](auto g) SB_V7_LAMBDA_INLINE {
          stage_b(g);
          stage_n(std::integral_constant<int, 20 + decltype(g)::value>{});
        });
      } else
#endif
      {
        run_b.draw(dest + 16, texels, w, stage_b);
      }
    }
    group_end();
    dest += 32;
    P = P2;
    left -= 32;
    s0 = Sample{s2u, s2v, z2};
    s1 = Sample{s3u, s3v, z3};
    su = u2;
    sv = v2;
    z2 = z4;
    z3 = z5;
    pos2 = pos4;
    pos3 = pos5;
    tu2 = tu4, tv2 = tv4, tu3 = tu5, tv3 = tv5;
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kV7N) cd1u = ncd1u, cd1v = ncd1v, cq2u = nq4u, cq2v = nq4v, cq3u = nq5u, cq3v = nq5v;
#endif
#if !defined(__x86_64__)
  };
#if defined(__arm__) && !defined(__aarch64__)
  if constexpr (kCurve) {
    while (left >= 81) pass(std::true_type{});
  }
#endif
  while (left > 48) pass(std::false_type{});
#else
  }
#endif
  // After one run more (left > 32): the state moves on 16 pixels, sample r + 2 and its steps
  // becoming run r's.
  auto next_run = [&](const Sample& s2, const RunSteps& u1, const RunSteps& v1) SB_LAMBDA_INLINE {
    dest += 16;
    P += double(16);
    left -= 16;
    s0 = s1;
    s1 = s2;
    su = u1;
    sv = v1;
    z2 = z3;
    pos2 = pos3;
    t2 = t3;
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kCurve && kLong) {
      cd1u = v7_sub_lo(cq3u, cq2u), cd1v = v7_sub_lo(cq3v, cq2v);  // samples r + 3 - r + 2
      cq2u = cq3u, cq2v = cq3v;
    }
#endif
  };
#if defined(__arm__) && !defined(__aarch64__)
  // Sample r + 2. persp_long_run_v7's instance: as the loop (or the set-up before it)
  // converted it (the same operations as sample(pos2, z2), so the same bits).
  auto sample2 = [&]() SB_LAMBDA_INLINE {
#if defined(SB_V7_NEON_STEPS)
    if constexpr (kCurve && kLong) return Sample{fixed16_bits_v(cq2u), fixed16_bits_v(cq2v), z2};
#endif
    return sample(pos2, z2);
  };
  if (kCurve && left > 32) {
    // ARMv7 second order: as below, sample r + 2 and run r + 1's steps computed beside run
    // r's pixels (stage slots; before draw16 the modelled Cortex-A9's in-order FP pipe and
    // the core moves waiting on it stalled), as the pass's stage_a computes them (c1 =
    // zck (z_1 + z_2), ddf = delta c1, cvt_sat, steps16_dd: steps16's bits).
    Sample s2{};
    double c1 = 0.0, fu = 0.0, fv = 0.0;
    int32_t iu = 0, iv = 0;
    RunSteps u1{}, v1{};
#if defined(SB_V7_NEON_STEPS) && defined(SB_V7_MID)
    if constexpr (kCurve && kLong) {  // run r in one asm statement, the ddf in its VFP slots
      v7_tail_run(dest, texels, w, run_regs(s0.u, s0.v, su, sv), cd1u, cd1v, s1.z, z2, zck, &iu, &iv);
      s2 = sample2();
      steps16_dd_uv(s2.u - s1.u, iu, s2.v - s1.v, iv, &u1, &v1);
      next_run(s2, u1, v1);
    } else
#endif
    {
    Run16<kCurve> run(s0.u, s0.v, su, sv);
    run.draw(dest, texels, w, [&](auto g) SB_LAMBDA_INLINE {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        s2 = sample2();
      } else if constexpr (G == 1) {  // the pass's stage_a operations (c1 = zck (z_1 + z_2))
        c1 = zck * (s1.z + s2.z);
      } else if constexpr (G == 2) {
        fu = double(s2.u - s1.u), fv = double(s2.v - s1.v);
      } else if constexpr (G == 3) {
        fu = fu * c1, fv = fv * c1;
      } else if constexpr (G == 6) {
        iu = cvt_sat(fu), iv = cvt_sat(fv);
      } else if constexpr (G == 8) {
        steps16_dd_uv(s2.u - s1.u, iu, s2.v - s1.v, iv, &u1, &v1);
      }
    });
    next_run(s2, u1, v1);
    }
  } else
#endif
  if (left > 32) {  // one run more whose next run is full and not the last
    const Sample s2 = kPre ? t2 : sample(pos2, z2);
    const double c1 = zc * 0.5 * (s1.z + s2.z);
    const RunSteps u1 = steps16<kCurve>(s1.u, s2.u, c1), v1 = steps16<kCurve>(s1.v, s2.v, c1);
    draw16_or_packed<kCurve, kPre>(dest, texels, w, run_a0, run_d0, s0.u, s0.v, su, sv);
    if constexpr (kPre) run_a0 = (uint64_t(uint32_t(s1.v)) << 32) + uint32_t(s1.u), run_d0 = pack_steps(v1.d, u1.d);
    next_run(s2, u1, v1);
  }
  // left = 17 .. 32: run r (full, its steps known), then the last run of left - 16 pixels,
  // which ends at the span's last pixel, sample r + 2 (pos2 = P_r + left - 1; for a one-pixel
  // last run that is sample r + 1 itself, which the walker does not recompute).
#if defined(__arm__) && !defined(__aarch64__)
#include "asm/span_persp_fast_v7last.inc"  // run r and the last run (ARMv7)
#else
  draw16_or_packed<kCurve, kPre>(dest, texels, w, run_a0, run_d0, s0.u, s0.v, su, sv);
  dest += 16;
  const int last = left - 16, steps = last - 1;
  const Sample s2 = kPre ? t2 : steps > 0 ? sample(pos2, z2) : s1;
  const double curve = zc * 0.5 * (s1.z + s2.z);
  RunSteps lu, lv;
#if defined(__x86_64__)
  if constexpr (!kCurve) {
    // x86-64 linear: run_steps' delta / steps truncated is trunc(delta / steps) in double
    // (see last_steps_q); steps 0 (s2 = s1, delta 0) gives 0.
    lu = RunSteps{int32_t(last_quotient(steps, s2.u - s1.u)), 0};
    lv = RunSteps{int32_t(last_quotient(steps, s2.v - s1.v)), 0};
  } else
#endif
  if constexpr (kPre) {
    // aarch64 linear (zc is 0 here, so curve is 0: run_steps' linear steps): delta / steps
    // truncated, two sdiv (no jump table, no call). 0 <= u, v < 2^31: the deltas fit int32.
    // Steps 0 (a one-pixel last run): draw_last draws that pixel at (s1.u, s1.v) and never
    // reads the steps, so s2 stays t2 and the divisor 1 (no branch: one block with run r's).
    const int32_t sd = steps > 0 ? steps : 1;
    lu = RunSteps{(s2.u - s1.u) / sd, 0}, lv = RunSteps{(s2.v - s1.v) / sd, 0};
  } else if constexpr (kCurve && (kLastSteps || kX86)) {
    last_steps(steps, s1, s2, curve, &lu, &lv);
  } else {
    run_steps_uv(steps, s1, s2, curve, &lu, &lv);
  }
  if (last == 16) {
    draw16<kCurve>(dest, texels, w, s1.u, s1.v, lu, lv);
  } else {
    draw_last<kCurve>(dest, last, texels, w, uint32_t(s1.u), uint32_t(s1.v), uint32_t(lu.d), uint32_t(lv.d), uint32_t(lu.dd),
             uint32_t(lv.dd));
  }
#endif
}
#undef SB_PERSP_FAST_BODY
#undef SB_CURVE_NOT_V7N
#if defined(__aarch64__) && defined(__GNUC__)
// Second-order spans of 1 .. 16 pixels: tiny_one_a64 (asm/span_persp_a64tiny.cpp), reached
// with a sibling call before this function saves any register (spans_range's and the single
// entry's such spans; the batch's runs of them go there from batch_from, two at a time).
template <bool kCurve>
void persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  if constexpr (kCurve) {
    if (uint32_t(n) - 1u < 16u) return tiny_one_a64(dest, n, texels, width, p);
  }
  persp_fast_inl<kCurve>(dest, n, texels, width, p);
}
void spans_range(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
void batch_from(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
// A run of second-order spans of 1 .. 16 pixels at it (tiny_curve_a64), then the items left.
// Out of line (spans_range's code and page cuts stay as they were).
__attribute__((noinline)) void tiny_then_batch(const PerspItem* it, const PerspItem* end, const uint8_t* texels,
                                               int width) {
  it = tiny_curve_run_a64(it, end, texels, width);
  if (it == end) return;  // (spans_range's register saves for no item)
  return batch_from(it, end, texels, width);
}
#include "asm/span_persp_fast_a64tests.inc"  // the item tests (see there)
// persp_long_a64_inl for one span, then the rest of its batch, items [next, end) (none for
// the single-span entry: next == end), through batch_from. Reached from batch_from and left
// with tail branches (the compiler's sibling calls): a long first item of the items left
// costs no call. A long item after a shorter one in the loop (spans_range, via persp_one) is
// still called, with next == end. Without sibling calls (-O0) each chained long item nests
// one frame. Page-aligned: where its loop's code falls against 4 KiB pages (where qemu cuts
// the blocks bench/count.sh times) does not move with the size of the code before it.
// Consecutive long items are drawn in this function's loop (one frame for the run of them);
// the next item's fields are read with its test (its pointer stays in a register for the next
// span's set-up, not reloaded from the stack).
__attribute__((noinline, aligned(4096))) void persp_long_a64(uint8_t* dest, int n, const uint8_t* texels,
                                                             int width, const PerspSpan& p, const PerspItem* next,
                                                             const PerspItem* end) {
  const PerspSpan* q = &p;
  for (;;) {
    persp_long_a64_inl(dest, n, texels, width, *q);
    if (next == end) return;
    const PerspItem* it = next++;
    // q = &it->span from the test's block (no latch block, and the set-up's block does not
    // compute it from a register it rewrites later: llvm-mca times that block as a loop).
    const bool is_long = long_next_a64(*it, n, dest, q);
    if (!is_long) return batch_from(it, end, texels, width);
  }
}
// A linear span of more than kShortMax pixels (persp_one's persp_fast<false>) as the first
// of the batch's items left, then the rest: reached and left with tail branches, as above.
// Consecutive such items are drawn in this function's loop.
__attribute__((noinline)) void persp_lin_a64(uint8_t* dest, int n, const uint8_t* texels, int width,
                                             const PerspSpan& p, const PerspItem* next, const PerspItem* end) {
  const PerspSpan* q = &p;
  for (;;) {
    // Every item here is is_lin_a64's (batch_from and the test below): n > kShortMax, so
    // persp_fast_inl's shorter-span tests fold away (no branch blocks before the head).
    if (n <= kShortMax) __builtin_unreachable();
    persp_fast_inl<false>(dest, n, texels, width, *q);
    if (next == end) return;
    if (!is_lin_a64(*next)) return batch_from(next, end, texels, width);
    dest = next->dest, n = next->n, q = &next->span;
    ++next;
  }
}
#endif

// The dispatcher: one span by its length and steps (surface_span_persp_fast), inlined into
// the batch loop too (surface_spans_persp_fast: the registers saved once per batch).
// is_short: 16 < n <= kShortMax; curve: second_order with dzi != 0 (persp_one computes them;
// the batch loop passes the ones its pair test computed).
SB_INLINE void persp_one_c(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p,
                           bool is_short, bool curve) {
  // curve = zc (z_a + z_b) / 2 with zc = 0 is 0 (the depths are finite): the linear steps.
  // Short spans (aarch64) go to persp_short from here, not past persp_fast's entry (which
  // saves the registers of the long-span loop).
  if (!curve) {
    if (is_short) return persp_short_inl<false>(dest, n, texels, width, p);
    return persp_fast<false>(dest, n, texels, width, p);
  }
  if (is_short) return persp_short_inl<true>(dest, n, texels, width, p);
#if defined(SB_V7_MID)
  if (n >= kMidMin && n <= kMidMax) return persp_mid_v7(dest, n, texels, width, p);  // ARMv7, four runs
#endif
#if defined(__aarch64__) && defined(__GNUC__)
  if (n > kShortMax) return persp_long_a64(dest, n, texels, width, p, nullptr, nullptr);  // n = 65 .. 80 too
#endif
  persp_fast<true>(dest, n, texels, width, p);
}
SB_INLINE bool is_short_n(int n) { return uint32_t(n) - 17u < uint32_t(kShortMax - 16); }
// The single-span entry's dispatcher (and the batch loop's off aarch64): the tests one by one.
// ARMv7: dzi == 0.0 on its bits (two core loads; +0 and -0 are 0, NaN is not: the FP
// compare's result) instead of vldr, vcmp, vmrs.
SB_INLINE bool is_zero_v7(const double& d) {
#if defined(__arm__) && !defined(__aarch64__)
  uint32_t lo, hi;
  __builtin_memcpy(&lo, &d, 4);
  __builtin_memcpy(&hi, reinterpret_cast<const char*>(&d) + 4, 4);
  return (lo | (hi << 1)) == 0;
#else
  return d == 0.0;
#endif
}
SB_INLINE void persp_one(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
#if defined(__aarch64__) && defined(__GNUC__)
  // aarch64 (the single-span entry only): a short second-order span, the three fields tested
  // without branches between (one qemu block, dzi on its integer bits), before the others.
  int64_t w64;  // width, sign-extended in the test's block
  ShortHead h;  // the sample block's head, from the test's block too
  if (short_curve_a64(n, p, width, w64, h)) {
    return persp_short_curve<true>(dest, n, texels, w64, p, h);
  }
#endif
  const bool is_short = n > 16 && n <= kShortMax;
  if (!p.second_order || is_zero_v7(p.dzi)) {
    if (is_short) return persp_short_inl<false>(dest, n, texels, width, p);
    return persp_fast<false>(dest, n, texels, width, p);
  }
  persp_one_c(dest, n, texels, width, p, is_short, true);
}

#if defined(__aarch64__) && defined(__GNUC__)
// Items [it, end) (surface_spans_persp_fast): a long first item reached with a tail branch
// (this function saves no registers), else the batch loop; persp_long_a64 returns here with
// a tail branch too.
void batch_from(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width) {
  if (it != end && is_long_a64(*it)) return persp_long_a64(it->dest, it->n, texels, width, it->span, it + 1, end);
  if (it != end && is_lin_a64(*it)) {
    return persp_lin_a64(it->dest, it->n, texels, width, it->span, it + 1, end);
  }
  if (end - it >= 2 && lin_short_a64(it[0]) && lin_short_a64(it[1])) return lin_pairs_a64(it, end, texels, width);
  if (it != end && tiny_curve_a64(*it)) return tiny_then_batch(it, end, texels, width);
  // A pair of 17 .. 48 px spans with two more such lengths after it (one pair alone costs
  // pairs48_a64's entry more than its block saves: persp32mix A53 +0.08); the lengths first
  // (one short block: the whole test as one block cost the other rows up to +0.03).
  if (end - it >= 4 && ((uint32_t(it[0].n) - 17u < 32u) & (uint32_t(it[1].n) - 17u < 32u) &
                        (uint32_t(it[2].n) - 17u < 32u) & (uint32_t(it[3].n) - 17u < 32u))) {
    if (pair48_a64(it[0]) & pair48_a64(it[1])) return pairs48_a64(it, end, texels, width);
  }
  return spans_range(it, end, texels, width);
}
#endif

#if defined(SB_V7_NEON_STEPS) && defined(SB_V7_MID)
#define SB_V7_LONG_RUN 1
// ARMv7 batches: a second-order span of 49 pixels or more that persp_mid_v7 does not draw
// (n = 49 or n > kMidMax), as spans_range tests it.
SB_INLINE bool long_v7(const PerspItem& x) {
  return x.span.second_order && !is_zero_v7(x.span.dzi) && x.n >= 49 &&
         uint32_t(x.n - kMidMin) > uint32_t(kMidMax - kMidMin);
}
// Such items from it on (it is one), while they follow each other: the five-run ones (65 ..
// 80 px) by persp_five_run_v7, the others by persp_fast<true, true> in persp_long_body_v7
// (defined at the end: asm/span_persp_fast_v7five.inc; GCC emits persp_long_body_v7 before
// the entries, which are page-aligned so that its size does not move their code against
// qemu's 4 KiB page cuts).
const PerspItem* persp_long_run_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
#endif
// The batch loop over items [it, end) (batch_from). Out of line on aarch64: the long paths
// return to batch_from with a tail branch; elsewhere inlined into surface_spans_persp_fast.
// Page-aligned on aarch64 (as persp_long_a64): its pair loop's code then keeps its place
// against qemu's 4 KiB page cuts (bench/count.sh times qemu's blocks) whatever precedes it.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__SSE2__)
const PerspItem* short_run_x86(const PerspItem* it, const PerspItem* end, const uint8_t* texels, uint32_t w);
#endif
#if defined(__aarch64__) && defined(__GNUC__)
__attribute__((noinline, aligned(4096)))
#else
SB_INLINE
#endif
void spans_range(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width) {
#if defined(__aarch64__) && defined(__GNUC__)
  // aarch64: two neighbouring short second-order spans (persp_short_inl<true>'s) take their
  // samples from one asm block (short_samples2, asm/span_persp_a64pair.h: the latency chains
  // paid once for both), then each its rest (short_rest, one copy in the loop); other spans
  // one by one.
  ShortSamples s[2];
  float64x2_t zhm;  // zh_ab as short_samples2 stores it: span b's zh loaded at its set-up
  // short_samples2 uses every vector register: d8 .. d15 are saved once here, at entry
  // (without this the compiler saved and restored d12 .. d15 around each pair).
  __asm__ volatile("" ::: "v8", "v9", "v10", "v11", "v12", "v13", "v14", "v15");
  while (it != end) {
    // Pairable: both it[0] and it[1] short second-order spans, it[1] inside the batch. Tested
    // without branches between (one qemu block): b is it[1], or it[0] again at the batch's
    // last item (no read past end; has_next false then).
    const bool sa = is_short_n(it->n);
    if (!it->span.second_order) {
      persp_one_c(it->dest, it->n, texels, width, it->span, sa, false);
      ++it;
      continue;
    }
    const bool ca = nonzero_bits(it->span.dzi);
    const bool has_next = it + 1 != end;
    const PerspItem& b = has_next ? it[1] : it[0];
    if (sa & ca & pairable_a64(b) & has_next) {
      // A chain of pairs: the next pair's test (it[2], it[3] both pairable_a64, it + 3 < end)
      // in this pair's samples block (short_samples2: the fields loaded at its start, tested
      // after its last NEON work), so the loop goes from pair to pair on one flag.
      const PerspItem* nx;  // the next pair (it + 2) while the chain goes on, else null
      for (;;) {
        ShortSamples q;
        int runs, last;  // span a's, from the block
        float64x2_t zh2;  // [a's dzi, b's dzi] * 0.5 (short_rest's zh), from the block
        short_samples2(it[0].span, it[0].n, it[1].span, it[1].n, q, s[1], it, end, nx, runs, last, zh2, zhm);
        // Span a's rest on the block's registers, then span b's on its stored samples.
        double zh = vgetq_lane_f64(zh2, 0);
#pragma GCC unroll 1
        for (int j = 0; j < 2; ++j, ++it) {
          short_rest<true>(it->dest, runs, last, texels, width, zh, q.S01, q.S23, q.S44, q.zs01, q.zs23, q.c01, q.c23);
          const int nb = it[1 - j].n;  // span b's n (span b itself after it: never past the pair)
          q = s[1], runs = (nb + 15) >> 4, last = nb - 16 * (runs - 1), zh = vgetq_lane_f64(zhm, 1);
        }
        if (!nx) break;  // the latch: one load and a branch (it == nx here: the block's pointer)
        it = nx;
      }
      continue;
    }
    persp_one_c(it->dest, it->n, texels, width, it->span, sa, ca);
    ++it;
  }
#elif defined(SB_V7_LONG_RUN)
  // ARMv7: persp_one's dispatch, but the second-order spans of 49 pixels and more that are
  // not persp_mid_v7's drawn out of line by persp_long_run_v7 (with the consecutive ones
  // after them: one call a run of them), the rest of persp_fast<true>'s spans (n <= 48)
  // here, with that bound stated (its long-span loop folds away): the loop's code is then
  // only in persp_long_run_v7, and this function's register allocation does not move with it.
  while (it != end) {
    const PerspSpan& p = it->span;
    const int n = it->n;
    const bool is_short = n > 16 && n <= kShortMax;
    if (!p.second_order || is_zero_v7(p.dzi)) {
      if (is_short) {
        persp_short_inl<false>(it->dest, n, texels, width, p);
      } else {
        persp_fast<false>(it->dest, n, texels, width, p);
      }
      ++it;
      continue;
    }
    if (is_short) {
      persp_short_inl<true>(it->dest, n, texels, width, p);
    } else if (n >= kMidMin && n <= kMidMax) {
      persp_mid_v7(it->dest, n, texels, width, p);
    } else if (n >= 49) {
      it = persp_long_run_v7(it, end, texels, width);
      continue;
    } else {
      if (n > 48) __builtin_unreachable();
#if defined(SB_V7_ONE)
      // n <= 48 (n <= 0 too, which persp_one_v7 skips): persp_one_v7 (one run) or
      // persp_mid_run_v7 (17 .. 48 pixels), each with the 1 .. 48 pixel spans after it.
      it = n <= 16 ? persp_one_v7(it, end, texels, width) : persp_mid_run_v7(it, end, texels, width);
      continue;
#else
      persp_fast<true>(it->dest, n, texels, width, p);
#endif
    }
    ++it;
  }
#elif defined(__x86_64__) && defined(__GNUC__) && defined(__SSE2__)
  // x86-64: persp_one's dispatch, with the runs of second-order spans of 1 .. kX86ShortMax
  // pixels drawn by short_run_x86 (one call a run of them; asm/span_persp_x86short.h).
  while (it != end) {
    const PerspSpan& p = it->span;
    const int n = it->n;
    if (!p.second_order || p.dzi == 0.0) {
      persp_fast<false>(it->dest, n, texels, width, p);
    } else if (uint32_t(n - 1) < uint32_t(kX86ShortMax)) {
      it = short_run_x86(it, end, texels, uint32_t(width));
      continue;
    } else {
      persp_fast<true>(it->dest, n, texels, width, p);
    }
    ++it;
  }
#else
  for (; it != end; ++it) persp_one(it->dest, it->n, texels, width, it->span);
#endif
}

#if defined(__aarch64__) && defined(__GNUC__)
// Two neighbouring short linear spans as the first items of the batch's items left
// (batch_from; lin_short_a64 both, it + 1 < end): their set-ups in one asm block
// (persp_short_lin2, asm/span_persp_a64lin2.h), pair after pair while the next two items are
// such a pair, then the items left by batch_from, reached with a tail branch (as
// persp_lin_a64 returns). A surface's spans are one batch, and a floor's or ceiling's are all
// linear (dzi 0), so the pairs come at a batch's start; spans_range (the mixed batches' loop)
// draws linear short spans one by one. Out of line, after the batch loop: its registers are
// its own (the pair block uses nearly all of them) and the batch loop's code does not move.
__attribute__((noinline)) void lin_pairs_a64(const PerspItem* it, const PerspItem* end, const uint8_t* texels,
                                             int width) {
  static_assert(kShortMax == 64, "short_lin_finish's next-pair test: n 17 .. 64 (n - 17 <= 47)");
  uint32_t again;
  do {
    // The next pair's test (it[2], it[3], or none when fewer than four items are left) in
    // span b's set-up block (short_lin_finish: the integer block's spare slots).
    again = persp_short_lin2(it, end, texels, width);  // it += 2
  } while (again);
  return batch_from(it, end, texels, width);
}
#endif

}  // namespace

#if !(defined(__arm__) && !defined(__aarch64__))
#if defined(__aarch64__) && defined(__GNUC__)
// Page-aligned on aarch64 (as persp_long_a64 and spans_range): the single entry's inlined
// short path keeps its place against qemu's 4 KiB page cuts (where bench/count.sh's timed
// blocks end) whatever the code before it weighs (a page end once cut its 111-line block).
__attribute__((aligned(4096)))
#endif
void surface_span_persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int /*height*/,
                             const PerspSpan& p) {
  persp_one(dest, n, texels, width, p);
}
#endif

#if defined(SB_V7_LONG_RUN)
// ARMv7: page-aligned (persp_long_run_v7, which the compiler emits before it, does not move
// its blocks against qemu's 4 KiB page cuts, where bench/count.sh's timed blocks end).
__attribute__((aligned(4096)))
#endif
void surface_spans_persp_fast(const PerspItem* items, int count, const uint8_t* texels, int width, int /*height*/) {
#if defined(__aarch64__) && defined(__GNUC__)
  batch_from(items, items + (count > 0 ? count : 0), texels, width);
#elif defined(SB_V7_ONE)
  // ARMv7: a first item of 1 .. 48 pixels (second order) to persp_short_v7 (with the ones
  // after it), the rest to the batch loop.
  const PerspItem* const end = items + (count > 0 ? count : 0);
  if (items != end && short_v7(*items)) items = persp_short_v7(items, end, texels, width);
  spans_range(items, end, texels, width);
#else
  spans_range(items, items + (count > 0 ? count : 0), texels, width);
#endif
}

#if defined(__arm__) && !defined(__aarch64__)
#if defined(SB_V7_MID)
namespace {
// The single-span entry's other spans (every one but persp_mid_v7's), out of line: reached
// from surface_span_persp_fast by a tail branch, so their registers are saved here, not on
// the entry's path.
__attribute__((noinline)) void persp_one_rest_v7(uint8_t* dest, int n, const uint8_t* texels, int width, int,
                                                 const PerspSpan& p) {
  persp_one(dest, n, texels, width, p);
}
}  // namespace
#endif
// ARMv7: after the batch entry (the object's last function), so that its code size does not
// move the batch entry's inlined long-span loop against 4 KiB pages (where qemu cuts the
// blocks bench/count.sh times; the tail's staged run moved it: A9 persp1920 6.92 -> 6.98).
// With SB_V7_MID: persp_mid_v7's spans (kMidMin .. kMidMax pixels, second order, dzi != 0)
// drawn here, the others by persp_one_rest_v7 (a tail call), so this function saves only what
// persp_mid_v7 uses (r4 .. r11: its asm keeps to d0 .. d7, d16 .. d31 between statements).
#if defined(SB_V7_LONG_RUN)
// As the batch entry (see there); scheduled over superblocks after RA as persp_long_run_v7
// (A9 model persp64single 7.43 -> 7.41; in the batch entry it cost the linear spans).
__attribute__((aligned(4096), optimize("sched2-use-superblocks")))
#endif
void surface_span_persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                             const PerspSpan& p) {
#if defined(SB_V7_MID)
  if (uint32_t(n - kMidMin) <= uint32_t(kMidMax - kMidMin) && p.second_order && !is_zero_v7(p.dzi)) {
    return persp_mid_v7<true>(dest, n, texels, width, p);
  }
  return persp_one_rest_v7(dest, n, texels, width, height, p);
#else
  (void)height;
  persp_one(dest, n, texels, width, p);
#endif
}
#endif

#if defined(SB_V7_LONG_RUN)
namespace {
#include "asm/span_persp_fast_v7five.inc"  // persp_long_body_v7, persp_long_run_v7, persp_five_run_v7
}  // namespace
#endif

#include "asm/span_persp_fast_x86run.inc"  // x86-64: short_run_x86 (see there)
#include "asm/span_persp_fast_v7one.inc"  // ARMv7: persp_one_v7, persp_mid_run_v7 (see there)

}  // namespace sb::simd
