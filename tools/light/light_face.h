// tools/light/light_face.h: per-face work of the light stage (samples, lights, shadows,
// styles), shared by the phases in light.cpp, light_dirt.cpp and light_bounce.cpp.
//
// A LightScene holds everything the faces share, read-only while a phase runs, so any number
// of threads may work on different faces at once. Every phase function depends only on the
// scene, the face index and data written by earlier phases (never by the running phase on
// another face): results do not depend on thread count or order.
//
// Light values in FaceWork buffers are "light units": the sum of the lights' values before
// rangescale (output byte = value * rangescale, rounded, clamped to 0..255).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"
#include "tools/light/light.h"
#include "tools/light/light_attrs.h"
#include "tools/light/light_entities.h"
#include "tools/light/light_trace.h"

namespace sb::tools {

// A face as bounce rays see it: where its polygon is and how its lightmap is addressed.
struct HitFace {
  bool usable = false;              // lit world face (not sky / liquid, not a submodel's)
  glm::vec3 normal{0, 0, 1};        // facing normal
  std::vector<glm::vec3> verts;
  std::vector<glm::vec3> edge_normals;  // in-plane, pointing out of the polygon
  glm::vec3 mins{0}, maxs{0};       // bounds of verts
  glm::vec3 reflect{0.5f};          // reflectivity 0..1 per channel (texture colour, see
                                    // light_bounce.h), bouncescale not included
};

struct LightScene {
  const BspWorld* world = nullptr;
  const LineTracer* tracer = nullptr;
  const LightSettings* settings = nullptr;  // bounce / dirt fields resolved (light.cpp)
  LightOptions opts;
  // light_faces[l * face_words + f / 64] bit f % 64: light l may see face f (its PVS holds a
  // leaf that marks the face, or the face belongs to a submodel, or there is no vis data).
  std::vector<uint64_t> light_faces;
  size_t face_words = 0;
  // face_sees_sky[f]: some leaf marking face f has in its PVS a leaf that marks a sky face
  // (or f belongs to a submodel). Faces without it get no sunlight.
  std::vector<uint8_t> face_sees_sky;

  // Dirt: unit ray directions in a local frame (z = surface normal), empty when no light
  // uses dirt. minlight_dirt: the worldspawn minimum light is scaled by the dirt factor.
  std::vector<glm::vec3> dirt_dirs;
  bool minlight_dirt = false;
  // Bounce: number of passes (0: off), and per face what rays that hit it need.
  int bounces = 0;
  std::vector<HitFace> hit_faces;
  std::vector<uint32_t> hit_plane;  // per face: plane index when usable, else UINT32_MAX
                                    // (compact, for the hit search)
  // Brush entity attributes (light_attrs.h): one per face, or empty (no side file).
  std::vector<FaceAttr> attrs;
  Occluders occluders;
  PhongNormals phong;

  bool light_may_see(size_t light, uint32_t face) const {
    return (light_faces[light * face_words + face / 64] >> (face % 64)) & 1;
  }
};

// Builds the visibility tables and each light's cull range (PointLight::range).
void prepare_scene(LightScene* scene, LightSettings* settings);

struct StyleBuffer {
  int style = 0;
  std::vector<float> rgb;  // grid * 3, light units
};

// The buffer of `style` in bufs, appended (zeroed, grid cells) when missing.
StyleBuffer& style_buffer(std::vector<StyleBuffer>& bufs, int style, size_t grid);

// Everything the phases produce for one face, until it is converted to bytes.
struct FaceWork {
  bool lit = false;               // false: sky, liquid (no lightmap)
  bool degenerate = false;        // texture axes parallel to the plane: lit at the centroid
  int gw = 0, gh = 0;             // lightmap grid (extents / 16 + 1)
  glm::vec3 normal{0, 0, 1};      // facing normal
  std::vector<glm::vec3> centres;  // grid points in the world (1 unit off the face)
  std::vector<float> occlusion;   // dirt phase: per grid point 0..1 (empty: no dirt)
  std::vector<StyleBuffer> light;  // direct (then + bounced) light; style 0 first
  std::vector<StyleBuffer> emit;  // light this face sends out in the running bounce pass
                                  // (already times its reflectivity and bouncescale)
  std::vector<StyleBuffer> gathered;  // bounce pass result (read by nobody during the pass)
  std::vector<float> local_min;   // delay 4 floors (output units), style 0; may be empty
  float minlight = -1;            // the face's entity "_minlight" (< 0: the worldspawn value)
  glm::vec3 minlight_color{1.0f}; // its "_minlight_color" / 255
  bool light_ignore = false;      // "_lightignore": minimum light only
  uint64_t traces = 0;            // direct-light rays
  uint64_t dirt_rays = 0, bounce_rays = 0, bounce_misses = 0;
};

// Phase 0 (with the dirt phase): lit flag, grid size, normal and grid points.
void face_setup(const LightScene& scene, uint32_t face_index, FaceWork* work);

// Direct light of every light and sun (dirt factors applied). When scene.bounces > 0, also
// fills work->emit with the bouncing share (bouncescale per light) times the reflectivity.
void light_face_direct(const LightScene& scene, uint32_t face_index, FaceWork* work);

struct FaceLightmap {
  bool lit = false;              // false: sky, liquid (no lightmap)
  uint8_t styles[4] = {255, 255, 255, 255};
  int num_styles = 0;
  std::vector<uint8_t> mono;     // num_styles * grid bytes, style after style
  std::vector<uint8_t> rgb;      // 3 bytes per mono byte (when opts.want_rgb)
  uint64_t traces = 0;
  bool styles_dropped = false;   // more than 4 styles were seen; the weakest were dropped
  int first_dropped_style = -1;
  bool degenerate = false;       // texture axes parallel to the plane: lit at the centroid
};

// Last phase: rangescale, minimum light (dirtied when scene.minlight_dirt), bytes, styles.
void finish_face(const LightScene& scene, const FaceWork& work, FaceLightmap* out);

}  // namespace sb::tools
