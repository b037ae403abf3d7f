// The whole-span drawer (asm/span_persp.h) against the engine's run walker
// (render::draw_surface_spans_by_runs, one surface_span call per 16-pixel run): the same
// pixels and z on random perspective gradients (steep, clamped, edge-on, behind the eye,
// linear and second order), span lengths 0 .. 1920, with the tuned kernels and with the
// scalar references forced; on real faces of LibreQuake maps seen from the maps' own
// viewpoints (skipped without the data); and the kernel's variants on non-finite input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#if defined(__aarch64__)
#include <arm_neon.h>
#endif

#include "asm/kernels.h"
#include "asm/span_persp_run.h"  // steps16_dd (internal linkage: this test's own copy)
// ARMv7 and x86-64: last_ddi, last_steps_i (the ARMv7 tails' parts; portable C++); aarch64:
// div_steps, short_steps_k3 and short_steps_k3v (asm/span_persp_a64short.h, a64mid.h, included
// by it).
#include "asm/span_persp_arm.h"
#include "engine/render/render_local.h"
#include "engine/render/span_draw.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"

namespace {

using sb::render::Span;
using sb::render::SpanGradients;

struct ScalarScope {  // forces the scalar references for its lifetime
  bool before = sb::simd::scalar_forced();
  explicit ScalarScope(bool on) { sb::simd::force_scalar(on); }
  ~ScalarScope() { sb::simd::force_scalar(before); }
};

struct Frame {
  std::vector<uint8_t> pixels;
  std::vector<uint16_t> z;
  sb::Framebuffer fb;
  Frame(int w, int h) : pixels(size_t(w) * h, 0), z(size_t(w) * h, 0) {
    fb.pixels = pixels.data();
    fb.width = fb.stride = w;
    fb.height = h;
    fb.zbuffer = z.data();
  }
};

SpanGradients random_gradients(std::mt19937& rng, int w, int h, int sw, int sh) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  SpanGradients g{};
  const double depth = 0.002 + 0.05 * (r(rng) + 1.0);
  g.zix = depth * r(rng) / w;
  g.ziy = depth * r(rng) / h;
  g.zi0 = depth + std::fabs(g.zix) * w + std::fabs(g.ziy) * h;
  if (rng() % 5 == 0) g.zi0 = depth * r(rng);  // edge-on or behind: clamped
  if (rng() % 7 == 0) g.zix *= 40.0;           // steep
  const double us = sw * (0.5 + r(rng)), vs = sh * (0.5 + r(rng));
  g.u0 = us * (g.zi0 * (0.5 + 0.5 * r(rng)));
  g.ux = us * (g.zix + r(rng) * depth / w);
  g.uy = us * g.ziy * r(rng);
  g.v0 = vs * (g.zi0 * (0.5 + 0.5 * r(rng)));
  g.vx = vs * g.zix * r(rng);
  g.vy = vs * (g.ziy + r(rng) * depth / h);
  g.second_order = rng() % 4 != 0;
  return g;
}

// Draws `spans` both ways (kernel, run walker) and expects identical pixels and z.
void expect_same(const std::vector<Span>& spans, const SpanGradients& g, const uint8_t* surf, int sw, int sh, int W,
                 int H, const char* what) {
  Frame a(W, H), b(W, H);
  sb::render::draw_surface_spans(spans.data(), uint32_t(spans.size()), g, surf, sw, sh, a.fb);
  sb::render::draw_surface_spans_by_runs(spans.data(), uint32_t(spans.size()), g, surf, sw, sh, b.fb);
  ASSERT_EQ(a.pixels, b.pixels) << what << " (" << (sb::simd::scalar_forced() ? "scalar" : "tuned") << ")";
  ASSERT_EQ(a.z, b.z) << what;
}

