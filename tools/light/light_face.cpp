// tools/light/light_face.cpp: see light_face.h.
//
// Sections: 1. scene tables (PVS per light, sky visibility, cull ranges)
//           2. sample points (texture grid -> world, pulled into the face, off the surface)
//           3. light contributions (falloff, angle, spot cone, shadow rays, suns, dirt,
//              the bouncing share)
//           4. styles and bytes
#include "tools/light/light_face.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "engine/world/world.h"
#include "tools/light/light_dirt.h"

namespace sb::tools {
namespace {

constexpr float kSurfaceOffset = 1.0f;  // samples sit this far off the face, along its normal
constexpr float kGrazeEpsilon = 1e-3f;  // |cos| below this counts as grazing (cos 0), not behind

// --- 1. scene tables -------------------------------------------------------------------------

// Faces marked by each leaf of the world, as (leaf -> faces) already in the BSP: marksurfaces.
// Returns the set of faces that belong to submodels (never marked by leaves).
std::vector<uint8_t> submodel_faces(const BspWorld& w) {
  std::vector<uint8_t> sub(w.num_faces, 0);
  for (uint32_t m = 1; m < w.num_models; ++m) {
    const SubModel& sm = w.models[m];
    for (uint32_t i = 0; i < sm.num_faces; ++i) {
      uint64_t f = uint64_t(sm.first_face) + i;
      if (f < w.num_faces) sub[f] = 1;
    }
  }
  return sub;
}

float light_range(const PointLight& l, float gate) {
  float mag = std::fabs(l.intensity);
  float g = gate > 1e-6f ? gate : 1e-6f;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  switch (l.falloff) {
    case Falloff::Linear:
    case Falloff::LocalMin: return mag / l.wait;
    case Falloff::Inverse: return 128.0f * mag / (g * l.wait);
    case Falloff::InverseSquare: return 128.0f * std::sqrt(mag / g) / l.wait;
    case Falloff::InverseSquareBiased: return mag <= g ? 0.0f : 128.0f * std::sqrt(mag / g - 1.0f) / l.wait;
    case Falloff::None: return kInf;
  }
  return kInf;
}

// Falloff value of light `l` at distance d (before angle, cone and rangescale).
// Inverse forms clamp the scaled distance below (32 units for 1/x, 64 for 1/x^2), so a sample
// next to the light gets at most 4x the intensity rather than infinity.
float falloff_value(const PointLight& l, float d) {
  float sd = d * l.wait;
  switch (l.falloff) {
    case Falloff::Linear:
    case Falloff::LocalMin: {
      float mag = std::fabs(l.intensity) - sd;
      if (mag <= 0) return 0;
      return l.intensity < 0 ? -mag : mag;
    }
    case Falloff::Inverse: return l.intensity * 128.0f / std::max(sd, 32.0f);
    case Falloff::InverseSquare: {
      float r = 128.0f / std::max(sd, 64.0f);
      return l.intensity * r * r;
    }
    case Falloff::InverseSquareBiased: {
      float x = sd / 128.0f;
      return l.intensity / (x * x + 1.0f);
    }
    case Falloff::None: return l.intensity;
  }
  return 0;
}

}  // namespace

void prepare_scene(LightScene* scene, LightSettings* settings) {
  const BspWorld& w = *scene->world;
  scene->settings = settings;
  for (PointLight& l : settings->lights) l.range = light_range(l, scene->opts.gate);

  std::vector<uint8_t> sub = submodel_faces(w);
  size_t words = (size_t(w.num_faces) + 63) / 64;
  scene->face_words = words;
  size_t row_bytes = pvs_row_bytes(w);
  std::vector<uint8_t> row(row_bytes + 1);

  // Per light: faces marked by a leaf in the light's PVS (plus the light's own leaf).
  scene->light_faces.assign(settings->lights.size() * words, 0);
  for (size_t li = 0; li < settings->lights.size(); ++li) {
    uint64_t* bits = &scene->light_faces[li * words];
    int leaf = point_in_leaf(w, settings->lights[li].origin);
    decompress_pvs(w, leaf, row.data(), row_bytes);
    for (uint32_t lf = 1; lf < w.num_leaves; ++lf) {
      if (int(lf) != leaf && !leaf_is_visible(row.data(), row_bytes, int(lf))) continue;
      const Leaf& L = w.leaves[lf];
      for (uint32_t k = 0; k < L.num_marksurfaces; ++k) {
        uint64_t ms = uint64_t(L.first_marksurface) + k;
        if (ms >= w.num_marksurfaces) break;
        uint32_t f = w.marksurfaces[ms];
        if (f < w.num_faces) bits[f / 64] |= uint64_t(1) << (f % 64);
      }
    }
    for (uint32_t f = 0; f < w.num_faces; ++f)
      if (sub[f]) bits[f / 64] |= uint64_t(1) << (f % 64);
  }

  // Sky visibility: leaves that mark a sky face (the open leaves in front of sky brushes;
  // sky leaves themselves are not reliably in the PVS), then leaves whose PVS holds one of
  // those, then the faces those leaves mark.
  scene->face_sees_sky.assign(w.num_faces, 0);
  if (settings->suns.empty()) return;
  std::vector<uint32_t> sky_leaves;
  for (uint32_t lf = 1; lf < w.num_leaves; ++lf) {
    const Leaf& L = w.leaves[lf];
    for (uint32_t k = 0; k < L.num_marksurfaces; ++k) {
      uint64_t ms = uint64_t(L.first_marksurface) + k;
      if (ms >= w.num_marksurfaces) break;
      uint32_t f = w.marksurfaces[ms];
      if (f < w.num_faces && (w.faces[f].flags & kFaceSky)) {
        sky_leaves.push_back(lf);
        break;
      }
    }
  }
  for (uint32_t lf = 1; lf < w.num_leaves; ++lf) {
    decompress_pvs(w, int(lf), row.data(), row_bytes);
    bool sees = false;
    for (uint32_t s : sky_leaves)
      if (s == lf || leaf_is_visible(row.data(), row_bytes, int(s))) {
        sees = true;
        break;
      }
    if (!sees) continue;
    const Leaf& L = w.leaves[lf];
    for (uint32_t k = 0; k < L.num_marksurfaces; ++k) {
      uint64_t ms = uint64_t(L.first_marksurface) + k;
      if (ms >= w.num_marksurfaces) break;
      uint32_t f = w.marksurfaces[ms];
      if (f < w.num_faces) scene->face_sees_sky[f] = 1;
    }
  }
  for (uint32_t f = 0; f < w.num_faces; ++f)
    if (sub[f]) scene->face_sees_sky[f] = 1;
}

namespace {

// --- 2. sample points --------------------------------------------------------------------------

struct FaceGeometry {
  std::vector<glm::vec3> verts;
  std::vector<glm::vec3> edge_normals;  // in-plane, pointing out of the polygon
  glm::vec3 normal{0, 0, 1};            // facing normal (flipped for back-side faces)
  glm::vec3 centroid{0};
  glm::vec3 mins{0}, maxs{0};
  // world(s, t) = base + s * ds + t * dt (on the face plane)
  glm::dvec3 base{0}, ds{0}, dt{0};
  bool degenerate = false;
};

void build_geometry(const BspWorld& w, const Face& f, FaceGeometry* g) {
  const Plane& pl = w.planes[f.plane];
  bool back = (f.flags & kFacePlaneBack) != 0;
  g->normal = back ? -pl.normal : pl.normal;
  g->verts.clear();
  for (uint32_t k = 0; k < f.num_edges; ++k) {
    int32_t se = w.surfedges[f.first_surfedge + k];
    uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
    g->verts.push_back(w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]]);
  }
  glm::dvec3 c(0);
  g->mins = g->maxs = g->verts[0];
  for (const glm::vec3& v : g->verts) {
    c += glm::dvec3(v);
    g->mins = glm::min(g->mins, v);
    g->maxs = glm::max(g->maxs, v);
  }
  g->centroid = glm::vec3(c / double(g->verts.size()));
  size_t n = g->verts.size();
  g->edge_normals.resize(n);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 a = g->verts[i], b = g->verts[(i + 1) % n];
    glm::vec3 en = glm::cross(b - a, g->normal);
    float len = glm::length(en);
    en = len > 1e-6f ? en / len : glm::vec3(0);
    if (glm::dot(g->centroid - a, en) > 0) en = -en;
    g->edge_normals[i] = en;
  }
  // Solve [S; T; Np] x = (s - s0, t - t0, dist) with Cramer's rule, in double.
  const TexInfo& ti = w.texinfo[f.texinfo];
  glm::dvec3 r0(ti.vecs[0]), r1(ti.vecs[1]), r2(pl.normal);
  glm::dvec3 c12 = glm::cross(r1, r2), c20 = glm::cross(r2, r0), c01 = glm::cross(r0, r1);
  double det = glm::dot(r0, c12);
  double scale = glm::length(r0) * glm::length(r1);
  if (!(std::fabs(det) > 1e-6 * (scale > 0 ? scale : 1))) {
    g->degenerate = true;
    return;
  }
  g->ds = c12 / det;
  g->dt = c20 / det;
  g->base = (-double(ti.vecs[0].w) * c12 - double(ti.vecs[1].w) * c20 + double(pl.dist) * c01) / det;
}

