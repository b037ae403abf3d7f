// The single-pass lit span kernel's 16-pixel runs whose 8-pixel groups cross several light
// cells (asm/lit_span_a64win.h on aarch64: a 3 x 3-cell window a group, the run drawn again
// by the per-pixel kernel when a group spans more): every variant against the scalar
// reference. Groups crossing 2 and 3 cells in u, in v and in both, both directions, bending
// (second order, also turning within a group), every mip, windows clamped at the surface's
// last cells, surfaces of exactly 3 cells and of fewer (no window fits) or more than 256
// (outside the block's byte-wide ranges), power-of-two textures up to and beyond 2^16
// texels and others, texture wrap (offsets, small textures), light at 0, at its maximum,
// random and a checkerboard; guard bytes after (and before) the run. The test counts the
// runs whose groups all fit a window and those with a group that does not (the fallback),
// by the same rule, so both paths are known to be exercised.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "asm/lit_span.h"

namespace {

using sb::simd::LitSpanSource;

constexpr int kGuard = 32;
constexpr uint8_t kGuardByte = 0xa5;

struct WinCase {
  int mip, width, height, tw, th, soff, toff;
  std::vector<uint16_t> grid;
  int grid_width;
  std::vector<uint8_t> texels, colormap;
  std::vector<uint32_t> wide;
  LitSpanSource src;
};

// Exactly sized grid (the window must not read past the contract's grid). light: 0 random,
// 1 all brightest (0), 2 all darkest (0x3fff), 3 a maximal checkerboard.
void make(WinCase& c, std::mt19937& rng, int mip, int width, int height, int tw, int th, int soff, int toff,
          int light) {
  c.mip = mip, c.width = width, c.height = height, c.tw = tw, c.th = th, c.soff = soff, c.toff = toff;
  const int b = 16 >> mip;
  c.grid_width = (width - 1) / b + 2 + int(rng() % 2);
  const int rows = (height - 1) / b + 2;
  c.grid.assign(size_t(c.grid_width) * rows, 0);
  for (size_t i = 0; i < c.grid.size(); ++i) {
    const uint16_t r = uint16_t(rng() % 0x4000);
    c.grid[i] = light == 0 ? r : light == 1 ? 0 : light == 2 ? 0x3fff : ((i + i / c.grid_width) % 2 ? 0x3fff : 0);
  }
  c.texels.resize(size_t(tw) * th);
  for (auto& t : c.texels) t = uint8_t(rng());
  c.colormap.resize(64 * 256);
  for (auto& m : c.colormap) m = uint8_t(rng());
  c.src = LitSpanSource{};
  c.src.texels = c.texels.data();
  c.src.tex_width = tw;
  c.src.tex_height = th;
  c.src.soff = soff;
  c.src.toff = toff;
  c.src.grid = c.grid.data();
  c.src.grid_width = c.grid_width;
  c.src.mip = mip;
  c.src.width = width;
  c.src.height = height;
  c.src.colormap = c.colormap.data();
  c.wide.assign(c.grid.size(), 0);
  sb::simd::lit_span_prepare(c.src, int(c.grid.size()), c.wide.data());
}

struct Walk {
  int n;
  int32_t u, v, du, dv, ddu, ddv;
};

bool valid(const WinCase& c, const Walk& w) {
  int64_t u = w.u, v = w.v, du = w.du, dv = w.dv;
  for (int k = 0; k < w.n; ++k) {
    if (u < 0 || u >= (int64_t(c.width) << 16) || v < 0 || v >= (int64_t(c.height) << 16)) return false;
    u += du, v += dv, du += w.ddu, dv += w.ddv;
  }
  return true;
}

// Whether every 8-pixel group of the first 16 pixels spans at most 3 cells each way (the
// window's rule; the origin's clamp never makes a group fit less).
bool groups_fit(const WinCase& c, const Walk& w) {
  const int lg = 4 - c.mip;
  int64_t u = w.u, v = w.v, du = w.du, dv = w.dv;
  bool fit = true;
  for (int g = 0; g < 2; ++g) {
    int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
    for (int k = 0; k < 8; ++k) {
      const int gx = int(u >> 16) >> lg, gy = int(v >> 16) >> lg;
      x0 = std::min(x0, gx), x1 = std::max(x1, gx), y0 = std::min(y0, gy), y1 = std::max(y1, gy);
      u += du, v += dv, du += w.ddu, dv += w.ddv;
    }
    fit &= x1 - x0 <= 2 && y1 - y0 <= 2;
  }
  return fit;
}

// asm/lit_span_neon.cpp's gate for the window (window_steps): runs beyond it go to the
// per-pixel kernel without trying the window.
bool gated_in(const WinCase& c, const Walk& w) {
  auto mag = [](int32_t x) { return uint64_t(uint32_t(x) ^ uint32_t(x >> 31)); };
  const uint64_t lim = uint64_t(0x50000) >> c.mip;
  return mag(w.du) + 16 * mag(w.ddu) < lim && mag(w.dv) + 16 * mag(w.ddv) < lim;
}

void check(const WinCase& c, const Walk& w, const char* what) {
  ASSERT_TRUE(valid(c, w)) << what;
  std::vector<uint8_t> want(size_t(w.n) + 2 * kGuard, kGuardByte);
  sb::simd::lit_span_scalar(want.data() + kGuard, w.n, c.src, w.u, w.v, w.du, w.dv, w.ddu, w.ddv);
  for (int i = 1; i < sb::simd::lit_span_variant_count(); ++i) {
    const sb::simd::LitSpanVariant var = sb::simd::lit_span_variant(i);
    if (!var.supported) continue;
    std::vector<uint8_t> got(want.size(), kGuardByte);
    var.fn(got.data() + kGuard, w.n, c.src, w.u, w.v, w.du, w.dv, w.ddu, w.ddv);
    ASSERT_EQ(want, got) << var.name << " " << what << ": n " << w.n << " mip " << c.mip << " surface " << c.width
                         << "x" << c.height << " texture " << c.tw << "x" << c.th << " u " << w.u << " v " << w.v
                         << " du " << w.du << " dv " << w.dv << " ddu " << w.ddu << " ddv " << w.ddv;
  }
}

// A step that moves a group (7 steps) over about `cells` cells of B texels, signed.
int32_t step_for(std::mt19937& rng, int b, double cells, bool negative) {
  const double texels = cells * b * (0.9 + 0.2 * double(rng() % 1000) / 1000.0) / 7.0;
  const int32_t d = int32_t(texels * 65536.0);
  return negative ? -d : d;
}

// A start so that the whole walk stays inside: from a random point inside the room the
// steps leave (positive steps start low, negative ones high), or at the edge.
int32_t start_for(std::mt19937& rng, int size, int64_t reach_lo, int64_t reach_hi, bool at_edge) {
  const int64_t lo = -reach_lo, hi = (int64_t(size) << 16) - 1 - reach_hi;
  if (hi < lo) return -1;
  if (at_edge) return int32_t(rng() % 2 ? lo : hi);
  return int32_t(lo + int64_t(rng() % uint64_t(hi - lo + 1)));
}

// The walk's lowest and highest offsets from its start over n pixels.
void reach(int n, int32_t d, int32_t dd, int64_t& lo, int64_t& hi) {
  int64_t p = 0, s = d;
  lo = 0, hi = 0;
  for (int k = 0; k < n; ++k) {
    lo = std::min(lo, p), hi = std::max(hi, p);
    p += s, s += dd;
  }
}

TEST(AsmLitSpanWindow, RunsOf16CrossingSeveralCells) {
  std::mt19937 rng(2323);
  struct Tex {
    int w, h;
  };
  const Tex texs[] = {{16, 16}, {64, 64}, {256, 256}, {512, 256}, {48, 80}, {8, 4}};
  const double spans[] = {0.7, 1.2, 1.8, 2.05, 2.15, 2.3, 2.8, 3.5};  // cells a group moves (7 steps)
  int cases = 0, fit = 0, unfit = 0, flagged = 0;
  WinCase c;
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    for (const Tex& t : texs) {
      for (int light = 0; light < 4; ++light) {
        // 3 cells exactly (one window position), a few, many (the origin clamped at both ends).
        const int cells_w = light == 0 ? 3 : 3 + int(rng() % 30), cells_h = light == 1 ? 3 : 3 + int(rng() % 30);
        const int width = cells_w * b - int(rng() % b), height = cells_h * b - int(rng() % b);
        make(c, rng, mip, std::max(1, width), std::max(1, height), std::max(1, t.w >> mip), std::max(1, t.h >> mip),
             int(rng() % 4001) - 2000, int(rng() % 4001) - 2000, light);
        for (int rep = 0; rep < 60; ++rep) {
          const int mode = rep % 6;
          const double su = spans[rng() % 8], sv = spans[rng() % 8];
          int32_t du = 0, dv = 0, ddu = 0, ddv = 0;
          switch (mode) {
            case 0: du = step_for(rng, b, su, rng() % 2); dv = int32_t(rng() % 20001) - 10000; break;  // u
            case 1: dv = step_for(rng, b, sv, rng() % 2); du = int32_t(rng() % 20001) - 10000; break;  // v
            case 2: du = step_for(rng, b, su, rng() % 2); dv = step_for(rng, b, sv, rng() % 2); break;  // both
            case 3:  // bending
              du = step_for(rng, b, su, rng() % 2);
              dv = step_for(rng, b, sv, rng() % 2);
              ddu = int32_t(rng() % 4001) - 2000;
              ddv = int32_t(rng() % 4001) - 2000;
              break;
            case 4:  // turning within a group
              du = step_for(rng, b, su, rng() % 2);
              ddu = du > 0 ? -int32_t(du / 6) : int32_t(-du / 6);
              dv = step_for(rng, b, sv, rng() % 2);
              break;
            default:  // along the surface's last cells (the clamped origin)
              du = step_for(rng, b, su, rng() % 2);
              dv = int32_t(rng() % 2001) - 1000;
              break;
          }
          for (int n : {16, 16, 17, 32}) {
            int64_t ulo, uhi, vlo, vhi;
            reach(n, du, ddu, ulo, uhi);
            reach(n, dv, ddv, vlo, vhi);
            const bool edge = mode == 5 || rng() % 4 == 0;
            const int32_t u = start_for(rng, c.width, ulo, uhi, edge), v = start_for(rng, c.height, vlo, vhi, edge);
            if (u < 0 || v < 0) continue;
            const Walk w{n, u, v, du, dv, ddu, ddv};
            if (!valid(c, w)) continue;
            check(c, w, "several cells");
            if (testing::Test::HasFatalFailure()) return;
            ++cases;
            if (n == 16) {
              const bool f = groups_fit(c, w);
              ++(f ? fit : unfit);
              flagged += !f && gated_in(c, w);
            }
          }
        }
      }
    }
  }
  std::printf("[ asm      ] lit_span window: %d runs compared (16-pixel runs: %d fit windows, %d do not, %d of "
              "those within the window's gate)\n", cases, fit, unfit, flagged);
  EXPECT_GT(cases, 3000);
  EXPECT_GT(fit, 1000);
  EXPECT_GT(unfit, 300);
  EXPECT_GT(flagged, 50);
}

