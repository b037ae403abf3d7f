// The engine's drawers through asm/ kernels: engine/render's lit-surface span drawer, z fill
// and surface builder give the same bytes with the tuned kernels as with
// simd::force_scalar(true) (the scalar references), over random perspective gradients
// (including steep, clamped and edge-on ones), span lengths 0..1920 and every mip level.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include "asm/kernels.h"
#include "engine/render/span_draw.h"
#include "engine/render/surface_cache.h"

namespace {

using sb::render::Span;

struct ScalarScope {  // forces the scalar references for its lifetime
  bool before = sb::simd::scalar_forced();
  explicit ScalarScope(bool on) { sb::simd::force_scalar(on); }
  ~ScalarScope() { sb::simd::force_scalar(before); }
};

struct Frame {
  int w, h;
  std::vector<uint8_t> pixels;
  std::vector<uint16_t> z;
  sb::Framebuffer fb;
  Frame(int width, int height) : w(width), h(height), pixels(size_t(width) * height, 0), z(size_t(width) * height, 0) {
    fb.pixels = pixels.data();
    fb.width = w;
    fb.height = h;
    fb.stride = w;
    fb.zbuffer = z.data();
  }
};

// A random plane in view: 1/z positive over most of the screen, texture coordinates
// spanning a few surfaces' worth (the drawer clamps).
sb::render::SpanGradients random_gradients(std::mt19937& rng, int w, int h, int sw, int sh) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  sb::render::SpanGradients g{};
  const double depth = 0.002 + 0.05 * (r(rng) + 1.0);
  g.zix = depth * r(rng) / w;
  g.ziy = depth * r(rng) / h;
  g.zi0 = depth + std::fabs(g.zix) * w + std::fabs(g.ziy) * h;  // positive everywhere
  if (rng() % 5 == 0) g.zi0 = depth * r(rng);                     // sometimes edge-on or behind
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

TEST(AsmEnginePaths, SurfaceSpansAndZMatchScalar) {
  std::printf("[ asm      ] tuned: %s\n", sb::simd::describe_active());
  std::mt19937 rng(42);
  const int W = 1920, H = 24;
  int spans_drawn = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int sw = 2 << (rng() % 9), sh = 2 << (rng() % 9);  // 2..512
    std::vector<uint8_t> surface(size_t(sw) * sh);
    for (auto& b : surface) b = uint8_t(rng());
    const sb::render::SpanGradients g = random_gradients(rng, W, H, sw, sh);
    std::vector<Span> spans;
    const int lengths[] = {0, 1, 15, 16, 17, 33, 320, 1920};
    for (int y = 0; y < H; ++y) {
      const int n = y < 8 ? lengths[y] : int(rng() % (W + 1));
      const int x = int(rng() % (W - n + 1));
      spans.push_back(Span{int16_t(x), int16_t(y), int16_t(n), 0});
    }
    Frame ref(W, H), got(W, H);
    {
      ScalarScope s(true);
      sb::render::draw_surface_spans(spans.data(), uint32_t(spans.size()), g, surface.data(), sw, sh, ref.fb);
    }
    {
      ScalarScope s(false);
      sb::render::draw_surface_spans(spans.data(), uint32_t(spans.size()), g, surface.data(), sw, sh, got.fb);
    }
    ASSERT_EQ(ref.pixels, got.pixels) << "trial " << trial << " surface " << sw << "x" << sh;
    ASSERT_EQ(ref.z, got.z) << "trial " << trial;
    spans_drawn += int(spans.size());
  }
  std::printf("[ asm      ] %d spans drawn both ways, identical pixels and z\n", spans_drawn);
}

TEST(AsmEnginePaths, BuildSurfaceMatchesScalarEveryMip) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int tw = 16 * (1 + int(rng() % 16)), th = 16 * (1 + int(rng() % 16));
    std::vector<uint8_t> texels;
    for (int m = 0; m < 4; ++m) texels.resize(texels.size() + size_t(tw >> m) * (th >> m));
    for (auto& b : texels) b = uint8_t(rng());
    sb::Texture tex{};
    tex.width = uint32_t(tw);
    tex.height = uint32_t(th);
    size_t off = 0;
    for (int m = 0; m < 4; ++m) {
      tex.mips[m] = texels.data() + off;
      off += size_t(tw >> m) * (th >> m);
    }
    const int ew = 16 * (1 + int(rng() % 64)), eh = 16 * (1 + int(rng() % 64));
    const int smin = (int(rng() % 200) - 100) * 16, tmin = (int(rng() % 200) - 100) * 16;
    const int gw = ew / 16 + 1, gh = eh / 16 + 1;
    std::vector<uint16_t> grid(size_t(gw) * gh);
    for (auto& v : grid) v = uint16_t(64 + rng() % (63 * 256 + 192));
    std::vector<uint8_t> colormap(64 * 256);
    for (auto& b : colormap) b = uint8_t(rng());
    for (int mip = 0; mip < 4; ++mip) {
      const int w = ew >> mip, h = eh >> mip;
      std::vector<uint8_t> ref(size_t(w) * h), got(size_t(w) * h);
      {
        ScalarScope s(true);
        sb::render::build_surface(grid.data(), gw, tex, mip, smin, tmin, w, h, colormap.data(), ref.data());
      }
      {
        ScalarScope s(false);
        sb::render::build_surface(grid.data(), gw, tex, mip, smin, tmin, w, h, colormap.data(), got.data());
      }
      ASSERT_EQ(ref, got) << "trial " << trial << " mip " << mip << " surface " << w << "x" << h;
    }
  }
}

}  // namespace
