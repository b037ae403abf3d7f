// tools/light/light_attrs.cpp: see light_attrs.h.
#include "tools/light/light_attrs.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

namespace sb::tools {
namespace {

void face_verts(const BspWorld& w, const Face& f, std::vector<glm::vec3>* out) {
  out->clear();
  for (uint32_t k = 0; k < f.num_edges; ++k) {
    int32_t se = w.surfedges[f.first_surfedge + k];
    uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
    out->push_back(w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]]);
  }
}

uint32_t face_vertex_index(const BspWorld& w, const Face& f, uint32_t k) {
  int32_t se = w.surfedges[f.first_surfedge + k];
  uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
  return se < 0 ? w.edges[e].v[1] : w.edges[e].v[0];
}

glm::vec3 facing_normal(const BspWorld& w, const Face& f) {
  const glm::vec3 n = w.planes[f.plane].normal;
  return (f.flags & kFacePlaneBack) ? -n : n;
}

// Slab test of the segment a + t (b - a), t in 0..1, against a box.
bool segment_hits_box(const glm::vec3& a, const glm::vec3& b, const glm::vec3& mins, const glm::vec3& maxs) {
  float t0 = 0, t1 = 1;
  for (int i = 0; i < 3; ++i) {
    float d = b[i] - a[i];
    if (std::fabs(d) < 1e-12f) {
      if (a[i] < mins[i] || a[i] > maxs[i]) return false;
      continue;
    }
    float inv = 1.0f / d;
    float ta = (mins[i] - a[i]) * inv, tb = (maxs[i] - a[i]) * inv;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

void Occluders::build(const BspWorld& w, const LineTracer& tracer, const std::vector<FaceAttr>& attrs) {
  verts_.clear();
  edge_normals_.clear();
  polys_.clear();
  groups_.clear();
  if (attrs.size() != w.num_faces) return;
  std::vector<uint8_t> sub(w.num_faces, 0);
  for (uint32_t m = 1; m < w.num_models; ++m)
    for (uint32_t i = 0; i < w.models[m].num_faces; ++i) {
      uint64_t f = uint64_t(w.models[m].first_face) + i;
      if (f < w.num_faces) sub[f] = 1;
    }
  // Faces by (entity, blocks-all), in face order.
  std::map<std::pair<uint32_t, bool>, std::vector<uint32_t>> by_group;
  std::vector<glm::vec3> vs;
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    const FaceAttr& a = attrs[f];
    bool all = (a.flags & kFaceAttrShadow) != 0;
    bool self = (a.flags & kFaceAttrSelfShadow) != 0;
    if (!all && !self) continue;
    const Face& face = w.faces[f];
    if (face.num_edges < 3) continue;
    if (!sub[f] && all) {
      // A world face with solid behind it already blocks in the tree.
      face_verts(w, face, &vs);
      glm::vec3 c(0);
      for (const glm::vec3& v : vs) c += v;
      c /= float(vs.size());
      if (tracer.contents(c - facing_normal(w, face) * 0.5f) == kContentsSolid) continue;
    }
    by_group[{a.entity, all}].push_back(f);
  }
  for (const auto& [key, faces] : by_group) {
    Group g;
    g.entity = key.first;
    g.all = key.second;
    g.first = uint32_t(polys_.size());
    bool first_box = true;
    for (uint32_t f : faces) {
      const Face& face = w.faces[f];
      face_verts(w, face, &vs);
      Poly p;
      p.normal = facing_normal(w, face);
      glm::vec3 c(0);
      for (const glm::vec3& v : vs) c += v;
      c /= float(vs.size());
      p.dist = glm::dot(p.normal, c);
      p.first = uint32_t(verts_.size());
      p.count = uint32_t(vs.size());
      p.mins = p.maxs = vs[0];
      for (size_t i = 0; i < vs.size(); ++i) {
        glm::vec3 e0 = vs[i], e1 = vs[(i + 1) % vs.size()];
        glm::vec3 en = glm::cross(e1 - e0, p.normal);
        float len = glm::length(en);
        en = len > 1e-6f ? en / len : glm::vec3(0);
        if (glm::dot(c - e0, en) > 0) en = -en;
        verts_.push_back(e0);
        edge_normals_.push_back(en);
        p.mins = glm::min(p.mins, e0);
        p.maxs = glm::max(p.maxs, e0);
      }
      p.mins -= glm::vec3(0.01f);
      p.maxs += glm::vec3(0.01f);
      if (first_box) {
        g.mins = p.mins, g.maxs = p.maxs;
        first_box = false;
      } else {
        g.mins = glm::min(g.mins, p.mins);
        g.maxs = glm::max(g.maxs, p.maxs);
      }
      polys_.push_back(p);
    }
    g.count = uint32_t(polys_.size()) - g.first;
    if (g.count) groups_.push_back(g);
  }
}

bool Occluders::group_blocks(const Group& g, const glm::vec3& a, const glm::vec3& b) const {
  if (!segment_hits_box(a, b, g.mins, g.maxs)) return false;
  for (uint32_t i = g.first; i < g.first + g.count; ++i) {
    const Poly& p = polys_[i];
    float da = glm::dot(p.normal, a) - p.dist, db = glm::dot(p.normal, b) - p.dist;
    if ((da > 0) == (db > 0) || da == db) continue;  // does not cross the plane
    glm::vec3 x = a + (b - a) * (da / (da - db));
    if (x.x < p.mins.x || x.y < p.mins.y || x.z < p.mins.z || x.x > p.maxs.x || x.y > p.maxs.y || x.z > p.maxs.z)
      continue;
    bool inside = true;
    for (uint32_t k = 0; k < p.count && inside; ++k)
      inside = glm::dot(x - verts_[p.first + k], edge_normals_[p.first + k]) <= 0.01f;
    if (inside) return true;
  }
  return false;
}

bool Occluders::blocks(const glm::vec3& a, const glm::vec3& b, uint32_t receiver) const {
  for (const Group& g : groups_) {
    if (!g.all && (receiver == 0 || receiver != g.entity)) continue;
    if (group_blocks(g, a, b)) return true;
  }
  return false;
}

void Occluders::candidates(const glm::vec3& mins, const glm::vec3& maxs, uint32_t receiver,
                           std::vector<uint32_t>* out) const {
  out->clear();
  for (uint32_t i = 0; i < groups_.size(); ++i) {
    const Group& g = groups_[i];
    if (!g.all && (receiver == 0 || receiver != g.entity)) continue;
    if (g.mins.x > maxs.x || g.mins.y > maxs.y || g.mins.z > maxs.z || g.maxs.x < mins.x || g.maxs.y < mins.y ||
        g.maxs.z < mins.z)
      continue;
    out->push_back(i);
  }
}

bool Occluders::blocks_among(const glm::vec3& a, const glm::vec3& b, const std::vector<uint32_t>& groups) const {
  for (uint32_t i : groups)
    if (group_blocks(groups_[i], a, b)) return true;
  return false;
}

void PhongNormals::build(const BspWorld& w, const std::vector<FaceAttr>& attrs) {
  first_.assign(w.num_faces, UINT32_MAX);
  normals_.clear();
  count_ = 0;
  if (attrs.size() != w.num_faces) return;
  std::vector<uint32_t> model(w.num_faces, 0);
  for (uint32_t m = 1; m < w.num_models; ++m)
    for (uint32_t i = 0; i < w.models[m].num_faces; ++i) {
      uint64_t f = uint64_t(w.models[m].first_face) + i;
      if (f < w.num_faces) model[f] = m;
    }
  // Per vertex index: (face, corner angle) of every phong face using it.
  struct Corner {
    uint32_t face;
    float weight;
  };
  std::map<uint32_t, std::vector<Corner>> corners;
  std::vector<glm::vec3> vs, flat(w.num_faces, glm::vec3(0));
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    if (!(attrs[f].phong_angle > 0)) continue;
    const Face& face = w.faces[f];
    if (face.num_edges < 3 || (w.texinfo[face.texinfo].flags & kTexSpecial)) continue;
    flat[f] = facing_normal(w, face);
    face_verts(w, face, &vs);
    size_t n = vs.size();
    for (size_t k = 0; k < n; ++k) {
      glm::vec3 e0 = vs[(k + n - 1) % n] - vs[k], e1 = vs[(k + 1) % n] - vs[k];
      float l0 = glm::length(e0), l1 = glm::length(e1);
      float angle = l0 > 1e-6f && l1 > 1e-6f ? std::acos(std::clamp(glm::dot(e0, e1) / (l0 * l1), -1.0f, 1.0f)) : 0.0f;
      corners[face_vertex_index(w, face, uint32_t(k))].push_back({f, angle});
    }
    first_[f] = 0;  // marked; filled below
  }
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    if (first_[f] == UINT32_MAX) continue;
    const Face& face = w.faces[f];
    const float cos_limit = std::cos(attrs[f].phong_angle * 3.14159265f / 180.0f);
    first_[f] = uint32_t(normals_.size());
    ++count_;
    for (uint32_t k = 0; k < face.num_edges; ++k) {
      glm::vec3 sum(0);
      for (const Corner& c : corners[face_vertex_index(w, face, k)]) {
        if (model[c.face] != model[f]) continue;
        if (c.face != f && glm::dot(flat[c.face], flat[f]) < cos_limit - 1e-6f) continue;
        sum += flat[c.face] * c.weight;
      }
      float len = glm::length(sum);
      normals_.push_back(len > 1e-6f ? sum / len : flat[f]);
    }
  }
}

