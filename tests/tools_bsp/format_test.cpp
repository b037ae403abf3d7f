// tests/tools_bsp/format_test.cpp: sbbsp's output format options: -bsp2 (BspOptions::format =
// Bsp2) writes BSP2 that the engine loads and draws pixel for pixel like the BSP29 output;
// -2psb likewise; -bsp29 fails with an error naming the BSP29 limit a map exceeds, where the
// default (Auto) falls back to BSP2.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"

namespace sb::test {
namespace {

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"bsptest_fmt.wad\"";

void write_wad() {
  static bool done = [] {
    std::vector<uint8_t> w = make_wad({"wall", "floor", "door"});
    return write_text_file(bsp_scratch_dir() + "/bsptest_fmt.wad", std::string(w.begin(), w.end()));
  }();
  (void)done;
}

// Two rooms side by side (a doorway between them), a door submodel and a light, shifted by dx.
std::string rooms_map(double dx) {
  write_wad();
  std::string world = room_brushes(dx - 64, -64, 0, dx + 64, 64, 128, "wall", /*open_east_wall=*/true);
  world += box_brush(dx + 64, -80, 0, dx + 80, -24, 128, "wall") + box_brush(dx + 64, 24, 0, dx + 80, 80, 128, "wall");
  world += box_brush(dx + 64, -24, 96, dx + 80, 24, 128, "wall");
  world += room_brushes(dx + 80, -64, 0, dx + 208, 64, 128, "floor");
  char keys[256];
  std::snprintf(keys, sizeof keys, "\"classname\" \"info_player_start\"\n\"origin\" \"%g 0 24\"", dx);
  std::string door = entity("\"classname\" \"func_door\"", box_brush(dx + 160, -16, 0, dx + 176, 16, 96, "door"));
  return entity(kWorld, world) + entity(keys) + door;
}

int file_version(const std::string& path) {
  std::vector<uint8_t> b = read_file_bytes(path);
  if (b.size() < 4) return 0;
  return int(b[0]) | int(b[1]) << 8 | int(b[2]) << 16 | int(b[3]) << 24;
}

constexpr int kVersionBsp2 = 'B' | 'S' << 8 | 'P' << 16 | '2' << 24;
constexpr int kVersion2psb = '2' | 'P' << 8 | 'S' << 16 | 'B' << 24;

// Renders the same views of both files and counts differing pixels.
void expect_same_pictures(LoadedBsp& a, LoadedBsp& b, int count, const std::string& what) {
  std::vector<uint8_t> colormap = test_colormap();
  std::vector<ViewParams> views = test_viewpoints(*a.world(), count);
  ASSERT_GE(views.size(), 3u) << what;
  std::vector<uint8_t> pa, ca, pb, cb;
  for (size_t i = 0; i < views.size(); ++i) {
    ASSERT_TRUE(a.render(views[i], 160, 100, colormap.data(), &pa, &ca).is_ok()) << what;
    ASSERT_TRUE(b.render(views[i], 160, 100, colormap.data(), &pb, &cb).is_ok()) << what;
    size_t diff = 0;
    for (size_t p = 0; p < pa.size(); ++p) diff += pa[p] != pb[p];
    EXPECT_EQ(diff, 0u) << what << ": view " << i << " differs in " << diff << " pixels";
    for (uint8_t c : cb) EXPECT_EQ(c, 1u) << what << ": coverage";
  }
}

void compare_formats(const std::string& name, const std::string& map_text, const std::string& map_file,
                     int views) {
  tools::bsp::BspOptions o29, o2, orm;
  o29.format = tools::BspFormat::Bsp29;
  o2.format = tools::BspFormat::Bsp2;
  orm.format = tools::BspFormat::Bsp2rmq;
  CompileRun r29, r2, rrm;
  if (map_file.empty()) {
    r29 = compile_text(name + "_29", map_text, {}, o29);
    r2 = compile_text(name + "_bsp2", map_text, {}, o2);
    rrm = compile_text(name + "_2psb", map_text, {}, orm);
  } else {
    auto run = [&](tools::bsp::BspOptions o, const std::string& suffix) {
      CompileRun r;
      r.bsp_path = bsp_scratch_dir() + "/" + name + suffix + ".bsp";
      o.map_path = map_file;
      o.bsp_path = r.bsp_path;
      o.quiet = true;
      r.status = tools::bsp::compile_map(o, &r.report);
      return r;
    };
    r29 = run(o29, "_29");
    r2 = run(o2, "_bsp2");
    rrm = run(orm, "_2psb");
  }
  ASSERT_TRUE(r29.status.is_ok()) << r29.status.message();
  ASSERT_TRUE(r2.status.is_ok()) << r2.status.message();
  ASSERT_TRUE(rrm.status.is_ok()) << rrm.status.message();
  EXPECT_EQ(r29.report.format_written, tools::BspFormat::Bsp29);
  EXPECT_EQ(r2.report.format_written, tools::BspFormat::Bsp2);
  EXPECT_EQ(rrm.report.format_written, tools::BspFormat::Bsp2rmq);
  EXPECT_EQ(file_version(r29.bsp_path), 29);
  EXPECT_EQ(file_version(r2.bsp_path), kVersionBsp2);
  EXPECT_EQ(file_version(rrm.bsp_path), kVersion2psb);
  EXPECT_GT(r2.report.bsp_bytes, r29.report.bsp_bytes) << "BSP2's wider records";

  LoadedBsp a(r29.bsp_path, 96), b(r2.bsp_path, 96), c(rrm.bsp_path, 96);
  ASSERT_NE(a.world(), nullptr) << a.error();
  ASSERT_NE(b.world(), nullptr) << b.error();
  ASSERT_NE(c.world(), nullptr) << c.error();
  EXPECT_EQ(b.world()->version, BspVersion::Bsp2);
  EXPECT_EQ(c.world()->version, BspVersion::Bsp2rmq);
  for (const LoadedBsp* x : {&b, &c}) {
    const BspWorld& w = *x->world();
    EXPECT_EQ(w.num_faces, a.world()->num_faces);
    EXPECT_EQ(w.num_leaves, a.world()->num_leaves);
    EXPECT_EQ(w.num_nodes, a.world()->num_nodes);
    EXPECT_EQ(w.num_clipnodes, a.world()->num_clipnodes);
    EXPECT_EQ(w.num_models, a.world()->num_models);
  }
  expect_same_pictures(a, b, views, name + " BSP29 vs BSP2");
  expect_same_pictures(a, c, views, name + " BSP29 vs 2PSB");
  RenderCheck rc = check_render(b, views);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_EQ(rc.coverage_errors, 0u);
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
}

TEST(SbbspFormat, ForcedBsp2LoadsAndRendersLikeBsp29) { compare_formats("fmt_rooms", rooms_map(0), "", 8); }

TEST(SbbspFormat, ForcedBsp2OfStartMapRendersLikeBsp29) {
  SB_REQUIRE_QUAKE_DATA();
  compare_formats("fmt_start", "", quake_dir() + "/lq1/maps/src/misc/start.map", 8);
}

TEST(SbbspFormat, Bsp29FailsNamingTheLimitWhereAutoWritesBsp2) {
  // Beyond x = 32767 the node and leaf boxes no longer fit BSP29's int16 fields.
  std::string map = rooms_map(40000);
  CompileRun autofmt = compile_text("fmt_far", map);
  ASSERT_TRUE(autofmt.status.is_ok()) << autofmt.status.message();
  EXPECT_EQ(autofmt.report.format_written, tools::BspFormat::Bsp2);
  EXPECT_EQ(file_version(autofmt.bsp_path), kVersionBsp2);
  LoadedBsp b(autofmt.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(point_contents(*b.world(), glm::vec3(40000, 0, 64)), kContentsEmpty);

  tools::bsp::BspOptions o;
  o.format = tools::BspFormat::Bsp29;
  CompileRun forced = compile_text("fmt_far_29", map, {}, o);
  ASSERT_FALSE(forced.status.is_ok());
  std::string msg = forced.status.message();
  EXPECT_NE(msg.find("-bsp29"), std::string::npos) << msg;
  EXPECT_NE(msg.find("bounds outside -32768..32767"), std::string::npos) << msg;
  EXPECT_NE(msg.find("fmt_far_29.map"), std::string::npos) << msg;
  EXPECT_TRUE(read_file_bytes(forced.bsp_path).empty()) << "nothing written";
}

// A map with nothing to draw (only a skip brush; ericw-tools' q1_skip_only.map is one) still
// gives a BSP every loader accepts: edge 0, the placeholder, must name a vertex that exists.
TEST(SbbspFormat, MapWithNoDrawnFaceStillLoads) {
  write_wad();
  std::string map = entity(kWorld, box_brush(-64, -64, -16, 64, 64, 0, "skip")) +
                    entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"");
  CompileRun r = compile_text("fmt_skip_only", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(b.world()->num_faces, 0u);
  EXPECT_GE(b.world()->num_vertices, 1u);
}

}  // namespace
}  // namespace sb::test