// Draws span p (n pixels) with the reference and with every supported variant, each into a
// buffer with 64 guard bytes (0xa5) on both sides: a failure, naming the variant and the
// first differing byte, unless every variant wrote exactly the reference's bytes and nothing
// outside the span. ref_out, if given, receives the reference's n bytes.
::testing::AssertionResult variants_match(int n, const uint8_t* surf, int sw, int sh, const sb::simd::PerspSpan& p,
                                          std::vector<uint8_t>* ref_out = nullptr) {
  constexpr int kGuard = 64;
  std::vector<uint8_t> ref(size_t(n) + 2 * kGuard, 0xa5), got(ref.size());
  sb::simd::surface_span_persp_scalar(ref.data() + kGuard, n, surf, sw, sh, p);
  auto guard_intact = [&](const std::vector<uint8_t>& b) {
    auto is_guard = [](uint8_t x) { return x == 0xa5; };
    return std::all_of(b.begin(), b.begin() + kGuard, is_guard) && std::all_of(b.end() - kGuard, b.end(), is_guard);
  };
  if (!guard_intact(ref)) return ::testing::AssertionFailure() << "the reference wrote outside its span of " << n;
  for (int v = 0; v < sb::simd::variant_count(); ++v) {
    const sb::simd::Variant var = sb::simd::variant(v);
    if (!var.kernels || !var.supported) continue;
    std::fill(got.begin(), got.end(), 0xa5);
    var.kernels->surface_span_persp(got.data() + kGuard, n, surf, sw, sh, p);
    const auto d = std::mismatch(ref.begin(), ref.end(), got.begin());
    if (d.first != ref.end()) {
      return ::testing::AssertionFailure() << var.kernels->name << " wrote " << int(*d.second) << " for "
                                           << int(*d.first) << " at byte " << (d.first - ref.begin()) - kGuard
                                           << " of a span of " << n;
    }
  }
  if (ref_out) ref_out->assign(ref.begin() + kGuard, ref.begin() + kGuard + n);
  return ::testing::AssertionSuccess();
}

TEST(AsmSpanPersp, MatchesTheRunWalkerOnRandomGradients) {
  std::mt19937 rng(99);
  const int W = 1920, H = 24;
  int spans_drawn = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const int sw = 1 + int(rng() % 700), sh = 1 + int(rng() % 300);
    std::vector<uint8_t> surface(size_t(sw) * sh);
    for (auto& b : surface) b = uint8_t(rng());
    const SpanGradients g = random_gradients(rng, W, H, sw, sh);
    std::vector<Span> spans;
    const int lengths[] = {0, 1, 2, 15, 16, 17, 31, 32, 33, 320, 1920};
    for (int y = 0; y < H; ++y) {
      const int n = y < 11 ? lengths[y] : int(rng() % (W + 1));
      spans.push_back(Span{int16_t(rng() % (W - n + 1)), int16_t(y), int16_t(n), 0});
    }
    for (bool scalar : {false, true}) {
      ScalarScope s(scalar);
      expect_same(spans, g, surface.data(), sw, sh, W, H, "random gradients");
    }
    spans_drawn += int(spans.size());
  }
  std::printf("[ asm      ] span_persp: %d spans x 2 kernel tables identical to the run walker\n", spans_drawn);
}

