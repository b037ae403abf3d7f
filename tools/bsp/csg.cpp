// tools/bsp/csg.cpp: see csg.h.
#include "tools/bsp/csg.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <tuple>

namespace sb::tools::bsp {
namespace {

constexpr double kMinFragmentArea = 0.01;
constexpr double kMergeEpsilon = 0.01;

// Splits `frag` (a piece of side `plane` of brush a) by brush b: pieces outside b are
// appended to `outside`; the rest (inside b) is dropped.
// With `inside_out`, the piece inside b is appended there instead of being dropped.
void clip_by_brush(const Winding& frag, int plane, bool coplanar_is_inside, const Brush& b, const PlaneSet& planes,
                   std::vector<Winding>* outside, std::vector<Winding>* inside_out = nullptr) {
  Winding inside = frag;
  Winding f, k;
  for (const BrushSide& t : b.sides) {
    if (t.plane == plane) {
      if (coplanar_is_inside) continue;
      outside->push_back(std::move(inside));
      return;
    }
    if (t.plane == (plane ^ 1)) continue;  // facing into b: inside
    // Classify first (split_winding's rules): most fragments lie on one side of most planes,
    // and then nothing needs copying.
    Side side = classify_winding(inside, planes[t.plane]);
    if (side == Side::Front) {
      outside->push_back(std::move(inside));
      return;
    }
    if (side == Side::Back) continue;
    if (side == Side::Cross) {
      split_winding(inside, planes[t.plane], &f, &k);
    } else {
      f.clear();
      k.clear();
    }
    if (f.empty() && k.empty()) {
      // On the plane within epsilon but a different plane index: treat by orientation.
      if (glm::dot(planes[t.plane].normal, planes[plane].normal) > 0 && !coplanar_is_inside) {
        outside->push_back(std::move(inside));
        return;
      }
      continue;
    }
    if (!f.empty()) {
      if (k.empty()) {
        outside->push_back(std::move(inside));
        return;
      }
      outside->push_back(std::move(f));
    }
    inside = std::move(k);
  }
  if (inside_out) inside_out->push_back(std::move(inside));
}

bool detail_like(int contents) { return contents == kContentsDetail || contents == kContentsIllusionary; }

}  // namespace

void csg_faces(const std::vector<Brush>& brushes, const PlaneSet& planes, std::vector<Face>* out, CsgStats* stats,
               Progress* progress) {
  out->clear();
  stats->brushes = int(brushes.size());
  std::vector<Winding> frags, next, hidden, covered_test;
  std::vector<int> rank(brushes.size());
  for (size_t b = 0; b < brushes.size(); ++b) rank[b] = contents_rank(brushes[b].contents);
  std::vector<size_t> near, maybe;
  BrushGrid grid(brushes);
  for (size_t a = 0; a < brushes.size(); ++a) {
    const Brush& A = brushes[a];
    if (progress) progress->advance();
    if (A.contents == kContentsHint) continue;
    int rank_a = rank[a];
    // Brushes that may remove A's faces (in brush order).
    grid.query(A.bounds, 0.1, &maybe);
    near.clear();
    for (size_t b : maybe) {
      const Brush& B = brushes[b];
      if (b == a || !A.bounds.overlaps(B.bounds, 0.1)) continue;
      if (rank[b] < rank_a || B.clips == Brush::Clips::None || B.contents == kContentsHint ||
          B.contents == kContentsIllusionary)
        continue;
      if (B.clips == Brush::Clips::Covered && A.clips != Brush::Clips::All) continue;
      near.push_back(b);
    }
    for (const BrushSide& s : A.sides) {
      if (s.w.empty() || s.bevel) continue;
      stats->sides++;
      frags.assign(1, s.w);
      hidden.clear();
      Bounds sb;
      for (const Vec3& p : s.w) sb.add(p);
      // A structural side's pieces inside detail brushes stay as undrawn faces, so that the
      // structural tree still holds every structural brush's boundary (detail never seals).
      bool keep_hidden = !detail_like(A.contents);
      for (size_t b : near) {
        const Brush& B = brushes[b];
        if (!sb.overlaps(B.bounds, 0.1)) continue;
        bool coplanar_inside = rank[b] > rank_a || b > a;
        next.clear();
        bool hide = keep_hidden && B.contents == kContentsDetail;
        if (B.clips == Brush::Clips::Covered) {
          // Keeps every fragment not entirely inside B whole.
          for (Winding& f : frags) {
            covered_test.clear();
            clip_by_brush(f, s.plane, coplanar_inside, B, planes, &covered_test);
            bool covered = true;
            for (const Winding& o : covered_test) covered = covered && winding_area(o) < kMinFragmentArea;
            if (!covered) next.push_back(std::move(f));
            else if (hide) hidden.push_back(std::move(f));
          }
        } else {
          for (const Winding& f : frags)
            clip_by_brush(f, s.plane, coplanar_inside, B, planes, &next, hide ? &hidden : nullptr);
        }
        frags.swap(next);
        if (frags.empty()) break;
      }
      // Hidden pieces are still removed inside the structural brushes.
      for (size_t b : near) {
        const Brush& B = brushes[b];
        if (hidden.empty()) break;
        if (B.contents == kContentsDetail || !sb.overlaps(B.bounds, 0.1)) continue;
        bool coplanar_inside = rank[b] > rank_a || b > a;
        next.clear();
        for (const Winding& f : hidden) clip_by_brush(f, s.plane, coplanar_inside, B, planes, &next);
        hidden.swap(next);
      }
      for (int pass = 0; pass < 2; ++pass)
        for (Winding& f : pass == 0 ? frags : hidden) {
          if (winding_area(f) < kMinFragmentArea) continue;
          stats->fragments++;
          Face face;
          face.w = std::move(f);
          face.plane = s.plane;
          face.texinfo = pass == 0 ? s.texinfo : -1;
          face.contents = A.contents;
          face.detail = detail_like(A.contents);
          face.attr = A.attr;
          out->push_back(std::move(face));
          stats->hidden += pass;
        }
    }
  }
  stats->merged = merge_faces(out, planes);
  // Back faces for liquids.
  size_t n = out->size();
  for (size_t i = 0; i < n; ++i) {
    Face& f = (*out)[i];
    if (!is_liquid(f.contents) || f.texinfo < 0) continue;
    Face b = f;
    b.plane = f.plane ^ 1;
    b.w = reverse_winding(f.w);
    out->push_back(std::move(b));
    stats->back_faces++;
  }
  for (Face& f : *out) f.update_bounds();
  stats->faces_out = int(out->size());
}

void hint_faces(const std::vector<Brush>& brushes, std::vector<Face>* out) {
  for (const Brush& b : brushes) {
    if (b.contents != kContentsHint) continue;
    for (const BrushSide& s : b.sides) {
      if (!s.hint || s.w.size() < 3) continue;
      Face f;
      f.w = s.w;
      f.plane = s.plane;
      f.texinfo = -1;
      f.contents = kContentsHint;
      f.hint = true;
      f.update_bounds();
      out->push_back(std::move(f));
    }
  }
}

namespace {

bool same_point(const Vec3& a, const Vec3& b) {
  return std::fabs(a.x - b.x) < kMergeEpsilon && std::fabs(a.y - b.y) < kMergeEpsilon &&
         std::fabs(a.z - b.z) < kMergeEpsilon;
}

// Convex turn at b (clockwise winding seen from the front of `normal`).
bool convex_at(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
  Vec3 e1 = b - a, e2 = c - b;
  double l1 = glm::length(e1), l2 = glm::length(e2);
  if (l1 < 1e-9 || l2 < 1e-9) return true;
  return glm::dot(glm::cross(e1 / l1, e2 / l2), normal) < 1e-5;
}

bool try_merge(const Winding& w1, const Winding& w2, const Vec3& normal, Winding* out) {
  size_t n1 = w1.size(), n2 = w2.size();
  for (size_t i = 0; i < n1; ++i) {
    const Vec3& a = w1[i];
    const Vec3& b = w1[(i + 1) % n1];
    for (size_t j = 0; j < n2; ++j) {
      if (!same_point(w2[j], b) || !same_point(w2[(j + 1) % n2], a)) continue;
      // w1: i+1 .. i (all of it, starting after the shared edge); w2: j+2 .. j-1.
      Winding m;
      m.reserve(n1 + n2 - 2);
      for (size_t k = 0; k < n1; ++k) m.push_back(w1[(i + 1 + k) % n1]);
      for (size_t k = 2; k < n2; ++k) m.push_back(w2[(j + k) % n2]);
      size_t n = m.size();
      for (size_t k = 0; k < n; ++k)
        if (!convex_at(m[(k + n - 1) % n], m[k], m[(k + 1) % n], normal)) return false;
      clean_winding(&m);
      if (m.size() < 3) return false;
      *out = std::move(m);
      return true;
    }
  }
  return false;
}

}  // namespace

int merge_faces(std::vector<Face>* faces, const PlaneSet& planes) {
  std::map<std::tuple<int, int, int, bool, int>, std::vector<size_t>> groups;
  for (size_t i = 0; i < faces->size(); ++i) {
    const Face& f = (*faces)[i];
    groups[{f.plane, f.texinfo, f.contents, f.detail, f.attr}].push_back(i);
  }
  std::vector<char> dead(faces->size(), 0);
  // Two faces can share an edge only where their boxes touch: checked before try_merge.
  std::vector<Bounds> box(faces->size());
  for (size_t i = 0; i < faces->size(); ++i)
    for (const Vec3& p : (*faces)[i].w) box[i].add(p);
  int merges = 0;
  for (auto& [key, ids] : groups) {
    if (ids.size() < 2) continue;
    Vec3 normal = planes[std::get<0>(key)].normal;
    bool changed = true;
    while (changed) {
      changed = false;
      for (size_t x = 0; x < ids.size(); ++x) {
        if (dead[ids[x]]) continue;
        for (size_t y = x + 1; y < ids.size(); ++y) {
          if (dead[ids[y]] || !box[ids[x]].overlaps(box[ids[y]], 2 * kMergeEpsilon)) continue;
          Winding m;
          if (try_merge((*faces)[ids[x]].w, (*faces)[ids[y]].w, normal, &m)) {
            (*faces)[ids[x]].w = std::move(m);
            box[ids[x]].add(box[ids[y]]);
            dead[ids[y]] = 1;
            ++merges;
            changed = true;
          }
        }
      }
    }
  }
  std::vector<Face> kept;
  kept.reserve(faces->size() - size_t(merges));
  for (size_t i = 0; i < faces->size(); ++i)
    if (!dead[i]) kept.push_back(std::move((*faces)[i]));
  faces->swap(kept);
  return merges;
}

}  // namespace sb::tools::bsp
