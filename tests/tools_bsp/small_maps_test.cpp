// tests/tools_bsp/small_maps_test.cpp: sbbsp on hand-made maps written by the test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine/formats/entities.h"
#include "engine/world/world.h"
#include "tests/support/png_image.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/bsp/map_file.h"

namespace sb::test {
namespace {

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"bsptest.wad\"";
const char* kPlayer = "\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"";
const char* kLight = "\"classname\" \"light\"\n\"origin\" \"0 0 96\"\n\"light\" \"300\"";

std::string wad_path() {
  static std::string p = [] {
    std::string path = bsp_scratch_dir() + "/bsptest.wad";
    std::vector<uint8_t> w = make_wad({"wall", "floor", "*water", "sky1", "door"});
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(w.data(), 1, w.size(), f);
    std::fclose(f);
    return path;
  }();
  return p;
}

std::string room_map(const std::string& extra_world = "", const std::string& extra_entities = "", bool leak = false) {
  wad_path();
  return entity(kWorld, room_brushes(-64, -64, 0, 64, 64, 128, "wall", leak) + extra_world) + entity(kPlayer) +
         entity(kLight) + extra_entities;
}

glm::vec3 face_normal(const BspWorld& w, const Face& f) {
  glm::vec3 n = w.planes[f.plane].normal;
  return (f.flags & kFacePlaneBack) ? -n : n;
}

glm::vec3 face_center(const BspWorld& w, const Face& f) {
  glm::vec3 c(0.0f);
  for (uint32_t i = 0; i < f.num_edges; ++i) {
    int32_t se = w.surfedges[f.first_surfedge + i];
    const Edge& e = w.edges[se >= 0 ? se : -se];
    c += w.vertices[se >= 0 ? e.v[0] : e.v[1]];
  }
  return c / float(f.num_edges);
}

TEST(SbbspSmall, BoxRoomCompilesLoadsAndRenders) {
  CompileRun r = compile_text("room", room_map());
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_FALSE(r.report.prt_path.empty());
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  EXPECT_EQ(w.num_faces, 6u) << "only the room's inner skin remains";
  EXPECT_EQ(w.missing_textures, 0u);
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    glm::vec3 n = face_normal(w, w.faces[i]);
    glm::vec3 c = face_center(w, w.faces[i]);
    EXPECT_GT(glm::dot(n, glm::vec3(0, 0, 64) - c), 0.0f) << "face " << i << " faces out of the room";
  }
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 64)), kContentsEmpty);
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, -8)), kContentsSolid);
  EXPECT_EQ(point_contents(w, glm::vec3(500, 0, 64)), kContentsSolid) << "the outside is filled";
  RenderCheck rc = check_render(b, 8);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.views, 4);
  EXPECT_EQ(rc.coverage_errors, 0u);
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
  EXPECT_LT(rc.unexplained, 0.005) << rc.summary;
  EXPECT_EQ(rc.faces_drawn.size(), 6u) << "every face is seen from inside";
  // The portal file names one leaf per room region.
  std::string prt;
  ASSERT_TRUE(tools::bsp::read_file(r.report.prt_path.c_str(), &prt));
  EXPECT_EQ(prt.rfind("PRT1\n", 0), 0u);
  // Entities: point entities kept verbatim, worldspawn first.
  EXPECT_NE(std::string(w.entities).find("\"origin\" \"0 0 96\""), std::string::npos);
  EXPECT_EQ(w.num_models, 1u);
  EXPECT_GE(w.models[0].headnode[1], 0) << "hull 1 has clipnodes";
}

