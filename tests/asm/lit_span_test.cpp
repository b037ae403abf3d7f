// The single-pass lit span kernel (asm/lit_span.h): the scalar reference against the closed
// form built from engine/render/surface_math.h (shade_at, positive-modulo texel), and every
// variant against the scalar reference, on random and edge inputs: span lengths 0..1920,
// every mip, power-of-two and other texture sizes, negative and large texture offsets,
// second-order steps, extreme light, and the whole range of the wrap (every texture width
// 16..4096 at the largest offset). Destinations carry guard bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "asm/lit_span.h"
#include "engine/render/surface_math.h"

namespace {

using sb::simd::LitSpanSource;

constexpr int kGuard = 64;
constexpr uint8_t kGuardByte = 0x5a;

struct LitCase {
  int mip, width, height, tw, th, soff, toff;
  std::vector<uint16_t> grid;
  int grid_width;
  std::vector<uint8_t> texels, colormap;
  mutable std::vector<uint32_t> wide;
  // prepared = false: the derived fields are left empty (the tuned variant must fall back).
  LitSpanSource src(bool prepared = true) const {
    LitSpanSource s;
    s.texels = texels.data();
    s.tex_width = tw;
    s.tex_height = th;
    s.soff = soff;
    s.toff = toff;
    s.grid = grid.data();
    s.grid_width = grid_width;
    s.mip = mip;
    s.width = width;
    s.height = height;
    s.colormap = colormap.data();
    if (prepared) {
      wide.assign(grid.size(), 0xdeadbeefu);
      sb::simd::lit_span_prepare(s, int(grid.size()), wide.data());
    }
    return s;
  }
};

struct Walk {
  int n;
  int32_t u, v, du, dv, ddu, ddv;
};

int pos_mod(int i, int n) { return ((i % n) + n) % n; }

// Exactly sized inputs (AddressSanitizer sees over-reads). light: 0 random, 1 all darkest,
// 2 all brightest, 3 a maximal checkerboard.
LitCase make_case(std::mt19937& rng, int mip, int width, int height, int tw, int th, int soff, int toff, int light) {
  LitCase c{mip, width, height, tw, th, soff, toff, {}, 0, {}, {}, {}};
  const int b = 16 >> mip;
  c.grid_width = (width - 1) / b + 2 + int(rng() % 3);  // wider than needed is allowed
  const int rows = (height - 1) / b + 2;
  c.grid.resize(size_t(c.grid_width) * rows);
  for (size_t i = 0; i < c.grid.size(); ++i) {
    const uint16_t r = uint16_t(rng() % 0x4000);
    c.grid[i] = light == 0 ? r : light == 1 ? 0x3fff : light == 2 ? 0 : ((i + i / c.grid_width) % 2 ? 0x3fff : 0);
  }
  c.texels.resize(size_t(tw) * th);
  for (auto& t : c.texels) t = uint8_t(rng());
  c.colormap.resize(64 * 256);
  for (auto& m : c.colormap) m = uint8_t(rng());
  return c;
}

bool walk_valid(const LitCase& c, const Walk& w) {
  int64_t u = w.u, v = w.v, du = w.du, dv = w.dv;
  for (int k = 0; k < w.n; ++k) {
    if (u < 0 || u >= (int64_t(c.width) << 16) || v < 0 || v >= (int64_t(c.height) << 16)) return false;
    u += du;
    v += dv;
    du += w.ddu;
    dv += w.ddv;
  }
  return true;
}

// From a random point to another over n pixels, linear or (when it stays inside) bending.
Walk random_walk(std::mt19937& rng, const LitCase& c, int n) {
  std::uniform_int_distribution<int64_t> ur(0, (int64_t(c.width) << 16) - 1), vr(0, (int64_t(c.height) << 16) - 1);
  const int steps = n > 1 ? n - 1 : 1;
  const int64_t u0 = ur(rng), v0 = vr(rng), u1 = ur(rng), v1 = vr(rng);
  Walk w{n, int32_t(u0), int32_t(v0), int32_t((u1 - u0) / steps), int32_t((v1 - v0) / steps), 0, 0};
  if (n > 2 && rng() % 2) {
    Walk b = w;
    b.ddu = int32_t(int64_t(rng() % 2001) - 1000);
    b.ddv = int32_t(int64_t(rng() % 2001) - 1000);
    if (walk_valid(c, b)) return b;
  }
  return w;
}

uint8_t closed_form(const LitCase& c, int32_t u, int32_t v) {
  const int U = u >> 16, V = v >> 16;
  const int shade = sb::render::shade_at(c.grid.data(), c.grid_width, U, V, c.mip);
  const uint8_t texel = c.texels[size_t(pos_mod(V + c.toff, c.th)) * c.tw + pos_mod(U + c.soff, c.tw)];
  return c.colormap[size_t(shade >> 8) * 256 + texel];
}

// Runs the scalar reference (checked against the closed form) and every other variant.
void check(const LitCase& c, const Walk& w, const char* what, bool closed = true, bool prepared = true) {
  ASSERT_TRUE(walk_valid(c, w)) << what;
  const LitSpanSource src = c.src(prepared);
  std::vector<uint8_t> want(size_t(w.n) + 2 * kGuard, kGuardByte);
  sb::simd::lit_span_scalar(want.data() + kGuard, w.n, src, w.u, w.v, w.du, w.dv, w.ddu, w.ddv);
  for (int i = 0; i < kGuard; ++i) {
    ASSERT_EQ(want[size_t(i)], kGuardByte);
    ASSERT_EQ(want[size_t(kGuard + w.n + i)], kGuardByte);
  }
  if (closed) {
    int64_t u = w.u, v = w.v, du = w.du, dv = w.dv;
    for (int k = 0; k < w.n; ++k) {
      ASSERT_EQ(want[size_t(kGuard + k)], closed_form(c, int32_t(u), int32_t(v)))
          << what << ": scalar vs closed form at pixel " << k << " mip " << c.mip;
      u += du;
      v += dv;
      du += w.ddu;
      dv += w.ddv;
    }
  }
  for (int i = 1; i < sb::simd::lit_span_variant_count(); ++i) {
    const sb::simd::LitSpanVariant var = sb::simd::lit_span_variant(i);
    if (!var.supported) continue;
    std::vector<uint8_t> got(want.size(), kGuardByte);
    var.fn(got.data() + kGuard, w.n, src, w.u, w.v, w.du, w.dv, w.ddu, w.ddv);
    ASSERT_EQ(want, got) << var.name << " " << what << ": n " << w.n << " mip " << c.mip << " surface " << c.width
                         << "x" << c.height << " texture " << c.tw << "x" << c.th << " offsets " << c.soff << ","
                         << c.toff << " u " << w.u << " v " << w.v << " du " << w.du << " dv " << w.dv;
  }
}

TEST(AsmLitSpan, VariantsListed) {
  ASSERT_GE(sb::simd::lit_span_variant_count(), 2);
  EXPECT_STREQ(sb::simd::lit_span_variant(0).name, "scalar");
  for (int i = 0; i < sb::simd::lit_span_variant_count(); ++i) {
    const auto v = sb::simd::lit_span_variant(i);
    std::printf("[ asm      ] lit_span: variant %s %s\n", v.name, v.supported ? "runs" : "SKIPPED (CPU lacks it)");
  }
  EXPECT_EQ(sb::simd::lit_span_variant(99).fn, nullptr);
}

TEST(AsmLitSpan, EveryVariantMatchesScalarAndClosedForm) {
  std::mt19937 rng(4242);
  const int lengths[] = {0, 1, 2, 15, 16, 17, 33, 320, 1920};
  struct Tex {
    int w, h;
  };
  const Tex texs[] = {{16, 16}, {64, 64}, {128, 32}, {48, 80}, {96, 16}, {16, 144}, {256, 256}, {4096, 16}};
  const int offsets[] = {0, 16, -16, -1024, 4080, 65536};
  int cases = 0;
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    for (const Tex& t : texs) {
      for (int light = 0; light < 4; ++light) {
        const int width = b * int(1 + rng() % 24), height = b * int(1 + rng() % 24);
        const int soff = offsets[rng() % 6] >> mip, toff = offsets[rng() % 6] >> mip;
        const LitCase c = make_case(rng, mip, width, height, t.w >> mip, t.h >> mip, soff, toff, light);
        for (int n : lengths) {
          check(c, random_walk(rng, c, n), "random");
          const int32_t umax = (width << 16) - 1, vmax = (height << 16) - 1;
          const int steps = n > 1 ? n - 1 : 1;
          check(c, Walk{n, 0, vmax, umax / steps, -vmax / steps, 0, 0}, "corner to corner");
          check(c, Walk{n, umax, vmax, 0, 0, 0, 0}, "last texel");
          check(c, random_walk(rng, c, n), "unprepared (fallback)", true, false);
          cases += 4;
        }
      }
    }
  }
  // Odd sizes the engine never makes but the contract allows (any size, any offset).
  for (int rep = 0; rep < 200; ++rep) {
    const int mip = int(rng() % 4);
    const int tw = 1 + int(rng() % 300), th = 1 + int(rng() % 300);
    const int width = 1 + int(rng() % 300), height = 1 + int(rng() % 300);
    const int soff = int(rng() % 2000001) - 1000000, toff = int(rng() % 2001) - 1000;
    const LitCase c = make_case(rng, mip, width, height, tw, th, soff, toff, 0);
    check(c, random_walk(rng, c, 1 + int(rng() % 40)), "odd sizes");
    ++cases;
  }
  std::printf("[ asm      ] lit_span: %d cases compared\n", cases);
}

