// The whole-span drawer (asm/span_persp.h) against the engine's run walker
// (render::draw_surface_spans_by_runs, one surface_span call per 16-pixel run): the same
// pixels and z on random perspective gradients (steep, clamped, edge-on, behind the eye,
// linear and second order), span lengths 0 .. 1920, with the tuned kernels and with the
// scalar references forced; on real faces of LibreQuake maps seen from the maps' own
// viewpoints (skipped without the data); and the kernel's variants on non-finite input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "asm/kernels.h"
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

TEST(AsmSpanPersp, VariantsAgreeOnNonFiniteAndHugeGradients) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double odd[] = {0.0, -0.0, 1e-300, -1e300, 1e300, inf, -inf, nan, 3.5, -2.25e-5};
  std::mt19937 rng(3);
  const int sw = 37, sh = 19;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  std::vector<uint8_t> ref(64 + 200 + 64), got(ref.size());
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
    std::fill(ref.begin(), ref.end(), 0xa5);
    std::fill(got.begin(), got.end(), 0xa5);
    sb::simd::surface_span_persp_scalar(ref.data() + 64, n, surf.data(), sw, sh, p);
    for (int v = 0; v < sb::simd::variant_count(); ++v) {
      const sb::simd::Variant var = sb::simd::variant(v);
      if (!var.kernels || !var.supported) continue;
      std::fill(got.begin(), got.end(), 0xa5);
      var.kernels->surface_span_persp(got.data() + 64, n, surf.data(), sw, sh, p);
      ASSERT_EQ(ref, got) << var.kernels->name << " case " << i;
    }
    ++cases;
  }
  std::printf("[ asm      ] span_persp: %d odd-gradient cases, every variant identical\n", cases);
}

// surface_span_fast (asm/surface_span.h) shares the whole-span drawer's 16-pixel runs; the
// NEON table holds it (asm_kernels_test covers it there), and here it is compared with the
// scalar reference on every target: random walks (linear and second order) that stay
// inside the surface, every length that splits differently into runs of 16.
TEST(AsmSpanPersp, SurfaceSpanFastMatchesScalar) {
  std::mt19937 rng(4242);
  const int lengths[] = {0, 1, 2, 3, 15, 16, 17, 31, 32, 33, 47, 48, 49, 320, 1919, 1920};
  int cases = 0, curved = 0;
  for (int trial = 0; trial < 400; ++trial) {
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
