// tools/vis/vis_graph.h: the portal graph shared by flow.cpp (visibility) and vis.cpp
// (building it from a PortalFile, gathering rows). Internal to tools/vis.
//
// Units are map units; windings are convex, planar, at most kMaxPts points. Nodes are PRT1
// leaves or PRT2 clusters; directed portal 2i leads from PRT portal i's node[0] to node[1],
// 2i + 1 back; a directed portal's plane normal points into the node it leads to.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "tools/vis/vis.h"

namespace sb::tools::vis {

constexpr double kEps = 0.01;  // units: a point within kEps of a plane counts as on it
constexpr int kMaxPts = 64;    // winding capacity (PRT windings and clipped ones)

struct V {
  double x, y, z;
};
inline V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V operator*(V a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

struct Plane {
  V n;       // unit normal
  double d;  // n . p == d on the plane
  double dist(V p) const { return dot(n, p) - d; }
};
inline Plane flip(const Plane& p) { return {{-p.n.x, -p.n.y, -p.n.z}, -p.d}; }

// Fixed-capacity convex polygon (no heap); copies move the used points only.
struct Wind {
  int n = 0;
  V p[kMaxPts];
  Wind() = default;
  Wind(const Wind& o) : n(o.n) {
    for (int i = 0; i < n; ++i) p[i] = o.p[i];
  }
  Wind& operator=(const Wind& o) {
    if (this != &o) {
      n = o.n;
      for (int i = 0; i < n; ++i) p[i] = o.p[i];
    }
    return *this;
  }
};

struct DPortal {
  Plane pl;      // normal into `to`
  int from, to;  // nodes
  V center;      // of the winding's points
  double radius; // every point is within radius of center
  Wind w;
};

struct Graph {
  int nodes = 0;
  std::vector<DPortal> portals;
  std::vector<std::vector<int>> node_portals;  // directed portals leading out of each node
  size_t words = 0;                            // 64-bit words per portal bitset
};

// The separators of (back, front) (flow.cpp): planes with `back` behind and `front` in front;
// a line from a point of `back` through a point of `front` continues in front of each. At
// most kMaxSeps.
constexpr int kMaxSeps = 4 * kMaxPts;
int find_separators(const Wind& back, const Wind& front, Plane* out);

// Builds the graph of `prt` (nodes: clusters, which are the leaves for PRT1).
Status build_graph(const PortalFile& prt, Graph* g);

// Fills *might_out with the flood of every directed portal (portals x words) and, when
// vis_out is not null, *vis_out with the full clipped flow's result (*flow_steps: steps of
// the recursion, a work measure). Progress goes to
// stderr through tools/common/progress.h unless opt.quiet.
void graph_flow(const Graph& g, const VisOptions& opt, std::vector<uint64_t>* might_out, std::vector<uint64_t>* vis_out,
                double* seconds_fast, double* seconds_full, int64_t* flow_steps);

}  // namespace sb::tools::vis
