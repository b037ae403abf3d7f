// engine/formats/wad.h: WAD2 archives (gfx.wad, texture wads) and the miptex
// layout shared by WAD2 lumps and the BSP 'textures' lump.
//
// WAD2 file:  "WAD2" | int32 numlumps | int32 infotableofs | ... lump data ...
//             directory at infotableofs: numlumps x 32-byte entries
//               int32 filepos, int32 disksize, int32 size, uint8 type,
//               uint8 compression, uint16 pad, char name[16] (NUL-padded)
// parse_wad() validates the header and every entry (lump inside the file, name
// NUL-terminated or exactly 16 chars, compression 0) and copies the directory
// into an arena; the Wad then points into the caller's `data`, which must
// outlive it. Lookups are case-insensitive. Errors name the wad, the lump
// (index and name) and the field.
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/error.h"
#include "memory/arena.h"

namespace sb {

enum WadLumpType : uint8_t {
  kWadPalette = 0x40,  // '@'
  kWadQtex = 0x41,
  kWadQpic = 0x42,     // 'B': qpic (see lmp.h parse_qpic)
  kWadSound = 0x43,
  kWadMiptex = 0x44,   // 'D': miptex (decode_miptex); also used for raw blobs such as CONCHARS
};

struct WadLump {
  char name[17];       // NUL-terminated (16 chars max)
  uint8_t type;        // WadLumpType (other values are kept as they are)
  const uint8_t* data; // into the wad's bytes
  uint32_t size;       // disksize
};

struct Wad {
  const char* name = nullptr;  // caller's string (e.g. "gfx.wad"), used in messages
  WadLump* lumps = nullptr;    // in the arena given to parse_wad
  uint32_t count = 0;

  // First lump whose name matches case-insensitively, or nullptr.
  const WadLump* find(const char* lump_name) const;
};

constexpr uint32_t kMaxWadLumps = 1u << 16;

Result<Wad> parse_wad(const char* wad_name, const uint8_t* data, size_t size, mem::Arena& into);

// ---- miptex
//   char name[16] | uint32 width | uint32 height | uint32 offsets[4]   (40 bytes)
// offsets are relative to the start of the miptex; mip i is (width>>i) x (height>>i)
// palette indices. All four offsets zero means "no pixel data" (external textures).
constexpr size_t kMiptexHeaderBytes = 40;
constexpr uint32_t kMaxTextureSize = 4096;  // width and height: multiples of 16 in 16..4096

struct MiptexView {
  char name[17];
  uint32_t width, height;
  const uint8_t* mips[4];  // into the decoded data; nullptr when !has_pixels
  bool has_pixels;
};

// Decodes the miptex at data[0..size). `file` and `what` prefix error messages,
// e.g. decode_miptex("maps/x.bsp", "lump 'textures' entry 3", ...) fails with
// "maps/x.bsp: lump 'textures' entry 3 ('wall1') field 'width' = 17 is not a multiple of 16 in 16..4096".
Status decode_miptex(const char* file, const char* what, const uint8_t* data, size_t size, MiptexView* out);

// Bytes of all four mips of a width x height texture.
inline size_t miptex_pixel_bytes(uint32_t width, uint32_t height) {
  size_t a = size_t(width) * height;
  return a + a / 4 + a / 16 + a / 64;
}

}  // namespace sb
