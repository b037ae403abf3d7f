// engine/render/surface_cache.cpp: building lit surfaces and keeping them in the cache.
//
// The builder is asm/'s surface_block kernel (asm/surface_block.h; tuned variants compute
// the same numerators per texel with bilinear weights). Its scalar reference walks the surface in light blocks of B = 16 >> mip texels. Within a block the
// shade is the bilinear blend of its four grid corners; rather than evaluating it per texel
// it steps the exact numerators of shade_at() (see surface_math.h):
//   left(fy)  = g00 * (B - fy) + g01 * fy        (steps by g01 - g00 per row)
//   right(fy) = g10 * (B - fy) + g11 * fy        (steps by g11 - g10 per row)
//   num(fx)   = left * B + (right - left) * fx   (steps by right - left per texel)
//   shade     = num >> (2 log2 B)
// so the result equals shade_at() bit for bit. Because texture sizes and texture_mins are
// multiples of 16 (>> mip: multiples of B), a block never straddles the texture's wrap.
#include "engine/render/surface_cache.h"

#include "asm/kernels.h"
#include "engine/core/log.h"
#include "engine/render/surface_math.h"

namespace sb::render {

namespace {

bool g_logged_exhausted = false;

uint32_t light_key(const int32_t* values, int32_t texture) {
  uint32_t h = 2166136261u;  // FNV-1a over the inputs the surface depends on
  auto mix = [&h](uint32_t x) {
    for (int i = 0; i < 4; ++i) {
      h ^= (x >> (8 * i)) & 0xffu;
      h *= 16777619u;
    }
  };
  for (int k = 0; k < kMaxLightStyles; ++k) mix(uint32_t(values[k]));
  mix(uint32_t(texture));
  return h;
}

void current_style_values(const Face& f, const int* lightstyles, int32_t* out) {
  for (int k = 0; k < kMaxLightStyles; ++k) out[k] = 0;
  if (f.light_offset == kNoLightmap) return;
  for (int k = 0; k < kMaxLightStyles && f.styles[k] != 255; ++k) {
    int v = kLightStyleNormal;
    if (lightstyles && f.styles[k] < kMaxLightStyleSlots) v = lightstyles[f.styles[k]];
    out[k] = v < 0 ? 0 : (v > 65535 ? 65535 : v);
  }
}

}  // namespace

void build_surface(const uint16_t* grid, int grid_width, const Texture& tex, int mip, int smin, int tmin,
                   int width, int height, const uint8_t* colormap, uint8_t* out) {
  // asm/surface_block.h is this loop's contract (its scalar reference is the block-stepping
  // loop described at the top of this file); texture sizes and texture_mins are multiples
  // of 16, so at every mip they are multiples of the block size.
  const int tw = int(tex.width >> mip), th = int(tex.height >> mip);
  const int b = 16 >> mip;
  const simd::SurfaceBlockFn fn =
      (tw % b == 0 && th % b == 0 && smin % 16 == 0 && tmin % 16 == 0) ? simd::active().surface_block
                                                                        : simd::surface_block_scalar;
  fn(grid, grid_width, tex.mips[mip], tw, th, mip, smin >> mip, tmin >> mip, width, height, colormap, out);
}

const uint8_t* fetch_surface(BspWorld& world, uint32_t face_index, int mip, const RenderInputs& in,
                             mem::MemorySystem& memory, RenderStats& stats, SurfaceHeader* header) {
  Face& face = world.faces[face_index];
  const TexInfo& ti = world.texinfo[face.texinfo];
  const int width = face.extents[0] >> mip, height = face.extents[1] >> mip;
  if (width <= 0 || height <= 0 || face.extents[0] > 4096 || face.extents[1] > 4096) return nullptr;

  const int32_t texture = animated_texture(world, ti.texture, in.time);
  int32_t values[kMaxLightStyles];
  current_style_values(face, in.lightstyles, values);
  const uint32_t frame = memory.frame_number();

  auto* block = static_cast<uint8_t*>(memory.cache.get(face.cache[mip], frame));
  if (block) {
    auto* h = reinterpret_cast<SurfaceHeader*>(block);
    bool same = h->width == width && h->height == height && h->mip == mip && h->texture == texture;
    for (int k = 0; k < kMaxLightStyles && same; ++k) same = h->style_values[k] == values[k];
    if (same) {
      ++stats.surface_cache_hits;
      if (header) *header = *h;
      return block + sizeof(SurfaceHeader);
    }
    if (h->width != width || h->height != height) {  // cannot happen for a given face; be safe
      memory.cache.free(face.cache[mip]);
      block = nullptr;
    }
  }

  if (!block) {
    const size_t size = sizeof(SurfaceHeader) + size_t(width) * size_t(height);
    face.cache[mip] = memory.cache.alloc(size, "surface", frame);
    block = static_cast<uint8_t*>(memory.cache.get(face.cache[mip], frame));
    if (!block) {
      face.cache[mip] = {};
      stats.cache_exhausted = true;
      if (!g_logged_exhausted) {
        g_logged_exhausted = true;
        char why[192];
        memory.cache.failure_message(why, sizeof why);
        log_warning("surface cache exhausted (face %u, mip %d, %dx%d): %s; drawing unlit", face_index, mip,
                    width, height, why);
      }
      return nullptr;
    }
  }

  // Build: light grid in the frame arena, popped on return.
  mem::ArenaScope scope(memory.frame());
  const int gsize = light_grid_size(face);
  auto* grid = scope.arena().push_array<uint16_t>(size_t(gsize), "light grid");
  if (!grid) {
    memory.cache.free(face.cache[mip]);
    face.cache[mip] = {};
    stats.cache_exhausted = true;
    if (!g_logged_exhausted) {
      g_logged_exhausted = true;
      log_warning("frame arena cannot hold a light grid of %d samples (face %u); drawing unlit", gsize,
                  face_index);
    }
    return nullptr;
  }
  const int gw = face_light_grid(world, face, in.lightstyles, grid, nullptr);
  build_surface(grid, gw, world.textures[texture], mip, face.texture_mins[0], face.texture_mins[1], width,
                height, in.colormap, block + sizeof(SurfaceHeader));

  auto* h = reinterpret_cast<SurfaceHeader*>(block);
  h->width = width;
  h->height = height;
  h->texture = texture;
  h->mip = mip;
  for (int k = 0; k < kMaxLightStyles; ++k) h->style_values[k] = values[k];
  face.cache_light_key[mip] = light_key(values, texture);
  ++stats.surfaces_built;
  if (header) *header = *h;
  return block + sizeof(SurfaceHeader);
}

void surface_cache_new_level() { g_logged_exhausted = false; }

}  // namespace sb::render
