// bench/lit_span_bench.cpp: the single-pass lit span kernel (asm/lit_span.h), every variant
// this CPU runs, against the cached path's span kernel (surface_span, scalar and tuned), as
// ns per pixel and the ratio to the cached span (lit / surface_span: how much more one
// pixel costs when texture and light are combined while drawing).
//
// Runs of 16 pixels with second-order steps (as the engine's walker calls the kernels), about
// one texel per pixel, over a 256x256 surface: texture 64x64 (power of two) and 48x80 (not),
// mips 0 and 2. Each figure is the fastest of many short trials (the minimum is what a
// shared machine disturbs least). Plain chrono timing, no framework: it needs only
// starbow_asm, so it also runs in cross builds (qemu-user). Nothing here is pass/fail.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "asm/kernels.h"
#include "asm/lit_span.h"

namespace {

using namespace sb::simd;

constexpr int kSurface = 256, kPixels = 1920, kRows = 32, kTrials = 300;

struct Scene {
  int mip, tw, th;
  std::vector<uint8_t> surface, texels, colormap;
  std::vector<uint16_t> grid;
  std::vector<uint32_t> wide;
  LitSpanSource src;
  Scene(int mip_, int tw_, int th_) : mip(mip_), tw(tw_ >> mip_), th(th_ >> mip_) {
    std::mt19937 rng(5);
    const int w = kSurface >> mip;
    surface.resize(size_t(w) * w);
    texels.resize(size_t(tw) * th);
    colormap.resize(64 * 256);
    for (auto& x : surface) x = uint8_t(rng());
    for (auto& x : texels) x = uint8_t(rng());
    for (auto& x : colormap) x = uint8_t(rng());
    const int gw = kSurface / 16 + 1;
    grid.resize(size_t(gw) * gw);
    for (auto& g : grid) g = uint16_t(64 + rng() % 0x3000);
    wide.resize(grid.size());
    src.texels = texels.data();
    src.tex_width = tw;
    src.tex_height = th;
    src.soff = 16 >> mip;
    src.toff = -(32 >> mip);
    src.grid = grid.data();
    src.grid_width = gw;
    src.mip = mip;
    src.width = src.height = w;
    src.colormap = colormap.data();
    lit_span_prepare(src, int(grid.size()), wide.data());
  }
};

// Fastest ns per pixel of `draw(dest, x, row)` over kRows rows of kPixels in 16-pixel runs.
template <class Draw>
double time_runs(const Draw& draw) {
  std::vector<uint8_t> dest(kPixels);
  double best = 1e30;
  unsigned sink = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int row = 0; row < kRows; ++row) {
      for (int x = 0; x < kPixels; x += 16) draw(dest.data() + x, x, row);
      sink += dest[size_t(row)];
    }
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(kRows) * kPixels));
  }
  if (sink == 0xffffffffu) std::printf(" ");
  return best;
}

// Run start and steps: about one texel per pixel across the surface, a gentle bend.
struct Steps {
  int32_t u, v, du, dv, ddu, ddv;
};
Steps steps_at(const Scene& s, int x, int row) {
  const int w = kSurface >> s.mip;
  const int32_t u = int32_t((x % (w - 20)) << 16), v = int32_t(((row * 7) % (w - 20)) << 16);
  return {u, v, 0xf000, 0x1800, -60, 20};
}

}  // namespace

int main() {
  std::printf("lit_span: ns per pixel, runs of 16, fastest of %d trials; ratio = variant / cached span (tuned)\n",
              kTrials);
  std::printf("active: lit_span=%s; %s\n\n", lit_span_active_name(), describe_active());
  std::printf("| texture | mip | kernel | ns/pixel | / cached span |\n|---|---|---|---|---|\n");
  struct Case {
    int tw, th, mip;
  };
  for (const Case& c : {Case{64, 64, 0}, Case{64, 64, 2}, Case{48, 80, 0}, Case{48, 80, 2}}) {
    const Scene s(c.mip, c.tw, c.th);
    const int w = kSurface >> c.mip;
    const SurfaceSpanFn tuned_span = active().surface_span;
    const double span = time_runs([&](uint8_t* d, int x, int row) {
      const Steps t = steps_at(s, x, row);
      tuned_span(d, 16, s.surface.data(), w, w, t.u, t.v, t.du, t.dv, t.ddu, t.ddv);
    });
    std::printf("| %dx%d | %d | surface_span (cached path) | %.2f | 1.00 |\n", c.tw, c.th, c.mip, span);
    for (int i = 0; i < lit_span_variant_count(); ++i) {
      const LitSpanVariant v = lit_span_variant(i);
      if (!v.supported) {
        std::printf("| %dx%d | %d | lit_span %s | skipped (CPU lacks it) | |\n", c.tw, c.th, c.mip, v.name);
        continue;
      }
      const double ns = time_runs([&](uint8_t* d, int x, int row) {
        const Steps t = steps_at(s, x, row);
        v.fn(d, 16, s.src, t.u, t.v, t.du, t.dv, t.ddu, t.ddv);
      });
      std::printf("| %dx%d | %d | lit_span %s | %.2f | %.2f |\n", c.tw, c.th, c.mip, v.name, ns, ns / span);
    }
  }
  return 0;
}
