// tests/asm/dispatch_test.cpp: the in-order core detection asm/dispatch.cpp runs on aarch64
// Linux (cpuinfo_in_order), fed /proc/cpuinfo texts of real kinds of machine.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "asm/kernels.h"
#include "asm/variants.h"

namespace {

bool in_order(const std::string& text) {
  std::FILE* f = std::tmpfile();
  if (!f) {
    ADD_FAILURE() << "tmpfile failed";
    return false;
  }
  std::fwrite(text.data(), 1, text.size(), f);
  std::rewind(f);
  const bool r = sb::simd::detail::cpuinfo_in_order(f);
  std::fclose(f);
  return r;
}

// One processor block as aarch64 Linux prints it.
std::string core(int n, const char* implementer, const char* part) {
  return "processor\t: " + std::to_string(n) +
         "\nBogoMIPS\t: 38.40\nFeatures\t: fp asimd evtstrm crc32 cpuid\nCPU implementer\t: " + implementer +
         "\nCPU architecture: 8\nCPU variant\t: 0x0\nCPU part\t: " + part + "\nCPU revision\t: 4\n\n";
}

TEST(AsmDispatch, InOrderCoresOnly) {
  std::string a53;
  for (int i = 0; i < 4; ++i) a53 += core(i, "0x41", "0xd03");
  EXPECT_TRUE(in_order(a53));                                          // Raspberry Pi 3
  EXPECT_TRUE(in_order(core(0, "0x41", "0xd05") + core(1, "0x41", "0xd05")));  // A55
  EXPECT_TRUE(in_order(core(0, "0x41", "0xd04")));                     // A35
}

TEST(AsmDispatch, AnyOutOfOrderCoreKeepsNeon) {
  std::string a72;
  for (int i = 0; i < 4; ++i) a72 += core(i, "0x41", "0xd08");
  EXPECT_FALSE(in_order(a72));  // Raspberry Pi 4
  // big.LITTLE: four A53 and two A72 (RK3399): the out-of-order loop.
  std::string big_little;
  for (int i = 0; i < 4; ++i) big_little += core(i, "0x41", "0xd03");
  for (int i = 4; i < 6; ++i) big_little += core(i, "0x41", "0xd08");
  EXPECT_FALSE(in_order(big_little));
  EXPECT_FALSE(in_order(core(0, "0x51", "0xd03")));  // part 0xd03 of another implementer
}

TEST(AsmDispatch, NoCorePartsMeansNotInOrder) {
  EXPECT_FALSE(in_order(""));
  EXPECT_FALSE(in_order("processor\t: 0\nvendor_id\t: GenuineIntel\nmodel name\t: Intel(R) Xeon(R)\n"));
  EXPECT_FALSE(in_order("CPU implementer\t: 0x41\n"));                 // cut before the part
  EXPECT_FALSE(in_order("CPU part\n"));                                // no value
}

TEST(AsmDispatch, LongLinesAreReadInPieces) {
  // A "Features" line longer than the reader's buffer whose continuation looks like a part
  // line must not count as one (the reader takes 255 characters at a time: the split falls
  // just before "CPU part").
  const std::string long_line = "Features\t: " + std::string(244, 'x') + "CPU part\t: 0xd08\n";
  EXPECT_TRUE(in_order(core(0, "0x41", "0xd03") + long_line));
  EXPECT_FALSE(in_order(core(0, "0x41", "0xd03") + core(1, "0x41", "0xd08") + long_line));
}

}  // namespace

// override_active (benchmarks: bench/span_hist.cpp) makes active() the given table, over a
// forced scalar choice too, and nullptr gives back the choice as it was.
TEST(AsmDispatch, OverrideReplacesTheActiveTableUntilCleared) {
  const sb::simd::Kernels* before = &sb::simd::active();
  sb::simd::Kernels mine = *before;
  mine.name = "mine";
  sb::simd::override_active(&mine);
  EXPECT_EQ(&sb::simd::active(), &mine);
  const bool forced = sb::simd::scalar_forced();
  sb::simd::force_scalar(!forced);
  EXPECT_EQ(&sb::simd::active(), &mine);
  sb::simd::force_scalar(forced);
  sb::simd::override_active(nullptr);
  EXPECT_EQ(&sb::simd::active(), before);
  EXPECT_STRNE(sb::simd::active().name, "mine");
}
