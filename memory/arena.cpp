#include "memory/arena.h"

#include <cstdio>
#include <cstring>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#define SB_POISON(p, n) ASAN_POISON_MEMORY_REGION((p), (n))
#define SB_UNPOISON(p, n) ASAN_UNPOISON_MEMORY_REGION((p), (n))
#else
#define SB_POISON(p, n) ((void)(p), (void)(n))
#define SB_UNPOISON(p, n) ((void)(p), (void)(n))
#endif

namespace sb::mem {

void Arena::init(const char* region_name, void* base, size_t capacity) {
  name_ = region_name;
  base_ = static_cast<uint8_t*>(base);
  capacity_ = capacity;
  used_ = 0;
  high_water_ = 0;
  fail_name_ = nullptr;
  fail_size_ = 0;
  tracked_count_ = 0;
  SB_POISON(base_, capacity_);
}

void Arena::record_failure(size_t size, const char* name) {
  fail_name_ = name ? name : "unnamed";
  fail_size_ = size;
}

void* Arena::push(size_t size, const char* name, size_t align) {
  if (align < 16) align = 16;
  uintptr_t start = reinterpret_cast<uintptr_t>(base_) + used_;
  uintptr_t aligned = (start + (align - 1)) & ~(uintptr_t)(align - 1);
  size_t pad = aligned - start;
  if (size > capacity_ || pad > capacity_ - used_ || size > capacity_ - used_ - pad) {
    record_failure(size, name);
    return nullptr;
  }
  size_t offset = used_ + pad;
  used_ = offset + size;
  if (used_ > high_water_) high_water_ = used_;
  SB_UNPOISON(base_ + offset, size);
  track(name, offset, size);
  return base_ + offset;
}

void* Arena::push_zero(size_t size, const char* name, size_t align) {
  void* p = push(size, name, align);
  if (p) std::memset(p, 0, size);
  return p;
}

void Arena::pop_to(size_t mark) {
  if (mark >= used_) return;
  SB_UNPOISON(base_ + mark, used_ - mark);  // alignment gaps stay poisoned until now
#ifndef NDEBUG
  std::memset(base_ + mark, 0xCD, used_ - mark);
#endif
  SB_POISON(base_ + mark, used_ - mark);
  used_ = mark;
  int kept = 0;
  for (int i = 0; i < tracked_count_; ++i)
    if (tracked_[i].offset < mark) tracked_[kept++] = tracked_[i];
  tracked_count_ = kept;
}

void Arena::track(const char* name, size_t offset, size_t size) {
  NamedAllocation rec{name ? name : "unnamed", offset, size};
  if (tracked_count_ < kTracked) {
    tracked_[tracked_count_++] = rec;
    return;
  }
  int smallest = 0;
  for (int i = 1; i < kTracked; ++i)
    if (tracked_[i].size < tracked_[smallest].size) smallest = i;
  if (tracked_[smallest].size < size) tracked_[smallest] = rec;
}

int Arena::largest(NamedAllocation* out, int max) const {
  NamedAllocation tmp[kTracked];
  int n = tracked_count_;
  for (int i = 0; i < n; ++i) tmp[i] = tracked_[i];
  for (int i = 1; i < n; ++i) {  // insertion sort, biggest first
    NamedAllocation v = tmp[i];
    int j = i - 1;
    while (j >= 0 && tmp[j].size < v.size) { tmp[j + 1] = tmp[j]; --j; }
    tmp[j + 1] = v;
  }
  int count = n < max ? n : max;
  for (int i = 0; i < count; ++i) out[i] = tmp[i];
  return count;
}

void Arena::failure_message(char* out, size_t out_size) const {
  std::snprintf(out, out_size, "region '%s' cannot fit '%s' (%zu bytes): %zu of %zu bytes free", name_,
                fail_name_ ? fail_name_ : "?", fail_size_, capacity_ - used_, capacity_);
}

}  // namespace sb::mem
