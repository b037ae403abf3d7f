// build_spans never touches the heap: a counting global operator new (this test binary
// only) must not move while it runs.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/render_front/front_test_util.h"
#include "tests/support/quake_data.h"
#include "engine/world/viewpoints.h"
#include "tests/support/test_world.h"

namespace {
std::atomic<size_t> g_heap_allocations{0};
}

void* operator new(size_t size) {
  g_heap_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  std::abort();  // tests build without exceptions (starbow_options)
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }

namespace sb::test::front {
namespace {

size_t heap_allocations_during_build(BspWorld& world, FrontRunner& runner, const ViewParams& p, int w, int h) {
  runner.arena().reset();
  render::ViewState view = render::setup_view(world, p, w, h, runner.next_frame());
  render::FrameSpans spans;
  RenderStats stats;
  size_t before = g_heap_allocations.load();
  Status s = render::build_spans(world, view, runner.arena(), &spans, &stats);
  size_t after = g_heap_allocations.load();
  EXPECT_TRUE(s.is_ok()) << s.message();
  return after - before;
}

TEST(FrontHeap, BuildSpansAllocatesNothing) {
  size_t before = g_heap_allocations.load();
  ::operator delete(::operator new(16));  // the counter works (a direct call is never elided)
  ASSERT_EQ(g_heap_allocations.load(), before + 1);
  auto room = make_pillar_room();
  FrontRunner runner;
  ViewParams p;
  p.origin = {-200, 30, 10};
  EXPECT_EQ(heap_allocations_during_build(room->world, runner, p, 640, 480), 0u);
  // Overflowing buffers must not reach for the heap either (and the warning is formatted
  // on the stack).
  FrontRunner small(40000);
  EXPECT_EQ(heap_allocations_during_build(room->world, small, p, 1280, 720), 0u);
}

TEST(FrontHeap, BuildSpansAllocatesNothingOnARealMap) {
  SB_REQUIRE_QUAKE_DATA();
  TestWorld tw("lq_e1m1");
  ASSERT_NE(tw.world(), nullptr) << tw.error();
  FrontRunner runner(tw.memory().frame().capacity());
  ViewParams views[8];
  int n = collect_viewpoints(*tw.world(), views, 8);
  for (int i = 0; i < n; ++i) EXPECT_EQ(heap_allocations_during_build(*tw.world(), runner, views[i], 1920, 1080), 0u);
}

}  // namespace
}  // namespace sb::test::front
