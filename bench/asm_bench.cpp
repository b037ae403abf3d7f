// bench/asm_bench.cpp: every asm/ kernel x every variant this CPU runs, as ns per pixel
// (spans, palette) or per texel (surface builder), with the ratio to the scalar reference
// (scalar time / variant time: above 1 is faster). Medians of --benchmark_repetitions
// (default 5). Nothing here is pass/fail.
//
//   surface_span  perspective runs of 16 pixels (as the engine's walker calls the kernel),
//                 second-order steps, over 320- and 1920-pixel spans of a 64x64 and a
//                 256x256 surface; also a whole 1920-pixel span in one call (linear)
//   surface_block 64x64 and 256x256 surfaces (mip-0 extents) at mips 0..3, 64x64 texture
//   z_span        320 and 1920 pixels
//   expand_palette 320x200 at scales 1, 2, 3 (x3: 960x600 out, platform/sdl2's -scale 3) and
//                 1920x1080 at scale 1 (per source pixel)
//   alias_span    spans of 16, 48 and 320 pixels over a 296x194 skin, all visible and with
//                 alternate runs of 8 pixels hidden by the z buffer
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "asm/kernels.h"

namespace {

using sb::simd::Kernels;

std::vector<uint8_t> random_bytes(std::mt19937& rng, size_t n) {
  std::vector<uint8_t> b(n);
  for (auto& x : b) x = uint8_t(rng());
  return b;
}

// ---------------------------------------------------------------- cases

struct Run {
  int offset, n;
  int32_t u, v, du, dv, ddu, ddv;
};

// A plane seen in perspective: u = (a + b x) / (c + e x) along the span, likewise v, cut
// into runs of 16 with exact ends and second-order steps (falling back to linear where the
// bend would leave the run's ends), clamped to the surface.
std::vector<Run> perspective_runs(int pixels, int w, int h, double phase) {
  std::vector<Run> runs;
  const double umax = double((w << 16) - 1), vmax = double((h << 16) - 1);
  auto at = [&](double x, double* u, double* v) {
    const double zi = 1.0 + 2.5 * x / pixels;  // depth shrinks 3.5x across the span
    *u = std::clamp((0.05 + 0.9 * std::fmod(phase + x / pixels, 1.0)) * umax / zi, 0.0, umax);
    *v = std::clamp((0.1 + 0.8 * x / pixels) * vmax / zi, 0.0, vmax);
  };
  for (int x = 0; x < pixels; x += 16) {
    const int n = std::min(16, pixels - x);
    const int steps = n > 1 ? (n < 16 ? n - 1 : 16) : 1;
    double ua, va, ub, vb;
    at(x, &ua, &va);
    at(x + steps, &ub, &vb);
    Run r{x, n, int32_t(ua), int32_t(va), 0, 0, 0, 0};
    auto bend = [&](int32_t a, int32_t b, int32_t* d, int32_t* dd) {
      const int64_t delta = int64_t(b) - a;
      *d = int32_t(delta / steps);
      *dd = 0;
      const int64_t dd2 = -delta / (steps * 8);  // a gentle parabola
      const int64_t d0 = (delta - dd2 * steps * (steps - 1) / 2) / steps;
      const int64_t reach = d0 * steps + dd2 * steps * (steps - 1) / 2;
      const bool ok = delta >= 0 ? (d0 >= 0 && d0 + dd2 * (steps - 1) >= 0 && reach >= 0 && reach <= delta)
                                 : (d0 <= 0 && d0 + dd2 * (steps - 1) <= 0 && reach <= 0 && reach >= delta);
      if (ok) {
        *d = int32_t(d0);
        *dd = int32_t(dd2);
      }
    };
    bend(r.u, int32_t(ub), &r.du, &r.ddu);
    bend(r.v, int32_t(vb), &r.dv, &r.ddv);
    runs.push_back(r);
  }
  return runs;
}

void bm_surface_span(benchmark::State& state, const Kernels* k, int pixels, int size, bool one_call) {
  std::mt19937 rng(1);
  const std::vector<uint8_t> surf = random_bytes(rng, size_t(size) * size);
  std::vector<std::vector<Run>> spans;
  for (int i = 0; i < 8; ++i) spans.push_back(perspective_runs(pixels, size, size, 0.11 * i));
  std::vector<uint8_t> dest(static_cast<size_t>(pixels));
  const sb::simd::SurfaceSpanFn fn = k->surface_span;
  for (auto _ : state) {
    for (const auto& runs : spans) {
      if (one_call) {
        const int32_t du = int32_t(((size - 1) << 16) / pixels);
        fn(dest.data(), pixels, surf.data(), size, size, 0, 0, du, du / 2, 0, 0);
      } else {
        for (const Run& r : runs) fn(dest.data() + r.offset, r.n, surf.data(), size, size, r.u, r.v, r.du, r.dv, r.ddu, r.ddv);
      }
      benchmark::DoNotOptimize(dest.data());
      benchmark::ClobberMemory();
    }
  }
  state.counters["units"] = double(pixels) * double(spans.size());
}

void bm_surface_block(benchmark::State& state, const Kernels* k, int extent, int mip) {
  std::mt19937 rng(2);
  const int b = 16 >> mip, w = extent >> mip, h = extent >> mip;
  const int gw = extent / 16 + 1, gh = extent / 16 + 1;
  std::vector<uint16_t> grid(size_t(gw) * gh);
  for (auto& g : grid) g = uint16_t(64 + rng() % 0x3000);
  const std::vector<uint8_t> tex = random_bytes(rng, size_t(64 >> mip) * (64 >> mip));
  const std::vector<uint8_t> cm = random_bytes(rng, 64 * 256);
  std::vector<uint8_t> out(size_t(w) * h);
  (void)b;
  for (auto _ : state) {
    k->surface_block(grid.data(), gw, tex.data(), 64 >> mip, 64 >> mip, mip, 16 >> mip, -(32 >> mip), w, h, cm.data(),
                     out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.counters["units"] = double(w) * h;
}

void bm_z_span(benchmark::State& state, const Kernels* k, int pixels) {
  std::vector<uint16_t> z(size_t(pixels) * 8);
  for (auto _ : state) {
    for (int i = 0; i < 8; ++i)
      k->z_span(z.data() + size_t(i) * pixels, pixels, 0x12340000u + uint32_t(i) * 977u, 0x00012345u);
    benchmark::DoNotOptimize(z.data());
    benchmark::ClobberMemory();
  }
  state.counters["units"] = double(pixels) * 8;
}

void bm_expand_palette(benchmark::State& state, const Kernels* k, int w, int h, int scale) {
  std::mt19937 rng(3);
  const std::vector<uint8_t> src = random_bytes(rng, size_t(w) * h);
  uint32_t pal[256];
  for (auto& p : pal) p = rng();
  std::vector<uint32_t> dst(size_t(w) * scale * size_t(h) * scale);
  for (auto _ : state) {
    k->expand_palette(src.data(), w, w, h, pal, dst.data(), ptrdiff_t(w) * scale, scale);
    benchmark::DoNotOptimize(dst.data());
    benchmark::ClobberMemory();
  }
  state.counters["units"] = double(w) * h;
}

void bm_alias_span(benchmark::State& state, const Kernels* k, int len, bool half_hidden) {
  std::mt19937 rng(4);
  constexpr int kW = 296, kH = 194, kRow = 1920;
  const std::vector<uint8_t> skin = random_bytes(rng, size_t(kW) * kH), cm = random_bytes(rng, 64 * 256);
  std::vector<uint8_t> dest(kRow);
  std::vector<uint16_t> z(kRow);
  // Visible pixels tie on later repetitions (still visible); hidden ones stay hidden.
  for (int x = 0; x < kRow; ++x) z[size_t(x)] = half_hidden && (x / 8) % 2 ? 0xffff : 0;
  sb::simd::AliasSpan a{};
  a.s = 3 << 16;
  a.t = 150 << 16;
  a.light = 2 << 16;
  a.zi = 0x40000000u;
  a.ds = int32_t(((kW - 8) << 16) / len);
  a.dt = -int32_t((100 << 16) / len);
  a.dlight = int32_t((60 << 16) / len);
  a.dzi = 0x3000;
  const int spans = kRow / len;
  for (auto _ : state) {
    for (int i = 0; i < spans; ++i)
      k->alias_span(dest.data() + i * len, z.data() + i * len, len, skin.data(), kW, cm.data(), a);
    benchmark::DoNotOptimize(dest.data());
    benchmark::ClobberMemory();
  }
  state.counters["units"] = double(spans) * len;
}

// ---------------------------------------------------------------- table of medians

struct Cell {
  std::string kernel, variant;
  double ns_per_unit = 0;
};
std::vector<Cell> g_cells;

class MedianReporter : public benchmark::ConsoleReporter {
 public:
  using Run_ = benchmark::BenchmarkReporter::Run;
  void ReportRuns(const std::vector<Run_>& runs) override {
    for (const auto& r : runs) {
      if (r.run_type != Run_::RT_Aggregate || r.aggregate_name != "median") continue;
      const std::string name = r.benchmark_name();  // kernel/case/variant_median
      const auto it = r.counters.find("units");
      if (it == r.counters.end() || it->second.value <= 0) continue;
      const size_t slash = name.rfind('/');
      std::string variant = name.substr(slash + 1);
      variant = variant.substr(0, variant.find('_'));
      g_cells.push_back({name.substr(0, slash), variant, r.GetAdjustedRealTime() / it->second.value});
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

void print_table() {
  std::printf("\nasm kernels: median ns per pixel (texel for surface_block; source pixel for expand_palette)\n");
  std::printf("and speed-up over scalar (scalar time / variant time). Tuned choice: %s\n\n",
              sb::simd::describe_active());
  std::printf("| %-40s | %-7s | %10s | %8s |\n", "kernel / case", "variant", "ns/unit", "x scalar");
  std::printf("|%s|%s|%s|%s|\n", std::string(42, '-').c_str(), std::string(9, '-').c_str(),
              std::string(12, '-').c_str(), std::string(10, '-').c_str());
  std::map<std::string, double> scalar;
  for (const Cell& c : g_cells)
    if (c.variant == "scalar") scalar[c.kernel] = c.ns_per_unit;
  for (const Cell& c : g_cells) {
    const double s = scalar.count(c.kernel) ? scalar[c.kernel] : 0.0;
    std::printf("| %-40s | %-7s | %10.3f | %8.2f |\n", c.kernel.c_str(), c.variant.c_str(), c.ns_per_unit,
                s > 0 && c.ns_per_unit > 0 ? s / c.ns_per_unit : 0.0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> args(argv, argv + argc);
  std::string reps = "--benchmark_repetitions=5", report = "--benchmark_report_aggregates_only=true";
  std::string mintime = "--benchmark_min_time=0.05";
  args.insert(args.begin() + 1, {reps.data(), report.data(), mintime.data()});  // the command line may override
  int n = int(args.size());
  benchmark::Initialize(&n, args.data());

  std::vector<const Kernels*> variants;
  for (int i = 0; i < sb::simd::variant_count(); ++i) {
    const sb::simd::Variant v = sb::simd::variant(i);
    if (!v.kernels || std::strcmp(v.kernels->name, "tuned") == 0) continue;
    if (!v.supported) {
      std::printf("variant %s: skipped (this CPU lacks it)\n", v.kernels->name);
      continue;
    }
    variants.push_back(v.kernels);
  }
  auto reg = [](const std::string& name, auto fn) { benchmark::RegisterBenchmark(name.c_str(), fn)->Unit(benchmark::kNanosecond); };
  for (const Kernels* k : variants) {
    const std::string v = k->name;
    reg("surface_span/runs16_320px_surf64/" + v, [k](benchmark::State& s) { bm_surface_span(s, k, 320, 64, false); });
    reg("surface_span/runs16_320px_surf256/" + v, [k](benchmark::State& s) { bm_surface_span(s, k, 320, 256, false); });
    reg("surface_span/runs16_1920px_surf256/" + v, [k](benchmark::State& s) { bm_surface_span(s, k, 1920, 256, false); });
    reg("surface_span/one_call_1920px_surf256/" + v, [k](benchmark::State& s) { bm_surface_span(s, k, 1920, 256, true); });
  }
  for (const Kernels* k : variants)
    for (int extent : {64, 256})
      for (int mip = 0; mip < 4; ++mip)
        reg("surface_block/surf" + std::to_string(extent) + "_mip" + std::to_string(mip) + "/" + k->name,
            [k, extent, mip](benchmark::State& s) { bm_surface_block(s, k, extent, mip); });
  for (const Kernels* k : variants)
    for (int px : {320, 1920})
      reg("z_span/" + std::to_string(px) + "px/" + k->name, [k, px](benchmark::State& s) { bm_z_span(s, k, px); });
  for (const Kernels* k : variants) {
    reg(std::string("expand_palette/320x200_x1/") + k->name, [k](benchmark::State& s) { bm_expand_palette(s, k, 320, 200, 1); });
    reg(std::string("expand_palette/320x200_x2/") + k->name, [k](benchmark::State& s) { bm_expand_palette(s, k, 320, 200, 2); });
    reg(std::string("expand_palette/320x200_x3/") + k->name, [k](benchmark::State& s) { bm_expand_palette(s, k, 320, 200, 3); });
    reg(std::string("expand_palette/1920x1080_x1/") + k->name, [k](benchmark::State& s) { bm_expand_palette(s, k, 1920, 1080, 1); });
  }
  for (const Kernels* k : variants) {
    if (std::strncmp(k->name, "avx2", 4) == 0) continue;  // the avx2 tables hold the sse2 alias span
    for (int len : {16, 48, 320})
      for (bool hid : {false, true})
        reg("alias_span/" + std::to_string(len) + "px" + (hid ? "_half_hidden/" : "_visible/") + k->name,
            [k, len, hid](benchmark::State& s) { bm_alias_span(s, k, len, hid); });
  }
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  std::stable_sort(g_cells.begin(), g_cells.end(), [](const Cell& a, const Cell& b) { return a.kernel < b.kernel; });
  print_table();
  return 0;
}