// The whole wrap range of the tuned variant: for every texture width 1..4096, surface
// columns 0..4095 at the largest reduced offset (tw - 1), one texel per pixel.
TEST(AsmLitSpan, WrapIsExactForEveryTextureWidth) {
  std::mt19937 rng(7);
  LitCase c = make_case(rng, 0, 4096, 16, 1, 1, 0, 0, 0);
  std::vector<uint8_t> row(4096);
  for (auto& x : row) x = uint8_t(rng());
  for (int tw = 1; tw <= 4096; ++tw) {
    c.tw = tw;
    c.th = 1;
    c.texels.assign(row.begin(), row.begin() + tw);
    c.soff = tw - 1 + (tw % 3 == 0 ? -3 * tw : 0);  // reduces to tw - 1 (sometimes from below 0)
    c.toff = -7;
    check(c, Walk{4096, 0, 5 << 16, 1 << 16, 0, 0, 0}, "wrap sweep", tw % 97 == 0);
    if (testing::Test::HasFatalFailure()) return;
  }
}

}  // namespace

namespace {

// A walk of n pixels whose coordinate crosses a cell boundary (B texels) between pixels p
// and p + 1 (p < 0: none), stepping d (16.16, may be negative) with second difference dd,
// starting near cell `cell`.
int32_t start_for_cross(int b, int cell, int p, int32_t d) {
  if (p < 0) return int32_t((int64_t(cell) * b << 16) + (b << 15));  // mid-cell
  // u_p just inside the boundary, u_{p+1} beyond it.
  const int64_t edge = int64_t(cell) * b << 16;
  const int64_t up = d >= 0 ? edge - 1 - (d > 1 ? int64_t(d) / 3 : 0) : edge + (d < -1 ? -int64_t(d) / 3 : 0);
  return int32_t(up - int64_t(p) * d);
}

}  // namespace

