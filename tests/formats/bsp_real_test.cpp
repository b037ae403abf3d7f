// Real maps: every BSP in lq1/maps and testmaps loads, .lit files, long entity
// values, BSP2 / 2PSB conversions load to the same world, PVS and viewpoints.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "engine/formats/entities.h"
#include "engine/world/viewpoints.h"
#include "engine/world/world.h"
#include "tests/formats/formats_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

std::vector<std::string> all_maps() {
  std::vector<std::string> out;
  std::string q = quake_dir();
  if (q.empty()) return out;
  std::error_code ec;
  for (auto& e : std::filesystem::directory_iterator(q + "/lq1/maps", ec))
    if (e.path().extension() == ".bsp") out.push_back(e.path().string());
  for (auto& e : std::filesystem::recursive_directory_iterator(q + "/testmaps", ec))
    if (e.path().extension() == ".bsp") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

const char* version_name(BspVersion v) {
  return v == BspVersion::Bsp29 ? "BSP29" : v == BspVersion::Bsp2 ? "BSP2" : "2PSB";
}

TEST(BspReal, EveryMapLoads) {
  SB_REQUIRE_QUAKE_DATA();
  auto maps = all_maps();
  ASSERT_GE(maps.size(), 24u);
  TestArenas arenas;
  for (const std::string& path : maps) {
    auto bytes = read_file(path);
    std::string name = std::filesystem::path(path).filename().string();
    size_t mark = arenas.level.mark();
    auto t0 = std::chrono::steady_clock::now();
    auto r = load_bsp(name.c_str(), bytes.data(), bytes.size(), arenas.level, arenas.scratch);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_TRUE(r.is_ok()) << r.message();
    const BspWorld& w = *r.value();
    std::printf("%-22s %-5s faces %6u leaves %5u nodes %5u clipnodes %6u texinfo %5u textures %4u models %3u "
                "vis %7u light %8u edges>2 %4u missing %u  %.1f ms, %.1f MB\n",
                name.c_str(), version_name(w.version), w.num_faces, w.num_leaves, w.num_nodes, w.num_clipnodes,
                w.num_texinfo, w.num_textures, w.num_models, w.visdata_size, w.lightdata_size,
                w.edges_shared_by_more_than_two_faces, w.missing_textures, ms,
                double(arenas.level.used() - mark) / (1 << 20));
    EXPECT_EQ(check_world_invariants(w), 0) << name;
    EXPECT_EQ(arenas.scratch.used(), 0u);
    arenas.level.pop_to(mark);
  }
}

TEST(BspReal, LitFilesLoad) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  for (const char* map : {"start", "lq_e0m1"}) {
    std::string base = quake_dir() + "/lq1/maps/" + map;
    auto bsp = read_file(base + ".bsp"), lit = read_file(base + ".lit");
    auto r = load_bsp(map, bsp.data(), bsp.size(), arenas.level, arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    BspWorld& w = *r.value();
    Status st = load_lit(w, (std::string(map) + ".lit").c_str(), lit.data(), lit.size(), arenas.level);
    ASSERT_TRUE(st.is_ok()) << st.message();
    ASSERT_NE(w.lightdata_rgb, nullptr);
    EXPECT_EQ(lit.size(), 8 + 3 * size_t(w.lightdata_size));
    EXPECT_EQ(std::memcmp(w.lightdata_rgb, lit.data() + 8, 3 * size_t(w.lightdata_size)), 0);
    EXPECT_EQ(check_world_invariants(w), 0);
    // A truncated or foreign .lit is an error naming the file.
    Status bad = load_lit(w, "short.lit", lit.data(), lit.size() / 2, arenas.level);
    EXPECT_FALSE(bad.is_ok());
    EXPECT_NE(std::strstr(bad.message(), "short.lit"), nullptr) << bad.message();
    arenas.level.reset();
  }
}

TEST(BspReal, LongEntityValueSurvives) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  auto bsp = read_file(quake_dir() + "/lq1/maps/start.bsp");
  auto r = load_bsp("maps/start.bsp", bsp.data(), bsp.size(), arenas.level, arenas.scratch);
  ASSERT_TRUE(r.is_ok()) << r.message();
  const BspWorld& w = *r.value();
  // Independent scan of the raw text for the worldspawn "wad" value.
  const char* key = std::strstr(w.entities, "\"wad\"");
  ASSERT_NE(key, nullptr);
  const char* open = std::strchr(key + 5, '"');
  const char* close = std::strchr(open + 1, '"');
  size_t expected = size_t(close - open - 1);
  ASSERT_GT(expected, 127u);
  Entity world_entity;
  ASSERT_TRUE(find_entity(std::string_view(w.entities, w.entities_size), "worldspawn", &world_entity));
  std::string_view wad;
  ASSERT_TRUE(world_entity.find("wad", &wad));
  EXPECT_EQ(wad.size(), expected);
  EXPECT_EQ(wad, std::string_view(open + 1, expected));
  // Every entity parses, and there is exactly one worldspawn.
  EntityIterator it(w.entities, w.entities_size);
  Entity e;
  int count = 0, worldspawns = 0;
  while (it.next(&e)) ++count, worldspawns += e.classname() == "worldspawn";
  EXPECT_EQ(it.error(), nullptr);
  EXPECT_GT(count, 10);
  EXPECT_EQ(worldspawns, 1);
}

