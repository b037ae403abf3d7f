// tools/light/main.cpp: sblight, the LIGHT stage of the map compiler.
//
//   sblight [options] file.bsp
//     -extra        2x2 supersampling per lightmap sample
//     -extra4       4x4 supersampling
//     -threads N    worker threads (default: hardware threads)
//     -lit          also write file.lit (QLIT version 1, RGB per sample)
//     -gate G       skip lights whose value stays below G over a face (default 1)
//     -dome N       about N directions of the _sunlight2 sky dome (default 32: 37 used)
//     -q            quiet: warnings and the summary only
//     -bounce [N]   N bounces of radiosity (default 1); -nobounce turns worldspawn "_bounce" off
//     -bouncescale F, -bouncecolorscale F (0..1), -bouncestyled, -bouncerays N (default 64),
//     -bouncestep N (bounce receivers every N lightmap samples each way, default 2)
//     -dirt         dirt (ambient occlusion) on every light; -nodirt turns "_dirt" off
//     -dirtdepth F, -dirtscale F, -dirtgain F, -dirtmode 0|1, -dirtangle F
//     -palette FILE 768-byte palette (palette.lmp) for bounce texture colours
//     -basedir DIR  game directory holding gfx/palette.lmp
//   Without -palette / -basedir the palette is looked for at <bsp dir>/../gfx/palette.lmp
//   and <bsp dir>/gfx/palette.lmp; with none, bounce uses grey reflectivity (a warning).
//   Options override the worldspawn keys of the same name (light_entities.h).
// The BSP is relit in place and written back in the format it was read in. When sbbsp left
// file.faceattr beside it (brush entity light keys, tools/common/face_attrs.h), it is read
// and checked against the BSP (a corrupt or mismatched one is an error).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "engine/core/log.h"
#include "engine/formats/lmp.h"
#include "tools/common/bsp_data.h"
#include "tools/common/face_attrs.h"
#include "tools/light/light.h"