bool inside_polygon(const FaceGeometry& g, const glm::vec3& p) {
  for (size_t i = 0; i < g.verts.size(); ++i)
    if (glm::dot(p - g.verts[i], g.edge_normals[i]) > 0.01f) return false;
  return true;
}

glm::vec3 closest_on_boundary(const FaceGeometry& g, const glm::vec3& p) {
  float best = std::numeric_limits<float>::infinity();
  glm::vec3 out = g.centroid;
  size_t n = g.verts.size();
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 a = g.verts[i], ab = g.verts[(i + 1) % n] - a;
    float len2 = glm::dot(ab, ab);
    float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    glm::vec3 q = a + ab * t;
    float d2 = glm::dot(p - q, p - q);
    if (d2 < best) {
      best = d2;
      out = q;
    }
  }
  return out;
}

// World position of the sample at texture coordinates (s, t): on the plane, moved into the
// polygon when it lies outside (to the nearest boundary point, then 1 unit towards the
// centroid), lifted kSurfaceOffset along the normal, and walked towards the centroid while
// it is in solid or sky (1, 2, 4, 8 units, then quarters of the way), so light neither
// leaks through walls nor is lost under them.
glm::vec3 sample_point(const LightScene& sc, const FaceGeometry& g, double s, double t) {
  glm::vec3 p = g.degenerate ? g.centroid : glm::vec3(g.base + s * g.ds + t * g.dt);
  if (!inside_polygon(g, p)) {
    p = closest_on_boundary(g, p);
    glm::vec3 to_c = g.centroid - p;
    float len = glm::length(to_c);
    p += len > 1.0f ? to_c / len : to_c;
  }
  glm::vec3 lifted = p + g.normal * kSurfaceOffset;
  int c = sc.tracer->contents(lifted);
  if (c != kContentsSolid && c != kContentsSky) return lifted;
  // Small steps first (a grid point on an edge where a wall stands is in solid by a hair),
  // then quarters of the way to the centroid.
  glm::vec3 to_c = g.centroid - p;
  float len = glm::length(to_c);
  for (float step : {1.0f, 2.0f, 4.0f, 8.0f}) {
    if (step >= len * 0.25f) break;
    glm::vec3 q = p + to_c * (step / len) + g.normal * kSurfaceOffset;
    c = sc.tracer->contents(q);
    if (c != kContentsSolid && c != kContentsSky) return q;
  }
  for (int k = 1; k <= 4; ++k) {
    glm::vec3 q = p + (g.centroid - p) * (float(k) * 0.25f) + g.normal * kSurfaceOffset;
    c = sc.tracer->contents(q);
    if (c != kContentsSolid && c != kContentsSky) return q;
  }
  return lifted;
}

