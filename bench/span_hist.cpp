// bench/span_hist.cpp: which spans real frames give the span drawer (issue 4). Renders the
// fixed flythrough (engine/host/camera_path.h) of each map at each resolution, cached path,
// light styles animated, with a kernel table whose surface_spans_persp records every item of
// every batch before drawing it with the tuned kernel (simd::override_active). Deterministic:
// the spans are the renderer's, not the kernel's, so the figures hold for every target.
//
// Each span is put in the class of the count row that stands for it (bench/count_kernels.cpp,
// bench/counts.md) by the aarch64 dispatch (asm/span_persp_fast.cpp: batch_from, spans_range,
// persp_one_c), which the tool repeats on the batch as the kernel sees it:
//   curve:  second_order with dzi != 0 (the parabola steps); lin: every other span
//   pair:   a short (17 .. 64 px) span drawn in a pair (curve: spans_range's short_samples2;
//           lin: lin_pairs_a64 at the start of what is left of a batch), else single
// Printed, per map and resolution: spans and pixels per frame in each class (mean over the
// frames) and each class's share of the drawer's pixels. `--markdown=FILE` writes the tables.
//
//   starbow_span_hist [--frames=N] [--maps=a,b] [--res=WxH,...] [--markdown=FILE]
#include <algorithm>
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
constexpr int kShortMax = 64;  // asm/span_persp_fast.cpp's

enum Class {
  kLin16,       // linear, 1 .. 16 px
  kLinPair,     // linear, 17 .. 64, in lin_pairs_a64
  kLinShort,    // linear, 17 .. 64, one by one
  kLinLong,     // linear, 65 and more
  kCurve16,     // curve, 1 .. 16, alone
  kCurve16Pair, // curve, 1 .. 16, the next item one too (counted as pairs: a pair test's view)
  kCurve32,     // curve, 17 .. 48, in a pair
  kCurve64,     // curve, 49 .. 64, in a pair
  kCurveSingle, // curve, 17 .. 64, alone (no short neighbour)
  kCurve80,     // curve, 65 .. 80 (persp_long_a64: one pass)
  kCurveLong,   // curve, 81 and more (persp_long_a64: two passes or more)
  kClasses
};
const char* const kClassName[kClasses] = {
    "lin 1-16",         "lin 17-64 paired", "lin 17-64 alone", "lin 65+",   "curve 1-16 alone", "curve 1-16 in twos",
    "curve 17-48 paired", "curve 49-64 paired", "curve 17-64 alone", "curve 65-80", "curve 81+"};
const char* const kClassRow[kClasses] = {"", "persp64lin", "", "persp192lin, persp1920lin", "persp16", "persp16",
                                         "persp32", "persp64", "persp64single", "persp72", "persp192, persp1920"};

struct Tally {
  double spans[kClasses] = {}, pixels[kClasses] = {};
  double batches = 0, items = 0;
};
Tally g_tally;
const simd::Kernels* g_tuned = nullptr;

bool curve(const simd::PerspItem& x) { return x.span.second_order && x.span.dzi != 0.0; }
bool is_short(const simd::PerspItem& x) { return x.n > 16 && x.n <= kShortMax; }

void add(const simd::PerspItem& x, Class c) {
  g_tally.spans[c] += 1;
  g_tally.pixels[c] += x.n;
}
void add_single(const simd::PerspItem& x) {
  if (!curve(x)) return add(x, x.n <= 16 ? kLin16 : x.n <= kShortMax ? kLinShort : kLinLong);
  add(x, x.n <= 16 ? kCurve16 : x.n <= kShortMax ? kCurveSingle : x.n <= 80 ? kCurve80 : kCurveLong);
}
void add_curve_pair(const simd::PerspItem& x) { add(x, x.n <= 48 ? kCurve32 : kCurve64); }

// The aarch64 batch dispatch (batch_from, spans_range), classifying instead of drawing.
void classify(const simd::PerspItem* it, const simd::PerspItem* end) {
  while (it != end) {
    // batch_from: runs of long curve or long linear items, then pairs of short linear items
    // at the start of what is left, else spans_range for all the rest.
    if (curve(*it) && it->n > 80) {
      add_single(*it++);
      continue;
    }
    if (!curve(*it) && it->n > kShortMax) {
      add_single(*it++);
      continue;
    }
    if (end - it >= 2 && !curve(it[0]) && is_short(it[0]) && !curve(it[1]) && is_short(it[1])) {
      do {
        add(it[0], kLinPair);
        add(it[1], kLinPair);
        it += 2;
      } while (end - it >= 2 && !curve(it[0]) && is_short(it[0]) && !curve(it[1]) && is_short(it[1]));
      continue;
    }
    // spans_range: to the batch's end.
    while (it != end) {
      if (curve(*it) && it->n <= 16 && it + 1 != end && curve(it[1]) && it[1].n <= 16) {
        add(it[0], kCurve16Pair);
        add(it[1], kCurve16Pair);
        it += 2;
        continue;
      }
      if (curve(*it) && is_short(*it) && it + 1 != end && curve(it[1]) && is_short(it[1])) {
        add_curve_pair(it[0]);
        add_curve_pair(it[1]);
        it += 2;
        continue;
      }
      add_single(*it++);
    }
  }
}

