// engine/render/bsp_walk.cpp: front-to-back walk of model 0.
//
// At each node stamped visible this frame:
//   1. its bounding box is tested against the frustum planes still named in clip_flags;
//      a box wholly outside one plane is skipped with everything below it, a plane the
//      box is wholly inside is dropped from clip_flags for the node's children and faces;
//   2. the child on the eye's side is walked first;
//   3. the node's faces that were stamped by a visible leaf (marksurfaces) and whose front
//      faces the eye are handed to add_face in order, so add order = front-to-back order
//      (BSP order: nothing added later can be in front of anything added earlier);
//   4. the other child is walked.
// A visible leaf stamps its marksurfaces with the frame number; because a face's front
// leaf lies on the face's front side, and the walk visits the eye's side first, a
// front-facing face's leaf has always been reached before the face's node emits it.
#include <glm/geometric.hpp>

#include "engine/render/front_local.h"

namespace sb::render::front {
namespace {

// A face is drawn only when the eye is this far (world units) in front of its plane;
// closer than that it is edge-on and covers no pixel centre.
constexpr float kBackfaceEpsilon = 0.01f;
constexpr int kMaxDepth = 4096;  // deeper than any real tree; stops a malformed cycle

struct Walk {
  BspWorld& world;
  const ViewState& view;
  EdgeTable& table;
  RenderStats& stats;
  uint32_t frame;
};

// Returns false when the box is wholly outside a plane in *flags; clears the bits of
// planes the box is wholly inside.
bool clip_box(const ViewState& v, const glm::vec3& mins, const glm::vec3& maxs, uint32_t* flags) {
  for (int i = 0; i < 4; ++i) {
    if (!(*flags & (1u << i))) continue;
    const Plane& p = v.frustum[i];
    // Corner farthest along the normal, and the one farthest against it.
    glm::vec3 hi((p.signbits & 1) ? mins.x : maxs.x, (p.signbits & 2) ? mins.y : maxs.y,
                 (p.signbits & 4) ? mins.z : maxs.z);
    glm::vec3 lo((p.signbits & 1) ? maxs.x : mins.x, (p.signbits & 2) ? maxs.y : mins.y,
                 (p.signbits & 4) ? maxs.z : mins.z);
    if (glm::dot(p.normal, hi) - p.dist < 0.0f) return false;
    if (glm::dot(p.normal, lo) - p.dist >= 0.0f) *flags &= ~(1u << i);
  }
  return true;
}

void visit_leaf(Walk& w, uint32_t leaf_index, uint32_t flags) {
  if (leaf_index >= w.world.num_leaves) return;
  const Leaf& leaf = w.world.leaves[leaf_index];
  if (leaf.visframe != w.frame || leaf.contents == kContentsSolid) return;
  if (flags && !clip_box(w.view, leaf.mins, leaf.maxs, &flags)) return;
  const uint32_t* ms = w.world.marksurfaces + leaf.first_marksurface;
  for (uint32_t i = 0; i < leaf.num_marksurfaces; ++i) w.world.faces[ms[i]].visframe = w.frame;
}

void visit(Walk& w, int32_t child, uint32_t flags, int depth) {
  // The far side is walked by looping, so recursion only deepens on the near side.
  while (!w.table.full && depth < kMaxDepth) {
    if (child < 0) {
      visit_leaf(w, uint32_t(-(int64_t(child) + 1)), flags);
      return;
    }
    if (uint32_t(child) >= w.world.num_nodes) return;
    const Node& node = w.world.nodes[child];
    if (node.visframe != w.frame) return;
    ++w.stats.nodes_visited;
    if (flags && !clip_box(w.view, node.mins, node.maxs, &flags)) return;

    const Plane& plane = w.world.planes[node.plane];
    const glm::vec3& o = w.view.origin;
    float d = (plane.type < 3 ? o[plane.type] * plane.normal[plane.type] : glm::dot(plane.normal, o)) - plane.dist;
    int side = d >= 0.0f ? 0 : 1;
    visit(w, node.children[side], flags, depth + 1);

    for (uint32_t i = 0; i < node.num_faces && !w.table.full; ++i) {
      uint32_t fi = node.first_face + i;
      Face& face = w.world.faces[fi];
      if (face.visframe != w.frame) continue;
      float facing = (face.flags & kFacePlaneBack) ? -d : d;
      if (!(facing > kBackfaceEpsilon)) continue;
      if (add_face(w.table, w.world, w.view, fi, flags)) {
        face.draw_frame = w.frame;
        ++w.stats.faces_emitted;
      }
    }

    child = node.children[side ^ 1];
    ++depth;
  }
}

}  // namespace

void walk_world(BspWorld& world, const ViewState& view, EdgeTable& table, RenderStats& stats) {
  if (world.num_models == 0) return;
  Walk w{world, view, table, stats, view.frame};
  visit(w, world.models[0].headnode[0], 0xfu, 0);
}

}  // namespace sb::render::front
