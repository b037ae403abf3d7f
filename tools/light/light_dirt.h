// tools/light/light_dirt.h: dirt (ambient occlusion) for the light stage.
//
// Per lightmap grid point (not per -extra sub-sample), N rays leave the sample point inside a
// cone of half angle "_dirtangle" (default 88 degrees) around the face normal, cosine
// weighted, in a fixed pattern (rings x azimuths; "_dirtmode" 1 jitters each ray inside its
// cell with a hash of face, grid point and ray, so results stay deterministic). A ray that
// enters solid within "_dirtdepth" units (default 128) at distance d counts 1 - d / depth
// (a wall touching the sample counts 1, one at the depth 0); rays that reach sky or nothing
// count 0; rays that start inside solid are left out. The occlusion o is the mean over the
// counted rays, 0..1.
// A light that uses dirt has its value at that grid point multiplied by
//   dirt_factor(o, scale, gain) = 1 - min(1, scale * o^gain)
// ("_dirtscale" default 1: larger is darker; "_dirtgain" default 1: smaller is darker and
// reaches further from corners). So an open floor (nothing within the depth) is unchanged.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "tools/light/light_face.h"

namespace sb::tools {

constexpr int kDirtRings = 4, kDirtAzimuths = 8;  // 32 rays per grid point

inline float dirt_factor(float occlusion, float scale, float gain) {
  if (!(occlusion > 0)) return 1.0f;
  float d = scale * (gain == 1.0f ? occlusion : std::pow(occlusion, gain));
  return d >= 1.0f ? 0.0f : 1.0f - d;
}

// The fixed ray pattern (local frame, z = normal) for a cone of half angle angle_deg.
std::vector<glm::vec3> dirt_directions(float angle_deg);

// Fills work->occlusion (one value per grid point) from work->centres. Needs face_setup().
void dirt_face(const LightScene& scene, uint32_t face_index, FaceWork* work);

// Orthonormal tangent frame (t, b) for unit normal n, chosen deterministically from n.
void tangent_frame(const glm::vec3& n, glm::vec3* t, glm::vec3* b);

// A deterministic hash of three integers -> 0..1 (for jittered ray patterns).
float hash_unit(uint32_t a, uint32_t b, uint32_t c);

}  // namespace sb::tools