TEST(SbbspSmall, OverlappingBrushesLeaveNoFaceInsideABrush) {
  std::string blocks = box_brush(-32, -32, 0, 16, 16, 48, "wall") + box_brush(-16, -16, 0, 32, 32, 64, "floor");
  CompileRun r = compile_text("overlap", room_map(blocks));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked);
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  auto inside = [](const glm::vec3& p, glm::vec3 lo, glm::vec3 hi) {
    return p.x > lo.x + 0.1f && p.x < hi.x - 0.1f && p.y > lo.y + 0.1f && p.y < hi.y - 0.1f && p.z > lo.z + 0.1f &&
           p.z < hi.z - 0.1f;
  };
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    glm::vec3 c = face_center(w, w.faces[i]);
    EXPECT_FALSE(inside(c, {-32, -32, 0}, {16, 16, 48})) << "face " << i << " inside brush A";
    EXPECT_FALSE(inside(c, {-16, -16, 0}, {32, 32, 64})) << "face " << i << " inside brush B";
  }
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 30)), kContentsSolid);
  EXPECT_EQ(point_contents(w, glm::vec3(24, 24, 56)), kContentsSolid);
  EXPECT_EQ(point_contents(w, glm::vec3(-24, -24, 56)), kContentsEmpty);
  RenderCheck rc = check_render(b, 8);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
  EXPECT_LT(rc.unexplained, 0.005) << rc.summary;
}

TEST(SbbspSmall, LeakWritesPointFileAndStillABsp) {
  CompileRun r = compile_text("leak", room_map("", "", /*leak=*/true));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_TRUE(r.report.leaked);
  EXPECT_NE(r.report.leak_message.find("info_player_start"), std::string::npos) << r.report.leak_message;
  EXPECT_NE(r.report.leak_message.find("(0 0 24)"), std::string::npos) << r.report.leak_message;
  std::string pts;
  ASSERT_TRUE(tools::bsp::read_file(r.report.pts_path.c_str(), &pts));
  EXPECT_GT(pts.size(), 10u);
  EXPECT_EQ(pts.rfind("0 0 24\n", 0), 0u) << "starts at the entity";
  EXPECT_TRUE(r.report.prt_path.empty());
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(b.world()->visdata_size, 0u);
}

TEST(SbbspSmall, DoorBecomesASubmodel) {
  std::string door = entity("\"classname\" \"func_door\"\n\"angle\" \"90\"", box_brush(-8, -48, 0, 8, 48, 96, "door"));
  CompileRun r = compile_text("door", room_map("", door));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  ASSERT_EQ(w.num_models, 2u);
  EXPECT_EQ(w.models[1].num_faces, 6u);
  EXPECT_NE(std::string(w.entities).find("\"model\" \"*1\""), std::string::npos);
  EXPECT_EQ(point_in_leaf_from(w, w.models[1].headnode[0], glm::vec3(0, 0, 48)), 0) << "inside the door: solid";
  EXPECT_NEAR(w.models[1].mins.y, -48.0f, 1.5f);
  EXPECT_EQ(w.models[0].num_faces, 6u) << "the door does not cut the world";
}

TEST(SbbspSmall, WaterIsLiquidAndSeenFromBothSides) {
  std::string water = box_brush(-64, -64, 0, 64, 64, 48, "*water");
  CompileRun r = compile_text("water", room_map(water));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 20)), kContentsWater);
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 80)), kContentsEmpty);
  int up = 0, down = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    const Face& f = w.faces[i];
    if (!(f.flags & kFaceTurb)) continue;
    glm::vec3 n = face_normal(w, f);
    glm::vec3 c = face_center(w, f);
    EXPECT_NEAR(c.z, 48.0f, 0.01f) << "only the surface of the water is drawn";
    if (n.z > 0.99f) ++up;
    if (n.z < -0.99f) ++down;
  }
  EXPECT_EQ(up, 1);
  EXPECT_EQ(down, 1);
  bool water_leaf = false;
  for (uint32_t l = 1; l < w.num_leaves; ++l) water_leaf |= w.leaves[l].contents == kContentsWater;
  EXPECT_TRUE(water_leaf);
  RenderCheck rc = check_render(b, 8);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
  EXPECT_LT(rc.unexplained, 0.005) << rc.summary;
}

