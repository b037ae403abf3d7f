// tools/light/light_bounce.cpp: see light_bounce.h.
#include "tools/light/light_bounce.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "tools/light/light_dirt.h"

namespace sb::tools {
namespace {

constexpr float kPi = 3.14159265358979323846f;
// Reflectivity of a face when the texture colours are ignored ("_bouncecolorscale" 0): a mid
// grey (127 / 255), so one bounce returns about half the light a surface receives.
constexpr float kBounceGrey = 127.0f / 255.0f;
constexpr float kInsideTolerance = 2;  // units a hit may lie outside its face's polygon

// Mean colour (0..1) of a texture's mip 0, or grey 0.5 without pixels or palette.
glm::vec3 texture_colour(const BspWorld& w, uint32_t t, const std::vector<uint8_t>& palette) {
  const Texture& tex = w.textures[t];
  if (palette.size() != 768 || t == w.placeholder_texture || !tex.mips[0] || tex.width == 0 || tex.height == 0)
    return glm::vec3(0.5f);
  uint64_t sum[3] = {0, 0, 0};
  size_t n = size_t(tex.width) * size_t(tex.height);
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* c = &palette[size_t(tex.mips[0][i]) * 3];
    sum[0] += c[0], sum[1] += c[1], sum[2] += c[2];
  }
  return glm::vec3(float(sum[0]), float(sum[1]), float(sum[2])) / (255.0f * float(n));
}

// Distance by which p lies outside the polygon (<= 0 inside); stops early once it exceeds
// `limit` (then returns some value above limit).
float outside_distance(const HitFace& f, const glm::vec3& p, float limit) {
  float worst = -1e30f;
  for (size_t i = 0; i < f.verts.size(); ++i) {
    worst = std::max(worst, glm::dot(p - f.verts[i], f.edge_normals[i]));
    if (worst > limit) break;
  }
  return worst;
}

constexpr float kMinNewStyle = 2.0f;  // output units (see bounce_commit)

// Whether face f may be the one hit at q (on the plane of node n): on that plane, facing the
// ray, q inside its bounds widened by `margin`.
inline bool hit_candidate(const LightScene& sc, uint32_t f, const Node& n, const glm::vec3& q, const glm::vec3& dir,
                          float margin) {
  if (sc.hit_plane[f] != n.plane) return false;  // also rejects unusable faces
  const HitFace& hf = sc.hit_faces[f];
  if (glm::dot(hf.normal, dir) >= 0) return false;
  return !(q.x < hf.mins.x - margin || q.y < hf.mins.y - margin || q.z < hf.mins.z - margin ||
           q.x > hf.maxs.x + margin || q.y > hf.maxs.y + margin || q.z > hf.maxs.z + margin);
}

// The face a ray travelling along `dir` hit at h, or -1. First among the faces the leaf the
// ray came from marks (few), then among all faces on the node's plane (a big plane may hold
// hundreds).
int find_hit_face(const LightScene& sc, const LineTracer::Hit& h, const glm::vec3& dir) {
  const BspWorld& w = *sc.world;
  if (h.node < 0 || uint32_t(h.node) >= w.num_nodes) return -1;
  const Node& n = w.nodes[h.node];
  if (h.leaf_before > 0 && uint32_t(h.leaf_before) < w.num_leaves) {
    const Leaf& L = w.leaves[h.leaf_before];
    for (uint32_t k = 0; k < L.num_marksurfaces; ++k) {
      uint64_t ms = uint64_t(L.first_marksurface) + k;
      if (ms >= w.num_marksurfaces) break;
      uint32_t f = w.marksurfaces[ms];
      if (f >= w.num_faces || !hit_candidate(sc, f, n, h.point, dir, 0.01f)) continue;
      if (outside_distance(sc.hit_faces[f], h.point, 0.01f) <= 0.01f) return int(f);
    }
  }
  int best = -1;
  float best_out = kInsideTolerance;
  for (uint32_t k = 0; k < n.num_faces; ++k) {
    uint32_t f = n.first_face + k;
    if (f >= w.num_faces) break;
    const HitFace& hf = sc.hit_faces[f];
    if (!hf.usable || glm::dot(hf.normal, dir) >= 0) continue;
    const glm::vec3& q = h.point;
    if (q.x < hf.mins.x - best_out || q.y < hf.mins.y - best_out || q.z < hf.mins.z - best_out ||
        q.x > hf.maxs.x + best_out || q.y > hf.maxs.y + best_out || q.z > hf.maxs.z + best_out)
      continue;
    float out = outside_distance(hf, q, best_out);
    if (out <= best_out) {
      best_out = out;
      best = int(f);
      if (out <= 0) break;
    }
  }
  return best;
}

// Bilinear read of buffer `rgb` (grid gw x gh) of face f at world point p.
glm::vec3 read_grid(const BspWorld& w, uint32_t f, int gw, int gh, const std::vector<float>& rgb, const glm::vec3& p) {
  const Face& face = w.faces[f];
  const TexInfo& ti = w.texinfo[face.texinfo];
  float s = glm::dot(p, glm::vec3(ti.vecs[0])) + ti.vecs[0].w;
  float t = glm::dot(p, glm::vec3(ti.vecs[1])) + ti.vecs[1].w;
  float x = std::clamp((s - float(face.texture_mins[0])) / 16.0f, 0.0f, float(gw - 1));
  float y = std::clamp((t - float(face.texture_mins[1])) / 16.0f, 0.0f, float(gh - 1));
  if (!std::isfinite(x)) x = 0;
  if (!std::isfinite(y)) y = 0;
  int x0 = std::min(int(x), gw - 1), y0 = std::min(int(y), gh - 1);
  int x1 = std::min(x0 + 1, gw - 1), y1 = std::min(y0 + 1, gh - 1);
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int gx, int gy) {
    const float* c = &rgb[(size_t(gy) * gw + gx) * 3];
    return glm::vec3(c[0], c[1], c[2]);
  };
  return (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
}

}  // namespace