void counting_spans(const simd::PerspItem* items, int count, const uint8_t* texels, int width, int height) {
  g_tally.batches += 1;
  g_tally.items += count;
  classify(items, items + std::max(count, 0));
  g_tuned->surface_spans_persp(items, count, texels, width, height);
}



// One map at one resolution: every path frame drawn once; false (with a message) when the
// map or memory is missing.
bool run(std::vector<uint8_t>& block, const std::string& quake_dir, const std::string& map, int w, int h,
         int frames, std::string* err) {
  static mem::MemorySystem memory;
  static fs::FileSystem files;
  static uint8_t palette[kPaletteBytes];
  static uint8_t colormap[kColormapBytes];
  char e[256];
  if (!memory.init(block.data(), block.size(), e, sizeof e)) return *err = e, false;
  Status s = host::open_search_path(files, quake_dir.c_str(), "lq1", "lq1", memory.permanent);
  if (s) s = host::load_palette_and_colormap(files, memory.scratch, palette, colormap);
  Result<BspWorld*> world = s ? host::load_world(files, map.c_str(), memory) : Result<BspWorld*>(s.error());
  if (!world) return *err = world.message(), false;
  Result<host::CameraPath> path = host::build_camera_path(*world.value(), memory.level);
  if (!path) return *err = path.message(), false;
  Framebuffer fb;
  fb.pixels = memory.permanent.push_array<uint8_t>(size_t(w) * h, "framebuffer");
  fb.zbuffer = memory.permanent.push_array<uint16_t>(size_t(w) * h, "zbuffer");
  fb.width = fb.stride = w;
  fb.height = h;
  if (!fb.pixels || !fb.zbuffer) return *err = "out of memory", false;
  for (int f = 0; f < frames; ++f) {
    RenderInputs in;
    in.world = world.value();
    in.view = host::camera_path_view(path.value(), f, frames, 90.0f);
    in.time = f * (1.0 / 30.0);
    int styles[kMaxLightStyleSlots];
    host::light_styles_at(in.time, true, styles);
    in.lightstyles = styles;
    in.colormap = colormap;
    memory.begin_frame();
    const Status r = render_world(in, fb, memory, nullptr);
    if (!r) return *err = r.message(), false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  bench::FlythroughArgs args;
  args.res = {{320, 240}, {640, 480}, {1920, 1080}};
  if (!bench::parse_flythrough_args(argc, argv, args)) return 2;
  const std::string& markdown = args.markdown;
  const int frames = args.frames;
  const std::vector<std::string>& maps = args.maps;
  const std::vector<std::pair<int, int>>& res = args.res;
  set_log_sink(bench::quiet_sink, nullptr);
  const char* env = std::getenv("STARBOW_QUAKE_DIR");
  const std::string quake_dir = env && *env ? env : STARBOW_QUAKE_DIR;
  simd::force_scalar(false);
  static simd::Kernels counting = simd::active();
  g_tuned = &simd::active();
  counting.name = "counting";
  counting.surface_spans_persp = counting_spans;
  simd::override_active(&counting);

  std::vector<uint8_t> block(kBlockMiB * mem::kMiB, 0);
  std::string out = "## Spans the drawer is given (bench/span_hist.cpp)\n\n";
  char line[512];
  std::snprintf(line, sizeof line,
                "%d flythrough frames a map, cached path, light styles animated. Each span is in the class of "
                "the aarch64 dispatch that draws it (curve: second order with dzi != 0; paired: drawn two at a "
                "time). Spans and pixels are means per frame; %% is the share of all the drawer's pixels.\n\n",
                frames);
  out += line;
  for (const std::string& map : maps) {
    for (const auto& [w, h] : res) {
      g_tally = Tally{};
      std::string err;
      if (!run(block, quake_dir, map, w, h, frames, &err)) {
        std::fprintf(stderr, "skipping %s %dx%d: %s\n", map.c_str(), w, h, err.c_str());
        break;
      }
      double all = 0;
      for (double p : g_tally.pixels) all += p;
      std::snprintf(line, sizeof line,
                    "### %s %dx%d: %.0f spans, %.0f px a frame (%.0f%% of the screen), %.1f spans a batch\n\n"
                    "| class | count row | spans | px | px %% | px a span |\n|---|---|---|---|---|---|\n",
                    map.c_str(), w, h, [&] {
                      double n = 0;
                      for (double s : g_tally.spans) n += s;
                      return n / frames;
                    }(), all / frames, 100.0 * all / frames / (double(w) * h),
                    g_tally.batches > 0 ? g_tally.items / g_tally.batches : 0.0);
      out += line;
      for (int c = 0; c < kClasses; ++c) {
        const double sp = g_tally.spans[c] / frames, px = g_tally.pixels[c] / frames;
        std::snprintf(line, sizeof line, "| %s | %s | %.1f | %.0f | %.1f | %.1f |\n", kClassName[c], kClassRow[c], sp, px,
                      all > 0 ? 100.0 * g_tally.pixels[c] / all : 0.0, sp > 0 ? px / sp : 0.0);
        out += line;
      }
      out += "\n";
      std::printf("%s %dx%d done\n", map.c_str(), w, h);
      std::fflush(stdout);
    }
  }
  simd::override_active(nullptr);
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
