// tools/light/light_entities.h: light sources and world light settings from an entity lump.
//
// Key meanings (the public documentation of the Quake light tools; units are map units):
//   light entities: classname starting with "light"
//     "light"  intensity, default 300 (0 counts as the default); negative lights darken
//     "wait"   distance scale of the falloff, default 1 (> 1 fades faster)
//     "delay"  falloff: 0 linear  value = light - d * wait            (0 beyond light / wait)
//                       1 inverse value = light * 128 / (d * wait)
//                       2 inverse square value = light * (128 / (d * wait))^2
//                       3 none   value = light
//                       4 local minlight: style-0 samples that see the light within
//                         light / wait units are raised to at least light, in output
//                         units 0..255 like the worldspawn minimum (no angle factor)
//                       5 biased inverse square value = light / ((d * wait / 128)^2 + 1)
//              (the scaled distance d * wait counts as at least 32 units for 1/x and 64 for
//              1/x^2, so a sample next to a light gets at most 4 x light, not infinity)
//     "style"  0..254 (engine: 1..11 animated, 32+ switchable); a light with a "targetname"
//              and no "style" gets a style 32.. per distinct targetname
//     "_color" r g b (0..255, or 0..1), default white
//     "_anglescale" / "_anglesense"  0..1, default the worldspawn value (0.5)
//     spotlight: "target" aims at the targeted entity's origin, else "mangle" (yaw pitch
//              roll, pitch up positive); cone "angle" (full angle, default 40 degrees;
//              used with "mangle" or "target" only), "_softangle" the inner full angle
//              where the light is full strength (default: same as the cone, hard edge)
//     "_sun" 1: not a point light but a sun of intensity "light" shining along its spot
//              direction (default straight down)
//     "_surface" name: a surface-light template: not a light itself; copies of it (same keys)
//              are placed 2 units in front of every face whose texture is `name` (any case),
//              about 128 units apart over the face (expand_surface_lights)
//   worldspawn: "light" / "_minlight" minimum light (output units 0..255, style 0);
//     "_sunlight" sun intensity (default 0), "_sunlight_mangle" (alias "_sun_mangle") yaw
//     pitch roll of the direction the sunlight travels (default 0 -90 0: straight down),
//     "_sunlight_color" (default white); "_sunlight2" intensity of a dome of suns over the
//     upper hemisphere (default 0), "_sunlight2_color" (alias "_sunlight_color2", default
//     white). "_sunlight_penumbra" (soft sun edges) is not implemented: one sharp sun.
//     "_anglescale"/"_anglesense" (default 0.5), "_dist" global distance scale (default 1),
//     "_range" rangescale (default 0.5).
//   bounce (radiosity; see light_bounce.h), worldspawn: "_bounce" n bounces (0 off, 1 on,
//     larger values more bounces, at most 8), "_bouncescale" (default 1), "_bouncecolorscale"
//     0..1 weight of the texture colour in what faces reflect (default 0: textures ignored,
//     faces reflect as mid grey 127/255; 1: they reflect their texture's mean colour),
//     "_bouncestyled" 1: styled lights bounce too (default 0);
//     light entities: "_bouncescale" (default 1, 0: this light does not bounce).
//   dirt (ambient occlusion; see light_dirt.h), worldspawn: "_dirt" 1 on for every light
//     (default -1 off), "_dirtdepth" (128), "_dirtscale" (1), "_dirtgain" (1, exponent),
//     "_dirtmode" (0 ordered rays, 1 jittered), "_dirtangle" (88, cone half angle 1..90),
//     "_sunlight_dirt", "_sunlight2_dirt", "_minlight_dirt" (1 / -1; default: "_dirt");
//     light entities: "_dirt" (1 / -1, default: "_dirt"), "_dirtscale", "_dirtgain".
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/core/error.h"
#include "engine/formats/bsp.h"

namespace sb::tools {

enum class Falloff { Linear = 0, Inverse = 1, InverseSquare = 2, None = 3, LocalMin = 4, InverseSquareBiased = 5 };

struct PointLight {
  glm::vec3 origin{0};
  float intensity = 300;    // "light" (may be negative)
  float wait = 1;           // distance scale (includes worldspawn "_dist")
  Falloff falloff = Falloff::Linear;
  int style = 0;            // 0..254
  glm::vec3 color{1};       // 0..1 per channel
  float anglescale = 0.5f;
  bool spot = false;
  glm::vec3 spot_dir{0, 0, -1};  // unit, direction the light shines
  float spot_cos_outer = 0;      // cos(cone / 2): no light outside
  float spot_cos_inner = 0;      // cos(softangle / 2): full light inside
  float range = 0;               // distance beyond which |value| < gate (filled by the lighter)
  float bouncescale = 1;         // "_bouncescale": share of this light that bounces
  int dirt = 0;                  // "_dirt": 1 on, -1 off, 0 the worldspawn setting
  float dirtscale = -1, dirtgain = -1;  // "_dirtscale" / "_dirtgain"; < 0: the global values
  int entity = 0;                // index of the entity in the lump (for messages)
};

struct Sun {
  glm::vec3 dir{0, 0, -1};  // unit, direction the light travels (from the sky downwards)
  float intensity = 0;
  glm::vec3 color{1};
  float anglescale = 0.5f;
  int style = 0;
  bool dome = false;        // part of the _sunlight2 dome (lit at grid points only)
  int dirt = 0;             // 1 on, -1 off, 0 the worldspawn "_dirt"
};

struct LightSettings {
  float minlight = 0;       // output units
  float anglescale = 0.5f;
  float rangescale = 0.5f;
  float dist_scale = 1;
  // Bounce and dirt settings from worldspawn (command-line options override them, see
  // LightOptions; resolve_light_options() applies both and fills every light's dirt fields).
  int bounce = 0;              // number of bounces
  float bouncescale = 1;
  float bouncecolorscale = 0;
  bool bouncestyled = false;
  int dirt = -1;               // 1 on, -1 off
  float dirtdepth = 128, dirtscale = 1, dirtgain = 1, dirtangle = 88;
  int dirtmode = 0;
  int sunlight_dirt = 0, sunlight2_dirt = 0, minlight_dirt = 0;  // 1 / -1, 0: follow "_dirt"
  std::vector<PointLight> lights;
  std::vector<Sun> suns;
  struct SurfaceTemplate {
    std::string texture;  // lower case
    PointLight light;     // origin unused
  };
  std::vector<SurfaceTemplate> surface_templates;
};

// Parses the entity text. Problems with a single entity are warnings naming the entity
// (index and classname / origin) and skip or default that key; a syntax error in the
// text is an error naming the file and offset. When `entities_out` is non-null and
// switchable lights got styles, it receives the rewritten entity text (else it is cleared).
Status parse_light_entities(const char* name, const std::string& entities, int dome_samples,
                            LightSettings* out, std::string* entities_out);

// Adds the copies of every "_surface" template (see above) to settings->lights, in face order.
// Returns the number of lights added.
int expand_surface_lights(const BspWorld& world, LightSettings* settings);

// Unit direction for (yaw, pitch) in degrees, pitch positive up (Quake's light convention).
glm::vec3 direction_from_yaw_pitch(float yaw_deg, float pitch_deg);

}  // namespace sb::tools
