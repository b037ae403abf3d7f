// engine/host/content.h: turning a search path into what a frame needs
// (palette, colormap, a loaded world). Shared by the host, benchmarks and tests.
//
//   open_search_path(basedir, game)   <basedir>/lq1 underneath, <basedir>/<game> on top
//   load_palette_and_colormap(fs)     gfx/palette.lmp (768 bytes), gfx/colormap.lmp (64 x 256)
//   load_world(fs, "start", memory)   cache.flush(); level.reset(); maps/start.bsp (+ .lit)
//
// Memory: the search path's pak directories go to `permanent`; file bytes are read
// into the scratch arena and released before returning; the world lives in the
// level arena until the next load_world.
#pragma once
#include <cstdint>

#include "engine/core/error.h"
#include "engine/formats/bsp.h"
#include "engine/formats/lmp.h"  // kPaletteBytes, kColormapBytes
#include "engine/fs/file_system.h"
#include "memory/memory_system.h"

namespace sb::host {

// Adds <basedir>/<base_game> (when it exists) and <basedir>/<game> on top of it
// (when game differs). Fails when neither folder exists, naming both.
Status open_search_path(fs::FileSystem& files, const char* basedir, const char* game, const char* base_game,
                        mem::Arena& permanent);

// Reads the palette and colormap. On failure both outputs hold a usable grey
// fallback (so the engine still runs) and the Status says what is missing.
Status load_palette_and_colormap(const fs::FileSystem& files, mem::Arena& scratch, uint8_t* palette768,
                                 uint8_t* colormap16k);
// The grey fallback alone (palette index i = grey i; colormap rows darken to 0).
void fallback_palette_and_colormap(uint8_t* palette768, uint8_t* colormap16k);

// "start" or "maps/start.bsp" -> "maps/start.bsp". False when it does not fit.
bool map_file_name(const char* map, char* out, size_t out_size);

// Flushes the cache, resets the level arena and loads maps/<map>.bsp (and its
// .lit when present) into it, then render_new_level(). On failure the level is
// empty and the message names the file and what was wrong.
Result<BspWorld*> load_world(const fs::FileSystem& files, const char* map, mem::MemorySystem& memory);

}  // namespace sb::host
