#include "memory/cache.h"

#include <cstdio>
#include <cstring>

namespace sb::mem {

// Every block, free or used, starts with this header. size includes the header.
struct Cache::Header {
  uint32_t size;
  uint32_t prev_size;  // 0 for the first block
  uint32_t slot;       // 0 when free
  uint32_t pad;
};
static_assert(sizeof(uint32_t) * 4 == 16, "header is 16 bytes");
static constexpr uint32_t kHeader = 16;
static constexpr uint32_t kMinSplit = 64;
// Every block (so every hole) is at least kMinBlock bytes: a hole keeps its links to the
// neighbouring holes of the hole list in the first 8 bytes after its header.
static constexpr uint32_t kMinBlock = 32;

namespace {
struct HoleLinks {
  uint32_t next, prev;  // offsets of the next / previous hole, Cache::kNone at the ends
};
}  // namespace

Cache::Header* Cache::header_at(uint32_t offset) const {
  return reinterpret_cast<Header*>(base_ + offset);
}

static HoleLinks* links_at(uint8_t* base, uint32_t offset) {
  return reinterpret_cast<HoleLinks*>(base + offset + kHeader);
}

void Cache::hole_insert(uint32_t off) {
  HoleLinks* l = links_at(base_, off);
  l->prev = kNone;
  l->next = hole_head_;
  if (hole_head_ != kNone) links_at(base_, hole_head_)->prev = off;
  hole_head_ = off;
}

void Cache::hole_remove(uint32_t off) {
  HoleLinks* l = links_at(base_, off);
  if (l->prev != kNone) links_at(base_, l->prev)->next = l->next; else hole_head_ = l->next;
  if (l->next != kNone) links_at(base_, l->next)->prev = l->prev;
}

void Cache::init(const char* region_name, void* base, size_t capacity, CacheSlot* slots, uint32_t max_slots) {
  name_ = region_name;
  uintptr_t b = reinterpret_cast<uintptr_t>(base);
  uintptr_t aligned = (b + 15) & ~uintptr_t(15);
  size_t lost = aligned - b;
  capacity = capacity > lost ? capacity - lost : 0;
  if (capacity > 0xfffffff0u) capacity = 0xfffffff0u;
  capacity_ = static_cast<uint32_t>(capacity) & ~15u;
  base_ = reinterpret_cast<uint8_t*>(aligned);
  slots_ = slots;
  max_slots_ = max_slots;
  stats_ = CacheStats{};
  stats_.capacity = capacity_;
  flush();
}

void Cache::flush() {
  // Rebuild the free-slot chain and one free block spanning the region.
  free_slot_head_ = 0;
  for (uint32_t i = max_slots_; i-- > 1;) {
    slots_[i].block_offset = kNone;
    slots_[i].lru_next = free_slot_head_;
    slots_[i].generation += 1;
    free_slot_head_ = i;
  }
  lru_head_ = lru_tail_ = 0;
  hole_head_ = kNone;
  if (capacity_ >= kMinBlock) {
    Header* h = header_at(0);
    h->size = capacity_;
    h->prev_size = 0;
    h->slot = 0;
    hole_insert(0);
  }
  stats_.used = 0;
  stats_.live_blocks = 0;
}

uint32_t Cache::alloc_slot() {
  uint32_t s = free_slot_head_;
  if (s) free_slot_head_ = slots_[s].lru_next;
  return s;
}

void Cache::lru_unlink(uint32_t s) {
  CacheSlot& c = slots_[s];
  if (c.lru_prev) slots_[c.lru_prev].lru_next = c.lru_next; else lru_head_ = c.lru_next;
  if (c.lru_next) slots_[c.lru_next].lru_prev = c.lru_prev; else lru_tail_ = c.lru_prev;
  c.lru_prev = c.lru_next = 0;
}

void Cache::lru_push_front(uint32_t s) {
  CacheSlot& c = slots_[s];
  c.lru_prev = 0;
  c.lru_next = lru_head_;
  if (lru_head_) slots_[lru_head_].lru_prev = s; else lru_tail_ = s;
  lru_head_ = s;
}

// First fit over the holes only (most recently freed first): O(holes), not O(blocks), so a
// full cache with thousands of live surfaces does not walk them all on every allocation.
uint32_t Cache::find_fit(uint32_t need) const {
  for (uint32_t off = hole_head_; off != kNone; off = links_at(base_, off)->next) {
    if (header_at(off)->size >= need) return off;
  }
  return kNone;
}

uint32_t Cache::release_block(uint32_t off) {
  Header* h = header_at(off);
  h->slot = 0;
  uint32_t next = off + h->size;
  if (next < capacity_ && header_at(next)->slot == 0) {  // merge with the following hole
    hole_remove(next);
    h->size += header_at(next)->size;
  }
  bool merged = false;
  if (off > 0) {  // merge into the preceding hole (already on the hole list)
    uint32_t prev = off - h->prev_size;
    Header* p = header_at(prev);
    if (p->slot == 0) {
      p->size += h->size;
      off = prev;
      h = p;
      merged = true;
    }
  }
  if (!merged) hole_insert(off);
  uint32_t after = off + h->size;
  if (after < capacity_) header_at(after)->prev_size = h->size;
  return off;
}

CacheHandle Cache::alloc(size_t size, const char* name, uint32_t frame) {
  if (size > capacity_) {
    fail_size_ = size; fail_name_ = name; ++stats_.failures;
    return {};
  }
  uint32_t need = (static_cast<uint32_t>(size) + kHeader + 15u) & ~15u;
  if (need < kMinBlock) need = kMinBlock;
  uint32_t off = find_fit(need);
  while (off == kNone) {
    // Evict the least recently used block, unless the current frame still uses it.
    uint32_t victim = lru_tail_;
    if (!victim || slots_[victim].last_frame == frame) {
      fail_size_ = size; fail_name_ = name; ++stats_.failures;
      return {};
    }
    stats_.used -= header_at(slots_[victim].block_offset)->size;
    uint32_t freed = release_block(slots_[victim].block_offset);
    lru_unlink(victim);
    slots_[victim].block_offset = kNone;
    slots_[victim].generation += 1;
    slots_[victim].lru_next = free_slot_head_;
    free_slot_head_ = victim;
    ++stats_.evictions;
    --stats_.live_blocks;
    if (header_at(freed)->size >= need) off = freed;
  }
  uint32_t slot = alloc_slot();
  if (!slot) {
    fail_size_ = size; fail_name_ = name; ++stats_.failures;
    return {};
  }
  Header* h = header_at(off);
  hole_remove(off);
  if (h->size - need >= kMinSplit) {  // split off the tail as a new hole
    uint32_t rest = off + need;
    Header* r = header_at(rest);
    r->size = h->size - need;
    r->prev_size = need;
    r->slot = 0;
    uint32_t after = rest + r->size;
    if (after < capacity_) header_at(after)->prev_size = r->size;
    h->size = need;
    hole_insert(rest);
  }
  h->slot = slot;
  CacheSlot& c = slots_[slot];
  c.block_offset = off;
  c.last_frame = frame;
  c.name = name;
  lru_push_front(slot);
  ++stats_.allocations;
  ++stats_.live_blocks;
  stats_.used += h->size;
  if (stats_.used > stats_.high_water) stats_.high_water = stats_.used;
  return {slot, c.generation};
}

void* Cache::get(CacheHandle h, uint32_t frame) {
  if (!h.valid() || h.slot >= max_slots_) return nullptr;
  CacheSlot& c = slots_[h.slot];
  if (c.generation != h.generation || c.block_offset == kNone) return nullptr;
  c.last_frame = frame;
  if (lru_head_ != h.slot) {
    lru_unlink(h.slot);
    lru_push_front(h.slot);
  }
  return base_ + c.block_offset + kHeader;
}

void* Cache::peek(CacheHandle h) const {
  if (!h.valid() || h.slot >= max_slots_) return nullptr;
  const CacheSlot& c = slots_[h.slot];
  if (c.generation != h.generation || c.block_offset == kNone) return nullptr;
  return base_ + c.block_offset + kHeader;
}

void Cache::free(CacheHandle h) {
  if (!peek(h)) return;
  CacheSlot& c = slots_[h.slot];
  stats_.used -= header_at(c.block_offset)->size;
  release_block(c.block_offset);
  lru_unlink(h.slot);
  c.block_offset = kNone;
  c.generation += 1;
  c.lru_next = free_slot_head_;
  free_slot_head_ = h.slot;
  --stats_.live_blocks;
}

void Cache::failure_message(char* out, size_t out_size) const {
  std::snprintf(out, out_size,
                "region '%s' cannot fit '%s' (%zu bytes): %u bytes in all, every block in use this frame",
                name_, fail_name_ ? fail_name_ : "?", fail_size_, capacity_);
}

bool Cache::check_consistency() const {
  uint32_t prev_size = 0, live = 0, holes = 0;
  size_t used = 0;
  bool prev_free = false;
  for (uint32_t off = 0; off < capacity_;) {
    const Header* h = header_at(off);
    if (h->size < kHeader || (h->size & 15u) || off + h->size > capacity_) return false;
    if (h->prev_size != prev_size) return false;
    bool is_free = h->slot == 0;
    if (is_free && prev_free) return false;  // holes must be coalesced
    if (is_free) ++holes;
    if (!is_free) {
      if (h->slot >= max_slots_ || slots_[h->slot].block_offset != off) return false;
      ++live;
      used += h->size;
    }
    prev_free = is_free;
    prev_size = h->size;
    off += h->size;
  }
  uint32_t lru_count = 0;
  for (uint32_t s = lru_head_; s; s = slots_[s].lru_next) {
    if (++lru_count > max_slots_) return false;
  }
  // The hole list holds exactly the free blocks, linked both ways.
  uint32_t listed = 0, back = kNone;
  for (uint32_t off = hole_head_; off != kNone; off = links_at(base_, off)->next) {
    if (off >= capacity_ || header_at(off)->slot != 0 || ++listed > holes) return false;
    if (links_at(base_, off)->prev != back) return false;
    back = off;
  }
  if (listed != holes) return false;
  return live == stats_.live_blocks && lru_count == live && used == stats_.used;
}

}  // namespace sb::mem
