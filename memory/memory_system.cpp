#include "memory/memory_system.h"

#include <cstdio>

namespace sb::mem {

RegionPlan region_plan(size_t total) {
  size_t sixteenth = (total / 16) & ~size_t(63);
  RegionPlan p;
  p.permanent = sixteenth * 2;  // framebuffer + zbuffer up to 1920x1080, tables, pak directories
  p.level = sixteenth * 5;
  p.cache = sixteenth * 5;
  p.frame_each = sixteenth;
  p.scratch = total - (p.permanent + p.level + p.cache + 2 * p.frame_each);
  return p;
}

bool MemorySystem::init(void* block, size_t size, char* error, size_t error_size) {
  if (size < kMinBlockMiB * kMiB) {
    std::snprintf(error, error_size, "memory block of %zu bytes is below the minimum of %zu MiB", size,
                  kMinBlockMiB);
    return false;
  }
  block_ = static_cast<uint8_t*>(block);
  size_ = size;
  RegionPlan p = region_plan(size);
  uint8_t* at = block_;
  permanent.init("permanent", at, p.permanent); at += p.permanent;
  level.init("level", at, p.level); at += p.level;
  uint8_t* cache_base = at; at += p.cache;
  frame_[0].init("frame", at, p.frame_each); at += p.frame_each;
  frame_[1].init("frame", at, p.frame_each); at += p.frame_each;
  scratch.init("scratch", at, p.scratch);

  // One slot per KiB of cache (a lit surface is rarely smaller), between 1024 and kCacheSlots.
  size_t want = p.cache / 1024;
  uint32_t slot_count = uint32_t(want < 1024 ? 1024 : (want > kCacheSlots ? kCacheSlots : want));
  auto* slots = permanent.push_array<CacheSlot>(slot_count, "cache slot table");
  if (!slots) {
    permanent.failure_message(error, error_size);
    return false;
  }
  cache.init("cache", cache_base, p.cache, slots, slot_count);
  frame_index_ = 0;
  frame_number_ = 0;
  return true;
}

uint32_t MemorySystem::begin_frame() {
  frame_index_ ^= 1;
  frame_[frame_index_].reset();
  return ++frame_number_;
}

void MemorySystem::report(ReportLine line, void* user) const {
  char buf[256];
  std::snprintf(buf, sizeof buf, "memory block: %.1f MiB", size_ / double(kMiB));
  line(user, buf);
  line(user, "region         size KiB    used KiB    high KiB");
  const Arena* arenas[] = {&permanent, &level, &frame_[0], &frame_[1], &scratch};
  const char* labels[] = {"permanent", "level", "frame 0", "frame 1", "scratch"};
  for (int i = 0; i < 5; ++i) {
    const Arena& a = *arenas[i];
    std::snprintf(buf, sizeof buf, "%-12s %10zu  %10zu  %10zu", labels[i], a.capacity() / 1024, a.used() / 1024,
                  a.high_water() / 1024);
    line(user, buf);
  }
  const CacheStats& cs = cache.stats();
  std::snprintf(buf, sizeof buf, "%-12s %10zu  %10zu  %10zu  (%u blocks, %llu allocs, %llu evictions)", "cache",
                cs.capacity / 1024, cs.used / 1024, cs.high_water / 1024, cs.live_blocks,
                (unsigned long long)cs.allocations, (unsigned long long)cs.evictions);
  line(user, buf);
  line(user, "largest named allocations:");
  for (int i = 0; i < 5; ++i) {
    if (i == 2 || i == 3) continue;  // frame contents change every frame; listed below
    NamedAllocation top[6];
    int n = arenas[i]->largest(top, 6);
    for (int k = 0; k < n; ++k) {
      std::snprintf(buf, sizeof buf, "  %-10s %-32s %10zu KiB", labels[i], top[k].name, top[k].size / 1024);
      line(user, buf);
    }
  }
  NamedAllocation top[6];
  int n = frame_[frame_index_].largest(top, 6);
  for (int k = 0; k < n; ++k) {
    std::snprintf(buf, sizeof buf, "  %-10s %-32s %10zu KiB", "frame", top[k].name, top[k].size / 1024);
    line(user, buf);
  }
}

}  // namespace sb::mem
