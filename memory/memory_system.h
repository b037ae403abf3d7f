// memory/memory_system.h: the one block and its regions.
//
//  low end                                                                 high end
//  [ permanent | level (BSP, models) | cache (LRU, evictable) | frame 0 | frame 1 | scratch ]
//    startup     reset on map change    surfaces                 one is reset     load temp
//                                                                 every frame
//
// The platform allocates the block once (size from -mem <MB>) and hands it to
// MemorySystem::init(). Region sizes are fixed fractions of the block (see
// region_plan()); nothing is ever taken from the heap afterwards.
// Lifetimes: permanent = process; level = until the next map load (reset());
// cache = until evicted (see cache.h); frame = current frame only (the other
// buffer holds the previous frame's data until begin_frame() flips again);
// scratch = inside an ArenaScope while loading.
#pragma once
#include <cstddef>
#include <cstdint>

#include "memory/arena.h"
#include "memory/cache.h"

namespace sb::mem {

constexpr size_t kMiB = 1024 * 1024;
constexpr size_t kDefaultBlockMiB = 128;  // fits a 1920x1080 session with a large map
constexpr size_t kMinBlockMiB = 16;

struct RegionPlan {
  size_t permanent, level, cache, frame_each, scratch;
};
// Splits `total` bytes among the regions (sixteenths: 2 / 5 / 5 / 1+1 / 2).
RegionPlan region_plan(size_t total);

using ReportLine = void (*)(void* user, const char* line);

class MemorySystem {
 public:
  static constexpr uint32_t kCacheSlots = 1u << 16;  // most cache blocks at once

  // Carves the regions out of block. Returns false with a message when the block
  // is too small to hold even the minimum plan.
  bool init(void* block, size_t size, char* error, size_t error_size);

  Arena permanent;
  Arena level;
  Arena scratch;
  Cache cache;

  Arena& frame() { return frame_[frame_index_]; }
  Arena& previous_frame() { return frame_[frame_index_ ^ 1]; }
  // Flips the frame buffers and resets the new current one. Returns the frame number.
  uint32_t begin_frame();
  uint32_t frame_number() const { return frame_number_; }

  size_t block_size() const { return size_; }
  // Per region: size, used, high-water, and the largest named allocations.
  void report(ReportLine line, void* user) const;

 private:
  uint8_t* block_ = nullptr;
  size_t size_ = 0;
  Arena frame_[2];
  int frame_index_ = 0;
  uint32_t frame_number_ = 0;
};

}  // namespace sb::mem
