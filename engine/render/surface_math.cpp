// engine/render/surface_math.cpp: the shared rules of surface_math.h (lighting, mip
// choice, animation, sky, turbulence). Both the edge-list renderer and the reference
// renderer call these, so every formula here is the documented one, exactly.
#include "engine/render/surface_math.h"

#include <cmath>

#include "engine/render/render.h"

namespace sb::render {

namespace {

int style_value(const int* lightstyles, uint8_t style) {
  int v = kLightStyleNormal;
  if (lightstyles && style < kMaxLightStyleSlots) v = lightstyles[style];
  if (v < 0) v = 0;
  if (v > 65535) v = 65535;
  return v;
}

inline int wrap(int64_t i, int n) {
  int64_t r = i % n;
  return int(r < 0 ? r + n : r);
}

}  // namespace

int face_light_grid(const BspWorld& world, const Face& face, const int* lightstyles, uint16_t* grid,
                    int* grid_height) {
  const int gw = face.extents[0] / 16 + 1;
  const int gh = face.extents[1] / 16 + 1;
  const int n = gw * gh;
  if (grid_height) *grid_height = gh;

  // Which styles contribute, and with what value.
  int values[kMaxLightStyles];
  int count = 0;
  if (face.light_offset != kNoLightmap && face.light_offset >= 0 && world.lightdata) {
    for (int k = 0; k < kMaxLightStyles && face.styles[k] != 255; ++k) {
      // The loader guarantees the blocks lie inside lightdata; stay safe regardless.
      uint64_t end = uint64_t(face.light_offset) + uint64_t(k + 1) * uint64_t(n);
      if (end > world.lightdata_size) break;
      values[count++] = style_value(lightstyles, face.styles[k]);
    }
  }

  if (face.light_offset == kNoLightmap || face.light_offset < 0 || !world.lightdata) {
    for (int i = 0; i < n; ++i) grid[i] = 64;  // full light: (255*256 - 255*256) >> 2 = 0, clamped
    return gw;
  }

  const uint8_t* samples = world.lightdata + face.light_offset;
  for (int i = 0; i < n; ++i) {
    int32_t l = 0;  // at most 4 * 255 * 65535: fits
    for (int k = 0; k < count; ++k) l += int32_t(samples[k * n + i]) * values[k];
    int32_t shade = (255 * 256 - l) >> 2;
    if (shade < 64) shade = 64;
    if (shade > 63 * 256 + 255) shade = 63 * 256 + 255;
    grid[i] = uint16_t(shade);
  }
  return gw;
}

uint16_t shade_at(const uint16_t* grid, int grid_width, int u, int v, int mip) {
  const int b = 16 >> mip;
  const int shift = 2 * (4 - mip);  // 2 * log2(B)
  const int gx = u / b, fx = u % b;
  const int gy = v / b, fy = v % b;
  const uint16_t* g = grid + gy * grid_width + gx;
  const int32_t g00 = g[0], g10 = g[1], g01 = g[grid_width], g11 = g[grid_width + 1];
  const int32_t top = g00 * (b - fx) + g10 * fx;
  const int32_t bottom = g01 * (b - fx) + g11 * fx;
  return uint16_t((top * (b - fy) + bottom * fy) >> shift);
}

int choose_mip(float nearzi, float xscale, float mipadjust) {
  if (!(mipadjust > 0.0f)) mipadjust = 1.0f;
  const float p = nearzi * xscale / mipadjust;
  if (p >= 1.0f) return 0;
  if (p >= 0.4f) return 1;
  if (p >= 0.2f) return 2;
  return 3;
}

int animated_texture(const BspWorld& world, int texture, double time) {
  if (texture < 0 || uint32_t(texture) >= world.num_textures) return texture;
  const Texture& base = world.textures[texture];
  if (base.anim_total == 0 || base.anim_next < 0) return texture;
  if (!std::isfinite(time)) time = 0.0;
  const int frame = wrap(int64_t(std::fmod(std::floor(time * 5.0), double(base.anim_total))), base.anim_total);
  int t = texture;
  for (int step = 0; step <= base.anim_total; ++step) {
    if (t < 0 || uint32_t(t) >= world.num_textures) break;
    if (world.textures[t].anim_index == frame) return t;
    t = world.textures[t].anim_next;
  }
  return texture;
}

uint8_t sky_texel(const Texture& sky, const glm::vec3& dir, double time) {
  if (!std::isfinite(time)) time = 0.0;
  double x = dir.x, y = dir.y, z = 3.0 * double(dir.z);
  double len = std::sqrt(x * x + y * y + z * z);
  if (len > 0.0 && std::isfinite(len)) {
    x /= len;
    y /= len;
  } else {
    x = 1.0;
    y = 0.0;
  }
  const int w = int(sky.width), h = int(sky.height), half = w / 2;
  const uint8_t* pix = sky.mips[0];
  // Front layer (left half), index 0 is transparent.
  {
    const double o = kSkyFrontSpeed * time;
    const int s = wrap(int64_t(std::floor(o + kSkyScale * x)), half);
    const int t = wrap(int64_t(std::floor(o + kSkyScale * y)), h);
    const uint8_t c = pix[t * w + s];
    if (c != 0) return c;
  }
  const double o = kSkyBackSpeed * time;
  const int s = wrap(int64_t(std::floor(o + kSkyScale * x)), half);
  const int t = wrap(int64_t(std::floor(o + kSkyScale * y)), h);
  return pix[t * w + half + s];
}

int32_t turb_offset(int i) {
  struct Table {
    int32_t v[128];
    Table() {
      for (int k = 0; k < 128; ++k) {
        v[k] = int32_t(std::lround(8.0 * std::sin(6.283185307179586 * k / 128.0) * 65536.0));
      }
    }
  };
  static const Table table;
  return table.v[i & 127];
}

int turb_phase(double time) {
  if (!std::isfinite(time)) return 0;
  return wrap(int64_t(std::fmod(std::floor(time * kTurbSpeed), 128.0)), 128);
}

uint8_t turb_texel(const Texture& tex, float s, float t, double time) {
  if (!std::isfinite(s) || std::fabs(s) > 1e9f) s = 0.0f;  // keeps the integer conversions defined
  if (!std::isfinite(t) || std::fabs(t) > 1e9f) t = 0.0f;
  const int phase = turb_phase(time);
  const int64_t si = int64_t(std::floor(double(s)));
  const int64_t ti = int64_t(std::floor(double(t)));
  const int64_t s2 = int64_t(std::floor(double(s) + turb_offset(int((ti + phase) & 127)) / 65536.0));
  const int64_t t2 = int64_t(std::floor(double(t) + turb_offset(int((si + phase) & 127)) / 65536.0));
  const int w = int(tex.width), h = int(tex.height);
  return tex.mips[0][wrap(t2, h) * w + wrap(s2, w)];
}

}  // namespace sb::render
