// tests/tools_light/light_box_world.h: hand-built closed worlds made of axis-aligned boxes,
// for the bounce and dirt tests (a room with walls, floor, ceiling and optional solid boxes
// inside, each surface with a chosen texture).
//
// Construction: the empty room interior is surrounded by a 16-unit solid shell; the tree is a
// k-d tree over the box planes (a region wholly inside a solid box becomes the shared solid
// leaf 0, a region touching no box an empty leaf, anything else is split on a box plane
// strictly inside it). Surfaces are given as rectangles on box planes facing into empty
// space; each is cut into one face per tree node lying on its plane (the node's region
// clips it), so the faces of a node are exactly the surface parts on its plane; parts with a
// solid box right in front of them are dropped.
// Textures: 16 x 16 miptex, every pixel one palette index (BoxWorld::textures).
// Every empty leaf marks every face (no vis: the light stage treats all faces as visible).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "tools/common/bsp_data.h"

namespace sb::tools::test {

struct Box {
  float mins[3], maxs[3];
};

// A surface: the side of plane axis = at, over [lo, hi] on the other two axes (in axis
// order), facing +axis (facing_positive) or -axis, with texture `texture`.
struct Rect {
  int axis;
  float at;
  bool facing_positive;
  float lo[2], hi[2];
  int texture;
};

struct BoxWorld {
  Box room;                     // the empty interior
  std::vector<Box> solids;      // solid boxes inside the room (not touching each other)
  std::vector<Rect> surfaces;   // every surface facing empty space
  std::vector<std::pair<std::string, uint8_t>> textures;  // name, palette index of every pixel
};

namespace box_detail {

struct Builder {
  BspData* b;
  std::vector<Box> solids;  // room shell + inner solids
  std::vector<std::array<float, 2>> split_planes;  // (axis, value) per node, by node index
  std::vector<Box> node_regions;

