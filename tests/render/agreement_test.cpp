// tests/render/agreement_test.cpp: the edge-list renderer (sb::render_world) against the
// independent reference renderer (tests/support/reference_renderer.h) on real maps.
//
// Per map: 50 viewpoints at 320x200, 3 at 640x480, 2 at a wide 12:5 aspect with fov 100,
// 2 with roll; times and light styles vary per view. Requirements per map:
//   - at least 98% of pixels carry the very same palette index as the exact reference.
//     render_world divides exactly every 16 pixels and steps in between with a second-order
//     term that follows the perspective curve (span_draw.h); Quake's purely linear stepping
//     measured 94.3-95.8% identical here at 320x200 (its error grows with the square of the
//     run's angle), the second-order step 99.4-99.7%.
//   - the mismatches are explained: along a polygon edge, or a neighbouring texel of the
//     same face and mip (the stepped coordinate rounding the other way);
//   - under 0.5% of pixels differ for no known reason (see render_compare.h for the classes:
//     polygon edge, neighbouring texel, other mip, unexplained), other mip included;
//   - render_world writes every pixel exactly once.
// The agreement figure and the breakdown are printed and recorded as test properties.
// STARBOW_RENDER_DUMP=<dir> writes actual | reference | difference PNGs of each map's
// worst views there (blue edge, green texel, yellow mip, red unexplained).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/reference_renderer.h"
#include "tests/support/render_compare.h"
#include "tests/support/test_world.h"

namespace sb::test {
namespace {

struct ViewCase {
  ViewParams view;
  int width, height;
  double time;
  bool styled;  // light styles other than normal
};

std::vector<ViewCase> agreement_views(const BspWorld& world) {
  std::vector<ViewParams> base = test_viewpoints(world, 57);
  std::vector<ViewCase> out;
  for (size_t i = 0; i < base.size(); ++i) {
    ViewCase c{base[i], 320, 200, 0.35 + 0.77 * double(i), i % 4 == 3};
    if (i >= 50 && i < 53) { c.width = 640; c.height = 480; }
    if (i >= 53 && i < 55) { c.width = 480; c.height = 200; c.view.fov_x = 100.0f; }
    if (i >= 55) c.view.roll = (i % 2) ? 15.0f : -20.0f;
    out.push_back(c);
  }
  return out;
}

struct ViewResult {
  size_t index;
  MismatchBreakdown b;
};

class AgreementTest : public ::testing::TestWithParam<const char*> {};

TEST_P(AgreementTest, MatchesReferenceRenderer) {
  SB_REQUIRE_QUAKE_DATA();
  const std::string map = GetParam();
  TestWorld tw(map);
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  const BspWorld& world = *tw.world();
  std::vector<uint8_t> colormap = load_colormap();
  ASSERT_FALSE(colormap.empty());

  std::vector<ViewCase> views = agreement_views(world);
  ASSERT_GE(views.size(), 50u) << map << ": too few viewpoints in empty space";

  std::vector<int> styles(kMaxLightStyleSlots);
  for (int i = 0; i < kMaxLightStyleSlots; ++i) styles[i] = i == 0 ? kLightStyleNormal : 30 + (i * 97) % 500;

  MismatchBreakdown total;
  std::vector<ViewResult> results;
  uint64_t coverage_errors = 0;
  std::vector<uint8_t> actual, coverage;
  for (size_t vi = 0; vi < views.size(); ++vi) {
    const ViewCase& c = views[vi];
    const int* ls = c.styled ? styles.data() : nullptr;
    RenderStats stats;
    Status st = tw.render(c.view, c.width, c.height, c.time, ls, colormap.data(), &actual, &coverage, &stats);
    ASSERT_TRUE(st.is_ok()) << map << " view " << vi << ": " << st.message();
    for (uint8_t n : coverage) coverage_errors += n != 1;

    ReferenceInputs in{&world, c.time, ls, colormap.data()};
    ReferenceRenderer ref(in);
    ReferenceFrame frame = ref.render(c.view, c.width, c.height);
    MismatchBreakdown b = classify_mismatches(ref, frame, actual.data(), c.width);
    total.add(b);
    results.push_back({vi, b});
  }

  std::cout << "[ agreement ] " << map << ": " << views.size() << " views, " << total.summary() << "\n";
  RecordProperty("agreement_percent", std::to_string(100.0 * total.agreement()));
  RecordProperty("interpolation_agreement_percent", std::to_string(100.0 * total.interpolation_agreement()));
  RecordProperty("breakdown", total.summary());

  // The worst views, by unexplained then mismatched pixels.
  std::sort(results.begin(), results.end(), [](const ViewResult& a, const ViewResult& b) {
    double ua = a.b.unexplained_fraction(), ub = b.b.unexplained_fraction();
    if (ua != ub) return ua > ub;
    return a.b.agreement() < b.b.agreement();
  });
  const char* dump = std::getenv("STARBOW_RENDER_DUMP");
  std::vector<uint8_t> palette = dump ? load_game_palette() : std::vector<uint8_t>{};
  for (size_t k = 0; k < std::min<size_t>(3, results.size()); ++k) {
    const ViewCase& c = views[results[k].index];
    std::cout << "[ agreement ]   worst view " << results[k].index << " (" << c.width << "x" << c.height
              << " origin " << c.view.origin.x << " " << c.view.origin.y << " " << c.view.origin.z << " yaw "
              << c.view.yaw << " pitch " << c.view.pitch << " roll " << c.view.roll << "): " << results[k].b.summary()
              << "\n";
    if (dump && !palette.empty()) {
      const int* ls = c.styled ? styles.data() : nullptr;
      ASSERT_TRUE(tw.render(c.view, c.width, c.height, c.time, ls, colormap.data(), &actual).is_ok());
      ReferenceInputs in{&world, c.time, ls, colormap.data()};
      ReferenceRenderer ref(in);
      ReferenceFrame frame = ref.render(c.view, c.width, c.height);
      std::vector<PixelClass> classes;
      classify_mismatches(ref, frame, actual.data(), c.width, &classes);
      int w = 0;
      std::vector<uint8_t> rgb = comparison_rgb(frame, actual.data(), c.width, classes, palette, &w);
      std::string path = std::string(dump) + "/" + map + "_worst" + std::to_string(k) + "_view" +
                         std::to_string(results[k].index) + ".png";
      std::string err;
      EXPECT_TRUE(write_rgb_png(path, w, c.height, rgb, &err)) << err;
    }
  }

  EXPECT_EQ(coverage_errors, 0u) << map << ": pixels not written exactly once";
  EXPECT_GE(total.agreement(), 0.98) << map << ": " << total.summary();
  EXPECT_LT(double(total.unexplained + total.mip) / double(total.pixels), 0.005) << map << ": " << total.summary();
}

INSTANTIATE_TEST_SUITE_P(Maps, AgreementTest, ::testing::Values("start", "lq_e0m1", "lq_e1m1", "lq_e0m3"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });

}  // namespace
}  // namespace sb::test
