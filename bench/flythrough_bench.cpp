// bench/flythrough_bench.cpp: the world renderer over the fixed flythrough path
// (engine/host/camera_path.h) of start, lq_e0m1 and lq_e1m1 at four resolutions.
//
// One benchmark run = the same 300 path frames in order, from a cold surface cache
// (as after a map load), each frame timed alone (manual time). Figures:
//   ms_median     median milliseconds per frame
//   ns_per_pixel  median frame time / pixels
//   cycles_px     ns_per_pixel x CPU GHz from /proc/cpuinfo (estimate; 0 when unknown)
//   mem_high_MiB  high-water of the whole block in use (all regions) for that resolution
//   frame_high_KiB, cache_high_KiB  the per-frame arena and surface cache high-water
// Nothing here is pass/fail. `--markdown=FILE` also writes the table as markdown
// (bench/run_bench.sh uses it). Content from STARBOW_QUAKE_DIR (env or CMake);
// maps that are absent are skipped with a message.
//
// Paths and light (issue 4): every map x resolution runs with the world drawn through the
// surface cache ("cached") and single pass ("single", RenderInputs::single_pass), each with
// light styles animating ("animated": styled surfaces rebuild in the cached path whenever a
// style value steps, 10 times a second), all styles normal ("static"), and every style
// value changing every frame ("dynamic": every lit surface rebuilds every frame in the
// cached path, as under dynamic lights that touch everything in view). Choose with
//   --paths=cached,single   --styles=animated,static,dynamic   (defaults: both paths,
//   animated and static)
// With both paths one run is "paired": each path frame is drawn by both, back to back (the
// single pass never touches the cache, so the cached path's history is unchanged). The
// second table gives single / cached per map, resolution and light (below 1: single wins).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "engine/core/log.h"
#include "engine/host/camera_path.h"
#include "engine/host/content.h"
#include "engine/host/lightstyles.h"
#include "engine/render/render.h"
#include "platform/common/platform.h"

