#include "tests/formats/formats_test_util.h"

#include <cmath>
#include <cstring>

namespace sb::test {

int check_world_invariants(const BspWorld& w) {
  int bad = 0;
  auto fail = [&](const char* what, uint32_t i) {
    if (++bad <= 5) ADD_FAILURE() << w.name << ": invariant '" << what << "' broken at " << i;
  };
  for (uint32_t i = 0; i < w.num_edges; ++i)
    if (w.edges[i].v[0] >= w.num_vertices || w.edges[i].v[1] >= w.num_vertices) fail("edge vertex", i);
  for (uint32_t i = 0; i < w.num_surfedges; ++i) {
    int64_t e = w.surfedges[i] < 0 ? -int64_t(w.surfedges[i]) : w.surfedges[i];
    if (uint64_t(e) >= w.num_edges) fail("surfedge", i);
  }
  uint32_t sink = 0;
  if (w.num_textures == 0 || w.placeholder_texture != w.num_textures - 1) fail("placeholder", 0);
  for (uint32_t i = 0; i < w.num_textures; ++i) {
    const Texture& t = w.textures[i];
    if (t.width < 16 || t.height < 16 || t.width % 16 || t.height % 16) fail("texture size", i);
    if (std::memchr(t.name, 0, sizeof t.name) == nullptr) fail("texture name", i);
    for (int m = 0; m < 4; ++m) {
      if (!t.mips[m]) { fail("texture mip", i); continue; }
      size_t bytes = size_t(t.width >> m) * (t.height >> m);
      sink += t.mips[m][0] + t.mips[m][bytes - 1];
    }
    if (t.anim_next >= int32_t(w.num_textures) || t.alternate >= int32_t(w.num_textures)) fail("texture anim", i);
  }
  for (uint32_t i = 0; i < w.num_texinfo; ++i) {
    if (w.texinfo[i].texture < 0 || uint32_t(w.texinfo[i].texture) >= w.num_textures) fail("texinfo texture", i);
    if (!(w.texinfo[i].mipadjust >= 1e-3f)) fail("texinfo mipadjust", i);
  }
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const Face& f = w.faces[i];
    if (f.plane >= w.num_planes || f.texinfo >= w.num_texinfo || f.num_edges < 3 || f.num_edges > kMaxFaceEdges ||
        uint64_t(f.first_surfedge) + f.num_edges > w.num_surfedges) {
      fail("face indices", i);
      continue;
    }
    if (f.extents[0] < 0 || f.extents[1] < 0 || f.extents[0] % 16 || f.extents[1] % 16) fail("face extents", i);
    if (f.light_offset != kNoLightmap) {
      int styles = 0;
      while (styles < kMaxLightStyles && f.styles[styles] != 255) ++styles;
      uint64_t area = uint64_t(f.extents[0] / 16 + 1) * (f.extents[1] / 16 + 1) * styles;
      if (f.light_offset < 0 || uint64_t(f.light_offset) + area > w.lightdata_size) {
        fail("face lightmap", i);
      } else if (area) {
        sink += w.lightdata[f.light_offset] + w.lightdata[f.light_offset + area - 1];
        if (w.lightdata_rgb) sink += w.lightdata_rgb[3 * (f.light_offset + area) - 1];
      }
    }
    if (f.draw_frame || f.visframe || f.cache[0].valid()) fail("face renderer state zeroed", i);
  }
  for (uint32_t i = 0; i < w.num_marksurfaces; ++i)
    if (w.marksurfaces[i] >= w.num_faces) fail("marksurface", i);
  for (uint32_t i = 0; i < w.num_leaves; ++i) {
    const Leaf& l = w.leaves[i];
    if (uint64_t(l.first_marksurface) + l.num_marksurfaces > w.num_marksurfaces) fail("leaf marksurfaces", i);
    if (l.vis_offset != -1 && (l.vis_offset < 0 || uint32_t(l.vis_offset) >= w.visdata_size)) fail("leaf visofs", i);
    if (l.parent < -1 || l.parent >= int32_t(w.num_nodes)) fail("leaf parent", i);
  }
  for (uint32_t i = 0; i < w.num_nodes; ++i) {
    const Node& n = w.nodes[i];
    if (n.plane >= w.num_planes || uint64_t(n.first_face) + n.num_faces > w.num_faces) fail("node", i);
    for (int k = 0; k < 2; ++k) {
      int32_t c = n.children[k];
      if (c >= 0 ? uint32_t(c) >= w.num_nodes : uint32_t(-1 - c) >= w.num_leaves) fail("node child", i);
      else if (c >= 0 && w.nodes[c].parent != int32_t(i)) fail("node parent", uint32_t(c));
    }
    // Parent chains end (depth bound).
    int32_t p = int32_t(i);
    int steps = 0;
    while (p >= 0 && steps <= kMaxTreeDepth + 1) p = w.nodes[p].parent, ++steps;
    if (steps > kMaxTreeDepth + 1) fail("node depth", i);
  }
  for (uint32_t i = 0; i < w.num_clipnodes; ++i)
    for (int k = 0; k < 2; ++k) {
      int32_t c = w.clipnodes[i].children[k];
      if (c >= int32_t(w.num_clipnodes) || c < kMinContents || w.clipnodes[i].plane >= w.num_planes) fail("clipnode", i);
    }
  if (w.num_models == 0) fail("models", 0);
  for (uint32_t i = 0; i < w.num_models; ++i) {
    const SubModel& m = w.models[i];
    if (m.headnode[0] < 0 || uint32_t(m.headnode[0]) >= w.num_nodes) fail("model headnode", i);
    if (uint64_t(m.first_face) + m.num_faces > w.num_faces) fail("model faces", i);
  }
  if (!w.entities || w.entities[w.entities_size] != 0 || std::strlen(w.entities) != w.entities_size) fail("entities", 0);
  volatile uint32_t keep = sink;
  (void)keep;
  return bad;
}

}  // namespace sb::test
