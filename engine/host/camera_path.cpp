#include "engine/host/camera_path.h"

#include <cmath>
#include <string_view>

#include "engine/formats/entities.h"

namespace sb::host {
namespace {

// TEMPORARY ADAPTER until engine/world/viewpoints.h (collect_viewpoints) lands:
// camera-worthy entities read with the entity parser.
struct Candidate {
  const char* classname;
  float eye_height;  // added to the entity origin
  int priority;      // lower sorts first
};
constexpr Candidate kCandidates[] = {
    {"info_player_start", 22.0f, 0},       {"info_intermission", 0.0f, 1},
    {"info_player_start2", 22.0f, 2},      {"info_player_deathmatch", 22.0f, 3},
    {"info_player_coop", 22.0f, 4},        {"info_teleport_destination", 22.0f, 5},
};

int collect_entity_views(const BspWorld& world, ViewParams* out, int* priority, int max) {
  if (!world.entities) return 0;
  EntityIterator it(world.entities, world.entities_size);
  Entity e;
  int count = 0;
  while (count < max && it.next(&e)) {
    std::string_view classname = e.classname();
    const Candidate* c = nullptr;
    for (const Candidate& k : kCandidates)
      if (classname == k.classname) c = &k;
    ViewParams v;
    if (!c || !entity_origin(e, &v.origin)) continue;
    v.origin.z += c->eye_height;
    glm::vec3 angles(0.0f);
    if (entity_angles(e, &angles)) {
      v.pitch = angles.x;
      v.yaw = angles.y;
    }
    out[count] = v;
    priority[count] = c->priority;
    ++count;
  }
  // Stable insertion sort by priority: keeps file order within a class.
  for (int i = 1; i < count; ++i)
    for (int j = i; j > 0 && priority[j] < priority[j - 1]; --j) {
      ViewParams tv = out[j]; out[j] = out[j - 1]; out[j - 1] = tv;
      int tp = priority[j]; priority[j] = priority[j - 1]; priority[j - 1] = tp;
    }
  return count;
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
  if (!points) {
    Error e;
    arena.failure_message(e.message, sizeof e.message);
    return e;
  }
  int priority[kMaxCameraPoints];
  int n = collect_entity_views(world, points, priority, kMaxCameraPoints);
  if (n == 0) {
    ViewParams v;
    if (world.num_models > 0) v.origin = (world.models[0].mins + world.models[0].maxs) * 0.5f;
    points[0] = v;
    n = 1;
  }
  return CameraPath{points, n};
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
    return v;
  }
  float u = t * float(path.count - 1);
  int seg = int(u);
  if (seg >= path.count - 1) seg = path.count - 2;
  float f = u - float(seg);
  float e = f * f * (3.0f - 2.0f * f);  // ease in and out at each viewpoint
  const ViewParams& a = path.points[seg];
  const ViewParams& b = path.points[seg + 1];
  v.origin = a.origin + (b.origin - a.origin) * e;
  v.yaw = wrap180(a.yaw + wrap180(b.yaw - a.yaw) * e + sweep_yaw);
  v.pitch = a.pitch + (b.pitch - a.pitch) * e + nod;
  return v;
}

}  // namespace sb::host