// ---- BSP29 -> BSP2 / 2PSB conversion (test-side writer) and comparison

std::vector<uint8_t> convert_bsp29(const std::vector<uint8_t>& in, BspVersion to) {
  auto rd16 = [&](size_t o) { uint16_t v; std::memcpy(&v, &in[o], 2); return v; };
  auto rdi16 = [&](size_t o) { int16_t v; std::memcpy(&v, &in[o], 2); return v; };
  auto rd32 = [&](size_t o) { int32_t v; std::memcpy(&v, &in[o], 4); return v; };
  std::vector<uint8_t> out(124, 0);
  std::memcpy(out.data(), to == BspVersion::Bsp2 ? "BSP2" : "2PSB", 4);
  auto put32 = [&](int32_t v) { uint8_t b[4]; std::memcpy(b, &v, 4); out.insert(out.end(), b, b + 4); };
  auto put16 = [&](int16_t v) { uint8_t b[2]; std::memcpy(b, &v, 2); out.insert(out.end(), b, b + 2); };
  auto putf = [&](float v) { uint8_t b[4]; std::memcpy(b, &v, 4); out.insert(out.end(), b, b + 4); };
  auto box = [&](size_t o) {
    for (int k = 0; k < 6; ++k) {
      if (to == BspVersion::Bsp2) putf(float(rdi16(o + 2 * k))); else put16(rdi16(o + 2 * k));
    }
  };
  int32_t num_nodes = rd32(4 + 8 * 5 + 4) / 24, num_clip = rd32(4 + 8 * 9 + 4) / 8;
  for (int lump = 0; lump < 15; ++lump) {
    size_t ofs = size_t(rd32(4 + 8 * lump)), len = size_t(rd32(8 + 8 * lump));
    while (out.size() % 4) out.push_back(0);
    size_t start = out.size();
    switch (lump) {
      case 5:  // nodes
        for (size_t r = ofs; r < ofs + len; r += 24) {
          put32(rd32(r));
          for (int k = 0; k < 2; ++k) {
            int32_t u = rd16(r + 4 + 2 * k);
            put32(u < num_nodes ? u : u - 65536);
          }
          box(r + 8);
          put32(rd16(r + 20));
          put32(rd16(r + 22));
        }
        break;
      case 7:  // faces
        for (size_t r = ofs; r < ofs + len; r += 20) {
          put32(rd16(r)); put32(rdi16(r + 2)); put32(rd32(r + 4)); put32(rd16(r + 8)); put32(rd16(r + 10));
          out.insert(out.end(), &in[r + 12], &in[r + 16]);
          put32(rd32(r + 16));
        }
        break;
      case 9:  // clipnodes
        for (size_t r = ofs; r < ofs + len; r += 8) {
          put32(rd32(r));
          for (int k = 0; k < 2; ++k) {
            int32_t u = rd16(r + 4 + 2 * k);
            put32(u < num_clip ? u : u - 65536);
          }
        }
        break;
      case 10:  // leaves
        for (size_t r = ofs; r < ofs + len; r += 28) {
          put32(rd32(r)); put32(rd32(r + 4));
          box(r + 8);
          put32(rd16(r + 20)); put32(rd16(r + 22));
          out.insert(out.end(), &in[r + 24], &in[r + 28]);
        }
        break;
      case 11:  // marksurfaces
        for (size_t r = ofs; r < ofs + len; r += 2) put32(rd16(r));
        break;
      case 12:  // edges
        for (size_t r = ofs; r < ofs + len; r += 2) put32(rd16(r));
        break;
      default:
        out.insert(out.end(), in.begin() + ofs, in.begin() + ofs + len);
    }
    int32_t o = int32_t(start), l = int32_t(out.size() - start);
    std::memcpy(&out[4 + 8 * lump], &o, 4);
    std::memcpy(&out[8 + 8 * lump], &l, 4);
  }
  return out;
}

