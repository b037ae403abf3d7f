#include "tests/formats/fs_test_util.h"

#include <atomic>
#include <cstring>
#include <fstream>
#include <random>

namespace sb::test {

std::vector<uint8_t> build_pak(const std::vector<PakFileSpec>& files) {
  std::vector<uint8_t> out(12, 0);
  std::memcpy(out.data(), "PACK", 4);
  std::vector<uint8_t> dir;
  for (const PakFileSpec& f : files) {
    int32_t pos = int32_t(out.size()), len = int32_t(f.data.size());
    out.insert(out.end(), f.data.begin(), f.data.end());
    uint8_t e[64] = {};
    std::memcpy(e, f.name.data(), f.name.size() < 55 ? f.name.size() : 55);
    std::memcpy(e + 56, &pos, 4);
    std::memcpy(e + 60, &len, 4);
    dir.insert(dir.end(), e, e + 64);
  }
  int32_t dirofs = int32_t(out.size()), dirlen = int32_t(dir.size());
  out.insert(out.end(), dir.begin(), dir.end());
  std::memcpy(out.data() + 4, &dirofs, 4);
  std::memcpy(out.data() + 8, &dirlen, 4);
  return out;
}

void write_pak(const std::filesystem::path& path, const std::vector<PakFileSpec>& files) {
  auto bytes = build_pak(files);
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TempDir::TempDir(const char* tag) {
  static std::atomic<int> counter{0};
  std::random_device rd;
  path = std::filesystem::temp_directory_path() /
         ("starbow_" + std::string(tag) + "_" + std::to_string(rd()) + "_" + std::to_string(counter++));
  std::filesystem::create_directories(path);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path, ec);
}

}  // namespace sb::test
