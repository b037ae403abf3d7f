// engine/render/surface_cache.h: lit surfaces (texture x light map), built on demand
// into the cache region and reused across frames.
//
//   cache block (mem::Cache, 16-byte aligned):
//   [ SurfaceHeader (32 bytes) | texels: width x height palette indices, row-major ]
//
// A face holds one handle per mip level (Face::cache[mip]). A block is reused while the
// light style values and the texture animation frame it was built with (kept exactly in its
// SurfaceHeader) still hold; otherwise it is rebuilt in place (same size). Evicted blocks are
// rebuilt on demand. Face::cache_light_key[mip] records an FNV-1a hash of those inputs
// (style values, then texture index) for diagnostics; the header is what is compared.
// Internal to render/ (and tests).
#pragma once
#include <cstdint>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "memory/memory_system.h"

namespace sb::render {

struct SurfaceHeader {
  int32_t width, height;    // extents >> mip (texels of that mip)
  int32_t texture;          // texture index built from (after animation)
  int32_t mip;
  int32_t style_values[kMaxLightStyles];  // values of the face's styles at build time (0 unused)
};
static_assert(sizeof(SurfaceHeader) == 32, "payload stays 16-byte aligned");

// Builds a lit surface: out[v * width + u] =
//   colormap[(shade_at(grid, grid_width, u, v, mip) >> 8) * 256 + texture_texel(tex, mip, smin, tmin, u, v)]
// block by block (16 >> mip texels square), stepping the light numerators incrementally.
// width and height must be multiples of 16 >> mip; the grid must cover them
// (grid_width >= width / (16 >> mip) + 1). smin, tmin: the face's texture_mins (mip 0 units,
// multiples of 16).
void build_surface(const uint16_t* grid, int grid_width, const Texture& tex, int mip, int smin, int tmin,
                   int width, int height, const uint8_t* colormap, uint8_t* out);

// The lit surface of world.faces[face] at `mip` for this frame: found in the cache or built
// there (the light grid is computed in the frame arena, popped before return). Counts
// stats.surfaces_built / surface_cache_hits. Returns nullptr (and *header untouched) when
// the surface cannot be had: zero-sized extents, or the cache cannot fit it this frame
// (then stats.cache_exhausted is set and a warning is logged once per level).
const uint8_t* fetch_surface(BspWorld& world, uint32_t face, int mip, const RenderInputs& in,
                             mem::MemorySystem& memory, RenderStats& stats, SurfaceHeader* header);

// Per-level reset of the cache's bookkeeping (the once-per-level warning).
void surface_cache_new_level();

}  // namespace sb::render
