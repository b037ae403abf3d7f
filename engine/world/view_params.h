// engine/world/view_params.h: where a camera is and where it looks.
// Shared by the renderer (engine/render/render.h includes this), the world queries
// that pick viewpoints (viewpoints.h), demos and benchmarks. Header only.
#pragma once
#include <glm/vec3.hpp>

namespace sb {

struct ViewParams {
  glm::vec3 origin{0.0f};
  float yaw = 0.0f, pitch = 0.0f, roll = 0.0f;  // degrees; Quake's conventions (pitch > 0 looks down)
  float fov_x = 90.0f;                          // horizontal field of view, degrees (10..170)
};

}  // namespace sb
