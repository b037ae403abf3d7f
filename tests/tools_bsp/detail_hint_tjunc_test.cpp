// tests/tools_bsp/detail_hint_tjunc_test.cpp: sbbsp's func_detail (PRT2 clusters, no seal),
// hint brushes (forced splitters, not drawn, not solid) and T-junction fixing, on hand-made maps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"
#include "tests/tools_bsp/bsp_test_util.h"
#include "tools/bsp/map_file.h"

namespace sb::test {
namespace {

const char* kWorld = "\"classname\" \"worldspawn\"\n\"wad\" \"bsptest2.wad\"";
const char* kPlayer = "\"classname\" \"info_player_start\"\n\"origin\" \"-96 0 24\"";
const char* kLight = "\"classname\" \"light\"\n\"origin\" \"96 0 96\"\n\"light\" \"300\"";

void write_wad() {
  static bool done = [] {
    std::vector<uint8_t> w = make_wad({"wall", "floor", "rock"});
    std::string path = bsp_scratch_dir() + "/bsptest2.wad";
    FILE* f = std::fopen(path.c_str(), "wb");
    std::fwrite(w.data(), 1, w.size(), f);
    std::fclose(f);
    return true;
  }();
  (void)done;
}

// Two rooms (x -192..0 and 0..192) joined by a doorway (y -32..32) in a 16-unit wall at x 0;
// `extra_world` goes into worldspawn, `extra_entities` after it.
std::string two_rooms(const std::string& extra_world, const std::string& extra_entities) {
  write_wad();
  std::string world = room_brushes(-192, -64, 0, 192, 64, 128, "wall");
  world += box_brush(-8, -64, 0, 8, -32, 128, "wall");
  world += box_brush(-8, 32, 0, 8, 64, 128, "wall");
  return entity(kWorld, world + extra_world) + entity(kPlayer) + entity(kLight) + extra_entities;
}

// The doorway pillar: x -8..8, y -8..8, full height.
std::string pillar() { return box_brush(-8, -8, 0, 8, 8, 128, "rock"); }

struct Prt {
  std::string magic;
  int leaves = 0, clusters = 0, portals = 0, portal_lines = 0;
  std::vector<int> cluster_of_leaf;  // PRT2: -1 where no cluster names the leaf
  int leaves_listed = 0;
  bool ok = false;
};

Prt read_prt(const std::string& path) {
  Prt p;
  std::string text;
  if (!tools::bsp::read_file(path.c_str(), &text)) return p;
  std::istringstream in(text);
  std::getline(in, p.magic);
  if (p.magic == "PRT1") {
    in >> p.leaves >> p.portals;
    p.clusters = p.leaves;
  } else if (p.magic == "PRT2") {
    in >> p.leaves >> p.clusters >> p.portals;
  } else {
    return p;
  }
  std::string line;
  std::getline(in, line);
  for (int i = 0; i < p.portals; ++i) {
    if (!std::getline(in, line)) return p;
    int n = 0, a = -1, b = -1;
    if (std::sscanf(line.c_str(), "%d %d %d", &n, &a, &b) != 3) return p;
    if (a < 0 || b < 0 || a >= p.clusters || b >= p.clusters || n < 3) return p;
    ++p.portal_lines;
  }
  if (p.magic == "PRT2") {
    p.cluster_of_leaf.assign(size_t(p.leaves), -1);
    for (int c = 0; c < p.clusters; ++c) {
      int leaf;
      while (in >> leaf && leaf >= 0) {
        if (leaf >= p.leaves || p.cluster_of_leaf[size_t(leaf)] >= 0) return p;
        p.cluster_of_leaf[size_t(leaf)] = c;
        ++p.leaves_listed;
      }
      if (!in) return p;
    }
  }
  p.ok = true;
  return p;
}

glm::vec3 face_vertex(const BspWorld& w, const Face& f, uint32_t i) {
  int32_t se = w.surfedges[f.first_surfedge + i];
  const Edge& e = w.edges[se >= 0 ? se : -se];
  return w.vertices[se >= 0 ? e.v[0] : e.v[1]];
}

glm::vec3 face_normal(const BspWorld& w, const Face& f) {
  glm::vec3 n = w.planes[f.plane].normal;
  return (f.flags & kFacePlaneBack) ? -n : n;
}

glm::vec3 face_center(const BspWorld& w, const Face& f) {
  glm::vec3 c(0.0f);
  for (uint32_t i = 0; i < f.num_edges; ++i) c += face_vertex(w, f, i);
  return c / float(f.num_edges);
}

// Contents at a point in clip hull `hull` of model 0.
int32_t hull_contents(const BspWorld& w, int hull, const glm::vec3& p) {
  int32_t n = w.models[0].headnode[hull];
  while (n >= 0) {
    const ClipNode& c = w.clipnodes[n];
    const Plane& pl = w.planes[c.plane];
    n = c.children[glm::dot(pl.normal, p) - pl.dist >= 0 ? 0 : 1];
  }
  return n;
}

// No edge is used by more than two faces, and never twice in the same direction.
void expect_edges_shared_by_at_most_two(const BspWorld& w) {
  std::map<uint32_t, std::pair<int, int>> uses;  // edge -> (forward, backward)
  for (uint32_t f = 0; f < w.num_faces; ++f)
    for (uint32_t i = 0; i < w.faces[f].num_edges; ++i) {
      int32_t se = w.surfedges[w.faces[f].first_surfedge + i];
      auto& u = uses[uint32_t(se >= 0 ? se : -se)];
      (se >= 0 ? u.first : u.second)++;
    }
  for (const auto& [e, u] : uses) {
    EXPECT_LE(u.first, 1) << "edge " << e;
    EXPECT_LE(u.second, 1) << "edge " << e;
  }
}

TEST(SbbspDetail, PillarMakesNoClusterBoundaryAndWritesPrt2) {
  // Reference: no pillar (PRT1), and the pillar as a structural brush.
  CompileRun plain = compile_text("detail_none", two_rooms("", ""));
  ASSERT_TRUE(plain.status.is_ok()) << plain.status.message();
  ASSERT_FALSE(plain.report.leaked) << plain.report.leak_message;
  Prt p0 = read_prt(plain.report.prt_path);
  ASSERT_TRUE(p0.ok);
  EXPECT_EQ(p0.magic, "PRT1");
  CompileRun structural = compile_text("detail_structural", two_rooms(pillar(), ""));
  ASSERT_TRUE(structural.status.is_ok()) << structural.status.message();
  Prt ps = read_prt(structural.report.prt_path);
  ASSERT_TRUE(ps.ok);
  EXPECT_EQ(ps.magic, "PRT1");

  std::string detail = entity("\"classname\" \"func_detail\"", pillar());
  CompileRun r = compile_text("detail_pillar", two_rooms("", detail));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_EQ(r.report.prt_format, "PRT2");
  Prt p = read_prt(r.report.prt_path);
  ASSERT_TRUE(p.ok) << "malformed PRT2";
  EXPECT_EQ(p.magic, "PRT2");
  EXPECT_EQ(p.portal_lines, p.portals);
  EXPECT_EQ(p.leaves, int(r.report.visleafs));
  EXPECT_EQ(p.leaves_listed, p.leaves) << "every PVS leaf belongs to exactly one cluster";
  EXPECT_LE(p.clusters, p0.leaves) << "the detail pillar adds no structural (cluster) leaf";
  EXPECT_LT(p.clusters, ps.leaves) << "a structural pillar would have";
  std::cout << "[ sbbsp ] doorway pillar: no pillar " << p0.leaves << " leaves; structural pillar " << ps.leaves
            << " leaves; func_detail pillar " << p.leaves << " leaves in " << p.clusters << " clusters, "
            << p.portals << " cluster portals\n";

  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  EXPECT_EQ(b.world()->num_models, 1u) << "func_detail merges into the world";
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 64)), kContentsSolid) << "the pillar is solid";
  EXPECT_EQ(point_contents(w, glm::vec3(0, 20, 64)), kContentsEmpty) << "beside the pillar";
  EXPECT_EQ(hull_contents(w, 1, glm::vec3(0, 0, 64)), kContentsSolid) << "hull 1 collides with the pillar";
  EXPECT_EQ(hull_contents(w, 1, glm::vec3(-96, 0, 40)), kContentsEmpty);
  int pillar_faces = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    glm::vec3 c = face_center(w, w.faces[i]);
    glm::vec3 n = face_normal(w, w.faces[i]);
    if (std::fabs(c.y) < 8.5f && std::fabs(c.x) < 8.5f && (std::fabs(n.x) > 0.9f || std::fabs(n.y) > 0.9f))
      ++pillar_faces;
  }
  EXPECT_GE(pillar_faces, 2) << "the pillar's sides facing the rooms are drawn";
  RenderCheck rc = check_render(b, 8);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.views, 2);
  EXPECT_EQ(rc.coverage_errors, 0u);
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;

  // -prt1 keeps the leaf portals.
  tools::bsp::BspOptions o;
  o.prt1_only = true;
  CompileRun r1 = compile_text("detail_pillar_prt1", two_rooms("", detail), {}, o);
  ASSERT_TRUE(r1.status.is_ok());
  Prt q = read_prt(r1.report.prt_path);
  ASSERT_TRUE(q.ok);
  EXPECT_EQ(q.magic, "PRT1");
  EXPECT_EQ(q.leaves, p.leaves);
}

