// tools/bsp/geom.cpp: see geom.h.
#include "tools/bsp/geom.h"

#include <algorithm>
#include <cmath>

namespace sb::tools::bsp {
namespace {

constexpr double kNormalEpsilon = 1e-5;
constexpr double kDistEpsilon = 0.01;

int dominant_axis(const Vec3& n) {
  double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  if (ax >= ay && ax >= az) return 0;
  return ay >= az ? 1 : 2;
}

int plane_type(const Vec3& n) {
  for (int i = 0; i < 3; ++i)
    if (n[i] == 1.0 || n[i] == -1.0) return i;
  return 3 + dominant_axis(n);
}

}  // namespace

int PlaneSet::find_or_add(Vec3 normal, double dist) {
  // Snap near-axial normals and near-integer distances.
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(normal[i]) > 1.0 - 1e-9) {
      double s = normal[i] > 0 ? 1.0 : -1.0;
      normal = Vec3(0.0);
      normal[i] = s;
      break;
    }
  }
  double r = std::floor(dist + 0.5);
  if (std::fabs(dist - r) < 1e-4) dist = r;
  // Canonical orientation: dominant component positive.
  bool flipped = normal[dominant_axis(normal)] < 0;
  if (flipped) {
    normal = -normal;
    dist = -dist;
  }
  int64_t key = int64_t(std::floor(dist));
  for (int64_t k = key - 1; k <= key + 1; ++k) {
    auto it = buckets_.find(k);
    if (it == buckets_.end()) continue;
    for (int idx : it->second) {
      const Plane& p = planes_[size_t(idx)];
      if (std::fabs(p.dist - dist) < kDistEpsilon && std::fabs(p.normal.x - normal.x) < kNormalEpsilon &&
          std::fabs(p.normal.y - normal.y) < kNormalEpsilon && std::fabs(p.normal.z - normal.z) < kNormalEpsilon)
        return flipped ? idx + 1 : idx;
    }
  }
  int idx = int(planes_.size());
  Plane front{normal, dist, plane_type(normal)};
  Plane back{-normal, -dist, front.type};
  planes_.push_back(front);
  planes_.push_back(back);
  buckets_[key].push_back(idx);
  return flipped ? idx + 1 : idx;
}

bool plane_from_points(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec3* normal, double* dist) {
  Vec3 n = glm::cross(p0 - p1, p2 - p1);
  double len = glm::length(n);
  if (!std::isfinite(len) || len < 1e-9) return false;
  n /= len;
  double d = glm::dot(n, p1);
  if (!std::isfinite(d)) return false;
  *normal = n;
  *dist = d;
  return true;
}

