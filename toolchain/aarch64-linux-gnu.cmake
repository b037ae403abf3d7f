# toolchain/aarch64-linux-gnu.cmake: 64-bit ARM (ARMv8-A) with Debian's cross compiler.
#   apt-get install g++-aarch64-linux-gnu qemu-user
#   cmake --preset cross-aarch64 && cmake --build --preset cross-aarch64 && ctest --preset cross-aarch64
# Test binaries run under qemu-user through CMAKE_CROSSCOMPILING_EMULATOR (binfmt is not
# registered on our machines, so nothing runs an aarch64 ELF by itself). What cross builds
# switch off (PNG, SDL2, benchmarks, host tools) is decided in cmake/StarbowCross.cmake.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(STARBOW_TARGET_TRIPLET aarch64-linux-gnu)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# Baseline ARMv8-A (Advanced SIMD is architectural): the compiler's default, stated here.
set(CMAKE_C_FLAGS_INIT "-march=armv8-a")
set(CMAKE_CXX_FLAGS_INIT "-march=armv8-a")

# The emulated CPU matches the compile flags (Cortex-A53 is ARMv8.0-A), so an instruction the
# target board lacks traps under test instead of passing on qemu's default "max" CPU.
set(STARBOW_QEMU_CPU "cortex-a53" CACHE STRING "qemu-aarch64 -cpu for tests (e.g. cortex-a53, cortex-a72, max)")
set(CMAKE_CROSSCOMPILING_EMULATOR "qemu-aarch64;-L;/usr/${STARBOW_TARGET_TRIPLET};-cpu;${STARBOW_QEMU_CPU}")

# Libraries, headers and CMake packages come only from the target's tree, never from the
# host's /usr/lib/x86_64-linux-gnu (whose libpng, SDL2 and GTest would link-fail anyway).
set(CMAKE_FIND_ROOT_PATH /usr/${STARBOW_TARGET_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
