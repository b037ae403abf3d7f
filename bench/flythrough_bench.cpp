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

void flythrough(benchmark::State& state, std::string map, int width, int height) {
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
  std::vector<double> times;
  times.reserve(kPathFrames);
  int frame = 0;
  for (auto _ : state) {
    RenderInputs in;
    in.world = world.value();
    in.view = host::camera_path_view(path.value(), frame % kPathFrames, kPathFrames, 90.0f);
    in.time = frame * (1.0 / 30.0);
    host::light_styles_at(in.time, true, styles);
    in.lightstyles = styles;
    in.colormap = colormap;
    auto t0 = std::chrono::steady_clock::now();
    memory.begin_frame();
    Status r = render_world(in, fb, memory, nullptr);
    auto t1 = std::chrono::steady_clock::now();
    if (!r) {
      state.SkipWithError(r.message());
      break;
    }
    double seconds = std::chrono::duration<double>(t1 - t0).count();
    state.SetIterationTime(seconds);
    times.push_back(seconds * 1000.0);
    ++frame;
  }
  if (times.empty()) return;
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  size_t n = sorted.size();
  Row row;
  row.map = map;
  row.width = width;
  row.height = height;
  row.ms_median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  row.ms_worst = sorted.back();
  row.ns_per_pixel = row.ms_median * 1e6 / (double(width) * height);
  row.cycles_per_pixel = g_mhz > 0 ? row.ns_per_pixel * g_mhz / 1000.0 : 0.0;
  // Everything in use at its peak: the arenas' high-water marks and the cache's.
  double frame_high = double(std::max(memory.frame().high_water(), memory.previous_frame().high_water()));
  double cache_high = double(memory.cache.stats().high_water);
  row.mem_high_mib = (double(memory.permanent.high_water()) + double(memory.level.high_water()) + cache_high +
                      2 * frame_high + double(memory.scratch.high_water())) / double(mem::kMiB);
  row.frame_high_kib = frame_high / 1024.0;
  row.cache_high_kib = cache_high / 1024.0;
  state.counters["ms_median"] = row.ms_median;
  state.counters["ms_worst"] = row.ms_worst;
  state.counters["ns_per_pixel"] = row.ns_per_pixel;
  state.counters["cycles_px"] = row.cycles_per_pixel;
  state.counters["mem_high_MiB"] = row.mem_high_mib;
  state.counters["frame_high_KiB"] = row.frame_high_kib;
  state.counters["cache_high_KiB"] = row.cache_high_kib;
  g_rows.push_back(row);
}

std::string markdown_table() {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "CPU: %.0f MHz (from /proc/cpuinfo; cycles/pixel = ns/pixel x GHz, an estimate)\n\n", g_mhz);
  out += line;
  out += "| map | resolution | ms/frame (median) | worst ms | ns/pixel | est. cycles/pixel | memory high-water MiB | "
         "frame arena KiB | surface cache KiB |\n";
  out += "|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : g_rows) {
    std::snprintf(line, sizeof line, "| %s | %dx%d | %.3f | %.3f | %.2f | %.1f | %.1f | %.0f | %.0f |\n",
                  r.map.c_str(), r.width, r.height, r.ms_median, r.ms_worst, r.ns_per_pixel, r.cycles_per_pixel,
                  r.mem_high_mib, r.frame_high_kib, r.cache_high_kib);
    out += line;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string markdown_path;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--markdown=", 11) == 0)
      markdown_path = argv[i] + 11;
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
      std::string name = std::string("flythrough/") + map + "/" + std::to_string(r[0]) + "x" + std::to_string(r[1]);
      benchmark::RegisterBenchmark(name.c_str(), flythrough, std::string(map), r[0], r[1])
          ->Iterations(kPathFrames)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
      ++registered;
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
