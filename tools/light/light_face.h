// tools/light/light_face.h: the lightmap of one face (samples, lights, shadows, styles).
//
// A LightScene holds everything the faces share, read-only while faces are lit, so any
// number of threads may call light_face() on different faces at once. light_face() depends
// only on the scene and the face index: results do not depend on thread count or order.
#pragma once
#include <cstdint>
#include <vector>

#include "engine/formats/bsp.h"
#include "tools/light/light.h"
#include "tools/light/light_entities.h"
#include "tools/light/light_trace.h"

namespace sb::tools {

struct LightScene {
  const BspWorld* world = nullptr;
  const LineTracer* tracer = nullptr;
  const LightSettings* settings = nullptr;
  LightOptions opts;
  // light_faces[l * face_words + f / 64] bit f % 64: light l may see face f (its PVS holds a
  // leaf that marks the face, or the face belongs to a submodel, or there is no vis data).
  std::vector<uint64_t> light_faces;
  size_t face_words = 0;
  // face_sees_sky[f]: some leaf marking face f has in its PVS a leaf that marks a sky face
  // (or f belongs to a submodel). Faces without it get no sunlight.
  std::vector<uint8_t> face_sees_sky;

  bool light_may_see(size_t light, uint32_t face) const {
    return (light_faces[light * face_words + face / 64] >> (face % 64)) & 1;
  }
};

// Builds the visibility tables and each light's cull range (PointLight::range).
void prepare_scene(LightScene* scene, LightSettings* settings);

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

void light_face(const LightScene& scene, uint32_t face_index, FaceLightmap* out);

}  // namespace sb::tools
