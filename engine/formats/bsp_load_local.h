// engine/formats/bsp_load_local.h: shared between bsp_load.cpp (geometry, tree,
// lighting, visibility) and bsp_textures.cpp (textures, texinfo, animation).
// Not for use outside engine/formats.
#pragma once
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstring>

#include "engine/formats/bsp.h"
#include "engine/fs/padded_push.h"

namespace sb::bsp_detail {

enum Lump {
  kLumpEntities, kLumpPlanes, kLumpTextures, kLumpVertices, kLumpVisibility, kLumpNodes, kLumpTexinfo,
  kLumpFaces, kLumpLighting, kLumpClipnodes, kLumpLeaves, kLumpMarksurfaces, kLumpEdges, kLumpSurfedges,
  kLumpModels, kNumLumps
};

extern const char* const kLumpNames[kNumLumps];

// Unaligned little-endian reads (every supported target is little-endian).
inline uint16_t rd_u16(const uint8_t* p) { uint16_t v; std::memcpy(&v, p, 2); return v; }
inline int16_t rd_i16(const uint8_t* p) { int16_t v; std::memcpy(&v, p, 2); return v; }
inline uint32_t rd_u32(const uint8_t* p) { uint32_t v; std::memcpy(&v, p, 4); return v; }
inline int32_t rd_i32(const uint8_t* p) { int32_t v; std::memcpy(&v, p, 4); return v; }
inline float rd_f32(const uint8_t* p) { float v; std::memcpy(&v, p, 4); return v; }

struct LumpView {
  const uint8_t* data;
  uint32_t offset, size;  // in the file
};

struct LoadContext {
  const char* name;
  BspVersion version;
  LumpView lumps[kNumLumps];
  mem::Arena* level;
  mem::Arena* scratch;
  BspWorld* w;
  uint8_t* texture_missing;  // scratch, one per texture slot: 1 = placeholder
};

// "<file>: lump '<lump>' " + formatted text.
Error lump_error(const LoadContext& c, int lump, const char* fmt, ...) __attribute__((format(printf, 3, 4)));
// "<file>: lump '<lump>' entry <i> field '<field>' = <v> out of range (0..<count-1>)".
Error range_error(const LoadContext& c, int lump, uint32_t entry, const char* field, int64_t value, uint64_t count);
// "<file>: lump '<lump>': <arena failure message>".
Error arena_error(const LoadContext& c, int lump, const mem::Arena& arena);

// Allocates count zeroed records in the level arena (at least one, so pointers are never null).
// All loader pushes go through mem_util (engine/fs/padded_push.h).
template <class T>
T* push_records(LoadContext& c, uint64_t count, const char* what) {
  return mem_util::push_array_padded<T>(*c.level, size_t(count ? count : 1), what);
}

// Textures lump -> w->textures (with the placeholder as the last slot).
Status load_textures(LoadContext& c);
// Texinfo lump -> w->texinfo (texture indices resolved to slots or the placeholder).
Status load_texinfo(LoadContext& c);
// Animation chains over w->textures (warnings for broken sequences, never errors).
void resolve_animations(LoadContext& c);

}  // namespace sb::bsp_detail
