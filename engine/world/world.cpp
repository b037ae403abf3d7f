// engine/world/world.cpp: point in leaf, PVS decompression.
#include "engine/world/world.h"

#include <cstring>

namespace sb {

int point_in_leaf_from(const BspWorld& world, int head_node, const glm::vec3& point) {
  if (world.num_nodes == 0 || head_node < 0 || uint32_t(head_node) >= world.num_nodes) return 0;
  int node = head_node;
  // The loader bounds the depth by kMaxTreeDepth; the counter is a second guard.
  for (int steps = 0; node >= 0 && steps <= kMaxTreeDepth; ++steps) {
    const Node& n = world.nodes[node];
    const Plane& p = world.planes[n.plane];
    float d = p.type < 3 ? point[p.type] - p.dist
                         : p.normal.x * point.x + p.normal.y * point.y + p.normal.z * point.z - p.dist;
    node = n.children[d > 0 ? 0 : 1];
  }
  return node < 0 ? -1 - node : 0;
}

int point_in_leaf(const BspWorld& world, const glm::vec3& point) {
  if (world.num_models == 0) return 0;
  return point_in_leaf_from(world, world.models[0].headnode[0], point);
}

bool decompress_pvs(const BspWorld& world, int leaf, uint8_t* out, size_t out_bytes) {
  size_t row = pvs_row_bytes(world);
  size_t n = row < out_bytes ? row : out_bytes;
  std::memset(out, 0, out_bytes);
  bool has_vis = leaf > 0 && uint32_t(leaf) < world.num_leaves && world.visdata_size > 0 &&
                 world.leaves[leaf].vis_offset >= 0 && uint32_t(world.leaves[leaf].vis_offset) < world.visdata_size;
  if (has_vis) {
    const uint8_t* in = world.visdata + world.leaves[leaf].vis_offset;
    const uint8_t* end = world.visdata + world.visdata_size;
    size_t c = 0;
    while (c < row) {
      if (in >= end) break;
      uint8_t b = *in++;
      if (b) {
        if (c < n) out[c] = b;
        ++c;
        continue;
      }
      if (in >= end) break;
      size_t zeros = *in++;
      c += zeros;  // out is already zero
    }
    if (c >= row) return true;
  }
  std::memset(out, 0xff, n);
  return false;
}

}  // namespace sb