// Every length from 1 to 100 (the short-span path's 2 .. 4 runs and the long path's first
// lengths), many gradients: each run count and last-run length on each side.
TEST(AsmSpanPersp, MatchesTheRunWalkerOnShortSpans) {
  std::mt19937 rng(7);
  const int W = 128, H = 100;
  int spans_drawn = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int sw = 1 + int(rng() % 400), sh = 1 + int(rng() % 300);
    std::vector<uint8_t> surface(size_t(sw) * sh);
    for (auto& b : surface) b = uint8_t(rng());
    const SpanGradients g = random_gradients(rng, W, H, sw, sh);
    std::vector<Span> spans;
    for (int y = 0; y < H; ++y) {
      const int n = y + 1;
      spans.push_back(Span{int16_t(rng() % (W - n + 1)), int16_t(y), int16_t(n), 0});
    }
    for (bool scalar : {false, true}) {
      ScalarScope s(scalar);
      expect_same(spans, g, surface.data(), sw, sh, W, H, "short spans");
    }
    spans_drawn += int(spans.size());
  }
  std::printf("[ asm      ] span_persp: %d short spans identical to the run walker\n", spans_drawn);
}

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
// asm/span_persp_a64short.h's short_steps_k3 (four-run short spans, second order: the full
// runs' steps and the last run's last_steps vector part in one asm block) against its parts:
// per full run and component steps16_dd(delta, cvt_sat(delta c)) packed as Run16 takes them,
// and last_steps' vector results (div_steps quotient, trunc, (q curve) -2 masked by |ddf| <
// 1e9) for every s = 1 .. 16. Samples: 0, the clamp's top, equal neighbours, random of every
// magnitude; curve factors at the 120 |dd| = |delta| edge, 0, tiny, huge, infinite and NaN.
TEST(AsmSpanPersp, ShortStepsK3MatchTheirParts) {
  using sb::simd::RunSteps;
  std::mt19937 rng(23);
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
  long checked = 0, wrong = 0;
  for (int i = 0; i < 400000; ++i) {
    int32_t u[5], v[5];
    for (int j = 0; j < 5; ++j) {
      u[j] = sample(), v[j] = sample();
      if (j > 0 && rng() % 8 == 0) u[j] = u[j - 1];
      if (j > 0 && rng() % 8 == 0) v[j] = v[j - 1];
    }
    double c[3];
    for (int j = 0; j < 3; ++j) c[j] = curve_for(rng() % 2 ? u[j + 1] - u[j] : v[j + 1] - v[j]);
    const int s = 1 + int(i % 16);
    const double zc = rng() % 16 == 0 ? kOdd[rng() % 9] : std::ldexp(double(int32_t(rng())), -int(rng() % 90));
    const double zk = rng() % 16 == 0 ? kOdd[rng() % 9] : std::ldexp(double(rng()), -int(rng() % 60));
    const int32_t s01[4] = {u[0], v[0], u[1], v[1]}, s23[4] = {u[2], v[2], u[3], v[3]}, s44[4] = {u[4], v[4], u[4], v[4]};
    const double c01[2] = {c[0], c[1]}, c23[2] = {c[2], 0.5}, zs23[2] = {1.0, zk};
    const sb::simd::ShortStepsK3 r =
        sb::simd::short_steps_k3(vld1q_s32(s01), vld1q_s32(s23), vld1q_s32(s44), vld1q_f64(c01), vld1q_f64(c23),
                                 vld1q_f64(zs23), s, zc);
    // Deltas.
    const int32_t d01[4] = {u[1] - u[0], v[1] - v[0], u[2] - u[1], v[2] - v[1]};
    const int32_t d23[4] = {u[3] - u[2], v[3] - v[2], u[4] - u[3], v[4] - v[3]};
    int32_t g01[4], g23[4];
    vst1q_s32(g01, r.D01), vst1q_s32(g23, r.D23);
    wrong += std::memcmp(g01, d01, sizeof d01) != 0 || std::memcmp(g23, d23, sizeof d23) != 0;
    // Full runs 0, 1, 2.
    const int64_t dl[3] = {vgetq_lane_s64(r.dlo, 0), vgetq_lane_s64(r.dlo, 1), vgetq_lane_s64(r.dhi, 0)};
    const int64_t ddl[3] = {vgetq_lane_s64(r.ddlo, 0), vgetq_lane_s64(r.ddlo, 1), vgetq_lane_s64(r.ddhi, 0)};
    for (int j = 0; j < 3; ++j) {
      const int32_t du = u[j + 1] - u[j], dv = v[j + 1] - v[j];
      const RunSteps su = sb::simd::steps16_dd(du, sb::simd::cvt_sat(double(du) * c[j]));
      const RunSteps sv = sb::simd::steps16_dd(dv, sb::simd::cvt_sat(double(dv) * c[j]));
      const uint64_t want_d = (uint64_t(uint32_t(sv.d)) << 32) + uint64_t(int64_t(su.d));
      const uint64_t want_dd = (uint64_t(uint32_t(sv.dd)) << 32) + uint64_t(int64_t(su.dd));
      wrong += uint64_t(dl[j]) != want_d || uint64_t(ddl[j]) != want_dd;
    }
    // The last run (3): last_steps' vector part.
    const double fd[2] = {double(d23[2]), double(d23[3])};
    const float64x2_t q = sb::simd::div_steps(vld1q_f64(fd), uint32_t(s));
    const int64x2_t lin = vcvtq_s64_f64(q);
    const float64x2_t ddf = vmulq_n_f64(vmulq_n_f64(q, zc * 0.5 * zk), -2.0);
    const int64x2_t dd =
        vandq_s64(vcvtq_s64_f64(ddf), vreinterpretq_s64_u64(vcaltq_f64(ddf, vdupq_n_f64(1e9))));
    wrong += vgetq_lane_s64(r.lin, 0) != vgetq_lane_s64(lin, 0) || vgetq_lane_s64(r.lin, 1) != vgetq_lane_s64(lin, 1);
    wrong += vgetq_lane_s64(r.dd, 0) != vgetq_lane_s64(dd, 0) || vgetq_lane_s64(r.dd, 1) != vgetq_lane_s64(dd, 1);
    ++checked;
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld four-run step blocks, %ld wrong\n", checked, wrong);
}
// asm/span_persp_a64mid.h's short_steps_k3v (the four-run path persp_short_inl takes: runs
// 0 .. 2 full, run 3 the last, with last_dd in run 2's vectors) against its parts: the full
// runs' steps16_dd (cvt_sat(delta c)) and the last run's last_steps (div_steps, (q curve)
// -2 and the 1e9 range, last_dd) for every steps = 0 .. 15 (s = max(steps, 1)). The last
// run's curve often at the T |dd| = |delta| edge (T = steps (steps - 1) / 2, 0 .. 105; for T
// = 1 with |dd| past the 2^25 clamp the full runs use), 0, tiny, huge, infinite and NaN.
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
  long checked = 0, wrong = 0;
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
                                  vld1q_f64(zs23), s, zc, st);
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
    ++checked;
  }
  EXPECT_EQ(wrong, 0);
  std::printf("[ asm      ] span_persp: %ld four-run step blocks (vector last run), %ld wrong\n", checked, wrong);
}
#endif


