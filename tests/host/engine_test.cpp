// tests/host/engine_test.cpp: the host in-process: startup, commands, bad input
// (the engine reports and keeps running), resize, screenshot, flythrough.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/host/host_test_util.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

bool uniform(const HostFrame& f) {
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x)
      if (f.pixels[y * f.stride + x] != f.pixels[0]) return false;
  return true;
}

void write_file(const fs::path& path, const std::vector<uint8_t>& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<uint8_t> read_file(const fs::path& path, size_t max = SIZE_MAX) {
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() > max) bytes.resize(max);
  return bytes;
}

class HostTest : public ::testing::Test {
 protected:
  void SetUp() override { capture_log_begin(); }
  void TearDown() override { capture_log_end(); }
};

TEST_F(HostTest, TruncatedBspInTempDirIsAnErrorAndTheEngineKeepsRunning) {
  std::string dir = make_temp_dir("trunc");
  ASSERT_FALSE(dir.empty());
  // A BSP29 header cut off after 40 bytes: version 29, then lump directory garbage.
  std::vector<uint8_t> bytes(40, 0xee);
  bytes[0] = 29, bytes[1] = bytes[2] = bytes[3] = 0;
  write_file(fs::path(dir) / "lq1/maps/trunc.bsp", bytes);
  write_file(fs::path(dir) / "lq1/maps/empty.bsp", {});
  EngineSession engine({"-basedir", dir, "-game", "lq1", "+map", "trunc", "+echo", "after-trunc", "+map", "empty",
                        "+echo", "after-empty", "+map", "nosuchmap", "+echo", "still-alive"});
  ASSERT_TRUE(engine.init_status().is_ok()) << engine.init_status().message();
  HostFrame f = engine.frame();
  EXPECT_FALSE(f.quit);
  ASSERT_NE(f.pixels, nullptr);
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "error: map trunc: ")) << log;
  EXPECT_TRUE(contains(log, "maps/trunc.bsp")) << log;
  EXPECT_TRUE(contains(log, "after-trunc")) << log;
  EXPECT_TRUE(contains(log, "error: map empty: ")) << log;
  EXPECT_TRUE(contains(log, "after-empty")) << log;
  EXPECT_TRUE(contains(log, "maps/nosuchmap.bsp")) << log;
  EXPECT_TRUE(contains(log, "still-alive")) << log;
  // Commands still work, frames still come.
  f = engine.frame("viewpos 1 2 3\nflythrough 5\necho next-works");
  EXPECT_TRUE(contains(captured_log(), "flythrough: no map loaded")) << captured_log();
  EXPECT_TRUE(contains(captured_log(), "next-works")) << captured_log();
  f = engine.frame("quit");
  EXPECT_TRUE(f.quit);
  fs::remove_all(dir);
}

TEST_F(HostTest, TruncatedRealBspThenAGoodMap) {
  SB_REQUIRE_QUAKE_DATA();
  std::string dir = make_temp_dir("half");
  fs::path start = fs::path(quake_dir()) / "lq1/maps/start.bsp";
  std::vector<uint8_t> whole = read_file(start);
  ASSERT_GT(whole.size(), 1000u);
  write_file(fs::path(dir) / "lq1/maps/half.bsp", std::vector<uint8_t>(whole.begin(), whole.begin() + whole.size() / 2));
  write_file(fs::path(dir) / "lq1/maps/good.bsp", whole);
  EngineSession engine({"-basedir", dir, "+map", "half", "+map", "good", "+screenshot", dir + "/good.png"});
  ASSERT_TRUE(engine.init_status().is_ok()) << engine.init_status().message();
  HostFrame f = engine.frame();
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "error: map half: ")) << log;
  EXPECT_TRUE(contains(log, "map good: 1105 faces")) << log;
  EXPECT_FALSE(uniform(f));
  EXPECT_TRUE(file_exists(dir + "/good.png"));
  fs::remove_all(dir);
}