bool prepare_bounce(LightScene* sc, const std::vector<uint8_t>& palette, float colorscale) {
  const BspWorld& w = *sc->world;
  std::vector<glm::vec3> colours(w.num_textures);
  for (uint32_t t = 0; t < w.num_textures; ++t) {
    glm::vec3 c = colorscale > 0 ? texture_colour(w, t, palette) : glm::vec3(kBounceGrey);
    colours[t] = glm::vec3(kBounceGrey * (1.0f - colorscale)) + c * colorscale;
  }
  std::vector<uint8_t> sub(w.num_faces, 0);
  for (uint32_t m = 1; m < w.num_models; ++m)
    for (uint32_t i = 0; i < w.models[m].num_faces; ++i) {
      uint64_t f = uint64_t(w.models[m].first_face) + i;
      if (f < w.num_faces) sub[f] = 1;
    }
  sc->hit_faces.assign(w.num_faces, HitFace());
  sc->hit_plane.assign(w.num_faces, UINT32_MAX);
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    const Face& face = w.faces[f];
    const TexInfo& ti = w.texinfo[face.texinfo];
    HitFace& hf = sc->hit_faces[f];
    hf.reflect = colours[ti.texture];
    if ((ti.flags & kTexSpecial) || sub[f]) continue;
    hf.usable = true;
    sc->hit_plane[f] = face.plane;
    const Plane& pl = w.planes[face.plane];
    hf.normal = (face.flags & kFacePlaneBack) ? -pl.normal : pl.normal;
    glm::vec3 centre(0);
    for (uint32_t k = 0; k < face.num_edges; ++k) {
      int32_t se = w.surfedges[face.first_surfedge + k];
      uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
      hf.verts.push_back(w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]]);
      centre += hf.verts.back();
    }
    centre /= float(hf.verts.size());
    hf.mins = hf.maxs = hf.verts[0];
    for (const glm::vec3& v : hf.verts) {
      hf.mins = glm::min(hf.mins, v);
      hf.maxs = glm::max(hf.maxs, v);
    }
    size_t n = hf.verts.size();
    hf.edge_normals.resize(n);
    for (size_t i = 0; i < n; ++i) {
      glm::vec3 a = hf.verts[i], b = hf.verts[(i + 1) % n];
      glm::vec3 en = glm::cross(b - a, hf.normal);
      float len = glm::length(en);
      en = len > 1e-6f ? en / len : glm::vec3(0);
      if (glm::dot(centre - a, en) > 0) en = -en;
      hf.edge_normals[i] = en;
    }
  }
  return palette.size() == 768 || colorscale <= 0;
}

