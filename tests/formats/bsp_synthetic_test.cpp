// A tiny BSP29 built in the test: exact checks of derived fields, placeholders,
// animation warnings, shared edges and the wording of errors.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/core/log.h"
#include "engine/formats/bsp.h"
#include "engine/formats/entities.h"
#include "engine/world/viewpoints.h"
#include "engine/world/world.h"
#include "tests/formats/formats_test_util.h"

namespace sb::test {
namespace {

struct Bytes {
  std::vector<uint8_t> b;
  template <class T>
  Bytes& put(T v) {
    uint8_t tmp[sizeof(T)];
    std::memcpy(tmp, &v, sizeof(T));
    b.insert(b.end(), tmp, tmp + sizeof(T));
    return *this;
  }
  Bytes& raw(const void* p, size_t n) {
    auto* c = static_cast<const uint8_t*>(p);
    b.insert(b.end(), c, c + n);
    return *this;
  }
};

struct FaceSpec {
  uint16_t plane = 0;
  int16_t side = 0;
  int32_t first_edge;
  uint16_t num_edges = 3;
  uint16_t texinfo;
  uint8_t styles[4] = {255, 255, 255, 255};
  int32_t lightofs = -1;
};

// Three triangles in the plane z = 0 sharing edge (v0, v1); one node, two leaves.
struct SynthBsp {
  std::string long_value = std::string(200, 'x');
  float texinfo_scale = 1.0f;
  std::vector<FaceSpec> faces;
  int16_t node_back_child = -1;  // leaf 0
  SynthBsp() {
    FaceSpec a{0, 0, 0, 3, 0, {0, 255, 255, 255}, 0};
    FaceSpec b{0, 1, 3, 3, 1};
    FaceSpec c{0, 0, 6, 3, 2};
    faces = {a, b, c};
  }

