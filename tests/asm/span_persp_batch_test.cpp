// The whole-span drawer's batch entry (asm/span_persp.h, surface_spans_persp): every variant's
// batch against surface_span_persp_scalar span by span, on batches mixing random and real
// spans of every kind the kernels tell apart (lengths 0 .. 1920 around each run and path
// boundary, second order and linear, dzi == 0, depths whose reciprocal needs the divide
// fallback, non-finite and huge or tiny depths), each span's dest between guard bytes.
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
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>
#include <cstring>

#include "asm/span_persp_arm.h"    // short_samples1 (asm/span_persp_a64short.h; this test's own copy)
#include "asm/span_persp_a64pair.h"  // short_samples2
#include "asm/span_persp_a64lin2.h"  // short_lin_setup2, short_lin_finish
#endif
#include "engine/render/render_local.h"
#include "engine/render/span_draw.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"

namespace {

using sb::simd::PerspItem;
using sb::simd::PerspSpan;
using namespace sb::test_persp;

TEST(AsmSpanPerspBatch, MatchesTheReferenceSpanBySpanOnMixedBatches) {
  std::mt19937 rng(4242);
  long spans = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    const int sw = 1 + int(rng() % 300), sh = 1 + int(rng() % 200);
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    // Mostly the engine's batches (one plane, rows' values), some items of other planes.
    const int count = trial % 10 == 0 ? int(rng() % 3) : int(rng() % 40);
    const PerspSpan plane = pick_span(rng, sw, sh);
    std::vector<PerspItem> items;
    for (int i = 0; i < count; ++i) {
      PerspSpan p = rng() % 3 ? plane : pick_span(rng, sw, sh);
      if (rng() % 2) {  // another row of the plane: zi0, uz0, vz0 moved
        const double dy = double(rng() % 50);
        p.zi0 += dy * 1e-5, p.uz0 += dy * 0.01, p.vz0 -= dy * 0.02;
      }
      p.px0 = double(rng() % 600) + 0.5;
      items.push_back(PerspItem{nullptr, pick_length(rng), p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in batches, every variant identical\n", spans);
}

// Every partial last run (asm/span_persp_run.h's draw_last: 1 .. 15 pixels in chunks of 8, 4,
// 2, 1 by the bits of n, 16 the full run) on every path: spans of 16 r + L pixels,
// L = 1 .. 16, r = 0 .. 12 (one run; the short, mid and paired paths; the long paths'
// tails), second order and linear, through the batch entry (alone and in pairs: aarch64's
// paired short spans) and the single-span entry, each span between guard bytes.
TEST(AsmSpanPerspBatch, EveryPartialLastRunLengthMatchesOnEveryPath) {
  std::mt19937 rng(2711);
  const int sw = 61, sh = 43;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  long spans = 0;
  for (int last = 1; last <= 16; ++last) {
    for (int r = 0; r <= 12; ++r) {
      const int n = 16 * r + last;
      for (int k = 0; k < 8; ++k) {
        PerspSpan a = pick_span(rng, sw, sh), b = pick_span(rng, sw, sh);
        a.second_order = b.second_order = k < 6;
        ASSERT_TRUE(batch_matches({PerspItem{nullptr, n, a}}, surf.data(), sw, sh)) << " n " << n << " k " << k;
        ASSERT_TRUE(batch_matches({PerspItem{nullptr, n, a}, PerspItem{nullptr, n, b}}, surf.data(), sw, sh))
            << " pair of n " << n << " k " << k;
        std::vector<uint8_t> ref(size_t(n) + 2 * kGuard, kGuardByte), got(ref.size());
        sb::simd::surface_span_persp_scalar(ref.data() + kGuard, n, surf.data(), sw, sh, a);
        for (int v = 0; v < sb::simd::variant_count(); ++v) {
          const sb::simd::Variant var = sb::simd::variant(v);
          if (!var.kernels || !var.supported) continue;
          std::fill(got.begin(), got.end(), kGuardByte);
          var.kernels->surface_span_persp(got.data() + kGuard, n, surf.data(), sw, sh, a);
          ASSERT_EQ(ref, got) << var.kernels->name << " single span of n " << n << " k " << k;
        }
        spans += 4;
      }
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans of every last-run length, every variant identical\n", spans);
}

// Second-order spans of two and three runs (17 .. 48 pixels) in pairs: aarch64 draws them from
// the four-run steps block with moved samples (asm/span_persp_a64few.h: steps_k3v_pass for
// three runs, steps_k1v_pass for two, the partial last run by last_chunks). Every length as
// span a and as span b against every other (so every run count and last-run length on both
// sides of the pair), on ordinary, steep (dzi 40 times), clamping (u past the surface's right
// edge and v below 0 along the span) and extreme gradients (the curve near its largest, huge
// u, v steps); then chains of such pairs (the pair loop's next-pair test) of random lengths.
// Each span between guard bytes: the bytes after each span stay untouched.
TEST(AsmSpanPerspBatch, TwoAndThreeRunPairsMatchOnEveryLengthPair) {
  std::mt19937 rng(3248);
  const int sw = 53, sh = 29;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  auto curve_span = [&](int kind) {
    PerspSpan p = pick_span(rng, sw, sh);
    p.second_order = true;
    const double depth = 0.002 + 0.05 * double(rng() % 1000) / 1000.0;
    switch (kind) {
      case 0: break;
      case 1: p.dzi *= 40.0; break;  // steep
      case 2:                        // clamped: u runs past umax, v below 0
        p.duz = std::fabs(p.duz) * 50.0 + double(sw) * depth;
        p.dvz = -std::fabs(p.dvz) * 50.0 - double(sh) * depth;
        break;
      default:  // extreme: 1/z from near 0 to depth across the span, huge steps
        p.zi0 = depth * 1e-3;
        p.dzi = (rng() % 2 ? 1.0 : -1.0) * depth / 48.0;
        if (p.dzi < 0) p.zi0 = depth;
        p.duz = double(int32_t(rng())) * depth * 1e-2;
        p.dvz = double(int32_t(rng())) * depth * 1e-2;
        break;
    }
    if (p.dzi == 0.0 || !std::isfinite(p.dzi)) p.dzi = depth * 1e-4;
    return p;
  };
  long spans = 0;
  for (int na = 17; na <= 48; ++na) {
    for (int nb = 17; nb <= 48; ++nb) {
      for (int kind = 0; kind < 4; ++kind) {
        const PerspSpan a = curve_span(kind), b = curve_span(int(rng() % 4));
        ASSERT_TRUE(batch_matches({PerspItem{nullptr, na, a}, PerspItem{nullptr, nb, b}}, surf.data(), sw, sh))
            << " na " << na << " nb " << nb << " kind " << kind;
        spans += 2;
      }
    }
  }
  for (int trial = 0; trial < 1000; ++trial) {
    std::vector<PerspItem> items;
    const int count = 2 + int(rng() % 9);
    for (int i = 0; i < count; ++i) items.push_back(PerspItem{nullptr, 17 + int(rng() % 32), curve_span(int(rng() % 4))});
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " chain trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld two- and three-run spans in pairs, every variant identical\n", spans);
}

// Pairs of short second-order spans side by side (the aarch64 paired samples): both spans of
// each pair 17 .. 64 pixels, one of them at a depth needing the divide fallback, or
// non-finite, or both ordinary; odd counts leave one span unpaired.
TEST(AsmSpanPerspBatch, ShortSecondOrderPairsMatchWithEdgeDepths) {
  std::mt19937 rng(77);
  const int sw = 37, sh = 19;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i);
  long spans = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<PerspItem> items;
    const int count = 1 + int(rng() % 9);
    for (int i = 0; i < count; ++i) {
      PerspSpan p = pick_span(rng, sw, sh);
      p.second_order = rng() % 8 != 0;
      items.push_back(PerspItem{nullptr, 17 + int(rng() % 48), p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld short spans in pairs, every variant identical\n", spans);
}

// Chains of pairs (aarch64: the batch loop goes from pair to pair on one flag, the next pair's
// test computed inside the pair before): runs of 0 .. 11 pairable spans (17 .. 64 pixels,
// second order, dzi != 0), each run ended by one span that fails exactly one of the tests
// (n 16 or 65 or 0, linear, dzi +-0, or none: a NaN dzi pairs), so the chain breaks at
// either span of a next pair, at the batch's end with 0 .. 3 items left, or not at all.
TEST(AsmSpanPerspBatch, ChainsOfPairsMatchWhereTheyBreak) {
  std::mt19937 rng(1357);
  const int sw = 45, sh = 29;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 13 + 5);
  auto pairable = [&]() {
    PerspSpan p{};
    const double depth = 0.002 + 0.05 * double(rng() % 1000) / 1000.0;
    p.dzi = depth * (double(rng() % 2001) - 1000.0) / 640000.0;
    if (p.dzi == 0.0) p.dzi = 1e-7;
    p.zi0 = depth + std::fabs(p.dzi) * 640.0;
    p.uz0 = sw * p.zi0 * 0.7, p.duz = sw * p.dzi * 0.9;
    p.vz0 = sh * p.zi0 * 0.4, p.dvz = -sh * p.dzi * 0.3;
    p.px0 = double(rng() % 600) + 0.5;
    p.umax = int32_t((uint32_t(sw) << 16) - 1), p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    p.second_order = true;
    return PerspItem{nullptr, 17 + int(rng() % 48), p};
  };
  long spans = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<PerspItem> items;
    const int runs = 1 + int(rng() % 4);
    for (int r = 0; r < runs; ++r) {
      const int len = int(rng() % 12);
      for (int i = 0; i < len; ++i) items.push_back(pairable());
      if (r == runs - 1 && rng() % 2) break;  // the batch ends in the chain
      PerspItem x = pairable();
      switch (rng() % 8) {
        case 0: x.n = 16; break;
        case 1: x.n = 65; break;
        case 2: x.n = 0; break;
        case 3: x.span.second_order = false; break;
        case 4: x.span.dzi = 0.0; break;
        case 5: x.span.dzi = -0.0; break;
        case 6: x.span.dzi = std::numeric_limits<double>::quiet_NaN(); break;
        default: break;
      }
      items.push_back(x);
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += long(items.size());
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in chains of pairs, every variant identical\n", spans);
}

// Chains of short linear spans (aarch64: two neighbouring ones, 17 .. 64 pixels, second_order
// off or dzi +-0, at the start of the batch's items left (batch_from: the batch's start, or
// after long spans) take their set-ups from one block, persp_short_lin2, and the pairs go on
// while the next two items pair): runs of 0 .. 9 such spans of every length with pick_span's
// edge values (the divide fallback for either span of a pair, clamped, non-finite), each run
// ended by a span that fails one test (n 16, 65 (a long linear span: the next run starts
// the items left again) or 0, second order with dzi != 0) or by the batch's end.
TEST(AsmSpanPerspBatch, ChainsOfLinearPairsMatchWithEdgeDepths) {
  std::mt19937 rng(4242);
  const int sw = 53, sh = 31;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 11 + (i >> 4));
  auto linear = [&]() {
    PerspSpan p = pick_span(rng, sw, sh);
    if (rng() % 3) {
      p.second_order = false;
    } else {
      p.second_order = true;
      p.dzi = rng() % 2 ? 0.0 : -0.0;
    }
    return PerspItem{nullptr, 17 + int(rng() % 48), p};
  };
  long spans = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<PerspItem> items;
    const int runs = 1 + int(rng() % 3);
    for (int r = 0; r < runs; ++r) {
      const int len = int(rng() % 10);
      for (int i = 0; i < len; ++i) items.push_back(linear());
      if (r == runs - 1 && rng() % 2) break;  // the batch ends in the chain
      PerspItem x = linear();
      switch (rng() % 4) {
        case 0: x.n = 16; break;
        case 1: x.n = 65; break;
        case 2: x.n = 0; break;
        default: x.span.second_order = true, x.span.dzi = 1e-6; break;
      }
      items.push_back(x);
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += long(items.size());
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in chains of linear pairs, every variant identical\n", spans);
}

// Runs of long spans (aarch64: a long first item of the items left is reached and left with
// tail branches, persp_long_a64 / persp_lin_a64 back to batch_from): batches of long second-
// order and linear spans (65 .. 400 pixels, dzi == 0 among them) in every order, with
// shorter spans before, between and after them.
TEST(AsmSpanPerspBatch, RunsOfLongSpansMatch) {
  std::mt19937 rng(913);
  const int sw = 61, sh = 23;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 7);
  long spans = 0;
  for (int trial = 0; trial < 600; ++trial) {
    std::vector<PerspItem> items;
    const int count = 1 + int(rng() % 12);
    for (int i = 0; i < count; ++i) {
      PerspSpan p = pick_span(rng, sw, sh);
      const int n = rng() % 5 ? 65 + int(rng() % 336) : int(rng() % 65);
      items.push_back(PerspItem{nullptr, n, p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " trial " << trial;
    spans += count;
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of long ones, every variant identical\n", spans);
}

// Batches of long spans all of one kind (aarch64: consecutive second-order spans over 64 px
// drawn in persp_long_a64's loop, consecutive linear ones over 64 px in persp_lin_a64's, one
// frame for the run), every length 65 .. 300 (each tail length after the passes), then a
// span of another kind or length ending the run; the batch's items against the reference.
TEST(AsmSpanPerspBatch, RunsOfOneKindOfLongSpanMatch) {
  std::mt19937 rng(1921);
  const int sw = 61, sh = 23;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (size_t i = 0; i < surf.size(); ++i) surf[i] = uint8_t(i * 13 + (i >> 5));
  long spans = 0;
  for (int kind = 0; kind < 3; ++kind) {  // second order, linear (second_order off), dzi == 0
    for (int n0 = 65; n0 <= 300; n0 += 5) {
      std::vector<PerspItem> items;
      const int count = 2 + int(rng() % 6);
      for (int i = 0; i < count; ++i) {
        PerspSpan p = pick_span(rng, sw, sh);
        p.second_order = kind != 1;
        if (kind == 2) p.dzi = 0.0;
        if (kind == 0 && p.dzi == 0.0) p.dzi = 1e-5;
        items.push_back(PerspItem{nullptr, n0 + i % 5, p});
      }
      PerspSpan last = pick_span(rng, sw, sh);  // another kind ends the run, or none
      if (rng() % 2) items.push_back(PerspItem{nullptr, int(rng() % 300), last});
      ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " kind " << kind << " n " << n0;
      spans += long(items.size());
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of one long kind, every variant identical\n", spans);
}

// Runs of long linear spans through the batch entry (aarch64: persp_lin_a64's loop over
// consecutive such items, each span's passes one generated asm loop): lengths 65 .. 2000 in
// steps of 7 (every residue mod 32: each tail and last-run length, odd and even pass counts),
// two to five per run, second_order off or dzi == 0, on a texture 32767 texels wide with
// steps up to 1000 times the edge cases' (samples clamped at 0 and at umax / vmax).
TEST(AsmSpanPerspBatch, RunsOfLongLinearSpansMatchUpTo2000Pixels) {
  std::mt19937 rng(2000);
  const int sw = 32767, sh = 5;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  long spans = 0;
  for (int n0 = 65; n0 <= 2000; n0 += 7) {
    std::vector<PerspItem> items;
    const int count = 2 + int(rng() % 4);
    for (int i = 0; i < count; ++i) {
      PerspSpan p = pick_span(rng, sw, sh);
      if (rng() % 2) p.duz *= 1000.0, p.dvz *= -300.0;
      if (rng() % 2) {
        p.second_order = false;
      } else {
        p.dzi = 0.0;
      }
      items.push_back(PerspItem{nullptr, std::min(2000, n0 + 32 * i + i), p});
    }
    ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " n " << n0;
    spans += long(items.size());
  }
  std::printf("[ asm      ] span_persp batch: %ld long linear spans up to 2000 px, every variant identical\n", spans);
}

// Five-run second-order spans (65 .. 80 pixels; ARMv7: persp_five_run_v7, reached from the
// batch loop through persp_long_run_v7's test, drawing the consecutive ones in one call):
// every length in batches of such spans (each length first, last and between others), the
// runs broken by spans of other paths (49, 64, 81 and over, linear, dzi == 0) and restarted;
// gradients over many magnitudes (depths near and below the 1/z clamp, u and v past both
// clamps, curves whose steps are accepted or rejected by the monotone test, non-finite
// values), and on a texture 32767 texels wide with extreme steps (deltas near +-2^31); the
// guard bytes after every span untouched (batch_matches).
TEST(AsmSpanPerspBatch, FiveRunSpansMatchOnEveryLength) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double odd[] = {0.0, -0.0, 1e-9, 1e-12, 1e-300, -1e300, 1e300, inf, -inf, nan};
  std::mt19937 rng(6580);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto logu = [&](double lo, double hi) {  // +-10^[lo, hi], log-uniform
    const double e = lo + (hi - lo) * double(rng() % 100000) / 100000.0;
    return (rng() & 1 ? 1.0 : -1.0) * std::pow(10.0, e);
  };
  // kind 0: extreme gradients on a 300 x 200 surface; kind 1: extreme steps on 32767 x 3.
  auto five_span = [&](int kind, int sw, int sh) {
    PerspSpan p{};
    if (kind == 0) {
      p.zi0 = rng() % 8 ? std::ldexp(unit(rng) + 1.0, -int(rng() % 32)) : odd[rng() % 10];
      p.dzi = rng() % 8 ? p.zi0 * std::ldexp(unit(rng), -int(rng() % 12)) : odd[rng() % 10];
      p.uz0 = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 20) * p.zi0 * sw : odd[rng() % 10];
      p.duz = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 26) * sw : odd[rng() % 10];
      p.vz0 = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 20) * p.zi0 * sh : odd[rng() % 10];
      p.dvz = rng() % 8 ? std::ldexp(unit(rng), int(rng() % 40) - 26) * sh : odd[rng() % 10];
      p.px0 = double(rng() % 2000) + 0.5;
      p.umax = int32_t((uint32_t(sw) << 16) - 1 - (rng() % 3 == 0 ? rng() % 65536 : 0));
      p.vmax = int32_t((uint32_t(sh) << 16) - 1 - (rng() % 3 == 0 ? rng() % 65536 : 0));
    } else {
      p.zi0 = std::fabs(logu(-4, 0));
      p.dzi = logu(-7, -2);
      p.uz0 = logu(2, 9) * p.zi0, p.duz = logu(0, 8) * std::fabs(p.dzi) * (rng() % 4 ? 1.0 : 1e3);
      p.vz0 = std::fabs(logu(-2, 1)) * p.zi0, p.dvz = logu(-3, 1) * std::fabs(p.dzi);
      p.px0 = double(rng() % 100) + (rng() & 1 ? 0.5 : 0.0);
      p.umax = int32_t((uint32_t(sw) << 16) - 1);
      p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    }
    p.second_order = true;
    return p;
  };
  long spans = 0;
  for (int kind = 0; kind < 2; ++kind) {
    const int sw = kind == 0 ? 300 : 32767, sh = kind == 0 ? 200 : 3;
    std::vector<uint8_t> surf(size_t(sw) * sh);
    for (auto& b : surf) b = uint8_t(rng());
    for (int trial = 0; trial < 1600; ++trial) {
      std::vector<PerspItem> items;
      const int n0 = 65 + trial % 16;  // this trial's length: first, then among others
      const int count = 1 + int(rng() % 8);
      for (int i = 0; i < count; ++i) {
        int n = i == 0 || rng() % 2 ? n0 : 65 + int(rng() % 16);
        PerspSpan p = five_span(kind, sw, sh);
        if (i > 0 && rng() % 5 == 0) {  // a span of another path breaks the run
          const int others[] = {49, 50, 64, 81, 96, 97, 200, 16, 33};
          n = rng() % 2 ? others[rng() % 9] : n;
          if (rng() % 3 == 0) p.second_order = false;
          if (rng() % 3 == 0) p.dzi = 0.0;
        }
        items.push_back(PerspItem{nullptr, n, p});
      }
      if (rng() % 2) items.push_back(PerspItem{nullptr, n0, five_span(kind, sw, sh)});  // n0 last too
      ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " kind " << kind << " trial " << trial;
      spans += long(items.size());
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld spans in runs of five-run ones, every variant identical\n", spans);
}

// A long batch of long spans only (aarch64: each one reached and left by tail branches,
// batch_from -> persp_long_a64 / persp_lin_a64 -> batch_from): 100000 items in one call
// must not nest a frame per item (that would overflow the stack and crash here); the tuned
// table's bytes checked against the reference on every 499th item.
TEST(AsmSpanPerspBatch, LongBatchOfLongSpansNestsNoFrames) {
  std::mt19937 rng(2718);
  const int sw = 64, sh = 64, kItems = 100000;
  std::vector<uint8_t> surf(size_t(sw) * sh);
  for (auto& b : surf) b = uint8_t(rng());
  std::vector<PerspItem> items;
  size_t size = 0;
  for (int i = 0; i < kItems; ++i) {
    PerspSpan p{};
    p.zi0 = 0.01, p.dzi = -1e-6, p.uz0 = 0.3, p.duz = 1e-4, p.vz0 = 0.2, p.dvz = 2e-5;
    p.px0 = double(i % 500) + 0.5;
    p.umax = int32_t((uint32_t(sw) << 16) - 1), p.vmax = int32_t((uint32_t(sh) << 16) - 1);
    p.second_order = i % 2 == 0;  // second order over 80 px, linear over 64: both long paths
    const int n = p.second_order ? 81 + int(rng() % 40) : 65 + int(rng() % 40);
    items.push_back(PerspItem{nullptr, n, p});
    size += size_t(n);
  }
  std::vector<uint8_t> got(size, 0);
  size_t at = 0;
  for (PerspItem& it : items) it.dest = got.data() + at, at += size_t(it.n);
  sb::simd::active().surface_spans_persp(items.data(), kItems, surf.data(), sw, sh);
  for (int i = 0; i < kItems; i += 499) {
    std::vector<uint8_t> ref(size_t(items[i].n));
    sb::simd::surface_span_persp_scalar(ref.data(), items[i].n, surf.data(), sw, sh, items[i].span);
    ASSERT_TRUE(std::equal(ref.begin(), ref.end(), items[i].dest)) << " item " << i;
  }
}

// Real faces' rows (LibreQuake maps from their own viewpoints; skipped without the data):
// one batch per face, items built as engine/render/span_draw.cpp builds them.
TEST(AsmSpanPerspBatch, MatchesOnRealFaces) {
  SB_REQUIRE_QUAKE_DATA();
  const int W = 640, H = 480;
  long spans = 0;
  sb::test::TestWorld tw("start");
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  const sb::BspWorld& w = *tw.world();
  std::mt19937 rng(31);
  for (const sb::ViewParams& vp : sb::test::test_viewpoints(w, 2)) {
    const sb::render::ViewState view = sb::render::setup_view(w, vp, W, H, 1);
    for (uint32_t fi = 0; fi < w.num_faces; fi += 37) {
      const sb::Face& f = w.faces[fi];
      if (f.extents[0] <= 0 || f.extents[1] <= 0) continue;
      const int mip = int(fi % 4);
      sb::render::SpanGradients g = sb::render::face_gradients(w, f, view, mip);
      g.second_order = (fi / 37) % 3 != 0;
      const int sw = f.extents[0] >> mip, sh = f.extents[1] >> mip;
      if (sw < 1 || sh < 1) continue;
      std::vector<uint8_t> surf(size_t(sw) * sh);
      for (auto& b : surf) b = uint8_t(rng());
      std::vector<PerspItem> items;
      for (int y = 0; y < H; y += 7) {
        const int n = y % 3 ? pick_length(rng) % (W + 1) : W;
        const int x0 = int(rng() % uint32_t(W - n + 1));
        const double py = y + 0.5;
        PerspSpan p{};
        p.zi0 = g.zi0 + g.ziy * py, p.dzi = g.zix;
        p.uz0 = g.u0 + g.uy * py, p.duz = g.ux;
        p.vz0 = g.v0 + g.vy * py, p.dvz = g.vx;
        p.px0 = x0 + 0.5;
        p.umax = int32_t((uint32_t(sw) << 16) - 1), p.vmax = int32_t((uint32_t(sh) << 16) - 1);
        p.second_order = g.second_order;
        items.push_back(PerspItem{nullptr, n, p});
      }
      ASSERT_TRUE(batch_matches(items, surf.data(), sw, sh)) << " face " << fi;
      spans += long(items.size());
    }
  }
  std::printf("[ asm      ] span_persp batch: %ld rows of real faces, every variant identical\n", spans);
}

#if defined(__aarch64__) && defined(__GNUC__)
// The paired sample block (short_samples2) against two runs of the single one
// (short_samples1), every output bit for bit (unused samples' lanes too): both spans 17 .. 64
// pixels, depths ordinary, NaN, infinite, huge (>= 2^1000: the divide), tiny or negative
// (clamped), significands of all ones (the divide) in either span, other fields random or
// non-finite.
TEST(AsmSpanPerspBatch, PairedSampleBlockMatchesTwoSingleBlocks) {
  using sb::simd::ShortSamples;
  std::mt19937 rng(606);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  auto any = [&]() {
    const double odd[] = {0.0, -0.0, 1e-300, -1e300, 1e300, inf, -inf, nan, 0x1p-1030, 3.5};
    return rng() % 4 ? r(rng) * std::ldexp(1.0, int(rng() % 40) - 20) : odd[rng() % 10];
  };
  auto pick = [&](PerspSpan* p) {
    *p = PerspSpan{};
    switch (rng() % 8) {
      case 0: p->zi0 = std::ldexp(2.0 - 0x1p-52, int(rng() % 120) - 60); break;  // all ones
      case 1: p->zi0 = std::ldexp(1.0 + r(rng) * 0.5, 1000 + int(rng() % 24)); break;  // huge, inf
      case 2: p->zi0 = any(); break;
      case 3: p->zi0 = std::ldexp(1.0 + 0.5 * r(rng), -int(rng() % 1000)); break;  // tiny
      default: p->zi0 = 0.01 * (1.5 + r(rng)); break;
    }
    p->dzi = rng() % 3 ? p->zi0 * 0.01 * r(rng) : (rng() % 2 ? std::ldexp(1.0, int(rng() % 40) - 100) : any());
    if (p->dzi == 0.0) p->dzi = 1e-7;
    p->uz0 = rng() % 5 ? p->zi0 * 65536.0 * 300.0 * r(rng) : any();
    p->duz = rng() % 5 ? p->zi0 * 650.0 * r(rng) : any();
    p->vz0 = rng() % 5 ? p->zi0 * 65536.0 * 300.0 * r(rng) : any();
    p->dvz = rng() % 5 ? p->zi0 * 650.0 * r(rng) : any();
    p->px0 = rng() % 7 ? double(rng() % 2000) + 0.5 : any();
    p->umax = int32_t(rng() % 0x7fffffff), p->vmax = int32_t(rng() % 0x7fffffff);
    p->second_order = true;
  };
  int fallback = 0, cases = 0;
  sb::simd::PerspItem two[2] = {};
  for (int trial = 0; trial < 60000; ++trial) {
    PerspSpan a, b;
    pick(&a), pick(&b);
    const int na = 17 + int(rng() % 48), nb = 17 + int(rng() % 48);
    alignas(16) ShortSamples pair[2];
    std::memset(pair, 0x5a, sizeof pair);
    const sb::simd::PerspItem* next = two;
    int runs_a = -1, last_a = -1;
    float64x2_t zh;
    float64x2_t zhm;
    sb::simd::short_samples2(a, na, b, nb, pair[0], pair[1], two, two + 2, next, runs_a, last_a, zh, zhm);
    ASSERT_EQ(std::memcmp(&zhm, &zh, 16), 0);  // the stored copy (span b's zh in the batch loop)
    const double zpa = vgetq_lane_f64(zh, 0), zpb = vgetq_lane_f64(zh, 1);
    const double wa = a.dzi * 0.5, wb = b.dzi * 0.5;  // the zh lanes: short_rest's dzi * 0.5, bit for bit
    ASSERT_EQ(std::memcmp(&zpa, &wa, 8), 0);
    ASSERT_EQ(std::memcmp(&zpb, &wb, 8), 0);
    ASSERT_EQ(next, nullptr);  // no items after the pair: the chain ends
    ASSERT_EQ(runs_a, (na + 15) >> 4);
    ASSERT_EQ(last_a, na - 16 * (runs_a - 1));
    ShortSamples sa, sbb;
    double zha, zhb;  // the single block's zc / 2: dzi * 0.5's bits
    sb::simd::ShortHead ha, hb;  // the single block's head (the single entry's test block does the same)
    sb::simd::short_head_asm(a, na, ha);
    sb::simd::short_samples1(a, na, ha, sa.S01, sa.S23, sa.S44, sa.zs01, sa.zs23, sa.c01, sa.c23, zha);
    sb::simd::short_head_asm(b, nb, hb);
    sb::simd::short_samples1(b, nb, hb, sbb.S01, sbb.S23, sbb.S44, sbb.zs01, sbb.zs23, sbb.c01, sbb.c23, zhb);
    const double wha = a.dzi * 0.5, whb = b.dzi * 0.5;
    ASSERT_EQ(std::memcmp(&zha, &wha, 8), 0);
    ASSERT_EQ(std::memcmp(&zhb, &whb, 8), 0);
    // S44: the paired block gives sample 4 twice, the single block [u_4, v_4, 0, 0] (its users
    // read the low half only): the single's high half is 0, its low half compared as the pair's.
    for (ShortSamples* s : {&sa, &sbb}) {
      ASSERT_EQ(vgetq_lane_s64(vreinterpretq_s64_s32(s->S44), 1), 0) << "trial " << trial;
      s->S44 = vcombine_s32(vget_low_s32(s->S44), vget_low_s32(s->S44));
    }
    ASSERT_EQ(std::memcmp(&pair[0], &sa, sizeof sa), 0) << "span a, trial " << trial << " zi0 " << a.zi0 << " n " << na;
    ASSERT_EQ(std::memcmp(&pair[1], &sbb, sizeof sbb), 0) << "span b, trial " << trial << " zi0 " << b.zi0 << " n " << nb;
    uint64_t bits;
    std::memcpy(&bits, &a.zi0, 8);
    fallback += ((bits + 1) << 12) == 0;
    ++cases;
  }
  std::printf("[ asm      ] span_persp batch: %d paired sample blocks (%d with an all-ones depth in span a) identical\n",
              cases, fallback);
  EXPECT_GT(fallback, cases / 20);
}

// The paired linear set-up (short_lin_setup2, then short_lin_finish for span b) against two
// runs of the single block (short_lin_setup), every output bit for bit (the last run's step by
// magic(s) and smulh there, by sdiv here: the same quotient for every 32-bit delta): both
// spans 17 .. 64 pixels, pick_span's values (the divide fallback in either span, clamped,
// non-finite), limits up to 2^32 - 1.
TEST(AsmSpanPerspBatch, PairedLinearSetupMatchesTwoSingleSetups) {
  std::mt19937 rng(5150);
  long cases = 0, pairs_next = 0;
  auto same = [](const sb::simd::ShortLinSetup& a, const sb::simd::ShortLinSetup& b) {
    return a.x0 == b.x0 && a.x1 == b.x1 && a.x2 == b.x2 && a.x3 == b.x3 && a.d0 == b.d0 && a.d1 == b.d1 &&
           a.d2 == b.d2 && a.ld == b.ld;
  };
  for (int trial = 0; trial < 40000; ++trial) {
    PerspSpan pa = pick_span(rng, 1 + int(rng() % 300), 1 + int(rng() % 300));
    PerspSpan pb = pick_span(rng, 1 + int(rng() % 300), 1 + int(rng() % 300));
    if (rng() % 8 == 0) pa.umax = int32_t(rng()), pb.vmax = int32_t(rng());
    const int na = 17 + int(rng() % 48), nb = 17 + int(rng() % 48);
    alignas(16) uint64_t buf[10];
    const sb::simd::ShortLinSetup ga = sb::simd::short_lin_setup2(na, pa, nb, pb, buf);
    // The finish block's next-pair test: items it[0 .. 3], end 2 .. 4 items on (it[2], it[3]
    // read only when four are left), each of it[2], it[3] with an n, second_order and dzi
    // around the test's edges (n 16 / 17 / 64 / 65 / 0 / negative; dzi +-0, tiny, NaN).
    PerspItem items[4] = {};
    for (PerspItem& x : items) {
      static const int ns[] = {16, 17, 40, 64, 65, 0, -5, 1000};
      static const double dz[] = {0.0, -0.0, 1e-300, -2.5, std::numeric_limits<double>::quiet_NaN()};
      x.n = rng() % 4 ? 17 + int(rng() % 48) : ns[rng() % 8];
      x.span.second_order = rng() % 2;
      x.span.dzi = dz[rng() % 5];
    }
    const int left = 2 + int(rng() % 3);
    uint32_t again = 7;
    const sb::simd::ShortLinSetup gb = sb::simd::short_lin_finish(nb, buf, items, items + left, again);
    auto pairable = [](const PerspItem& x) {
      return x.n > 16 && x.n <= 64 && (!x.span.second_order || x.span.dzi == 0.0);
    };
    const uint32_t want = left == 4 && pairable(items[2]) && pairable(items[3]);
    pairs_next += want;
    ASSERT_EQ(again, want) << " trial " << trial << " left " << left;
    const sb::simd::ShortLinSetup ra = sb::simd::short_lin_setup(na, pa);
    const sb::simd::ShortLinSetup rb = sb::simd::short_lin_setup(nb, pb);
    ASSERT_TRUE(same(ga, ra)) << " span a, trial " << trial << " na " << na;
    ASSERT_TRUE(same(gb, rb)) << " span b, trial " << trial << " nb " << nb;
    ++cases;
  }
  std::printf("[ asm      ] span_persp batch: %ld paired linear set-ups, both spans as the single block's"
              " (next pair's test: %ld pairable)\n", cases, pairs_next);
  EXPECT_GT(pairs_next, cases / 20);
}
#endif

}  // namespace
