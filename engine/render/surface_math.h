// engine/render/surface_math.h: the rules that the edge-list renderer and the
// reference renderer must share exactly: lighting, mip choice, texture lookup,
// texture animation, sky and turbulence. Everything else (projection,
// rasterisation, perspective) the reference renderer does its own way.
// Every function here is pure (no globals, no allocation) and deterministic.
// Non-finite inputs never reach an integer conversion: a non-finite time counts as 0,
// non-finite (or beyond +-1e9) s, t in turb_texel count as 0, a non-finite sky direction
// as (1, 0, 0).
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"

namespace sb::render {

// Light grid of a face: (extents[0]/16 + 1) x (extents[1]/16 + 1) shade values, row-major
// (index = gy * grid_width + gx; grid point (gx, gy) sits at surface texel (16 gx, 16 gy) of mip 0).
// Samples: lightdata[light_offset + k * light_grid_size(face) + index] for the k-th style of
// face.styles (k = 0..3, the list ends at the first 255).
// Style values: lightstyles[style] when lightstyles != nullptr and style < kMaxLightStyleSlots,
// otherwise kLightStyleNormal (256); negative values count as 0, values above 65535 as 65535.
// shade = 16 bits, high byte = colormap row (0 brightest .. 63 darkest):
//   L = sum over the face's styles of sample * style_value   (style_value 256 = normal)
//   shade = clamp((255 * 256 - L) >> 2, 64, 63 * 256 + 255)   (>> is an arithmetic shift)
// Faces without a lightmap (light_offset == kNoLightmap) get full light (L = 255 * 256,
// i.e. shade 64 everywhere).
// grid must hold light_grid_size(face) entries. Returns the grid width; *grid_height (when
// non-null) gets the grid height.
inline int light_grid_size(const Face& f) { return (f.extents[0] / 16 + 1) * (f.extents[1] / 16 + 1); }
int face_light_grid(const BspWorld& world, const Face& face, const int* lightstyles, uint16_t* grid,
                    int* grid_height);

// Shade at surface texel (u, v) of mip level `mip`, u = (s - texture_mins[0]) >> mip, likewise v,
// with 0 <= u < extents[0] >> mip and 0 <= v < extents[1] >> mip:
// the bilinear interpolation of the grid with block size B = 16 >> mip, gx = u / B, fx = u % B,
// gy = v / B, fy = v % B, gAB = grid[(gy + B') * grid_width + gx + A'] for A, B in {0, 1},
// computed as
//   (((g00*(B-fx) + g10*fx) * (B-fy) + (g01*(B-fx) + g11*fx) * fy) >> (2 * log2 B)
// exactly (the surface builder steps the same numerators incrementally).
uint16_t shade_at(const uint16_t* grid, int grid_width, int u, int v, int mip);

// Mip level for a surface whose nearest vertex has 1/z = nearzi (the vertices of the
// face polygon after clipping to the four ViewState::frustum planes), seen with
// projection scale xscale: pixels per texel p = nearzi * xscale / texinfo.mipadjust
// (float arithmetic, in that order; mipadjust <= 0 counts as 1);
// mip 0 if p >= 1, 1 if p >= 0.4, 2 if p >= 0.2, else 3 (also for NaN).
int choose_mip(float nearzi, float xscale, float mipadjust);

// Texel of texture `tex` at mip `mip` for surface texel (u, v) of a face whose
// texture_mins are (smin, tmin): wraps with a positive modulo.
inline uint8_t texture_texel(const Texture& tex, int mip, int smin, int tmin, int u, int v) {
  int w = int(tex.width >> mip), h = int(tex.height >> mip);
  int s = ((u + (smin >> mip)) % w + w) % w;
  int t = ((v + (tmin >> mip)) % h + h) % h;
  return tex.mips[mip][t * w + s];
}

// Texture animation: the texture index to draw at `time` for a face whose texinfo names
// `texture`. Not animated (anim_total == 0 or anim_next < 0): `texture` itself. Otherwise
// frame = floor(time * 5) mod anim_total (positive modulo), and the result is the texture
// of that anim_index found by following anim_next from `texture` (at most anim_total steps;
// a broken chain yields `texture`). The alternate sequence is never chosen here.
int animated_texture(const BspWorld& world, int texture, double time);

// Sky: a pixel looking along world direction `dir` (not normalised) at time `time`
// shows the front layer (left half of the sky texture, mip 0; index 0 = transparent) over
// the back layer (right half). Let H = width / 2 (layer width), n = normalize(dir.x, dir.y,
// 3 * dir.z) (the flattened dome; a zero vector counts as (1, 0, 0)), all in double:
//   layer s = floor(speed * time + kSkyScale * n.x), t = floor(speed * time + kSkyScale * n.y)
//   texel   = mips[0][(t mod height) * width + (s mod H) + (0 for front, H for back)]
// (positive modulo), speed = 16 texels/s for the front layer and 8 for the back layer.
constexpr double kSkyScale = 378.0;
constexpr double kSkyFrontSpeed = 16.0, kSkyBackSpeed = 8.0;
uint8_t sky_texel(const Texture& sky, const glm::vec3& dir, double time);

// Turbulent surfaces (water, slime, lava, teleport): unlit mip-0 texel at texture
// coordinates (s, t) (floating, texture space: s = dot(p, vecs[0]) + vecs[0].w), warped by a
// sine of the other axis with amplitude 8 texels and period 128 texels, moving with time:
//   phase = floor(time * kTurbSpeed) mod 128, si = floor(s), ti = floor(t)
//   s' = floor(s + turb_offset((ti + phase) mod 128) / 65536.0)
//   t' = floor(t + turb_offset((si + phase) mod 128) / 65536.0)
//   texel = mips[0][(t' mod height) * width + (s' mod width)]       (positive modulo, double)
// turb_offset(i) = round(8 * sin(2 pi i / 128) * 65536): 16.16 fixed point, i in 0..127.
constexpr double kTurbSpeed = 20.0;  // table steps per second
int32_t turb_offset(int i);
int turb_phase(double time);  // floor(time * kTurbSpeed) mod 128, in 0..127
uint8_t turb_texel(const Texture& tex, float s, float t, double time);

}  // namespace sb::render