// --- 3. light contributions ----------------------------------------------------------------------

float box_distance(const glm::vec3& p, const glm::vec3& mins, const glm::vec3& maxs) {
  glm::vec3 d = glm::max(glm::max(mins - p, p - maxs), glm::vec3(0));
  return glm::length(d);
}

// Adds v * colour to cell `cell` of the buffer of `style` (created on first use, cached in
// *slot) and, when bounce is on and the style bounces, v * colour * bouncescale to emit.
struct Accumulator {
  FaceWork* work;
  size_t grid;
  bool bounce;        // scene.bounces > 0
  bool styled;        // every style bounces (else style 0 only)
  void add(int style, StyleBuffer** slot, StyleBuffer** emit_slot, size_t cell, float v, const glm::vec3& color,
           float bouncescale) {
    if (!*slot) *slot = &style_buffer(work->light, style, grid);
    float* o = &(*slot)->rgb[cell * 3];
    o[0] += v * color.r;
    o[1] += v * color.g;
    o[2] += v * color.b;
    if (!bounce || bouncescale <= 0 || (style != 0 && !styled)) return;
    if (!*emit_slot) *emit_slot = &style_buffer(work->emit, style, grid);
    float* e = &(*emit_slot)->rgb[cell * 3];
    float vb = v * bouncescale;
    e[0] += vb * color.r;
    e[1] += vb * color.g;
    e[2] += vb * color.b;
  }
};

}  // namespace