void bounce_gather(const LightScene& sc, uint32_t fi, const std::vector<FaceWork>& all, FaceWork* work) {
  work->gathered.clear();
  if (!work->lit || work->centres.empty()) return;
  const BspWorld& w = *sc.world;
  const int gw = work->gw, gh = work->gh;
  const int kReceiverStep = std::clamp(sc.opts.bounce_step, 1, 16);
  const int rw = (gw - 1 + kReceiverStep - 1) / kReceiverStep + 1;
  const int rh = (gh - 1 + kReceiverStep - 1) / kReceiverStep + 1;
  const size_t receivers = size_t(rw) * size_t(rh);
  const int rays = std::max(1, sc.opts.bounce_rays);
  const int sx = std::max(1, int(std::sqrt(float(rays)))), sy = std::max(1, rays / sx);
  const float span = sc.tracer->world_span();
  const float scale = sc.settings->bouncescale;
  glm::vec3 t, b;
  const glm::vec3 n = work->normal;
  tangent_frame(n, &t, &b);

  // Gathers at grid point `cell` into slot `index` of dst (buffers of `size` entries, a
  // buffer appended per new style). Returns false when no ray could be used.
  std::vector<glm::vec3> sum;  // per buffer of dst, for the point being gathered
  auto gather = [&](uint32_t cell, std::vector<StyleBuffer>& dst, size_t size, size_t index) -> bool {
    const glm::vec3 p = work->centres[cell];
    sum.assign(dst.size(), glm::vec3(0));
    int counted = 0;
    for (int j = 0; j < sy; ++j)
      for (int i = 0; i < sx; ++i) {
        const uint32_t ray = uint32_t(j * sx + i);
        float u = (float(i) + hash_unit(fi, cell, 2 * ray)) / float(sx);      // sin^2 theta
        float v = (float(j) + hash_unit(fi, cell, 2 * ray + 1)) / float(sy);  // azimuth
        float r = std::sqrt(u), phi = v * 2.0f * kPi;
        glm::vec3 d = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * std::sqrt(std::max(0.0f, 1.0f - u));
        ++work->bounce_rays;
        LineTracer::Hit h = sc.tracer->first_hit(p, p + d * span);
        if (h.contents == kContentsEmpty) {
          ++counted;
          continue;
        }
        if (h.node < 0) continue;  // starts inside solid or sky
        if (h.contents == kContentsSky) {
          ++counted;
          continue;
        }
        int hf = find_hit_face(sc, h, d);
        if (hf < 0) {
          ++work->bounce_misses;
          continue;
        }
        ++counted;
        const FaceWork& src = all[size_t(hf)];
        for (const StyleBuffer& e : src.emit) {
          size_t slot = 0;
          while (slot < dst.size() && dst[slot].style != e.style) ++slot;
          if (slot == dst.size()) {
            dst.push_back({e.style, std::vector<float>(size * 3, 0.0f)});
            sum.push_back(glm::vec3(0));
          }
          // Not clamped to what a byte can show: a surface lit far beyond 255 (next to a bright
          // pool of surface lights) sends all of that light on, as the reference lighter does.
          sum[slot] += read_grid(w, uint32_t(hf), src.gw, src.gh, e.rgb, h.point);
        }
      }
    const float k = counted ? scale / float(counted) : 0.0f;
    for (size_t s = 0; s < dst.size(); ++s) {
      dst[s].rgb[index * 3] = sum[s].r * k;
      dst[s].rgb[index * 3 + 1] = sum[s].g * k;
      dst[s].rgb[index * 3 + 2] = sum[s].b * k;
    }
    return counted > 0;
  };

  // Receivers.
  std::vector<StyleBuffer> recv;
  std::vector<uint8_t> valid(receivers, 0);
  for (int ry = 0; ry < rh; ++ry)
    for (int rx = 0; rx < rw; ++rx) {
      const int gx = std::min(rx * kReceiverStep, gw - 1), gy = std::min(ry * kReceiverStep, gh - 1);
      size_t ri = size_t(ry) * rw + rx;
      valid[ri] = gather(uint32_t(gy * gw + gx), recv, receivers, ri);
    }

  // Every grid point: bilinear between the receivers around it, unless they disagree (more
  // than kRefine light units and half of the brightest, summed over styles and channels)
  // or one of them gathered nothing: then it is gathered itself.
  constexpr float kRefine = 24.0f;
  const size_t grid = size_t(gw) * size_t(gh);
  std::vector<StyleBuffer>& out = work->gathered;
  for (const StyleBuffer& rb : recv) style_buffer(out, rb.style, grid);
  for (int gy = 0; gy < gh; ++gy) {
    int ry0 = std::min(gy / kReceiverStep, rh - 1), ry1 = std::min(ry0 + 1, rh - 1);
    int y0 = std::min(ry0 * kReceiverStep, gh - 1), y1 = std::min(ry1 * kReceiverStep, gh - 1);
    float fy = y1 > y0 ? float(gy - y0) / float(y1 - y0) : 0.0f;
    for (int gx = 0; gx < gw; ++gx) {
      int rx0 = std::min(gx / kReceiverStep, rw - 1), rx1 = std::min(rx0 + 1, rw - 1);
      int x0 = std::min(rx0 * kReceiverStep, gw - 1), x1 = std::min(rx1 * kReceiverStep, gw - 1);
      float fx = x1 > x0 ? float(gx - x0) / float(x1 - x0) : 0.0f;
      const size_t cell = size_t(gy) * gw + gx;
      const size_t corners[4] = {size_t(ry0) * rw + rx0, size_t(ry0) * rw + rx1, size_t(ry1) * rw + rx0,
                                 size_t(ry1) * rw + rx1};
      bool is_receiver = (gx == x0 || gx == x1) && (gy == y0 || gy == y1);
      if (!is_receiver) {
        bool refine = false;
        for (size_t c : corners) refine |= !valid[c];
        float lo = 1e30f, hi = 0;
        for (size_t c : corners) {
          float v = 0;
          for (const StyleBuffer& rb : recv) v += rb.rgb[c * 3] + rb.rgb[c * 3 + 1] + rb.rgb[c * 3 + 2];
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
        refine |= hi - lo > kRefine && hi - lo > 0.5f * hi;
        if (refine) {
          gather(uint32_t(cell), out, grid, cell);
          continue;
        }
      }
      for (const StyleBuffer& rb : recv) {
        StyleBuffer& o = style_buffer(out, rb.style, grid);
        for (int c = 0; c < 3; ++c) {
          auto at = [&](size_t r) { return rb.rgb[r * 3 + size_t(c)]; };
          o.rgb[cell * 3 + size_t(c)] = (at(corners[0]) * (1 - fx) + at(corners[1]) * fx) * (1 - fy) +
                                        (at(corners[2]) * (1 - fx) + at(corners[3]) * fx) * fy;
        }
      }
    }
  }
}

void bounce_commit(const LightScene& sc, uint32_t fi, FaceWork* work, bool another_pass) {
  const size_t grid = size_t(work->gw) * size_t(work->gh);
  const float range = sc.settings->rangescale;
  for (const StyleBuffer& g : work->gathered) {
    // A style new to this face that bounce would only add a glimmer of (every sample under
    // kMinNewStyle output units): not worth a lightmap of its own.
    bool has = false;
    for (const StyleBuffer& l : work->light) has |= l.style == g.style;
    if (!has && g.style != 0) {
      float peak = 0;
      for (float x : g.rgb) peak = std::max(peak, x);
      if (peak * range < kMinNewStyle) continue;
    }
    StyleBuffer& l = style_buffer(work->light, g.style, grid);
    for (size_t k = 0; k < grid * 3; ++k) l.rgb[k] += g.rgb[k];
  }
  work->emit.clear();
  if (another_pass) {
    const glm::vec3 r = sc.hit_faces[fi].usable ? sc.hit_faces[fi].reflect : glm::vec3(0);
    work->emit.swap(work->gathered);
    for (StyleBuffer& e : work->emit)
      for (size_t k = 0; k < grid; ++k) {
        e.rgb[k * 3] *= r.r;
        e.rgb[k * 3 + 1] *= r.g;
        e.rgb[k * 3 + 2] *= r.b;
      }
  }
  work->gathered.clear();
  work->gathered.shrink_to_fit();
}

}  // namespace sb::tools