TEST(SbbspSmall, SkyCeiling) {
  wad_path();
  std::string brushes = box_brush(-80, -80, -16, 80, 80, 0, "floor") + box_brush(-80, -80, 128, 80, 80, 144, "sky1") +
                        box_brush(-80, -80, 0, -64, 80, 128, "wall") + box_brush(64, -80, 0, 80, 80, 128, "wall") +
                        box_brush(-64, -80, 0, 64, -64, 128, "wall") + box_brush(-64, 64, 0, 64, 80, 128, "wall");
  CompileRun r = compile_text("sky", entity(kWorld, brushes) + entity(kPlayer) + entity(kLight));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  int sky = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i)
    if (w.faces[i].flags & kFaceSky) {
      ++sky;
      EXPECT_LT(face_normal(w, w.faces[i]).z, -0.99f);
    }
  EXPECT_EQ(sky, 1);
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 136)), kContentsSky);
  RenderCheck rc = check_render(b, 8);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
  EXPECT_LT(rc.unexplained, 0.005) << rc.summary;
}

// s, t of the floor's corner computed by hand from the .map line, against the compiled texinfo.
void expect_texinfo(const BspWorld& w, const glm::vec3& vertex, double s_expected, double t_expected) {
  bool found = false;
  for (uint32_t i = 0; i < w.num_faces && !found; ++i) {
    const Face& f = w.faces[i];
    if (face_normal(w, f).z < 0.99f) continue;  // the floor's top
    const TexInfo& ti = w.texinfo[f.texinfo];
    double s = glm::dot(glm::vec3(ti.vecs[0]), vertex) + ti.vecs[0].w;
    double t = glm::dot(glm::vec3(ti.vecs[1]), vertex) + ti.vecs[1].w;
    EXPECT_NEAR(s, s_expected, 1e-3);
    EXPECT_NEAR(t, t_expected, 1e-3);
    found = true;
  }
  EXPECT_TRUE(found);
}

