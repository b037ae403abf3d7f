// tests/render/golden_test.cpp: render_world's pictures of a few fixed views, compared by
// palette index with approved images in tests/golden/ (8-bit paletted PNGs, the real palette).
//
// The golden images are our own renders of third-party maps: generated output, small,
// committed on purpose. Re-approval is deliberate:
//   STARBOW_APPROVE_GOLDEN=1 ./render_tests --gtest_filter='Golden*'
// rewrites them (only when the new picture still agrees with the reference renderer).
// A mismatch writes the actual image and a difference picture to <build>/golden_actual/.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/build_features.h"
#include "tests/support/png_image.h"
#include "tests/support/quake_data.h"
#include "tests/support/reference_renderer.h"
#include "tests/support/render_compare.h"
#include "tests/support/test_world.h"

namespace sb::test {
namespace {

struct GoldenView {
  const char* name;  // file stem in tests/golden/
  const char* map;
  float origin[3], yaw, pitch;
  double time;
};

constexpr int kWidth = 320, kHeight = 200;

// Chosen by looking (from test_viewpoints): lit walls at all four mips, sky, turbulent
// surfaces (teleports, slime) and animated textures between them.
const GoldenView kViews[] = {
    {"start_sky_hall", "start", {-1568.0f, -544.0f, 30.0f}, 345.0f, -15.0f, 1.0},
    {"start_high", "start", {-1560.0f, -504.0f, 184.0f}, -25.0f, 10.0f, 2.5},
    {"start_gates", "start", {-68.0f, -462.0f, -22.0f}, 270.0f, 10.0f, 4.0},
    {"start_teleports", "start", {-992.0f, -672.0f, 30.0f}, 330.0f, -15.0f, 7.25},
    {"lq_e0m1_sky", "lq_e0m1", {512.0f, 2048.0f, 326.0f}, 15.0f, 0.0f, 1.0},
    {"lq_e0m1_slime", "lq_e0m1", {300.0f, -898.0f, -184.0f}, 345.0f, 20.0f, 2.5},
    {"lq_e0m1_animated", "lq_e0m1", {-688.0f, 896.0f, 276.0f}, 270.0f, 20.0f, 4.0},
    {"lq_e0m1_hall", "lq_e0m1", {-928.0f, -144.0f, 64.0f}, 0.0f, 10.0f, 7.25},
};

ViewParams params(const GoldenView& g) {
  ViewParams v;
  v.origin = glm::vec3(g.origin[0], g.origin[1], g.origin[2]);
  v.yaw = g.yaw;
  v.pitch = g.pitch;
  return v;
}

class GoldenTest : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTest, MatchesApprovedImages) {
  SB_REQUIRE_QUAKE_DATA();
  SB_REQUIRE_PNG();  // the approved images are PNG files
  const std::string map = GetParam();
  TestWorld tw(map);
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  std::vector<uint8_t> colormap = load_colormap(), palette = load_game_palette();
  ASSERT_FALSE(colormap.empty());
  ASSERT_FALSE(palette.empty());
  const bool approve = [] {
    const char* e = std::getenv("STARBOW_APPROVE_GOLDEN");
    return e && std::string(e) == "1";
  }();
  const std::string golden_dir = std::string(STARBOW_SOURCE_DIR) + "/tests/golden";
  const std::string actual_dir = std::string(STARBOW_BINARY_DIR) + "/golden_actual";

  int checked = 0;
  for (const GoldenView& g : kViews) {
    if (map != g.map) continue;
    ++checked;
    ViewParams view = params(g);
    std::vector<uint8_t> actual;
    Status st = tw.render(view, kWidth, kHeight, g.time, nullptr, colormap.data(), &actual);
    ASSERT_TRUE(st.is_ok()) << g.name << ": " << st.message();
    IndexedImage image{kWidth, kHeight, actual};
    const std::string golden_path = golden_dir + "/" + g.name + ".png";

    if (approve) {
      // Never approve a picture the reference renderer disagrees with.
      ReferenceRenderer ref(ReferenceInputs{tw.world(), g.time, nullptr, colormap.data()});
      ReferenceFrame frame = ref.render(view, kWidth, kHeight);
      MismatchBreakdown b = classify_mismatches(ref, frame, actual.data(), kWidth);
      // Every mismatch explained (edge or neighbouring texel), as in agreement_test.cpp; the
      // per-view identical share is lower than the per-map 98% on sky-heavy views, whose
      // layer coordinates are stepped linearly between the exact samples.
      ASSERT_GE(b.agreement(), 0.95) << g.name << ": not approving, " << b.summary();
      ASSERT_LT(double(b.unexplained + b.mip) / double(b.pixels), 0.005)
          << g.name << ": not approving, " << b.summary();
      std::string err;
      ASSERT_TRUE(write_indexed_png(golden_path, image, palette, &err)) << err;
      std::cout << "[ golden ] approved " << golden_path << " (" << b.summary() << ")\n";
      continue;
    }

    IndexedImage golden;
    std::string err;
    if (!read_indexed_png(golden_path, &golden, &err)) {
      ADD_FAILURE() << g.name << ": no golden image (" << err
                    << "). Approve the current render with STARBOW_APPROVE_GOLDEN=1.";
      continue;
    }
    ASSERT_EQ(golden.width, kWidth) << golden_path;
    ASSERT_EQ(golden.height, kHeight) << golden_path;
    size_t differing = 0;
    for (size_t i = 0; i < actual.size(); ++i) differing += actual[i] != golden.pixels[i];
    if (differing == 0) continue;

    std::filesystem::create_directories(actual_dir);
    const std::string actual_path = actual_dir + "/" + g.name + ".png";
    write_indexed_png(actual_path, image, palette);
    // actual | golden | difference (red where they differ).
    std::vector<uint8_t> rgb(size_t(kWidth) * 3 * kHeight * 3, 0);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        size_t i = size_t(y) * kWidth + x;
        const uint8_t* a = &palette[actual[i] * 3];
        const uint8_t* b = &palette[golden.pixels[i] * 3];
        uint8_t* row = &rgb[size_t(y) * kWidth * 3 * 3];
        for (int k = 0; k < 3; ++k) {
          row[(x)*3 + k] = a[k];
          row[(x + kWidth) * 3 + k] = b[k];
          row[(x + 2 * kWidth) * 3 + k] = actual[i] != golden.pixels[i] ? (k == 0 ? 255 : 0) : uint8_t(b[k] / 3);
        }
      }
    write_rgb_png(actual_dir + "/" + g.name + "_diff.png", kWidth * 3, kHeight, rgb);
    ADD_FAILURE() << g.name << ": " << differing << " of " << actual.size()
                  << " pixels differ from the approved image " << golden_path << ".\n  Actual: " << actual_path
                  << "\n  Actual | approved | difference: " << actual_dir << "/" << g.name << "_diff.png"
                  << "\n  If the change is intended, approve it: STARBOW_APPROVE_GOLDEN=1 "
                  << "render_tests --gtest_filter='*Golden*'";
  }
  EXPECT_GT(checked, 0);
}

INSTANTIATE_TEST_SUITE_P(Maps, GoldenTest, ::testing::Values("start", "lq_e0m1"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });

}  // namespace
}  // namespace sb::test