TEST(SbbspDetail, DetailDoesNotSealTheMap) {
  write_wad();
  // A room whose east wall is missing; a func_detail brush closes the hole.
  std::string world = room_brushes(-64, -64, 0, 64, 64, 128, "wall", /*open_east_wall=*/true);
  std::string plug = box_brush(64, -80, -16, 80, 80, 144, "rock");
  std::string map = entity(kWorld, world) + entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"") +
                    entity("\"classname\" \"func_detail\"", plug);
  CompileRun r = compile_text("detail_leak", map);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_TRUE(r.report.leaked) << "detail brushes never seal (ericw-tools semantics)";
  std::string sealed = entity(kWorld, world + plug) + entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 24\"");
  CompileRun s = compile_text("detail_leak_structural", sealed);
  ASSERT_TRUE(s.status.is_ok());
  EXPECT_FALSE(s.report.leaked) << "the same brush as structural seals";
}

TEST(SbbspDetail, IllusionaryIsDrawnButNotSolid) {
  std::string ghost = entity("\"classname\" \"func_detail_illusionary\"", pillar());
  CompileRun r = compile_text("detail_illusionary", two_rooms("", ghost));
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  LoadedBsp b(r.bsp_path);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 64)), kContentsEmpty);
  EXPECT_EQ(hull_contents(w, 1, glm::vec3(0, 0, 64)), kContentsEmpty);
  int pillar_faces = 0;
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    glm::vec3 c = face_center(w, w.faces[i]);
    if (std::fabs(c.y) < 8.5f && std::fabs(c.x) < 8.5f && c.z > 1 && c.z < 127) ++pillar_faces;
  }
  EXPECT_GE(pillar_faces, 2);
}

