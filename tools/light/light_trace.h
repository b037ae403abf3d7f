// tools/light/light_trace.h: line traces through the world's hull-0 BSP tree, for shadows.
//
// A segment is walked front to back through model 0's node tree (sb::BspWorld, checked by
// sb::load_bsp: acyclic, depth <= kMaxTreeDepth, so the recursion is bounded). The first leaf
// along it whose contents block light is reported: solid and sky block; empty, water, slime
// and lava let light through. Thread-safe: reads the world only.
#pragma once
#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"

namespace sb::tools {

class LineTracer {
 public:
  explicit LineTracer(const BspWorld& world);

  // Contents of the first blocking leaf (kContentsSolid or kContentsSky) met going from
  // a to b, or kContentsEmpty when nothing blocks.
  int first_blocker(const glm::vec3& a, const glm::vec3& b) const;

  // True when nothing blocks the segment.
  bool clear(const glm::vec3& a, const glm::vec3& b) const { return first_blocker(a, b) == kContentsEmpty; }

  // Where a segment first enters a blocking leaf (for bounce and dirt rays).
  struct Hit {
    int contents = kContentsEmpty;  // kContentsSolid / kContentsSky, or kContentsEmpty (clear)
    glm::vec3 point{0};             // entry point (on the plane of `node`); a when node is -1
    int node = -1;                  // node whose plane the entry point lies on; -1 when the
                                    // segment starts inside the blocking leaf
    int leaf_before = -1;           // last non-blocking leaf crossed before it (-1: none)
  };
  Hit first_hit(const glm::vec3& a, const glm::vec3& b) const;

  // Contents of the leaf holding p (hull 0).
  int contents(const glm::vec3& p) const;

  // Length that crosses the whole world from anywhere inside it (diagonal of model 0's
  // bounds plus a margin), for sun rays.
  float world_span() const { return span_; }

 private:
  int trace(int node, glm::vec3 a, glm::vec3 b) const;
  bool trace_hit(int node, glm::vec3 a, glm::vec3 b, int split, Hit* out) const;

  const BspWorld& world_;
  int head_;
  float span_;
};

}  // namespace sb::tools
