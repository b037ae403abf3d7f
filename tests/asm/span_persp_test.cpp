// The whole-span drawer (asm/span_persp.h) against the engine's run walker
// (render::draw_surface_spans_by_runs, one surface_span call per 16-pixel run): the same
// pixels and z on random perspective gradients (steep, clamped, edge-on, behind the eye,
// linear and second order), span lengths 0 .. 1920, with the tuned kernels and with the
// scalar references forced; on real faces of LibreQuake maps seen from the maps' own
// viewpoints (skipped without the data); and the kernel's variants on non-finite input.
// The parts (step quotients, clamps, reciprocals, the aarch64 setup blocks) are checked one
// by one in span_persp_parts_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "asm/kernels.h"
#include "asm/span_persp.h"
#include "asm/surface_span.h"
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
// A second-order span over a sw x sh surface with extreme steps: 1/z, u / z and v / z and
// their gradients drawn log-uniformly (dzi up to 10^dzi_hi), u steps sometimes 1000x larger,
// so the per-run deltas reach +-2^31.
sb::simd::PerspSpan extreme_step_span(std::mt19937& rng, int sw, int sh, double dzi_hi) {
  auto logu = [&](double lo, double hi) {  // +-10^[lo, hi], log-uniform
    const double e = lo + (hi - lo) * double(rng() % 100000) / 100000.0;
    return (rng() & 1 ? 1.0 : -1.0) * std::pow(10.0, e);
  };
  sb::simd::PerspSpan p{};
  p.zi0 = std::fabs(logu(-4, 0));
  p.dzi = logu(-7, dzi_hi);
  p.uz0 = logu(2, 9) * p.zi0, p.duz = logu(0, 8) * std::fabs(p.dzi) * (rng() % 4 ? 1.0 : 1e3);
  p.vz0 = std::fabs(logu(-2, 1)) * p.zi0, p.dvz = logu(-3, 1) * std::fabs(p.dzi);
  p.px0 = double(rng() % 100) + (rng() & 1 ? 0.5 : 0.0);
  p.umax = int32_t((uint32_t(sw) << 16) - 1);
  p.vmax = int32_t((uint32_t(sh) << 16) - 1);
  p.second_order = true;
  return p;
}

