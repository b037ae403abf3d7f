// engine/render/view.cpp: setup_view (camera basis, projection scale, frustum planes,
// view leaf).
//
// Angles (degrees, Quake's conventions): yaw turns about +z (0 looks along +x, 90 along
// +y), positive pitch looks down, roll turns the right/up pair about forward.
// Frustum planes pass through the eye; their normals point into the view volume and
// each plane is exactly the set of points projecting onto one screen border:
//   left   sx >= 0       right  sx <= width
//   top    sy >= 0       bottom sy <= height
#include <cmath>

#include <glm/geometric.hpp>

#include "engine/render/front_local.h"
#include "engine/world/world.h"

namespace sb::render {
namespace {

constexpr float kPi = 3.14159265358979323846f;

Plane plane_through(const glm::vec3& normal_unscaled, const glm::vec3& origin) {
  Plane p{};
  float len = glm::length(normal_unscaled);
  glm::vec3 n = len > 0.0f ? normal_unscaled / len : glm::vec3(1.0f, 0.0f, 0.0f);
  p.normal = n;
  p.dist = glm::dot(n, origin);
  p.type = 3;  // never treated as axial: box tests use signbits
  p.signbits = uint8_t((n.x < 0.0f ? 1 : 0) | (n.y < 0.0f ? 2 : 0) | (n.z < 0.0f ? 4 : 0));
  return p;
}

float finite_or(float v, float fallback) { return std::isfinite(v) ? v : fallback; }

}  // namespace

ViewState setup_view(const BspWorld& world, const ViewParams& params, int width, int height, uint32_t frame) {
  ViewState v{};
  v.width = width < 1 ? 1 : width;
  v.height = height < 1 ? 1 : height;
  v.frame = frame;
  v.origin = glm::vec3(finite_or(params.origin.x, 0.0f), finite_or(params.origin.y, 0.0f),
                       finite_or(params.origin.z, 0.0f));

  const float deg = kPi / 180.0f;
  float yaw = std::fmod(finite_or(params.yaw, 0.0f), 360.0f) * deg;
  float pitch = std::fmod(finite_or(params.pitch, 0.0f), 360.0f) * deg;
  float roll = std::fmod(finite_or(params.roll, 0.0f), 360.0f) * deg;
  float sy = std::sin(yaw), cy = std::cos(yaw);
  float sp = std::sin(pitch), cp = std::cos(pitch);
  float sr = std::sin(roll), cr = std::cos(roll);

  // Unrolled basis first (pitch tips forward down and up forward), then roll.
  glm::vec3 forward(cp * cy, cp * sy, -sp);
  glm::vec3 right0(sy, -cy, 0.0f);
  glm::vec3 up0(sp * cy, sp * sy, cp);
  v.forward = forward;
  v.right = cr * right0 - sr * up0;
  v.up = cr * up0 + sr * right0;

  float fov = finite_or(params.fov_x, 90.0f);
  if (fov < 1.0f) fov = 1.0f;
  if (fov > 179.0f) fov = 179.0f;
  v.xcenter = float(v.width) * 0.5f;
  v.ycenter = float(v.height) * 0.5f;
  v.xscale = v.xcenter / std::tan(fov * 0.5f * deg);
  v.yscale = v.xscale;

  // sx >= 0      <=>  xcenter * z + xscale * x >= 0          (x = right, y = up, z = forward)
  // sx <= width  <=>  (width - xcenter) * z - xscale * x >= 0
  // sy >= 0      <=>  ycenter * z - yscale * y >= 0
  // sy <= height <=>  (height - ycenter) * z + yscale * y >= 0
  const float w = float(v.width), h = float(v.height);
  v.frustum[0] = plane_through(v.xcenter * v.forward + v.xscale * v.right, v.origin);
  v.frustum[1] = plane_through((w - v.xcenter) * v.forward - v.xscale * v.right, v.origin);
  v.frustum[2] = plane_through(v.ycenter * v.forward - v.yscale * v.up, v.origin);
  v.frustum[3] = plane_through((h - v.ycenter) * v.forward + v.yscale * v.up, v.origin);

  v.view_leaf = point_in_leaf(world, v.origin);
  return v;
}

}  // namespace sb::render
