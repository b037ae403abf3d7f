#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "memory/arena.h"
#include "memory/cache.h"
#include "memory/memory_system.h"

namespace sb::mem {
namespace {

TEST(Arena, PushAlignsAndTracksHighWater) {
  alignas(16) static uint8_t buf[4096];
  Arena a;
  a.init("test", buf, sizeof buf);
  void* p = a.push(10, "ten");
  void* q = a.push(100, "hundred");
  ASSERT_NE(p, nullptr);
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(q) % 16, 0u);
  EXPECT_GE(a.used(), 110u);
  size_t m = a.mark();
  a.push(1000, "big");
  size_t high = a.high_water();
  a.pop_to(m);
  EXPECT_EQ(a.used(), m);
  EXPECT_EQ(a.high_water(), high);
  NamedAllocation top[4];
  int n = a.largest(top, 4);
  ASSERT_EQ(n, 2);  // "big" was popped
  EXPECT_STREQ(top[0].name, "hundred");
}

TEST(Arena, ExhaustionIsAnErrorNamingRegionRequestAndBudget) {
  alignas(16) static uint8_t buf[1024];
  Arena a;
  a.init("level", buf, sizeof buf);
  EXPECT_EQ(a.push(2000, "bsp faces"), nullptr);
  EXPECT_EQ(a.push_array<uint64_t>(SIZE_MAX / 4, "huge"), nullptr);  // overflow-safe
  char msg[256];
  a.failure_message(msg, sizeof msg);
  EXPECT_NE(std::strstr(msg, "level"), nullptr) << msg;
  EXPECT_NE(std::strstr(msg, "huge"), nullptr) << msg;
  EXPECT_NE(std::strstr(msg, "1024"), nullptr) << msg;
  EXPECT_EQ(a.used(), 0u);
}

TEST(Arena, ScopePopsOnExit) {
  alignas(16) static uint8_t buf[1024];
  Arena a;
  a.init("scratch", buf, sizeof buf);
  a.push(32, "keep");
  size_t before = a.used();
  {
    ArenaScope scope(a);
    a.push(500, "temp");
    EXPECT_GT(a.used(), before);
  }
  EXPECT_EQ(a.used(), before);
}

struct CacheFixture : ::testing::Test {
  static constexpr size_t kSize = 64 * 1024;
  alignas(16) uint8_t buf[kSize];
  CacheSlot slots[256];
  Cache cache;
  void SetUp() override { cache.init("cache", buf, kSize, slots, 256); }
};

TEST_F(CacheFixture, AllocGetFree) {
  CacheHandle h = cache.alloc(1000, "surface", 1);
  ASSERT_TRUE(h.valid());
  void* p = cache.get(h, 1);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % 16, 0u);
  std::memset(p, 7, 1000);
  EXPECT_TRUE(cache.check_consistency());
  cache.free(h);
  EXPECT_EQ(cache.get(h, 1), nullptr);  // stale handle
  EXPECT_TRUE(cache.check_consistency());
}

TEST_F(CacheFixture, EvictsLeastRecentlyUsedNotCurrentFrame) {
  // Fill with 8 KiB blocks across frames 1..7, touch frame-1's block in frame 8.
  std::vector<CacheHandle> hs;
  for (uint32_t f = 1; f <= 7; ++f) hs.push_back(cache.alloc(8000, "s", f));
  for (auto& h : hs) ASSERT_TRUE(h.valid());
  ASSERT_NE(cache.get(hs[0], 8), nullptr);  // now most recent
  CacheHandle extra = cache.alloc(16000, "extra", 8);
  ASSERT_TRUE(extra.valid());
  EXPECT_NE(cache.peek(hs[0]), nullptr) << "recently used block was evicted";
  EXPECT_EQ(cache.peek(hs[1]), nullptr) << "least recently used block survived";
  EXPECT_GE(cache.stats().evictions, 1u);
  EXPECT_TRUE(cache.check_consistency());
}

