#include "engine/host/camera_path.h"

#include <cmath>

#include "engine/world/viewpoints.h"
#include "engine/world/world.h"

namespace sb::host {
namespace {

constexpr float kSampleStep = 16.0f;  // units between line-of-sight samples

// True when every sample on the segment a..b lies in a non-solid leaf.
bool line_is_clear(const BspWorld& world, const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 d = b - a;
  float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  int steps = int(len / kSampleStep) + 1;
  for (int i = 0; i <= steps; ++i) {
    glm::vec3 p = a + d * (float(i) / float(steps));
    if (world.leaves[point_in_leaf(world, p)].contents == kContentsSolid) return false;
  }
  return true;
}

float distance2(const glm::vec3& a, const glm::vec3& b) {
  glm::vec3 d = b - a;
  return d.x * d.x + d.y * d.y + d.z * d.z;
}

float wrap180(float a) {
  a = std::fmod(a, 360.0f);
  if (a > 180.0f) a -= 360.0f;
  if (a < -180.0f) a += 360.0f;
  return a;
}

}  // namespace

Result<CameraPath> build_camera_path(const BspWorld& world, mem::Arena& arena) {
  ViewParams* points = arena.push_array<ViewParams>(kMaxCameraPoints, "camera path");
  uint8_t* cut = arena.push_array<uint8_t>(kMaxCameraPoints, "camera path cuts");
  if (!points || !cut) {
    Error e;
    arena.failure_message(e.message, sizeof e.message);
    return e;
  }
  ViewParams candidates[kCameraCandidates];
  bool used[kCameraCandidates] = {};
  int n = collect_viewpoints(world, candidates, kCameraCandidates);
  if (n <= 0) {
    ViewParams v;
    if (world.num_models > 0) v.origin = (world.models[0].mins + world.models[0].maxs) * 0.5f;
    points[0] = v;
    return CameraPath{points, cut, 1};
  }
  // Greedy chain from the first viewpoint: nearest clear line first, else a cut to
  // the nearest remaining point. Viewpoints at an already used origin (the turned
  // copies collect_viewpoints adds) are skipped: the sweep already turns the view.
  int count = 0, current = 0;
  used[0] = true;
  points[count] = candidates[0];
  cut[count++] = 0;
  while (count < kMaxCameraPoints) {
    int clear = -1, any = -1;
    float clear_d = 0.0f, any_d = 0.0f;
    const glm::vec3& from = candidates[current].origin;
    for (int j = 0; j < n; ++j) {
      if (used[j]) continue;
      float d = distance2(from, candidates[j].origin);
      bool duplicate = false;
      for (int k = 0; k < count && !duplicate; ++k) duplicate = distance2(points[k].origin, candidates[j].origin) < 1.0f;
      if (duplicate) {
        used[j] = true;
        continue;
      }
      if (any < 0 || d < any_d) any = j, any_d = d;
      if ((clear < 0 || d < clear_d) && line_is_clear(world, from, candidates[j].origin)) clear = j, clear_d = d;
    }
    int next = clear >= 0 ? clear : any;
    if (next < 0) break;
    used[next] = true;
    points[count] = candidates[next];
    cut[count++] = clear >= 0 ? 0 : 1;
    current = next;
  }
  return CameraPath{points, cut, count};
}

ViewParams camera_path_view(const CameraPath& path, int frame, int total, float fov_x) {
  ViewParams v;
  v.fov_x = fov_x;
  if (path.count == 0 || total <= 0) return v;
  if (frame < 0) frame = 0;
  if (frame >= total) frame = total - 1;
  float t = total > 1 ? float(frame) / float(total - 1) : 0.0f;  // 0..1 over the whole flight
  // Slow look-around: two full turns over the flight plus a gentle nod.
  float sweep_yaw = 720.0f * t;
  float nod = 12.0f * std::sin(t * 6.2831853f * 3.0f);
  if (path.count == 1) {
    v.origin = path.points[0].origin;
    v.yaw = wrap180(path.points[0].yaw + sweep_yaw);
    v.pitch = nod;
    return v;  // (a lone point keeps a level view)
  }
  float u = t * float(path.count - 1);
  int seg = int(u);
  if (seg >= path.count - 1) seg = path.count - 2;
  float f = u - float(seg);
  float e = f * f * (3.0f - 2.0f * f);  // ease in and out at each viewpoint
  const ViewParams& a = path.points[seg];
  const ViewParams& b = path.points[seg + 1];
  if (path.cut_before && path.cut_before[seg + 1]) e = f < 0.5f ? 0.0f : 1.0f;  // jump, never fly through walls
  v.origin = a.origin + (b.origin - a.origin) * e;
  v.yaw = wrap180(a.yaw + wrap180(b.yaw - a.yaw) * e + sweep_yaw);
  v.pitch = a.pitch + (b.pitch - a.pitch) * e + nod;
  if (v.pitch > 80.0f) v.pitch = 80.0f;  // entity "angle -1/-2" means straight up/down
  if (v.pitch < -80.0f) v.pitch = -80.0f;
  return v;
}

}  // namespace sb::host
