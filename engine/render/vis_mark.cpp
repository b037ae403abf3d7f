// engine/render/vis_mark.cpp: potentially visible set -> visframe stamps.
//
// A leaf is visible this frame when Leaf::visframe == ViewState::frame; a node is on the
// way to a visible leaf when Node::visframe == frame. Stamps are never cleared: an old
// frame number simply stops matching. Frame numbers must therefore grow from frame to
// frame (MemorySystem::begin_frame counts from 1; frame 0 is handled by wiping stamps).
//
// PVS rows: bit (i & 7) of byte (i >> 3) says whether leaf i + 1 is visible (leaf 0 is
// the shared solid leaf and has no bit). Rows are expanded by sb::decompress_pvs
// (engine/world/world.h) into frame memory.
#include "engine/render/front_local.h"
#include "engine/world/world.h"

namespace sb::render::front {

namespace {

void stamp_all(BspWorld& world, uint32_t frame) {
  for (uint32_t i = 0; i < world.num_leaves; ++i) world.leaves[i].visframe = frame;
  for (uint32_t i = 0; i < world.num_nodes; ++i) world.nodes[i].visframe = frame;
}

// Stamps leaf `leaf` and its ancestors; stops at the first ancestor already stamped.
// Returns 1 when the leaf was newly stamped.
uint32_t stamp_leaf(BspWorld& world, uint32_t leaf, uint32_t frame) {
  Leaf& l = world.leaves[leaf];
  if (l.visframe == frame) return 0;
  l.visframe = frame;
  int32_t node = l.parent;
  for (uint32_t steps = 0; steps <= world.num_nodes; ++steps) {  // bound stops a malformed cycle
    if (node < 0 || uint32_t(node) >= world.num_nodes) break;
    Node& n = world.nodes[node];
    if (n.visframe == frame) break;
    n.visframe = frame;
    node = n.parent;
  }
  return 1;
}

}  // namespace

uint32_t mark_visible(BspWorld& world, const ViewState& view, mem::Arena& frame) {
  const uint32_t f = view.frame;
  if (f == 0) {
    // Stamps start at 0 after a level reset, so frame 0 would find everything "visible".
    // Wipe them to a value no real frame uses before marking.
    for (uint32_t i = 0; i < world.num_leaves; ++i) world.leaves[i].visframe = 0xffffffffu;
    for (uint32_t i = 0; i < world.num_nodes; ++i) world.nodes[i].visframe = 0xffffffffu;
    for (uint32_t i = 0; i < world.num_faces; ++i) world.faces[i].visframe = 0xffffffffu;
  }
  if (world.num_leaves == 0) return 0;

  const int view_leaf = view.view_leaf >= 0 && uint32_t(view.view_leaf) < world.num_leaves ? view.view_leaf : 0;
  const Leaf& vl = world.leaves[view_leaf];
  uint32_t visleafs = world.num_models > 0 ? world.models[0].visleafs : 0;
  if (visleafs > world.num_leaves - 1) visleafs = world.num_leaves - 1;

  const uint32_t row_bytes = uint32_t(pvs_row_bytes(world));
  bool everything = view_leaf == 0 || vl.contents == kContentsSolid || visleafs == 0 || row_bytes == 0;
  uint8_t* row = nullptr;
  if (!everything) {
    row = static_cast<uint8_t*>(frame.push(row_bytes, "render pvs row"));
    // No room, no PVS for this leaf, or a row running past visdata: everything visible
    // (slower, never wrong).
    everything = !row || !decompress_pvs(world, view_leaf, row, row_bytes);
  }
  if (everything) {
    stamp_all(world, f);
    return world.num_leaves - 1;
  }

  uint32_t count = stamp_leaf(world, uint32_t(view_leaf), f);  // a leaf always sees itself
  for (uint32_t byte = 0; byte < row_bytes; ++byte) {
    uint32_t bits = row[byte];
    if (bits == 0) continue;
    for (uint32_t bit = 0; bit < 8; ++bit) {
      if (!(bits & (1u << bit))) continue;
      uint32_t leaf = byte * 8 + bit + 1;
      if (leaf > visleafs) break;
      count += stamp_leaf(world, leaf, f);
    }
  }
  return count;
}

}  // namespace sb::render::front
