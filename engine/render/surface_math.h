// engine/render/surface_math.h: the rules that the edge-list renderer and the
// reference renderer must share exactly: lighting, mip choice, texture lookup,
// sky and turbulence. Everything else (projection, rasterisation, perspective)
// the reference renderer does its own way.
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"

namespace sb::render {

// Light grid of a face: (extents[0]/16 + 1) x (extents[1]/16 + 1) shade values.
// shade = 16 bits, high byte = colormap row (0 brightest .. 63 darkest):
//   L = sum over the face's styles of sample * style_value   (style_value 256 = normal)
//   shade = clamp((255 * 256 - L) >> 2, 64, 63 * 256 + 255)   ... (see surface_math.cpp)
// Faces without a lightmap get the row for full light (L = 255*256): shade = 0x40 clamp.
// Returns the grid width; grid must hold 18*18 entries (the 256-texel extent limit
// gives at most 17x17; larger faces are rejected by the loader... or clamped, see .cpp).
int face_light_grid(const BspWorld& world, const Face& face, const int* lightstyles, uint16_t* grid,
                    int* grid_height);

// Shade at surface texel (u, v) of mip level `mip`, u = (s - texture_mins[0]) >> mip, likewise v:
// the bilinear interpolation of the grid with block size B = 16 >> mip, computed as
//   (((g00*(B-fx) + g10*fx) * (B-fy) + (g01*(B-fx) + g11*fx) * fy) >> (2 * log2 B)
// exactly (the surface builder steps the same numerators incrementally).
uint16_t shade_at(const uint16_t* grid, int grid_width, int u, int v, int mip);

// Mip level for a surface whose nearest clipped vertex has 1/z = nearzi, seen with
// projection scale xscale: pixels per texel p = nearzi * xscale / texinfo.mipadjust;
// mip 0 if p >= 1, 1 if p >= 0.4, 2 if p >= 0.2, else 3.
int choose_mip(float nearzi, float xscale, float mipadjust);

// Texel of texture `tex` at mip `mip` for surface texel (u, v) of a face whose
// texture_mins are (smin, tmin): wraps with a positive modulo.
inline uint8_t texture_texel(const Texture& tex, int mip, int smin, int tmin, int u, int v) {
  int w = int(tex.width >> mip), h = int(tex.height >> mip);
  int s = ((u + (smin >> mip)) % w + w) % w;
  int t = ((v + (tmin >> mip)) % h + h) % h;
  return tex.mips[mip][t * w + s];
}

// Sky: a pixel looking along world direction `dir` (not normalised) at time `time`
// shows the front layer (left half of the sky texture; index 0 = transparent) over
// the back layer (right half); layers scroll at 8 and 16 texels per second.
uint8_t sky_texel(const Texture& sky, const glm::vec3& dir, double time);

// Turbulent surfaces (water, slime, lava, teleport): unlit mip-0 texel at texture
// coordinates (s, t) (floating, texture space), warped by a sine of the other axis
// with amplitude 8 texels and period 128 texels, moving with time.
uint8_t turb_texel(const Texture& tex, float s, float t, double time);

}  // namespace sb::render
