// tests/host/executables_test.cpp: the built programs end to end.
//   starbow       headless: screenshot PNG (exists, not uniform), -memstats table,
//                 flythrough figures, default run ends by itself
//   starbow_sdl   under xvfb-run: -frames 30 +screenshot; with no display: the clean
//                 fallback to headless (message, exit code 0)
// SDL tests skip visibly when starbow_sdl was not built (sanitize preset) or xvfb-run
// is missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/host/host_test_util.h"
#include "tests/support/build_features.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

std::string binary(const char* name) { return std::string(STARBOW_BINARY_DIR) + "/" + name; }

std::string content_args() { return "-basedir '" + quake_dir() + "' -game lq1"; }

void expect_good_png(const std::string& path, int w, int h) {
  ASSERT_TRUE(file_exists(path)) << path;
  int pw = 0, ph = 0;
  std::vector<uint8_t> rgb;
  std::string error;
  ASSERT_TRUE(read_png_rgb(path, &pw, &ph, &rgb, &error)) << error;
  EXPECT_EQ(pw, w);
  EXPECT_EQ(ph, h);
  EXPECT_GT(distinct_colours(rgb), 16) << path << " looks uniform";
}

class Executables : public ::testing::Test {
 protected:
  void SetUp() override {
    SB_REQUIRE_NATIVE_PROGRAMS();  // cross builds: tests/toolchain runs starbow through the emulator
    dir_ = make_temp_dir("exe");
    ASSERT_FALSE(dir_.empty());
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  std::string dir_;
};

TEST_F(Executables, HeadlessScreenshotIsAPictureAndMemstatsPrintsRegions) {
  SB_REQUIRE_QUAKE_DATA();
  ASSERT_TRUE(file_exists(binary("starbow"))) << "build the starbow target first";
  std::string png = dir_ + "/shot.png";
  std::string out;
  int rc = run_command("'" + binary("starbow") + "' " + content_args() +
                           " -memstats -res 320x240 +viewmap start +screenshot '" + png + "' +quit",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  expect_good_png(png, 320, 240);
  EXPECT_TRUE(contains(out, "region")) << out;
  for (const char* region : {"permanent", "level", "frame", "scratch", "cache"}) EXPECT_TRUE(contains(out, region)) << out;
}

TEST_F(Executables, HeadlessFlythroughPrintsFigures) {
  SB_REQUIRE_QUAKE_DATA();
  std::string out;
  int rc = run_command("'" + binary("starbow") + "' " + content_args() +
                           " -res 320x200 +viewmap lq_e0m1 +flythrough 30 +quit",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_TRUE(contains(out, "flythrough lq_e0m1 320x200: 30 frames")) << out;
  EXPECT_TRUE(contains(out, "ms/frame median")) << out;
  EXPECT_TRUE(contains(out, "ms worst")) << out;
}

TEST_F(Executables, HeadlessDefaultRunEndsByItself) {
  SB_REQUIRE_QUAKE_DATA();
  std::string out;
  // No + commands: the default map, a screenshot in the working directory, a flythrough, quit.
  int rc = run_command("cd '" + dir_ + "' && '" + binary("starbow") + "' " + content_args() + " -res 320x200", &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_TRUE(contains(out, "viewmap start:")) << out;
  EXPECT_TRUE(contains(out, "flythrough start 320x200: 300 frames")) << out;
  expect_good_png(dir_ + "/starbow_start.png", 320, 200);
}

TEST_F(Executables, HeadlessBadArgumentsFailWithAMessage) {
  std::string out;
  int rc = run_command("'" + binary("starbow") + "' -mem nothing", &out);
  EXPECT_NE(rc, 0);
  EXPECT_TRUE(contains(out, "-mem")) << out;
}

TEST_F(Executables, SdlUnderXvfbWritesAScreenshot) {
  SB_REQUIRE_QUAKE_DATA();
  if (!file_exists(binary("starbow_sdl"))) GTEST_SKIP() << "starbow_sdl not built (STARBOW_SDL2=OFF or no SDL2)";
  if (!program_on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run not installed: cannot test the SDL window";
  std::string png = dir_ + "/sdl.png";
  std::string out;
  int rc = run_command("env -u SDL_VIDEODRIVER xvfb-run -a -s '-screen 0 1024x768x24' '" + binary("starbow_sdl") +
                           "' " + content_args() + " -res 400x300 -frames 30 +viewmap start +screenshot '" + png + "'",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_FALSE(contains(out, "running headless")) << out;
  expect_good_png(png, 400, 300);
}

TEST_F(Executables, SdlWithoutDisplayFallsBackToHeadless) {
  SB_REQUIRE_QUAKE_DATA();
  if (!file_exists(binary("starbow_sdl"))) GTEST_SKIP() << "starbow_sdl not built (STARBOW_SDL2=OFF or no SDL2)";
  std::string png = dir_ + "/fallback.png";
  std::string out;
  int rc = run_command("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER '" + binary("starbow_sdl") + "' " +
                           content_args() + " -res 320x200 +viewmap start +screenshot '" + png + "' +quit",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_TRUE(contains(out, "running headless")) << out;
  expect_good_png(png, 320, 200);
}

TEST_F(Executables, SdlDummyDriverWhenNamedExplicitly) {
  SB_REQUIRE_QUAKE_DATA();
  if (!file_exists(binary("starbow_sdl"))) GTEST_SKIP() << "starbow_sdl not built (STARBOW_SDL2=OFF or no SDL2)";
  std::string out;
  int rc = run_command("env -u DISPLAY SDL_VIDEODRIVER=dummy '" + binary("starbow_sdl") + "' " + content_args() +
                           " -res 320x200 -frames 5 +viewmap start",
                       &out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_FALSE(contains(out, "running headless")) << out;
}

}  // namespace
}  // namespace sb::test