// asm/lit_span_a64.h (aarch64 neon): 16-pixel runs whose 8-pixel groups lie in one cell,
// cross one cell boundary in u, v or both (at the same or different pixels), two boundaries,
// step backwards, bend (second order, also changing direction within a group); every lane
// position of the crossing, every mip, textures up to and beyond 2^16 texels; n 16, 17, 31,
// 32, 48 (16-pixel blocks then the general path). Everywhere else the same variants too.
TEST(AsmLitSpan, RunsOf16AcrossCellBoundaries) {
  std::mt19937 rng(1616);
  struct Tex {
    int w, h;
  };
  const Tex texs[] = {{64, 64}, {256, 256}, {512, 256}, {16, 8}};
  int cases = 0;
  for (int mip = 0; mip < 4; ++mip) {
    const int b = 16 >> mip;
    for (const Tex& t : texs) {
      const int size = b * 40;
      const LitCase c = make_case(rng, mip, size, size, std::max(1, t.w >> mip), std::max(1, t.h >> mip),
                                  int(rng() % 64) - 32, int(rng() % 64) - 32, int(rng() % 4));
      for (int p = -1; p < 16; ++p) {
        for (int mode = 0; mode < 9; ++mode) {
          for (int n : {16, 17, 31, 32, 48}) {
            // Steps between 0.05 and 2 texels a pixel (mode 5: about B / 3, two crossings
            // in a group), signs by mode.
            const int32_t small = int32_t(3277 + rng() % 127795);
            int32_t du = small, dv = int32_t(rng() % 30000), ddu = 0, ddv = 0;
            int pu = p, pv = -1;
            switch (mode) {
              case 0: break;                                          // u crosses at p
              case 1: std::swap(du, dv); pu = -1; pv = p; break;      // v crosses at p
              case 2: dv = du; pv = p; break;                         // both at p
              case 3: pv = p < 0 ? -1 : (p + 5) % 16; dv = du; break; // both, other pixels
              case 4: du = -du; break;                                // backwards
              case 5: du = int32_t((b << 16) / 3 + rng() % 1000); break;
              case 6: ddu = int32_t(rng() % 4001) - 2000; ddv = int32_t(rng() % 4001) - 2000; break;
              case 7: du = int32_t(rng() % 20000) - 10000; ddu = du > 0 ? -int32_t(3000 + rng() % 2000)
                                                                         : int32_t(3000 + rng() % 2000); break;
              default: du = 0; dv = 0; ddu = int32_t(rng() % 2001) - 1000; ddv = 0; break;  // still, then drifting
            }
            const int cell = 12 + int(rng() % 8);
            Walk w{n, start_for_cross(b, cell, pu, du), start_for_cross(b, cell, pv, dv), du, dv, ddu, ddv};
            if (!walk_valid(c, w)) continue;
            check(c, w, "runs of 16 across cells", false);
            if (testing::Test::HasFatalFailure()) return;
            ++cases;
          }
        }
      }
    }
  }
  EXPECT_GT(cases, 2000);
  std::printf("[ asm      ] lit_span: %d runs across cell boundaries compared\n", cases);
}

