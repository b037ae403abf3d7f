// memory/cache.h: the evictable cache region (surfaces, later skins and sounds).
//
//   [hdr|block A][hdr|free][hdr|block B][hdr|block C] ...   address order, coalescing
//   LRU list:  most recent  B <-> A <-> C  least recent (evicted first)
//   hole list: every free block, linked through its first 8 payload bytes (first fit)
//
// Owners hold a CacheHandle (slot + generation), never a pointer that outlives a
// frame. get() returns nullptr once the block was evicted: the owner rebuilds.
// alloc() evicts least-recently-used blocks until a contiguous hole fits; blocks
// touched in the current frame are never evicted (that frame still draws from
// them), so a frame that needs more than the whole cache gets an invalid handle
// and last_failure() explains it. Nothing here touches the heap; the slot table
// comes from the caller (the permanent arena).
// Alignment: block payloads are 16-byte aligned.
#pragma once
#include <cstddef>
#include <cstdint>

namespace sb::mem {

struct CacheHandle {
  uint32_t slot = 0;  // 0 is never a valid slot
  uint32_t generation = 0;
  bool valid() const { return slot != 0; }
};

struct CacheSlot {
  uint32_t generation = 0;
  uint32_t block_offset = 0;  // offset of the block header; kNone when free
  uint32_t lru_prev = 0, lru_next = 0;
  uint32_t last_frame = 0;
  const char* name = nullptr;
};

struct CacheStats {
  size_t capacity = 0, used = 0, high_water = 0;
  uint32_t live_blocks = 0;
  uint64_t allocations = 0, evictions = 0, failures = 0;
};

class Cache {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  // slots: caller-owned table of max_slots entries (slot 0 is reserved).
  void init(const char* region_name, void* base, size_t capacity, CacheSlot* slots, uint32_t max_slots);

  // A block of `size` bytes, marked as used in `frame`. Invalid handle on failure.
  CacheHandle alloc(size_t size, const char* name, uint32_t frame);
  // The block's memory, marked as used in `frame` (most recent); nullptr if evicted.
  void* get(CacheHandle h, uint32_t frame);
  // Like get() but without touching the LRU order.
  void* peek(CacheHandle h) const;
  void free(CacheHandle h);
  void flush();  // evicts everything (map change)

  const char* name() const { return name_; }
  const CacheStats& stats() const { return stats_; }
  void failure_message(char* out, size_t out_size) const;
  // Walks the block list and LRU list checking every invariant (tests use it).
  bool check_consistency() const;

 private:
  struct Header;
  Header* header_at(uint32_t offset) const;
  uint32_t alloc_slot();
  void lru_unlink(uint32_t slot);
  void lru_push_front(uint32_t slot);
  uint32_t find_fit(uint32_t need) const;
  void hole_insert(uint32_t offset);  // free blocks are also on a list of holes (cache.cpp)
  void hole_remove(uint32_t offset);
  uint32_t release_block(uint32_t offset);  // returns offset of the coalesced free block

  const char* name_ = "cache";
  uint8_t* base_ = nullptr;
  uint32_t capacity_ = 0;
  CacheSlot* slots_ = nullptr;
  uint32_t max_slots_ = 0;
  uint32_t free_slot_head_ = 0;
  uint32_t lru_head_ = 0, lru_tail_ = 0;
  uint32_t hole_head_ = kNone;  // offset of the first free block on the hole list
  CacheStats stats_;
  size_t fail_size_ = 0;
  const char* fail_name_ = nullptr;
};

}  // namespace sb::mem
