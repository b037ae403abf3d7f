// tests/host/sdl_scale_test.cpp: starbow_sdl's -scale K presentation (palette expansion and
// integer scaling on the CPU through asm/ expand_palette). SDL's dummy video driver saves
// every presented window surface as a BMP (SDL_VIDEO_DUMMY_SAVE_FRAMES=1): with -res 320x200
// -scale 3 the window is 960x600 and every 3x3 block of it is one colour. Skips visibly when
// starbow_sdl was not built or the LibreQuake data is absent.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/host/host_test_util.h"
#include "tests/support/build_features.h"
#include "tests/support/quake_data.h"

namespace sb::test {
namespace {

namespace fs = std::filesystem;

uint32_t le32(const std::vector<uint8_t>& b, size_t at) {
  return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8 | uint32_t(b[at + 2]) << 16 | uint32_t(b[at + 3]) << 24;
}

TEST(SdlScale, ScaleThreeExpandsEveryPixelToA3x3Block) {
  SB_REQUIRE_NATIVE_PROGRAMS();
  SB_REQUIRE_QUAKE_DATA();
  const std::string exe = std::string(STARBOW_BINARY_DIR) + "/starbow_sdl";
  if (!file_exists(exe)) GTEST_SKIP() << "starbow_sdl not built (STARBOW_SDL2=OFF or no SDL2)";
  const std::string dir = make_temp_dir("sdlscale");
  ASSERT_FALSE(dir.empty());
  std::string out;
  const int rc = run_command("cd '" + dir + "' && env -u DISPLAY SDL_VIDEODRIVER=dummy SDL_VIDEO_DUMMY_SAVE_FRAMES=1 '" +
                                 exe + "' -basedir '" + quake_dir() + "' -game lq1 -res 320x200 -scale 3 -frames 2 "
                                 "+viewmap start",
                             &out);
  EXPECT_EQ(rc, 0) << out;
  std::string bmp;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".bmp" && e.path().string() > bmp) bmp = e.path().string();  // the last frame
  ASSERT_FALSE(bmp.empty()) << "no frame saved; output:\n" << out;
  std::ifstream f(bmp, std::ios::binary);
  const std::vector<uint8_t> b((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  fs::remove_all(dir);
  ASSERT_GT(b.size(), 54u);
  const uint32_t off = le32(b, 10), w = le32(b, 18), h_raw = le32(b, 22);
  const int h = int32_t(h_raw) < 0 ? -int32_t(h_raw) : int32_t(h_raw);
  const int bpp = b[28] | b[29] << 8;
  ASSERT_EQ(w, 960u);
  ASSERT_EQ(h, 600);
  ASSERT_TRUE(bpp == 24 || bpp == 32) << bpp;
  const size_t px = size_t(bpp / 8), stride = (w * px + 3) & ~size_t(3);
  ASSERT_GE(b.size(), off + stride * size_t(h));
  auto at = [&](int x, int y) {  // any row order: blocks are 3 rows tall either way, 600 % 3 == 0
    const uint8_t* p = b.data() + off + size_t(y) * stride + size_t(x) * px;
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16;
  };
  int mismatches = 0, colours_seen = 0;
  uint32_t last = 0xffffffffu;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < int(w); ++x) {
      const uint32_t c = at(x, y);
      if (c != at(x - x % 3, y - y % 3)) ++mismatches;
      if (c != last) ++colours_seen, last = c;
    }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(colours_seen, 1000) << "the frame looks flat";
}

}  // namespace
}  // namespace sb::test