Vec3 winding_normal(const Winding& w) {
  // Newell's method; Quake's clockwise order gives the negated right-hand normal.
  Vec3 n(0.0);
  for (size_t i = 0; i < w.size(); ++i) {
    const Vec3& a = w[i];
    const Vec3& b = w[(i + 1) % w.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  double len = glm::length(n);
  if (len < 1e-12) return Vec3(0.0);
  return -n / len;
}

Winding base_winding(const Plane& plane) {
  int axis = dominant_axis(plane.normal);
  Vec3 up(0.0);
  if (axis == 2) up.x = 1.0;
  else up.z = 1.0;
  up -= plane.normal * glm::dot(up, plane.normal);
  up = glm::normalize(up);
  Vec3 org = plane.normal * plane.dist;
  Vec3 right = glm::cross(up, plane.normal);
  up *= kWorldExtent;
  right *= kWorldExtent;
  Winding w{org - right + up, org + right + up, org + right - up, org - right - up};
  if (glm::dot(winding_normal(w), plane.normal) < 0) w = reverse_winding(w);
  return w;
}

Winding reverse_winding(const Winding& w) { return Winding(w.rbegin(), w.rend()); }

namespace {

// Point on segment a-b where the plane distance crosses zero; axial planes get the exact
// coordinate so that shared edges meet exactly.
Vec3 intersect(const Vec3& a, const Vec3& b, double da, double db, const Plane& p) {
  double t = da / (da - db);
  Vec3 r = a + (b - a) * t;
  if (p.type < 3) r[p.type] = p.normal[p.type] > 0 ? p.dist : -p.dist;
  return r;
}

// Per-vertex plane distances and sides (0 front, 1 back, 2 on the plane, within eps), with
// counts per side: on the stack for ordinary windings (no heap traffic in the hottest
// routines of CSG and tree building), in a thread-local buffer beyond that.
struct VertexSides {
  static constexpr size_t kStack = 64;
  double d_stack[kStack];
  int s_stack[kStack];
  double* d = d_stack;
  int* s = s_stack;
  int counts[3] = {0, 0, 0};

  VertexSides(const Winding& w, const Plane& plane, double eps) {
    const size_t n = w.size();
    if (n > kStack) {
      thread_local std::vector<double> d_heap;
      thread_local std::vector<int> s_heap;
      d_heap.resize(n);
      s_heap.resize(n);
      d = d_heap.data();
      s = s_heap.data();
    }
    for (size_t i = 0; i < n; ++i) {
      d[i] = plane.distance(w[i]);
      s[i] = d[i] > eps ? 0 : (d[i] < -eps ? 1 : 2);
      counts[s[i]]++;
    }
  }
};

}  // namespace

void split_winding(const Winding& w, const Plane& plane, Winding* front, Winding* back, double eps) {
  front->clear();
  back->clear();
  size_t n = w.size();
  if (n < 3) return;
  VertexSides vs(w, plane, eps);
  const double* d = vs.d;
  const int* s = vs.s;
  const int* counts = vs.counts;
  if (counts[0] == 0 && counts[1] == 0) return;  // on the plane
  if (counts[1] == 0) { *front = w; return; }
  if (counts[0] == 0) { *back = w; return; }
  front->reserve(n + 2);
  back->reserve(n + 2);
  for (size_t i = 0; i < n; ++i) {
    size_t j = (i + 1) % n;
    const Vec3& a = w[i];
    if (s[i] == 2) {
      front->push_back(a);
      back->push_back(a);
      continue;
    }
    (s[i] == 0 ? front : back)->push_back(a);
    if (s[j] == 2 || s[j] == s[i]) continue;
    Vec3 m = intersect(a, w[j], d[i], d[j], plane);
    front->push_back(m);
    back->push_back(m);
  }
  if (front->size() < 3) front->clear();
  if (back->size() < 3) back->clear();
}

void clip_winding_to(const Winding& w, const Plane& plane, bool keep_front, double eps, Winding* out) {
  // split_winding's rules, building only the kept side.
  out->clear();
  size_t n = w.size();
  if (n < 3) return;
  VertexSides vs(w, plane, eps);
  const double* d = vs.d;
  const int* s = vs.s;
  const int* counts = vs.counts;
  const int keep = keep_front ? 0 : 1;
  if ((counts[0] == 0 && counts[1] == 0) || counts[1 - keep] == 0) {  // on the plane, or all kept
    out->assign(w.begin(), w.end());
    return;
  }
  if (counts[keep] == 0) return;
  out->reserve(n + 2);
  for (size_t i = 0; i < n; ++i) {
    size_t j = (i + 1) % n;
    const Vec3& a = w[i];
    if (s[i] == 2) {
      out->push_back(a);
      continue;
    }
    if (s[i] == keep) out->push_back(a);
    if (s[j] == 2 || s[j] == s[i]) continue;
    out->push_back(intersect(a, w[j], d[i], d[j], plane));
  }
  if (out->size() < 3) out->clear();
}

Winding clip_winding(const Winding& w, const Plane& plane, bool keep_front, double eps) {
  Winding out;
  clip_winding_to(w, plane, keep_front, eps, &out);
  return out;
}

Side classify_winding(const Winding& w, const Plane& plane, double eps) {
  bool front = false, back = false;
  for (const Vec3& p : w) {
    double d = plane.distance(p);
    if (d > eps) front = true;
    else if (d < -eps) back = true;
  }
  if (front && back) return Side::Cross;
  if (front) return Side::Front;
  if (back) return Side::Back;
  return Side::On;
}

double winding_area(const Winding& w) {
  double area = 0;
  for (size_t i = 2; i < w.size(); ++i) area += 0.5 * glm::length(glm::cross(w[i - 1] - w[0], w[i] - w[0]));
  return area;
}

double winding_min_width(const Winding& w) {
  if (w.size() < 3) return 0;
  Vec3 n = winding_normal(w);
  double best = 1e30;
  for (size_t i = 0; i < w.size(); ++i) {
    Vec3 e = w[(i + 1) % w.size()] - w[i];
    Vec3 across = glm::cross(n, e);
    double len = glm::length(across);
    if (len < 1e-9) continue;  // repeated vertex: that edge has no direction
    across /= len;
    double far = 0;
    for (const Vec3& p : w) far = std::max(far, std::fabs(glm::dot(p - w[i], across)));
    best = std::min(best, far);
  }
  return best == 1e30 ? 0 : best;
}

Vec3 winding_center(const Winding& w) {
  Vec3 c(0.0);
  for (const Vec3& p : w) c += p;
  return w.empty() ? c : c / double(w.size());
}

void winding_bounds(const Winding& w, Vec3* mins, Vec3* maxs) {
  Bounds b;
  for (const Vec3& p : w) b.add(p);
  *mins = b.mins;
  *maxs = b.maxs;
}

void clean_winding(Winding* w, double eps) {
  Winding& v = *w;
  // Coincident neighbours.
  Winding out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    if (!out.empty() && glm::length(a - out.back()) < eps) continue;
    out.push_back(a);
  }
  while (out.size() > 1 && glm::length(out.front() - out.back()) < eps) out.pop_back();
  // Collinear middle points.
  bool changed = true;
  while (changed && out.size() > 3) {
    changed = false;
    for (size_t i = 0; i < out.size(); ++i) {
      const Vec3& a = out[(i + out.size() - 1) % out.size()];
      const Vec3& b = out[i];
      const Vec3& c = out[(i + 1) % out.size()];
      Vec3 e1 = b - a, e2 = c - b;
      double l1 = glm::length(e1), l2 = glm::length(e2);
      if (l1 < 1e-12 || l2 < 1e-12 || glm::length(glm::cross(e1 / l1, e2 / l2)) < 1e-5) {
        if (glm::dot(e1, e2) >= 0 || l1 < 1e-12 || l2 < 1e-12) {
          out.erase(out.begin() + long(i));
          changed = true;
          break;
        }
      }
    }
  }
  if (out.size() < 3) out.clear();
  v.swap(out);
}

}  // namespace sb::tools::bsp