TEST_F(HostTest, GameFolderLayersOverTheBaseGame) {
  SB_REQUIRE_QUAKE_DATA();
  std::string dir = make_temp_dir("game");
  std::vector<uint8_t> start = read_file(fs::path(quake_dir()) / "lq1/maps/start.bsp");
  write_file(fs::path(dir) / "lq1/maps/base_only.bsp", start);
  write_file(fs::path(dir) / "lq1/maps/both.bsp", start);
  write_file(fs::path(dir) / "mymod/maps/mod_only.bsp", start);
  write_file(fs::path(dir) / "mymod/maps/both.bsp", {1, 2, 3});  // the mod's copy wins: broken on purpose
  EngineSession engine({"-basedir", dir, "-game", "mymod", "+map", "base_only", "+map", "mod_only", "+map", "both"});
  ASSERT_TRUE(engine.init_status().is_ok()) << engine.init_status().message();
  engine.frame();
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "map base_only: 1105 faces")) << log;
  EXPECT_TRUE(contains(log, "map mod_only: 1105 faces")) << log;
  EXPECT_TRUE(contains(log, "error: map both: ")) << log;
  fs::remove_all(dir);
}

TEST_F(HostTest, BadCommandsReportAndKeepRunning) {
  SB_REQUIRE_QUAKE_DATA();
  EngineSession engine({"-basedir", quake_dir(), "-game", "lq1", "+viewmap", "start"});
  ASSERT_TRUE(engine.init_status().is_ok());
  engine.frame();
  engine.frame("viewpos 1 2\nviewpos a b c\nfov 500\nnosuchcommand 1\nflythrough -3\nscreenshot\n"
               "map\nviewmap does_not_exist\necho survived");
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "usage: viewpos")) << log;
  EXPECT_TRUE(contains(log, "fov: 500 is outside")) << log;
  EXPECT_TRUE(contains(log, "unknown command \"nosuchcommand\"")) << log;
  EXPECT_TRUE(contains(log, "usage: flythrough")) << log;
  EXPECT_TRUE(contains(log, "usage: screenshot")) << log;
  EXPECT_TRUE(contains(log, "maps/does_not_exist.bsp")) << log;
  EXPECT_TRUE(contains(log, "survived")) << log;
  HostFrame f = engine.frame("viewmap start");
  EXPECT_FALSE(uniform(f));
}

TEST_F(HostTest, DefaultStartupViewsStartFromThePlayerStart) {
  SB_REQUIRE_QUAKE_DATA();
  EngineSession engine({"-basedir", quake_dir(), "-res", "320x200"});
  ASSERT_TRUE(engine.init_status().is_ok());
  HostFrame f = engine.frame();
  EXPECT_TRUE(contains(captured_log(), "viewmap start:")) << captured_log();
  EXPECT_EQ(f.width, 320);
  EXPECT_EQ(f.height, 200);
  EXPECT_FALSE(uniform(f));
  ASSERT_NE(f.palette, nullptr);
}

TEST_F(HostTest, MissingContentSaysHowToPointBasedir) {
  EngineSession engine({"-basedir", "/nonexistent/starbow/content"});
  ASSERT_TRUE(engine.init_status().is_ok()) << engine.init_status().message();
  HostFrame f = engine.frame("quit");
  EXPECT_TRUE(f.quit);
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "-basedir")) << log;
  EXPECT_TRUE(contains(log, "/nonexistent/starbow/content")) << log;
}

TEST_F(HostTest, ResizeWithinTheReservedSizeAndClampAbove) {
  SB_REQUIRE_QUAKE_DATA();
  EngineSession engine({"-basedir", quake_dir(), "+viewmap", "start"}, 96, 800, 600);
  ASSERT_TRUE(engine.init_status().is_ok());
  HostInput in;
  in.width = 800, in.height = 600;
  HostFrame f = engine.frame(in, 0.01);
  EXPECT_EQ(f.width, 800);
  EXPECT_EQ(f.height, 600);
  EXPECT_FALSE(uniform(f));
  in.width = 1000, in.height = 700;  // above the reservation: clamped, warned once
  f = engine.frame(in, 0.01);
  EXPECT_EQ(f.width, 800);
  EXPECT_EQ(f.height, 600);
  EXPECT_TRUE(contains(captured_log(), "larger than the 800x600 reserved")) << captured_log();
  in.width = 100, in.height = 50;  // below the minimum: clamped to 320x200
  f = engine.frame(in, 0.01);
  EXPECT_EQ(f.width, 320);
  EXPECT_EQ(f.height, 200);
}

