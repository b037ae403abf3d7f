// engine/fs/padded_push.h: arena pushes whose sizes are rounded up to 16 bytes,
// used by engine/fs, engine/formats and engine/world.
//
// Why: every push is 16-byte aligned, so a push of an odd size leaves padding
// before the next one. That padding stays ASan-poisoned, and Arena::pop_to()
// in Debug builds memsets everything above the mark, padding included, which
// ASan reports as use-after-poison. With every size a multiple of 16 and the
// first mark aligned (align_mark), there is never padding to trip over. Drop
// this header once pop_to() unpoisons before it fills.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "memory/arena.h"

namespace sb::mem_util {

inline size_t round16(size_t n) { return n > SIZE_MAX - 15 ? SIZE_MAX : (n + 15) & ~size_t(15); }

// Zeroed memory for `size` bytes (at least 16 are taken); nullptr when it does not fit.
inline void* push_padded(mem::Arena& a, size_t size, const char* name) {
  size_t padded = round16(size ? size : 1);
  if (padded == SIZE_MAX) return a.push(SIZE_MAX, name);  // records the failure
  return a.push_zero(padded, name);
}

template <class T>
T* push_array_padded(mem::Arena& a, size_t count, const char* name) {
  static_assert(alignof(T) <= 16);
  if (count > SIZE_MAX / sizeof(T) / 2) return static_cast<T*>(a.push(SIZE_MAX, name));
  return static_cast<T*>(push_padded(a, count * sizeof(T), name));
}

// Moves the arena's position up to a 16-byte boundary (an empty push) and returns it.
inline size_t align_mark(mem::Arena& a) {
  a.push(0, "alignment");
  return a.mark();
}

}  // namespace sb::mem_util
