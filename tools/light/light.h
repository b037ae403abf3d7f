// tools/light/light.h: the LIGHT stage of the map compiler (sblight).
//
// Computes a lightmap for every face with a normal texture (not sky, not turbulent) of a
// BSP held in a BspData, from the light entities of its entity lump, and writes the result
// back into the BspData: the lighting lump, each face's styles[] and lightofs. Nothing else
// in the BspData changes except, when switchable lights (a "targetname" and no "style") get
// styles 32.. assigned, the entity text (a "style" pair is added to those entities).
//
// Lightmap layout (what engine/render/surface_math.h reads): per lit face, for each of its
// styles k (styles[k] != 255, k = 0..3, style 0 always first), a row-major grid of
// (extents[0]/16 + 1) x (extents[1]/16 + 1) bytes, grid point (gx, gy) lying at texture
// coordinates (texture_mins[0] + 16 gx, texture_mins[1] + 16 gy). texture_mins / extents are
// taken from sb::load_bsp (engine/formats/bsp_load.cpp), so they match the engine bit for bit.
//
// Light model (the documented semantics of the Quake light tools' keys; see light_entities.h):
//   value(d) = falloff by "delay" of intensity "light" at distance d scaled by "wait",
//   times the angle factor (1 - anglescale) + anglescale * cos(incidence) (anglescale 0.5),
//   times the spot cone factor, if the shadow ray from the sample to the light is clear;
//   summed per style, times rangescale (0.5), floored at the worldspawn minimum light
//   (style 0 only), rounded and clamped to 0..255. Lights carry RGB ("_color"); the
//   lighting lump holds the brightest of the three channels (what the Quake light tools
//   write: a lump byte equals max(r, g, b) of the .lit), the .lit each channel.
//   Suns: a sample is lit when the ray towards the sun reaches a sky leaf first; the angle
//   factor applies with cos 0 for faces the sun grazes (walls under a vertical sun get
//   1 - anglescale of it); suns are scaled by rangescale like every other light.
// Determinism: every face is computed on its own from read-only data and written by index:
// the output is byte-identical for any thread count.
// Phases, each on worker threads and each timed: dirt (ambient occlusion per grid point,
// light_dirt.h), direct (lights and suns, as above, each light's share scaled by the dirt
// factor when dirt applies to it), bounce (radiosity, light_bounce.h: gathered light that
// faces reflect, added to style 0 or, with bouncestyled, to the emitting style), then the
// conversion to bytes (minimum light last, itself dirtied when "_minlight_dirt" applies).
// Brush entity keys (_minlight, _minlight_color, _shadow, _selfshadow, _lightignore, _phong,
// _phong_angle) come per face from sbbsp's side file: see light_attrs.h.
// Not implemented: sunlight penumbra, deviance, BSPX / LIGHTING_E5BGR9.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/common/bsp_data.h"
#include "tools/common/face_attrs.h"

namespace sb::tools {

struct LightOptions {
  int extra = 1;            // supersampling per axis: 1, 2 (-extra) or 4 (-extra4)
  int threads = 0;          // 0: std::thread::hardware_concurrency()
  bool quiet = false;       // -q: warnings and the summary only
  bool want_rgb = false;    // also produce RGB samples (for a .lit file)
  float gate = 1.0f;        // -gate: a light whose value (before rangescale) stays below
                            // this over the face is skipped (inverse falloffs)
  int dome_samples = 32;    // about this many directions of the "_sunlight2" sky dome (4k^2 + 1: 37)

  // Bounce and dirt. Values below 0 mean "not given": the worldspawn key (or its default)
  // applies; given values override worldspawn (as the Quake light tools' options do).
  int bounce = -1;              // -bounce [n]: number of bounces (0..8)
  float bouncescale = -1;       // -bouncescale
  float bouncecolorscale = -1;  // -bouncecolorscale 0..1
  int bouncestyled = -1;        // -bouncestyled: 1
  int bounce_rays = 64;         // gather rays per bounce receiver (-bouncerays)
  int bounce_step = 2;          // receivers every this many grid points each way (-bouncestep)
  int dirt = -1;                // -dirt: 1 (on for every light unless it says otherwise)
  float dirtdepth = -1, dirtscale = -1, dirtgain = -1, dirtangle = -1;
  int dirtmode = -1;
  // Texture colours for bounce: 768 bytes (256 x r, g, b), e.g. gfx/palette.lmp. Empty:
  // every texture reflects as grey 0.5 (LightStats::palette_missing is set).
  std::vector<uint8_t> palette;
};

struct LightStats {
  uint32_t faces = 0;          // faces in the BSP
  uint32_t faces_lit = 0;      // faces that got a lightmap
  uint64_t samples = 0;        // grid samples over all lit faces and styles
  uint64_t traces = 0;         // shadow rays cast
  uint32_t lights = 0;         // point / spot lights used
  uint32_t suns = 0;           // sun directions (sunlight, _sun lights, dome directions)
  uint32_t styles_dropped = 0; // faces that had more than 4 styles
  uint32_t threads = 0;
  double seconds = 0;          // lighting time (not reading / writing)
  double dirt_seconds = 0, direct_seconds = 0, bounce_seconds = 0;  // per phase
  int bounces = 0;             // bounce passes done
  bool dirt = false;           // dirt was computed (some light or the minimum light uses it)
  uint64_t dirt_rays = 0;      // rays cast for dirt
  uint64_t bounce_rays = 0;    // rays cast for bounce
  uint64_t bounce_misses = 0;  // bounce rays that hit a surface no face could be found for
  bool palette_missing = false;  // bounce ran with grey reflectivity (no palette)
  double mean_sample = 0;      // mean style-0 sample value over lit faces
  uint32_t occluder_polygons = 0;  // faces of brush entities that cast shadows (light_attrs.h)
  uint32_t phong_faces = 0;        // faces lit with phong normals
};

// Relights `bsp` in place. `name` names the file in messages. When opts.want_rgb, *rgb gets
// 3 bytes per lighting-lump byte (the .lit payload, without header); otherwise it is cleared.
// `attrs` (optional, one per face: sbbsp's .faceattr side file, tools/common/face_attrs.h)
// carries the brush entities' light keys (light_attrs.h); null or empty: none.
Status light_bsp(const char* name, BspData* bsp, const LightOptions& opts, LightStats* stats,
                 std::vector<uint8_t>* rgb, const std::vector<FaceAttr>* attrs = nullptr);

// Writes a .lit file: "QLIT", int32 version 1 (little endian), then `rgb`.
Status write_lit(const char* path, const std::vector<uint8_t>& rgb);

// Mean byte of the style-0 samples of every face with a lightmap (for comparisons with other
// compilers' output). Faces whose lightmap lies outside the lump are ignored.
double mean_style0_sample(const BspData& bsp);

}  // namespace sb::tools