StyleBuffer& style_buffer(std::vector<StyleBuffer>& bufs, int style, size_t grid) {
  for (StyleBuffer& b : bufs)
    if (b.style == style) return b;
  bufs.push_back({style, std::vector<float>(grid * 3, 0.0f)});
  return bufs.back();
}

void face_setup(const LightScene& sc, uint32_t face_index, FaceWork* work) {
  *work = FaceWork();
  const BspWorld& w = *sc.world;
  const Face& f = w.faces[face_index];
  if (w.texinfo[f.texinfo].flags & kTexSpecial) return;
  work->lit = true;
  if (!sc.attrs.empty()) {
    const FaceAttr& a = sc.attrs[face_index];
    work->minlight = a.minlight;
    work->minlight_color = glm::vec3(a.minlight_color[0], a.minlight_color[1], a.minlight_color[2]) / 255.0f;
    work->light_ignore = (a.flags & kFaceAttrLightIgnore) != 0;
  }
  FaceGeometry g;
  build_geometry(w, f, &g);
  work->degenerate = g.degenerate;
  work->normal = g.normal;
  work->gw = f.extents[0] / 16 + 1;
  work->gh = f.extents[1] / 16 + 1;
  work->centres.resize(size_t(work->gw) * size_t(work->gh));
  for (int gy = 0; gy < work->gh; ++gy)
    for (int gx = 0; gx < work->gw; ++gx)
      work->centres[size_t(gy) * work->gw + gx] = sample_point(
          sc, g, double(f.texture_mins[0]) + 16.0 * gx, double(f.texture_mins[1]) + 16.0 * gy);
}

