// tools/common/bsp_data.h: a BSP file as the tools see it: every lump in a typed,
// width-neutral array (32-bit indices, float bounds), read from and written to BSP29,
// BSP2 or 2PSB disk layouts.
//
// Contracts:
//   - read_bsp/parse_bsp accept the three versions; they check lump bounds and record
//     sizes only (the engine's load_bsp checks every index; tools that need that run it).
//   - write_bsp with BspFormat::Auto writes BSP29 unless a BSP29 limit would be
//     exceeded (fits_bsp29 says which), then BSP2. Output is deterministic.
//   - Children: >= 0 node index, < 0 leaf -(child + 1) (nodes) or contents (clipnodes).
//   - textures holds the raw miptex lump (count, offsets, miptex headers, pixels).
// Tools may use the heap (std::vector); the engine never includes this.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"

namespace sb::tools {

struct DPlane { float normal[3]; float dist; int32_t type; };
struct DNode {
  int32_t plane; int32_t children[2];
  float mins[3], maxs[3];
  uint32_t first_face, num_faces;
};
struct DLeaf {
  int32_t contents; int32_t visofs;
  float mins[3], maxs[3];
  uint32_t first_marksurface, num_marksurfaces;
  uint8_t ambient[4];
};
struct DClipNode { int32_t plane; int32_t children[2]; };
struct DTexInfo { float vecs[2][4]; int32_t miptex; int32_t flags; };
struct DFace {
  int32_t plane; int32_t side;
  int32_t first_edge; int32_t num_edges;
  int32_t texinfo;
  uint8_t styles[4];
  int32_t lightofs;  // -1: no lightmap
};
struct DEdge { uint32_t v[2]; };
struct DModel {
  float mins[3], maxs[3], origin[3];
  int32_t headnode[4];
  int32_t visleafs;
  int32_t first_face, num_faces;
};

enum class BspFormat { Auto, Bsp29, Bsp2, Bsp2rmq };

struct BspData {
  BspFormat format = BspFormat::Bsp29;  // what was read
  std::string entities;                 // without the trailing NUL (added on write)
  std::vector<DPlane> planes;
  std::vector<uint8_t> textures;        // raw miptex lump
  std::vector<float> vertices;          // x, y, z triples
  std::vector<uint8_t> visdata;
  std::vector<DNode> nodes;
  std::vector<DTexInfo> texinfo;
  std::vector<DFace> faces;
  std::vector<uint8_t> lighting;
  std::vector<DClipNode> clipnodes;
  std::vector<DLeaf> leaves;
  std::vector<uint32_t> marksurfaces;
  std::vector<DEdge> edges;
  std::vector<int32_t> surfedges;
  std::vector<DModel> models;
};

Status parse_bsp(const char* name, const uint8_t* data, size_t size, BspData* out);
Status read_bsp(const char* path, BspData* out);

// True when every count, index and bound fits BSP29's fields; otherwise *why names the first
// limit exceeded (e.g. "nodes: 40000 > 32767").
bool fits_bsp29(const BspData& bsp, std::string* why);

// Serialises to the given format (Auto: BSP29 when it fits, else BSP2). *used tells which.
Status serialize_bsp(const BspData& bsp, BspFormat format, std::vector<uint8_t>* out, BspFormat* used);
Status write_bsp(const char* path, const BspData& bsp, BspFormat format = BspFormat::Auto,
                 BspFormat* used = nullptr);

}  // namespace sb::tools
