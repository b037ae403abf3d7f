// tools/content/content_build.cpp: see content_build.h.
#include "tools/content/content_build.h"

#include <chrono>
#include <cstring>
#include <filesystem>

#include "engine/formats/wad.h"
#include "memory/arena.h"
#include "tools/content/preview.h"
#include "tools/content/textures.h"
#include "tools/content/wad_writer.h"

namespace sb::content {

bool verify_wad(const std::vector<uint8_t>& wad, const std::vector<Miptex>& textures, std::string* error) {
  std::vector<uint8_t> arena_memory(textures.size() * sizeof(WadLump) + 4096);
  mem::Arena arena;
  arena.init("verify_wad", arena_memory.data(), arena_memory.size());
  Result<Wad> parsed = parse_wad("starbow.wad", wad.data(), wad.size(), arena);
  if (!parsed) {
    *error = parsed.message();
    return false;
  }
  if (parsed->count != textures.size()) {
    *error = "starbow.wad: " + std::to_string(parsed->count) + " lumps, expected " + std::to_string(textures.size());
    return false;
  }
  for (const Miptex& t : textures) {
    const WadLump* lump = parsed->find(t.name.c_str());
    if (!lump || lump->type != kWadMiptex) {
      *error = "starbow.wad: lump '" + t.name + "' missing or not a miptex";
      return false;
    }
    MiptexView view;
    Status st = decode_miptex("starbow.wad", "lump", lump->data, lump->size, &view);
    if (!st) {
      *error = st.message();
      return false;
    }
    if (std::strcmp(view.name, t.name.c_str()) != 0 || int(view.width) != t.width || int(view.height) != t.height ||
        !view.has_pixels) {
      *error = "starbow.wad: lump '" + t.name + "' header differs from the texture";
      return false;
    }
    for (int m = 0; m < 4; ++m)
      if (std::memcmp(view.mips[m], t.mips[size_t(m)].data(), t.mips[size_t(m)].size()) != 0) {
        *error = "starbow.wad: lump '" + t.name + "' mip " + std::to_string(m) + " pixels differ";
        return false;
      }
  }
  return true;
}

bool build_content(const std::string& outdir, uint32_t seed, const std::string& preview_dir, ContentSummary* summary,
                   std::string* error) {
  auto start = std::chrono::steady_clock::now();
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(fs::path(outdir) / "gfx", ec);
  if (ec) {
    *error = outdir + "/gfx: cannot create directory: " + ec.message();
    return false;
  }
  PaletteData pal = make_palette();
  std::vector<uint8_t> colormap = make_colormap(pal);
  std::vector<Miptex> textures = make_all_textures(pal, seed);
  std::vector<uint8_t> wad = encode_wad(textures, error);
  if (wad.empty()) return false;
  if (!verify_wad(wad, textures, error)) return false;
  std::vector<uint8_t> palette_bytes(pal.bytes.begin(), pal.bytes.end());
  if (!write_file(outdir + "/gfx/palette.lmp", palette_bytes, error)) return false;
  if (!write_file(outdir + "/gfx/colormap.lmp", colormap, error)) return false;
  if (!write_file(outdir + "/starbow.wad", wad, error)) return false;

  if (!preview_dir.empty()) {
    fs::create_directories(preview_dir, ec);
    if (ec) {
      *error = preview_dir + ": cannot create directory: " + ec.message();
      return false;
    }
    if (!write_palette_preview(preview_dir + "/palette.png", pal, error)) return false;
    if (!write_colormap_preview(preview_dir + "/colormap.png", pal, colormap, error)) return false;
    if (!write_contact_sheet(preview_dir + "/all.png", pal, textures, error)) return false;
    for (const Miptex& t : textures) {
      std::string file = t.name;
      for (char& c : file)
        if (c == '*') c = '_';  // '*' and '+' in file names are awkward in shells
        else if (c == '+') c = '-';
      int scale = t.width <= 32 ? 4 : (t.width <= 64 ? 3 : 2);
      if (!write_texture_preview(preview_dir + "/" + file + ".png", pal, colormap, t, scale, error)) return false;
    }
  }
  if (summary) {
    summary->textures = int(textures.size());
    summary->wad_bytes = wad.size();
    summary->texels = 0;
    for (const Miptex& t : textures)
      for (const auto& m : t.mips) summary->texels += m.size();
    summary->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return true;
}

}  // namespace sb::content