TEST(AsmSpanPersp, LongSpansMatchOnExtremeSteps) {
  std::mt19937 rng(11);
  const int sw = 32767, sh = 3;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  const int lengths[] = {65, 79, 80, 81, 82, 95, 96, 97, 112, 113, 127, 128, 129, 144, 145, 160, 161, 176, 177, 1920};
  int cases = 0;
  for (int i = 0; i < 6000; ++i) {
    const sb::simd::PerspSpan p = extreme_step_span(rng, sw, sh, -3);
    const int n = i < 2000 ? lengths[i % 20] : 65 + int(rng() % 1936);
    ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " case " << i << " n " << n;
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d long extreme-step spans, every variant identical\n", cases);
}

// Long linear spans (aarch64: persp_fast's linear passes as one generated asm loop,
// asm/span_persp_a64lin_pass.h) with extreme steps on a texture 32767 texels wide, so that
// samples clamp at 0 and at umax / vmax and the per-run deltas reach +-2^31: every length 65 ..
// 2000 (each pass count, odd and even, and each tail and last-run length), second_order off
// and dzi == 0 alike, no byte outside the span written (variants_match's guards).
TEST(AsmSpanPersp, LongLinearSpansMatchOnExtremeSteps) {
  std::mt19937 rng(192);
  const int sw = 32767, sh = 3;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int n = 65; n <= 2000; ++n) {
    for (int kind = 0; kind < 2; ++kind) {
      sb::simd::PerspSpan p = extreme_step_span(rng, sw, sh, -3);
      if (kind == 0) {
        p.second_order = false;  // dzi kept: the depth varies, the steps stay linear
      } else {
        p.dzi = 0.0;  // a constant depth, duz / dvz as drawn
      }
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " n " << n << " kind " << kind;
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d long linear extreme-step spans, every variant identical\n", cases);
}

// Every long-span tail shape (aarch64: 17 .. 48 pixels after the passes, two or three runs,
// the last 1 .. 16 pixels; two full runs drawn as one pass): each length 65 .. 208 on
// random gradients, with sharp curves (the last run's dd accepted and rejected), no byte
// outside the span written; linear spans as well (their tail samples from the pass loop).
TEST(AsmSpanPersp, LongSpansMatchOnEveryTailLength) {
  std::mt19937 rng(23);
  const int sw = 256, sh = 256;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int n = 65; n <= 208; ++n) {
    for (int k = 0; k < 18; ++k) {  // k >= 12: linear steps (the aarch64 linear tail's samples)
      sb::simd::PerspSpan p{};
      p.zi0 = 0.002 + 0.01 * double(rng() % 1000) / 1000.0;
      p.dzi = (rng() & 1 ? 1.0 : -1.0) * p.zi0 * double(1 + rng() % 1000) * (k % 12 < 6 ? 1e-5 : 4e-3);
      p.uz0 = double(rng() % (sw << 16)) / 65536.0 * p.zi0, p.duz = (double(rng() % 2001) - 1000.0) * 1e-4;
      p.vz0 = double(rng() % (sh << 16)) / 65536.0 * p.zi0, p.dvz = (double(rng() % 2001) - 1000.0) * 1e-4;
      p.px0 = double(rng() % 100) + (rng() & 1 ? 0.5 : 0.0);
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = k < 12;
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " n " << n << " k " << k;
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d long spans of every tail length, every variant identical\n", cases);
}

// The long tails' curve factors at the ends of the double range (aarch64: the tail's depth sum
// comes straight from the pass loop's z23 lanes, faddp; the last run's dd is 0 whatever the
// depths where its steps are 0): every length 65 .. 208 with dzi huge (the curve overflows),
// tiny or subnormal (it underflows), infinite or NaN (clamped as the engine clamps them), and
// depths from the 1e-9 clamp (z = 1e9) to ordinary ones, the span's bytes and its guards.
TEST(AsmSpanPersp, LongSpansMatchOnEveryTailLengthWithExtremeCurves) {
  std::mt19937 rng(31);
  const int sw = 64, sh = 64;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  const double inf = std::numeric_limits<double>::infinity();
  const double dzis[] = {1e300, -1e300, std::numeric_limits<double>::max(), 1e-300, -1e-300, 0x1p-1070, -0x1p-1074,
                         1e-310, inf, -inf, std::numeric_limits<double>::quiet_NaN(), 3e-12, -7e-13};
  int cases = 0;
  for (int n = 65; n <= 208; ++n) {
    for (const double dzi : dzis) {
      sb::simd::PerspSpan p{};
      p.zi0 = rng() & 1 ? 1e-12 : 0.002 + 0.01 * double(rng() % 1000) / 1000.0;  // 1e-12: z at the clamp
      p.dzi = dzi;
      p.uz0 = double(rng() % (sw << 16)) / 65536.0 * 0.004, p.duz = (double(rng() % 2001) - 1000.0) * 1e-6;
      p.vz0 = double(rng() % (sh << 16)) / 65536.0 * 0.004, p.dvz = (double(rng() % 2001) - 1000.0) * 1e-6;
      p.px0 = double(rng() % 100) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " n " << n << " dzi " << dzi;
      ++cases;
    }
  }
  std::printf("[ asm      ] span_persp: %d long spans with extreme curves, every variant identical\n", cases);
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

// Four-run second-order spans (49 .. 65 pixels; ARMv7: the mid path, whose prologue asm
// computes run 0's steps16_dd with shifts for the 120 multiplies) on a texture 32767 texels
// wide, as LongSpansMatchOnExtremeSteps: clamped samples swing between 0 and umax (deltas
// near +-2^31, |delta - 120 dd| up to 2^32), the steps accepted and rejected.
TEST(AsmSpanPersp, FourRunSpansMatchOnExtremeSteps) {
  std::mt19937 rng(49);
  const int sw = 32767, sh = 3;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  int cases = 0;
  for (int i = 0; i < 8500; ++i) {
    const sb::simd::PerspSpan p = extreme_step_span(rng, sw, sh, -2);
    const int n = 49 + i % 17;
    ASSERT_TRUE(variants_match(n, surf.data(), sw, sh, p)) << " case " << i << " n " << n;
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d four-run extreme-step spans, every variant identical\n", cases);
}

#if defined(__arm__) && !defined(__aarch64__)
// One surface_span_persp_fast call with d8 .. d15 (callee-saved under the AAPCS) holding
// known values: true if they hold them after the call.
__attribute__((noinline)) bool keeps_d8_d15(uint8_t* dest, int n, const uint8_t* surf, int sw, int sh,
                                            const sb::simd::PerspSpan& p) {
  void (*volatile fn)(uint8_t*, int, const uint8_t*, int, int, const sb::simd::PerspSpan&) =
      sb::simd::surface_span_persp_fast;
  register double r8 __asm__("d8") = 1.25, r9 __asm__("d9") = -2.5, r10 __asm__("d10") = 3.75;
  register double r11 __asm__("d11") = -4.125, r12 __asm__("d12") = 5.0625, r13 __asm__("d13") = -6.5;
  register double r14 __asm__("d14") = 7.75, r15 __asm__("d15") = -8.875;
  __asm__ volatile("" : "+w"(r8), "+w"(r9), "+w"(r10), "+w"(r11), "+w"(r12), "+w"(r13), "+w"(r14), "+w"(r15));
  fn(dest, n, surf, sw, sh, p);
  __asm__ volatile("" : "+w"(r8), "+w"(r9), "+w"(r10), "+w"(r11), "+w"(r12), "+w"(r13), "+w"(r14), "+w"(r15));
  return r8 == 1.25 && r9 == -2.5 && r10 == 3.75 && r11 == -4.125 && r12 == 5.0625 && r13 == -6.5 && r14 == 7.75 &&
         r15 == -8.875;
}
#endif

// ARMv7: the single-span entry draws the mid path's spans (50 .. 64 pixels, second order)
// with no compiler saves of d8 .. d15 (its prologue asm saves the d8 .. d11 it uses itself,
// asm/span_persp_v7mid.h) and tail-calls the other paths: every path keeps the callee-saved
// VFP registers, and draws what the scalar reference draws.
TEST(AsmSpanPersp, SingleEntryKeepsCalleeSavedRegisters) {
#if defined(__arm__) && !defined(__aarch64__)
  std::mt19937 rng(5064);
  const int sw = 300, sh = 200;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<uint8_t> ref(300), got(300);
  for (int i = 0; i < 3000; ++i) {
    sb::simd::PerspSpan p{};
    p.zi0 = std::ldexp(unit(rng) + 1.0, -int(rng() % 16));
    p.dzi = i % 5 == 4 ? 0.0 : p.zi0 * std::ldexp(unit(rng), -int(rng() % 12));
    p.uz0 = unit(rng) * p.zi0 * sw, p.duz = std::ldexp(unit(rng), -int(rng() % 12)) * sw;
    p.vz0 = unit(rng) * p.zi0 * sh, p.dvz = std::ldexp(unit(rng), -int(rng() % 12)) * sh;
    p.px0 = double(rng() % 200) + 0.5;
    p.umax = int32_t((uint32_t(sw) << 16) - 1);
    p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    p.second_order = i % 7 != 6;
    const int n = i % 2 ? 49 + int(rng() % 17) : int(rng() % 260);
    sb::simd::surface_span_persp_scalar(ref.data(), n, surf.data(), sw, sh, p);
    ASSERT_TRUE(keeps_d8_d15(got.data(), n, surf.data(), sw, sh, p)) << " case " << i << " n " << n;
    ASSERT_TRUE(std::equal(ref.begin(), ref.begin() + n, got.begin())) << " case " << i << " n " << n;
  }
#else
  GTEST_SKIP() << "ARMv7 only";
#endif
}

// surface_span_fast (asm/surface_span.h) shares the whole-span drawer's 16-pixel runs; the
// NEON table holds it (asm_kernels_test covers it there), and here it is compared with the
// scalar reference on every target: random walks (linear and second order) that stay
// inside the surface, every length that splits differently into runs of 16 (every partial
// last run, 1 .. 15 pixels: asm/span_persp_run.h's draw_last).
TEST(AsmSpanPersp, SurfaceSpanFastMatchesScalar) {
  std::mt19937 rng(4242);
  const int lengths[] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12,  13,   14,
                         15, 16, 17, 31, 32, 33, 47, 48, 49, 55, 60, 63, 320, 1919, 1920};
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
