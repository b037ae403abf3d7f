// engine/formats/bsp.h: a loaded BSP world (BSP29, BSP2, 2PSB), ready to render and query.
//
// Every array lives in the level arena and is valid until the level is reset.
// The loader (bsp_load.cpp) has checked every index, count and offset, so code
// that walks these arrays may index them without further bounds checks:
//   Node::children / Leaf / Face / Edge / TexInfo / Texture indices are in range,
//   face edge loops are closed and have >= 3 edges, lightmap spans lie inside
//   lightdata, texture mips lie inside their lump.
// Further guarantees: node trees are acyclic, every node has at most one parent
// and no path from a model's head node is deeper than kMaxTreeDepth (clip hulls
// likewise), so recursive walks terminate with bounded depth; faces have at most
// kMaxFaceEdges edges; vertices, planes and texinfo vectors are finite.
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

// kTexSpecial: sky or turbulent, no lightmap. Set when the file says so and, in
// addition, by the loader for every texinfo whose texture is kTexSky or kTexTurb.
enum TexInfoFlags : uint32_t { kTexSpecial = 1 };

struct TexInfo {
  glm::vec4 vecs[2];  // s = dot(xyz, vecs[0]) + vecs[0].w, likewise t
  int32_t texture;    // index into BspWorld::textures; always valid: a missing or broken
                      // texture points at a synthesized checker placeholder (logged once)
  uint32_t flags;
  float mipadjust;    // texels per world unit along the longer texture axis (>= 1e-3)
};

// kTexSky: names starting "sky" (any case); kTexTurb: names starting '*'.
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
constexpr uint32_t kMaxFaceEdges = 256;  // the loader rejects faces with more edges
constexpr int kMaxTreeDepth = 1024;      // the loader rejects deeper node / clipnode trees
constexpr int kMinContents = -14;        // clip hull contents lie in kMinContents..-1
constexpr int kNoLightmap = -1;

struct Face {
  uint32_t plane;
  uint32_t first_surfedge;  // into BspWorld::surfedges
  uint32_t num_edges;
  uint32_t texinfo;
  uint16_t flags;            // FaceFlags
  uint8_t styles[kMaxLightStyles];  // 255 = unused
  int32_t light_offset;      // byte offset into lightdata, or kNoLightmap
  int32_t texture_mins[2];   // floor(min s / 16) * 16, likewise t (s, t over the face's vertices)
  int32_t extents[2];        // (ceil(max/16) - floor(min/16)) * 16; lightmap is extents/16+1 wide.
                             // The loader rejects lit faces with extents over 2048 texels.
  // Renderer state (mutable, per level):
  uint32_t visframe;
  uint32_t draw_frame;       // frame in which the renderer last emitted this face
  mem::CacheHandle cache[4]; // lit surface per mip level
  uint32_t cache_light_key[4];  // light-style values the cached surface was built with
};

struct Node {
  uint32_t plane;
  int32_t children[2];  // >= 0: node index; < 0: leaf index -(child + 1)
  glm::vec3 mins, maxs; // bounding box (BSP29/2PSB: the file's integer box widened by 1 unit
                        // each way, as old compilers truncated; BSP2: the file's float box)
  uint32_t first_face, num_faces;  // faces lying on this node's plane
  int32_t parent;       // -1 for a head node (or a node no head node reaches)
  uint32_t visframe;
};

struct Leaf {
  int32_t contents;     // Contents, kMinContents..-1
  int32_t vis_offset;   // into visdata (< visdata_size), or -1 (everything visible)
  glm::vec3 mins, maxs; // as Node::mins/maxs
  uint32_t first_marksurface, num_marksurfaces;
  uint8_t ambient[4];
  int32_t parent;       // node index (the solid leaf 0 is shared: any one of its parents),
                        // -1 when no node reachable from a head node refers to it
  uint32_t visframe;
};

struct ClipNode {
  uint32_t plane;
  int32_t children[2];  // >= 0 clipnode; < 0 contents
};

struct SubModel {
  glm::vec3 mins, maxs, origin;
  int32_t headnode[4];  // [0] BSP node (always valid); [1..3] clip hulls: clipnode index or
                        // contents (kMinContents..-1; kContentsEmpty when the map has no clipnodes)
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
  const char* entities; uint32_t entities_size;            // NUL-terminated copy; size = strlen
  uint32_t placeholder_texture;  // index of the synthesized checker (always the last texture)

  // Counts of odd but valid input seen at load (reported, drawn correctly anyway).
  uint32_t edges_shared_by_more_than_two_faces;
  uint32_t missing_textures;     // texture slots / texinfo references replaced by the placeholder
};

// Parses a BSP held in `data` (any alignment) into `level`. `name` is used in
// error messages. On failure the level arena is popped back to where it was.
// Everything the world points at is copied into `level`: `data` may be freed
// afterwards. `scratch` is used for temporaries and restored before returning.
Result<BspWorld*> load_bsp(const char* name, const uint8_t* data, size_t size, mem::Arena& level,
                           mem::Arena& scratch);

// Reads a .lit file ("QLIT", int32 version 1, then 3 bytes per lightdata sample)
// for an already loaded world; copies the samples into `level` and sets
// lightdata_rgb. The file must hold at least 3 * lightdata_size sample bytes.
Status load_lit(BspWorld& world, const char* name, const uint8_t* data, size_t size, mem::Arena& level);

}  // namespace sb
