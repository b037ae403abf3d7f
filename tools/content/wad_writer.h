// tools/content/wad_writer.h: writes WAD2 texture archives (the layout engine/formats/wad.h
// reads) and the raw miptex bytes shared with the BSP 'textures' lump.
//
//   "WAD2" | int32 numlumps | int32 infotableofs | lump data ... | directory
//   directory entry (32 bytes): int32 filepos, int32 disksize, int32 size, uint8 type ('D'),
//                               uint8 compression (0), uint16 pad (0), char name[16]
//   miptex lump: char name[16] | uint32 width | uint32 height | uint32 offsets[4] | mips 0..3
// Lumps are 4-byte aligned; all integers little-endian. Output is deterministic.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tools/content/image.h"

namespace sb::content {

// One miptex lump. Fails (returns empty, *error set) on a bad name (empty or longer
// than 15 characters), a size that is not a multiple of 16 in 16..4096, or mip data of
// the wrong size.
std::vector<uint8_t> encode_miptex(const Miptex& tex, std::string* error);

// A WAD2 file holding the textures in the given order (all lumps type 'D').
std::vector<uint8_t> encode_wad(const std::vector<Miptex>& textures, std::string* error);

// Writes bytes to a file (creating parent directories is the caller's job). False on failure.
bool write_file(const std::string& path, const std::vector<uint8_t>& bytes, std::string* error);

}  // namespace sb::content