// A box on the floor: as func_detail it cuts a hole in the floor face (fragments around it);
// as func_detail_wall the floor face stays whole (overdraw instead of splits).
TEST(SbbspDetail, DetailWallKeepsTheFloorWhole) {
  write_wad();
  std::string box = box_brush(-16, -16, 0, 16, 16, 32, "rock");
  auto floor_faces = [&](const char* cls, int* count) {
    std::string map = entity(kWorld, room_brushes(-64, -64, 0, 64, 64, 128, "wall")) +
                      entity("\"classname\" \"info_player_start\"\n\"origin\" \"-40 -40 24\"") +
                      entity(std::string("\"classname\" \"") + cls + "\"", box);
    CompileRun r = compile_text(std::string("detail_floor_") + cls, map);
    ASSERT_TRUE(r.status.is_ok()) << r.status.message();
    ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
    LoadedBsp b(r.bsp_path);
    ASSERT_NE(b.world(), nullptr) << b.error();
    const BspWorld& w = *b.world();
    *count = 0;
    for (uint32_t i = 0; i < w.num_faces; ++i)
      if (face_normal(w, w.faces[i]).z > 0.99f && std::fabs(face_center(w, w.faces[i]).z) < 0.01f) ++*count;
    EXPECT_EQ(point_contents(w, glm::vec3(0, 0, 16)), kContentsSolid) << cls;
  };
  int detail = 0, wall = 0;
  floor_faces("func_detail", &detail);
  floor_faces("func_detail_wall", &wall);
  EXPECT_EQ(wall, 1);
  EXPECT_GE(detail, 2);
}

