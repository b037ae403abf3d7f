// tests/host/engine_includes_test.cpp: engine/ (and memory/, asm/) never include a
// platform or OS header. The arrows point one way: platform -> engine -> memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sb::test {
namespace {

// Header names (or prefixes) the engine must never include.
const char* const kForbidden[] = {"SDL", "sys/", "linux/", "unistd.h", "fcntl.h", "windows.h",
                                  "hidapi", "gpiod", "xf86drm", "asm/ioctl", "dlfcn.h", "pthread.h"};

// The forbidden header a line includes, or empty. Handles "# include", <> and "".
std::string forbidden_include(const std::string& line) {
  size_t p = line.find_first_not_of(" \t");
  if (p == std::string::npos || line[p] != '#') return {};
  p = line.find_first_not_of(" \t", p + 1);
  if (p == std::string::npos || line.compare(p, 7, "include") != 0) return {};
  size_t open = line.find_first_of("<\"", p + 7);
  if (open == std::string::npos) return {};
  size_t close = line.find_first_of(">\"", open + 1);
  std::string header = line.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1);
  for (const char* f : kForbidden) {
    // a match at the start of the header or after a '/' ("SDL2/SDL.h", "libdrm/xf86drm.h")
    for (size_t at = header.find(f); at != std::string::npos; at = header.find(f, at + 1))
      if (at == 0 || header[at - 1] == '/') return header;
  }
  return {};
}

TEST(EngineIncludes, MatcherCatchesForbiddenForms) {
  EXPECT_EQ(forbidden_include("#include <SDL.h>"), "SDL.h");
  EXPECT_EQ(forbidden_include("  #  include <SDL2/SDL_video.h>"), "SDL2/SDL_video.h");
  EXPECT_EQ(forbidden_include("#include <sys/mman.h>"), "sys/mman.h");
  EXPECT_EQ(forbidden_include("#include \"unistd.h\""), "unistd.h");
  EXPECT_EQ(forbidden_include("#include <linux/fb.h>"), "linux/fb.h");
  EXPECT_EQ(forbidden_include("#include <libdrm/xf86drm.h>"), "libdrm/xf86drm.h");
  EXPECT_EQ(forbidden_include("#include <hidapi/hidapi.h>"), "hidapi/hidapi.h");
  EXPECT_EQ(forbidden_include("#include <gpiod.h>"), "gpiod.h");
  EXPECT_EQ(forbidden_include("#include <windows.h>"), "windows.h");
  EXPECT_EQ(forbidden_include("#include <fcntl.h>"), "fcntl.h");
  EXPECT_EQ(forbidden_include("#include <cstdio>"), "");
  EXPECT_EQ(forbidden_include("#include \"engine/render/sys_view.h\""), "");  // not a sys/ folder
  EXPECT_EQ(forbidden_include("// #include <SDL.h> in a comment"), "");
}

TEST(EngineIncludes, EngineMemoryAndAsmIncludeNoPlatformHeader) {
  namespace fs = std::filesystem;
  std::vector<std::string> offenders;
  int files = 0;
  for (const char* dir : {"engine", "memory", "asm"}) {
    fs::path root = fs::path(STARBOW_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (!entry.is_regular_file()) continue;
      std::string ext = entry.path().extension().string();
      if (ext != ".h" && ext != ".hpp" && ext != ".cpp" && ext != ".cc" && ext != ".c" && ext != ".inl") continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        std::string h = forbidden_include(line);
        if (!h.empty()) offenders.push_back(entry.path().string() + ":" + std::to_string(n) + ": " + h);
      }
    }
  }
  EXPECT_GT(files, 10) << "scanned too few files under " << STARBOW_SOURCE_DIR;
  std::ostringstream all;
  for (const std::string& o : offenders) all << "\n  " << o;
  EXPECT_TRUE(offenders.empty()) << "platform/OS headers included by the engine:" << all.str();
}

}  // namespace
}  // namespace sb::test
