// tests/support/test_world.h: a real map loaded the way the engine loads it, for render tests.
//
// TestWorld owns a heap block (test code) carved by sb::mem::MemorySystem; the BSP is parsed
// by sb::load_bsp into memory.level and handed to render_new_level. Also here: the real
// colormap and palette, and a deterministic set of viewpoints derived from entity origins.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "memory/memory_system.h"

namespace sb::test {

class TestWorld {
 public:
  // Loads <quake_dir>/lq1/maps/<map>.bsp. On failure world() is null and error() says why.
  explicit TestWorld(const std::string& map, size_t block_mib = 96);
  TestWorld(const TestWorld&) = delete;
  TestWorld& operator=(const TestWorld&) = delete;

  BspWorld* world() const { return world_; }
  const std::string& error() const { return error_; }
  mem::MemorySystem& memory() { return memory_; }

  // Renders one frame with sb::render_world into `pixels` (width * height, stride = width).
  // `coverage` (optional, width * height) counts writes per pixel.
  Status render(const ViewParams& view, int width, int height, double time, const int* lightstyles,
                const uint8_t* colormap, std::vector<uint8_t>* pixels, std::vector<uint8_t>* coverage = nullptr,
                RenderStats* stats = nullptr);

 private:
  std::unique_ptr<uint8_t[]> block_;
  mem::MemorySystem memory_;
  std::vector<uint8_t> file_;
  BspWorld* world_ = nullptr;
  std::string error_;
};

// gfx/colormap.lmp (64 x 256; the trailing byte, if any, dropped) and gfx/palette.lmp
// (768 bytes). Empty when missing.
std::vector<uint8_t> load_colormap();
std::vector<uint8_t> load_game_palette();

// Leaf contents at a point (model 0's BSP tree).
int32_t point_contents(const BspWorld& world, const glm::vec3& p);

// Up to `count` viewpoints: eye positions at entity origins (players, monsters, items,
// lights) with 8 units of empty space around them along each axis, each looking in a different direction (yaw from the
// entity's angle plus a golden-angle sequence, pitch cycling through -25..30 degrees).
// Deterministic for a given map.
std::vector<ViewParams> entity_viewpoints(const BspWorld& world, int count);

// `count` viewpoints for render tests: sb::collect_viewpoints (engine/world/viewpoints.h)
// filtered to eyes with 8 units of non-solid space along every axis (an eye on a floor
// or wall plane makes a degenerate picture), picked evenly over that list, with pitch
// cycling through -25..30 degrees where the entity gave none. Falls back to
// entity_viewpoints when that yields too few. Deterministic for a given map.
std::vector<ViewParams> test_viewpoints(const BspWorld& world, int count);

}  // namespace sb::test
