// tests/tools_bsp/real_maps_test.cpp: LibreQuake map sources (Valve 220, WADs named by relative
// paths) compiled by sbbsp without a leak, loaded with sb::load_bsp, drawn by render_world and
// compared with the reference renderer. Prints counts and times beside ericw-tools' figures
// (../shared/quake/REFERENCE.md).
#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "tests/support/quake_data.h"
#include "tests/tools_bsp/bsp_test_util.h"

namespace sb::test {
namespace {

struct RealMap {
  const char* source;  // under lq1/maps/src
  const char* name;
  int ref_faces, ref_leaves, ref_nodes, ref_clipnodes;
  double ref_seconds;
};

class SbbspRealMap : public ::testing::TestWithParam<RealMap> {};

TEST_P(SbbspRealMap, CompilesWithoutLeakLoadsAndRenders) {
  SB_REQUIRE_QUAKE_DATA();
  const RealMap& m = GetParam();
  std::string src = quake_dir() + "/lq1/maps/src/" + m.source;
  std::string out = bsp_scratch_dir() + "/" + m.name + ".bsp";
  CompileRun r = compile_file(src, out);
  ASSERT_TRUE(r.status.is_ok()) << r.status.message();
  EXPECT_FALSE(r.report.leaked) << r.report.leak_message;
  EXPECT_EQ(r.report.missing_textures, 0);
  LoadedBsp b(out, 96);
  ASSERT_NE(b.world(), nullptr) << b.error();
  const BspWorld& w = *b.world();
  std::cout << "[ sbbsp ] " << m.name << ": faces " << w.num_faces << " (ericw " << m.ref_faces << "), leaves "
            << w.num_leaves << " (" << m.ref_leaves << "), nodes " << w.num_nodes << " (" << m.ref_nodes
            << "), clipnodes " << w.num_clipnodes << " (" << m.ref_clipnodes << "), split +"
            << r.report.split_percent << "%, tjunc vertices " << r.report.tjunc_vertices << ", "
            << r.report.total_seconds << " s (ericw qbsp " << m.ref_seconds << " s)\n";
  RecordProperty("faces", int(w.num_faces));
  RecordProperty("seconds", std::to_string(r.report.total_seconds));
  RenderCheck rc = check_render(b, 12, 320, 200);
  EXPECT_TRUE(rc.error.empty()) << rc.error;
  EXPECT_GE(rc.views, 8);
  EXPECT_EQ(rc.coverage_errors, 0u);
  EXPECT_GE(rc.agreement, 0.98);
  std::cout << "[ sbbsp ] " << m.name << ": " << rc.views << " views, agreement with the reference "
            << 100.0 * rc.agreement << "%\n";
}

INSTANTIATE_TEST_SUITE_P(LibreQuake, SbbspRealMap,
                         ::testing::Values(RealMap{"misc/start.map", "start", 1105, 524, 622, 1264, 0.3},
                                           RealMap{"e0/lq_e0m1.map", "lq_e0m1", 3865, 1094, 1979, 5123, 2.3},
                                           RealMap{"e1/lq_e1m1.map", "lq_e1m1", 17373, 4730, 8017, 19776, 16.4}),
                         [](const ::testing::TestParamInfo<RealMap>& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace sb::test