// The last texel of the surface (u, v at the clamp edge) in 16-pixel runs, every mip, and
// bytes after a 16-pixel run untouched (check()'s guards).
TEST(AsmLitSpan, RunsOf16AtTheSurfaceEdge) {
  std::mt19937 rng(1717);
  for (int mip = 0; mip < 4; ++mip) {
    for (int rep = 0; rep < 40; ++rep) {
      const int b = 16 >> mip;
      const int width = b * int(1 + rng() % 20) - int(rng() % b), height = b * int(1 + rng() % 20) - int(rng() % b);
      const LitCase c = make_case(rng, mip, std::max(1, width), std::max(1, height), 64 >> mip, 32 >> mip, 5, -9,
                                  int(rng() % 4));
      const int32_t umax = (c.width << 16) - 1, vmax = (c.height << 16) - 1;
      for (int n : {16, 32}) {
        check(c, Walk{n, umax, vmax, 0, 0, 0, 0}, "last texel, still");
        const int32_t d = int32_t(rng() % 40000);
        if (int64_t(d) * (n - 1) <= umax) check(c, Walk{n, int32_t(umax - d * (n - 1)), vmax, d, 0, 0, 0}, "to the edge");
        if (int64_t(d) * (n - 1) <= vmax) check(c, Walk{n, umax, vmax, 0, -d, 0, 0}, "from the corner");
        if (testing::Test::HasFatalFailure()) return;
      }
    }
  }
}
