// tools/light/light_surface.cpp: surface lights: copies of "_surface" templates placed over
// the faces that carry the named texture (see light_entities.h).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "tools/light/light_entities.h"

namespace sb::tools {
namespace {

constexpr float kSpacing = 128.0f;      // between copies over a face
constexpr float kLiftOffSurface = 2.0f;  // copies sit this far in front of the face

std::string lower(const char* s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool inside(const std::vector<glm::vec3>& verts, const glm::vec3& normal, const glm::vec3& p) {
  size_t n = verts.size();
  glm::vec3 centre(0);
  for (const glm::vec3& v : verts) centre += v;
  centre /= float(n);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3 en = glm::cross(verts[(i + 1) % n] - verts[i], normal);
    if (glm::dot(centre - verts[i], en) > 0) en = -en;
    if (glm::dot(p - verts[i], en) > 0) return false;
  }
  return true;
}

}  // namespace

int expand_surface_lights(const BspWorld& w, LightSettings* settings) {
  if (settings->surface_templates.empty()) return 0;
  int added = 0;
  std::vector<std::string> names(w.num_textures);
  for (uint32_t t = 0; t < w.num_textures; ++t) names[t] = lower(w.textures[t].name);
  for (uint32_t f = 0; f < w.num_faces; ++f) {
    const Face& face = w.faces[f];
    const std::string& tex = names[w.texinfo[face.texinfo].texture];
    for (const LightSettings::SurfaceTemplate& tpl : settings->surface_templates) {
      if (tpl.texture != tex) continue;
      std::vector<glm::vec3> verts;
      glm::vec3 centre(0);
      for (uint32_t k = 0; k < face.num_edges; ++k) {
        int32_t se = w.surfedges[face.first_surfedge + k];
        uint32_t e = uint32_t(se < 0 ? -int64_t(se) : se);
        verts.push_back(w.vertices[se < 0 ? w.edges[e].v[1] : w.edges[e].v[0]]);
        centre += verts.back();
      }
      centre /= float(verts.size());
      glm::vec3 normal = w.planes[face.plane].normal * ((face.flags & kFacePlaneBack) ? -1.0f : 1.0f);
      // In-plane axes: along the first usable edge, and across it.
      glm::vec3 u(0);
      for (size_t i = 0; i < verts.size() && glm::dot(u, u) < 1e-6f; ++i) u = verts[(i + 1) % verts.size()] - verts[i];
      if (glm::dot(u, u) < 1e-6f) continue;
      u = glm::normalize(u);
      glm::vec3 v = glm::cross(normal, u);
      float umin = 1e30f, umax = -1e30f, vmin = 1e30f, vmax = -1e30f;
      for (const glm::vec3& p : verts) {
        float a = glm::dot(p - centre, u), b = glm::dot(p - centre, v);
        umin = std::min(umin, a), umax = std::max(umax, a), vmin = std::min(vmin, b), vmax = std::max(vmax, b);
      }
      int nu = std::max(1, int(std::ceil((umax - umin) / kSpacing)));
      int nv = std::max(1, int(std::ceil((vmax - vmin) / kSpacing)));
      if (nu * nv > 4096) nu = nv = 64;  // absurd faces: bounded
      int placed = 0;
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
          glm::vec3 p = centre + u * (umin + (i + 0.5f) * (umax - umin) / nu) + v * (vmin + (j + 0.5f) * (vmax - vmin) / nv);
          if (!inside(verts, normal, p)) continue;
          PointLight l = tpl.light;
          l.origin = p + normal * kLiftOffSurface;
          settings->lights.push_back(l);
          ++placed;
        }
      if (!placed) {
        PointLight l = tpl.light;
        l.origin = centre + normal * kLiftOffSurface;
        settings->lights.push_back(l);
        ++placed;
      }
      added += placed;
    }
  }
  return added;
}

}  // namespace sb::tools
