// Second-order spans of 65 .. 80 pixels (aarch64: persp_long_a64 with no full pass, the set-up
// entering its loop at the last pass, then the 33 .. 48-pixel tail; elsewhere the portable
// paths) against surface_span_persp_scalar, every length on its own: single calls and
// batches (runs of them in persp_long_a64's loop, after and before other spans), on gentle
// and extreme gradients, u and v clamped at both ends, curves whose quadratic steps the
// monotone test rejects, the reciprocal's divide fallback and non-finite input; every span
// between guard bytes (no byte before or after it written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "asm/kernels.h"
#include "asm/span_persp.h"
#include "tests/asm/span_persp_batch_util.h"

namespace {

using sb::simd::PerspItem;
using sb::simd::PerspSpan;

constexpr int kGuard = 48;
constexpr uint8_t kGuardByte = 0xa5;
constexpr int kMinN = 65, kMaxN = 80;

// A second-order span of class `kind` (0 .. 7) on a sw x sh surface.
PerspSpan one_pass_span(std::mt19937& rng, int kind, int sw, int sh) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  auto logu = [&](double lo, double hi) {  // +-10^[lo, hi], log-uniform
    const double e = lo + (hi - lo) * double(rng() % 100000) / 100000.0;
    return (rng() & 1 ? 1.0 : -1.0) * std::pow(10.0, e);
  };
  PerspSpan p{};
  p.umax = int32_t((uint32_t(sw) << 16) - 1);
  p.vmax = int32_t((uint32_t(sh) << 16) - 1);
  p.px0 = double(rng() % 600) + (rng() & 1 ? 0.5 : 0.0);
  p.second_order = true;
  const double depth = 0.002 + 0.05 * (r(rng) + 1.0);
  p.zi0 = depth;
  p.dzi = depth * r(rng) / 160.0;
  if (p.dzi == 0.0) p.dzi = 1e-7;
  p.uz0 = sw * 0.5 * p.zi0 * (1.0 + 0.5 * r(rng)), p.duz = sw * p.dzi * r(rng);
  p.vz0 = sh * 0.5 * p.zi0 * (1.0 + 0.5 * r(rng)), p.dvz = sh * p.dzi * r(rng);
  switch (kind) {
    case 0: break;  // gentle
    case 1:  // steep depth: strong curves (dd accepted or rejected by its range)
      p.dzi = p.zi0 * (r(rng) > 0 ? 1.0 : -1.0) * double(1 + rng() % 1000) * 4e-4;
      p.duz = (double(rng() % 2001) - 1000.0) * 1e-3 * sw * p.zi0;
      p.dvz = (double(rng() % 2001) - 1000.0) * 1e-3 * sh * p.zi0;
      break;
    case 2:  // u and v past their clamps (negative or beyond the surface) along the span
      p.uz0 = sw * p.zi0 * (r(rng) > 0 ? 1.6 : -0.6), p.duz = -p.uz0 / 40.0 + sw * p.dzi * r(rng);
      p.vz0 = sh * p.zi0 * (r(rng) > 0 ? 1.6 : -0.6), p.dvz = -p.vz0 / 50.0;
      break;
    case 3: {  // nearly constant u, v under a sharp curve: small deltas, large dd (monotone test rejects)
      p.dzi = p.zi0 * (r(rng) > 0 ? 1.0 : -1.0) * (0.002 + 0.01 * (r(rng) + 1.0));
      const double u = sw * (0.5 + 0.4 * r(rng)), v = sh * (0.5 + 0.4 * r(rng));
      const double eu = std::ldexp(r(rng), -int(rng() % 12)), ev = std::ldexp(r(rng), -int(rng() % 12));
      p.uz0 = u * p.zi0, p.duz = u * p.dzi * (1.0 + eu);
      p.vz0 = v * p.zi0, p.dvz = v * p.dzi * (1.0 + ev);
      break;
    }
    case 4:  // extreme steps (wide surfaces: deltas and dd near their limits)
      p.zi0 = std::fabs(logu(-4, 0));
      p.dzi = logu(-7, -2);
      p.uz0 = logu(2, 9) * p.zi0, p.duz = logu(0, 8) * std::fabs(p.dzi) * (rng() % 4 ? 1.0 : 1e3);
      p.vz0 = std::fabs(logu(-2, 1)) * p.zi0, p.dvz = logu(-3, 1) * std::fabs(p.dzi);
      break;
    case 5: {  // depths the reciprocal cannot give (its divide fallback), huge depths
      const int k = int(rng() % 60) - 29;
      p.zi0 = rng() % 8 ? std::ldexp(2.0 - 0x1p-52, k) : std::ldexp(1.5, 1000 + int(rng() % 20));
      p.dzi = std::ldexp(rng() & 1 ? 1.0 : -1.0, k - 80);
      p.uz0 = std::ldexp(std::nextafter(double(1 + rng() % 30) * 65536.0, 0.0), k + 1 - 16);
      p.vz0 = std::ldexp(double(rng() % 1000), k);
      p.duz = p.dvz = 0.0;
      break;
    }
    case 6: {  // non-finite, huge or tiny values somewhere (dzi stays non-zero: this path)
      const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
      const double odd[] = {-0.0, 1e-300, -1e300, 1e300, inf, -inf, nan, 0x1p-1030, 0x1p1020};
      const double x = odd[rng() % 9];
      switch (rng() % 5) {
        case 0: p.zi0 = x; break;
        case 1: p.dzi = x == 0.0 ? 1e-300 : x; break;
        case 2: p.uz0 = x; break;
        case 3: p.duz = x; break;
        default: p.dvz = x; break;
      }
      break;
    }
    default:  // edge-on or behind the eye: 1/z clamped over part of the span
      p.zi0 = depth * r(rng), p.dzi = -p.zi0 / double(20 + rng() % 80);
      if (p.dzi == 0.0) p.dzi = 1e-6;
      break;
  }
  return p;
}