// The short spans' reciprocal falls back to the divide for depths whose significand is all
// ones (there 1 / zi lies 2^-107 from a rounding midpoint) and for zi >= 2^1000: spans of
// 17 .. 64 pixels at such a constant depth, u placed so that z one ulp low moves it one
// texel left (u 65536 = A (1 + 2^-52) with A = c 2^16 - ulp: exactly c 2^16 or more when z
// is right, A when it is low).
TEST(AsmSpanPersp, ShortSpansDivideWhereTheReciprocalCannot) {
  std::mt19937 rng(5);
  const int sw = 37, sh = 19;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i);  // every texel of a row differs
  std::vector<uint8_t> ref;
  int cases = 0;
  std::vector<int> ks;
  for (int k = -29; k < 60; ++k) ks.push_back(k);
  for (int k = 60; k < 1000; k += 37) ks.push_back(k);
  for (int k : {1000, 1001, 1010, 1022}) ks.push_back(k);
  for (int k : ks) {
    for (int c : {3, 5, 7, 11, 13}) {
      const double m = double(c) * 65536.0, a = std::nextafter(m, 0.0);
      sb::simd::PerspSpan p{};
      p.zi0 = k < 1000 ? std::ldexp(2.0 - 0x1p-52, k) : std::ldexp(1.5, k);
      p.dzi = rng() & 1 ? 0.0 : std::ldexp(1.0, k - 80);  // second order; zi still rounds to zi0
      p.uz0 = k < 1000 ? std::ldexp(a, k + 1 - 16) : 0.0;
      p.px0 = double(rng() % 100) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      const int n = 17 + int(rng() % 48);
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p, &ref)) << " k " << k;
      if (k < 1000) {
        EXPECT_EQ(ref[0], uint8_t(c)) << k;  // the case is the sensitive one
      }
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d short spans at all-ones and huge depths, every variant identical\n",
              cases);
}

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