  std::vector<uint8_t> build() const {
    Bytes lumps[15];
    std::string ents = "{\n\"classname\" \"worldspawn\"\n\"message\" \"" + long_value +
                       "\"\n}\n{\n\"classname\" \"info_player_start\"\n\"origin\" \"16 16 32\"\n\"angle\" \"90\"\n}\n";
    lumps[0].raw(ents.data(), ents.size() + 1);
    lumps[1].put(0.0f).put(0.0f).put(1.0f).put(0.0f).put(int32_t(2));  // plane z = 0
    // textures: wall (pixels), -1, +0anim, +2anim (missing +1), sky1 without pixels
    const char* names[5] = {"wall", nullptr, "+0anim", "+2anim", "sky1"};
    Bytes tex;
    tex.put(int32_t(5));
    std::vector<int32_t> ofs;
    Bytes data;
    for (int i = 0; i < 5; ++i) {
      if (!names[i]) { ofs.push_back(-1); continue; }
      ofs.push_back(int32_t(4 + 4 * 5 + data.b.size()));
      char name[16] = {};
      std::strncpy(name, names[i], 15);
      data.raw(name, 16).put(uint32_t(16)).put(uint32_t(16));
      bool pixels = i != 4;
      uint32_t o = 40;
      for (int m = 0; m < 4; ++m) {
        data.put(pixels ? o : 0u);
        o += (16u >> m) * (16u >> m);
      }
      if (pixels)
        for (uint32_t k = 0; k < 340; ++k) data.put(uint8_t(k * 7 + i));
    }
    for (int32_t o : ofs) tex.put(o);
    tex.raw(data.b.data(), data.b.size());
    lumps[2] = tex;
    const float v[6][3] = {{0, 0, 0}, {64, 0, 0}, {64, 64, 0}, {0, -64, 0}, {32, 32, 0}, {0, 64, 0}};
    for (auto& p : v) lumps[3].put(p[0]).put(p[1]).put(p[2]);
    // nodes: plane 0, front leaf 1, back leaf per node_back_child, box, faces 0..3
    lumps[5].put(int32_t(0)).put(int16_t(-2)).put(node_back_child);
    for (int16_t x : {-64, -64, -64, 64, 64, 64}) lumps[5].put(x);
    lumps[5].put(uint16_t(0)).put(uint16_t(3));
    // texinfo 0 -> texture 0, 1 -> texture 1 (missing slot), 2 -> texture 9 (out of range)
    for (int32_t t : {0, 1, 9}) {
      lumps[6].put(texinfo_scale).put(0.0f).put(0.0f).put(0.0f).put(0.0f).put(texinfo_scale).put(0.0f).put(0.0f);
      lumps[6].put(t).put(int32_t(0));
    }
    for (const FaceSpec& f : faces) {
      lumps[7].put(f.plane).put(f.side).put(f.first_edge).put(f.num_edges).put(f.texinfo).raw(f.styles, 4);
      lumps[7].put(f.lightofs);
    }
    for (int i = 0; i < 25; ++i) lumps[8].put(uint8_t(100 + i));  // 5x5 lightmap of face 0
    // leaves: 0 solid, 1 empty with all three faces
    lumps[10].put(int32_t(-2)).put(int32_t(-1));
    for (int k = 0; k < 6; ++k) lumps[10].put(int16_t(0));
    lumps[10].put(uint16_t(0)).put(uint16_t(0)).put(uint32_t(0));
    lumps[10].put(int32_t(-1)).put(int32_t(-1));
    for (int16_t x : {-64, -64, 0, 64, 64, 64}) lumps[10].put(x);
    lumps[10].put(uint16_t(0)).put(uint16_t(3)).put(uint32_t(0));
    for (uint16_t m : {0, 1, 2}) lumps[11].put(m);
    // edges: 0 unused (a surfedge cannot say "edge 0 backwards"), 1 (v0,v1) 2 (v1,v2) 3 (v2,v0)
    // 4 (v0,v3) 5 (v3,v1) 6 (v1,v4) 7 (v4,v0). Face A: v0 v1 v2; B: v1 v0 v3; C: v0 v1 v4.
    const uint16_t e[8][2] = {{0, 0}, {0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 1}, {1, 4}, {4, 0}};
    for (auto& p : e) lumps[12].put(p[0]).put(p[1]);
    for (int32_t s : {1, 2, 3, -1, 4, 5, 1, 6, 7}) lumps[13].put(s);
    for (float x : {-64.f, -64.f, -64.f, 64.f, 64.f, 64.f, 0.f, 0.f, 0.f}) lumps[14].put(x);
    lumps[14].put(int32_t(0)).put(int32_t(-1)).put(int32_t(-1)).put(int32_t(-1));
    lumps[14].put(int32_t(1)).put(int32_t(0)).put(int32_t(3));

    Bytes out;
    out.put(int32_t(29));
    size_t pos = 4 + 15 * 8;
    for (auto& l : lumps) {
      out.put(int32_t(pos)).put(int32_t(l.b.size()));
      pos += (l.b.size() + 3) & ~size_t(3);
    }
    for (auto& l : lumps) {
      out.raw(l.b.data(), l.b.size());
      while (out.b.size() % 4) out.b.push_back(0);
    }
    return out.b;
  }
};

Result<BspWorld*> load(TestArenas& a, const std::vector<uint8_t>& bytes) {
  return load_bsp("maps/synth.bsp", bytes.data(), bytes.size(), a.level, a.scratch);
}

struct CapturedLog {
  static void sink(void* user, LogLevel level, const char* line) {
    if (level == LogLevel::Warning) static_cast<CapturedLog*>(user)->warnings.push_back(line);
  }
  CapturedLog() { set_log_sink(sink, this); }
  ~CapturedLog() { set_log_sink(nullptr, nullptr); }
  std::vector<std::string> warnings;
};

TEST(BspSynthetic, DerivedFieldsPlaceholdersAndSharedEdges) {
  TestArenas a(8u << 20, 1u << 20);
  SynthBsp s;
  CapturedLog log;
  auto r = load(a, s.build());
  ASSERT_TRUE(r.is_ok()) << r.message();
  // One warning for the missing textures, one for the broken animation.
  ASSERT_EQ(log.warnings.size(), 2u);
  EXPECT_NE(log.warnings[0].find("'+0anim'"), std::string::npos) << log.warnings[0];
  EXPECT_NE(log.warnings[1].find("maps/synth.bsp: 3 missing textures"), std::string::npos) << log.warnings[1];
  const BspWorld& w = *r.value();
  EXPECT_EQ(check_world_invariants(w), 0);
  EXPECT_EQ(w.num_faces, 3u);
  EXPECT_EQ(w.edges_shared_by_more_than_two_faces, 1u);  // edge 1 is used by all three faces
  const Face& fa = w.faces[0];
  EXPECT_EQ(fa.texture_mins[0], 0);
  EXPECT_EQ(fa.texture_mins[1], 0);
  EXPECT_EQ(fa.extents[0], 64);
  EXPECT_EQ(fa.extents[1], 64);
  EXPECT_EQ(fa.light_offset, 0);
  EXPECT_EQ(fa.flags, 0);
  EXPECT_EQ(w.faces[1].flags, kFacePlaneBack | kFaceMissingTexture);
  EXPECT_EQ(w.faces[1].texture_mins[1], -64);
  EXPECT_EQ(w.faces[2].flags, kFaceMissingTexture);
  EXPECT_EQ(w.texinfo[2].texture, int32_t(w.placeholder_texture));
  EXPECT_FLOAT_EQ(w.texinfo[0].mipadjust, 1.0f);
  EXPECT_EQ(w.num_textures, 6u);
  EXPECT_EQ(w.placeholder_texture, 5u);
  EXPECT_STREQ(w.textures[0].name, "wall");
  EXPECT_EQ(w.textures[0].mips[3][0], uint8_t(7 * 336));  // last mip starts at pixel byte 336
  EXPECT_EQ(w.textures[4].kind, kTexSky);                  // placeholder keeps the name and kind
  EXPECT_EQ(w.textures[4].width, 16u);
  EXPECT_EQ(w.missing_textures, 3u);  // -1 slot, sky1 without pixels, texinfo 2 out of range
  EXPECT_EQ(w.textures[2].anim_total, 0);  // +0anim +2anim: frame 1 missing -> not animated
  EXPECT_EQ(w.textures[2].anim_next, -1);
  EXPECT_EQ(w.planes[0].type, 2);
  EXPECT_EQ(w.planes[0].signbits, 0);
  EXPECT_EQ(w.nodes[0].parent, -1);
  EXPECT_EQ(w.leaves[1].parent, 0);
  EXPECT_EQ(w.nodes[0].mins.x, -65.0f);  // widened integer box
  // Entities: a 200-character value survives.
  Entity e;
  ASSERT_TRUE(find_entity(std::string_view(w.entities, w.entities_size), "worldspawn", &e));
  std::string_view msg;
  ASSERT_TRUE(e.find("message", &msg));
  EXPECT_EQ(msg.size(), 200u);
  // World queries: above the plane is leaf 1, below is the solid leaf 0.
  EXPECT_EQ(point_in_leaf(w, glm::vec3(1, 1, 10)), 1);
  EXPECT_EQ(point_in_leaf(w, glm::vec3(1, 1, -10)), 0);
  uint8_t row[4] = {0, 0, 0, 0};
  EXPECT_FALSE(decompress_pvs(w, 1, row, sizeof row));  // no visdata: all visible
  EXPECT_TRUE(leaf_is_visible(row, pvs_row_bytes(w), 1));
  ViewParams views[8];
  int n = collect_viewpoints(w, views, 8);
  ASSERT_EQ(n, 4);  // the start point and its three turns (no pair for a midpoint)
  EXPECT_EQ(views[0].origin, glm::vec3(16, 16, 54));
  EXPECT_EQ(views[0].yaw, 90.0f);
  EXPECT_EQ(views[1].yaw, 180.0f);
  EXPECT_EQ(views[3].yaw, 0.0f);
}

void expect_error(TestArenas& a, const std::vector<uint8_t>& bytes, std::initializer_list<const char*> parts) {
  size_t mark = a.level.mark();
  auto r = load(a, bytes);
  ASSERT_FALSE(r.is_ok());
  EXPECT_EQ(a.level.mark(), mark) << "level arena not restored";
  EXPECT_EQ(a.scratch.used(), 0u);
  EXPECT_EQ(std::strncmp(r.message(), "maps/synth.bsp: ", 16), 0) << r.message();
  for (const char* p : parts) EXPECT_NE(std::strstr(r.message(), p), nullptr) << "'" << p << "' not in: " << r.message();
}

TEST(BspSynthetic, ErrorsNameFileLumpEntryAndField) {
  TestArenas a(8u << 20, 1u << 20);
  {
    SynthBsp s;
    s.faces[0].texinfo = 9999;
    expect_error(a, s.build(), {"lump 'faces' entry 0 field 'texinfo' = 9999 out of range (0..2)"});
  }
  {
    SynthBsp s;
    s.faces[0].lightofs = 1;  // 25 bytes from 1 runs past 25
    expect_error(a, s.build(), {"lump 'faces' entry 0 field 'lightofs' = 1", "runs past lump 'lighting' (25 bytes)"});
  }
  {
    SynthBsp s;
    s.faces[2].num_edges = 2;
    expect_error(a, s.build(), {"lump 'faces' entry 2 field 'num_edges' = 2"});
  }
  {
    SynthBsp s;
    s.faces[1].first_edge = 7;  // 7..9 past 9 surfedges
    expect_error(a, s.build(), {"lump 'faces' entry 1 field 'first_edge' = 7"});
  }
  {
    SynthBsp s;
    s.faces[0].first_edge = 1;  // surfedges 2, 3, -1: v1 v2, v2 v0, then v1 v0: not a loop
    expect_error(a, s.build(), {"lump 'faces' entry 0", "not closed"});
  }
  {
    SynthBsp s;
    s.texinfo_scale = 64.0f;  // s spans 0..4096 texels
    expect_error(a, s.build(), {"lump 'faces' entry 0", "extents 4096x4096", "exceed 2048"});
  }
  {
    SynthBsp s;
    s.node_back_child = -10;  // leaf 9 of 2
    expect_error(a, s.build(), {"lump 'nodes' entry 0 field 'children[1]'", "leaf 9"});
  }
  {
    SynthBsp s;
    auto bytes = s.build();
    int32_t bad_len = 21;  // planes: not a multiple of 20
    std::memcpy(&bytes[4 + 8 * 1 + 4], &bad_len, 4);
    expect_error(a, bytes, {"lump 'planes'", "not a multiple of 20"});
    bytes = s.build();
    int32_t bad_ofs = int32_t(bytes.size());
    std::memcpy(&bytes[4 + 8 * 7], &bad_ofs, 4);
    expect_error(a, bytes, {"lump 'faces'", "outside the file"});
    bytes = s.build();
    bytes[0] = 30;
    expect_error(a, bytes, {"header field 'version' = 30"});
  }
}

}  // namespace
}  // namespace sb::test
