// tools/bsp/emit.h: trees to BspData lumps.
//
// Hull 0: nodes in preorder (front child first); a node's faces are contiguous; every face
// is subdivided so that its texture extents stay within `subdivide` texels on both axes
// (sky and liquid faces excepted: they have no lightmap); all solid leaves share leaf 0;
// the other leaves are numbered in tree order (the world's first, so that world leaf i is
// PVS bit i - 1); marksurfaces list, per leaf, the faces in front of which it lies (a face
// cut into pieces marks each piece only in the leaves that piece touches).
// Vertices are welded within 0.01 units (and snapped to integers within 0.01); an edge is
// reused only by one other face walking it the other way, so no edge has more than two faces.
// T-junctions (with `fix_tjunctions`, per model): every vertex of the model's faces that lies
// inside another of its face edges (within kTjuncEpsilon of the line, more than 0.05 units
// from both ends) is inserted into that edge, so that neighbouring faces share their vertices
// and the renderer shows no cracks; a face that grows beyond kMaxFaceVertices is cut into
// pieces along chords between its vertices.
// Faces get lightofs -1 and styles 255 (the light stage fills them).
// Clip hulls: clipnodes in preorder; children are clipnode indices or contents.
#pragma once
#include <map>
#include <unordered_map>
#include <vector>

#include "tools/bsp/textures.h"
#include "tools/bsp/tree.h"
#include "tools/common/bsp_data.h"

namespace sb::tools::bsp {

constexpr double kTjuncEpsilon = 0.03;
constexpr size_t kMaxFaceVertices = 64;

struct EmitStats {
  int faces_before_subdivide = 0, faces_out = 0, subdivided = 0, new_edges_for_sharing = 0;
  int tjunc_vertices = 0;     // vertices inserted into face edges
  int tjunc_face_splits = 0;  // extra faces made by cutting faces over kMaxFaceVertices
};

class Emitter {
 public:
  Emitter(BspData* bsp, const PlaneSet& planes, const TextureSet& textures, double subdivide,
          bool fix_tjunctions = true)
      : bsp_(bsp), planes_(planes), textures_(textures), subdivide_(subdivide), fix_tjunctions_(fix_tjunctions) {}

  // Adds the shared solid leaf 0 and edge 0; call once before any model.
  void begin();
  // Emits a hull-0 tree (faces already pruned). `leaf_index` receives, per tree node, the
  // output leaf index (0 for solid leaves, -1 for nodes). Returns the output head node.
  int emit_hull0(const Tree& tree, const std::vector<bool>& face_visible,
                 const std::vector<std::vector<int>>& leaves_of_face, std::vector<int>* leaf_index, int* first_face,
                 int* num_faces);
  // Emits a clip tree; returns the head clipnode index or a contents value.
  int emit_clip(const Tree& tree);

  int plane_index(int canonical);
  const EmitStats& stats() const { return stats_; }
  // Per output face (in BspData::faces order): the csg Face::attr it came from.
  const std::vector<int>& face_attrs() const { return face_attr_; }

 private:
  using Polys = std::vector<std::vector<uint32_t>>;  // vertex index lists of one tree face
  int emit_node(const Tree& tree, int n, const std::vector<bool>& face_visible, const std::vector<int>& leaf_index,
                const std::vector<Polys>& polys, std::vector<std::vector<uint32_t>>* face_ids_of);
  // Subdivides a tree face and welds its vertices (no lump written yet).
  void face_polygons(const Face& f, Polys* out);
  void add_polygon(const Winding& w, Polys* out);
  void write_face(const Face& f, const std::vector<uint32_t>& vs, std::vector<uint32_t>* out_ids);
  void fix_tjunctions(std::vector<Polys>* polys);
  uint32_t vertex(const Vec3& v);
  int32_t edge(uint32_t a, uint32_t b);
  int emit_clip_node(const Tree& tree, int n);

  BspData* bsp_;
  std::vector<int> face_attr_;
  const PlaneSet& planes_;
  const TextureSet& textures_;
  double subdivide_;
  bool fix_tjunctions_;
  std::map<int, int> plane_map_;
  std::unordered_map<int64_t, std::vector<uint32_t>> vertex_hash_;
  // (a, b) as walked by the face that created it -> edge index, while unused backwards.
  std::unordered_map<uint64_t, int32_t> open_edges_;
  EmitStats stats_;
};

}  // namespace sb::tools::bsp
