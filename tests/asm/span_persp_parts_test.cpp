// The whole-span drawer's parts (asm/span_persp_*.h) against the run walker's own
// arithmetic, one part at a time: the step quotient without a divide, the full runs' and the
// last run's steps, the depth and fixed-point clamps, the reciprocal without a divide, and
// the aarch64 setup blocks (four-run steps, short linear setup). Each is checked on the
// ends of its range and on random values, because a step one unit off seldom shows in the
// drawn texels (tests/asm/span_persp_test.cpp compares whole spans).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#if defined(__aarch64__)
#include <arm_neon.h>
#endif

#include "asm/span_persp_run.h"  // steps16_dd (internal linkage: this test's own copy)
// ARMv7 and x86-64: last_ddi, last_steps_i (the ARMv7 tails' parts; portable C++); aarch64:
// div_steps and short_steps_k3v (asm/span_persp_a64short.h, a64mid.h, included by it).
#include "asm/span_persp_arm.h"
#include "asm/span_persp_a64longlast.h"  // pass_last (aarch64)
#include "asm/surface_span.h"

namespace {
// asm/span_persp_arm.h's div_steps (the last run's step quotient on aarch64): a / s as
// RN(1/s), q0 = a RN(1/s), e = fma(-q0, s, a), fma(e, RN(1/s), q0), bit for bit a / s for
// integers |a| < 2^31 and s = 1 .. 16: the same operations, on the ends of the range, the
// small quotients, and random integers of every magnitude.
TEST(AsmSpanPersp, StepQuotientWithoutDivide) {
  auto bits = [](double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  std::mt19937 rng(11);
  long checked = 0, wrong = 0;
  for (int s = 1; s <= 16; ++s) {
    const double y = 1.0 / s, sd = double(s);
    auto check = [&](int64_t ai) {
      const volatile double av = double(ai);
      const double a = av;
      const double q0 = a * y;
      const double e = std::fma(-q0, sd, a);
      const double q = std::fma(e, y, q0);
      wrong += bits(q) != bits(a / sd);
      ++checked;
    };
    for (int64_t a = -70000; a <= 70000; ++a) check(a);
    for (int64_t k = 0; k < 70000; ++k) check(INT32_MAX - k), check(-INT32_MAX + k);
    for (int i = 0; i < 200000; ++i) {
      const int sh = int(rng() % 32);
      check(int64_t(int32_t(rng()) >> sh));
    }
    for (int k = 0; k < 31; ++k) {  // around multiples of s times powers of two
      for (int64_t d = -3; d <= 3; ++d) {
        const int64_t a = int64_t(s) << k;
        if (a + d < INT32_MAX) check(a + d), check(-(a + d));
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld step quotients without a divide, %ld wrong\n", checked, wrong);
}

// asm/span_persp_run.h's full-run step test steps16_dd (ARMv7: in asm) against the walker's
// (asm/span_walk.h) integer arithmetic for steps 16 given dd: |delta| < 2^31 - 2^16 (the
// clamps), dd over every magnitude, the 2^25 and int32 ends among them.
TEST(AsmSpanPersp, FullRunStepsMatchTheWalker) {
  auto walker = [](int64_t delta, int64_t dd) {
    const int64_t linear = delta / 16, bend = dd * 120, d0 = (delta - bend) / 16;
    const int64_t last_step = d0 + dd * 15, reach = d0 * 16 + bend;
    const bool monotone = delta >= 0 ? (d0 >= 0 && last_step >= 0 && reach >= 0 && reach <= delta)
                                     : (d0 <= 0 && last_step <= 0 && reach <= 0 && reach >= delta);
    if (!monotone || d0 > INT32_MAX || d0 < INT32_MIN) return std::pair<int64_t, int64_t>{linear, 0};
    return std::pair<int64_t, int64_t>{d0, dd};
  };
  std::mt19937 rng(5);
  const int32_t kMaxDelta = INT32_MAX - 65535;
  long checked = 0, wrong = 0;
  auto check = [&](int32_t delta, int32_t dd) {
    const sb::simd::RunSteps got = sb::simd::steps16_dd(delta, dd);
    const auto want = walker(delta, dd);
    wrong += got.d != want.first || got.dd != want.second;
    // The u, v pair form (ARMv7: its own asm, the chains interleaved), with a second pair.
    const int32_t delta2 = -delta, dd2 = dd ^ 5;
    sb::simd::RunSteps a, b;
    sb::simd::steps16_dd_uv(delta, dd, delta2, dd2, &a, &b);
    const auto want2 = walker(delta2, dd2);
    wrong += a.d != want.first || a.dd != want.second || b.d != want2.first || b.dd != want2.second;
    ++checked;
  };
  const int32_t ends[] = {0, 1, -1, 15, -15, 16, -16, (1 << 25) - 1, -(1 << 25) + 1, 1 << 25, -(1 << 25),
                          (1 << 25) + 1, INT32_MAX, INT32_MIN, INT32_MIN + 1, 17895697, -17895697};
  for (int i = 0; i < 2000000; ++i) {
    const int32_t delta = int32_t(int64_t(rng()) % (2 * int64_t(kMaxDelta) + 1) - kMaxDelta) >> (rng() % 31);
    int32_t dd = int32_t(rng()) >> (rng() % 32);
    if (i % 4 == 0) dd = int32_t(delta / 120 + int32_t(rng() % 5) - 2);  // next to the 120 |dd| = |delta| edge
    if (i % 4 == 1) dd = -int32_t(delta / 120 + int32_t(rng() % 5) - 2);
    check(delta, dd);
  }
  for (int32_t dd : ends) {
    for (int32_t delta : {0, 1, -1, 120, -120, kMaxDelta, -kMaxDelta, 2013265800, -2013265800, 2013265920}) {
      check(delta, dd);
    }
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld full-run step tests, %ld wrong\n", checked, wrong);
}

// asm/span_persp_run.h's branch-free depth clamp (ARMv7: vcmpe, vmrs, a conditional vmov)
// against max(zi, kMinZi) with NaN -> kMinZi, as the walker clamps 1/z.
TEST(AsmSpanPersp, DepthClampWithoutBranchMatches) {
  const double k = sb::simd::span_walk::kMinZi, nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  long wrong = 0;
  for (double zi : {0.0, -0.0, k, std::nextafter(k, 0.0), std::nextafter(k, 1.0), -k, 1.0, -1.0, 1e300, -1e300, inf,
                    -inf, nan, -nan, 5e-324, 0.25, 123456.75}) {
    const double want = zi > k ? zi : k;
    const double got = sb::simd::max_or_lo_sel(zi, k);
    wrong += std::memcmp(&want, &got, sizeof got) != 0;
  }
  EXPECT_EQ(wrong, 0);
}

// The to_fixed inputs both conversion tests run: bounds m from 0 to INT32_MAX, for each
// zero, tiny, (-1, 0] and (0, 1) after scaling, the bound's neighbourhood, 2^32 / 2^16,
// huge, infinite and NaN values; then 300000 random (q, m) pairs from rng.
template <class Check>
void to_fixed_cases(std::mt19937& rng, Check&& check) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (int32_t m : {0, 1, 65535, 65536, (1 << 24) - 1, INT32_MAX - 65535, INT32_MAX}) {
    const double mq = double(m) / 65536.0;
    for (double q : {0.0, -0.0, 1e-300, -1e-300, 0.5 / 65536, -0.5 / 65536, 1.0 / 65536, -1.0 / 65536, mq,
                     std::nextafter(mq, 0.0), std::nextafter(mq, 1e300), mq + 1.0 / 65536, mq - 1.0 / 65536,
                     65536.0, 32768.0, 4294967296.0 / 65536, 4294967295.0 / 65536, 1e10, -1e10, 1e300, -1e300,
                     inf, -inf, nan, -nan}) {
      check(q, m);
    }
  }
  for (int i = 0; i < 300000; ++i) {
    const int32_t m = int32_t(rng() >> 1) >> (rng() % 31);
    const double q = std::ldexp(double(int32_t(rng())), -int(rng() % 60));
    check(q, m);
  }
}

// asm/span_persp_run.h's ARMv7 to_fixed in the VFP/NEON registers (vcvt.u32.f64 #16, then
// vmin.u32 against the bound) against the walker's to_fixed: zero, negatives, (-1, 0] and
// (0, 1) after scaling, the bound's neighbourhood, huge, infinite and NaN values.
TEST(AsmSpanPersp, FixedPointClampMatchesTheWalker) {
  if constexpr (!sb::simd::kFixed16) GTEST_SKIP() << "ARMv7 only";
  std::mt19937 rng(13);
  long checked = 0, wrong = 0;
  auto check = [&](double q, int32_t m) {
    const int32_t want = sb::simd::span_walk::to_fixed(q, m);
    const int32_t got =
        sb::simd::fixed16_bits(sb::simd::min_ufixed16(sb::simd::cvt_ufixed16(q), sb::simd::bound16(m)));
    wrong += got != want;
    ++checked;
  };
  to_fixed_cases(rng, check);
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld fixed-point clamps, %ld wrong\n", checked, wrong);
}

// aarch64 long linear spans (asm/span_persp_fast.cpp) take to_fixed as fcvtzu #16, uqxtn and
// an unsigned min with m: the walker's to_fixed on the same edges and random values.
TEST(AsmSpanPersp, UnsignedFixedPointClampMatchesTheWalker) {
#if defined(__aarch64__)
  std::mt19937 rng(17);
  long checked = 0, wrong = 0;
  auto check = [&](double q, int32_t m) {
    const int32_t want = sb::simd::span_walk::to_fixed(q, m);
    const uint32x2_t c = vqmovn_u64(vcvtq_n_u64_f64(vdupq_n_f64(q), 16));
    const int32_t got = int32_t(vget_lane_u32(vmin_u32(c, vdup_n_u32(uint32_t(m))), 0));
    wrong += got != want;
    ++checked;
  };
  to_fixed_cases(rng, check);
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld unsigned fixed-point clamps, %ld wrong\n", checked, wrong);
#else
  GTEST_SKIP() << "aarch64 only";
#endif
}

// aarch64 short linear spans (asm/span_persp_a64lin.h) clamp before converting: fcvtzu #16
// of fmin(q, m 2^-16) (the limit from m as an unsigned 32-bit integer, ucvtf #16), the
// 64-bit lane taken whole: the walker's to_fixed on the same edges and random values.
TEST(AsmSpanPersp, MinBeforeFixedPointMatchesTheWalker) {
#if defined(__aarch64__)
  std::mt19937 rng(19);
  long checked = 0, wrong = 0;
  auto check = [&](double q, int32_t m) {
    const int32_t want = sb::simd::span_walk::to_fixed(q, m);
    const float64x2_t lim = vcvtq_n_f64_u64(vmovl_u32(vdup_n_u32(uint32_t(m))), 16);
    const uint64_t c = vgetq_lane_u64(vcvtq_n_u64_f64(vminq_f64(vdupq_n_f64(q), lim), 16), 0);
    wrong += c != uint64_t(uint32_t(want));
    ++checked;
  };
  to_fixed_cases(rng, check);
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld clamps before the conversion, %ld wrong\n", checked, wrong);
#else
  GTEST_SKIP() << "aarch64 only";
#endif
}

#if !defined(__aarch64__)
// asm/span_persp_arm.h's last-run steps as the ARMv7 tails take them in two parts
// (last_ddi: ddf converted, its range test in integers; last_steps_i) against the walker's
// run_steps (asm/span_walk.h) for steps 1 .. 15: clamped ends, curves of every magnitude
// (ddf near the +-1e9 range ends, 0, NaN, infinite).
TEST(AsmSpanPersp, LastRunStepsMatchTheWalker) {
  std::mt19937 rng(11);
  const int32_t kMax = INT32_MAX - 65535;
  long checked = 0, wrong = 0;
  auto check = [&](int32_t a, int32_t b, int steps, double curve) {
    const sb::simd::RunSteps want = sb::simd::span_walk::run_steps(a, b, steps, curve);
    const int32_t delta = b - a;
    const double q = sb::simd::last_quotient(steps, delta);
    const int32_t ddi = sb::simd::last_ddi(q, curve);
    sb::simd::RunSteps got, other;
    sb::simd::last_steps_i(steps, delta, 0, int32_t(q), 0, ddi, 0, &got, &other);
    wrong += got.d != want.d || got.dd != want.dd;
    ++checked;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 400000; ++i) {
    const int steps = 1 + int(rng() % 15);
    const int32_t a = int32_t(rng() % uint32_t(kMax)), b = int32_t(rng() % uint32_t(kMax)) >> (rng() % 31);
    const double q = double(b - a) / steps;
    double curve = std::ldexp(double(int32_t(rng())) / 2147483648.0, -int(rng() % 40));
    if (i % 3 == 0 && q != 0.0) curve = -5e8 / q * (1.0 + (double(int(rng() % 2001)) - 1000.0) * 1e-12);
    if (i % 3 == 1 && q != 0.0) curve = 5e8 / q * (1.0 + (double(int(rng() % 2001)) - 1000.0) * 1e-12);
    check(a, b, steps, curve);
  }
  // dd at the accept boundary T |dd| <= |delta| (T = steps (steps - 1) / 2): |dd| = k - 1,
  // k, k + 1 with k = |delta| / T, both signs (ddf = +-(target + 1/2): truncated to target).
  for (int i = 0; i < 100000; ++i) {
    const int steps = 2 + int(rng() % 14);
    const int32_t a = int32_t(rng() % uint32_t(kMax)), b = int32_t(rng() % uint32_t(kMax)) >> (rng() % 31);
    const double q = double(b - a) / steps;
    if (q == 0.0) continue;
    const int64_t pd = b > a ? int64_t(b) - a : int64_t(a) - b, T = steps * (steps - 1) / 2, k = pd / T;
    for (int64_t target : {k - 1, k, k + 1}) {
      if (target < 0) continue;
      check(a, b, steps, -(double(target) + 0.5) / (2.0 * q));
      check(a, b, steps, (double(target) + 0.5) / (2.0 * q));
    }
  }
  for (int steps = 1; steps <= 15; ++steps) {
    for (double curve : {0.0, -0.0, nan, inf, -inf, 1e-300, 1e300}) {
      for (int32_t a : {0, 1, kMax}) {
        for (int32_t b : {0, 1, 7, kMax, kMax - 1}) check(a, b, steps, curve);
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld last-run step tests, %ld wrong\n", checked, wrong);
}
#endif

#if defined(__aarch64__)
// asm/span_persp_arm.h's short-span reciprocal (aarch64): y0 = frecpe(b), two steps
// y = y * frecps(b, y), two fused steps y = fma(y, fma(-b, y, 1), y), bit for bit 1 / b
// for b in [2^-30, 2^1000) whose significand is not all ones (the kernel divides for the
// rest; the proof is in the header). The same operations: frecpe's bound (2^-8.45) on every
// table interval of every exponent, both ends of each interval, inputs whose reciprocal
// lies within a few 2^-106 of a rounding midpoint (the hard cases), random significands
// and exponents, and the engine's usual depths; the all-ones significands must be wrong
// somewhere (else the kernel's test for them would be needless: the proof's exception).
TEST(AsmSpanPersp, ReciprocalWithoutDivide) {
  auto bits = [](double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  auto from = [](uint64_t b) {
    double x;
    std::memcpy(&x, &b, sizeof x);
    return x;
  };
  auto recip = [](float64x2_t b) {
    const float64x2_t one = vdupq_n_f64(1.0);
    float64x2_t y = vrecpeq_f64(b);
    y = vmulq_f64(y, vrecpsq_f64(b, y));
    y = vmulq_f64(y, vrecpsq_f64(b, y));
    y = vfmaq_f64(y, y, vfmsq_f64(one, b, y));
    return vfmaq_f64(y, y, vfmsq_f64(one, b, y));
  };
  constexpr uint64_t kFrac = (uint64_t(1) << 52) - 1;
  long checked = 0, wrong = 0, ones_wrong = 0;
  auto check = [&](double a, double b) {
    const float64x2_t r = recip(vcombine_f64(vdup_n_f64(a), vdup_n_f64(b)));
    const double got[2] = {vgetq_lane_f64(r, 0), vgetq_lane_f64(r, 1)}, in[2] = {a, b};
    for (int l = 0; l < 2; ++l) {
      const volatile double x = in[l];
      const bool bad = bits(got[l]) != bits(1.0 / x);
      if ((bits(in[l]) & kFrac) == kFrac) {
        ones_wrong += bad;
      } else {
        wrong += bad;
        ++checked;
      }
    }
  };
  const int emin = -30, emax = 999;
  double max_err = 0.0;
  for (int e = emin; e <= emax; ++e) {
    for (uint64_t i = 0; i < 256; ++i) {
      const uint64_t lo = uint64_t(e + 1023) << 52 | i << 44, hi = lo + (uint64_t(1) << 44) - 1;
      const double y = vgetq_lane_f64(vrecpeq_f64(vdupq_n_f64(from(lo))), 0);
      ASSERT_EQ(bits(y), bits(vgetq_lane_f64(vrecpeq_f64(vdupq_n_f64(from(hi))), 0))) << e << " " << i;
      // |b y - 1| at both ends (b y exact in long double: 53 + 9 bits), scaled to [1, 2).
      for (uint64_t end : {lo, hi}) {
        const double b = std::ldexp(from(end), -e), ys = std::ldexp(y, e);
        max_err = std::max(max_err, double(std::fabs((long double)b * ys - 1.0L)));
      }
      check(from(lo), from(hi));
    }
  }
  EXPECT_LT(max_err, 0x1.78p-9);  // 2^-8.453 measured; the proof takes 2^-8.44
  std::mt19937_64 rng(77);
  for (long t = 0; t < 400000; ++t) {  // 1 / b next to a midpoint M 2^-54: B = round(2^106 / M) + k
    const unsigned __int128 M = (unsigned __int128)(uint64_t(1) << 53 | (rng() & kFrac) | 1);
    const uint64_t B = uint64_t(((unsigned __int128)1 << 106) / M);
    for (uint64_t Bk = B - 2; Bk <= B + 2; ++Bk) {
      if (Bk < (uint64_t(1) << 52) || Bk >= (uint64_t(1) << 53)) continue;
      const uint64_t e = uint64_t(int(rng() % uint64_t(emax - emin + 1)) + emin + 1023);
      check(from(e << 52 | (Bk & kFrac)), from(uint64_t(1023) << 52 | (Bk & kFrac)));
    }
  }
  for (long t = 0; t < 4000000; ++t) {
    const uint64_t e = uint64_t(int(rng() % uint64_t(emax - emin + 1)) + emin + 1023);
    check(from(e << 52 | (rng() & kFrac)), 1e-9 + double(rng() >> 11) * 0x1p-53 * 1e3);
  }
  for (int e = emin; e <= emax; ++e) check(from(uint64_t(e + 1023) << 52 | kFrac), from(uint64_t(e + 1023) << 52));
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(ones_wrong, 0);
  std::printf("[ asm      ] span_persp: %ld reciprocals without a divide, %ld wrong (frecpe error 2^%.3f)\n",
              checked, wrong, std::log2(max_err));
}
#endif
#if defined(__aarch64__)
// asm/span_persp_a64mid.h's short_steps_k3v (the four-run path persp_short_inl takes: runs
// 0 .. 2 full, run 3 the last, with last_dd in run 2's vectors) against its parts: the full
// runs' steps16_dd (cvt_sat(delta c)) and the last run's last_steps (div_steps, (q curve)
// -2 and the 1e9 range, last_dd) for every steps = 0 .. 15 (s = max(steps, 1)). The last
// run's curve often at the T |dd| = |delta| edge (T = steps (steps - 1) / 2, 0 .. 105; for T
// = 1 with |dd| past the 2^25 clamp the full runs use), 0, tiny, huge, infinite and NaN.
// The engine runs the same steps as steps_k3v_pass (the first pass drawn inside the block):
// it is checked on the same inputs.
TEST(AsmSpanPersp, ShortStepsK3vMatchTheirParts) {
  using sb::simd::RunSteps;
  std::mt19937 rng(29);
  const int32_t kTop = INT32_MAX - 65535;
  const double kOdd[] = {0.0, -0.0, 1e-300, -1e-300, 1e300, -1e300, std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()};
  auto sample = [&]() -> int32_t {
    switch (rng() % 4) {
      case 0: return rng() % 2 ? 0 : kTop - int32_t(rng() % 2);
      case 1: return int32_t(rng() % (uint32_t(kTop) + 1));
      default: return int32_t((rng() % (uint32_t(kTop) + 1)) >> (rng() % 31));
    }
  };
  auto curve_for = [&](int32_t delta) -> double {  // a factor c with trunc(delta c) near the edge
    const uint32_t r = rng() % 8;
    if (r == 0) return kOdd[rng() % 9];
    if (r == 1 || delta == 0) return std::ldexp(double(int32_t(rng())), -int(rng() % 80));
    const int32_t t = int32_t(delta / 120) + int32_t(rng() % 5) - 2;
    const double want = (rng() % 2 ? t : -t) + (rng() % 1000) / 1000.0;
    return want / double(delta);
  };
  auto unpacked = [](const RunSteps& su, const RunSteps& sv, bool dd) {
    return (uint64_t(uint32_t(dd ? sv.dd : sv.d)) << 32) + uint32_t(dd ? su.dd : su.d);
  };
  long checked = 0, wrong = 0, wrong_pass = 0;
  std::vector<uint8_t> texture(3 << 17);  // texels[-2^17 .. 2^17 + 2^17)
  for (auto& t : texture) t = uint8_t(rng());
  const uint8_t* texels = texture.data() + (1 << 17);
  for (int i = 0; i < 400000; ++i) {
    int32_t u[5], v[5];
    for (int j = 0; j < 5; ++j) {
      u[j] = sample(), v[j] = sample();
      if (j > 0 && rng() % 8 == 0) u[j] = u[j - 1];
      if (j > 0 && rng() % 8 == 0) v[j] = v[j - 1];
    }
    double c[3];
    for (int j = 0; j < 3; ++j) c[j] = curve_for(rng() % 2 ? u[j + 1] - u[j] : v[j + 1] - v[j]);
    const int steps = i % 16, s = steps > 1 ? steps : 1;
    const int32_t du3 = u[4] - u[3], dv3 = v[4] - v[3];
    double zc = rng() % 16 == 0 ? kOdd[rng() % 9] : std::ldexp(double(int32_t(rng())), -int(rng() % 90));
    double zk = rng() % 16 == 0 ? kOdd[rng() % 9] : std::ldexp(double(rng()), -int(rng() % 60));
    const int T = steps * (steps - 1) / 2;
    if (rng() % 2 && T > 0 && (du3 != 0 || dv3 != 0)) {  // the last run's T |dd| = |delta| edge
      const int32_t dl = rng() % 2 && du3 != 0 ? du3 : (dv3 != 0 ? dv3 : du3);
      const double want = double(dl / T) + int32_t(rng() % 5) - 2 + (rng() % 1000) / 1000.0;
      zc = rng() % 2 ? 1.0 : -1.0, zk = want / (-(double(dl) / s) * zc);
    }
    const int32_t s01[4] = {u[0], v[0], u[1], v[1]}, s23[4] = {u[2], v[2], u[3], v[3]};
    const int32_t s44[4] = {u[4], v[4], u[4], v[4]};
    const double c01[2] = {c[0], c[1]}, c23[2] = {c[2], 0.5}, zs23[2] = {1.0, zk};
    uint64_t st[6];
    const sb::simd::MidFirst f =
        sb::simd::short_steps_k3v(vld1q_s32(s01), vld1q_s32(s23), vld1q_s32(s44), vld1q_f64(c01), vld1q_f64(c23),
                                  vld1q_f64(zs23), s, zc * 0.5, st);
    auto uv = [&](int j) { return (uint64_t(uint32_t(v[j])) << 32) + uint32_t(u[j]); };
    wrong += f.a_uv != uv(0) || f.b_uv != uv(1) || st[0] != uv(2) || st[1] != uv(3);
    // Full runs 0, 1, 2.
    const uint64_t gd[3] = {f.a_d, f.b_d, st[2]}, gdd[3] = {f.a_dd, f.b_dd, st[4]};
    for (int j = 0; j < 3; ++j) {
      const int32_t du = u[j + 1] - u[j], dv = v[j + 1] - v[j];
      const RunSteps su = sb::simd::steps16_dd(du, sb::simd::cvt_sat(double(du) * c[j]));
      const RunSteps sv = sb::simd::steps16_dd(dv, sb::simd::cvt_sat(double(dv) * c[j]));
      wrong += gd[j] != unpacked(su, sv, false) || gdd[j] != unpacked(su, sv, true);
    }
    // The last run (3): last_steps.
    RunSteps su, sv;
    const double fd[2] = {double(du3), double(dv3)};
    sb::simd::last_steps(steps, du3, dv3, vld1q_f64(fd), zc * 0.5 * zk, &su, &sv);
    wrong += st[3] != unpacked(su, sv, false) || st[5] != unpacked(su, sv, true);
    // The engine's block (steps_k3v_pass: the same steps with the first pass drawn inside):
    // the same st, the second pass's arguments packed from it, full iff s = 15, and runs 0, 1 drawn as the
    // reference draws them with the steps checked above (texture 1 texel wide: every
    // (v >> 16) + (u >> 16) lies inside the guarded texel buffer).
    uint64_t st2[6];
    uint8_t drawn[32], want[32];
    bool full = false;
    const sb::simd::MidFirst g = sb::simd::steps_k3v_pass(
        drawn, texels, 1, vld1q_s32(s01), vld1q_s32(s23), vld1q_s32(s44), vld1q_f64(c01), vld1q_f64(c23),
        vld1q_f64(zs23), s, zc * 0.5, st2, full);
    wrong_pass += !std::equal(st, st + 6, st2) || full != (s == 15);
    wrong_pass += g.a_uv != st[0] || g.b_uv != st[1] || g.a_d != sb::simd::mid_pack(st[2]) ||
                  g.b_d != sb::simd::mid_pack(st[3]) || g.a_dd != sb::simd::mid_pack(st[4]) ||
                  g.b_dd != sb::simd::mid_pack(st[5]);
    for (int j = 0; j < 2; ++j) {
      const uint64_t d = j ? f.b_d : f.a_d, dd = j ? f.b_dd : f.a_dd;
      sb::simd::surface_span_scalar(want + 16 * j, 16, texels, 1, 1, u[j], v[j], int32_t(uint32_t(d)),
                                    int32_t(d >> 32), int32_t(uint32_t(dd)), int32_t(dd >> 32));
    }
    wrong_pass += std::memcmp(drawn, want, 32) != 0;
    ++checked;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(wrong_pass, 0);
  std::printf("[ asm      ] span_persp: %ld four-run step blocks (vector last run), %ld wrong; with the first "
              "pass %ld wrong\n", checked, wrong, wrong_pass);
}
#endif

#if defined(__aarch64__)
// asm/span_persp_a64lin.h's setup block (short linear spans) against the walker's parts: the
// samples as asm/span_persp.cpp's exact() at the walker's positions, the full runs' steps as
// steps16_packed, the last run's as run_steps (delta / steps per component, truncating):
// every length 17 .. 64, samples rising, falling, equal and at the clamps. Sensitive to a
// step one unit off, which drawn texels rarely show.
TEST(AsmSpanPersp, ShortLinearSetupMatchesTheWalkersParts) {
  using sb::simd::span_walk::kMinZi;
  using sb::simd::span_walk::to_fixed;
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  long checked = 0, wrong = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    for (int n = 17; n <= 64; ++n) {
      sb::simd::PerspSpan p{};
      p.zi0 = 0.01 * (1.5 + r(rng));
      p.dzi = trial % 7 == 0 ? 0.0 : p.zi0 * 0.02 * r(rng);
      const double scale = std::ldexp(1.0, int(rng() % 12));
      p.uz0 = p.zi0 * 65536.0 * 64.0 * (0.5 + 0.6 * r(rng)) * scale;
      p.duz = p.zi0 * 65536.0 * r(rng) * scale * (trial % 3 == 0 ? 0.0 : 1.0);
      p.vz0 = p.zi0 * 65536.0 * 64.0 * (0.5 + 0.6 * r(rng)) * scale;
      p.dvz = p.zi0 * 65536.0 * r(rng) * scale;
      p.px0 = double(rng() % 2000) + (rng() & 1 ? 0.5 : 0.0);
      p.umax = trial % 5 == 0 ? int32_t(rng() % (1u << 23)) : INT32_MAX - 65535;
      p.vmax = trial % 11 == 0 ? 0 : int32_t((64u << 16) - 1) * int32_t(1 + rng() % 64);
      auto sample = [&](double px) {
        double zi = p.zi0 + p.dzi * px;
        if (!(zi > kMinZi)) zi = kMinZi;
        const double z = 1.0 / zi;
        const uint32_t u = uint32_t(to_fixed((p.uz0 + p.duz * px) * z, p.umax));
        const uint32_t v = uint32_t(to_fixed((p.vz0 + p.dvz * px) * z, p.vmax));
        return uint64_t(v) << 32 | u;
      };
      // The walker's positions: run starts P_j = P_{j-1} + 16, each run's end sample one
      // addition from its start (16, or the last run's last pixel).
      uint64_t x[5];
      double pj = p.px0;
      x[0] = sample(pj);
      for (int j = 0; j < 4; ++j) {
        const int left = n - 16 * j;
        x[j + 1] = left > 1 ? sample(pj + double(left > 16 ? 16 : left - 1)) : x[j];
        pj += 16.0;
      }
      const int k = (n - 1) >> 4, last = n - 16 * k, s = last > 2 ? last - 1 : 1;
      auto lo = [](uint64_t a) { return int32_t(uint32_t(a)); };
      auto hi = [](uint64_t a) { return int32_t(a >> 32); };
      auto packed = [](int32_t du, int32_t dv) { return (uint64_t(uint32_t(dv)) << 32) + uint64_t(int64_t(du)); };
      const sb::simd::ShortLinSetup got = sb::simd::short_lin_setup(n, p);
      const uint64_t want_ld = packed((lo(x[k + 1]) - lo(x[k])) / s, (hi(x[k + 1]) - hi(x[k])) / s);
      bool bad = got.ld != want_ld;
      const uint64_t gx[4] = {got.x0, got.x1, got.x2, got.x3}, gd[3] = {got.d0, got.d1, got.d2};
      for (int j = 0; j <= k; ++j) bad |= gx[j] != x[j];
      for (int j = 0; j < k; ++j) bad |= gd[j] != sb::simd::steps16_packed(x[j], x[j + 1]);
      if (bad && wrong < 5) ADD_FAILURE() << "n " << n << " trial " << trial;
      wrong += bad;
      ++checked;
    }
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld short linear setups, %ld wrong\n", checked, wrong);
}
#endif

#if defined(__aarch64__)
// asm/span_persp_a64longlast.h's pass_last (the long tail's runs r, r + 1 and its partial last
// run in one block) against its parts: short_pass<true> for the two runs, draw_last<true> for
// the last run, on every last = 1 .. 15, random starts and steps (second steps of both signs,
// 0, and the largest that keep a run inside the texture); bytes past d[31 + last] untouched.
TEST(AsmSpanPersp, PassLastMatchesItsParts) {
  std::mt19937 rng(41);
  const int tw = 256, th = 256;
  std::vector<uint8_t> tex(size_t(tw) * th);
  for (auto& b : tex) b = uint8_t(rng());
  auto packed = [](int32_t lo, int32_t hi) { return (uint64_t(uint32_t(hi)) << 32) + uint64_t(int64_t(lo)); };
  // a start in the texture's middle half, a step of at most 3 texels a pixel and a second
  // step of at most 2^13 / 65536 texel: every position of a 16-pixel run stays inside.
  auto coord = [&]() { return int32_t((64u << 16) + rng() % (128u << 16)); };
  auto step = [&]() { return int32_t(rng() % (6u << 16)) - int32_t(3u << 16); };
  auto step2 = [&](int k) {
    switch (k % 4) {
      case 0: return int32_t(0);
      case 1: return int32_t(8191);
      case 2: return int32_t(-8191);
      default: return int32_t(rng() % 16383) - 8191;
    }
  };
  long checked = 0, wrong = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int last = 1 + trial % 15;
    int32_t u[3], v[3], du[3], dv[3], ddu[3], ddv[3];
    for (int r = 0; r < 3; ++r) {
      u[r] = coord(), v[r] = coord(), du[r] = step(), dv[r] = step();
      ddu[r] = step2(trial + r), ddv[r] = step2(trial / 4 + r);
    }
    uint8_t want[64], got[64];
    for (int i = 0; i < 64; ++i) want[i] = got[i] = uint8_t(i * 37 + trial);
    const uint64_t w = uint64_t(tw);
    sb::simd::short_pass<true>(want, tex.data(), w, packed(u[0], v[0]), packed(du[0], dv[0]), packed(ddu[0], ddv[0]),
                               packed(u[1], v[1]), packed(du[1], dv[1]), packed(ddu[1], ddv[1]));
    sb::simd::draw_last<true>(want + 32, last, tex.data(), uint32_t(tw), uint32_t(u[2]), uint32_t(v[2]),
                              uint32_t(du[2]), uint32_t(dv[2]), uint32_t(ddu[2]), uint32_t(ddv[2]));
    sb::simd::pass_last(got, tex.data(), w, last, packed(u[0], v[0]), packed(du[0], dv[0]), packed(ddu[0], ddv[0]),
                        packed(u[1], v[1]), packed(du[1], dv[1]), packed(ddu[1], ddv[1]), packed(u[2], v[2]), du[2],
                        dv[2], ddu[2], ddv[2]);
    const bool bad = std::memcmp(want, got, sizeof want) != 0;
    if (bad && wrong < 5) ADD_FAILURE() << "last " << last << " trial " << trial;
    wrong += bad;
    ++checked;
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld pass_last blocks, %ld wrong\n", checked, wrong);
}
#else
TEST(AsmSpanPersp, PassLastMatchesItsParts) { GTEST_SKIP() << "aarch64 only"; }
#endif

}  // namespace
