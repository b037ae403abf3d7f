// tools/light/light_attrs.h: what the light stage does with the per-face attributes of brush
// entities (tools/common/face_attrs.h, from sbbsp's .faceattr side file).
//
//   Shadows: solid world leaves block light (light_trace.h), so worldspawn, func_group,
//     func_detail and func_detail_wall cast shadows as before. Faces that are not solid in the
//     world tree cast none unless their entity says so: brush models (func_door, func_wall,
//     ...) and func_detail_illusionary with "_shadow" "1" become occluder polygons that block
//     every shadow and sun ray ("_shadow" implies self-shadowing); "_selfshadow" "1" makes the
//     entity's faces block rays towards its own faces only. Dirt and bounce rays ignore them.
//   Minimum light: "_minlight" replaces the worldspawn minimum on that entity's faces (style
//     0 floor, in output units), coloured by "_minlight_color" in the .lit (the monochrome
//     byte gets the brightest channel).
//   "_lightignore" "1": the faces get no light and no bounce, only their minimum light.
//   Phong: faces with a phong angle get, for lighting only, a normal interpolated across the
//     face from vertex normals: at each vertex the corner-angle-weighted mean of the normals
//     of the phong faces of the same BSP model sharing that vertex whose normal lies within
//     the face's phong angle of its own.
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"
#include "tools/common/face_attrs.h"
#include "tools/light/light_trace.h"

namespace sb::tools {

// Polygons that block light without being solid in the world tree, grouped by entity.
class Occluders {
 public:
  // Collects the occluding faces of `attrs` (one per world face; empty: none).
  void build(const BspWorld& w, const LineTracer& tracer, const std::vector<FaceAttr>& attrs);
  bool empty() const { return groups_.empty(); }
  size_t polygons() const { return polys_.size(); }
  // True when a polygon blocks the segment a -> b for a receiving face of entity `receiver`
  // (0: no entity attributes).
  bool blocks(const glm::vec3& a, const glm::vec3& b, uint32_t receiver) const;
  // The groups that may block segments lying inside the box mins..maxs towards a face of
  // entity `receiver` (into *out, cleared first); blocks_among tests only those.
  void candidates(const glm::vec3& mins, const glm::vec3& maxs, uint32_t receiver, std::vector<uint32_t>* out) const;
  bool blocks_among(const glm::vec3& a, const glm::vec3& b, const std::vector<uint32_t>& groups) const;

 private:
  struct Poly {
    glm::vec3 normal{0};
    float dist = 0;
    uint32_t first = 0, count = 0;  // into verts_ / edge_normals_
    glm::vec3 mins{0}, maxs{0};
  };
  struct Group {
    uint32_t entity = 0;
    bool all = false;  // blocks rays towards every face (else only the entity's own faces)
    glm::vec3 mins{0}, maxs{0};
    uint32_t first = 0, count = 0;  // into polys_
  };
  bool group_blocks(const Group& g, const glm::vec3& a, const glm::vec3& b) const;
  std::vector<glm::vec3> verts_, edge_normals_;
  std::vector<Poly> polys_;
  std::vector<Group> groups_;
};

// Phong vertex normals per face (empty for faces without phong).
class PhongNormals {
 public:
  void build(const BspWorld& w, const std::vector<FaceAttr>& attrs);
  bool has(uint32_t face) const { return face < first_.size() && first_[face] != UINT32_MAX; }
  // Normal at point p on face `face` (whose polygon is `verts`, flat normal `flat`):
  // vertex normals blended over the fan triangle (centroid, v_i, v_i+1) holding p.
  glm::vec3 normal_at(uint32_t face, const std::vector<glm::vec3>& verts, const glm::vec3& flat,
                      const glm::vec3& p) const;
  size_t faces() const { return count_; }

 private:
  std::vector<uint32_t> first_;  // per face: index into normals_ (UINT32_MAX: none)
  std::vector<glm::vec3> normals_;
  size_t count_ = 0;
};

}  // namespace sb::tools
