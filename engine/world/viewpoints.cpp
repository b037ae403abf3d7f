// engine/world/viewpoints.cpp: camera positions from entities and leaves.
#include "engine/world/viewpoints.h"

#include <string_view>

#include "engine/formats/entities.h"
#include "engine/world/world.h"

namespace sb {
namespace {

constexpr int kClasses = 7;
constexpr float kEyeHeight = 22.0f;

// Class rank of an entity for viewpoint order, or -1 when it does not give one.
int class_rank(std::string_view cls) {
  if (cls == "info_player_start") return 0;
  if (cls.starts_with("info_player_")) return 1;
  if (cls == "info_intermission") return 2;
  if (cls.starts_with("item_")) return 3;
  if (cls.starts_with("weapon_")) return 4;
  if (cls.starts_with("monster_")) return 5;
  if (cls.starts_with("light")) return 6;
  return -1;
}

bool open_at(const BspWorld& w, const glm::vec3& p) {
  return w.leaves[point_in_leaf(w, p)].contents != kContentsSolid;
}

}  // namespace

int collect_viewpoints(const BspWorld& world, ViewParams* out, int max) {
  if (max <= 0 || world.num_leaves == 0 || world.num_models == 0) return 0;
  int n = 0;
  // 1. Entities, one pass per class so the order is by class, then by file order.
  std::string_view text(world.entities ? world.entities : "", world.entities ? world.entities_size : 0);
  for (int rank = 0; rank < kClasses && n < max; ++rank) {
    EntityIterator it(text);
    Entity e;
    while (n < max && it.next(&e)) {
      if (class_rank(e.classname()) != rank) continue;
      glm::vec3 origin;
      if (!entity_origin(e, &origin)) continue;
      if (rank <= 1) origin.z += kEyeHeight;
      if (!open_at(world, origin)) continue;
      glm::vec3 angles(0.0f);
      entity_angles(e, &angles);
      ViewParams v;
      v.origin = origin;
      v.pitch = angles.x;
      v.yaw = angles.y;
      v.roll = angles.z;
      out[n++] = v;
    }
  }
  // 2. No entity gave a viewpoint: leaf centres, spread over the world's leaves.
  if (n == 0) {
    uint32_t leaves = world.models[0].visleafs ? world.models[0].visleafs + 1 : world.num_leaves;
    if (leaves > world.num_leaves) leaves = world.num_leaves;
    uint32_t step = leaves / uint32_t(max) > 1 ? leaves / uint32_t(max) : 1;
    for (uint32_t i = 1; i < leaves && n < max; i += step) {
      const Leaf& l = world.leaves[i];
      if (l.contents == kContentsSolid) continue;
      glm::vec3 c = (l.mins + l.maxs) * 0.5f;
      if (!open_at(world, c)) continue;
      ViewParams v;
      v.origin = c;
      out[n++] = v;
    }
  }
  if (n == 0) return 0;
  // 3. Fill up: midpoints, then turned copies.
  int base = n;
  for (int i = 0; i + 1 < base && n < max; ++i) {
    glm::vec3 mid = (out[i].origin + out[i + 1].origin) * 0.5f;
    if (!open_at(world, mid)) continue;
    ViewParams v = out[i];
    v.origin = mid;
    out[n++] = v;
  }
  int with_mids = n;
  for (int turn = 1; turn <= 3 && n < max; ++turn)
    for (int i = 0; i < with_mids && n < max; ++i) {
      ViewParams v = out[i];
      v.yaw += 90.0f * float(turn);
      if (v.yaw >= 360.0f) v.yaw -= 360.0f;
      out[n++] = v;
    }
  return n;
}

}  // namespace sb
