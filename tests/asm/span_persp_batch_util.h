// tests/asm/span_persp_batch_util.h: what the whole-span drawer's batch tests share
// (tests/asm/span_persp_batch_test.cpp, span_persp_short_batch_test.cpp): span lengths and
// gradients around every path's boundaries and edge cases, and the check of a batch drawn by
// every variant against surface_span_persp_scalar item by item, each dest between guard bytes.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "asm/kernels.h"
#include "asm/span_persp.h"

namespace sb::test_persp {

using sb::simd::PerspItem;
using sb::simd::PerspSpan;

inline constexpr int kGuard = 32;
inline constexpr uint8_t kGuardByte = 0xa5;

// A span length: the kernels' boundaries (one run, the short paths' 17 .. 64, the long
// paths), or random.
inline int pick_length(std::mt19937& rng) {
  static const int kLengths[] = {0,  1,  2,  15, 16, 17, 18, 31, 32, 33, 47, 48, 49, 50, 55, 60,
                                 63, 64, 64, 64, 65, 80, 81, 96, 97, 200, 1920};
  switch (rng() % 4) {
    case 0: return 48 + int(rng() % 17);  // 48 .. 64: the engine's default spans' lengths
    case 1: return 17 + int(rng() % 48);  // the short paths
    case 2: return int(rng() % 300);
    default: return kLengths[rng() % (sizeof kLengths / sizeof kLengths[0])];
  }
}

// A span's gradients: a plane's (1/z falling or rising along the row, u and v across the
// surface), with some of them edge cases: dzi == 0, the reciprocal's divide fallback (a depth
// with a significand of all ones, or >= 2^1000), non-finite or extreme depths and steps.
inline PerspSpan pick_span(std::mt19937& rng, int sw, int sh) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  PerspSpan p{};
  const double depth = 0.002 + 0.05 * (r(rng) + 1.0);
  p.dzi = depth * r(rng) / 640.0;
  p.zi0 = depth + std::fabs(p.dzi) * 640.0;
  const double us = sw * (0.5 + r(rng)), vs = sh * (0.5 + r(rng));
  p.uz0 = us * p.zi0 * (0.5 + 0.5 * r(rng));
  p.duz = us * (p.dzi + r(rng) * depth / 640.0);
  p.vz0 = vs * p.zi0 * (0.5 + 0.5 * r(rng));
  p.dvz = vs * p.dzi * r(rng);
  p.px0 = double(rng() % 600) + 0.5;
  p.umax = int32_t((uint32_t(sw) << 16) - 1);
  p.vmax = int32_t((uint32_t(sh) << 16) - 1);
  p.second_order = rng() % 4 != 0;
  switch (rng() % 12) {
    case 0: p.dzi = 0.0; break;
    case 1: p.zi0 = depth * r(rng); break;  // edge-on or behind: clamped
    case 2: p.dzi *= 40.0; break;           // steep
    case 3: {                               // the reciprocal's divide fallback
      const int k = int(rng() % 60) - 29;
      p.zi0 = rng() % 8 ? std::ldexp(2.0 - 0x1p-52, k) : std::ldexp(1.5, 1000 + int(rng() % 20));
      p.dzi = rng() & 1 ? 0.0 : std::ldexp(1.0, k - 80);
      p.uz0 = std::ldexp(std::nextafter(double(1 + rng() % 30) * 65536.0, 0.0), k + 1 - 16);
      p.vz0 = std::ldexp(double(rng() % 1000), k);
      p.duz = p.dvz = 0.0;
      break;
    }
    case 4: {  // non-finite, huge or tiny values somewhere
      const double odd[] = {0.0, -0.0, 1e-300, -1e300, 1e300, inf, -inf, nan, 0x1p-1030, 0x1p1020};
      const double x = odd[rng() % 10];
      switch (rng() % 4) {
        case 0: p.zi0 = x; break;
        case 1: p.dzi = x; break;
        case 2: p.uz0 = x; break;
        default: p.dvz = x; break;
      }
      break;
    }
    default: break;
  }
  return p;
}

// Draws the batch with every supported variant's surface_spans_persp into a buffer holding
// each item's dest between guard bytes, and with surface_span_persp_scalar item by item into
// another: a failure naming the variant and item unless the buffers are the same.
inline ::testing::AssertionResult batch_matches(std::vector<PerspItem> items, const uint8_t* surf, int sw, int sh) {
  size_t size = kGuard;
  std::vector<size_t> offsets;
  for (const PerspItem& it : items) {
    offsets.push_back(size);
    size += size_t(std::max(it.n, 0)) + kGuard;
  }
  std::vector<uint8_t> ref(size, kGuardByte), got(size);
  for (size_t i = 0; i < items.size(); ++i)
    sb::simd::surface_span_persp_scalar(ref.data() + offsets[i], items[i].n, surf, sw, sh, items[i].span);
  for (int v = 0; v < sb::simd::variant_count(); ++v) {
    const sb::simd::Variant var = sb::simd::variant(v);
    if (!var.kernels || !var.supported) continue;
    std::fill(got.begin(), got.end(), kGuardByte);
    for (size_t i = 0; i < items.size(); ++i) items[i].dest = got.data() + offsets[i];
    var.kernels->surface_spans_persp(items.data(), int(items.size()), surf, sw, sh);
    const auto d = std::mismatch(ref.begin(), ref.end(), got.begin());
    if (d.first != ref.end()) {
      const size_t at = size_t(d.first - ref.begin());
      const size_t item = size_t(std::upper_bound(offsets.begin(), offsets.end(), at) - offsets.begin());
      auto r = ::testing::AssertionFailure() << var.kernels->name << " wrote " << int(*d.second) << " for "
                                             << int(*d.first) << " at buffer byte " << at << " of a batch of "
                                             << items.size();
      if (item > 0) r << ", item " << item - 1 << " (n " << items[item - 1].n << ", byte " << at - offsets[item - 1] << ")";
      return r;
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace sb::test_persp