void light_face_direct(const LightScene& sc, uint32_t face_index, FaceWork* work) {
  if (!work->lit) return;
  const BspWorld& w = *sc.world;
  const Face& f = w.faces[face_index];
  const LightSettings& set = *sc.settings;

  FaceGeometry g;
  build_geometry(w, f, &g);
  const int gw = work->gw, gh = work->gh;
  const size_t grid = size_t(gw) * size_t(gh);
  const int sub = sc.opts.extra == 4 ? 4 : (sc.opts.extra == 2 ? 2 : 1);
  const size_t per = size_t(sub) * size_t(sub);
  const float weight = 1.0f / float(per);
  const std::vector<glm::vec3>& centres = work->centres;

  // Sample points: per grid point, `per` sub-samples on a centred sub-grid of the 16-texel
  // cell (the grid points themselves without supersampling, and for the sky dome).
  std::vector<glm::vec3> sub_pts;
  if (sub > 1) {
    sub_pts.resize(grid * per);
    for (int gy = 0; gy < gh; ++gy)
      for (int gx = 0; gx < gw; ++gx) {
        size_t cell = size_t(gy) * gw + gx;
        double s0 = double(f.texture_mins[0]) + 16.0 * gx, t0 = double(f.texture_mins[1]) + 16.0 * gy;
        for (int j = 0; j < sub; ++j)
          for (int i = 0; i < sub; ++i) {
            double os = (i + 0.5) * 16.0 / sub - 8.0, ot = (j + 0.5) * 16.0 / sub - 8.0;
            sub_pts[cell * per + size_t(j) * sub + i] = sample_point(sc, g, s0 + os, t0 + ot);
          }
      }
  }
  const std::vector<glm::vec3>& pts = sub > 1 ? sub_pts : centres;

  // Dirt factors per grid point: the global ones, and per light with its own scale / gain.
  const bool has_dirt = !work->occlusion.empty();
  std::vector<float> global_dirt, own_dirt;
  if (has_dirt) {
    global_dirt.resize(grid);
    for (size_t k = 0; k < grid; ++k) global_dirt[k] = dirt_factor(work->occlusion[k], set.dirtscale, set.dirtgain);
  }

  style_buffer(work->light, 0, grid);
  if (work->light_ignore) return;
  Accumulator acc{work, grid, sc.bounces > 0, set.bouncestyled};
  const float face_plane = glm::dot(g.normal, g.centroid);
  const uint32_t receiver = sc.attrs.empty() ? 0 : sc.attrs[face_index].entity;
  const bool occluders = !sc.occluders.empty();
  std::vector<uint32_t> near_groups;
  // Phong: a lighting normal per sample point (and per grid point for the sky dome).
  std::vector<glm::vec3> normals, centre_normals;
  const bool phong = sc.phong.has(face_index) && !g.degenerate;
  if (phong) {
    normals.resize(pts.size());
    for (size_t k = 0; k < pts.size(); ++k) normals[k] = sc.phong.normal_at(face_index, g.verts, g.normal, pts[k]);
    centre_normals.resize(centres.size());
    for (size_t k = 0; k < centres.size(); ++k)
      centre_normals[k] = sc.phong.normal_at(face_index, g.verts, g.normal, centres[k]);
  }

  for (size_t li = 0; li < set.lights.size(); ++li) {
    const PointLight& l = set.lights[li];
    if (!sc.light_may_see(li, face_index)) continue;
    if (glm::dot(g.normal, l.origin) - face_plane <= 0) continue;  // behind the face
    if (box_distance(l.origin, g.mins, g.maxs) > l.range) continue;
    const float* dirt = nullptr;
    if (has_dirt && l.dirt > 0 && l.falloff != Falloff::LocalMin) {
      if (l.dirtscale == set.dirtscale && l.dirtgain == set.dirtgain) {
        dirt = global_dirt.data();
      } else {
        own_dirt.resize(grid);
        for (size_t k = 0; k < grid; ++k) own_dirt[k] = dirt_factor(work->occlusion[k], l.dirtscale, l.dirtgain);
        dirt = own_dirt.data();
      }
    }
    // Occluder groups inside the box around the sample points and the light.
    bool occ = false;
    if (occluders) {
      glm::vec3 lo = glm::min(g.mins, l.origin) - glm::vec3(2.0f), hi = glm::max(g.maxs, l.origin) + glm::vec3(2.0f);
      sc.occluders.candidates(lo, hi, receiver, &near_groups);
      occ = !near_groups.empty();
    }
    StyleBuffer *buf = nullptr, *emit = nullptr;
    for (size_t k = 0; k < pts.size(); ++k) {
      const glm::vec3& p = pts[k];
      glm::vec3 d = l.origin - p;
      float dist = glm::length(d);
      if (dist < 1e-3f) dist = 1e-3f;
      glm::vec3 dir = d / dist;
      float cos_n = glm::dot(dir, phong ? normals[k] : g.normal);
      if (cos_n <= 0) continue;
      float value = falloff_value(l, dist);
      if (value == 0) continue;
      if (l.spot) {
        float cs = -glm::dot(dir, l.spot_dir);
        if (cs < l.spot_cos_outer) continue;
        if (cs < l.spot_cos_inner) value *= (cs - l.spot_cos_outer) / (l.spot_cos_inner - l.spot_cos_outer);
      }
      if (l.falloff != Falloff::LocalMin) value *= (1.0f - l.anglescale) + l.anglescale * cos_n;
      ++work->traces;
      if (!sc.tracer->clear(p, l.origin)) continue;
      if (occ && sc.occluders.blocks_among(p, l.origin, near_groups)) continue;
      size_t cell = k / per;
      if (l.falloff == Falloff::LocalMin) {
        if (work->local_min.empty()) work->local_min.assign(grid, 0.0f);
        work->local_min[cell] = std::max(work->local_min[cell], std::min(std::fabs(l.intensity), 255.0f));
        continue;
      }
      float v = value * weight;
      if (dirt) v *= dirt[cell];
      acc.add(l.style, &buf, &emit, cell, v, l.color, l.bouncescale);
    }
  }

  // Suns: a sample is lit when the ray towards the sun reaches a sky leaf first.
  if (!set.suns.empty() && sc.face_sees_sky[face_index]) {
    const float span = sc.tracer->world_span();
    for (const Sun& s : set.suns) {
      // A face the sun grazes (cos 0, e.g. a wall under a sun straight down) still gets the
      // angle factor's floor, 1 - anglescale: only faces turned away from the sun get none.
      float cos_n = -glm::dot(s.dir, g.normal);
      if (cos_n < -kGrazeEpsilon) continue;
      cos_n = std::max(cos_n, 0.0f);
      float value = s.intensity * ((1.0f - s.anglescale) + s.anglescale * cos_n);
      const std::vector<glm::vec3>& P = s.dome ? centres : pts;
      const std::vector<glm::vec3>& PN = s.dome ? centre_normals : normals;
      size_t pp = s.dome ? 1 : per;
      float wgt = s.dome ? 1.0f : weight;
      const float* dirt = has_dirt && s.dirt > 0 ? global_dirt.data() : nullptr;
      StyleBuffer *buf = nullptr, *emit = nullptr;
      for (size_t k = 0; k < P.size(); ++k) {
        float pv = value;
        if (phong) {  // the angle factor with the sample's normal (none when it faces away)
          float c = -glm::dot(s.dir, PN[k]);
          if (c < -kGrazeEpsilon) continue;
          pv = s.intensity * ((1.0f - s.anglescale) + s.anglescale * std::max(c, 0.0f));
        }
        ++work->traces;
        glm::vec3 far = P[k] - s.dir * span;
        if (sc.tracer->first_blocker(P[k], far) != kContentsSky) continue;
        if (occluders && sc.occluders.blocks(P[k], far, receiver)) continue;
        size_t cell = k / pp;
        float v = pv * wgt;
        if (dirt) v *= dirt[cell];
        acc.add(s.style, &buf, &emit, cell, v, s.color, 1.0f);
      }
    }
  }

  // What bounces from here: the bouncing share times the face's reflectivity.
  if (sc.bounces > 0) {
    const glm::vec3 r = sc.hit_faces[face_index].usable ? sc.hit_faces[face_index].reflect : glm::vec3(0);
    for (StyleBuffer& e : work->emit)
      for (size_t k = 0; k < grid; ++k) {
        e.rgb[k * 3] *= r.r;
        e.rgb[k * 3 + 1] *= r.g;
        e.rgb[k * 3 + 2] *= r.b;
      }
  }
}