// Linear spans of every short length (17 .. 64: each run count and last-run length) with
// texture steps of both signs and sizes, u and v each rising or falling: every variant
// against the walker (surface_span_persp_scalar), guard bytes after the span untouched.
TEST(AsmSpanPersp, ShortLinearSpansMatchTheWalkerBothWays) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const int sw = 64, sh = 64;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  std::vector<uint8_t> ref(80), got(80);
  int cases = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    for (int n = 17; n <= 64; ++n) {
      sb::simd::PerspSpan p{};
      p.zi0 = 0.01 * (1.5 + r(rng));
      p.dzi = p.zi0 * 0.01 * r(rng);
      const double su = (trial & 1 ? -1.0 : 1.0) * (trial % 5 + 1) * 40.0, sv = (trial & 2 ? -1.0 : 1.0) * 30.0;
      p.uz0 = p.zi0 * sw * 65536.0 * (0.5 + 0.4 * r(rng));
      p.duz = p.zi0 * 65536.0 * (su + r(rng)) / 64.0 + p.dzi * p.uz0 / p.zi0;
      p.vz0 = p.zi0 * sh * 65536.0 * (0.5 + 0.4 * r(rng));
      p.dvz = p.zi0 * 65536.0 * (sv + r(rng)) / 64.0 + p.dzi * p.vz0 / p.zi0;
      p.px0 = double(rng() % 300) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = false;
      std::fill(ref.begin(), ref.end(), 0xa5);
      sb::simd::surface_span_persp_scalar(ref.data(), n, surf.data(), sw, sh, p);
      for (int v = 0; v < sb::simd::variant_count(); ++v) {
        const sb::simd::Variant var = sb::simd::variant(v);
        if (!var.kernels || !var.supported) continue;
        std::fill(got.begin(), got.end(), 0xa5);
        var.kernels->surface_span_persp(got.data(), n, surf.data(), sw, sh, p);
        ASSERT_EQ(ref, got) << var.kernels->name << " n " << n << " trial " << trial;
      }
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d short linear spans, every variant identical\n", cases);
}

TEST(AsmSpanPersp, VariantsAgreeOnNonFiniteAndHugeGradients) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double odd[] = {0.0, -0.0, 1e-300, -1e300, 1e300, inf, -inf, nan, 3.5, -2.25e-5};
  std::mt19937 rng(3);
  const int sw = 37, sh = 19;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int i = 0; i < 4000; ++i) {
    sb::simd::PerspSpan p{};
    double* f[] = {&p.zi0, &p.dzi, &p.uz0, &p.duz, &p.vz0, &p.dvz};
    for (double* x : f) *x = rng() % 3 ? odd[rng() % 10] : std::ldexp(double(int(rng() % 2001) - 1000), -10);
    p.px0 = double(rng() % 2000) + 0.5;
    p.umax = int32_t((uint32_t(sw) << 16) - 1);
    p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    p.second_order = rng() & 1;
    const int n = int(rng() % 200);
    ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " case " << i;
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d odd-gradient cases, every variant identical\n", cases);
}

