// tests/support/reference_renderer.h: an independent reference renderer for tests.
//
// Slow, simple, obviously right. It shares with the real renderer only the rules in
// engine/render/surface_math.h (lighting grid, shade interpolation, mip choice, texel
// lookup, sky, turbulence) and the screen conventions of engine/render/render_local.h.
// Everything else is done its own way, in double precision:
//   - its own view basis from yaw/pitch/roll (x forward, y left, z up, pitch > 0 looks down);
//   - every face of model 0 that faces the viewer is considered (no PVS: a z-buffer gives
//     the same picture, the PVS only removes hidden things);
//   - a pixel belongs to a face when the ray through the pixel centre passes inside the
//     face's edges (tested in 3D against the plane through the eye and each edge, so faces
//     sharing an edge split its pixels exactly; ties go by the top-left rule);
//   - depth is the exact ray/plane intersection; the nearest face wins;
//   - texture coordinates are evaluated exactly at the hit point (no 16-pixel stepping).
// The mip level comes from choose_mip() with nearzi = the largest 1/z of the face polygon
// after clipping to the four frustum planes (clipped here, by this file).
//
// Test code: uses the heap and std containers freely. Not for the engine.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"

namespace sb::test {

constexpr uint32_t kNoFace = 0xffffffffu;  // pixel covered by no face (drawn in colour 0)

enum class SampleKind : uint8_t { None, Lit, Sky, Turb };

// What the reference saw at one pixel (for explaining disagreements).
struct ReferenceSample {
  uint32_t face = kNoFace;
  SampleKind kind = SampleKind::None;
  int8_t mip = 0;
  int32_t u = 0, v = 0;     // surface texel at `mip` (Lit), after clamping
  double s = 0, t = 0;      // exact texture coordinates at the hit point (Lit, Turb)
  double depth = 0;         // view-space z of the hit point
  int32_t texture = -1;     // texture index after animation
};

struct ReferenceFrame {
  int width = 0, height = 0;
  // The view this frame was drawn with: ray(sx, sy) is the direction through screen point
  // (sx, sy) (pixel centres at x + 0.5), with unit depth along forward.
  glm::dvec3 origin, forward, right, up;
  double xcenter = 0, ycenter = 0, xscale = 1, yscale = 1;
  glm::dvec3 ray(double sx, double sy) const {
    return forward + ((sx - xcenter) / xscale) * right - ((sy - ycenter) / yscale) * up;
  }
  std::vector<uint8_t> pixels;          // palette indices, row-major, no padding
  std::vector<ReferenceSample> samples; // one per pixel
  uint32_t face_at(int x, int y) const { return samples[size_t(y) * width + x].face; }
};

// Per-frame inputs other than the view.
struct ReferenceInputs {
  const BspWorld* world = nullptr;
  double time = 0.0;
  const int* lightstyles = nullptr;  // kMaxLightStyleSlots values (256 = normal); nullptr = all normal
  const uint8_t* colormap = nullptr; // 64 x 256
};

class ReferenceRenderer {
 public:
  explicit ReferenceRenderer(const ReferenceInputs& in);

  ReferenceFrame render(const ViewParams& view, int width, int height);

  // Colour of lit surface texel (u, v) (clamped like the renderer does) of `face` at `mip`,
  // drawn with texture `texture` (already animated). For mismatch classification.
  uint8_t lit_colour(uint32_t face, int texture, int mip, int u, int v);
  // Colour of a turbulent face at texture coordinates (s, t).
  uint8_t turb_colour(int texture, double s, double t) const;
  // Colour of the sky along world direction dir.
  uint8_t sky_colour(int texture, const glm::dvec3& dir) const;
  // The sky rule of surface_math.h written out here: the layer coordinates of dir before the
  // scroll (kSkyScale * the flattened, normalised direction's x and y, in texels) ...
  static void sky_coords(const glm::dvec3& dir, double* qx, double* qy);
  // ... and the colour at layer coordinates (qx, qy) (equals sky_colour for sky_coords(dir)).
  uint8_t sky_colour_at(int texture, double qx, double qy) const;

  // Exact texture coordinates where the ray origin + z * ray (z > 0) meets the plane of
  // `face`; false when it does not.
  bool face_st(uint32_t face, const glm::dvec3& origin, const glm::dvec3& ray, double* s, double* t) const;

  // The texture a face shows at this renderer's time (animation resolved).
  int animated_texture(uint32_t face) const;

  const BspWorld& world() const { return *in_.world; }

 private:
  const std::vector<uint16_t>& light_grid(uint32_t face, int* grid_width);

  ReferenceInputs in_;
  std::vector<std::vector<uint16_t>> grids_;  // per face, computed on first use
  std::vector<int> grid_widths_;
  std::vector<uint8_t> grid_done_;
};

// The whole picture in one call: palette indices, and (optionally) the face id of every
// pixel (kNoFace where nothing is drawn).
std::vector<uint8_t> reference_render(const BspWorld& world, const ViewParams& view, int width, int height,
                                      double time, const int* lightstyles, const uint8_t* colormap,
                                      std::vector<uint32_t>* face_ids = nullptr);

}  // namespace sb::test