// --- 4. styles and bytes ---------------------------------------------------------------------

void finish_face(const LightScene& sc, const FaceWork& work, FaceLightmap* out) {
  *out = FaceLightmap();
  out->traces = work.traces;
  if (!work.lit) return;
  out->lit = true;
  out->degenerate = work.degenerate;
  const LightSettings& set = *sc.settings;
  const size_t grid = size_t(work.gw) * size_t(work.gh);
  const float range = set.rangescale;
  const bool dirty_min = sc.minlight_dirt && !work.occlusion.empty();
  auto to_byte = [](float v) -> uint8_t {
    if (!(v > 0)) return 0;
    if (v >= 254.5f) return 255;
    return uint8_t(v + 0.5f);
  };
  struct Converted {
    int style;
    std::vector<uint8_t> mono, rgb;
    uint64_t sum = 0;
  };
  std::vector<Converted> conv;
  for (const StyleBuffer& b : work.light) {
    Converted c;
    c.style = b.style;
    c.mono.resize(grid);
    if (sc.opts.want_rgb) c.rgb.resize(grid * 3);
    for (size_t k = 0; k < grid; ++k) {
      float r = b.rgb[k * 3] * range, gg = b.rgb[k * 3 + 1] * range, bb = b.rgb[k * 3 + 2] * range;
      // The monochrome lightmap holds the brightest channel (as the Quake light tools write it, so
      // that engines which normalise a .lit against the .bsp lightmap see equal intensity).
      float m = std::max({r, gg, bb});
      if (work.light_ignore) r = gg = bb = m = 0;
      if (b.style == 0) {
        // The entity's minimum light (coloured) when it gives one, else worldspawn's (white).
        const bool own = work.minlight >= 0;
        float floor = own ? work.minlight : set.minlight;
        if (dirty_min) floor *= dirt_factor(work.occlusion[k], set.dirtscale, set.dirtgain);
        glm::vec3 fc = own ? floor * work.minlight_color : glm::vec3(floor);
        if (!work.local_min.empty()) fc = glm::max(fc, glm::vec3(work.local_min[k]));
        m = std::max(m, std::max({fc.r, fc.g, fc.b}));
        r = std::max(r, fc.r);
        gg = std::max(gg, fc.g);
        bb = std::max(bb, fc.b);
      }
      c.mono[k] = to_byte(m);
      c.sum += c.mono[k];
      if (sc.opts.want_rgb) {
        // Too bright: scaled down whole so the brightest channel is 255, keeping the hue (a
        // saturated green stays green, as in the reference .lit files, not white).
        if (m > 255.0f) {
          float f = 255.0f / m;
          r *= f, gg *= f, bb *= f;
        }
        c.rgb[k * 3] = to_byte(r);
        c.rgb[k * 3 + 1] = to_byte(gg);
        c.rgb[k * 3 + 2] = to_byte(bb);
      }
    }
    if (b.style != 0 && c.sum == 0) continue;  // a style that left no light here
    conv.push_back(std::move(c));
  }
  // Style 0 first, then at most 3 others in the order first seen; the weakest go first.
  while (conv.size() > 4) {
    size_t weakest = 1;
    for (size_t k = 2; k < conv.size(); ++k)
      if (conv[k].sum < conv[weakest].sum) weakest = k;
    out->styles_dropped = true;
    if (out->first_dropped_style < 0) out->first_dropped_style = conv[weakest].style;
    conv.erase(conv.begin() + std::ptrdiff_t(weakest));
  }
  out->num_styles = int(conv.size());
  out->mono.reserve(grid * conv.size());
  for (size_t k = 0; k < conv.size(); ++k) {
    out->styles[k] = uint8_t(conv[k].style);
    out->mono.insert(out->mono.end(), conv[k].mono.begin(), conv[k].mono.end());
    if (sc.opts.want_rgb) out->rgb.insert(out->rgb.end(), conv[k].rgb.begin(), conv[k].rgb.end());
  }
}

}  // namespace sb::tools
