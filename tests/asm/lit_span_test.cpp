// The single-pass lit span kernel (asm/lit_span.h): the scalar reference against the closed
// form built from engine/render/surface_math.h (shade_at, positive-modulo texel), and every
// variant against the scalar reference, on random and edge inputs: span lengths 0..1920,
// every mip, power-of-two and other texture sizes, negative and large texture offsets,
// second-order steps, extreme light, and the whole range of the wrap (every texture width
// 16..4096 at the largest offset). Destinations carry guard bytes.
#include <gtest/gtest.h>

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
