// bench/kernel_ratio_bench.cpp (starbow_kernel_ratio): how much the tuned asm/ kernels speed
// up whole frames: the flythrough path (engine/host/camera_path.h) of each map at each
// resolution, every path frame drawn twice back to back, once with the tuned kernels and
// once with the scalar references (simd::force_scalar), each kernel table with its own
// memory block, world and surface cache, so each sees exactly the history a run of its own
// would (surface builds included: the builder is a kernel too). The two frames of a pair run
// in alternating order. Figure: "tuned / scalar ms", the median over the path of the
// per-frame ratios (the pairing cancels most of a shared machine's noise), beside the two
// medians. Below 1: the tuned kernels are faster. Never pass/fail.
//
//   starbow_kernel_ratio [--markdown=FILE] [--frames=N] [--maps=a,b] [--res=WxH,WxH]
// Defaults: 300 frames; start, lq_e0m1, lq_e1m1; 320x200, 640x480, 1280x720, 1920x1080.
// Content from STARBOW_QUAKE_DIR (env or CMake); absent maps are skipped with a message.
// bench/run_bench.sh appends the table to bench/results.md.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "asm/kernels.h"
#include "bench/flythrough_args.h"
#include "engine/core/log.h"
#include "engine/host/camera_path.h"
#include "engine/host/content.h"
#include "engine/host/lightstyles.h"
#include "engine/render/render.h"
#include "platform/common/platform.h"

namespace {

using namespace sb;

constexpr size_t kBlockMiB = 160;


double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One kernel table's world: its own block, memory system, files, world, path, framebuffer.
struct Side {
  std::vector<uint8_t> block;
  mem::MemorySystem memory;
  fs::FileSystem files;
  uint8_t palette[kPaletteBytes];
  uint8_t colormap[kColormapBytes];
  BspWorld* world = nullptr;
  host::CameraPath path{};
  Framebuffer fb;

  bool open(const std::string& quake_dir, const std::string& map, int w, int h, std::string* err) {
    block.assign(kBlockMiB * mem::kMiB, 0);
    char e[256];
    if (!memory.init(block.data(), block.size(), e, sizeof e)) return *err = e, false;
    Status s = host::open_search_path(files, quake_dir.c_str(), "lq1", "lq1", memory.permanent);
    if (s) s = host::load_palette_and_colormap(files, memory.scratch, palette, colormap);
    Result<BspWorld*> wr = s ? host::load_world(files, map.c_str(), memory) : Result<BspWorld*>(s.error());
    if (!wr) return *err = wr.message(), false;
    world = wr.value();
    Result<host::CameraPath> p = host::build_camera_path(*world, memory.level);
    if (!p) return *err = p.message(), false;
    path = p.value();
    fb.pixels = memory.permanent.push_array<uint8_t>(size_t(w) * h, "framebuffer");
    fb.zbuffer = memory.permanent.push_array<uint16_t>(size_t(w) * h, "zbuffer");
    fb.width = fb.stride = w;
    fb.height = h;
    if (!fb.pixels || !fb.zbuffer) return *err = "out of memory", false;
    return true;
  }

  // Renders path frame `frame` of `frames`; returns milliseconds, or -1 on failure.
  double frame_ms(int frame, int frames) {
    RenderInputs in;
    in.world = world;
    in.view = host::camera_path_view(path, frame % frames, frames, 90.0f);
    in.time = frame * (1.0 / 30.0);
    int styles[kMaxLightStyleSlots];
    host::light_styles_at(in.time, true, styles);
    in.lightstyles = styles;
    in.colormap = colormap;
    const auto t0 = std::chrono::steady_clock::now();
    memory.begin_frame();
    const Status r = render_world(in, fb, memory, nullptr);
    const auto t1 = std::chrono::steady_clock::now();
    if (!r) {
      std::fprintf(stderr, "render: %s\n", r.message());
      return -1.0;
    }
    return std::chrono::duration<double>(t1 - t0).count() * 1000.0;
  }
};

struct Row {
  std::string map;
  int w, h;
  double tuned_ms, scalar_ms, ratio;
  bool same_pixels;
};


}  // namespace

