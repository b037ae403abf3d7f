// memory/arena.h: linear arenas carved from the one memory block.
//
//   base                         used            high_water        capacity
//   |<------ live allocations --->|                  |                 |
//   [ named push | named push | ...]...free............................]
//                   ^ mark: a position; pop_to(mark) frees everything above it
//
// An Arena never calls the heap. push() returns nullptr when the request does
// not fit and records the failure (region name, request, budget) so the caller
// can turn it into an error value with arena_failure_message(). Every push has a
// name; the arena keeps the largest named allocations for the memory report.
// Alignment: every push is aligned to at least 16 bytes (SIMD-safe).
// Lifetime: memory is valid until the arena is popped below it or reset.
// Debug builds fill popped memory with 0xCD and, under AddressSanitizer, poison it.
#pragma once
#include <cstddef>
#include <cstdint>

namespace sb::mem {

struct NamedAllocation {
  const char* name = nullptr;  // static string
  size_t offset = 0;
  size_t size = 0;
};

class Arena {
 public:
  static constexpr int kTracked = 24;  // largest named allocations kept per arena

  Arena() = default;
  void init(const char* region_name, void* base, size_t capacity);

  // Returns aligned memory or nullptr (with last_failure() set) when it does not fit.
  void* push(size_t size, const char* name, size_t align = 16);
  void* push_zero(size_t size, const char* name, size_t align = 16);
  template <class T>
  T* push_array(size_t count, const char* name) {
    if (count > SIZE_MAX / sizeof(T)) { record_failure(SIZE_MAX, name); return nullptr; }
    return static_cast<T*>(push_zero(count * sizeof(T), name, alignof(T) < 16 ? 16 : alignof(T)));
  }

  size_t mark() const { return used_; }
  void pop_to(size_t mark);
  void reset() { pop_to(0); }

  const char* name() const { return name_; }
  uint8_t* base() const { return base_; }
  size_t capacity() const { return capacity_; }
  size_t used() const { return used_; }
  size_t remaining() const { return capacity_ - used_; }
  size_t high_water() const { return high_water_; }
  bool contains(const void* p) const {
    auto* b = static_cast<const uint8_t*>(p);
    return b >= base_ && b < base_ + capacity_;
  }

  // The last failed request: its name and size (0 when none has failed).
  const char* last_failure_name() const { return fail_name_; }
  size_t last_failure_size() const { return fail_size_; }
  // "region 'level' cannot fit 'bsp faces' (1234567 bytes): 1000 of 4000 bytes free"
  void failure_message(char* out, size_t out_size) const;

  // Largest live named allocations, biggest first; returns the count written.
  int largest(NamedAllocation* out, int max) const;

 private:
  void record_failure(size_t size, const char* name);
  void track(const char* name, size_t offset, size_t size);

  const char* name_ = "unnamed";
  uint8_t* base_ = nullptr;
  size_t capacity_ = 0;
  size_t used_ = 0;
  size_t high_water_ = 0;
  const char* fail_name_ = nullptr;
  size_t fail_size_ = 0;
  NamedAllocation tracked_[kTracked] = {};
  int tracked_count_ = 0;
};

// A temporary scope: everything pushed while it lives is popped when it ends.
class ArenaScope {
 public:
  explicit ArenaScope(Arena& a) : arena_(a), mark_(a.mark()) {}
  ~ArenaScope() { arena_.pop_to(mark_); }
  ArenaScope(const ArenaScope&) = delete;
  ArenaScope& operator=(const ArenaScope&) = delete;
  Arena& arena() { return arena_; }

 private:
  Arena& arena_;
  size_t mark_;
};

}  // namespace sb::mem
