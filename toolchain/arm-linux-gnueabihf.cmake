# toolchain/arm-linux-gnueabihf.cmake: 32-bit ARM (ARMv7-A, hard float) with Debian's cross
# compiler, built for NEON: -mfpu=neon-vfpv4 (Cortex-A7/A15 class boards) so NEON kernels
# compile; the scalar references may be auto-vectorised with NEON too, so the target must
# have it.
#   apt-get install g++-arm-linux-gnueabihf qemu-user
#   cmake --preset cross-armhf && cmake --build --preset cross-armhf && ctest --preset cross-armhf
# Test binaries run under qemu-user through CMAKE_CROSSCOMPILING_EMULATOR (binfmt is not
# registered on our machines). What cross builds switch off is decided in cmake/StarbowCross.cmake.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR armv7l)
set(STARBOW_TARGET_TRIPLET arm-linux-gnueabihf)

set(CMAKE_C_COMPILER arm-linux-gnueabihf-gcc)
set(CMAKE_CXX_COMPILER arm-linux-gnueabihf-g++)
set(CMAKE_C_FLAGS_INIT "-march=armv7-a -mfpu=neon-vfpv4 -mfloat-abi=hard")
set(CMAKE_CXX_FLAGS_INIT "-march=armv7-a -mfpu=neon-vfpv4 -mfloat-abi=hard")

# The emulated CPU matches the compile flags (Cortex-A7: ARMv7-A with NEON and VFPv4).
set(STARBOW_QEMU_CPU "cortex-a7" CACHE STRING "qemu-arm -cpu for tests (e.g. cortex-a7, cortex-a15, max)")
set(CMAKE_CROSSCOMPILING_EMULATOR "qemu-arm;-L;/usr/${STARBOW_TARGET_TRIPLET};-cpu;${STARBOW_QEMU_CPU}")

# Libraries, headers and CMake packages come only from the target's tree.
set(CMAKE_FIND_ROOT_PATH /usr/${STARBOW_TARGET_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
