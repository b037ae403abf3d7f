// The whole-span drawer's batch entry on runs of short second-order spans (1 .. 48 pixels,
// dzi != 0): the paths each target draws them with (aarch64: the tiny pair loop,
// asm/span_persp_a64tiny.cpp; ARMv7: persp_one_v7 and persp_mid_run_v7,
// asm/span_persp_fast_v7one.inc; x86-64: short_run_x86, asm/span_persp_x86short.h), reached at
// a batch's start and mid-batch, against surface_span_persp_scalar item by item
// (tests/asm/span_persp_batch_util.h). Split from span_persp_batch_test.cpp.
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
using namespace sb::test_persp;

// Runs of one-run second-order spans (ARMv7: persp_one_v7 draws 1 .. 16 pixel spans with
// dzi != 0 two at a time, the set-ups of a pair interleaved; the last of an odd run alone), of
// 17 .. 48 pixel ones (persp_mid_run_v7: two or three runs, one asm set-up) and of both mixed
// (the paths go from one to the other), every length in every position of a pair: runs of
// 0 .. 9 spans of a plane's rows or of pick_span's edge gradients (clamped u / v, steep,
// behind the eye, non-finite or huge values, the divide fallback), at the batch's start or
// after another span, ended by a span neither path takes (n 0, 49 .. 80, linear, dzi +-0) or
// one of the other kind, or by the batch's end; each span between guard bytes.
TEST(AsmSpanPerspBatch, RunsOfOneRunSecondOrderSpansMatch) {
  std::mt19937 rng(5150);
  const int sw = 47, sh = 27;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 29 + (i >> 3));
  long spans = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int kind = trial % 4;  // 0, 1: 1 .. 16 pixels; 2: 17 .. 48; 3: either, item by item
    const PerspSpan plane = pick_span(rng, sw, sh);
    auto curve = [&](int i) {
      PerspSpan p = rng() % 3 ? plane : pick_span(rng, sw, sh);
      if (rng() % 2) p.zi0 += double(rng() % 50) * 1e-5, p.uz0 += double(rng() % 50) * 0.01;
      if (rng() % 8 == 0) p.uz0 *= 3.0, p.vz0 *= -2.0;  // clamped at umax / 0
      p.second_order = true;
      if (p.dzi == 0.0) p.dzi = rng() % 2 ? 1e-7 : -3e-6;
      p.px0 = double(rng() % 600) + 0.5;
      // Every length at either place of a pair over the trials (i: the place in the run).
      const bool one = kind < 2 || (kind == 3 && rng() % 2);
      const int n = one ? 1 + int((trial / 4 + i * 7) % 16) : 17 + int(rng() % 32);
      return PerspItem{nullptr, n, p};
    };
    std::vector<PerspItem> items;
    const int runs = 1 + int(rng() % 3);
    for (int r = 0; r < runs; ++r) {
      const int len = int(rng() % 10);
      for (int i = 0; i < len; ++i) items.push_back(curve(i));
      if (r == runs - 1 && rng() % 2) break;  // the batch ends in the run
      PerspItem x = curve(0);
      switch (rng() % 6) {
        case 0: x.n = 0; break;
        case 1: x.n = 17 + int(rng() % 32); break;
        case 2: x.n = 49 + int(rng() % 32); break;
        case 3: x.span.second_order = false; break;
        case 4: x.span.dzi = rng() % 2 ? 0.0 : -0.0; break;
        default: break;
      }
      items.push_back(x);
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += long(items.size());
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of one-run spans, every variant identical\n", spans);
}