  static bool inside(const Box& r, const Box& s) {
    for (int a = 0; a < 3; ++a)
      if (r.mins[a] < s.mins[a] || r.maxs[a] > s.maxs[a]) return false;
    return true;
  }
  static bool overlaps(const Box& r, const Box& s) {
    for (int a = 0; a < 3; ++a)
      if (r.mins[a] >= s.maxs[a] || r.maxs[a] <= s.mins[a]) return false;
    return true;
  }
  int plane_index(int axis, float value) {
    for (size_t i = 0; i < b->planes.size(); ++i)
      if (b->planes[i].type == axis && b->planes[i].dist == value) return int(i);
    DPlane p = {};
    p.normal[axis] = 1;
    p.dist = value;
    p.type = axis;
    b->planes.push_back(p);
    return int(b->planes.size() - 1);
  }
  // Returns the child encoding: node index >= 0, or -(leaf + 1).
  int build(const Box& region) {
    for (const Box& s : solids)
      if (inside(region, s)) return -1;  // leaf 0, solid
    for (const Box& s : solids) {
      if (!overlaps(region, s)) continue;
      for (int a = 0; a < 3; ++a)
        for (float v : {s.mins[a], s.maxs[a]}) {
          if (!(v > region.mins[a] && v < region.maxs[a])) continue;
          int index = int(b->nodes.size());
          b->nodes.push_back(DNode{});
          split_planes.push_back({float(a), v});
          node_regions.push_back(region);
          Box front = region, back = region;
          front.mins[a] = v;
          back.maxs[a] = v;
          int f = build(front), k = build(back);
          DNode& n = b->nodes[size_t(index)];
          n.plane = plane_index(a, v);
          n.children[0] = f;
          n.children[1] = k;
          for (int c = 0; c < 3; ++c) {
            n.mins[c] = region.mins[c];
            n.maxs[c] = region.maxs[c];
          }
          return index;
        }
    }
    DLeaf l = {};
    l.contents = -1;  // empty
    l.visofs = -1;
    for (int c = 0; c < 3; ++c) {
      l.mins[c] = region.mins[c];
      l.maxs[c] = region.maxs[c];
    }
    b->leaves.push_back(l);
    return -int(b->leaves.size());
  }
};

inline void other_axes(int axis, int* u, int* v) {
  *u = axis == 0 ? 1 : 0;
  *v = axis == 2 ? 1 : 2;
}

}  // namespace box_detail

inline BspData build_box_world(const BoxWorld& world, const std::string& entities) {
  BspData b;
  b.format = BspFormat::Bsp29;
  b.entities = entities;
  box_detail::Builder bld{&b, {}, {}, {}};
  const Box& r = world.room;
  Box outer = r;
  for (int a = 0; a < 3; ++a) {
    outer.mins[a] -= 16;
    outer.maxs[a] += 16;
  }
  // Shell: six slabs around the room.
  for (int a = 0; a < 3; ++a) {
    Box lo = outer, hi = outer;
    lo.maxs[a] = r.mins[a];
    hi.mins[a] = r.maxs[a];
    bld.solids.push_back(lo);
    bld.solids.push_back(hi);
  }
  for (const Box& s : world.solids) bld.solids.push_back(s);
  DLeaf solid = {};
  solid.contents = -2;
  solid.visofs = -1;
  b.leaves.push_back(solid);
  bld.build(outer);

  // Surfaces cut along every solid's bounds, so each part is wholly covered or not.
  int u, v;
  std::vector<Rect> parts;
  for (const Rect& s : world.surfaces) {
    box_detail::other_axes(s.axis, &u, &v);
    std::vector<float> cu = {s.lo[0], s.hi[0]}, cv = {s.lo[1], s.hi[1]};
    for (const Box& sb : bld.solids) {
      for (float x : {sb.mins[u], sb.maxs[u]})
        if (x > s.lo[0] && x < s.hi[0]) cu.push_back(x);
      for (float x : {sb.mins[v], sb.maxs[v]})
        if (x > s.lo[1] && x < s.hi[1]) cv.push_back(x);
    }
    std::sort(cu.begin(), cu.end());
    cu.erase(std::unique(cu.begin(), cu.end()), cu.end());
    std::sort(cv.begin(), cv.end());
    cv.erase(std::unique(cv.begin(), cv.end()), cv.end());
    for (size_t i = 0; i + 1 < cu.size(); ++i)
      for (size_t j = 0; j + 1 < cv.size(); ++j) {
        Rect p = s;
        p.lo[0] = cu[i], p.hi[0] = cu[i + 1], p.lo[1] = cv[j], p.hi[1] = cv[j + 1];
        parts.push_back(p);
      }
  }

  // Faces, grouped by node.
  for (size_t n = 0; n < b.nodes.size(); ++n) {
    int axis = int(bld.split_planes[n][0]);
    float at = bld.split_planes[n][1];
    const Box& region = bld.node_regions[n];
    b.nodes[n].first_face = uint32_t(b.faces.size());
    for (const Rect& s : parts) {
      if (s.axis != axis || s.at != at) continue;
      box_detail::other_axes(axis, &u, &v);
      float lo0 = std::max(s.lo[0], region.mins[u]), hi0 = std::min(s.hi[0], region.maxs[u]);
      float lo1 = std::max(s.lo[1], region.mins[v]), hi1 = std::min(s.hi[1], region.maxs[v]);
      if (!(lo0 < hi0 && lo1 < hi1)) continue;
      // Parts covered by a solid on their facing side (e.g. a wall where a box touches it)
      // lie between two solids: no face.
      float probe[3];
      probe[axis] = at + (s.facing_positive ? 0.5f : -0.5f);
      probe[u] = 0.5f * (lo0 + hi0);
      probe[v] = 0.5f * (lo1 + hi1);
      bool covered = false;
      for (const Box& sb : bld.solids) {
        bool in = true;
        for (int c = 0; c < 3; ++c) in = in && probe[c] > sb.mins[c] && probe[c] < sb.maxs[c];
        covered = covered || in;
      }
      if (covered) continue;
      // Texture axes: the two other world axes (s along u, t along v).
      DTexInfo ti = {};
      ti.vecs[0][u] = 1;
      ti.vecs[1][v] = 1;
      ti.miptex = s.texture;
      b.texinfo.push_back(ti);
      DFace f = {};
      f.plane = bld.plane_index(axis, at);
      f.side = s.facing_positive ? 0 : 1;
      f.first_edge = int32_t(b.surfedges.size());
      f.num_edges = 4;
      f.texinfo = int32_t(b.texinfo.size() - 1);
      std::memset(f.styles, 255, 4);
      f.lightofs = -1;
      // Corners counter-clockwise seen from the facing side.
      float c[4][2] = {{lo0, lo1}, {hi0, lo1}, {hi0, hi1}, {lo0, hi1}};
      bool keep = s.facing_positive != (axis == 1);  // u x v is +axis for x, z; -axis for y
      uint32_t first_vertex = uint32_t(b.vertices.size() / 3);
      for (int k = 0; k < 4; ++k) {
        int kk = keep ? k : 3 - k;
        float p[3];
        p[axis] = at;
        p[u] = c[kk][0];
        p[v] = c[kk][1];
        b.vertices.insert(b.vertices.end(), p, p + 3);
      }
      if (b.edges.empty()) b.edges.push_back(DEdge{{0, 0}});
      for (uint32_t k = 0; k < 4; ++k) {
        b.edges.push_back(DEdge{{first_vertex + k, first_vertex + (k + 1) % 4}});
        b.surfedges.push_back(int32_t(b.edges.size() - 1));
      }
      b.faces.push_back(f);
    }
    b.nodes[n].num_faces = uint32_t(b.faces.size()) - b.nodes[n].first_face;
  }
  for (uint32_t f = 0; f < b.faces.size(); ++f) b.marksurfaces.push_back(f);
  for (size_t l = 1; l < b.leaves.size(); ++l) b.leaves[l].num_marksurfaces = uint32_t(b.marksurfaces.size());

  // Miptex lump: 16 x 16 textures of one palette index each.
  std::vector<uint8_t>& t = b.textures;
  auto put32 = [&t](uint32_t x) {
    for (int i = 0; i < 4; ++i) t.push_back(uint8_t(x >> (8 * i)));
  };
  put32(uint32_t(world.textures.size()));
  size_t table = t.size();
  for (size_t i = 0; i < world.textures.size(); ++i) put32(0);
  for (size_t i = 0; i < world.textures.size(); ++i) {
    uint32_t at = uint32_t(t.size());
    std::memcpy(&t[table + 4 * i], &at, 4);  // little-endian hosts (x86, arm)
    char name[16] = {};
    std::strncpy(name, world.textures[i].first.c_str(), 15);
    t.insert(t.end(), name, name + 16);
    put32(16);
    put32(16);
    uint32_t off = 40;
    for (int m = 0; m < 4; ++m) {
      put32(off);
      off += (16u >> m) * (16u >> m);
    }
    t.resize(at + off, world.textures[i].second);
  }

  DModel m = {};
  for (int a = 0; a < 3; ++a) {
    m.mins[a] = outer.mins[a];
    m.maxs[a] = outer.maxs[a];
  }
  m.headnode[0] = 0;
  m.headnode[1] = m.headnode[2] = m.headnode[3] = -1;
  m.visleafs = int32_t(b.leaves.size() - 1);
  m.first_face = 0;
  m.num_faces = int32_t(b.faces.size());
  b.models = {m};
  return b;
}

// The six inner surfaces of the room, with textures floor, ceiling, walls.
inline void add_room_surfaces(BoxWorld* w, int floor_tex, int ceiling_tex, int wall_tex) {
  const Box& r = w->room;
  int u, v;
  for (int a = 0; a < 3; ++a) {
    box_detail::other_axes(a, &u, &v);
    Rect lo = {a, r.mins[a], true, {r.mins[u], r.mins[v]}, {r.maxs[u], r.maxs[v]}, a == 2 ? floor_tex : wall_tex};
    Rect hi = {a, r.maxs[a], false, {r.mins[u], r.mins[v]}, {r.maxs[u], r.maxs[v]}, a == 2 ? ceiling_tex : wall_tex};
    w->surfaces.push_back(lo);
    w->surfaces.push_back(hi);
  }
}

}  // namespace sb::tools::test