namespace {

void usage() {
  std::fprintf(stderr,
               "usage: sblight [-extra | -extra4] [-threads N] [-lit] [-gate G] [-dome N] [-q]\n"
               "               [-bounce [N]] [-nobounce] [-bouncescale F] [-bouncecolorscale F] [-bouncestyled]\n"
               "               [-bouncerays N] [-bouncestep N] [-dirt] [-nodirt] [-dirtdepth F] [-dirtscale F] [-dirtgain F]\n"
               "               [-dirtmode 0|1] [-dirtangle F] [-palette FILE] [-basedir DIR] file.bsp\n");
}

bool parse_int(const char* s, int lo, int hi, int* out) {
  char* end = nullptr;
  long v = std::strtol(s, &end, 10);
  if (!s[0] || *end || v < lo || v > hi) return false;
  *out = int(v);
  return true;
}

bool parse_number(const char* s, double lo, double hi, float* out) {
  char* end = nullptr;
  double v = std::strtod(s, &end);
  if (!s[0] || *end || !(v >= lo && v <= hi)) return false;
  *out = float(v);
  return true;
}

// Reads a 768-byte palette; false (and *out untouched) when the file is missing or bad.
bool load_palette(const std::string& path, std::vector<uint8_t>* out, std::string* error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  std::vector<uint8_t> bytes(1024);
  size_t n = std::fread(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  sb::Palette pal;
  sb::Status st = sb::parse_palette(path.c_str(), bytes.data(), n, &pal);
  if (!st) {
    *error = st.message();
    return false;
  }
  out->assign(pal.rgb, pal.rgb + sb::kPaletteBytes);
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
  std::string palette_path, basedir;
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
    } else if (!std::strcmp(a, "-bounce")) {
      opts.bounce = 1;
      if (i + 2 < argc && parse_int(argv[i + 1], 0, 8, &opts.bounce)) ++i;  // optional count
    } else if (!std::strcmp(a, "-nobounce")) {
      opts.bounce = 0;
    } else if (!std::strcmp(a, "-bouncestyled")) {
      opts.bouncestyled = 1;
    } else if (!std::strcmp(a, "-dirt")) {
      opts.dirt = 1;
    } else if (!std::strcmp(a, "-nodirt")) {
      opts.dirt = 0;
    } else if (!std::strcmp(a, "-palette") || !std::strcmp(a, "-basedir")) {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "sblight: %s needs a value\n", a);
        return 2;
      }
      (!std::strcmp(a, "-palette") ? palette_path : basedir) = argv[++i];
    } else if (!std::strcmp(a, "-bouncerays") || !std::strcmp(a, "-dirtmode") || !std::strcmp(a, "-bouncestep")) {
      bool mode = !std::strcmp(a, "-dirtmode"), step = !std::strcmp(a, "-bouncestep");
      if (i + 1 >= argc || !parse_int(argv[i + 1], mode ? 0 : 1, mode ? 1 : (step ? 16 : 4096),
                                      mode ? &opts.dirtmode : (step ? &opts.bounce_step : &opts.bounce_rays))) {
        std::fprintf(stderr, "sblight: %s needs a value in range\n", a);
        return 2;
      }
      ++i;
    } else if (!std::strcmp(a, "-bouncescale") || !std::strcmp(a, "-bouncecolorscale") ||
               !std::strcmp(a, "-dirtdepth") || !std::strcmp(a, "-dirtscale") || !std::strcmp(a, "-dirtgain") ||
               !std::strcmp(a, "-dirtangle")) {
      float* target = !std::strcmp(a, "-bouncescale")        ? &opts.bouncescale
                      : !std::strcmp(a, "-bouncecolorscale") ? &opts.bouncecolorscale
                      : !std::strcmp(a, "-dirtdepth")        ? &opts.dirtdepth
                      : !std::strcmp(a, "-dirtscale")        ? &opts.dirtscale
                      : !std::strcmp(a, "-dirtgain")         ? &opts.dirtgain
                                                             : &opts.dirtangle;
      if (i + 1 >= argc || !parse_number(argv[i + 1], 0, 1e6, target)) {
        std::fprintf(stderr, "sblight: %s needs a number >= 0\n", a);
        return 2;
      }
      ++i;
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

  // Palette for bounce colours: -palette, else -basedir/gfx, else next to the BSP's folder.
  {
    std::vector<std::string> candidates;
    if (!palette_path.empty()) {
      candidates.push_back(palette_path);
    } else if (!basedir.empty()) {
      candidates.push_back(basedir + "/gfx/palette.lmp");
    } else {
      std::string dir = path;
      size_t slash = dir.find_last_of("/\\");
      dir = slash == std::string::npos ? std::string(".") : dir.substr(0, slash);
      candidates.push_back(dir + "/../gfx/palette.lmp");
      candidates.push_back(dir + "/gfx/palette.lmp");
    }
    std::string error;
    for (const std::string& c : candidates)
      if (load_palette(c, &opts.palette, &error)) {
        if (!opts.quiet) std::printf("sblight: palette %s\n", c.c_str());
        break;
      }
    if (!error.empty()) std::fprintf(stderr, "sblight: %s\n", error.c_str());
    if ((!palette_path.empty() || !basedir.empty()) && opts.palette.empty()) {
      std::fprintf(stderr, "sblight: cannot read palette '%s'\n", candidates[0].c_str());
      return 1;
    }
  }

  sb::tools::BspData bsp;
  sb::Status st = sb::tools::read_bsp(path, &bsp);
  if (!st) {
    std::fprintf(stderr, "sblight: %s\n", st.message());
    return 1;
  }
  if (!opts.quiet)
    std::printf("sblight: %s (%s): %zu faces, extra %dx%d\n", path, format_name(bsp.format), bsp.faces.size(),
                opts.extra, opts.extra);
  // Brush entity light keys from sbbsp's side file (absent: none).
  std::vector<sb::tools::FaceAttr> attrs;
  bool attrs_found = false;
  const std::string attr_path = sb::tools::face_attr_path(path);
  st = sb::tools::read_face_attrs(attr_path.c_str(), bsp, &attrs, &attrs_found);
  if (!st) {
    std::fprintf(stderr, "sblight: %s\n", st.message());
    return 1;
  }
  if (attrs_found && !opts.quiet) std::printf("sblight: face attributes from %s\n", attr_path.c_str());
  sb::tools::LightStats stats;
  std::vector<uint8_t> rgb;
  st = sb::tools::light_bsp(path, &bsp, opts, &stats, want_lit ? &rgb : nullptr, &attrs);
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
  std::printf("sblight: phases: dirt %.2f s (%llu rays), direct %.2f s, bounce %.2f s (%d pass%s, %llu rays, "
              "%llu unresolved hits%s)\n",
              stats.dirt_seconds, (unsigned long long)stats.dirt_rays, stats.direct_seconds, stats.bounce_seconds,
              stats.bounces, stats.bounces == 1 ? "" : "es", (unsigned long long)stats.bounce_rays,
              (unsigned long long)stats.bounce_misses, stats.bounces && stats.palette_missing ? ", grey: no palette" : "");
  if (attrs_found)
    std::printf("sblight: face attributes: %u occluder polygons, %u phong faces\n", stats.occluder_polygons,
                stats.phong_faces);
  if (stats.styles_dropped) std::printf("sblight: %u faces dropped light styles (more than 4)\n", stats.styles_dropped);
  return 0;
}