TEST(BspReal, Bsp2And2psbConversionsLoadToTheSameWorld) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  auto bsp = read_file(quake_dir() + "/lq1/maps/start.bsp");
  auto r29 = load_bsp("start.bsp", bsp.data(), bsp.size(), arenas.level, arenas.scratch);
  ASSERT_TRUE(r29.is_ok()) << r29.message();
  const BspWorld& a = *r29.value();
  for (BspVersion v : {BspVersion::Bsp2, BspVersion::Bsp2rmq}) {
    auto conv = convert_bsp29(bsp, v);
    auto r = load_bsp("start2.bsp", conv.data(), conv.size(), arenas.level, arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    const BspWorld& b = *r.value();
    EXPECT_EQ(b.version, v);
    EXPECT_EQ(check_world_invariants(b), 0);
    ASSERT_EQ(a.num_faces, b.num_faces);
    ASSERT_EQ(a.num_nodes, b.num_nodes);
    ASSERT_EQ(a.num_leaves, b.num_leaves);
    ASSERT_EQ(a.num_clipnodes, b.num_clipnodes);
    ASSERT_EQ(a.num_edges, b.num_edges);
    ASSERT_EQ(a.num_marksurfaces, b.num_marksurfaces);
    EXPECT_EQ(a.edges_shared_by_more_than_two_faces, b.edges_shared_by_more_than_two_faces);
    for (uint32_t i = 0; i < a.num_faces; ++i) {
      const Face &fa = a.faces[i], &fb = b.faces[i];
      ASSERT_TRUE(fa.plane == fb.plane && fa.first_surfedge == fb.first_surfedge && fa.num_edges == fb.num_edges &&
                  fa.texinfo == fb.texinfo && fa.flags == fb.flags && fa.light_offset == fb.light_offset &&
                  fa.extents[0] == fb.extents[0] && fa.extents[1] == fb.extents[1] &&
                  fa.texture_mins[0] == fb.texture_mins[0] && fa.texture_mins[1] == fb.texture_mins[1])
          << "face " << i;
    }
    float pad = v == BspVersion::Bsp2 ? 1.0f : 0.0f;  // BSP2 boxes are float: not widened
    for (uint32_t i = 0; i < a.num_nodes; ++i) {
      ASSERT_EQ(a.nodes[i].children[0], b.nodes[i].children[0]);
      ASSERT_EQ(a.nodes[i].children[1], b.nodes[i].children[1]);
      ASSERT_EQ(a.nodes[i].parent, b.nodes[i].parent);
      ASSERT_EQ(a.nodes[i].mins.x + pad, b.nodes[i].mins.x);
      ASSERT_EQ(a.nodes[i].maxs.z - pad, b.nodes[i].maxs.z);
    }
    for (uint32_t i = 0; i < a.num_leaves; ++i) {
      ASSERT_EQ(a.leaves[i].contents, b.leaves[i].contents);
      ASSERT_EQ(a.leaves[i].vis_offset, b.leaves[i].vis_offset);
      ASSERT_EQ(a.leaves[i].first_marksurface, b.leaves[i].first_marksurface);
      ASSERT_EQ(a.leaves[i].num_marksurfaces, b.leaves[i].num_marksurfaces);
      ASSERT_EQ(std::memcmp(a.leaves[i].ambient, b.leaves[i].ambient, 4), 0);
    }
    for (uint32_t i = 0; i < a.num_clipnodes; ++i) {
      ASSERT_EQ(a.clipnodes[i].children[0], b.clipnodes[i].children[0]);
      ASSERT_EQ(a.clipnodes[i].children[1], b.clipnodes[i].children[1]);
    }
    for (uint32_t i = 0; i < a.num_marksurfaces; ++i) ASSERT_EQ(a.marksurfaces[i], b.marksurfaces[i]);
  }
}