TEST_F(CacheFixture, FailsClearlyWhenTheFrameNeedsMoreThanEverything) {
  CacheHandle a = cache.alloc(40000, "a", 3);
  ASSERT_TRUE(a.valid());
  CacheHandle b = cache.alloc(40000, "b", 3);  // a is in use this frame: cannot evict
  EXPECT_FALSE(b.valid());
  char msg[256];
  cache.failure_message(msg, sizeof msg);
  EXPECT_NE(std::strstr(msg, "'b'"), nullptr) << msg;
  CacheHandle c = cache.alloc(40000, "c", 4);  // next frame: a may go
  EXPECT_TRUE(c.valid());
  EXPECT_TRUE(cache.check_consistency());
}

TEST_F(CacheFixture, RandomisedStressKeepsInvariants) {
  // Sizes from 0 bytes up; every live block keeps its fill pattern (hole bookkeeping lives
  // inside free blocks and must never touch a live one).
  struct Live {
    CacheHandle h;
    size_t size;
    uint8_t fill;
  };
  std::mt19937 rng(1234);
  std::vector<Live> live;
  for (uint32_t frame = 1; frame < 400; ++frame) {
    for (int k = 0; k < 6; ++k) {
      size_t size = (rng() % 8 == 0) ? rng() % 24 : 16 + rng() % 6000;
      CacheHandle h = cache.alloc(size, "r", frame);
      if (h.valid()) {
        auto* p = static_cast<uint8_t*>(cache.get(h, frame));
        const uint8_t fill = uint8_t(rng());
        std::memset(p, fill, size);
        live.push_back({h, size, fill});
      }
      if (!live.empty() && rng() % 3 == 0) {
        size_t i = rng() % live.size();
        cache.free(live[i].h);
        live.erase(live.begin() + long(i));
      }
    }
    ASSERT_TRUE(cache.check_consistency()) << "frame " << frame;
    for (size_t i = 0; i < live.size();) {
      const auto* p = static_cast<const uint8_t*>(cache.peek(live[i].h));
      if (!p) {  // evicted: fine, the owner would rebuild
        live.erase(live.begin() + long(i));
        continue;
      }
      for (size_t b = 0; b < live[i].size; ++b) ASSERT_EQ(p[b], live[i].fill) << "frame " << frame;
      ++i;
    }
  }
  EXPECT_GT(cache.stats().evictions, 0u) << "the stress must reach the full-cache path";
}

TEST(MemorySystem, RegionsTileTheBlockAndFramesFlip) {
  std::vector<uint8_t> block(32 * kMiB);
  MemorySystem m;
  char err[256];
  ASSERT_TRUE(m.init(block.data(), block.size(), err, sizeof err)) << err;
  RegionPlan p = region_plan(block.size());
  EXPECT_EQ(p.permanent + p.level + p.cache + 2 * p.frame_each + p.scratch, block.size());
  Arena* f0 = &m.frame();
  f0->push(100, "x");
  m.begin_frame();
  EXPECT_NE(&m.frame(), f0);
  EXPECT_EQ(m.frame().used(), 0u);
  EXPECT_EQ(m.previous_frame().used(), f0->used());
  std::string text;
  m.report([](void* u, const char* line) { *static_cast<std::string*>(u) += std::string(line) + "\n"; }, &text);
  EXPECT_NE(text.find("level"), std::string::npos);
  EXPECT_NE(text.find("cache slot table"), std::string::npos);
}

TEST(MemorySystem, TheDocumentedMinimumBlockWorks) {
  std::vector<uint8_t> block(kMinBlockMiB * kMiB);
  MemorySystem m;
  char err[256];
  ASSERT_TRUE(m.init(block.data(), block.size(), err, sizeof err)) << err;
  EXPECT_TRUE(m.cache.alloc(4096, "surface", 1).valid());
}

TEST(MemorySystem, RejectsATinyBlock) {
  std::vector<uint8_t> block(1 * kMiB);
  MemorySystem m;
  char err[256];
  EXPECT_FALSE(m.init(block.data(), block.size(), err, sizeof err));
  EXPECT_NE(std::strstr(err, "minimum"), nullptr);
}

}  // namespace
}  // namespace sb::mem
