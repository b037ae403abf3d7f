// tools/content/content_build.h: everything sbcontent writes, as one call.
//
// build_content(outdir) writes (creating directories as needed):
//   <outdir>/gfx/palette.lmp    768 bytes
//   <outdir>/gfx/colormap.lmp   64 * 256 + 1 bytes
//   <outdir>/starbow.wad        WAD2 of every texture in texture_specs()
// then reads the WAD back through the engine's parse_wad + decode_miptex and compares
// every pixel (verify_wad), so a file the engine cannot read is never left behind
// silently. With a preview directory it also writes PNGs there (preview.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tools/content/image.h"
#include "tools/content/palette.h"

namespace sb::content {

struct ContentSummary {
  int textures = 0;
  size_t wad_bytes = 0;
  size_t texels = 0;  // all mip levels
  double seconds = 0;
};

bool build_content(const std::string& outdir, uint32_t seed, const std::string& preview_dir, ContentSummary* summary,
                   std::string* error);

// Parses `wad` with engine/formats/wad.h and checks that it holds exactly `textures`
// (names, sizes, every mip's pixels). False with a message naming the lump otherwise.
bool verify_wad(const std::vector<uint8_t>& wad, const std::vector<Miptex>& textures, std::string* error);

}  // namespace sb::content