TEST(SbbspSmall, StandardTextureAlignment) {
  wad_path();
  // Floor top (normal +z): base axes s = +x, t = -y. Rotation 90: s -> (0, 1, 0)... see below.
  std::string floor = box_brush(-64, -64, -16, 64, 64, 0, "floor", "8 4 90 2 0.5");
  std::string map = entity(kWorld, floor + room_brushes(-64, -64, 0, 64, 64, 128, "wall").substr(0)) + entity(kPlayer);
  // The room's own floor would hide ours: build the room without it.
  std::string walls;
  walls += box_brush(-80, -80, 128, 80, 80, 144, "wall") + box_brush(-80, -80, -16, -64, 80, 128, "wall") +
           box_brush(64, -80, -16, 80, 80, 128, "wall") + box_brush(-64, -80, -16, 64, -64, 128, "wall") +
           box_brush(-64, 64, -16, 64, 80, 128, "wall");
  map = entity(kWorld, floor + walls) + entity(kPlayer);
  CompileRun r = compile_text("texstd", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  // Base s = (1,0,0), t = (0,-1,0); rotating by 90 degrees in the x/y plane:
  //   s' = (cos*1 - sin*0, sin*1 + cos*0, 0) = (0, 1, 0); t' = (cos*0 - sin*(-1), sin*0 + cos*(-1), 0) = (1, 0, 0).
  // Scales 2 and 0.5: vecs s = (0, 0.5, 0) + 8, t = (2, 0, 0) + 4. At (64, -64, 0):
  //   s = -32 + 8 = -24; t = 128 + 4 = 132.
  expect_texinfo(*b.world(), glm::vec3(64, -64, 0), -24.0, 132.0);
}

TEST(SbbspSmall, Valve220TextureAlignment) {
  wad_path();
  std::string walls = box_brush(-80, -80, 128, 80, 80, 144, "wall") + box_brush(-80, -80, -16, -64, 80, 128, "wall") +
                      box_brush(64, -80, -16, 80, 80, 128, "wall") + box_brush(-64, -80, -16, 64, -64, 128, "wall") +
                      box_brush(-64, 64, -16, 64, 80, 128, "wall");
  // Same box as box_brush's floor, written in Valve 220 with explicit axes on every face.
  std::string floor = box_brush(-64, -64, -16, 64, 64, 0, "floor", "[ 0.6 0.8 0 10 ] [ -0.8 0.6 0 -6 ] 0 0.5 4");
  std::string map = "{\n\"mapversion\" \"220\"\n" + std::string(kWorld) + "\n" + floor + walls + "}\n" + entity(kPlayer);
  CompileRun r = compile_text("texvalve", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  // s = dot(p, u / 0.5) + 10, t = dot(p, v / 4) - 6 at (64, -64, 0):
  //   u.p = 0.6*64 - 0.8*64 = -12.8 -> s = -25.6 + 10 = -15.6
  //   v.p = -0.8*64 - 0.6*64 = -89.6 -> t = -22.4 - 6 = -28.4
  expect_texinfo(*b.world(), glm::vec3(64, -64, 0), -15.6, -28.4);
}

TEST(SbbspSmall, MalformedMapNamesFileAndLine) {
  CompileRun r = compile_text("bad", "{\n\"classname\" \"worldspawn\"\n{\n( 0 0 0 ) ( 1 0 0 ) oops\n}\n}\n");
  ASSERT_FALSE(r.status.is_ok());
  EXPECT_NE(std::string(r.status.message()).find("bad.map:4:"), std::string::npos) << r.status.message();
  CompileRun r2 = compile_text("bad2", "{\n\"classname\" \"worldspawn\"\n{\n");
  ASSERT_FALSE(r2.status.is_ok());
  EXPECT_NE(std::string(r2.status.message()).find("bad2.map:3:"), std::string::npos) << r2.status.message();
  tools::bsp::BspOptions opt;
  opt.map_path = bsp_scratch_dir() + "/does_not_exist.map";
  opt.quiet = true;
  tools::bsp::CompileReport rep;
  Status s = tools::bsp::compile_map(opt, &rep);
  ASSERT_FALSE(s.is_ok());
  EXPECT_NE(std::string(s.message()).find("does_not_exist.map"), std::string::npos);
}

TEST(SbbspSmall, DegenerateAndNanBrushesAreSkippedWithWarnings) {
  std::string flat = box_brush(0, 0, 32, 16, 16, 32, "wall");  // no volume
  std::string nan_brush =
      "{\n( 0 0 0 ) ( 0 0 0 ) ( 1 1 1 ) wall 0 0 0 1 1\n( nan 0 0 ) ( 1 0 0 ) ( 0 1 0 ) wall 0 0 0 1 1\n"
      "( 0 0 0 ) ( 0 1 0 ) ( 0 0 1 ) wall 0 0 0 1 1\n( 0 0 8 ) ( 1 0 8 ) ( 0 1 8 ) wall 0 0 0 1 1\n}\n";
  CompileRun r = compile_text("degenerate", room_map(flat + nan_brush));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_EQ(r.report.skipped_brushes, 2);
  int named = 0;
  for (const std::string& w : r.report.warnings) named += w.find("degenerate.map:") != std::string::npos;
  EXPECT_GE(named, 2);
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(b.world()->num_faces, 6u);
}

TEST(SbbspSmall, MissingTexturesGetAPlaceholderAndAWarning) {
  std::string map = entity("\"classname\" \"worldspawn\"\n\"wad\" \"nowhere.wad\"",
                           room_brushes(-64, -64, 0, 64, 64, 128, "nosuchtex")) +
                    entity(kPlayer);
  CompileRun r = compile_text("missing", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_EQ(r.report.missing_textures, 1);
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  EXPECT_EQ(b.world()->missing_textures, 0u) << "the placeholder is a real miptex";
  EXPECT_STREQ(b.world()->textures[0].name, "nosuchtex");
}

TEST(SbbspSmall, LongValuesAndDeterminism) {
  std::string longv(300, 'x');
  std::string ent = entity("\"classname\" \"info_notnull\"\n\"origin\" \"8 8 8\"\n\"message\" \"" + longv + "\"");
  CompileRun a = compile_text("det_a", room_map("", ent));
  CompileRun b = compile_text("det_b", room_map("", ent));
  ASSERT_TRUE(a.status.is_ok() && b.status.is_ok());
  EXPECT_EQ(read_file_bytes(a.bsp_path), read_file_bytes(b.bsp_path));
  EXPECT_NE(a.report.bsp.entities.find(longv), std::string::npos);
}

}  // namespace
}  // namespace sb::test
