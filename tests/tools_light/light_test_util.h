// tests/tools_light/light_test_util.h: helpers for the light stage tests: the engine's view
// of a BspData, and a tiny hand-built world (a floor, optionally a hanging wall).
#pragma once
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "memory/memory_system.h"
#include "tools/common/bsp_data.h"

namespace sb::tools::test {

// Serialises a BspData and loads it with sb::load_bsp (every index checked).
class EngineView {
 public:
  explicit EngineView(const BspData& bsp) {
    std::vector<uint8_t> bytes;
    Status s = serialize_bsp(bsp, bsp.format, &bytes, nullptr);
    if (!s) {
      error_ = s.message();
      return;
    }
    size_t size = 64 * mem::kMiB + bytes.size() * 8;
    block_.reset(new uint8_t[size]);
    char err[256] = {};
    if (!memory_.init(block_.get(), size, err, sizeof err)) {
      error_ = err;
      return;
    }
    Result<BspWorld*> r = load_bsp("test.bsp", bytes.data(), bytes.size(), memory_.level, memory_.scratch);
    if (!r) {
      error_ = r.message();
      return;
    }
    world_ = r.value();
  }
  const BspWorld* world() const { return world_; }
  const std::string& error() const { return error_; }

 private:
  std::unique_ptr<uint8_t[]> block_;
  mem::MemorySystem memory_;
  BspWorld* world_ = nullptr;
  std::string error_;
};

// A floor face z = 0 over x 0..512, y 0..256 (texture s = x, t = y: a 33 x 17 light grid,
// grid point (gx, gy) at (16 gx, 16 gy)), seen from above. With `wall`, a solid slab
// x 240..272, z >= 16 spanning every y hangs over the floor (a 16-unit gap under it).
// Tree: node 0 z=0 (below: solid); node 1 x=240 (x<240: leaf 1); node 2 x=272 (x>272: leaf 2);
// node 3 z=16 (above: solid, below: leaf 3). Without the wall node 1's both sides are empty.
inline BspData make_floor_world(bool wall, const std::string& entities) {
  BspData b;
  b.format = BspFormat::Bsp29;
  b.entities = entities;
  b.planes = {{{0, 0, 1}, 0, 2}, {{1, 0, 0}, 240, 0}, {{1, 0, 0}, 272, 0}, {{0, 0, 1}, 16, 2}};
  // Miptex lump: one 16x16 texture "floor".
  {
    std::vector<uint8_t>& t = b.textures;
    auto put32 = [&t](uint32_t v) {
      for (int i = 0; i < 4; ++i) t.push_back(uint8_t(v >> (8 * i)));
    };
    put32(1);
    put32(8);
    size_t start = t.size();
    char name[16] = "floor";
    t.insert(t.end(), name, name + 16);
    put32(16);
    put32(16);
    uint32_t off = 40;
    for (int m = 0; m < 4; ++m) {
      put32(off);
      off += (16u >> m) * (16u >> m);
    }
    t.resize(start + off, 7);
  }
  b.vertices = {0, 0, 0, 512, 0, 0, 512, 256, 0, 0, 256, 0};
  b.edges = {{{0, 0}}, {{0, 1}}, {{1, 2}}, {{2, 3}}, {{3, 0}}};
  // Counter-clockwise seen from above (the front of plane z = 0).
  b.surfedges = {1, 2, 3, 4};
  DTexInfo ti = {};
  ti.vecs[0][0] = 1;
  ti.vecs[1][1] = 1;
  b.texinfo = {ti};
  DFace f = {};
  f.plane = 0;
  f.side = 0;
  f.first_edge = 0;
  f.num_edges = 4;
  f.texinfo = 0;
  std::memset(f.styles, 255, 4);
  f.lightofs = -1;
  b.faces = {f};
  auto leaf = [](int32_t contents, uint32_t marks) {
    DLeaf l = {};
    l.contents = contents;
    l.visofs = -1;
    l.mins[0] = -1024; l.mins[1] = -1024; l.mins[2] = -1024;
    l.maxs[0] = 1024; l.maxs[1] = 1024; l.maxs[2] = 1024;
    l.first_marksurface = 0;
    l.num_marksurfaces = marks;
    return l;
  };
  b.leaves = {leaf(-2, 0), leaf(-1, 1), leaf(-1, 1), leaf(-1, 1)};
  b.marksurfaces = {0};
  auto node = [](int32_t plane, int32_t front, int32_t back, uint32_t nfaces) {
    DNode n = {};
    n.plane = plane;
    n.children[0] = front;
    n.children[1] = back;
    for (int a = 0; a < 3; ++a) {
      n.mins[a] = -1024;
      n.maxs[a] = 1024;
    }
    n.first_face = 0;
    n.num_faces = nfaces;
    return n;
  };
  // Leaf child encoding: -(leaf + 1).
  b.nodes = {node(0, 1, -1, 1), node(1, 2, -2, 0), node(2, -3, wall ? 3 : -4, 0), node(3, -1, -4, 0)};
  if (!wall) b.nodes.pop_back();
  DModel m = {};
  for (int a = 0; a < 3; ++a) {
    m.mins[a] = -16;
    m.maxs[a] = 528;
  }
  m.headnode[0] = 0;
  m.headnode[1] = m.headnode[2] = m.headnode[3] = -1;
  m.visleafs = 3;
  m.first_face = 0;
  m.num_faces = 1;
  b.models = {m};
  return b;
}

}  // namespace sb::tools::test
