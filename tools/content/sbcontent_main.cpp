// tools/content/sbcontent_main.cpp: sbcontent, Starbow's content generator.
//   sbcontent <outdir> [-preview <dir>] [-seed <n>] [-list]
// Writes <outdir>/gfx/palette.lmp, <outdir>/gfx/colormap.lmp and <outdir>/starbow.wad
// (see content_build.h). Exit status 0 on success, 1 on failure (message on stderr).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tools/content/content_build.h"
#include "tools/content/textures.h"

int main(int argc, char** argv) {
  using namespace sb::content;
  std::string outdir, preview;
  uint32_t seed = kDefaultSeed;
  bool list = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "-preview") && i + 1 < argc) {
      preview = argv[++i];
    } else if (!std::strcmp(argv[i], "-seed") && i + 1 < argc) {
      seed = uint32_t(std::strtoul(argv[++i], nullptr, 0));
    } else if (!std::strcmp(argv[i], "-list")) {
      list = true;
    } else if (argv[i][0] != '-' && outdir.empty()) {
      outdir = argv[i];
    } else {
      std::fprintf(stderr, "sbcontent: unknown argument '%s'\n", argv[i]);
      outdir.clear();
      break;
    }
  }
  if (list) {
    for (const TextureSpec& s : texture_specs())
      std::printf("%-10s %4dx%-4d %s\n", s.name, s.width, s.height, s.description);
    if (outdir.empty()) return 0;
  }
  if (outdir.empty()) {
    std::fprintf(stderr, "usage: sbcontent <outdir> [-preview <dir>] [-seed <n>] [-list]\n");
    return 1;
  }
  ContentSummary summary;
  std::string error;
  if (!build_content(outdir, seed, preview, &summary, &error)) {
    std::fprintf(stderr, "sbcontent: %s\n", error.c_str());
    return 1;
  }
  std::printf("sbcontent: %s: palette, colormap, starbow.wad (%d textures, %zu bytes, %zu texels) in %.2f s\n",
              outdir.c_str(), summary.textures, summary.wad_bytes, summary.texels, summary.seconds);
  return 0;
}
