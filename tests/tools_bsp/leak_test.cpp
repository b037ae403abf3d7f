// tests/tools_bsp/leak_test.cpp: what seals a map and what counts as a leak, one hand-made map
// per class of cause found on LibreQuake's sources (see tools/bsp/tree.h):
//   - a crack thinner than kThinPortal between two wall brushes seals (lqdm3: angled brushes
//     whose vertices miss by a unit leave a wedge 0.18 units wide), and is filled;
//   - a point entity on a wall's outer face is not outside (it touches the wall);
//   - a map whose only point entities are lights (b_*.map prefabs) has nothing to flood
//     from: the outside is kept, no leak, no .pts;
// and lqdm3 itself (hull 0 only, in memory) compiles without a leak.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/world/world.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/bsp/geom.h"
#include "tools/bsp/tree.h"

namespace sb::test {
namespace {

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"bsptest_leak.wad\"";
const char* kPlayer = "\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"";

void write_wad() {
  static bool done = [] {
    std::vector<uint8_t> w = make_wad({"wall", "floor"});
    return write_text_file(bsp_scratch_dir() + "/bsptest_leak.wad", std::string(w.begin(), w.end()));
  }();
  (void)done;
}

// The room of bsp_test_util (inside -64..64 x -64..64 x 0..128) whose east wall (x 64..80) is
// two brushes with a crack `gap` units wide between them at y 0..gap, from the inside to the
// outside and from the floor to the ceiling.
std::string cracked_room(double gap) {
  write_wad();
  std::string world = room_brushes(-64, -64, 0, 64, 64, 128, "wall", /*open_east_wall=*/true);
  world += box_brush(64, -80, -16, 80, 0, 144, "wall");
  world += box_brush(64, gap, -16, 80, 80, 144, "wall");
  return entity(kWorld, world) + entity(kPlayer);
}

TEST(SbbspLeak, MinWidthOfAWinding) {
  using tools::bsp::Vec3;
  tools::bsp::Winding rect{Vec3(0, 0, 0), Vec3(0, 10, 0), Vec3(0.2, 10, 0), Vec3(0.2, 0, 0)};
  EXPECT_NEAR(tools::bsp::winding_min_width(rect), 0.2, 1e-9);
  tools::bsp::Winding tri{Vec3(0, 0, 0), Vec3(0, 0, 8), Vec3(8, 0, 0)};
  EXPECT_NEAR(tools::bsp::winding_min_width(tri), 8 / std::sqrt(2.0), 1e-9);
  EXPECT_EQ(tools::bsp::winding_min_width({Vec3(0.0), Vec3(1, 0, 0)}), 0.0);
}

TEST(SbbspLeak, ThinCrackSealsAndIsFilled) {
  CompileRun r = compile_text("leak_crack_thin", cracked_room(0.15));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_FALSE(r.report.leaked) << "a 0.15-unit crack seals: " << r.report.leak_message;
  EXPECT_FALSE(r.report.prt_path.empty());
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 64)), kContentsEmpty);
  EXPECT_EQ(point_contents(w, glm::vec3(72, 0.075f, 64)), kContentsSolid) << "the crack is filled";
  EXPECT_EQ(point_contents(w, glm::vec3(500, 0, 64)), kContentsSolid) << "the outside is filled";
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const glm::vec3 n = w.planes[w.faces[i].plane].normal;
    EXPECT_FALSE(std::fabs(n.y) > 0.99f && std::fabs(std::fabs(w.planes[w.faces[i].plane].dist) - 0.075f) < 0.1f)
        << "no face is drawn inside the crack (face " << i << ")";
  }
}

TEST(SbbspLeak, CrackWiderThanTheLimitStillLeaks) {
  CompileRun r = compile_text("leak_crack_wide", cracked_room(1.0));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_TRUE(r.report.leaked) << "a 1-unit crack is a hole";
  EXPECT_FALSE(r.report.pts_path.empty());
}

TEST(SbbspLeak, EntityOnAnOuterWallFaceIsNotOutside) {
  write_wad();
  // The east wall spans x 64..80; its outer face is the plane x = 80 (whose front is outside).
  std::string world = room_brushes(-64, -64, 0, 64, 64, 128, "wall");
  std::string map = entity(kWorld, world) + entity(kPlayer) +
                    entity("\"classname\" \"light\"\n\"origin\" \"80 8 64\"");
  CompileRun r = compile_text("leak_entity_on_face", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_FALSE(r.report.leaked) << r.report.leak_message;
  // The same light a unit further out is outside.
  std::string out = entity(kWorld, world) + entity(kPlayer) + entity("\"classname\" \"light\"\n\"origin\" \"81 8 64\"");
  CompileRun o = compile_text("leak_entity_off_face", out);
  ASSERT_TRUE(o.status.is_ok()) << o.status.message();
  EXPECT_TRUE(o.report.leaked);
  EXPECT_NE(o.report.leak_message.find("light"), std::string::npos) << o.report.leak_message;
}

TEST(SbbspLeak, LightsOnlyPrefabKeepsItsOutsideWithoutALeak) {
  write_wad();
  // An item prefab: two brushes, lit from outside; no other point entity.
  std::string world = box_brush(0, 0, 0, 32, 32, 16, "wall") + box_brush(8, 8, 16, 24, 24, 24, "floor");
  std::string map = entity(kWorld, world) + entity("\"classname\" \"light\"\n\"origin\" \"16 -64 64\"") +
                    entity("\"classname\" \"light\"\n\"origin\" \"16 96 64\"");
  std::remove((bsp_scratch_dir() + "/leak_prefab.pts").c_str());
  CompileRun r = compile_text("leak_prefab", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_TRUE(r.report.outside_kept);
  EXPECT_TRUE(r.report.pts_path.empty());
  FILE* f = std::fopen((bsp_scratch_dir() + "/leak_prefab.pts").c_str(), "rb");
  EXPECT_EQ(f, nullptr) << "no point file";
  if (f) std::fclose(f);
  bool noted = false;
  for (const std::string& s : r.report.warnings) noted = noted || s.find("no entities to flood from; outside kept") != std::string::npos;
  EXPECT_TRUE(noted);
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(point_contents(*b.world(), glm::vec3(16, 16, 200)), kContentsEmpty) << "the outside is kept";
  EXPECT_GT(b.world()->num_faces, 0u);

  // One non-light entity makes the lights count again: now they are outside.
  std::string occupied = map + entity("\"classname\" \"info_null\"\n\"origin\" \"16 16 8\"");
  CompileRun o = compile_text("leak_prefab_occupied", occupied);
  ASSERT_TRUE(o.status.is_ok()) << o.status.message();
  EXPECT_FALSE(o.report.outside_kept);
  EXPECT_TRUE(o.report.leaked);
}

TEST(SbbspLeak, Lqdm3HasNoLeak) {
  SB_REQUIRE_QUAKE_DATA();
  tools::bsp::BspOptions opt;
  opt.map_path = quake_dir() + "/lq1/maps/src/dm/lqdm3.map";
  opt.clip_hulls = false;  // hull 0 decides the leak; the clip hulls take most of the time
  opt.write_files = false;
  opt.quiet = true;
  tools::bsp::CompileReport rep;
  Status s = tools::bsp::compile_map(opt, &rep);
  ASSERT_TRUE(s.is_ok()) << s.message();
  EXPECT_FALSE(rep.leaked) << rep.leak_message;
  EXPECT_GT(rep.filled_leaves, 0);
}

}  // namespace
}  // namespace sb::test
