// tests/support/build_features.h: skip, visibly, tests that need something this build
// does not have. Cross builds (cmake/StarbowCross.cmake) define STARBOW_CROSSCOMPILING and
// STARBOW_TARGET_TRIPLET for every test, and STARBOW_NO_PNG comes with starbow_test_support
// when STARBOW_PNG is OFF. Use inside a TEST body or a fixture's SetUp (GTEST_SKIP returns
// from the enclosing function only).
#pragma once
#include <gtest/gtest.h>

// PNG files read or written through tests/support/png_image.h or libpng.
#ifdef STARBOW_NO_PNG
#define SB_REQUIRE_PNG() GTEST_SKIP() << "PNG support compiled out (STARBOW_PNG=OFF, e.g. a cross build): skipping"
#else
#define SB_REQUIRE_PNG() static_cast<void>(0)
#endif

// Starting the built programs (starbow, starbow_sdl) as child processes. A cross-built test
// runs under qemu-user; with binfmt unregistered its children (target binaries) cannot start.
#ifdef STARBOW_CROSSCOMPILING
#define SB_REQUIRE_NATIVE_PROGRAMS()                                                                     \
  GTEST_SKIP() << "cross build (" STARBOW_TARGET_TRIPLET "): the built programs cannot be started from " \
                  "a test under qemu-user; ctest runs starbow through the emulator instead (tests/toolchain)"
#else
#define SB_REQUIRE_NATIVE_PROGRAMS() static_cast<void>(0)
#endif
