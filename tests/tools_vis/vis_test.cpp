// tests/tools_vis/vis_test.cpp: sbvis (tools/vis) on a hand-made map compiled by sbbsp's
// library and on LibreQuake's start.map: self and neighbour visibility, a bend that hides,
// the compressed rows decoded by the engine, and render_world unchanged by the PVS.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "engine/world/world.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/bsp/compile.h"
#include "tools/vis/vis.h"

namespace sb::test {
namespace {

using tools::vis::PortalFile;
using tools::vis::VisOptions;
using tools::vis::VisStats;

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"vistest.wad\"";

std::string wad_path() {
  static std::string p = [] {
    std::string path = bsp_scratch_dir() + "/vistest.wad";
    std::vector<uint8_t> w = make_wad({"wall", "floor", "sky1"});
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(w.data(), 1, w.size(), f);
    std::fclose(f);
    return path;
  }();
  return p;
}

// Room A (x 0..256, y 0..256), a corridor east (y 96..160) that bends north at x 576..640,
// and room B (x 448..768, y 640..896); z 0..128. No straight line joins A and B.
std::string bend_map() {
  wad_path();
  std::string b = room_brushes(0, 0, 0, 768, 896, 128, "wall");
  b += box_brush(256, 0, 0, 768, 96, 128, "wall");
  b += box_brush(256, 160, 0, 576, 640, 128, "wall");
  b += box_brush(0, 256, 0, 256, 896, 128, "wall");
  b += box_brush(256, 640, 0, 448, 896, 128, "wall");
  b += box_brush(640, 96, 0, 768, 640, 128, "wall");
  return entity(kWorld, b) + entity("\"classname\" \"info_player_start\"\n\"origin\" \"128 128 24\"") +
         entity("\"classname\" \"light\"\n\"origin\" \"608 768 64\"\n\"light\" \"300\"") +
         entity("\"classname\" \"light\"\n\"origin\" \"608 128 64\"\n\"light\" \"300\"");
}

std::string prt_of(const std::string& bsp) { return bsp.substr(0, bsp.size() - 4) + ".prt"; }

// Compiles `map_text` (or a map file), keeps an unvised copy "<name>_novis.bsp" and vises
// "<name>.bsp".
struct Vised {
  std::string bsp, novis;
  VisStats stats;
  Status status;
  PortalFile prt;
};

Vised compile_and_vis(const CompileRun& r, const VisOptions& opt) {
  Vised v;
  v.bsp = r.bsp_path;
  v.novis = r.bsp_path.substr(0, r.bsp_path.size() - 4) + "_novis.bsp";
  std::filesystem::copy_file(v.bsp, v.novis, std::filesystem::copy_options::overwrite_existing);
  v.status = tools::vis::run_vis(v.bsp, opt, &v.stats);
  if (v.status) v.status = tools::vis::read_prt(prt_of(v.bsp).c_str(), &v.prt);
  // The portals as run_vis used them (no portals into sky, leaf boxes).
  tools::BspData data;
  if (v.status) v.status = tools::read_bsp(v.bsp.c_str(), &data);
  if (v.status) tools::vis::prepare_portals(&v.prt, data, opt);
  return v;
}

bool sees(const BspWorld& w, int from, int to) {
  std::vector<uint8_t> row(pvs_row_bytes(w));
  if (!decompress_pvs(w, from, row.data(), row.size())) return true;
  return leaf_is_visible(row.data(), row.size(), to);
}

// Renders the same views with and without the PVS; returns the number of differing pixels.
size_t render_difference(const std::string& vised, const std::string& novis, const std::vector<ViewParams>& views,
                         int wdt, int hgt, std::string* err) {
  LoadedBsp a(vised), b(novis);
  if (!a.world() || !b.world()) {
    *err = a.world() ? b.error() : a.error();
    return 0;
  }
  std::vector<uint8_t> colormap = test_colormap();
  size_t diff = 0;
  std::vector<uint8_t> pa, pb, ca, cb;
  for (const ViewParams& v : views) {
    Status s1 = a.render(v, wdt, hgt, colormap.data(), &pa, &ca);
    Status s2 = b.render(v, wdt, hgt, colormap.data(), &pb, &cb);
    if (!s1 || !s2) {
      *err = s1 ? s2.message() : s1.message();
      return 0;
    }
    for (size_t i = 0; i < pa.size(); ++i) diff += pa[i] != pb[i];
  }
  return diff;
}

TEST(SbvisUnit, CompressionRoundTripsThroughTheEngineDecoder) {
  // Rows with long zero runs (> 255 bytes), isolated bytes and a trailing run.
  const size_t bytes = 700;
  std::vector<uint8_t> row(bytes, 0);
  row[0] = 0x81;
  row[300] = 0x10;
  row[301] = 0xff;
  row[699 - 40] = 0x02;
  std::vector<uint8_t> packed;
  tools::vis::compress_row(row.data(), bytes, &packed);
  EXPECT_LT(packed.size(), 20u);
  // Decode the way the engine reads it: through a BspWorld holding only what it needs.
  BspWorld w{};
  SubModel m{};
  m.visleafs = uint32_t(bytes * 8);
  Leaf leaves[2] = {};
  leaves[1].vis_offset = 0;
  w.models = &m;
  w.num_models = 1;
  w.leaves = leaves;
  w.num_leaves = 2;
  w.visdata = packed.data();
  w.visdata_size = uint32_t(packed.size());
  std::vector<uint8_t> out(bytes);
  ASSERT_TRUE(decompress_pvs(w, 1, out.data(), out.size()));
  EXPECT_EQ(out, row);
}

TEST(SbvisUnit, BadPortalFilesAreErrors) {
  PortalFile p;
  EXPECT_FALSE(tools::vis::parse_prt("x.prt", "PRT2\n1\n0\n", &p).is_ok());
  EXPECT_FALSE(tools::vis::parse_prt("x.prt", "PRT1\n2\n1\n4 0 5 (0 0 0 ) (0 1 0 ) (0 1 1 ) (0 0 1 )\n", &p).is_ok());
  EXPECT_FALSE(tools::vis::parse_prt("x.prt", "PRT1\n2\n1\n4 0 1 (0 0 0 ) (0 1 0 )\n", &p).is_ok());
  EXPECT_TRUE(tools::vis::parse_prt("x.prt", "PRT1\n2\n1\n4 0 1 (0 0 0 ) (0 1 0 ) (0 1 1 ) (0 0 1 )\n", &p).is_ok());
  EXPECT_EQ(p.num_leaves, 2);
  ASSERT_EQ(p.portals.size(), 1u);
  VisStats st;
  EXPECT_FALSE(tools::vis::run_vis(bsp_scratch_dir() + "/vis_missing.bsp", VisOptions(), &st).is_ok());
}

class SbvisBend : public ::testing::TestWithParam<bool> {};  // param: fast mode

TEST_P(SbvisBend, SelfNeighboursBendAndRendering) {
  const bool fast = GetParam();
  const std::string name = fast ? "vis_bend_fast" : "vis_bend_full";
  CompileRun r = compile_text(name, bend_map(), {wad_path()});
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  VisOptions opt;
  opt.fast = fast;
  opt.quiet = true;
  Vised v = compile_and_vis(r, opt);
  ASSERT_TRUE(v.status.is_ok()) << v.status.message();
  std::cout << "[ sbvis ] bend map (" << (fast ? "fast" : "full") << "): " << v.stats.leaves << " leaves, "
            << v.stats.portals << " portals, " << v.stats.mean_visible << " visible leaves per leaf\n";

  LoadedBsp b(v.bsp);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  ASSERT_EQ(int(w.models[0].visleafs), v.prt.num_leaves);
  ASSERT_GT(w.visdata_size, 0u);
  // Every row decodes, and every leaf sees itself and its portal neighbours.
  for (int l = 1; l <= v.prt.num_leaves; ++l) {
    std::vector<uint8_t> row(pvs_row_bytes(w));
    ASSERT_TRUE(decompress_pvs(w, l, row.data(), row.size())) << "leaf " << l;
    EXPECT_TRUE(leaf_is_visible(row.data(), row.size(), l)) << "leaf " << l;
  }
  for (const tools::vis::PrtPortal& p : v.prt.portals) {
    EXPECT_TRUE(sees(w, p.leaf[0] + 1, p.leaf[1] + 1));
    EXPECT_TRUE(sees(w, p.leaf[1] + 1, p.leaf[0] + 1));
  }
  // The two rooms: not visible to each other in full mode (the fast flood may be looser).
  int la = point_in_leaf(w, glm::vec3(128, 128, 64));
  int lb = point_in_leaf(w, glm::vec3(608, 768, 64));
  ASSERT_GT(la, 0);
  ASSERT_GT(lb, 0);
  ASSERT_NE(la, lb);
  if (!fast) {
    EXPECT_FALSE(sees(w, la, lb));
    EXPECT_FALSE(sees(w, lb, la));
    // No leaf of room A's far half sees any leaf of room B.
    for (float x = 16; x < 240; x += 32)
      for (float y = 16; y < 240; y += 32)
        EXPECT_FALSE(sees(w, point_in_leaf(w, glm::vec3(x, y, 64)), lb)) << x << " " << y;
  }
  // The PVS hides nothing that is drawn: identical pictures with and without it.
  std::vector<ViewParams> views = test_viewpoints(w, 8);
  const glm::vec3 eyes[] = {{128, 128, 64}, {40, 200, 100}, {300, 128, 64}, {608, 128, 64},
                            {608, 400, 64}, {608, 700, 64}, {500, 860, 30}, {740, 660, 100}};
  for (int i = 0; i < 8; ++i)
    for (float yaw = 0; yaw < 360; yaw += 90) {
      ViewParams vp;
      vp.origin = eyes[i];
      vp.yaw = yaw + 10.0f * float(i);
      vp.pitch = float(i % 3) * 10.0f - 10.0f;
      views.push_back(vp);
    }
  std::string err;
  size_t diff = render_difference(v.bsp, v.novis, views, 160, 100, &err);
  EXPECT_TRUE(err.empty()) << err;
  EXPECT_EQ(diff, 0u) << "pixels that differ with the PVS, over " << views.size() << " views";

  // The comparison can fail: a PVS where each leaf sees only itself changes the pictures.
  tools::BspData data;
  ASSERT_TRUE(tools::read_bsp(v.bsp.c_str(), &data).is_ok());
  const size_t rb = (size_t(v.prt.num_leaves) + 7) / 8;
  std::vector<uint8_t> self_only(size_t(v.prt.num_leaves) * rb, 0);
  for (int l = 0; l < v.prt.num_leaves; ++l) self_only[size_t(l) * rb + size_t(l / 8)] |= uint8_t(1u << (l % 8));
  ASSERT_TRUE(tools::vis::store_pvs(&data, v.prt.num_leaves, self_only, nullptr).is_ok());
  std::string broken = bsp_scratch_dir() + "/" + name + "_selfonly.bsp";
  ASSERT_TRUE(tools::write_bsp(broken.c_str(), data).is_ok());
  EXPECT_GT(render_difference(broken, v.novis, views, 160, 100, &err), 0u);
}

INSTANTIATE_TEST_SUITE_P(Modes, SbvisBend, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Fast" : "Full"; });

// Room A (x 0..1024, y 0..256) with rows of func_detail pillars, a straight corridor north
// (x 896..960, y 256..512) and room B (x 0..1024, y 512..1024); z 0..128. A line through the
// corridor runs at most 64 units east or west per 256 north, so the west part of A cannot see
// B. A's structural region west of the corridor holds every pillar: with one vis cluster per
// detail subtree, all its leaves share the row of the leaves next to the corridor, which do
// see B.
std::string detail_room_map() {
  wad_path();
  std::string b = room_brushes(0, 0, 0, 1024, 1024, 128, "wall");
  b += box_brush(0, 256, 0, 896, 512, 128, "wall");
  b += box_brush(960, 256, 0, 1024, 512, 128, "wall");
  std::string d;
  for (int x = 48; x < 880; x += 96)
    for (int y = 48; y < 240; y += 64) d += box_brush(x, y, 0, x + 16, y + 16, 128, "floor");
  return entity(kWorld, b) + entity("\"classname\" \"func_detail\"", d) +
         entity("\"classname\" \"info_player_start\"\n\"origin\" \"24 24 24\"") +
         entity("\"classname\" \"light\"\n\"origin\" \"512 768 64\"\n\"light\" \"300\"") +
         entity("\"classname\" \"light\"\n\"origin\" \"512 200 64\"\n\"light\" \"300\"");
}

// Leaves (BSP numbers) whose whole box lies in x < x_max, y < y_max.
std::vector<int> leaves_within(const BspWorld& w, float x_max, float y_max) {
  std::vector<int> out;
  for (int l = 1; l <= int(w.models[0].visleafs); ++l) {
    const auto& leaf = w.leaves[size_t(l)];
    if (leaf.contents != -1) continue;
    if (leaf.maxs.x <= x_max && leaf.maxs.y <= y_max) out.push_back(l);
  }
  return out;
}

// Param: 0 PRT2 (default clusters), 1 PRT1, 2 PRT2 with big clusters split (-clusterleaves 8).
class SbvisDetail : public ::testing::TestWithParam<int> {};

TEST_P(SbvisDetail, WestOfTheDetailRoomDoesNotSeeRoomB) {
  const bool clusters = GetParam() != 1;
  const int split = GetParam() == 2 ? 8 : tools::bsp::BspOptions().cluster_leaves;
  auto run = [&](const std::string& name, int cluster_leaves, Vised* out) {
    tools::bsp::BspOptions bo;
    bo.prt1_only = !clusters;
    bo.cluster_leaves = cluster_leaves;
    CompileRun r = compile_text(name, detail_room_map(), {wad_path()}, bo);
    ASSERT_TRUE(r.status.is_ok()) << r.status.message();
    ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
    ASSERT_EQ(r.report.prt_format, clusters ? "PRT2" : "PRT1");
    VisOptions opt;
    opt.quiet = true;
    *out = compile_and_vis(r, opt);
    ASSERT_TRUE(out->status.is_ok()) << out->status.message();
  };
  Vised v;
  run(GetParam() == 0 ? "vis_detail2" : GetParam() == 1 ? "vis_detail1" : "vis_detail2_split", split, &v);
  if (HasFatalFailure()) return;
  std::cout << "[ sbvis ] detail room (" << (clusters ? "PRT2" : "PRT1") << "): " << v.stats.leaves << " leaves, "
            << v.stats.clusters << " clusters, visible leaves per leaf " << v.stats.mean_visible << "\n";
  LoadedBsp b(v.bsp);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  const int lb = point_in_leaf(w, glm::vec3(512, 768, 64));
  const int lc = point_in_leaf(w, glm::vec3(928, 400, 64));  // in the corridor: sees B
  ASSERT_GT(lb, 0);
  EXPECT_TRUE(sees(w, lc, lb));
  const std::vector<int> west = leaves_within(w, 480, 256);
  ASSERT_GT(west.size(), 4u);
  for (int l : west) EXPECT_FALSE(sees(w, l, lb)) << "leaf " << l << " (west of room A) sees room B";
  // The pictures are the same with and without the PVS.
  std::vector<ViewParams> views = test_viewpoints(w, 8);
  const glm::vec3 eyes[] = {{40, 40, 64}, {300, 200, 64}, {900, 128, 64}, {928, 300, 64}, {928, 500, 64},
                            {512, 700, 64}, {100, 1000, 100}, {1000, 600, 30}};
  for (int i = 0; i < 8; ++i)
    for (float yaw = 0; yaw < 360; yaw += 90) {
      ViewParams vp;
      vp.origin = eyes[i];
      vp.yaw = yaw + 10.0f * float(i);
      views.push_back(vp);
    }
  std::string err;
  EXPECT_EQ(render_difference(v.bsp, v.novis, views, 160, 100, &err), 0u);
  EXPECT_TRUE(err.empty()) << err;
  if (GetParam() != 0) return;
  // The test can fail: with one cluster per detail subtree (-clusterleaves 0) and every
  // leaf given its cluster's row (no leaf boxes), west leaves share the row of leaves that
  // see B.
  Vised coarse;
  run("vis_detail2_coarse", 0, &coarse);
  if (HasFatalFailure()) return;
  LoadedBsp c(coarse.bsp);
  ASSERT_NE(c.world(), nullptr) << c.error();
  PortalFile cp;
  ASSERT_TRUE(tools::vis::read_prt(prt_of(coarse.bsp).c_str(), &cp).is_ok());
  VisOptions o;
  o.quiet = true;
  std::vector<uint8_t> rows;
  VisStats cs;
  ASSERT_TRUE(tools::vis::compute_pvs(cp, o, &rows, &cs).is_ok());
  const size_t rb = (size_t(cp.num_leaves) + 7) / 8;
  const int lbc = point_in_leaf(*c.world(), glm::vec3(512, 768, 64)) - 1;
  int seeing = 0;
  for (int l : leaves_within(*c.world(), 480, 256)) seeing += (rows[size_t(l - 1) * rb + size_t(lbc >> 3)] >> (lbc & 7)) & 1;
  EXPECT_GT(seeing, 0);
  EXPECT_LT(v.stats.mean_visible, cs.mean_visible);
}

INSTANTIATE_TEST_SUITE_P(Formats, SbvisDetail, ::testing::Values(0, 1, 2), [](const ::testing::TestParamInfo<int>& i) {
  return i.param == 0 ? "Prt2" : i.param == 1 ? "Prt1" : "Prt2SplitClusters";
});

// Rooms A (x 0..256) and B (x 512..768), y 0..256, z 0..256, with a block of sky between
// them. Sky is drawn opaque: A must not see B through it (with -transsky the portals
// through the sky brush join them).
TEST(SbvisSky, SkyBetweenRoomsIsOpaque) {
  wad_path();
  std::string b = room_brushes(0, 0, 0, 768, 256, 256, "wall");
  b += box_brush(256, 0, 0, 512, 256, 256, "sky1");
  std::string map = entity(kWorld, b) + entity("\"classname\" \"info_player_start\"\n\"origin\" \"128 128 24\"") +
                    entity("\"classname\" \"light\"\n\"origin\" \"128 128 200\"\n\"light\" \"300\"") +
                    entity("\"classname\" \"light\"\n\"origin\" \"640 128 200\"\n\"light\" \"300\"");
  CompileRun r = compile_text("vis_sky", map, {wad_path()});
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  VisOptions opt;
  opt.quiet = true;
  Vised v = compile_and_vis(r, opt);
  ASSERT_TRUE(v.status.is_ok()) << v.status.message();
  {
    LoadedBsp b1(v.bsp);
    ASSERT_NE(b1.world(), nullptr) << b1.error();
    const BspWorld& w = *b1.world();
    const int la = point_in_leaf(w, glm::vec3(128, 128, 200)), lb = point_in_leaf(w, glm::vec3(640, 128, 200));
    const int ls = point_in_leaf(w, glm::vec3(384, 128, 200));
    ASSERT_GT(la, 0);
    ASSERT_GT(lb, 0);
    ASSERT_EQ(w.leaves[size_t(ls)].contents, -6);  // the sky brush is a sky leaf
    EXPECT_FALSE(sees(w, la, lb));
    EXPECT_FALSE(sees(w, lb, la));
    std::vector<ViewParams> views = test_viewpoints(w, 8);
    for (float yaw = 0; yaw < 360; yaw += 45) {
      ViewParams vp;
      vp.origin = glm::vec3(128, 128, 200);
      vp.yaw = yaw;
      vp.pitch = 10;
      views.push_back(vp);
      vp.origin = glm::vec3(640, 128, 64);
      views.push_back(vp);
    }
    std::string err;
    EXPECT_EQ(render_difference(v.bsp, v.novis, views, 160, 100, &err), 0u);
    EXPECT_TRUE(err.empty()) << err;
  }
  // See-through sky joins the rooms (what the default used to do).
  std::filesystem::copy_file(v.novis, v.bsp, std::filesystem::copy_options::overwrite_existing);
  opt.trans_sky = true;
  VisStats st;
  ASSERT_TRUE(tools::vis::run_vis(v.bsp, opt, &st).is_ok());
  LoadedBsp b2(v.bsp);
  ASSERT_NE(b2.world(), nullptr) << b2.error();
  EXPECT_TRUE(sees(*b2.world(), point_in_leaf(*b2.world(), glm::vec3(128, 128, 200)),
                   point_in_leaf(*b2.world(), glm::vec3(640, 128, 200))));
  EXPECT_GT(st.mean_visible, v.stats.mean_visible);
}

TEST(SbvisReal, StartMapVisedAgreesAndIsDeterministic) {
  SB_REQUIRE_QUAKE_DATA();
  std::string src = quake_dir() + "/lq1/maps/src/misc/start.map";
  std::string out = bsp_scratch_dir() + "/vis_start.bsp";
  CompileRun r = compile_file(src, out);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  VisOptions opt;
  opt.quiet = true;
  opt.threads = 2;
  Vised v = compile_and_vis(r, opt);
  ASSERT_TRUE(v.status.is_ok()) << v.status.message();
  std::cout << "[ sbvis ] start (full, 2 threads): " << v.stats.leaves << " leaves, " << v.stats.portals
            << " portals, visible leaves per leaf " << v.stats.mean_visible << " (fast flood " << v.stats.mean_might
            << "; ericw-tools 65.1 over 524 leaves), visdata " << v.stats.visdata_bytes << " bytes, "
            << v.stats.seconds_total << " s\n";
  EXPECT_LT(v.stats.mean_visible, v.stats.mean_might);
  EXPECT_GE(v.stats.mean_visible, 1.0);

  // The same rows on one thread.
  std::vector<uint8_t> rows1, rows2;
  VisStats s1, s2;
  VisOptions o1 = opt;
  o1.threads = 1;
  ASSERT_TRUE(tools::vis::compute_pvs(v.prt, o1, &rows1, &s1).is_ok());
  ASSERT_TRUE(tools::vis::compute_pvs(v.prt, opt, &rows2, &s2).is_ok());
  EXPECT_EQ(rows1, rows2);

  LoadedBsp b(v.bsp, 96);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  for (int l = 1; l <= v.prt.num_leaves; ++l) {
    std::vector<uint8_t> row(pvs_row_bytes(w));
    ASSERT_TRUE(decompress_pvs(w, l, row.data(), row.size())) << "leaf " << l;
    const uint8_t* want = &rows2[size_t(l - 1) * row.size()];
    ASSERT_TRUE(std::equal(row.begin(), row.end(), want)) << "leaf " << l;
  }
  std::vector<ViewParams> views = test_viewpoints(w, 24);
  std::string err;
  size_t diff = render_difference(v.bsp, v.novis, views, 160, 100, &err);
  EXPECT_TRUE(err.empty()) << err;
  EXPECT_EQ(diff, 0u) << "pixels that differ with the PVS, over " << views.size() << " views";
}

}  // namespace
}  // namespace sb::test
