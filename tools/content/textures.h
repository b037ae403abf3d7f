// tools/content/textures.h: the catalogue of Starbow's procedural textures.
//
// Every texture is a pure function of (palette, seed): the same seed gives the same
// bytes on every run. Each texture's own seed is derived from the global seed and its
// name, so adding a texture does not change the others. Sizes are multiples of 16.
// Names follow Quake's conventions: "sky..." = two-layer sky (256 x 128: front layer on
// the left with index 0 transparent, back layer on the right), '*' = turbulent liquid
// (64 x 64, tileable), "+0x"/"+1x" = animation frames, clip/trigger/skip = compiler markers.
#pragma once
#include <cstdint>
#include <vector>

#include "tools/content/image.h"
#include "tools/content/palette.h"

namespace sb::content {

constexpr uint32_t kDefaultSeed = 0x53544152u;  // "STAR"

struct TextureSpec {
  const char* name;         // <= 15 characters
  int width, height;        // multiples of 16
  Image (*make)(const PaletteData& pal, int width, int height, uint32_t seed);
  QuantizeOptions quantize;
  const char* description;  // one line, for the catalogue printout
};

// All textures, in WAD order.
const std::vector<TextureSpec>& texture_specs();
// The seed a texture gets from the global seed.
uint32_t texture_seed(const char* name, uint32_t global_seed);
// Generates one texture's full-colour image and its miptex.
Image make_texture_image(const PaletteData& pal, const TextureSpec& spec, uint32_t global_seed);
Miptex make_texture(const PaletteData& pal, const TextureSpec& spec, uint32_t global_seed);
std::vector<Miptex> make_all_textures(const PaletteData& pal, uint32_t global_seed);

// Generators (textures_surfaces.cpp, textures_tech.cpp, textures_special.cpp).
Image make_brick(const PaletteData&, int w, int h, uint32_t seed);
Image make_stone_blocks(const PaletteData&, int w, int h, uint32_t seed);
Image make_cobbles(const PaletteData&, int w, int h, uint32_t seed);
Image make_floor_tiles(const PaletteData&, int w, int h, uint32_t seed);
Image make_planks(const PaletteData&, int w, int h, uint32_t seed);
Image make_crate(const PaletteData&, int w, int h, uint32_t seed);
Image make_rock(const PaletteData&, int w, int h, uint32_t seed);
Image make_grass(const PaletteData&, int w, int h, uint32_t seed);
Image make_ceiling(const PaletteData&, int w, int h, uint32_t seed);
Image make_metal_plate(const PaletteData&, int w, int h, uint32_t seed);
Image make_metal_panels(const PaletteData&, int w, int h, uint32_t seed);
Image make_door(const PaletteData&, int w, int h, uint32_t seed);
Image make_tech_wall(const PaletteData&, int w, int h, uint32_t seed);
Image make_light_fixture(const PaletteData&, int w, int h, uint32_t seed);
Image make_button(const PaletteData&, int w, int h, uint32_t seed);
Image make_hazard_trim(const PaletteData&, int w, int h, uint32_t seed);
Image make_anim_light_on(const PaletteData&, int w, int h, uint32_t seed);
Image make_anim_light_off(const PaletteData&, int w, int h, uint32_t seed);
Image make_sky(const PaletteData&, int w, int h, uint32_t seed);
Image make_water(const PaletteData&, int w, int h, uint32_t seed);
Image make_slime(const PaletteData&, int w, int h, uint32_t seed);
Image make_lava(const PaletteData&, int w, int h, uint32_t seed);
Image make_teleport(const PaletteData&, int w, int h, uint32_t seed);
Image make_clip(const PaletteData&, int w, int h, uint32_t seed);
Image make_trigger(const PaletteData&, int w, int h, uint32_t seed);
Image make_skip(const PaletteData&, int w, int h, uint32_t seed);

}  // namespace sb::content
