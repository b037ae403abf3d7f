// engine/render/surface_cache.cpp: building lit surfaces and keeping them in the cache.
//
// The builder walks the surface in light blocks of B = 16 >> mip texels. Within a block the
// shade is the bilinear blend of its four grid corners; rather than evaluating it per texel
// it steps the exact numerators of shade_at() (see surface_math.h):
//   left(fy)  = g00 * (B - fy) + g01 * fy        (steps by g01 - g00 per row)
//   right(fy) = g10 * (B - fy) + g11 * fy        (steps by g11 - g10 per row)
//   num(fx)   = left * B + (right - left) * fx   (steps by right - left per texel)
//   shade     = num >> (2 log2 B)
// so the result equals shade_at() bit for bit. Because texture sizes and texture_mins are
// multiples of 16 (>> mip: multiples of B), a block never straddles the texture's wrap.
#include "engine/render/surface_cache.h"

#include "engine/core/log.h"
#include "engine/render/surface_math.h"

namespace sb::render {

namespace {

bool g_logged_exhausted = false;

inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

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
  const int b = 16 >> mip;
  const int shift = 2 * (4 - mip);
  const int tw = int(tex.width >> mip), th = int(tex.height >> mip);
  const uint8_t* texels = tex.mips[mip];
  const int soff = smin >> mip, toff = tmin >> mip;
  const int bw = width / b, bh = height / b;

  for (int by = 0; by < bh; ++by) {
    const uint16_t* grow = grid + by * grid_width;
    const int trow = wrap(by * b + toff, th);
    uint8_t* drow = out + by * b * width;
    for (int bx = 0; bx < bw; ++bx) {
      const int32_t g00 = grow[bx], g10 = grow[bx + 1];
      const int32_t g01 = grow[bx + grid_width], g11 = grow[bx + grid_width + 1];
      int32_t left = g00 * b, right = g10 * b;  // numerators at fy = 0, scaled by B
      const int32_t left_step = g01 - g00, right_step = g11 - g10;
      const uint8_t* src = texels + trow * tw + wrap(bx * b + soff, tw);
      uint8_t* dst = drow + bx * b;
      for (int fy = 0; fy < b; ++fy) {
        // left, right here hold g00*(B-fy) + g01*fy etc.; num(fx) = left*B + (right-left)*fx.
        int32_t num = left * b;
        const int32_t step = right - left;
        for (int fx = 0; fx < b; ++fx) {
          dst[fx] = colormap[((num >> shift) & 0xff00) + src[fx]];
          num += step;
        }
        left += left_step;
        right += right_step;
        src += tw;
        dst += width;
      }
    }
  }
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