// Second-order spans of 17 .. 48 pixels reached mid-batch (ARMv7: the batch loop sends them to
// persp_mid_run_v7 after any other item, not only after one-run spans): every n 17 .. 48 right
// after each kind of item the loop draws itself or hands to another path (linear 17 .. 64 and
// long, dzi +-0, second order 49, 50 .. 64, 65 .. 80 and long, n 0), with pick_span's edge
// gradients (clamped, divide fallback, non-finite), followed by nothing (the batch's end), a
// one-run span, another 17 .. 48 pixel span or a linear one; every variant's bytes the
// reference's, bytes after each span untouched (batch_matches' guards).
TEST(AsmSpanPerspBatch, MidBatchSecondOrderSpansOf17To48Match) {
  std::mt19937 rng(4848);
  const int sw = 61, sh = 23;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 37 + (i >> 2));
  auto curve = [&](int n) {
    PerspSpan p = pick_span(rng, sw, sh);
    p.second_order = true;
    if (p.dzi == 0.0) p.dzi = rng() % 2 ? 2e-7 : -4e-6;
    return PerspItem{nullptr, n, p};
  };
  long spans = 0;
  for (int before = 0; before < 10; ++before) {
    for (int n = 17; n <= 48; ++n) {
      for (int k = 0; k < 12; ++k) {
        std::vector<PerspItem> items;
        if (k % 3 == 0) items.push_back(curve(1 + int(rng() % 16)));  // a one-run span first
        PerspItem x = curve(0);
        switch (before) {
          case 0: x.span.second_order = false, x.n = 17 + int(rng() % 48); break;
          case 1: x.span.second_order = false, x.n = 65 + int(rng() % 200); break;
          case 2: x.span.dzi = rng() % 2 ? 0.0 : -0.0, x.n = 17 + int(rng() % 100); break;
          case 3: x.n = 49; break;
          case 4: x.n = 50 + int(rng() % 15); break;
          case 5: x.n = 65 + int(rng() % 16); break;
          case 6: x.n = 81 + int(rng() % 300); break;
          case 7: x.n = 0; break;
          case 8: x.span.second_order = false, x.n = 1 + int(rng() % 16); break;
          default: x.n = 17 + int(rng() % 32); break;  // after a 17 .. 48 pixel span
        }
        items.push_back(x);
        items.push_back(curve(n));
        switch (k % 4) {
          case 0: break;
          case 1: items.push_back(curve(1 + int(rng() % 16))); break;
          case 2: items.push_back(curve(17 + int(rng() % 32))); break;
          default: {
            PerspItem l = curve(17 + int(rng() % 48));
            l.span.second_order = false;
            items.push_back(l);
            break;
          }
        }
        ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " before " << before << " n " << n << " k " << k;
        spans += long(items.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans around mid-batch 17-48 px ones, every variant identical\n", spans);
}

// Short second-order spans in runs (x86-64: second order with dzi != 0 and 1 .. 48 pixels
// drawn inline in the batch loop, asm/span_persp_x86short.h; one, two and three runs, last
// runs of 1 .. 16 pixels): every n 1 .. 48 in runs of 1 .. 11 such spans, mixed with longer,
// linear, dzi +-0 and empty items, with extreme gradients (steep or tiny dzi: second-order
// steps rejected or 0; huge u, v: the clamps at max; negative: at 0; huge, tiny or non-finite
// dzi, with u, v clamped (no change along the span) or not; non-finite values and the divide
// fallback from pick_span), each span between guard bytes (the bytes after it untouched).
TEST(AsmSpanPerspBatch, RunsOfShortSecondOrderSpansMatch) {
  std::mt19937 rng(4816);
  long spans = 0;
  for (int trial = 0; trial < 2400; ++trial) {
    const int sw = 1 + int(rng() % 90), sh = 1 + int(rng() % 70);
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    std::vector<PerspItem> items;
    const int count = 1 + int(rng() % 11);
    for (int i = 0; i < count; ++i) {
      PerspSpan p = pick_span(rng, sw, sh);
      int n = 1 + (trial * 11 + i) % 48;  // every length, in every position of a run
      if (rng() % 6 == 0) {  // another kind between the short ones
        switch (rng() % 5) {
          case 0: n = 49 + int(rng() % 200); break;
          case 1: p.second_order = false; break;
          case 2: p.dzi = rng() % 2 ? 0.0 : -0.0; break;
          case 3: n = 0; break;
          default: n = pick_length(rng); break;
        }
      } else {
        p.second_order = true;
        if (p.dzi == 0.0) p.dzi = rng() % 2 ? 1e-7 : -1e-7;
        switch (rng() % 9) {
          case 0: p.dzi *= 1e4; break;                    // steep: large dd, often rejected
          case 1: p.dzi = std::ldexp(1.0, -1000); break;  // tiny: curve underflows to 0 or near
          case 2: p.uz0 *= 1e3, p.duz *= 1e3; break;      // u past umax (clamped)
          case 3: p.vz0 = -std::fabs(p.vz0) * 4.0; break;  // v below 0 (clamped)
          case 4: p.duz = -p.duz * 300.0, p.dvz = p.dvz * 300.0; break;  // across the clamps
          case 5: {  // extreme or non-finite curve, with u, v clamped (delta 0) or not
            const double odd[] = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                                  std::numeric_limits<double>::quiet_NaN(), 1e300, -1e300, 0x1p1020, 1e-300,
                                  0x1p-1030};
            p.dzi = odd[rng() % 8];
            if (rng() % 2) p.uz0 = p.vz0 = 1e30, p.duz = p.dvz = 0.0;
            break;
          }
          default: break;
        }
      }
      items.push_back(PerspItem{nullptr, n, p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of short second-order ones, every variant identical\n",
              spans);
}

// Short second-order spans on surfaces up to the contract's widest (32767 texels), with
// steep depths and u sweeping across the surface within a few pixels: the last run's
// deltas reach 2^31 - 2^16 and second-order steps of 1e9 or more, where the walker's range
// test -1e9 < ddf < 1e9 decides (a narrower surface rejects such steps by the monotone test
// anyway); every length 1 .. 48 (last runs of 3 pixels: steps 2, the only ones where it
// decides), each span between guard bytes.
TEST(AsmSpanPerspBatch, ShortSecondOrderSpansOnWideSurfacesMatch) {
  std::mt19937 rng(6502);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  long spans = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int sw = 32767 - int(rng() % 2000), sh = 1 + int(rng() % 3);
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    std::vector<PerspItem> items;
    const int count = 1 + int(rng() % 8);
    for (int i = 0; i < count; ++i) {
      PerspSpan p{};
      p.zi0 = std::ldexp(1.0, -int(rng() % 20));
      p.dzi = p.zi0 * r(rng) * (rng() % 2 ? 0.5 : 0.02);
      if (p.dzi == 0.0) p.dzi = 1e-9;
      p.uz0 = p.zi0 * sw * (0.5 + 0.5 * r(rng));
      p.duz = p.zi0 * sw * r(rng) * (rng() % 2 ? 1.0 : 0.3);
      p.vz0 = p.zi0 * sh * 0.5, p.dvz = p.dzi * sh * r(rng);
      p.px0 = double(rng() % 64) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1), p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      int n = rng() % 3 ? 3 + 16 * int(rng() % 3) : 1 + int(rng() % 48);
      if (rng() % 2) {
        // The last run's 3 pixels at x = 0.5, 1.5, 2.5 (px0 = 0.5 - (n - 3)): 1/z from 1.75
        // to 4.75 (dzi 1.5: curve about 0.59), u from about 760 to 32000 texels (ddf about
        // -1.2e9) or from about 29000 to 3700 (ddf about +1e9), within the monotone test's
        // reach (|dd| <= |delta|); scaled by up to 10% around the range test's bound.
        n = 3 + 16 * int(rng() % 3);
        const double k = 1.0 + 0.1 * r(rng), ku = sw / 32767.0 * (1.0 + 0.02 * r(rng));
        p.zi0 = 1.0, p.dzi = 1.5 * k, p.px0 = 0.5 - double(n - 3);
        p.uz0 = -36330.0 * ku, p.duz = 75332.0 * ku;
        if (rng() % 2) p.uz0 = 60000.0 * ku, p.duz = -17000.0 * ku;
        p.vz0 = 0.5, p.dvz = 0.0;
      }
      items.push_back(PerspItem{nullptr, n, p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld short spans on wide surfaces, every variant identical\n", spans);
}

// Second-order spans of 1 .. 16 pixels side by side (aarch64: tiny_curve_run,
// asm/span_persp_a64tiny.h, two at a time in 2-lane vectors, a lone one paired with itself):
// every length 1 .. 16 as span a and as span b of a pair, each pair alone, after a linear or
// long span, and followed by a third such span (odd counts: the lone one); the spans'
// gradients pick_span's (edge depths, the reciprocal's divide fallback in either span,
// non-finite values, steep), second order with dzi != 0.
TEST(AsmSpanPerspBatch, TinySecondOrderPairsMatchForEveryLengthPair) {
  std::mt19937 rng(1616);
  const int sw = 53, sh = 31;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 29 + 3);
  auto tiny = [&](int n) {
    PerspSpan p = pick_span(rng, sw, sh);
    p.second_order = true;
    if (p.dzi == 0.0) p.dzi = rng() % 2 ? 1e-7 : -3e-6;
    return PerspItem{nullptr, n, p};
  };
  long spans = 0;
  for (int na = 1; na <= 16; ++na) {
    for (int nb = 1; nb <= 16; ++nb) {
      for (int k = 0; k < 12; ++k) {
        std::vector<PerspItem> items;
        if (k % 4 == 1) {  // after another kind of span
          PerspItem x = tiny(k % 8 == 1 ? 40 : 5);
          x.span.second_order = k % 8 == 1;
          items.push_back(x);
        }
        items.push_back(tiny(na));
        items.push_back(tiny(nb));
        if (k % 3 == 2) items.push_back(tiny(1 + int(rng() % 16)));  // a lone third one
        if (k % 6 == 5) items.push_back(tiny(17 + int(rng() % 100)));
        ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " na " << na << " nb " << nb << " k " << k;
        spans += long(items.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans around pairs of 1 .. 16 px, every variant identical\n", spans);
}

// Runs of 1 .. 16 pixel spans of one plane's rows (the engine's surface edges) broken by
// spans of other kinds (linear, dzi +-0 or NaN, n 0 or 17 or long), u and v clamped at either
// end of the surface (the plane's texture coordinates past it), extreme dzi and depths.
TEST(AsmSpanPerspBatch, RunsOfTinySecondOrderSpansMatch) {
  std::mt19937 rng(8128);
  long spans = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int sw = 1 + int(rng() % 90), sh = 1 + int(rng() % 70);
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    PerspSpan plane = pick_span(rng, sw, sh);
    plane.second_order = true;
    if (plane.dzi == 0.0) plane.dzi = 2e-6;
    switch (trial % 6) {
      case 0: plane.uz0 *= 40.0, plane.vz0 = -plane.vz0 * 30.0; break;  // clamped: u at umax, v at 0
      case 1: plane.duz *= 1e4, plane.dvz *= -1e4; break;              // u, v crossing both clamps
      case 2: plane.dzi *= 300.0; break;                                // steep (zi clamped along it)
      default: break;
    }
    std::vector<PerspItem> items;
    const int count = 1 + int(rng() % 24);
    for (int i = 0; i < count; ++i) {
      PerspSpan p = plane;
      const double dy = double(rng() % 40);
      p.zi0 += dy * 1e-5, p.uz0 += dy * 0.5, p.vz0 -= dy * 0.7;
      p.px0 = double(rng() % 640) + 0.5;
      int n = 1 + int(rng() % 16);
      switch (rng() % 12) {
        case 0: p.second_order = false; break;
        case 1: p.dzi = rng() % 2 ? 0.0 : -0.0; break;
        case 2: p.dzi = std::numeric_limits<double>::quiet_NaN(); break;  // dzi != 0: the tiny path
        case 3: n = rng() % 2 ? 0 : 17; break;
        case 4: n = pick_length(rng); break;
        case 5: p = pick_span(rng, sw, sh), p.second_order = true; break;
        default: break;
      }
      items.push_back(PerspItem{nullptr, n, p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of 1 .. 16 px, every variant identical\n", spans);
}

// The tiny pair block (aarch64: asm/span_persp_a64tiny_pair.h) loads the samples of the two
// items after a pair speculatively, before its tests: runs of 1 .. 5 spans of 1 .. 16 pixels
// followed by one or two items of every other kind, some with fields that would take the
// divide fallback or give non-finite samples (2^1010, +-inf, NaN depths, n 0, 17 .. 80, linear,
// dzi +-0), or by the batch's end; each run's last pair then samples those items (or a), and
// their bytes must stay untouched / the scalar's.
TEST(AsmSpanPerspBatch, TinyRunsBeforeItemsOfEveryKindMatch) {
  std::mt19937 rng(4242);
  const int sw = 41, sh = 23;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 7 + 1);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  auto tiny = [&]() {
    PerspSpan p = pick_span(rng, sw, sh);
    p.second_order = true;
    if (p.dzi == 0.0) p.dzi = 1e-6;
    return PerspItem{nullptr, 1 + int(rng() % 16), p};
  };
  auto other = [&](int kind) {
    PerspItem x = tiny();
    switch (kind) {
      case 0: x.n = 0; break;
      case 1: x.n = 17 + int(rng() % 64); break;
      case 2: x.span.second_order = false; break;
      case 3: x.span.dzi = rng() % 2 ? 0.0 : -0.0; break;
      case 4: x.n = 17 + int(rng() % 30), x.span.zi0 = std::ldexp(1.0, 1010); break;
      case 5: x.span.second_order = false, x.span.zi0 = rng() % 2 ? inf : -inf; break;
      case 6: x.n = 0, x.span.zi0 = nan, x.span.uz0 = nan, x.span.px0 = inf; break;
      case 7: x.n = 17 + int(rng() % 8), x.span.zi0 = std::ldexp(2.0 - 0x1p-52, -7); break;  // all-ones significand
      default: break;
    }
    return x;
  };
  long spans = 0;
  for (int run = 1; run <= 5; ++run) {
    for (int k1 = -1; k1 < 8; ++k1) {
      for (int k2 = -1; k2 < 8; ++k2) {
        for (int rep = 0; rep < 6; ++rep) {
          std::vector<PerspItem> items;
          for (int i = 0; i < run; ++i) items.push_back(tiny());
          if (k1 >= 0) items.push_back(other(k1));
          if (k1 >= 0 && k2 >= 0) items.push_back(rep % 2 ? other(k2) : tiny());
          if (k1 >= 0 && k2 >= 0 && rep % 3 == 2) items.push_back(tiny());
          ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " run " << run << " k1 " << k1 << " k2 " << k2;
          spans += long(items.size());
        }
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans, tiny runs before items of every kind, every variant identical\n",
              spans);
}

}  // namespace

// The tiny spans' draws (aarch64: draw_tiny's asm chunks of 8 and 4 pixels and its one-block
// tails of n & 7 = 1 .. 7 pixels, asm/span_persp_a64tinydraw.h): every n 1 .. 16 as span a, as
// span b and as a lone span (an odd run's last; mid-batch after a linear one: tiny_one_a64),
// on narrow, wide (v w past 2^24) and tall surfaces, with curved steps (large dzi: second
// differences accepted, of both signs), u and v clamped at 0 or the maximum along the span,
// steep and pick_span's edge gradients; bytes after each span untouched (batch_matches).
TEST(AsmSpanPerspBatch, TinySpanDrawsMatchForEveryLength) {
  std::mt19937 rng(1707);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const int dims[][2] = {{1, 1}, {3, 5}, {64, 64}, {32767, 3}, {4099, 311}};
  long spans = 0;
  for (const auto& dm : dims) {
    const int sw = dm[0], sh = dm[1];
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    auto tiny = [&](int n, int kind) {
      PerspSpan p = pick_span(rng, sw, sh);
      p.second_order = true;
      switch (kind % 5) {
        case 0: {  // curved: 1/z from zi0 rising or falling fast over the span
          p.zi0 = 0.01 + 0.2 * (r(rng) + 1.0);
          p.dzi = p.zi0 * 0.08 * r(rng);
          p.uz0 = p.zi0 * sw * (0.5 + 0.5 * r(rng)), p.duz = p.dzi * sw * 4.0 * r(rng);
          p.vz0 = p.zi0 * sh * (0.5 + 0.5 * r(rng)), p.dvz = p.dzi * sh * 4.0 * r(rng);
          p.px0 = double(rng() % 8) + 0.5;
          break;
        }
        case 1: p.uz0 *= 5.0, p.vz0 = -p.vz0; break;       // clamped: u at umax, v at 0
        case 2: p.duz *= 300.0, p.dvz *= -300.0; break;   // crossing both clamps within the span
        case 3: p.dzi *= 50.0; break;                     // steep
        default: break;                                   // pick_span's
      }
      if (p.dzi == 0.0) p.dzi = rng() % 2 ? 1e-7 : -3e-6;
      return PerspItem{nullptr, n, p};
    };
    for (int n = 1; n <= 16; ++n) {
      for (int k = 0; k < 40; ++k) {
        const int other = 1 + int(rng() % 16);
        std::vector<PerspItem> items;
        switch (k % 4) {
          case 0: items = {tiny(n, k / 4), tiny(other, k / 4 + 1)}; break;  // n as span a
          case 1: items = {tiny(other, k / 4), tiny(n, k / 4 + 1)}; break;  // n as span b
          case 2: items = {tiny(other, k / 4), tiny(other, k / 4), tiny(n, k / 4 + 2)}; break;  // lone, last
          default: {  // lone mid-batch, after a linear span
            PerspItem x = tiny(20 + int(rng() % 40), 4);
            x.span.second_order = false;
            items = {x, tiny(n, k / 4)};
            break;
          }
        }
        ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " w " << sw << " n " << n << " k " << k;
        spans += long(items.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans, tiny draws of every length, every variant identical\n", spans);
}

// Batches starting with pairs of second-order spans of 17 .. 48 pixels (aarch64: pairs48_a64,
// asm/span_persp_a64pair48.h, taken at a batch's start when four such lengths come first; the
// samples block without sample 4): every length 17 .. 48 as span a and as span b of the first
// pair (every last-run length of two- and three-run spans in either place), then a second
// pair of such lengths, then what ends the chain or goes on: a third pair, a 49 .. 64 px span
// (the four-run pairs' loop), a 1 .. 16 px one, a linear one, dzi +-0, n 0, or the batch's end;
// the gradients pick_span's (clamped u / v, steep, behind the eye, non-finite or huge values,
// the reciprocal's divide fallback in either span) with u or v pushed past the surface's edges
// in some, second order with dzi != 0 in the pairs; each span between guard bytes.
TEST(AsmSpanPerspBatch, PairsOf17To48PxSpansAtABatchStartMatchForEveryLengthPair) {
  std::mt19937 rng(4848);
  const int sw = 61, sh = 37;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 37 + 11);
  auto span = [&](int n) {
    PerspSpan p = pick_span(rng, sw, sh);
    p.second_order = true;
    if (p.dzi == 0.0) p.dzi = rng() % 2 ? 2e-7 : -5e-6;
    switch (rng() % 8) {
      case 0: p.uz0 *= 1e3, p.duz *= 1e3; break;                      // u past umax
      case 1: p.vz0 = -std::fabs(p.vz0) * 4.0; break;                 // v below 0
      case 2: p.duz = -p.duz * 300.0, p.dvz = p.dvz * 300.0; break;   // across the clamps
      case 3: p.dzi *= 1e4; break;                                    // steep
      default: break;
    }
    return PerspItem{nullptr, n, p};
  };
  auto mid = [&]() { return 17 + int(rng() % 32); };
  long spans = 0;
  for (int na = 17; na <= 48; ++na) {
    for (int nb = 17; nb <= 48; ++nb) {
      for (int k = 0; k < 3; ++k) {
        std::vector<PerspItem> items;
        items.push_back(span(na));
        items.push_back(span(nb));
        items.push_back(span(mid()));
        items.push_back(span(mid()));
        switch ((na + nb + k) % 8) {
          case 0: items.push_back(span(mid())), items.push_back(span(mid())); break;  // a third pair
          case 1: {  // a 49 .. 64 px span as a or b of the next pair
            const bool first = rng() % 2;
            items.push_back(span(first ? 49 + int(rng() % 16) : mid()));
            items.push_back(span(first ? mid() : 49 + int(rng() % 16)));
            break;
          }
          case 2: items.push_back(span(1 + int(rng() % 16))); break;
          case 3: {  // linear, or dzi +-0
            PerspItem x = span(mid());
            if (rng() % 2) {
              x.span.second_order = false;
            } else {
              x.span.dzi = rng() % 2 ? 0.0 : -0.0;
            }
            items.push_back(x), items.push_back(span(mid()));
            break;
          }
          case 4: items.push_back(span(0)), items.push_back(span(mid())); break;
          case 5: items.push_back(span(mid())); break;  // a lone one after the pairs
          default: break;  // the batch's end
        }
        ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " na " << na << " nb " << nb << " k " << k;
        spans += long(items.size());
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans from pairs of 17 .. 48 px, every variant identical\n", spans);
}

// Pairs of second-order spans of 17 .. 48 pixels (aarch64: steps_k1v_pass / steps_k2v_pass,
// asm/span_persp_a64few.h, from pairs48_a64 at a batch's start and from spans_range after a
// 1 .. 16 px span) on wide surfaces: ShortSecondOrderSpansOnWideSurfacesMatch's gradients, where
// the last run's range test -1e9 < ddf < 1e9 decides (last runs of 3 pixels) or the monotone
// test rejects (steep), and every other last-run length with steps near either test's bound;
// four to seven such spans a batch, each between guard bytes.
TEST(AsmSpanPerspBatch, PairsOf17To48PxSpansOnWideSurfacesMatch) {
  std::mt19937 rng(3248);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  long spans = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int sw = 32767 - int(rng() % 2000), sh = 1 + int(rng() % 3);
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    auto span = [&](int n) {
      PerspSpan p{};
      p.zi0 = std::ldexp(1.0, -int(rng() % 20));
      p.dzi = p.zi0 * r(rng) * (rng() % 2 ? 0.5 : 0.02);
      if (p.dzi == 0.0) p.dzi = 1e-9;
      p.uz0 = p.zi0 * sw * (0.5 + 0.5 * r(rng));
      p.duz = p.zi0 * sw * r(rng) * (rng() % 2 ? 1.0 : 0.3);
      p.vz0 = p.zi0 * sh * 0.5, p.dvz = p.dzi * sh * r(rng);
      p.px0 = double(rng() % 64) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1), p.vmax = int32_t((uint32_t(sh) << 16) - 1);
      p.second_order = true;
      if (rng() % 2) {
        // The last run's 3 pixels across the range test's bound (as in the test above).
        const double k = 1.0 + 0.1 * r(rng), ku = sw / 32767.0 * (1.0 + 0.02 * r(rng));
        p.zi0 = 1.0, p.dzi = 1.5 * k, p.px0 = 0.5 - double(n - 3);
        p.uz0 = -36330.0 * ku, p.duz = 75332.0 * ku;
        if (rng() % 2) p.uz0 = 60000.0 * ku, p.duz = -17000.0 * ku;
        p.vz0 = 0.5, p.dvz = 0.0;
        if (rng() % 4 == 0) p.dzi *= 1e3;  // steep: rejected by the monotone test
      }
      return PerspItem{nullptr, n, p};
    };
    auto len = [&]() { return rng() % 2 ? 19 + 16 * int(rng() % 2) : 17 + int(rng() % 32); };
    std::vector<PerspItem> items;
    if (trial % 2) items.push_back(span(1 + int(rng() % 16)));  // spans_range's pairs
    const int count = 4 + int(rng() % 4);
    for (int i = 0; i < count; ++i) items.push_back(span(len()));
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += long(items.size());
  }
  std::printf("[ asm      ] span_persp batch: %ld spans of 17 .. 48 px in pairs on wide surfaces, every variant identical\n",
              spans);
}