namespace {

using namespace sb;

constexpr int kPathFrames = 300;
constexpr size_t kBlockMiB = 160;

struct Row {
  std::string map;
  int width = 0, height = 0;
  bool single_pass = false;
  int light = 0;  // Light
  double ms_median = 0, ms_worst = 0, ns_per_pixel = 0, cycles_per_pixel = 0;
  double mem_high_mib = 0, frame_high_kib = 0, cache_high_kib = 0;
};
std::vector<Row> g_rows;
std::string g_quake_dir;
double g_mhz = 0.0;
void* g_block = nullptr;

void quiet_sink(void*, LogLevel level, const char* line) {
  if (level != LogLevel::Info) std::fprintf(stderr, "%s\n", line);
}

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Which paths one run measures. Paired: every path frame is drawn by both paths, back to
// back, alternating which goes first; the single-pass frames never touch the surface cache,
// so the cached path sees the same cache history as alone. Pairing cancels most of the
// noise of a shared machine from the single / cached ratio.
enum class Paths { kCached, kSingle, kPaired };
enum Light { kAnimated, kStatic, kDynamic };
const char* const kLightNames[] = {"animated", "static", "dynamic"};

// Median of the per-frame ratios single / cached, per paired run (same order as g_rows' pairs).
struct PairRatio {
  std::string map;
  int width = 0, height = 0;
  int light = 0;
  double median_ratio = 0;
};
std::vector<PairRatio> g_pair_ratios;

void flythrough(benchmark::State& state, std::string map, int width, int height, Paths paths, int light) {
  static mem::MemorySystem memory;  // re-initialised per run: fresh high-water marks
  static fs::FileSystem files;
  static uint8_t palette[kPaletteBytes];
  static uint8_t colormap[kColormapBytes];
  char error[256];
  if (!memory.init(g_block, kBlockMiB * mem::kMiB, error, sizeof error)) {
    state.SkipWithError(error);
    return;
  }
  Status s = host::open_search_path(files, g_quake_dir.c_str(), "lq1", "lq1", memory.permanent);
  if (s) s = host::load_palette_and_colormap(files, memory.scratch, palette, colormap);
  Result<BspWorld*> world = s ? host::load_world(files, map.c_str(), memory) : Result<BspWorld*>(s.error());
  if (!world) {
    state.SkipWithError(world.message());
    return;
  }
  Result<host::CameraPath> path = host::build_camera_path(*world.value(), memory.level);
  Framebuffer fb;
  fb.pixels = memory.permanent.push_array<uint8_t>(size_t(width) * height, "framebuffer");
  fb.zbuffer = memory.permanent.push_array<uint16_t>(size_t(width) * height, "zbuffer");
  fb.width = fb.stride = width;
  fb.height = height;
  if (!path || !fb.pixels || !fb.zbuffer) {
    state.SkipWithError("out of memory setting up the benchmark");
    return;
  }
  int styles[kMaxLightStyleSlots];
  std::vector<double> times[2];  // [0] cached, [1] single pass; milliseconds per frame
  for (auto& t : times) t.reserve(kPathFrames);
  int frame = 0;
  for (auto _ : state) {
    RenderInputs in;
    in.world = world.value();
    in.view = host::camera_path_view(path.value(), frame % kPathFrames, kPathFrames, 90.0f);
    in.time = frame * (1.0 / 30.0);
    host::light_styles_at(in.time, light == kAnimated, styles);
    if (light == kDynamic) host::light_styles_every_frame(unsigned(frame), styles);
    in.lightstyles = styles;
    in.colormap = colormap;
    double seconds = 0.0;
    bool failed = false;
    for (int k = 0; k < 2 && !failed; ++k) {
      const int which = paths == Paths::kPaired ? (k + frame) % 2 : (paths == Paths::kSingle ? 1 : 0);
      if (paths != Paths::kPaired && k == 1) break;
      in.single_pass = which == 1;
      auto t0 = std::chrono::steady_clock::now();
      memory.begin_frame();
      Status r = render_world(in, fb, memory, nullptr);
      auto t1 = std::chrono::steady_clock::now();
      if (!r) {
        state.SkipWithError(r.message());
        failed = true;
        break;
      }
      const double sec = std::chrono::duration<double>(t1 - t0).count();
      seconds += sec;
      times[which].push_back(sec * 1000.0);
    }
    if (failed) break;
    state.SetIterationTime(seconds);
    ++frame;
  }
  // Everything in use at its peak: the arenas' high-water marks and the cache's.
  const double frame_high = double(std::max(memory.frame().high_water(), memory.previous_frame().high_water()));
  const double cache_high = double(memory.cache.stats().high_water);
  for (int which = 0; which < 2; ++which) {
    if (times[which].empty()) continue;
    Row row;
    row.map = map;
    row.width = width;
    row.height = height;
    row.single_pass = which == 1;
    row.light = light;
    row.ms_median = median_of(times[which]);
    row.ms_worst = *std::max_element(times[which].begin(), times[which].end());
    row.ns_per_pixel = row.ms_median * 1e6 / (double(width) * height);
    row.cycles_per_pixel = g_mhz > 0 ? row.ns_per_pixel * g_mhz / 1000.0 : 0.0;
    const double cache = which == 0 ? cache_high : 0.0;  // the single pass uses no cache
    row.mem_high_mib = (double(memory.permanent.high_water()) + double(memory.level.high_water()) + cache +
                        2 * frame_high + double(memory.scratch.high_water())) / double(mem::kMiB);
    row.frame_high_kib = frame_high / 1024.0;
    row.cache_high_kib = cache / 1024.0;
    const char* tag = which == 0 ? "cached_" : "single_";
    state.counters[std::string(tag) + "ms_median"] = row.ms_median;
    state.counters[std::string(tag) + "ms_worst"] = row.ms_worst;
    state.counters[std::string(tag) + "ns_per_pixel"] = row.ns_per_pixel;
    state.counters[std::string(tag) + "mem_high_MiB"] = row.mem_high_mib;
    g_rows.push_back(row);
  }
  if (!times[0].empty() && times[0].size() == times[1].size()) {
    std::vector<double> ratios(times[0].size());
    for (size_t i = 0; i < ratios.size(); ++i) ratios[i] = times[0][i] > 0 ? times[1][i] / times[0][i] : 0.0;
    const double r = median_of(ratios);
    state.counters["single_over_cached"] = r;
    g_pair_ratios.push_back(PairRatio{map, width, height, light, r});
  }
}

std::string markdown_table() {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "CPU: %.0f MHz (from /proc/cpuinfo; cycles/pixel = ns/pixel x GHz, an estimate)\n\n", g_mhz);
  out += line;
  out += "| map | resolution | path | light styles | ms/frame (median) | worst ms | ns/pixel | est. cycles/pixel | "
         "memory high-water MiB | frame arena KiB | surface cache KiB |\n";
  out += "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : g_rows) {
    std::snprintf(line, sizeof line, "| %s | %dx%d | %s | %s | %.3f | %.3f | %.2f | %.1f | %.1f | %.0f | %.0f |\n",
                  r.map.c_str(), r.width, r.height, r.single_pass ? "single" : "cached",
                  kLightNames[r.light], r.ms_median, r.ms_worst, r.ns_per_pixel, r.cycles_per_pixel,
                  r.mem_high_mib, r.frame_high_kib, r.cache_high_kib);
    out += line;
  }
  // Single pass against cached, where both ran with the same map, resolution and light.
  std::string ratios;
  for (const Row& c : g_rows) {
    if (c.single_pass) continue;
    for (const Row& s : g_rows) {
      if (!s.single_pass || s.map != c.map || s.width != c.width || s.height != c.height || s.light != c.light)
        continue;
      const double ratio = c.ms_median > 0 ? s.ms_median / c.ms_median : 0.0;
      double per_frame = 0.0;  // from a paired run, when there was one
      for (const PairRatio& p : g_pair_ratios)
        if (p.map == c.map && p.width == c.width && p.height == c.height && p.light == c.light)
          per_frame = p.median_ratio;
      const double r = per_frame > 0 ? per_frame : ratio;
      char pf[32] = "-";
      if (per_frame > 0) std::snprintf(pf, sizeof pf, "%.2f", per_frame);
      const double worst = c.ms_worst > 0 ? s.ms_worst / c.ms_worst : 0.0;
      std::snprintf(line, sizeof line, "| %s | %dx%d | %s | %.3f | %.3f | %.2f | %s | %.2f | %s |\n",
                    c.map.c_str(), c.width, c.height, kLightNames[c.light], c.ms_median, s.ms_median, ratio, pf,
                    worst, r < 0.97 ? "single" : r > 1.03 ? "cached" : "even");
      ratios += line;
    }
  }
  if (!ratios.empty()) {
    out += "\nSingle pass / cached: ratio of the median ms per frame, and (paired runs: both paths draw every "
           "path frame back to back) the median of the per-frame ratios, which shared-machine noise disturbs "
           "least. Below 1: single pass is faster; within 3%: even.\n\n";
    out += "| map | resolution | light styles | cached ms | single ms | single / cached (medians) | "
           "single / cached (per frame) | single / cached (worst frame) | faster (median) |\n";
    out += "|---|---|---|---|---|---|---|---|---|\n";
    out += ratios;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string markdown_path, paths = "cached,single", light = "animated,static";
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--markdown=", 11) == 0)
      markdown_path = argv[i] + 11;
    else if (std::strncmp(argv[i], "--paths=", 8) == 0)
      paths = argv[i] + 8;
    else if (std::strncmp(argv[i], "--styles=", 9) == 0)
      light = argv[i] + 9;
    else
      args.push_back(argv[i]);
  }
  int bargc = int(args.size());
  benchmark::Initialize(&bargc, args.data());
  set_log_sink(quiet_sink, nullptr);

  const char* env = std::getenv("STARBOW_QUAKE_DIR");
  g_quake_dir = env && *env ? env : STARBOW_QUAKE_DIR;
  g_mhz = platform::cpu_mhz();
  g_block = std::aligned_alloc(64, kBlockMiB * mem::kMiB);
  const int res[][2] = {{320, 200}, {640, 480}, {1280, 720}, {1920, 1080}};
  int registered = 0;
  for (const char* map : {"start", "lq_e0m1", "lq_e1m1"}) {
    std::string file = g_quake_dir + "/lq1/maps/" + map + ".bsp";
    if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
      std::fclose(f);
    } else {
      std::fprintf(stderr, "skipping %s: %s not found (set STARBOW_QUAKE_DIR)\n", map, file.c_str());
      continue;
    }
    for (const auto& r : res) {
      for (int lm = kAnimated; lm <= kDynamic; ++lm) {
        const char* light_name = kLightNames[lm];
        if (light.find(light_name) == std::string::npos) continue;
        const bool cached = paths.find("cached") != std::string::npos;
        const bool single = paths.find("single") != std::string::npos;
        if (!cached && !single) continue;
        const Paths which = cached && single ? Paths::kPaired : cached ? Paths::kCached : Paths::kSingle;
        const char* path = which == Paths::kPaired ? "paired" : cached ? "cached" : "single";
        std::string name = std::string("flythrough/") + map + "/" + std::to_string(r[0]) + "x" +
                           std::to_string(r[1]) + "/" + path + "/" + light_name;
        benchmark::RegisterBenchmark(name.c_str(), flythrough, std::string(map), r[0], r[1], which, lm)
            ->Iterations(kPathFrames)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        ++registered;
      }
    }
  }
  if (registered == 0) std::fprintf(stderr, "no maps found: nothing to measure\n");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::string table = markdown_table();
  std::printf("\n%s", table.c_str());
  if (!markdown_path.empty()) {
    if (std::FILE* f = std::fopen(markdown_path.c_str(), "w")) {
      std::fprintf(f, "# Starbow flythrough benchmark\n\n");
      std::fprintf(f, "%d path frames per row (engine/host/camera_path.h), cold surface cache at the start, one "
                      "core. Times are for comparing, never pass/fail.\n\n", kPathFrames);
      std::fputs(table.c_str(), f);
      std::fclose(f);
    }
  }
  std::free(g_block);
  return 0;
}