// Long second-order spans (persp_fast's pass loop: aarch64 asm/span_persp_a64long.h) on a
// texture 32767 texels wide, so that clamped samples swing between 0 and umax (deltas near
// +-2^31, |delta - 120 dd| up to 2^32) under strong curvature; lengths at each pass boundary
// (the loop runs while more than 48 pixels are left, two runs a pass) and random ones.
TEST(AsmSpanPersp, LongSpansMatchOnExtremeSteps) {
  std::mt19937 rng(11);
  const int sw = 32767, sh = 3;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  const int lengths[] = {65, 79, 80, 81, 82, 95, 96, 97, 112, 113, 127, 128, 129, 144, 145, 160, 161, 176, 177, 1920};
  auto logu = [&](double lo, double hi) {  // +-10^[lo, hi], log-uniform
    const double e = lo + (hi - lo) * double(rng() % 100000) / 100000.0;
    return (rng() & 1 ? 1.0 : -1.0) * std::pow(10.0, e);
  };
  int cases = 0;
  for (int i = 0; i < 6000; ++i) {
    sb::simd::PerspSpan p{};
    p.zi0 = std::fabs(logu(-4, 0));
    p.dzi = logu(-7, -3);
    p.uz0 = logu(2, 9) * p.zi0, p.duz = logu(0, 8) * std::fabs(p.dzi) * (rng() % 4 ? 1.0 : 1e3);
    p.vz0 = std::fabs(logu(-2, 1)) * p.zi0, p.dvz = logu(-3, 1) * std::fabs(p.dzi);
    p.px0 = double(rng() % 100) + (rng() & 1 ? 0.5 : 0.0);
    p.umax = int32_t((uint32_t(sw) << 16) - 1);
    p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    p.second_order = true;
    const int n = i < 2000 ? lengths[i % 20] : 65 + int(rng() % 1936);
    ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " case " << i << " n " << n;
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d long extreme-step spans, every variant identical\n", cases);
}

// Every long-span tail shape (aarch64: 17 .. 48 pixels after the passes, two or three runs,
// the last 1 .. 16 pixels; two full runs drawn as one pass): each length 81 .. 208 on
// random gradients, with sharp curves (the last run's dd accepted and rejected), no byte
// outside the span written.
TEST(AsmSpanPersp, LongSpansMatchOnEveryTailLength) {
  std::mt19937 rng(23);
  const int sw = 256, sh = 256;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int n = 81; n <= 208; ++n) {
    for (int k = 0; k < 12; ++k) {
      sb::simd::PerspSpan p{};
      p.zi0 = 0.002 + 0.01 * double(rng() % 1000) / 1000.0;
      p.dzi = (rng() & 1 ? 1.0 : -1.0) * p.zi0 * double(1 + rng() % 1000) * (k < 6 ? 1e-5 : 4e-3);
      p.uz0 = double(rng() % (sw << 16)) / 65536.0 * p.zi0, p.duz = (double(rng() % 2001) - 1000.0) * 1e-4;
      p.vz0 = double(rng() % (sh << 16)) / 65536.0 * p.zi0, p.dvz = (double(rng() % 2001) - 1000.0) * 1e-4;
      p.px0 = double(rng() % 100) + (rng() & 1 ? 0.5 : 0.0);
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " n " << n << " k " << k;
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d long spans of every tail length, every variant identical\n", cases);
}

// The same depths on long second-order spans (the aarch64 pass loop's reciprocals, computed
// a pass ahead without a divide, take its divide branch there): every sample sits next to a
// texel boundary that a reciprocal one ulp off would cross.
TEST(AsmSpanPersp, LongSpansDivideWhereTheReciprocalCannot) {
  std::mt19937 rng(7);
  const int sw = 37, sh = 19;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i);
  std::vector<uint8_t> ref;
  const int lengths[] = {81, 96, 97, 113, 128, 129, 160, 161, 300, 1920};
  int cases = 0;
  for (int k : {-29, -3, 0, 1, 7, 40, 300, 999, 1000, 1010, 1022}) {
    for (int c : {3, 5, 7, 11, 13}) {
      const double m = double(c) * 65536.0, a = std::nextafter(m, 0.0);
      sb::simd::PerspSpan p{};
      p.zi0 = k < 1000 ? std::ldexp(2.0 - 0x1p-52, k) : std::ldexp(1.5, k);
      p.dzi = std::ldexp(rng() & 1 ? 1.0 : -1.0, k - 80);  // second order; zi still rounds to zi0
      p.uz0 = k < 1000 ? std::ldexp(a, k + 1 - 16) : 0.0;
      p.px0 = double(rng() % 100) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      const int n = lengths[cases % 10];
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p, &ref)) << " k " << k << " n " << n;
      if (k < 1000) {
        EXPECT_EQ(ref[n - 1], uint8_t(c)) << k;  // the case is the sensitive one
      }
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d long spans at all-ones and huge depths, every variant identical\n", cases);
}

// Second-order spans of four runs (49 .. 65 pixels: the ARMv7 path for 50 .. 64 and its
// neighbours) against the reference on gradients spread over many magnitudes: depths near
// and below the 1/z clamp, u and v past both clamps and saturating, curves whose run steps
// are rejected (|dd| large) or accepted, and the non-finite values; no byte outside the span
// is written.
TEST(AsmSpanPersp, FourRunSpansMatchOnExtremeGradients) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double odd[] = {0.0, -0.0, 1e-9, 1e-12, 1e-300, -1e300, 1e300, inf, -inf, nan};
  std::mt19937 rng(64);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int sw = 300, sh = 200;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int i = 0; i < 20000; ++i) {
    sb::simd::PerspSpan p{};
    p.zi0 = rng() % 8 ? std::ldexp(unit(rng) + 1.0, -int(rng() % 32)) : odd[rng() % 10];
    p.dzi = rng() % 8 ? p.zi0 * std::ldexp(unit(rng), -int(rng() % 12)) : odd[rng() % 10];
    p.uz0 = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 20) * p.zi0 * sw : odd[rng() % 10];
    p.duz = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 26) * sw : odd[rng() % 10];
    p.vz0 = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 20) * p.zi0 * sh : odd[rng() % 10];
    p.dvz = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 26) * sh : odd[rng() % 10];
    p.px0 = double(rng() % 2000) + 0.5;
    p.umax = int32_t((uint32_t(sw) << 16) - 1 - (rng() % 3 == 0 ? rng() % 65536 : 0));
    p.vmax = int32_t((uint32_t(sh) << 16) - 1 - (rng() % 3 == 0 ? rng() % 65536 : 0));
    p.second_order = true;
    const int n = 49 + int(rng() % 17);
    ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " case " << i << " n " << n;
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d four-run second-order spans, every variant identical\n", cases);
}