// LibreQuake's start.map has func_detail, _wall and _illusionary: a PRT2 file where every PVS
// leaf is in one cluster, fewer clusters than leaves.
TEST(SbbspDetail, StartMapWritesAValidPrt2) {
  SB_REQUIRE_QUAKE_DATA();
  tools::bsp::BspOptions opt;
  opt.map_path = quake_dir() + "/lq1/maps/src/misc/start.map";
  opt.bsp_path = bsp_scratch_dir() + "/start_prt2.bsp";
  opt.quiet = true;
  opt.clip_hulls = false;
  tools::bsp::CompileReport rep;
  Status st = tools::bsp::compile_map(opt, &rep);
  ASSERT_TRUE(st.is_ok()) << st.message();
  ASSERT_FALSE(rep.leaked) << rep.leak_message;
  Prt p = read_prt(rep.prt_path);
  ASSERT_TRUE(p.ok) << "malformed PRT2";
  EXPECT_EQ(p.magic, "PRT2");
  EXPECT_EQ(p.leaves, rep.visleafs);
  EXPECT_EQ(p.leaves_listed, p.leaves);
  EXPECT_LT(p.clusters, p.leaves);
  EXPECT_GT(p.portals, 0);
  std::cout << "[ sbbsp ] start.map: " << p.leaves << " leaves in " << p.clusters << " clusters, " << p.portals
            << " cluster portals (" << rep.portals << " portals in the whole hull-0 tree)\n";
}