// r_lightstyles 2 (the benchmark's "dynamic" light, bench/singlepass_arm.py): every style value
// changes every frame (240, 248, 256, 264 in turn), so a still view changes from frame to frame
// and differs from r_lightstyles 0 (all 256) in most frames. Both paths draw the same picture.
TEST_F(HostTest, LightStylesTwoChangesEveryStyleEveryFrame) {
  SB_REQUIRE_QUAKE_DATA();
  std::vector<std::vector<uint8_t>> pics[2][2];  // [mode 0 / 2][cached / single] frames
  for (int m = 0; m < 2; ++m) {
    for (int single = 0; single < 2; ++single) {
      EngineSession engine({"-basedir", quake_dir(), "-res", "320x200", "+viewmap", "start", "+r_lightstyles",
                            m ? "2" : "0", "+r_singlepass", single ? "1" : "0"});
      ASSERT_TRUE(engine.init_status().is_ok());
      for (int k = 0; k < 8; ++k) {
        HostFrame f = engine.frame();
        ASSERT_NE(f.pixels, nullptr);
        std::vector<uint8_t> pic;
        for (int y = 0; y < f.height; ++y) pic.insert(pic.end(), f.pixels + y * f.stride, f.pixels + y * f.stride + f.width);
        pics[m][single].push_back(pic);
      }
    }
  }
  int changes = 0, unlike_static = 0;
  for (size_t k = 2; k < 8; ++k) {
    changes += pics[1][0][k] != pics[1][0][k - 1];
    unlike_static += pics[1][0][k] != pics[0][0][k];
  }
  EXPECT_GE(changes, 5) << "r_lightstyles 2: the picture should change every frame";
  EXPECT_GE(unlike_static, 4) << "r_lightstyles 2: most frames should differ from all-normal styles";
  for (int m = 0; m < 2; ++m)
    for (size_t k = 0; k < 8; ++k) EXPECT_TRUE(pics[m][0][k] == pics[m][1][k]) << "mode " << m << " frame " << k;
}

TEST_F(HostTest, FlythroughPrintsFiguresThenRunsTheRestOfTheBuffer) {
  SB_REQUIRE_QUAKE_DATA();
  EngineSession engine({"-basedir", quake_dir(), "-res", "320x200", "+viewmap", "start", "+flythrough", "20",
                        "+echo", "after-flight", "+quit"});
  ASSERT_TRUE(engine.init_status().is_ok());
  int frames = 0;
  HostFrame f;
  do {
    f = engine.frame();
    ++frames;
    if (frames == 10) {
      EXPECT_FALSE(contains(captured_log(), "after-flight"));  // held while flying
    }
  } while (!f.quit && frames < 100);
  EXPECT_TRUE(f.quit);
  EXPECT_EQ(frames, 21);  // 20 flight frames, then the rest of the buffer (echo, quit)
  std::string log = captured_log();
  EXPECT_TRUE(contains(log, "flythrough start 320x200: 20 frames,")) << log;
  EXPECT_TRUE(contains(log, "ms/frame median")) << log;
  EXPECT_TRUE(contains(log, "after-flight")) << log;
}

TEST_F(HostTest, InitFailsCleanlyOnBadInput) {
  {
    EngineSession engine({"-res", "wide"});
    EXPECT_FALSE(engine.init_status().is_ok());
    EXPECT_TRUE(contains(engine.init_status().message(), "-res"));
  }
  {
    EngineSession engine({}, 8);  // below the memory minimum
    EXPECT_FALSE(engine.init_status().is_ok());
    EXPECT_TRUE(contains(engine.init_status().message(), "memory"));
  }
  HostInput in;
  HostFrame f = engine_frame(in, 0.0);  // no engine: asks to quit, no crash
  EXPECT_TRUE(f.quit);
}

}  // namespace
}  // namespace sb::test
