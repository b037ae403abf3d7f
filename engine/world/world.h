// engine/world/world.h: queries over a loaded BspWorld (engine/formats/bsp.h):
// which leaf holds a point, and which leaves a leaf can see (PVS).
//
// PVS rows: bit (i - 1) of a row stands for leaf i (leaf 0, the shared solid
// leaf, has no bit); a row has pvs_row_bytes(world) = ceil(models[0].visleafs / 8)
// bytes. visdata is run-length encoded: a nonzero byte is copied, a zero byte is
// followed by a count of zero bytes to emit.
// Nothing here allocates; callers pass the output rows.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"

namespace sb {

// The leaf of the world model (model 0) containing `point`: walks from
// models[0].headnode[0]; a point exactly on a plane goes to the back side.
// Always returns a valid leaf index (the loader guarantees a finite, acyclic tree).
int point_in_leaf(const BspWorld& world, const glm::vec3& point);

// Same walk from an arbitrary head node (submodels); returns a leaf index.
int point_in_leaf_from(const BspWorld& world, int head_node, const glm::vec3& point);

// Bytes in one decompressed PVS row.
inline size_t pvs_row_bytes(const BspWorld& world) {
  return world.num_models ? (size_t(world.models[0].visleafs) + 7) / 8 : 0;
}

// Decompresses the PVS of `leaf` into out[0..out_bytes). Writes min(out_bytes,
// row) bytes of the row and zeroes the rest of out. Everything is visible
// (all row bytes 0xff) for leaf 0, leaves with vis_offset -1, worlds without
// visdata, leaves out of range, and rows whose encoding would run past the end
// of visdata (never reads outside visdata). Returns true when the row came from
// visdata, false when the all-visible fallback was used.
bool decompress_pvs(const BspWorld& world, int leaf, uint8_t* out, size_t out_bytes);

// Whether leaf `leaf` (1-based world leaf index) is set in a decompressed row of
// row_bytes bytes. Leaf 0 and leaves past the row are reported not visible.
inline bool leaf_is_visible(const uint8_t* row, size_t row_bytes, int leaf) {
  if (leaf < 1) return false;
  size_t bit = size_t(leaf - 1);
  if (bit / 8 >= row_bytes) return false;
  return (row[bit >> 3] >> (bit & 7)) & 1;
}

}  // namespace sb