TEST(BspReal, TexturesKindsFlagsAndAnimation) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  int sky = 0, turb = 0, animated = 0, back = 0;
  for (const char* map : {"start", "lq_e0m1", "lq_e1m1"}) {
    auto bsp = read_file(quake_dir() + "/lq1/maps/" + map + ".bsp");
    auto r = load_bsp(map, bsp.data(), bsp.size(), arenas.level, arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    const BspWorld& w = *r.value();
    for (uint32_t i = 0; i < w.num_textures; ++i) {
      const Texture& t = w.textures[i];
      if (t.anim_total) {
        ++animated;
        ASSERT_EQ(t.name[0], '+');
        // Following anim_next anim_total times returns to the start.
        int32_t k = int32_t(i);
        for (int s = 0; s < t.anim_total; ++s) k = w.textures[k].anim_next;
        EXPECT_EQ(k, int32_t(i)) << t.name;
      }
    }
    for (uint32_t i = 0; i < w.num_faces; ++i) {
      const Face& f = w.faces[i];
      const Texture& t = w.textures[w.texinfo[f.texinfo].texture];
      sky += (f.flags & kFaceSky) != 0;
      turb += (f.flags & kFaceTurb) != 0;
      back += (f.flags & kFacePlaneBack) != 0;
      EXPECT_EQ((f.flags & kFaceSky) != 0, t.kind == kTexSky);
      EXPECT_EQ((f.flags & kFaceTurb) != 0, t.name[0] == '*');
      if (t.kind != kTexNormal) {
        EXPECT_TRUE(w.texinfo[f.texinfo].flags & kTexSpecial);
      }
    }
    arenas.level.reset();
  }
  std::printf("sky faces %d, turb faces %d, back faces %d, animated textures %d\n", sky, turb, back, animated);
  EXPECT_GT(sky, 0);
  EXPECT_GT(turb, 0);
  EXPECT_GT(back, 0);
  EXPECT_GT(animated, 0);
}

