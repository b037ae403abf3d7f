// tools/common/face_attrs.h: per-face light attributes that sbbsp hands to sblight in a side
// file next to the BSP ("maps/foo.bsp" -> "maps/foo.faceattr"), from the light keys of brush
// entities (func_group, func_detail*, and every brush model; worldspawn's keys are the light
// stage's global settings and are not repeated here):
//   "_minlight" n, "_minlight_color" / "_mincolor" "r g b" (0..255 or 0..1, default white),
//   "_shadow" n, "_selfshadow" / "_shadowself" n, "_lightignore" n, "_phong" n,
//   "_phong_angle" degrees (default 89 with "_phong" "1"; alone it also enables phong).
// sbbsp writes the file only when some entity has one of these keys (and removes a stale one
// otherwise); faces of different attributes are never merged, so only maps that use the keys
// can get a different BSP.
// World-merged entities (func_group, func_detail*) lose their identity in the BSP, so the
// attributes travel per BSP face, in BSP face order.
//
// File layout (little endian):
//   offset 0   char[4]  "SBFA"
//          4   uint32   version (kFaceAttrVersion = 1)
//          8   uint32   face count (must equal the BSP's)
//         12   uint32   record size (16)
//         16   uint64   face hash: FNV-1a 64 over each face's plane, side, first_edge,
//                       num_edges, texinfo (int32 each; lightofs and styles excluded, as the
//                       light stage rewrites them)
//         24   count x record:
//                +0  float32  minlight (output units; < 0: not given, the worldspawn value applies)
//                +4  uint8[3] minlight colour r, g, b
//                +7  uint8    flags (kFaceAttr*)
//                +8  float32  phong angle in degrees (0: no phong)
//               +12  uint32   source entity: index of the entity in the .map (shadow and phong
//                            groups: faces of one entity belong together)
// A file that is too short, has another magic / version / record size, a face count or hash
// that does not match the BSP, or a non-finite value is an error naming the file and the
// byte offset. sblight lights as without attributes when the file does not exist.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "tools/common/bsp_data.h"

namespace sb::tools {

constexpr uint32_t kFaceAttrVersion = 1;
constexpr uint32_t kFaceAttrRecordSize = 16;
constexpr size_t kFaceAttrHeaderSize = 24;

enum : uint8_t {
  kFaceAttrShadow = 1,       // casts shadows on every face ("_shadow" "1")
  kFaceAttrSelfShadow = 2,   // casts shadows on the faces of its own entity only ("_selfshadow")
  kFaceAttrLightIgnore = 4,  // gets no light, only its minimum light ("_lightignore" "1")
  kFaceAttrNoShadow = 8,     // "_shadow" "-1": would cast none (not implemented for world solids)
};

struct FaceAttr {
  float minlight = -1.0f;
  uint8_t minlight_color[3] = {255, 255, 255};
  uint8_t flags = 0;
  float phong_angle = 0.0f;
  uint32_t entity = 0;
  bool operator==(const FaceAttr& o) const {
    return minlight == o.minlight && minlight_color[0] == o.minlight_color[0] &&
           minlight_color[1] == o.minlight_color[1] && minlight_color[2] == o.minlight_color[2] &&
           flags == o.flags && phong_angle == o.phong_angle && entity == o.entity;
  }
};

// The side file's name for a BSP path: ".bsp" replaced by (or, without it, ".faceattr" added).
std::string face_attr_path(const std::string& bsp_path);

uint64_t face_attr_hash(const BspData& bsp);

// Serialises attrs (one per bsp face) to bytes.
void serialize_face_attrs(const BspData& bsp, const std::vector<FaceAttr>& attrs, std::vector<uint8_t>* out);
Status write_face_attrs(const char* path, const BspData& bsp, const std::vector<FaceAttr>& attrs);

// Parses bytes checked against `bsp` (count and hash). `name` names the file in messages.
Status parse_face_attrs(const char* name, const uint8_t* data, size_t size, const BspData& bsp,
                        std::vector<FaceAttr>* out);
// *found is false (and out empty, status ok) when the file does not exist.
Status read_face_attrs(const char* path, const BspData& bsp, std::vector<FaceAttr>* out, bool* found);

}  // namespace sb::tools
