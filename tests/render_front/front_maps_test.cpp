// Front end on real maps (LibreQuake): coverage (every pixel in exactly one span) and
// agreement with a brute-force ray caster, over many viewpoints and resolutions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/world/viewpoints.h"
#include "tests/render_front/front_test_util.h"
#include "tests/support/quake_data.h"
#include "tests/support/test_world.h"

namespace sb::test::front {
namespace {

struct Resolution {
  int w, h;
  int views;  // viewpoints checked at this size
};
const Resolution kResolutions[] = {{320, 200, 40}, {640, 480, 16}, {1280, 720, 6}, {1920, 1080, 4}, {333, 197, 24}};

std::vector<ViewParams> viewpoints(const BspWorld& world, int count) {
  std::vector<ViewParams> v(static_cast<size_t>(count));
  int n = collect_viewpoints(world, v.data(), count);
  v.resize(size_t(n));
  // Vary pitch and fov a little so the set is not all level 90-degree views.
  const float pitches[] = {0, -20, 25, 10, -5, 40};
  const float fovs[] = {90, 90, 110, 70, 90, 130};
  for (size_t i = 0; i < v.size(); ++i) {
    if (v[i].pitch == 0) v[i].pitch = pitches[i % 6];
    v[i].fov_x = fovs[(i / 6) % 6];
  }
  return v;
}

class FrontMaps : public ::testing::TestWithParam<const char*> {};

TEST_P(FrontMaps, CoverageAndAgreementWithRayCaster) {
  SB_REQUIRE_QUAKE_DATA();
  TestWorld tw(GetParam());
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  BspWorld& world = *tw.world();
  RayCaster caster(world);
  FrontRunner runner(tw.memory().frame().capacity());
  std::vector<ViewParams> views = viewpoints(world, 40);
  ASSERT_GE(views.size(), 4u);

  for (const Resolution& r : kResolutions) {
    Agreement total;
    double worst = 1.0;
    std::vector<double> ms;
    uint32_t max_spans = 0, max_edges = 0, max_surfs = 0;
    for (int i = 0; i < r.views && i < int(views.size()); ++i) {
      FrontFrame f = runner.run(world, views[size_t(i)], r.w, r.h);
      ASSERT_TRUE(f.ok()) << f.status;
      ASSERT_EQ(f.contract_error, "") << "view " << i;
      ASSERT_EQ(f.bad_coverage(), 0u) << "view " << i << " at " << r.w << "x" << r.h;
      EXPECT_FALSE(f.stats.edges_overflowed || f.stats.surfaces_overflowed || f.stats.spans_overflowed);
      Agreement a = compare(f, caster.cast(f.view));
      EXPECT_GE(a.ratio(), 0.995) << GetParam() << " view " << i << " " << r.w << "x" << r.h << ": " << a.describe();
      EXPECT_EQ(a.far_from_edge, 0u) << GetParam() << " view " << i << " " << r.w << "x" << r.h << ": "
                                     << a.describe() << a.examples;
      worst = std::min(worst, a.ratio());
      total.add(a);
      ms.push_back(f.build_ms);
      max_spans = std::max(max_spans, f.num_spans);
      max_edges = std::max(max_edges, f.stats.edges);
      max_surfs = std::max(max_surfs, f.stats.surfaces);
    }
    std::sort(ms.begin(), ms.end());
    std::printf("%-8s %4dx%-4d %2zu views: %s; worst view %.4f%%; build_spans median %.3f ms max %.3f ms; "
                "max spans %u edges %u surfaces %u\n",
                GetParam(), r.w, r.h, ms.size(), total.describe().c_str(), 100.0 * worst, ms[ms.size() / 2],
                ms.back(), max_spans, max_edges, max_surfs);
  }
}

TEST_P(FrontMaps, OutsideTheWorldAndInSolid) {
  SB_REQUIRE_QUAKE_DATA();
  TestWorld tw(GetParam());
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  BspWorld& world = *tw.world();
  RayCaster caster(world);
  FrontRunner runner(tw.memory().frame().capacity());
  const SubModel& m = world.models[0];
  glm::vec3 centre = (m.mins + m.maxs) * 0.5f;
  const glm::vec3 eyes[] = {m.mins - glm::vec3(200.0f), m.maxs + glm::vec3(50.0f), centre,
                            glm::vec3(m.mins.x - 500.0f, centre.y, centre.z)};
  Agreement total;
  for (const glm::vec3& e : eyes) {
    for (float yaw : {0.0f, 45.0f, 200.0f}) {
      ViewParams p;
      p.origin = e;
      p.yaw = yaw;
      p.pitch = -15;
      p.fov_x = 120;
      FrontFrame f = runner.run(world, p, 320, 200);
      ASSERT_TRUE(f.ok()) << f.status;
      ASSERT_EQ(f.bad_coverage(), 0u);
      Agreement a = compare(f, caster.cast(f.view));
      EXPECT_EQ(a.far_from_edge, 0u) << a.describe() << a.examples;
      total.add(a);
    }
  }
  std::printf("%-8s outside/in solid: %s\n", GetParam(), total.describe().c_str());
}

TEST_P(FrontMaps, SmallFrameArenaOverflowsButCovers) {
  SB_REQUIRE_QUAKE_DATA();
  TestWorld tw(GetParam());
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  BspWorld& world = *tw.world();
  std::vector<ViewParams> views = viewpoints(world, 8);
  bool any_overflow = false;
  for (size_t bytes : {size_t(64) << 10, size_t(160) << 10}) {
    FrontRunner runner(bytes);
    for (const ViewParams& v : views) {
      for (auto sz : {std::pair{640, 480}, std::pair{1920, 1080}}) {
        FrontFrame f = runner.run(world, v, sz.first, sz.second);
        if (!f.ok()) continue;  // refused: too small for even the fallback
        ASSERT_EQ(f.contract_error, "");
        ASSERT_EQ(f.bad_coverage(), 0u) << bytes << " bytes, " << sz.first << "x" << sz.second;
        any_overflow |= f.stats.edges_overflowed || f.stats.surfaces_overflowed || f.stats.spans_overflowed;
      }
    }
  }
  EXPECT_TRUE(any_overflow);
}

// Not pass/fail: prints build_spans times (best of 3 runs per view; median and worst view).
TEST_P(FrontMaps, Timing) {
  SB_REQUIRE_QUAKE_DATA();
  TestWorld tw(GetParam());
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  BspWorld& world = *tw.world();
  FrontRunner runner(tw.memory().frame().capacity());
  std::vector<ViewParams> views = viewpoints(world, 24);
  for (auto sz : {std::pair{320, 200}, std::pair{640, 480}, std::pair{1920, 1080}}) {
    std::vector<double> best;
    double spans = 0;
    for (const ViewParams& v : views) {
      double b = 1e30;
      for (int k = 0; k < 3; ++k) {
        FrontFrame f = runner.run(world, v, sz.first, sz.second);
        ASSERT_TRUE(f.ok());
        b = std::min(b, f.build_ms);
        if (k == 0) spans += f.num_spans;
      }
      best.push_back(b);
    }
    std::sort(best.begin(), best.end());
    std::printf("%-8s %4dx%-4d build_spans: median %.3f ms, worst view %.3f ms (%zu views, %.0f spans avg)\n",
                GetParam(), sz.first, sz.second, best[best.size() / 2], best.back(), best.size(),
                spans / double(views.size()));
  }
}

INSTANTIATE_TEST_SUITE_P(LibreQuake, FrontMaps, ::testing::Values("start", "lq_e0m1", "lq_e1m1"),
                         [](const auto& param_info) { return std::string(param_info.param); });

}  // namespace
}  // namespace sb::test::front
