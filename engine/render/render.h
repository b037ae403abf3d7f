// engine/render/render.h: the world renderer's public face.
//
// One frame:  setup_view -> mark PVS leaves -> BSP walk front to back -> edge list
//             -> spans per surface (front end, edge_list.cpp)
//             -> per surface: surface cache fetch/build -> span drawer (back end)
// Every screen pixel is written exactly once per frame (tests check it).
// Memory: the renderer's working arrays come from the frame arena; lit surfaces
// from the cache region. After init it never touches the heap.
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/core/error.h"
#include "engine/formats/bsp.h"
#include "engine/world/view_params.h"  // ViewParams
#include "memory/memory_system.h"

namespace sb {

// The 8-bit target. zbuffer (optional) gets 1/z of every drawn world pixel, as
// 16.16 fixed point scaled by 0x8000 (Quake's convention), for later model passes.
struct Framebuffer {
  uint8_t* pixels = nullptr;
  int width = 0, height = 0, stride = 0;  // stride in bytes
  uint16_t* zbuffer = nullptr;            // width * height entries, or nullptr
  // Test hook: when set, every pixel write adds one to the matching entry.
  uint8_t* coverage = nullptr;            // width * height entries, or nullptr
};

constexpr int kMaxLightStyleSlots = 64;
constexpr int kLightStyleNormal = 256;  // 'm' in Quake's style strings

struct RenderInputs {
  BspWorld* world = nullptr;  // the renderer keeps per-face state (cache handles) in it
  ViewParams view;
  double time = 0.0;                       // seconds: sky scroll, turbulence, texture animation
  const int* lightstyles = nullptr;        // kMaxLightStyleSlots values, 256 = normal; nullptr = all normal
  const uint8_t* colormap = nullptr;       // 64 rows x 256 (row 0 brightest)
  // Between the exact divides every 16 pixels: true = linear plus a second-order term that
  // follows the perspective curve (default); false = purely linear, as Quake stepped.
  bool span_second_order = true;
  // World surfaces: false = lit surfaces from the surface cache (default); true = single pass,
  // texture and light combined per pixel by the span drawer (asm/lit_span.h), no cache.
  // Both give the same pixels (tests/render_back/single_pass_test.cpp). Sky and turbulent
  // surfaces draw the same way either way.
  bool single_pass = false;
};

struct RenderStats {
  uint32_t visible_leaves = 0, nodes_visited = 0, faces_emitted = 0;
  uint32_t edges = 0, surfaces = 0, spans = 0;
  uint32_t surfaces_built = 0, surface_cache_hits = 0;
  uint32_t single_pass_surfaces = 0;  // lit surfaces drawn single pass (RenderInputs::single_pass)
  uint32_t mip_counts[4] = {};
  bool edges_overflowed = false, surfaces_overflowed = false, spans_overflowed = false;
  bool cache_exhausted = false;
};

// Draws the world into fb. Warnings about overflowing buffers are logged once per
// level; the frame still draws what fits (and every pixel is still written).
Status render_world(const RenderInputs& in, Framebuffer& fb, mem::MemorySystem& memory, RenderStats* stats);

// Forget per-level renderer state (call after loading a new world).
void render_new_level(BspWorld& world);

}  // namespace sb
