// tests/formats/formats_test_util.h: arenas, file reading and an independent
// invariant checker for loaded worlds (shared by the formats tests).
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "memory/arena.h"

namespace sb::test {

// A level arena and a scratch arena on one heap block.
struct TestArenas {
  explicit TestArenas(size_t level_bytes = 96u << 20, size_t scratch_bytes = 16u << 20)
      : block(new (std::align_val_t(64)) uint8_t[level_bytes + scratch_bytes]) {
    level.init("level", block, level_bytes);
    scratch.init("scratch", block + level_bytes, scratch_bytes);
  }
  ~TestArenas() { ::operator delete[](block, std::align_val_t(64)); }
  TestArenas(const TestArenas&) = delete;
  TestArenas& operator=(const TestArenas&) = delete;
  uint8_t* block;
  mem::Arena level, scratch;
};

inline std::vector<uint8_t> read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::vector<uint8_t>((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Checks every guarantee bsp.h makes, by brute force; returns the number of
// violations (each reported with ADD_FAILURE up to a few). Touches every
// lightmap byte and texel the guarantees promise, so ASan sees bad pointers.
int check_world_invariants(const BspWorld& w);

}  // namespace sb::test