// Surfaces where no window fits (fewer than 3 cells a way) or whose cells pass 255 (the
// block's byte-wide ranges): the run goes another way, same bytes.
TEST(AsmLitSpanWindow, SurfacesOutsideTheWindowsRange) {
  std::mt19937 rng(2424);
  WinCase c;
  int cases = 0;
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    const int sizes[][2] = {{b, 40 * b}, {2 * b, 40 * b}, {40 * b, 2 * b}, {3 * b, 3 * b}, {4096, 3 * b}, {3 * b, 4096},
                            {4096, 4096}};
    for (const auto& s : sizes) {
      make(c, rng, mip, s[0], s[1], 64 >> mip, 64 >> mip, 3, -5, int(rng() % 4));
      for (int rep = 0; rep < 40; ++rep) {
        const int32_t du = step_for(rng, b, 1.0 + double(rng() % 200) / 100.0, rng() % 2);
        const int32_t dv = step_for(rng, b, double(rng() % 300) / 100.0, rng() % 2);
        int64_t ulo, uhi, vlo, vhi;
        reach(16, du, 0, ulo, uhi);
        reach(16, dv, 0, vlo, vhi);
        const int32_t u = start_for(rng, c.width, ulo, uhi, rng() % 3 == 0);
        const int32_t v = start_for(rng, c.height, vlo, vhi, rng() % 3 == 0);
        if (u < 0 || v < 0) continue;
        const Walk w{16, u, v, du, dv, 0, 0};
        if (!valid(c, w)) continue;
        check(c, w, "outside the window's range");
        if (testing::Test::HasFatalFailure()) return;
        ++cases;
      }
    }
  }
  std::printf("[ asm      ] lit_span window: %d runs on small and large surfaces compared\n", cases);
  EXPECT_GT(cases, 300);
}

}  // namespace