// surface_span_fast (asm/surface_span.h) shares the whole-span drawer's 16-pixel runs; the
// NEON table holds it (asm_kernels_test covers it there), and here it is compared with the
// scalar reference on every target: random walks (linear and second order) that stay
// inside the surface, every length that splits differently into runs of 16.
TEST(AsmSpanPersp, SurfaceSpanFastMatchesScalar) {
  std::mt19937 rng(4242);
  const int lengths[] = {0, 1, 2, 3, 15, 16, 17, 31, 32, 33, 47, 48, 49, 320, 1919, 1920};
  int cases = 0, curved = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int w = 1 + int(rng() % 600), h = 1 + int(rng() % 300);
    std::vector<uint8_t> surf(size_t(w) * h);
    for (auto& b : surf) b = uint8_t(rng());
    const int64_t umax = (int64_t(w) << 16) - 1, vmax = (int64_t(h) << 16) - 1;
    for (int n : lengths) {
      auto walk = [&](int64_t max, int32_t* a, int32_t* d, int32_t* dd) {
        const int64_t x0 = int64_t(rng() % uint64_t(max + 1)), x1 = int64_t(rng() % uint64_t(max + 1));
        const int64_t steps = n > 1 ? n - 1 : 1;
        *a = int32_t(x0);
        *d = int32_t((x1 - x0) / steps);
        *dd = 0;
        if (trial % 2 && n > 2) {  // a bend, kept only if every pixel stays inside
          const int64_t ddc = int64_t(rng() % 2001) - 1000;
          const int64_t d0 = (x1 - x0 - ddc * steps * (steps - 1) / 2) / steps;
          int64_t x = x0, dx = d0;
          bool inside = d0 >= INT32_MIN && d0 <= INT32_MAX;
          for (int k = 0; k < n && inside; ++k, x += dx, dx += ddc) inside = x >= 0 && x <= max;
          if (inside) *d = int32_t(d0), *dd = int32_t(ddc);
        }
      };
      int32_t u, du, ddu, v, dv, ddv;
      walk(umax, &u, &du, &ddu);
      walk(vmax, &v, &dv, &ddv);
      std::vector<uint8_t> want(size_t(n) + 64, 0x5a), got(want);
      sb::simd::surface_span_scalar(want.data() + 32, n, surf.data(), w, h, u, v, du, dv, ddu, ddv);
      sb::simd::surface_span_fast(got.data() + 32, n, surf.data(), w, h, u, v, du, dv, ddu, ddv);
      ASSERT_EQ(want, got) << "n " << n << " surface " << w << "x" << h << " u " << u << " v " << v << " du " << du
                           << " dv " << dv << " ddu " << ddu << " ddv " << ddv;
      ++cases;
      curved += ddu != 0 || ddv != 0;
    }
  }
  std::printf("[ asm      ] surface_span_fast: %d spans (%d second order) identical to scalar\n", cases, curved);
  EXPECT_GT(curved, cases / 8);
}

