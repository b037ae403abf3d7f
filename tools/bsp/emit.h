// tools/bsp/emit.h: trees to BspData lumps.
//
// Hull 0: nodes in preorder (front child first); a node's faces are contiguous; every face
// is subdivided so that its texture extents stay within `subdivide` texels on both axes
// (sky and liquid faces excepted: they have no lightmap); all solid leaves share leaf 0;
// the other leaves are numbered in tree order (the world's first, so that world leaf i is
// PVS bit i - 1); marksurfaces list, per leaf, the faces in front of which it lies.
// Vertices are welded within 0.01 units (and snapped to integers within 0.01); an edge is
// reused only by one other face walking it the other way, so no edge has more than two faces.
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

struct EmitStats {
  int faces_before_subdivide = 0, faces_out = 0, subdivided = 0, new_edges_for_sharing = 0;
};

class Emitter {
 public:
  Emitter(BspData* bsp, const PlaneSet& planes, const TextureSet& textures, double subdivide)
      : bsp_(bsp), planes_(planes), textures_(textures), subdivide_(subdivide) {}

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

 private:
  int emit_node(const Tree& tree, int n, const std::vector<bool>& face_visible, const std::vector<int>& leaf_index,
                std::vector<std::vector<uint32_t>>* face_ids_of);
  void emit_face(const Face& f, std::vector<uint32_t>* out_ids);
  void emit_polygon(const Face& f, const Winding& w, std::vector<uint32_t>* out_ids);
  uint32_t vertex(const Vec3& v);
  int32_t edge(uint32_t a, uint32_t b);
  int emit_clip_node(const Tree& tree, int n);

  BspData* bsp_;
  const PlaneSet& planes_;
  const TextureSet& textures_;
  double subdivide_;
  std::map<int, int> plane_map_;
  std::unordered_map<int64_t, std::vector<uint32_t>> vertex_hash_;
  // (a, b) as walked by the face that created it -> edge index, while unused backwards.
  std::unordered_map<uint64_t, int32_t> open_edges_;
  EmitStats stats_;
};

}  // namespace sb::tools::bsp
