// tests/support/no_png/png_image_off.cpp: png_image.h for builds without libpng
// (STARBOW_PNG=OFF, which cross builds choose: cmake/StarbowCross.cmake). Replaces
// png_image.cpp there. PNG reading and writing return false with a message saying why;
// tests that need PNG files call SB_REQUIRE_PNG() (tests/support/build_features.h) and skip.
// The two plain file helpers behave as in png_image.cpp.
#include <cstdio>
#include <memory>

#include "tests/support/png_image.h"

namespace sb::test {
namespace {

constexpr const char* kNoPng = ": PNG support compiled out (STARBOW_PNG=OFF: no libpng for this target)";

bool compiled_out(const std::string& path, std::string* error) {
  if (error) *error = path + kNoPng;
  return false;
}

}  // namespace

std::vector<uint8_t> read_file_bytes(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!f) return {};
  std::vector<uint8_t> data;
  uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f.get())) > 0) data.insert(data.end(), buf, buf + n);
  return data;
}

std::vector<uint8_t> load_palette(const std::string& path) {
  std::vector<uint8_t> p = read_file_bytes(path);
  if (p.size() != 768) return {};
  return p;
}

bool write_indexed_png(const std::string& path, const IndexedImage&, const std::vector<uint8_t>&, std::string* error) {
  return compiled_out(path, error);
}

bool read_indexed_png(const std::string& path, IndexedImage*, std::string* error) { return compiled_out(path, error); }

bool write_rgb_png(const std::string& path, int, int, const std::vector<uint8_t>&, std::string* error) {
  return compiled_out(path, error);
}

}  // namespace sb::test
