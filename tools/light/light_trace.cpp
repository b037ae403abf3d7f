// tools/light/light_trace.cpp: see light_trace.h.
#include "tools/light/light_trace.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "engine/world/world.h"

namespace sb::tools {

LineTracer::LineTracer(const BspWorld& world) : world_(world) {
  head_ = world.num_models ? world.models[0].headnode[0] : -1;
  float span = 65536.0f;
  if (world.num_models) {
    glm::vec3 d = world.models[0].maxs - world.models[0].mins;
    float len = glm::length(d);
    if (std::isfinite(len)) span = len + 1024.0f;
  }
  span_ = span;
}

int LineTracer::contents(const glm::vec3& p) const {
  if (head_ < 0) return kContentsSolid;
  int leaf = point_in_leaf(world_, p);
  return world_.leaves[leaf].contents;
}

int LineTracer::first_blocker(const glm::vec3& a, const glm::vec3& b) const {
  if (head_ < 0) return kContentsSolid;
  return trace(head_, a, b);
}

namespace {

// Signed distances of a and b from the plane (axial planes without the dot product).
inline void plane_distances(const Plane& p, const glm::vec3& a, const glm::vec3& b, float* da, float* db) {
  if (p.type < 3) {
    *da = a[p.type] - p.dist;
    *db = b[p.type] - p.dist;
  } else {
    *da = glm::dot(p.normal, a) - p.dist;
    *db = glm::dot(p.normal, b) - p.dist;
  }
}

}  // namespace

// Walks the segment a -> b from `node`. The near part of a split segment is walked first;
// the far part continues in the loop (one recursion per split, bounded by the tree depth).
int LineTracer::trace(int node, glm::vec3 a, glm::vec3 b) const {
  while (node >= 0) {
    const Node& n = world_.nodes[node];
    const Plane& p = world_.planes[n.plane];
    float da, db;
    plane_distances(p, a, b, &da, &db);
    if (da >= 0 && db >= 0) {
      node = n.children[0];
      continue;
    }
    if (da < 0 && db < 0) {
      node = n.children[1];
      continue;
    }
    int near_side = da < 0;  // the side a lies on
    float frac = da / (da - db);
    glm::vec3 mid = a + (b - a) * frac;
    int hit = trace(n.children[near_side], a, mid);
    if (hit != kContentsEmpty) return hit;
    node = n.children[near_side ^ 1];
    a = mid;
  }
  int contents = world_.leaves[-1 - node].contents;
  if (contents == kContentsSolid || contents == kContentsSky) return contents;
  return kContentsEmpty;
}

LineTracer::Hit LineTracer::first_hit(const glm::vec3& a, const glm::vec3& b) const {
  Hit h;
  if (head_ < 0) {
    h.contents = kContentsSolid;
    h.point = a;
    return h;
  }
  trace_hit(head_, a, b, -1, &h);
  return h;
}

// As trace(), also carrying the node whose split produced the current start point `a`
// (`split`), so the first blocking leaf reports where, and on which plane, it was entered.
// Returns true when a blocking leaf was found (*out filled).
bool LineTracer::trace_hit(int node, glm::vec3 a, glm::vec3 b, int split, Hit* out) const {
  while (node >= 0) {
    const Node& n = world_.nodes[node];
    const Plane& p = world_.planes[n.plane];
    float da, db;
    plane_distances(p, a, b, &da, &db);
    if (da >= 0 && db >= 0) {
      node = n.children[0];
      continue;
    }
    if (da < 0 && db < 0) {
      node = n.children[1];
      continue;
    }
    int near_side = da < 0;
    float frac = da / (da - db);
    glm::vec3 mid = a + (b - a) * frac;
    if (trace_hit(n.children[near_side], a, mid, split, out)) return true;
    split = node;
    node = n.children[near_side ^ 1];
    a = mid;
  }
  int contents = world_.leaves[-1 - node].contents;
  if (contents != kContentsSolid && contents != kContentsSky) {
    out->leaf_before = -1 - node;
    return false;
  }
  out->contents = contents;
  out->point = a;
  out->node = split;
  return true;
}

}  // namespace sb::tools
