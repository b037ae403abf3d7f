// engine/render/edge_list.cpp: one face -> one FrontSurface and its FrontEdges.
//
//   world vertices --(minus eye, dot with right/up/forward)--> view space (x, y, z)
//   --clip to the frustum planes named in clip_flags--> convex polygon inside the view
//   --project--> screen points, clamped to [0, width] x [0, height]
//   --each non-horizontal edge--> FrontEdge in the bucket of its first scanline.
//
// Winding: the projected polygon's signed area tells which edges are leading (the
// surface starts right of them) and which are trailing. With y growing downwards and a
// positive area (vertices clockwise on screen), an edge going down is trailing.
//
// Edges are not shared between faces (modern compilers share an edge among more than two
// faces, which Quake's two-slot edge sharing could not express). Instead every face emits
// its own copy; copies of one world edge are computed from identical projected end points
// in the same top-to-bottom order, so they land on identical pixels and leave no cracks.
// Clip points are likewise computed from the inside end towards the outside end, so two
// faces clipping the same edge against the same plane get the same point.
#include <cmath>

#include <glm/geometric.hpp>

#include "engine/render/front_local.h"

namespace sb::render::front {
namespace {

constexpr float kMinZ = 1.0f / 4096.0f;   // projection never divides by less (1/z <= 4096)
constexpr float kMinArea2 = 1.0f / 1024.0f;  // twice the screen area below which a face is dropped
constexpr float kHugeCoordinate = 1.0e15f;   // view-space magnitudes above this are rejected

// Signed distance of view-space point v to frustum plane i (>= 0 inside).
inline float plane_dist(const ViewState& view, int i, const float* v) {
  switch (i) {
    case 0: return view.xcenter * v[2] + view.xscale * v[0];
    case 1: return (float(view.width) - view.xcenter) * v[2] - view.xscale * v[0];
    case 2: return view.ycenter * v[2] - view.yscale * v[1];
    default: return (float(view.height) - view.ycenter) * v[2] + view.yscale * v[1];
  }
}

// Sutherland-Hodgman against one plane. Returns the output count, or -1 when the output
// would exceed cap (the face is then dropped).
int clip_polygon(const ViewState& view, int plane, const float* in, int n, float* out, int cap) {
  int m = 0;
  float d0 = plane_dist(view, plane, in + 3 * (n - 1));
  const float* p0 = in + 3 * (n - 1);
  for (int i = 0; i < n; ++i) {
    const float* p1 = in + 3 * i;
    float d1 = plane_dist(view, plane, p1);
    bool in0 = d0 >= 0.0f, in1 = d1 >= 0.0f;
    if (in0 != in1) {
      if (m >= cap) return -1;
      // Always from the inside end, so every face clipping this edge gets the same point.
      const float* a = in0 ? p0 : p1;
      const float* b = in0 ? p1 : p0;
      float da = in0 ? d0 : d1, db = in0 ? d1 : d0;
      float t = da / (da - db);
      float* o = out + 3 * m++;
      o[0] = a[0] + t * (b[0] - a[0]);
      o[1] = a[1] + t * (b[1] - a[1]);
      o[2] = a[2] + t * (b[2] - a[2]);
    }
    if (in1) {
      if (m >= cap) return -1;
      float* o = out + 3 * m++;
      o[0] = p1[0]; o[1] = p1[1]; o[2] = p1[2];
    }
    p0 = p1;
    d0 = d1;
  }
  return m;
}

// Clamp that also maps NaN to lo.
inline float clampf(float v, float lo, float hi) { return v > lo ? (v < hi ? v : hi) : lo; }

}  // namespace

bool add_face(EdgeTable& table, const BspWorld& world, const ViewState& view, uint32_t face_index,
              uint32_t clip_flags) {
  if (table.full) return false;
  const Face& face = world.faces[face_index];
  const uint32_t n = face.num_edges;
  if (n < 3 || n > table.poly_cap / 2) return false;  // poly_cap >= 2 * max face edges + 8
  if (table.num_surfs >= table.max_surfs) {
    table.surfaces_overflowed = true;
    table.full = true;
    return false;
  }

  // Gather into view space.
  float* poly = table.poly_a;
  float* other = table.poly_b;
  for (uint32_t i = 0; i < n; ++i) {
    int32_t se = world.surfedges[face.first_surfedge + i];
    uint32_t vi = se >= 0 ? world.edges[se].v[0] : world.edges[uint32_t(-int64_t(se))].v[1];
    glm::vec3 rel = world.vertices[vi] - view.origin;
    float x = glm::dot(rel, view.right), y = glm::dot(rel, view.up), z = glm::dot(rel, view.forward);
    if (!(std::fabs(x) + std::fabs(y) + std::fabs(z) < kHugeCoordinate)) return false;  // also NaN
    poly[3 * i] = x;
    poly[3 * i + 1] = y;
    poly[3 * i + 2] = z;
  }

  // Clip. Each plane adds at most one vertex to a convex polygon; the cap guards the rest.
  int count = int(n);
  const int cap = int(table.poly_cap);
  for (int p = 0; p < 4 && count >= 3; ++p) {
    if (!(clip_flags & (1u << p))) continue;
    count = clip_polygon(view, p, poly, count, other, cap);
    if (count < 0) return false;
    float* t = poly; poly = other; other = t;
  }
  if (count < 3) return false;

  // Project.
  const float w = float(table.width), h = float(table.height);
  float* pr = table.proj;
  float nearzi = 0.0f;
  for (int i = 0; i < count; ++i) {
    const float* v = poly + 3 * i;
    float z = v[2] > kMinZ ? v[2] : kMinZ;
    float zi = 1.0f / z;
    if (zi > nearzi) nearzi = zi;
    pr[2 * i] = clampf(view.xcenter + view.xscale * v[0] * zi, 0.0f, w);
    pr[2 * i + 1] = clampf(view.ycenter - view.yscale * v[1] * zi, 0.0f, h);
  }
  float area2 = 0.0f;
  for (int i = 0, j = count - 1; i < count; j = i++) area2 += pr[2 * j] * pr[2 * i + 1] - pr[2 * i] * pr[2 * j + 1];
  if (!(std::fabs(area2) >= kMinArea2)) return false;
  const bool clockwise = area2 > 0.0f;

  if (table.num_edges + uint32_t(count) > table.max_edges) {
    table.edges_overflowed = true;
    table.full = true;
    return false;
  }

  // Emit edges.
  const uint32_t surf = table.num_surfs;
  uint32_t emitted = 0;
  for (int i = 0, j = count - 1; i < count; j = i++) {
    float x0 = pr[2 * j], y0 = pr[2 * j + 1], x1 = pr[2 * i], y1 = pr[2 * i + 1];
    if (y0 == y1) continue;
    const bool down = y1 > y0;
    // Canonical order: from the top end, whichever way the polygon runs.
    float xt = down ? x0 : x1, yt = down ? y0 : y1, xb = down ? x1 : x0, yb = down ? y1 : y0;
    int row_top = int(std::ceil(yt - 0.5f));
    int row_bottom = int(std::ceil(yb - 0.5f));
    if (row_top < 0) row_top = 0;
    if (row_bottom > table.height) row_bottom = table.height;
    if (row_top >= row_bottom) continue;  // crosses no scanline centre

    double slope = (double(xb) - double(xt)) / (double(yb) - double(yt));
    double x_first = double(xt) + (double(row_top) + 0.5 - double(yt)) * slope;
    double lo = xt < xb ? xt : xb, hi = xt < xb ? xb : xt;
    if (x_first < lo) x_first = lo;
    if (x_first > hi) x_first = hi;
    const double limit = double(table.width) + 2.0;
    if (slope > limit) slope = limit;
    if (slope < -limit) slope = -limit;

    FrontEdge& e = table.edges[table.num_edges];
    e.x = int32_t(std::ceil((x_first - 0.5) * 65536.0));  // ceil keeps ceil(x - 0.5) exact below 1/65536
    e.dx = int32_t(std::lround(slope * 65536.0));
    e.surf = surf | (down == clockwise ? kTrailingBit : 0u);
    e.ybottom = row_bottom;
    e.next = table.row_heads[row_top];
    table.row_heads[row_top] = table.num_edges;
    ++table.num_edges;
    ++emitted;
  }
  if (emitted == 0) return false;

  FrontSurface& s = table.surfs[surf];
  s.face = face_index;
  s.key = surf;
  s.nearzi = nearzi;
  s.winding = 0;
  s.prev = s.next = kNone;
  s.num_spans = 0;
  s.first_span = 0;
  ++table.num_surfs;
  return true;
}

}  // namespace sb::render::front
