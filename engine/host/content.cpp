#include "engine/host/content.h"

#include <cstdio>
#include <cstring>

#include "engine/core/log.h"
#include "engine/render/render.h"

namespace sb::host {
namespace {

bool join(char* out, size_t out_size, const char* a, const char* b) {
  int n = std::snprintf(out, out_size, "%s/%s", a, b);
  return n > 0 && size_t(n) < out_size;
}

}  // namespace

Status open_search_path(fs::FileSystem& files, const char* basedir, const char* game, const char* base_game,
                        mem::Arena& permanent) {
  files.clear();
  char path[fs::kMaxPathBytes];
  if (!join(path, sizeof path, basedir, base_game)) return make_error("%s/%s: path too long", basedir, base_game);
  Status base = files.add_game_dir(path, permanent);
  bool same = std::strcmp(game, base_game) == 0;
  if (same) return base;
  if (!join(path, sizeof path, basedir, game)) return make_error("%s/%s: path too long", basedir, game);
  Status mod = files.add_game_dir(path, permanent);
  if (!mod && !base)
    return make_error("no game folder: neither %s/%s nor %s/%s could be opened (%s)", basedir, base_game, basedir,
                      game, mod.message());
  return mod ? Status::ok() : mod;
}

void fallback_palette_and_colormap(uint8_t* palette, uint8_t* colormap) {
  for (int i = 0; i < 256; ++i) palette[i * 3] = palette[i * 3 + 1] = palette[i * 3 + 2] = uint8_t(i);
  for (int row = 0; row < kColormapRows; ++row)
    for (int i = 0; i < 256; ++i) {
      int v = i * (kColormapRows - row) / 32;  // row 32 = unchanged, row 0 = twice as bright
      colormap[row * 256 + i] = uint8_t(v > 255 ? 255 : v);
    }
}

Status load_palette_and_colormap(const fs::FileSystem& files, mem::Arena& scratch, uint8_t* palette,
                                 uint8_t* colormap) {
  fallback_palette_and_colormap(palette, colormap);
  mem::ArenaScope scope(scratch);
  Result<fs::FileData> pal = files.load("gfx/palette.lmp", scratch);
  if (!pal) return pal.error();
  Palette parsed;
  SB_TRY(parse_palette("gfx/palette.lmp", pal.value().data, pal.value().size, &parsed));
  Result<fs::FileData> cmap = files.load("gfx/colormap.lmp", scratch);
  if (!cmap) return cmap.error();
  uint8_t* rows = scratch.push_array<uint8_t>(kColormapBytes, "colormap (parse)");
  if (!rows) return make_error("gfx/colormap.lmp: scratch region cannot fit %zu bytes", kColormapBytes);
  SB_TRY(parse_colormap("gfx/colormap.lmp", cmap.value().data, cmap.value().size, rows, nullptr));
  std::memcpy(palette, parsed.rgb, kPaletteBytes);
  std::memcpy(colormap, rows, kColormapBytes);
  return Status::ok();
}

bool map_file_name(const char* map, char* out, size_t out_size) {
  size_t n = std::strlen(map);
  bool has_dir = std::strncmp(map, "maps/", 5) == 0;
  bool has_ext = n >= 4 && std::strcmp(map + n - 4, ".bsp") == 0;
  int w = std::snprintf(out, out_size, "%s%s%s", has_dir ? "" : "maps/", map, has_ext ? "" : ".bsp");
  return n > 0 && w > 0 && size_t(w) < out_size;
}

Result<BspWorld*> load_world(const fs::FileSystem& files, const char* map, mem::MemorySystem& memory) {
  memory.cache.flush();
  memory.level.reset();
  char name[fs::kMaxPathBytes];
  if (!map_file_name(map, name, sizeof name)) return make_error("map name '%.60s' is not usable", map);

  mem::ArenaScope scope(memory.scratch);
  Result<fs::FileData> file = files.load(name, memory.scratch);
  if (!file) return file.error();
  Result<BspWorld*> world = load_bsp(name, file.value().data, file.value().size, memory.level, memory.scratch);
  if (!world) {
    memory.level.reset();
    return world.error();
  }
  // Coloured light is optional: a missing .lit is normal, a broken one is a warning.
  char lit[fs::kMaxPathBytes];
  std::snprintf(lit, sizeof lit, "%.*s.lit", int(std::strlen(name) - 4), name);
  if (files.exists(lit)) {
    Result<fs::FileData> lit_file = files.load(lit, memory.scratch);
    Status s = lit_file ? load_lit(*world.value(), lit, lit_file.value().data, lit_file.value().size, memory.level)
                        : lit_file.status();
    if (!s) log_warning("%s (drawing with white light)", s.message());
  }
  render_new_level(*world.value());
  return world;
}

}  // namespace sb::host
