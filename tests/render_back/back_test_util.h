// tests/render_back/back_test_util.h: hand-made worlds, views and memory for the back-end
// tests (test code: heap allowed).
#pragma once
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "engine/render/render_local.h"
#include "memory/memory_system.h"

namespace sb::test::back {

// A BspWorld whose arrays live in this object's vectors. Only what the back end reads is
// filled: planes, texinfo, textures, faces, lightdata.
class HandWorld {
 public:
  HandWorld();
  // Random texture of w x h (multiples of 16) with its 4 mips; returns its index.
  int add_texture(const char* name, int w, int h, uint32_t seed, TextureKind kind = kTexNormal);
  // Plane with normal n and dist d; returns its index.
  int add_plane(glm::vec3 n, float d);
  int add_texinfo(glm::vec4 s, glm::vec4 t, int texture, uint32_t flags = 0);
  // Face with random lightmap samples for `styles` (255-terminated); returns its index.
  int add_face(int plane, int texinfo, int smin, int tmin, int ext_s, int ext_t, const uint8_t styles[4],
               uint32_t seed, uint16_t flags = 0, bool lit = true);
  BspWorld& world();  // (re)points the BspWorld at the vectors

 private:
  BspWorld w_{};
  std::vector<Plane> planes_;
  std::vector<TexInfo> texinfo_;
  std::vector<Texture> textures_;
  std::vector<std::unique_ptr<std::vector<uint8_t>>> texels_;
  std::vector<Face> faces_;
  std::vector<uint8_t> light_;
};

// Quake-convention view basis (pitch > 0 looks down), no roll; fov_x in degrees.
render::ViewState make_view(glm::vec3 origin, float yaw, float pitch, float fov_x, int width, int height,
                            uint32_t frame = 1);

// Real colormap when the Quake data is present, else a synthetic one (row r, index i -> (i + 4r) & 255).
std::vector<uint8_t> colormap_or_synthetic();
std::vector<uint8_t> load_palette_or_grey();

// A memory block of `mib` MiB with its MemorySystem.
struct TestMemory {
  explicit TestMemory(size_t mib);
  std::vector<uint8_t> block;
  mem::MemorySystem mem;
};

// A framebuffer with owned storage.
struct TestFramebuffer {
  TestFramebuffer(int w, int h, bool with_z = true, bool with_coverage = true);
  std::vector<uint8_t> pixels, coverage;
  std::vector<uint16_t> z;
  Framebuffer fb;
};

// Exact texture coordinates (s, t) where the ray through pixel centre (px, py) hits the
// plane of `face`: computed directly (ray/plane intersection), independent of span_draw.
// Returns false when the ray does not hit the plane in front of the eye.
bool exact_st(const BspWorld& world, const Face& face, const render::ViewState& view, double px, double py,
              double* s, double* t, double* zi = nullptr);

// Writes an indexed image through the palette to `path` as PNG (for looking at renders).
bool dump_png(const std::string& path, const uint8_t* pixels, int width, int height, int stride);

}  // namespace sb::test::back
