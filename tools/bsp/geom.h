// tools/bsp/geom.h: the geometry every sbbsp stage shares: planes (deduplicated, in
// front/back pairs) and convex polygons ("windings").
//
// Contracts:
//   - All geometry is double precision; units are map units (texels at scale 1).
//   - PlaneSet stores planes in pairs: index 2k is the canonical plane (its dominant normal
//     component is positive; axial planes have normal +X, +Y or +Z), 2k+1 the same plane
//     flipped. index ^ 1 is always the opposite plane. Near-axial normals snap to axial and
//     near-integer distances snap to integers, so the same plane written twice in a .map
//     (or reached by two computations) gets one index.
//   - A Winding is a convex polygon, clockwise when seen from the front of its plane
//     (Quake's convention): normal == normalize(cross(p[0] - p[1], p[2] - p[1])).
//   - kOnEpsilon: points closer than this to a plane count as on it.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/geometric.hpp>

namespace sb::tools::bsp {

using Vec3 = glm::dvec3;

constexpr double kOnEpsilon = 0.05;
constexpr double kWorldExtent = 131072.0;  // half size of a "huge" winding

struct Plane {
  Vec3 normal;
  double dist = 0;
  int type = 0;  // 0,1,2: axial X,Y,Z; 3,4,5: dominant axis X,Y,Z (after canonicalisation)
  double distance(const Vec3& p) const { return glm::dot(normal, p) - dist; }
};

class PlaneSet {
 public:
  // Index of (normal, dist) after snapping; adds the pair when new. normal must be unit length.
  int find_or_add(Vec3 normal, double dist);
  const Plane& operator[](int i) const { return planes_[size_t(i)]; }
  int size() const { return int(planes_.size()); }

 private:
  std::vector<Plane> planes_;
  std::unordered_map<int64_t, std::vector<int>> buckets_;  // floor(canonical dist) -> even indices
};

// Plane from three points in .map order (normal = cross(p0 - p1, p2 - p1)); false when the
// points are collinear or not finite.
bool plane_from_points(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec3* normal, double* dist);

using Winding = std::vector<Vec3>;

enum class Side { Front, Back, On, Cross };

// A square of half size kWorldExtent on the plane, clockwise seen from the front.
Winding base_winding(const Plane& plane);
// Keeps the part of w in front of (keep_front) or behind the plane. Points within eps count
// as kept. Returns an empty winding when nothing (or a sliver) is left.
Winding clip_winding(const Winding& w, const Plane& plane, bool keep_front, double eps = kOnEpsilon);
// Splits w by the plane. A winding lying on the plane goes to neither (both empty).
void split_winding(const Winding& w, const Plane& plane, Winding* front, Winding* back,
                   double eps = kOnEpsilon);
// clip_winding into *out (its storage reused; out must not alias w).
void clip_winding_to(const Winding& w, const Plane& plane, bool keep_front, double eps, Winding* out);
Side classify_winding(const Winding& w, const Plane& plane, double eps = kOnEpsilon);
double winding_area(const Winding& w);
// The polygon's smallest width in its own plane: the least, over its edges, of the largest
// distance of a vertex from that edge's line (exact for convex polygons). 0 for degenerate ones.
double winding_min_width(const Winding& w);
Vec3 winding_center(const Winding& w);
void winding_bounds(const Winding& w, Vec3* mins, Vec3* maxs);
// Normal implied by the vertex order (zero vector for degenerate windings).
Vec3 winding_normal(const Winding& w);
// Drops vertices closer than `eps` to their predecessor and collinear middle points.
void clean_winding(Winding* w, double eps = 0.01);
Winding reverse_winding(const Winding& w);

// Boxes.
struct Bounds {
  Vec3 mins{1e30, 1e30, 1e30}, maxs{-1e30, -1e30, -1e30};
  void add(const Vec3& p) { mins = glm::min(mins, p); maxs = glm::max(maxs, p); }
  void add(const Bounds& b) { mins = glm::min(mins, b.mins); maxs = glm::max(maxs, b.maxs); }
  bool empty() const { return mins.x > maxs.x; }
  bool overlaps(const Bounds& b, double eps) const {
    for (int i = 0; i < 3; ++i)
      if (mins[i] > b.maxs[i] + eps || maxs[i] < b.mins[i] - eps) return false;
    return true;
  }
};

// Side of a box relative to a plane: Front, Back or Cross (boxes touching within eps count
// as on that side). Inline: tree building calls it for every face and candidate plane.
inline Side box_side(const Bounds& b, const Plane& p, double eps = kOnEpsilon) {
  if (p.type < 3) {
    double s = p.normal[p.type];
    double lo = b.mins[p.type] * s, hi = b.maxs[p.type] * s;
    if (s < 0) std::swap(lo, hi);
    if (lo >= p.dist - eps) return Side::Front;
    if (hi <= p.dist + eps) return Side::Back;
    return Side::Cross;
  }
  double lo = 0, hi = 0;
  for (int i = 0; i < 3; ++i) {
    double a = p.normal[i] * b.mins[i], c = p.normal[i] * b.maxs[i];
    lo += std::min(a, c);
    hi += std::max(a, c);
  }
  if (lo >= p.dist - eps) return Side::Front;
  if (hi <= p.dist + eps) return Side::Back;
  return Side::Cross;
}

}  // namespace sb::tools::bsp
