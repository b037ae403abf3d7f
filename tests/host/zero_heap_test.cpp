// tests/host/zero_heap_test.cpp: after init, frames never touch the heap. KEEP THIS TEST.
//
// Every heap entry point of this test binary is counted while `g_counting` is set:
//  - normal builds: malloc / calloc / realloc / aligned_alloc / posix_memalign / memalign
//    are replaced here and forward to glibc's __libc_* functions; every operator new
//    form is replaced too (and allocates through the counted malloc);
//  - AddressSanitizer builds (ASan owns malloc): the sanitizer's malloc hook counts
//    every allocation, operator new included.
// The engine runs hundreds of frames of a real map with a moving camera, animated
// light styles, a resize and a flythrough, with the world drawn through the surface cache and
// single pass (r_singlepass); the count must stay 0.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/host/host_test_util.h"
#include "tests/support/quake_data.h"

#if defined(__SANITIZE_ADDRESS__)
#define SB_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SB_TEST_ASAN 1
#endif
#endif

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
inline void count() {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

#if defined(SB_TEST_ASAN)
// From the sanitizer runtime (GCC ships no header for it; clang's is sanitizer/allocator_interface.h).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, size_t),
                                                         void (*free_hook)(const volatile void*));
namespace {
void on_malloc(const volatile void*, size_t) { count(); }
void on_free(const volatile void*) {}
[[maybe_unused]] const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
}  // namespace
#else
extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);

void* malloc(size_t n) {
  count();
  return __libc_malloc(n);
}
void* calloc(size_t n, size_t s) {
  count();
  return __libc_calloc(n, s);
}
void* realloc(void* p, size_t n) {
  count();
  return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
void* memalign(size_t a, size_t n) {
  count();
  return __libc_memalign(a, n);
}
void* aligned_alloc(size_t a, size_t n) {
  count();
  return __libc_memalign(a, n);
}
int posix_memalign(void** out, size_t a, size_t n) {
  count();
  void* p = __libc_memalign(a, n);
  if (!p) return 12;  // ENOMEM
  *out = p;
  return 0;
}
}  // extern "C"

void* operator new(size_t n) {
  if (void* p = std::malloc(n ? n : 1)) return p;
  std::abort();  // tests build without exceptions (starbow_options)
}
void* operator new[](size_t n) { return operator new(n); }
void* operator new(size_t n, const std::nothrow_t&) noexcept { return std::malloc(n ? n : 1); }
void* operator new[](size_t n, const std::nothrow_t&) noexcept { return std::malloc(n ? n : 1); }
void* operator new(size_t n, std::align_val_t a) {
  if (void* p = aligned_alloc(size_t(a), (n + size_t(a) - 1) / size_t(a) * size_t(a))) return p;
  std::abort();  // tests build without exceptions (starbow_options)
}
void* operator new[](size_t n, std::align_val_t a) { return operator new(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { std::free(p); }
#endif

namespace sb::test {
namespace {

// The counter itself must work, or a 0 below would prove nothing.
TEST(ZeroHeap, CounterSeesAllocations) {
  g_allocations = 0;
  g_counting = true;
  void* volatile p = std::malloc(32);
  int* volatile q = new int(7);
  g_counting = false;
  std::free(p);
  delete q;
  EXPECT_GE(g_allocations.load(), 2);
}

TEST(ZeroHeap, HundredsOfFramesOfARealMapAllocateNothing) {
  SB_REQUIRE_QUAKE_DATA();
  capture_log_begin();
  {
    EngineSession engine({"-basedir", quake_dir(), "-game", "lq1", "-res", "640x480", "+viewmap", "lq_e0m1"}, 128,
                         1280, 720);
    ASSERT_TRUE(engine.init_status().is_ok()) << engine.init_status().message();
    HostFrame first = engine.frame();  // runs the + commands: loads the map (heap allowed until here)
    ASSERT_FALSE(first.quit);
    ASSERT_NE(captured_log().find("viewmap lq_e0m1:"), std::string::npos) << captured_log();

    g_allocations = 0;
    g_counting = true;
    for (int i = 0; i < 300; ++i) {
      HostInput in;
      in.forward = (i / 50) % 2 ? -1.0f : 1.0f;  // back and forth
      in.right = i % 3 == 0 ? 0.5f : 0.0f;
      in.yaw_delta = 1.5f;                       // keep turning: new surfaces enter the cache
      in.pitch_delta = (i % 40) < 20 ? 0.5f : -0.5f;
      in.fast = i % 7 == 0;
      if (i == 150) in.width = 1280, in.height = 720;  // a resize inside the reserved size
      if (i == 100) in.commands = "r_singlepass 1";      // single pass: light grids in the frame arena
      if (i == 130) in.commands = "r_singlepass 0";      // back to the surface cache
      if (i == 200) in.commands = "r_singlepass 1; flythrough 60";  // the timed path, single pass
      if (i == 270) in.commands = "r_singlepass 0";
      HostFrame f = engine.frame(in, 1.0 / 30.0);         // 10 s of light-style animation
      if (f.quit) break;
    }
    g_counting = false;
    long counted = g_allocations.load();
    EXPECT_EQ(counted, 0) << "heap allocations while rendering frames after init";
    std::string log = captured_log();
    EXPECT_NE(log.find("flythrough lq_e0m1 1280x720: 60 frames"), std::string::npos) << log;
  }
  capture_log_end();
}

}  // namespace
}  // namespace sb::test
