// tests/toolchain/target_test.cpp: what the test binaries were compiled for and what they
// run on. Under the cross presets (toolchain/*.cmake) every test binary runs under qemu-user,
// so this is where a wrong compiler, wrong flags or a missing emulator shows first:
//   cross-aarch64  __aarch64__ and __ARM_NEON, 8-byte pointers, uname machine "aarch64"
//   cross-armhf    __arm__ (ARMv7), __ARM_NEON, hard-float calls, 4-byte pointers, "armv7l"
//   native         x86-64 with SSE2 (what the default presets build on our machines)
// It also runs one 16-lane vector add through the target's SIMD unit and checks it against
// scalar code: a kernel test in asm/ sees the same architecture and instructions.
#include <gtest/gtest.h>
#include <sys/utsname.h>

#include <cstdint>
#include <cstdio>
#include <string>

#if defined(__ARM_NEON)
#include <arm_neon.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

#define SB_STR(x) SB_STR2(x)
#define SB_STR2(x) #x

std::string compiled_for() {
  std::string s;
#if defined(__aarch64__)
  s = "aarch64 (__aarch64__)";
#elif defined(__arm__)
  s = "arm (__arm__, __ARM_ARCH " SB_STR(__ARM_ARCH) ")";
#elif defined(__x86_64__)
  s = "x86-64 (__x86_64__)";
#else
  s = "unknown architecture";
#endif
  const char* const features[] = {
#if defined(__ARM_NEON)
      "__ARM_NEON",
#endif
#if defined(__ARM_FEATURE_FMA)
      "__ARM_FEATURE_FMA",
#endif
#if defined(__ARM_PCS_VFP)
      "__ARM_PCS_VFP (hard float)",
#endif
#if defined(__SSE2__)
      "__SSE2__",
#endif
#if defined(__SSE4_1__)
      "__SSE4_1__",
#endif
#if defined(__AVX2__)
      "__AVX2__",
#endif
      nullptr};
  for (const char* const* f = features; *f; ++f) s += std::string(" ") + *f;
  return s;
}

std::string running_on() {
  utsname u{};
  return uname(&u) == 0 ? std::string(u.machine) : std::string("?");
}

// 16 bytes + 16 bytes, wrapping, through the SIMD unit when there is one.
void add16(const uint8_t* a, const uint8_t* b, uint8_t* out) {
#if defined(__ARM_NEON)
  vst1q_u8(out, vaddq_u8(vld1q_u8(a), vld1q_u8(b)));
#elif defined(__SSE2__)
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out),
                   _mm_add_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a)),
                                _mm_loadu_si128(reinterpret_cast<const __m128i*>(b))));
#else
  for (int i = 0; i < 16; ++i) out[i] = uint8_t(a[i] + b[i]);
#endif
}

TEST(Target, ReportsWhatItWasBuiltForAndRunsOn) {
#ifdef STARBOW_TARGET_TRIPLET
  const std::string triplet = STARBOW_TARGET_TRIPLET;
#else
  const std::string triplet = "native";
#endif
  const std::string machine = running_on();
  std::printf("[ target ] %s build: compiled for %s; running on %s; %zu-byte pointers\n", triplet.c_str(),
              compiled_for().c_str(), machine.c_str(), sizeof(void*));
  RecordProperty("compiled_for", compiled_for());
  RecordProperty("running_on", machine);

  if (triplet == "aarch64-linux-gnu") {
#if !defined(__aarch64__) || !defined(__ARM_NEON)
    ADD_FAILURE() << "cross-aarch64 build without __aarch64__ / __ARM_NEON";
#endif
    EXPECT_EQ(sizeof(void*), 8u);
    EXPECT_EQ(machine, "aarch64");
  } else if (triplet == "arm-linux-gnueabihf") {
#if !defined(__arm__) || !defined(__ARM_NEON) || !defined(__ARM_PCS_VFP) || __ARM_ARCH != 7
    ADD_FAILURE() << "cross-armhf build without ARMv7 + NEON + hard float (see toolchain/arm-linux-gnueabihf.cmake)";
#endif
    EXPECT_EQ(sizeof(void*), 4u);
    EXPECT_EQ(machine.rfind("armv7", 0), 0u) << machine;
  } else if (triplet == "native") {
#if defined(__x86_64__)
    EXPECT_EQ(machine, "x86_64");
#elif defined(__aarch64__)
    EXPECT_EQ(machine, "aarch64");
#endif
  } else {
    ADD_FAILURE() << "unknown target triplet " << triplet << ": teach this test about it";
  }
}

TEST(Target, SimdAddMatchesScalar) {
  uint8_t a[16], b[16], simd[16];
  for (int i = 0; i < 16; ++i) {
    a[i] = uint8_t(i * 37 + 200);
    b[i] = uint8_t(255 - i * 11);
  }
  add16(a, b, simd);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(simd[i], uint8_t(a[i] + b[i])) << "lane " << i;
}

}  // namespace