int main(int argc, char** argv) {
  bench::FlythroughArgs args;
  args.res = {{320, 200}, {640, 480}, {1280, 720}, {1920, 1080}};
  if (!bench::parse_flythrough_args(argc, argv, args)) return 2;
  const std::string& markdown = args.markdown;
  const int frames = args.frames;
  const std::vector<std::string>& maps = args.maps;
  const std::vector<std::pair<int, int>>& res = args.res;
  set_log_sink(bench::quiet_sink, nullptr);
  const char* env = std::getenv("STARBOW_QUAKE_DIR");
  const std::string quake_dir = env && *env ? env : STARBOW_QUAKE_DIR;
  const bool forced_before = simd::scalar_forced();
  std::printf("tuned kernels: %s\n", (simd::force_scalar(false), simd::describe_active()));
  std::vector<Row> rows;
  for (const std::string& map : maps) {
    for (const auto& [w, h] : res) {
      Side sides[2];  // [0] tuned, [1] scalar
      std::string err;
      if (!sides[0].open(quake_dir, map, w, h, &err) || !sides[1].open(quake_dir, map, w, h, &err)) {
        std::fprintf(stderr, "skipping %s %dx%d: %s\n", map.c_str(), w, h, err.c_str());
        break;
      }
      std::vector<double> ms[2], ratio;
      bool same = true, failed = false;
      for (int f = 0; f < frames && !failed; ++f) {
        double t[2];
        for (int k = 0; k < 2; ++k) {
          const int which = (k + f) % 2;  // alternate which table goes first
          simd::force_scalar(which == 1);
          t[which] = sides[which].frame_ms(f, frames);
          if (t[which] < 0) failed = true;
        }
        if (failed) break;
        ms[0].push_back(t[0]);
        ms[1].push_back(t[1]);
        ratio.push_back(t[0] / t[1]);
        same = same && std::memcmp(sides[0].fb.pixels, sides[1].fb.pixels, size_t(w) * h) == 0;
      }
      simd::force_scalar(forced_before);
      if (failed || ratio.empty()) continue;
      rows.push_back({map, w, h, median(ms[0]), median(ms[1]), median(ratio), same});
      const Row& r = rows.back();
      std::printf("%-8s %4dx%-4d  tuned %8.3f ms  scalar %8.3f ms  tuned/scalar %.3f%s\n", r.map.c_str(), w, h,
                  r.tuned_ms, r.scalar_ms, r.ratio, same ? "" : "  (PIXELS DIFFER)");
      std::fflush(stdout);
    }
  }
  std::string out = "## Tuned ÷ scalar kernels (bench/kernel_ratio_bench.cpp)\n\n";
  char line[512];
  std::snprintf(line, sizeof line,
                "Each of %d path frames drawn back to back with the tuned kernels (%s) and with the scalar "
                "references, each with its own surface cache; \"tuned ÷ scalar ms\" is the median of the per-frame "
                "ratios (below 1: tuned is faster). Cached path, light styles animated. Never pass/fail.\n\n",
                frames, (simd::force_scalar(false), simd::describe_active()));
  simd::force_scalar(forced_before);
  out += line;
  out += "| map | resolution | tuned ms (median) | scalar ms (median) | tuned ÷ scalar ms | same pixels |\n";
  out += "|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %dx%d | %.3f | %.3f | %.3f | %s |\n", r.map.c_str(), r.w, r.h, r.tuned_ms,
                  r.scalar_ms, r.ratio, r.same_pixels ? "yes" : "NO");
    out += line;
  }
  std::printf("\n%s", out.c_str());
  if (!markdown.empty()) {
    if (std::FILE* f = std::fopen(markdown.c_str(), "w")) {
      std::fputs(out.c_str(), f);
      std::fclose(f);
    } else {
      std::fprintf(stderr, "cannot write %s\n", markdown.c_str());
      return 1;
    }
  }
  return 0;
}
