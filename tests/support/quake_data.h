// tests/support/quake_data.h: where the real Quake-format content is, for data tests.
#pragma once
#include <string>

namespace sb::test {

// STARBOW_QUAKE_DIR (CMake cache variable), overridable by the environment variable
// of the same name. Empty when the folder does not exist.
std::string quake_dir();

// Skips the current test, with a visible message, when the content is absent.
#define SB_REQUIRE_QUAKE_DATA()                                                                 \
  do {                                                                                          \
    if (::sb::test::quake_dir().empty())                                                        \
      GTEST_SKIP() << "Quake data not found (set -DSTARBOW_QUAKE_DIR=...): skipping data test"; \
  } while (0)

}  // namespace sb::test