TEST(World, PvsOfEveryLeaf) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  for (const char* map : {"start", "lq_e0m1"}) {
    auto bsp = read_file(quake_dir() + "/lq1/maps/" + map + ".bsp");
    auto r = load_bsp(map, bsp.data(), bsp.size(), arenas.level, arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    const BspWorld& w = *r.value();
    int leaves = int(w.models[0].visleafs);
    size_t row = pvs_row_bytes(w);
    ASSERT_GT(leaves, 0);
    std::vector<uint8_t> all(size_t(leaves + 1) * row);
    int with_vis = 0, sees_self = 0;
    long visible_sum = 0;
    for (int l = 1; l <= leaves; ++l) {
      bool from_data = decompress_pvs(w, l, &all[size_t(l) * row], row);
      EXPECT_EQ(from_data, w.leaves[l].vis_offset >= 0) << l;
      if (!from_data) continue;
      ++with_vis;
      sees_self += leaf_is_visible(&all[size_t(l) * row], row, l);
      for (int o = 1; o <= leaves; ++o) visible_sum += leaf_is_visible(&all[size_t(l) * row], row, o);
    }
    long asym = 0, pairs = 0;
    for (int a = 1; a <= leaves; ++a)
      for (int b = a + 1; b <= leaves; ++b) {
        bool ab = leaf_is_visible(&all[size_t(a) * row], row, b), ba = leaf_is_visible(&all[size_t(b) * row], row, a);
        pairs += ab || ba;
        asym += ab != ba;
      }
    std::printf("%s: %d leaves, %d with vis, %d see themselves, mean visible %.1f, asymmetric pairs %ld of %ld\n", map,
                leaves, with_vis, sees_self, with_vis ? double(visible_sum) / with_vis : 0.0, asym, pairs);
    EXPECT_GT(with_vis, leaves * 9 / 10);
    EXPECT_EQ(sees_self, with_vis);
    EXPECT_LT(asym, pairs / 20 + 1);  // vis is symmetric in practice
    // Leaf 0, no visdata and out-of-range leaves: all visible, never read past the end.
    std::vector<uint8_t> out(row + 3, 0x55);
    EXPECT_FALSE(decompress_pvs(w, 0, out.data(), out.size()));
    EXPECT_EQ(out[0], 0xff);
    EXPECT_EQ(out[row], 0);  // beyond the row: zeroed
    BspWorld truncated = w;
    int probe = 1;
    while (probe <= leaves && w.leaves[probe].vis_offset < 0) ++probe;
    truncated.visdata_size = uint32_t(w.leaves[probe].vis_offset) + 1;  // the row is cut after one byte
    std::vector<uint8_t> exact(truncated.visdata, truncated.visdata + truncated.visdata_size);
    truncated.visdata = exact.data();  // exact heap copy: ASan catches any read past it
    bool ok = decompress_pvs(truncated, probe, out.data(), row);
    if (!ok) {
      for (size_t i = 0; i < row; ++i) ASSERT_EQ(out[i], 0xff);
    }
    arenas.level.reset();
  }
}

TEST(World, ViewpointsLandInOpenLeaves) {
  SB_REQUIRE_QUAKE_DATA();
  TestArenas arenas;
  for (const char* map : {"start", "lq_e0m1", "lqdm2", "b_batt0"}) {
    auto bsp = read_file(quake_dir() + "/lq1/maps/" + map + ".bsp");
    auto r = load_bsp(map, bsp.data(), bsp.size(), arenas.level, arenas.scratch);
    ASSERT_TRUE(r.is_ok()) << r.message();
    const BspWorld& w = *r.value();
    ViewParams views[64], again[64];
    int n = collect_viewpoints(w, views, 64);
    int m = collect_viewpoints(w, again, 64);
    ASSERT_EQ(n, m);
    EXPECT_GT(n, 0) << map;
    for (int i = 0; i < n; ++i) {
      int leaf = point_in_leaf(w, views[i].origin);
      ASSERT_GE(leaf, 0);
      ASSERT_LT(uint32_t(leaf), w.num_leaves);
      EXPECT_NE(w.leaves[leaf].contents, kContentsSolid) << map << " viewpoint " << i;
      EXPECT_EQ(std::memcmp(&views[i], &again[i], sizeof views[i]), 0);
    }
    std::printf("%s: %d viewpoints, first at (%.0f %.0f %.0f) yaw %.0f\n", map, n, views[0].origin.x,
                views[0].origin.y, views[0].origin.z, views[0].yaw);
    if (std::strcmp(map, "start") == 0) {
      Entity start;
      ASSERT_TRUE(find_entity(std::string_view(w.entities, w.entities_size), "info_player_start", &start));
      glm::vec3 o;
      ASSERT_TRUE(entity_origin(start, &o));
      EXPECT_EQ(views[0].origin, o + glm::vec3(0, 0, 22));
      EXPECT_EQ(n, 64);
    }
    arenas.level.reset();
  }
}

}  // namespace
}  // namespace sb::test
