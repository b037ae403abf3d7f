// tools/light/light_dirt.cpp: see light_dirt.h.
#include "tools/light/light_dirt.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace sb::tools {
namespace {

constexpr float kPi = 3.14159265358979323846f;

// Local direction for the cell (ring, azimuth) at offsets (ju, jv) in 0..1 inside the cell:
// cosine weighted (sin^2 of the polar angle uniform) up to the cone's half angle.
glm::vec3 cone_direction(int ring, int azimuth, float ju, float jv, float sin2_max) {
  float u = (float(ring) + ju) / float(kDirtRings) * sin2_max;  // sin^2 theta
  float phi = (float(azimuth) + jv) / float(kDirtAzimuths) * 2.0f * kPi;
  float r = std::sqrt(u);
  return glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u)));
}

}  // namespace

void tangent_frame(const glm::vec3& n, glm::vec3* t, glm::vec3* b) {
  // Cross with the world axis least aligned with n.
  glm::vec3 axis = std::fabs(n.x) < 0.6f ? glm::vec3(1, 0, 0) : (std::fabs(n.y) < 0.6f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
  *t = glm::normalize(glm::cross(n, axis));
  *b = glm::cross(n, *t);
}

float hash_unit(uint32_t a, uint32_t b, uint32_t c) {
  uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return float(h >> 8) * (1.0f / 16777216.0f);
}

std::vector<glm::vec3> dirt_directions(float angle_deg) {
  float a = std::clamp(angle_deg, 1.0f, 90.0f) * kPi / 180.0f;
  float sin2_max = std::sin(a) * std::sin(a);
  std::vector<glm::vec3> dirs;
  dirs.reserve(kDirtRings * kDirtAzimuths);
  for (int ring = 0; ring < kDirtRings; ++ring)
    for (int az = 0; az < kDirtAzimuths; ++az)  // alternate rings offset by half a step
      dirs.push_back(cone_direction(ring, az, 0.5f, (ring & 1) ? 0.0f : 0.5f, sin2_max));
  return dirs;
}

void dirt_face(const LightScene& sc, uint32_t face_index, FaceWork* work) {
  if (!work->lit || sc.dirt_dirs.empty()) return;
  const LightSettings& set = *sc.settings;
  const float depth = set.dirtdepth;
  const bool jitter = set.dirtmode == 1;
  const float a = std::clamp(set.dirtangle, 1.0f, 90.0f) * kPi / 180.0f;
  const float sin2_max = std::sin(a) * std::sin(a);
  glm::vec3 t, b;
  const glm::vec3 n = work->normal;
  tangent_frame(n, &t, &b);
  work->occlusion.assign(work->centres.size(), 0.0f);
  for (size_t k = 0; k < work->centres.size(); ++k) {
    const glm::vec3 p = work->centres[k];
    float occ = 0;
    int counted = 0;
    for (int i = 0; i < int(sc.dirt_dirs.size()); ++i) {
      glm::vec3 local = sc.dirt_dirs[size_t(i)];
      if (jitter) {
        uint32_t cell = uint32_t(k);
        local = cone_direction(i / kDirtAzimuths, i % kDirtAzimuths, hash_unit(face_index, cell, uint32_t(2 * i)),
                               hash_unit(face_index, cell, uint32_t(2 * i + 1)), sin2_max);
      }
      glm::vec3 d = t * local.x + b * local.y + n * local.z;
      ++work->dirt_rays;
      LineTracer::Hit h = sc.tracer->first_hit(p, p + d * depth);
      if (h.contents != kContentsEmpty && h.node < 0) continue;  // starts inside solid / sky
      ++counted;
      if (h.contents != kContentsSolid) continue;
      float dist = glm::length(h.point - p);
      occ += std::max(0.0f, 1.0f - dist / depth);
    }
    work->occlusion[k] = counted ? occ / float(counted) : 0.0f;
  }
}

}  // namespace sb::tools
