// tools/content/textures.cpp: the texture catalogue (see textures.h).
#include "tools/content/textures.h"

#include "tools/content/noise.h"

namespace sb::content {

const std::vector<TextureSpec>& texture_specs() {
  static const QuantizeOptions plain{};
  static const QuantizeOptions soft{0.02f, false};
  static const QuantizeOptions sky{0.03f, true};
  static const std::vector<TextureSpec> specs = {
      {"brick1", 128, 128, make_brick, plain, "red-brown bricks in running bond"},
      {"stone1", 128, 128, make_stone_blocks, plain, "cool grey ashlar blocks"},
      {"cobble1", 128, 128, make_cobbles, plain, "rounded floor cobbles"},
      {"tile1", 64, 64, make_floor_tiles, plain, "glazed ceramic floor tiles"},
      {"planks1", 128, 128, make_planks, plain, "wooden planks with nails"},
      {"crate1", 64, 64, make_crate, plain, "wooden crate face"},
      {"rock1", 128, 128, make_rock, plain, "natural layered rock"},
      {"grass1", 64, 64, make_grass, plain, "grass with dirt patches"},
      {"ceil1", 64, 64, make_ceiling, plain, "perforated ceiling panels"},
      {"metal1", 64, 64, make_metal_plate, plain, "riveted steel plate"},
      {"metal2", 128, 128, make_metal_panels, plain, "rusty riveted panels"},
      {"door1", 64, 128, make_door, plain, "steel door with the Starbow star"},
      {"tech1", 64, 128, make_tech_wall, plain, "tech wall: vent, cyan strip, lamps"},
      {"light1", 32, 32, make_light_fixture, plain, "warm white light fixture"},
      {"button1", 32, 32, make_button, plain, "red lamp button"},
      {"hazard1", 64, 16, make_hazard_trim, plain, "yellow and black warning trim"},
      {"+0light", 32, 32, make_anim_light_on, plain, "animated cyan light, frame 0 (on)"},
      {"+1light", 32, 32, make_anim_light_off, plain, "animated cyan light, frame 1 (dim)"},
      {"sky1", 256, 128, make_sky, sky, "dusk sky: cloud wisps over a nebula"},
      {"*water1", 64, 64, make_water, soft, "water with caustics"},
      {"*slime1", 64, 64, make_slime, soft, "bubbling green slime"},
      {"*lava1", 64, 64, make_lava, soft, "lava crust over glowing cracks"},
      {"*tele1", 64, 64, make_teleport, soft, "teleporter energy"},
      {"clip", 64, 64, make_clip, plain, "compiler: clip (collision only)"},
      {"trigger", 64, 64, make_trigger, plain, "compiler: trigger volumes"},
      {"skip", 64, 64, make_skip, plain, "compiler: skipped face"},
  };
  return specs;
}

uint32_t texture_seed(const char* name, uint32_t global_seed) {
  uint32_t h = 2166136261u;  // FNV-1a over the name, then mixed with the global seed
  for (const char* p = name; *p; ++p) h = (h ^ uint8_t(*p)) * 16777619u;
  return hash3(int32_t(h), int32_t(global_seed), 0x7e3au);
}

Image make_texture_image(const PaletteData& pal, const TextureSpec& spec, uint32_t global_seed) {
  return spec.make(pal, spec.width, spec.height, texture_seed(spec.name, global_seed));
}

Miptex make_texture(const PaletteData& pal, const TextureSpec& spec, uint32_t global_seed) {
  return build_miptex(pal, spec.name, make_texture_image(pal, spec, global_seed), spec.quantize);
}

std::vector<Miptex> make_all_textures(const PaletteData& pal, uint32_t global_seed) {
  std::vector<Miptex> out;
  for (const TextureSpec& spec : texture_specs()) out.push_back(make_texture(pal, spec, global_seed));
  return out;
}

}  // namespace sb::content
