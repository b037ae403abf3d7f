// engine/formats/bsp.h: a loaded BSP world (BSP29, BSP2, 2PSB), ready to render and query.
//
// Every array lives in the level arena and is valid until the level is reset.
// The loader (bsp_load.cpp) has checked every index, count and offset, so code
// that walks these arrays may index them without further bounds checks:
//   Node::children / Leaf / Face / Edge / TexInfo / Texture indices are in range,
//   face edge loops are closed and have >= 3 edges, lightmap spans lie inside
//   lightdata, texture mips lie inside their lump.
// Coordinates are Quake's: x forward (east), y left (north), z up; units = texels
// at scale 1.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "engine/core/error.h"
#include "memory/arena.h"
#include "memory/cache.h"

namespace sb {

enum class BspVersion : uint8_t { Bsp29, Bsp2, Bsp2rmq /* "2PSB" */ };

enum Contents : int32_t {
  kContentsEmpty = -1, kContentsSolid = -2, kContentsWater = -3, kContentsSlime = -4,
  kContentsLava = -5, kContentsSky = -6,
};

struct Plane {
  glm::vec3 normal;
  float dist;
  uint8_t type;      // 0,1,2 = axial x,y,z; 3+ = not axial
  uint8_t signbits;  // bit i set when normal[i] < 0 (for box tests)
  uint8_t pad[2];
};

struct Edge {
  uint32_t v[2];  // vertex indices
};

enum TexInfoFlags : uint32_t { kTexSpecial = 1 };  // sky or turbulent: no lightmap

struct TexInfo {
  glm::vec4 vecs[2];  // s = dot(xyz, vecs[0]) + vecs[0].w, likewise t
  int32_t texture;    // index into BspWorld::textures, or -1 when the texture is missing
  uint32_t flags;
  float mipadjust;    // texels per world unit along the longer texture axis (>= 1e-3)
};

enum TextureKind : uint8_t { kTexNormal, kTexSky, kTexTurb /* '*' names */ };

struct Texture {
  char name[17];      // NUL-terminated
  TextureKind kind;
  uint32_t width, height;  // mip 0; multiples of 16 (checked)
  const uint8_t* mips[4];  // palette indices, mip i is (width>>i) x (height>>i)
  // Animation (+0..+9 primary sequence, +a..+j alternate), resolved at load:
  int32_t anim_next;       // next frame's texture index, or -1 when not animated
  int32_t alternate;       // first frame of the other sequence, or -1
  uint16_t anim_total;     // frames in this sequence (0 when not animated)
  uint16_t anim_index;     // this frame's position in its sequence
};

enum FaceFlags : uint16_t {
  kFacePlaneBack = 1,  // the face's front is the back of its plane
  kFaceSky = 2,
  kFaceTurb = 4,
  kFaceMissingTexture = 8,
};

constexpr int kMaxLightStyles = 4;
constexpr int kNoLightmap = -1;

struct Face {
  uint32_t plane;
  uint32_t first_surfedge;  // into BspWorld::surfedges
  uint32_t num_edges;
  uint32_t texinfo;
  uint16_t flags;            // FaceFlags
  uint8_t styles[kMaxLightStyles];  // 255 = unused
  int32_t light_offset;      // byte offset into lightdata, or kNoLightmap
  int16_t texture_mins[2];   // floor(min s / 16) * 16, likewise t
  int16_t extents[2];        // (ceil(max/16) - floor(min/16)) * 16; lightmap is extents/16+1 wide
  // Renderer state (mutable, per level):
  uint32_t visframe;
  uint32_t draw_frame;       // frame in which the renderer last emitted this face
  mem::CacheHandle cache[4]; // lit surface per mip level
  uint32_t cache_light_key[4];  // light-style values the cached surface was built with
};

struct Node {
  uint32_t plane;
  int32_t children[2];  // >= 0: node index; < 0: leaf index -(child + 1)
  glm::vec3 mins, maxs; // bounding box (from the file's integer box, widened)
  uint32_t first_face, num_faces;  // faces lying on this node's plane
  int32_t parent;       // -1 for a head node
  uint32_t visframe;
};

struct Leaf {
  int32_t contents;
  int32_t vis_offset;   // into visdata, or -1 (everything visible)
  glm::vec3 mins, maxs;
  uint32_t first_marksurface, num_marksurfaces;
  uint8_t ambient[4];
  int32_t parent;       // node index
  uint32_t visframe;
};

struct ClipNode {
  uint32_t plane;
  int32_t children[2];  // >= 0 clipnode; < 0 contents
};

struct SubModel {
  glm::vec3 mins, maxs, origin;
  int32_t headnode[4];  // [0] BSP node, [1..3] clip hulls
  uint32_t visleafs;    // leaves in the world PVS (model 0 only is meaningful)
  uint32_t first_face, num_faces;
};

struct BspWorld {
  char name[64];  // e.g. "maps/start.bsp"
  BspVersion version;

  Plane* planes; uint32_t num_planes;
  glm::vec3* vertices; uint32_t num_vertices;
  Edge* edges; uint32_t num_edges;
  int32_t* surfedges; uint32_t num_surfedges;  // > 0: edge forwards, < 0: edge -i backwards
  TexInfo* texinfo; uint32_t num_texinfo;
  Texture* textures; uint32_t num_textures;
  Face* faces; uint32_t num_faces;
  uint32_t* marksurfaces; uint32_t num_marksurfaces;
  Node* nodes; uint32_t num_nodes;
  Leaf* leaves; uint32_t num_leaves;  // leaf 0 is the shared solid leaf
  ClipNode* clipnodes; uint32_t num_clipnodes;
  SubModel* models; uint32_t num_models;

  const uint8_t* visdata; uint32_t visdata_size;
  const uint8_t* lightdata; uint32_t lightdata_size;      // one byte per sample
  const uint8_t* lightdata_rgb;  // from a .lit file (3 bytes per sample) or nullptr
  const char* entities; uint32_t entities_size;            // NUL-terminated copy

  // Counts of odd but valid input seen at load (reported, drawn correctly anyway).
  uint32_t edges_shared_by_more_than_two_faces;
};

// Parses a BSP held in `data` (any alignment) into `level`. `name` is used in
// error messages. On failure the level arena is popped back to where it was.
Result<BspWorld*> load_bsp(const char* name, const uint8_t* data, size_t size, mem::Arena& level,
                           mem::Arena& scratch);

// Reads a .lit file (QLIT, version 1) for an already loaded world; sets lightdata_rgb.
Status load_lit(BspWorld& world, const char* name, const uint8_t* data, size_t size, mem::Arena& level);

}  // namespace sb
