// tests/tools_bsp/hulls_test.cpp: the clip hulls: the same bytes whatever the thread count,
// and the shape of hull 1 on a hand-made room (the player box stays 16 units off the walls,
// 24 above the floor).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/world/world.h"
#include "tests/support/quake_data.h"
#include "tests/tools_bsp/bsp_test_util.h"

namespace sb::test {
namespace {

// Contents at p in clip hull `hull` of the world model.
int32_t hull_point_contents(const BspWorld& w, int hull, const glm::vec3& p) {
  int32_t n = w.models[0].headnode[hull];
  while (n >= 0) {
    const ClipNode& c = w.clipnodes[n];
    const Plane& pl = w.planes[c.plane];
    float d = pl.normal.x * p.x + pl.normal.y * p.y + pl.normal.z * p.z - pl.dist;
    n = c.children[d >= 0 ? 0 : 1];
  }
  return n;
}

std::vector<uint8_t> bytes_of(const tools::bsp::CompileReport& r) {
  std::vector<uint8_t> out;
  tools::BspFormat used;
  EXPECT_TRUE(tools::serialize_bsp(r.bsp, tools::BspFormat::Auto, &out, &used).is_ok());
  return out;
}

tools::bsp::CompileReport compile_in_memory(const std::string& map, int threads) {
  tools::bsp::BspOptions opt;
  opt.map_path = map;
  opt.threads = threads;
  opt.write_files = false;
  opt.quiet = true;
  tools::bsp::CompileReport rep;
  Status s = tools::bsp::compile_map(opt, &rep);
  EXPECT_TRUE(s.is_ok()) << s.message();
  return rep;
}

TEST(SbbspHulls, SameBytesOnOneAndTwoThreads) {
  SB_REQUIRE_QUAKE_DATA();
  std::string map = quake_dir() + "/lq1/maps/src/e0/lq_e0m1.map";
  tools::bsp::CompileReport one = compile_in_memory(map, 1);
  tools::bsp::CompileReport two = compile_in_memory(map, 2);
  ASSERT_GT(one.bsp.clipnodes.size(), 1000u);
  EXPECT_EQ(one.bsp.clipnodes.size(), two.bsp.clipnodes.size());
  EXPECT_TRUE(bytes_of(one) == bytes_of(two)) << "hull trees built on two threads differ";
}

TEST(SbbspHulls, Hull1KeepsThePlayerBoxOffTheWalls) {
  std::vector<uint8_t> w = make_wad({"wall"});
  write_text_file(bsp_scratch_dir() + "/bsptest_hull.wad", std::string(w.begin(), w.end()));
  std::string map = entity("\"classname\" \"worldspawn\"\n\"wad\" \"bsptest_hull.wad\"",
                           room_brushes(-128, -128, 0, 128, 128, 192, "wall") + box_brush(-16, -16, 0, 16, 16, 64, "wall")) +
                    entity("\"classname\" \"info_player_start\"\n\"origin\" \"64 64 24\"");
  for (int threads : {1, 2}) {
    tools::bsp::BspOptions opt;
    opt.threads = threads;
    CompileRun r = compile_text("hull1_room_" + std::to_string(threads), map, {}, opt);
    ASSERT_TRUE(r.status.is_ok()) << r.status.message();
    LoadedBsp b(r.bsp_path);
    ASSERT_NE(b.world(), nullptr) << b.error();
    const BspWorld& world = *b.world();
    auto hull1 = [&](float x, float y, float z) { return hull_point_contents(world, 1, glm::vec3(x, y, z)); };
    EXPECT_EQ(hull1(64, 64, 24), kContentsEmpty) << threads;
    EXPECT_EQ(hull1(64, 64, 23), kContentsSolid) << "24 above the floor";
    EXPECT_EQ(hull1(111, 64, 64), kContentsEmpty);
    EXPECT_EQ(hull1(113, 64, 64), kContentsSolid) << "16 off the east wall";
    EXPECT_EQ(hull1(-31, 0, 40), kContentsSolid) << "the pillar (x -16..16) grown by 16";
    EXPECT_EQ(hull1(-33, 0, 40), kContentsEmpty) << "beside the grown pillar";
    EXPECT_EQ(hull1(0, 0, 87), kContentsSolid) << "above the pillar (top 64) by less than 24";
    EXPECT_EQ(hull1(0, 0, 89), kContentsEmpty);
    EXPECT_EQ(hull1(500, 0, 64), kContentsSolid) << "the outside is filled";
  }
}

}  // namespace
}  // namespace sb::test