// A hint brush (x -64..0 inside a 128-unit room; its +x face "hint", the others "hintskip").
TEST(SbbspHint, HintPlaneSplitsButDrawsNothingAndIsNotSolid) {
  write_wad();
  std::string hint = box_brush(-64, -64, 0, 0, 64, 128, "hintskip");
  hint.replace(hint.find("hintskip"), 8, "hint");  // the first face written is +x (x = 0)
  auto map = [&](const std::string& extra) {
    return entity(kWorld, room_brushes(-64, -64, 0, 64, 64, 128, "wall") + extra) +
           entity("\"classname\" \"info_player_start\"\n\"origin\" \"-32 0 24\"");
  };
  CompileRun plain = compile_text("hint_none", map(""));
  CompileRun r = compile_text("hint", map(hint));
  ASSERT_TRUE(plain.status.is_ok() && r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_EQ(r.report.missing_textures, 0) << "hint textures never reach the texture lump";
  LoadedBsp b0(plain.bsp_path), b(r.bsp_path);
  ASSERT_NE(b0.world(), nullptr);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w0 = *b0.world();
  const BspWorld& w = *b.world();
  bool node_on_hint = false;
  for (uint32_t i = 0; i < w.num_nodes; ++i) {
    const Plane& p = w.planes[w.nodes[i].plane];
    if (std::fabs(std::fabs(p.normal.x) - 1) < 1e-6f && std::fabs(p.dist) < 1e-4f) node_on_hint = true;
  }
  EXPECT_TRUE(node_on_hint) << "the hint plane x = 0 is a node plane";
  // Nothing is drawn on the hint plane; the four faces it crosses (floor, ceiling, north and
  // south walls) are split by it, the others are unchanged.
  EXPECT_EQ(w.num_faces, w0.num_faces + 4);
  for (uint32_t i = 0; i < w.num_faces; ++i) {
    glm::vec3 n = face_normal(w, w.faces[i]), c = face_center(w, w.faces[i]);
    EXPECT_FALSE(std::fabs(n.x) > 0.99f && std::fabs(c.x) < 1.0f) << "face " << i << " on the hint plane";
  }
  auto count_leaves = [](const BspWorld& world, bool solid) {
    int n = 0;
    for (uint32_t i = 1; i < world.num_leaves; ++i) n += (world.leaves[i].contents == kContentsSolid) == solid;
    return n;
  };
  EXPECT_EQ(count_leaves(w, true), count_leaves(w0, true)) << "the number of solid leaves does not change";
  EXPECT_EQ(count_leaves(w, false), count_leaves(w0, false) + 1) << "the room is cut in two empty leaves";
  EXPECT_EQ(point_contents(w, glm::vec3(-32, 0, 64)), kContentsEmpty) << "hint brushes are not solid";
  EXPECT_EQ(hull_contents(w, 1, glm::vec3(-32, 0, 64)), kContentsEmpty);
  RenderCheck rc = check_render(b, 4);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
}

// The floor is two slabs of different textures meeting at x = 0; the south wall's bottom edge
// runs from x -64 to 64 at z 8 and so has the slabs' shared corner (0 -64 8) inside it.
TEST(SbbspTjunc, BigFaceEdgeGetsTheSmallFacesVertex) {
  write_wad();
  std::string slabs = box_brush(-64, -64, 0, 0, 64, 8, "floor") + box_brush(0, -64, 0, 64, 64, 8, "rock");
  std::string map = entity(kWorld, room_brushes(-64, -64, 0, 64, 64, 128, "wall") + slabs) +
                    entity("\"classname\" \"info_player_start\"\n\"origin\" \"0 0 40\"") +
                    entity("\"classname\" \"light\"\n\"origin\" \"0 0 96\"");
  auto south_wall_has_vertex = [](const BspWorld& w, int* faces) {
    bool found = false;
    *faces = 0;
    for (uint32_t i = 0; i < w.num_faces; ++i) {
      const Face& f = w.faces[i];
      glm::vec3 n = face_normal(w, f), c = face_center(w, f);
      if (n.y < 0.99f || std::fabs(c.y + 64) > 0.01f) continue;
      ++*faces;
      for (uint32_t k = 0; k < f.num_edges; ++k)
        if (glm::length(face_vertex(w, f, k) - glm::vec3(0, -64, 8)) < 0.01f) found = true;
    }
    return found;
  };
  tools::bsp::BspOptions off;
  off.tjunc = false;
  CompileRun r0 = compile_text("tjunc_off", map, {}, off);
  CompileRun r = compile_text("tjunc", map);
  ASSERT_TRUE(r0.status.is_ok() && r.status.is_ok()) << r.status.message();
  ASSERT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_EQ(r0.report.tjunc_vertices, 0);
  EXPECT_GT(r.report.tjunc_vertices, 0);
  LoadedBsp b0(r0.bsp_path), b(r.bsp_path);
  ASSERT_NE(b0.world(), nullptr) << b0.error();
  ASSERT_NE(b.world(), nullptr) << b.error();
  int walls0 = 0, walls = 0;
  EXPECT_FALSE(south_wall_has_vertex(*b0.world(), &walls0)) << "without the fix: a T-junction";
  EXPECT_TRUE(south_wall_has_vertex(*b.world(), &walls)) << "the fix puts the vertex into the big face's edge";
  EXPECT_EQ(walls, 1);
  EXPECT_EQ(walls0, 1);
  EXPECT_EQ(b.world()->num_faces, b0.world()->num_faces) << "no face was cut";
  expect_edges_shared_by_at_most_two(*b.world());
  RenderCheck rc = check_render(b, 4);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_EQ(rc.coverage_errors, 0u);
  EXPECT_GE(rc.agreement, 0.95) << rc.summary;
  std::string summary = tools::bsp::summary_text(r.report);
  EXPECT_NE(summary.find("tjunc vertices added"), std::string::npos) << summary;
  EXPECT_NE(summary.find("BSP29"), std::string::npos) << summary;
}

}  // namespace
}  // namespace sb::test