// Single calls: each variant's surface_span_persp against the reference, guard bytes on
// both sides.
::testing::AssertionResult single_matches(int n, const uint8_t* surf, int sw, int sh, const PerspSpan& p) {
  std::vector<uint8_t> ref(size_t(n) + 2 * kGuard, kGuardByte), got(ref.size());
  sb::simd::surface_span_persp_scalar(ref.data() + kGuard, n, surf, sw, sh, p);
  for (int v = 0; v < sb::simd::variant_count(); ++v) {
    const sb::simd::Variant var = sb::simd::variant(v);
    if (!var.kernels || !var.supported) continue;
    std::fill(got.begin(), got.end(), kGuardByte);
    var.kernels->surface_span_persp(got.data() + kGuard, n, surf, sw, sh, p);
    const auto d = std::mismatch(ref.begin(), ref.end(), got.begin());
    if (d.first != ref.end()) {
      return ::testing::AssertionFailure() << var.kernels->name << " wrote " << int(*d.second) << " for "
                                           << int(*d.first) << " at byte " << (d.first - ref.begin()) - kGuard
                                           << " of a span of " << n;
    }
  }
  return ::testing::AssertionSuccess();
}

std::vector<uint8_t> make_surface(std::mt19937& rng, int sw, int sh) {
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  return surf;
}

TEST(AsmSpanPerspOnePass, EveryLengthMatchesInSingleCalls) {
  std::mt19937 rng(7265);
  const int dims[][2] = {{64, 64}, {37, 19}, {256, 3}, {32767, 2}};
  int cases = 0;
  for (const auto& dim : dims) {
    const int sw = dim[0], sh = dim[1];
    const std::vector<uint8_t> surf = make_surface(rng, sw, sh);
    for (int n = kMinN; n <= kMaxN; ++n) {
      for (int kind = 0; kind < 8; ++kind) {
        for (int k = 0; k < 12; ++k) {
          const PerspSpan p = one_pass_span(rng, kind, sw, sh);
          ASSERT_TRUE(single_matches(n, surf.data(), sw, sh, p)) << " n " << n << " kind " << kind << " sw " << sw;
          ++cases;
        }
      }
    }
  }
  std::printf("[ asm      ] span_persp: %d one-pass spans (65 .. 80 px), every variant identical\n", cases);
}

// Runs of such spans (aarch64: persp_long_a64's loop, long_next_a64's test at 64), every
// length first and in the run, with a span of another kind or length (1 .. 64, 81 .. 200,
// linear, dzi == 0) before, between or after them.
TEST(AsmSpanPerspOnePass, EveryLengthMatchesInBatches) {
  std::mt19937 rng(8072);
  long spans = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const int sw = trial == 3 ? 32767 : 64 + 61 * trial, sh = trial == 3 ? 2 : 23 + 20 * trial;
    const std::vector<uint8_t> surf = make_surface(rng, sw, sh);
    for (int n = kMinN; n <= kMaxN; ++n) {
      for (int shape = 0; shape < 6; ++shape) {
        std::vector<PerspItem> items;
        auto other = [&] {  // another kind or length
          PerspSpan q = one_pass_span(rng, int(rng() % 8), sw, sh);
          int m = int(rng() % 65);
          switch (rng() % 4) {
            case 0: m = 81 + int(rng() % 120); break;
            case 1: q.second_order = false, m = int(rng() % 200); break;
            case 2: q.dzi = 0.0, m = int(rng() % 200); break;
            default: break;
          }
          items.push_back(PerspItem{nullptr, m, q});
        };
        if (shape & 1) other();
        const int count = 1 + int(rng() % 6);
        for (int i = 0; i < count; ++i) {
          const int m = i == 0 ? n : kMinN + int(rng() % (kMaxN - kMinN + 1));
          items.push_back(PerspItem{nullptr, m, one_pass_span(rng, int(rng() % 8), sw, sh)});
          if (shape == 4 && i + 1 < count) other();  // broken runs
        }
        if (shape & 2) other();
        ASSERT_TRUE(sb::test_persp::batch_matches(items, surf.data(), sw, sh)) << " n " << n << " shape " << shape << " sw " << sw;
        spans += long(items.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans around runs of one-pass spans, every variant identical\n",
              spans);
}

}  // namespace