TEST(AsmSpanPersp, MatchesTheRunWalkerOnRealFaces) {
  SB_REQUIRE_QUAKE_DATA();
  const int W = 640, H = 480;
  long spans_drawn = 0;
  for (const char* map : {"start", "lq_e1m1"}) {
    sb::test::TestWorld tw(map);
    ASSERT_NE(tw.world(), nullptr) << tw.error();
    const sb::BspWorld& w = *tw.world();
    const std::vector<sb::ViewParams> views = sb::test::test_viewpoints(w, 2);
    std::mt19937 rng(17);
    for (const sb::ViewParams& vp : views) {
      const sb::render::ViewState view = sb::render::setup_view(w, vp, W, H, 1);
      for (uint32_t fi = 0; fi < w.num_faces; fi += 29) {
        const sb::Face& f = w.faces[fi];
        if (f.extents[0] <= 0 || f.extents[1] <= 0) continue;
        const int mip = int(fi % 4);
        SpanGradients g = sb::render::face_gradients(w, f, view, mip);
        g.second_order = (fi / 29) % 3 != 0;
        const int sw = f.extents[0] >> mip, sh = f.extents[1] >> mip;
        if (sw < 1 || sh < 1) continue;
        std::vector<uint8_t> surface(size_t(sw) * sh);
        for (auto& b : surface) b = uint8_t(rng());
        // Every row of the screen, as spans of the whole row and of random pieces of it.
        std::vector<Span> spans;
        for (int y = 0; y < H; y += 11) {
          const int n = y % 2 ? W : 1 + int(rng() % W);
          spans.push_back(Span{int16_t(rng() % (W - n + 1)), int16_t(y), int16_t(n), 0});
        }
        expect_same(spans, g, surface.data(), sw, sh, W, H, map);
        spans_drawn += long(spans.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp: %ld spans of real faces identical to the run walker\n", spans_drawn);
}

}  // namespace
