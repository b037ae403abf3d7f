// tools/light/main.cpp: sblight, the LIGHT stage of the map compiler.
//
//   sblight [options] file.bsp
//     -extra        2x2 supersampling per lightmap sample
//     -extra4       4x4 supersampling
//     -threads N    worker threads (default: hardware threads)
//     -lit          also write file.lit (QLIT version 1, RGB per sample)
//     -gate G       skip lights whose value stays below G over a face (default 1)
//     -dome N       directions of the _sunlight2 sky dome (default 32)
//     -q            quiet: warnings and the summary only
// The BSP is relit in place and written back in the format it was read in.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "engine/core/log.h"
#include "tools/common/bsp_data.h"
#include "tools/light/light.h"

namespace {

void usage() {
  std::fprintf(stderr,
               "usage: sblight [-extra | -extra4] [-threads N] [-lit] [-gate G] [-dome N] [-q] file.bsp\n");
}

bool parse_int(const char* s, int lo, int hi, int* out) {
  char* end = nullptr;
  long v = std::strtol(s, &end, 10);
  if (!s[0] || *end || v < lo || v > hi) return false;
  *out = int(v);
  return true;
}

const char* format_name(sb::tools::BspFormat f) {
  switch (f) {
    case sb::tools::BspFormat::Bsp29: return "BSP29";
    case sb::tools::BspFormat::Bsp2: return "BSP2";
    case sb::tools::BspFormat::Bsp2rmq: return "2PSB";
    default: return "auto";
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // summary lines interleave with warnings in order
  sb::tools::LightOptions opts;
  bool want_lit = false;
  const char* path = nullptr;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!std::strcmp(a, "-extra")) {
      opts.extra = 2;
    } else if (!std::strcmp(a, "-extra4")) {
      opts.extra = 4;
    } else if (!std::strcmp(a, "-lit")) {
      want_lit = true;
    } else if (!std::strcmp(a, "-q")) {
      opts.quiet = true;
    } else if (!std::strcmp(a, "-threads") || !std::strcmp(a, "-dome") || !std::strcmp(a, "-gate")) {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "sblight: %s needs a value\n", a);
        return 2;
      }
      const char* v = argv[++i];
      if (!std::strcmp(a, "-gate")) {
        char* end = nullptr;
        double g = std::strtod(v, &end);
        if (!v[0] || *end || !(g >= 0 && g < 1e6)) {
          std::fprintf(stderr, "sblight: -gate '%s': expected a number >= 0\n", v);
          return 2;
        }
        opts.gate = float(g);
      } else if (!parse_int(v, !std::strcmp(a, "-dome") ? 0 : 1, !std::strcmp(a, "-dome") ? 4096 : 256,
                            !std::strcmp(a, "-dome") ? &opts.dome_samples : &opts.threads)) {
        std::fprintf(stderr, "sblight: %s '%s': out of range\n", a, v);
        return 2;
      }
    } else if (a[0] == '-') {
      std::fprintf(stderr, "sblight: unknown option '%s'\n", a);
      usage();
      return 2;
    } else if (path) {
      std::fprintf(stderr, "sblight: more than one input file ('%s', '%s')\n", path, a);
      return 2;
    } else {
      path = a;
    }
  }
  if (!path) {
    usage();
    return 2;
  }
  opts.want_rgb = want_lit;

  sb::tools::BspData bsp;
  sb::Status st = sb::tools::read_bsp(path, &bsp);
  if (!st) {
    std::fprintf(stderr, "sblight: %s\n", st.message());
    return 1;
  }
  if (!opts.quiet)
    std::printf("sblight: %s (%s): %zu faces, extra %dx%d\n", path, format_name(bsp.format), bsp.faces.size(),
                opts.extra, opts.extra);
  sb::tools::LightStats stats;
  std::vector<uint8_t> rgb;
  st = sb::tools::light_bsp(path, &bsp, opts, &stats, want_lit ? &rgb : nullptr);
  if (!st) {
    std::fprintf(stderr, "sblight: %s\n", st.message());
    return 1;
  }
  sb::tools::BspFormat used;
  st = sb::tools::write_bsp(path, bsp, bsp.format, &used);
  if (!st) {
    std::fprintf(stderr, "sblight: %s\n", st.message());
    return 1;
  }
  if (want_lit) {
    std::string lit = path;
    size_t dot = lit.rfind('.');
    size_t slash = lit.find_last_of("/\\");
    if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) lit.resize(dot);
    lit += ".lit";
    st = sb::tools::write_lit(lit.c_str(), rgb);
    if (!st) {
      std::fprintf(stderr, "sblight: %s\n", st.message());
      return 1;
    }
  }
  std::printf(
      "sblight: %s: %u of %u faces lit, %llu samples (%.1f KiB lightmap), %u lights, %u sun directions, "
      "%llu rays, %.2f s on %u threads, mean sample %.1f%s\n",
      path, stats.faces_lit, stats.faces, (unsigned long long)stats.samples, double(bsp.lighting.size()) / 1024.0,
      stats.lights, stats.suns, (unsigned long long)stats.traces, stats.seconds, stats.threads, stats.mean_sample,
      want_lit ? " (+ .lit)" : "");
  if (stats.styles_dropped) std::printf("sblight: %u faces dropped light styles (more than 4)\n", stats.styles_dropped);
  return 0;
}
