// engine/host/camera_path.h: the deterministic flythrough route through a map.
//
//   viewpoints (player starts, intermission cameras, teleport targets; in a fixed order)
//   P0 ----> P1 ----> P2 ... ----> Pn-1        frame f of N lies at u = f / (N-1) * (n-1)
//         eased position, shortest-arc yaw,    plus a slow look-around sweep so every
//         linear pitch                         segment shows more than one direction
//
// The same (world, frame, N) gives the same view on every machine and run, so
// flythrough figures and benchmark rows compare like with like.
// Memory: the viewpoint array lives in the arena passed to build_camera_path
// (the level arena): valid until the level is reset.
#pragma once

#include "engine/core/error.h"
#include "engine/formats/bsp.h"
#include "engine/world/view_params.h"
#include "memory/arena.h"

namespace sb::host {

struct CameraPath {
  const ViewParams* points = nullptr;
  int count = 0;
};

constexpr int kMaxCameraPoints = 64;

// Viewpoints of the world in a fixed order (the first is the player start when the
// map has one). A map with no usable entity gets one point at the centre of the
// world model's box. Fails only when the arena is full.
Result<CameraPath> build_camera_path(const BspWorld& world, mem::Arena& arena);

// The view at frame `frame` of a flythrough of `total` frames (0 <= frame < total).
ViewParams camera_path_view(const CameraPath& path, int frame, int total, float fov_x);

}  // namespace sb::host