glm::vec3 PhongNormals::normal_at(uint32_t face, const std::vector<glm::vec3>& verts, const glm::vec3& flat,
                                  const glm::vec3& p) const {
  if (!has(face)) return flat;
  const glm::vec3* vn = &normals_[first_[face]];
  size_t n = verts.size();
  glm::vec3 c(0), cn(0);
  for (size_t i = 0; i < n; ++i) {
    c += verts[i];
    cn += vn[i];
  }
  c /= float(n);
  cn /= float(n);
  // Barycentric coordinates in each fan triangle (c, v_i, v_i+1), measured in the plane; the
  // triangle where p is inside (or least outside) is used, coordinates clamped to >= 0.
  float best = -1e30f;
  glm::vec3 out = flat;
  for (size_t i = 0; i < n; ++i) {
    const glm::vec3 &a = verts[i], &b = verts[(i + 1) % n];
    float area = glm::dot(glm::cross(a - c, b - c), flat);
    if (std::fabs(area) < 1e-6f) continue;
    float wa = glm::dot(glm::cross(b - p, c - p), flat) / area;
    float wb = glm::dot(glm::cross(c - p, a - p), flat) / area;
    float wc = 1.0f - wa - wb;
    float worst = std::min({wa, wb, wc});
    if (worst <= best) continue;
    best = worst;
    wa = std::max(wa, 0.0f), wb = std::max(wb, 0.0f), wc = std::max(wc, 0.0f);
    float s = wa + wb + wc;
    glm::vec3 m = (vn[i] * wa + vn[(i + 1) % n] * wb + cn * wc) / (s > 0 ? s : 1.0f);
    float len = glm::length(m);
    out = len > 1e-6f ? m / len : flat;
    if (worst >= 0) break;
  }
  return out;
}

}  // namespace sb::tools
