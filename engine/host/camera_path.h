// engine/host/camera_path.h: the deterministic flythrough route through a map.
//
//   collect_viewpoints (engine/world/viewpoints.h): player start first, then other
//   entities; chained greedily from the start to the nearest unvisited viewpoint
//   whose straight line stays out of solid leaves (sampled every 16 units):
//
//   P0 ----> P1 ----> P2 ~~cut~~ P3 ----> ...  frame f of N lies at u = f / (N-1) * (n-1)
//   eased position, shortest-arc yaw, linear pitch, plus a slow look-around sweep.
//   When no clear line is left the chain jumps ("cut") to the nearest remaining
//   viewpoint: that segment holds at its start for half its time, then at its end,
//   so the camera is never placed inside a wall.
//
// The same (world, frame, N) gives the same view on every machine and run, so
// flythrough figures and benchmark rows compare like with like.
// Memory: the viewpoint array lives in the arena passed to build_camera_path
// (the level arena): valid until the level is reset.
#pragma once
#include <cstdint>


#include "engine/core/error.h"
#include "engine/formats/bsp.h"
#include "engine/world/view_params.h"
#include "memory/arena.h"

namespace sb::host {

struct CameraPath {
  const ViewParams* points = nullptr;
  const uint8_t* cut_before = nullptr;  // cut_before[i] != 0: jump (no flight) from point i-1 to i
  int count = 0;
};

constexpr int kCameraCandidates = 64;  // viewpoints asked of collect_viewpoints
constexpr int kMaxCameraPoints = 16;   // points kept on the route

// The route through the world (the first point is the player start when the map
// has one; a world without a non-solid leaf gets its box centre). Fails only when
// the arena is full.
Result<CameraPath> build_camera_path(const BspWorld& world, mem::Arena& arena);

// The view at frame `frame` of a flythrough of `total` frames (0 <= frame < total).
ViewParams camera_path_view(const CameraPath& path, int frame, int total, float fov_x);

}  // namespace sb::host
