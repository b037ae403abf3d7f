// tests/formats/fs_test_util.h: temporary directories and a PAK writer for tests.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sb::test {

struct PakFileSpec {
  std::string name;
  std::vector<uint8_t> data;
};

// The bytes of a PAK holding `files` in order (data first, directory last).
std::vector<uint8_t> build_pak(const std::vector<PakFileSpec>& files);
void write_pak(const std::filesystem::path& path, const std::vector<PakFileSpec>& files);
void write_text(const std::filesystem::path& path, const std::string& text);

// A fresh directory under the system temp dir, removed on destruction.
struct TempDir {
  explicit TempDir(const char* tag);
  ~TempDir();
  std::filesystem::path path;
};

}  // namespace sb::test
