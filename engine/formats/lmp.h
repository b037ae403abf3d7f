// engine/formats/lmp.h: the small lump files in gfx/: palette.lmp, colormap.lmp
// and qpic pictures (menu graphics, also qpic lumps inside gfx.wad).
//
//   palette.lmp   768 bytes: 256 x (r, g, b)
//   colormap.lmp  64 rows x 256 palette indices (row 0 brightest, 63 darkest),
//                 optionally followed by one byte (Quake's files carry the number
//                 of fullbright colours there); any other size is an error
//   qpic          int32 width | int32 height | width*height palette indices
// Parsers check sizes and copy or point; errors name the file and the field.
#pragma once
#include <cstddef>
#include <cstdint>

#include "engine/core/error.h"

namespace sb {

constexpr size_t kPaletteBytes = 768;
constexpr int kColormapRows = 64;
constexpr size_t kColormapBytes = size_t(kColormapRows) * 256;
constexpr int32_t kMaxQpicSize = 4096;  // width and height: 1..4096

struct Palette {
  uint8_t rgb[kPaletteBytes];
};

// Copies the 768 colour bytes into *out. The size must be exactly 768.
Status parse_palette(const char* name, const uint8_t* data, size_t size, Palette* out);

// Checks a colormap and copies its 64 x 256 table into out (kColormapBytes bytes).
// *extra_byte (may be null) gets the optional 16385th byte, or -1 when absent.
Status parse_colormap(const char* name, const uint8_t* data, size_t size, uint8_t* out, int* extra_byte);

struct QpicView {
  int32_t width = 0, height = 0;
  const uint8_t* pixels = nullptr;  // into the caller's data, row-major, width*height bytes
};

// A qpic held in data[0..size); trailing bytes after the pixels are allowed.
Status parse_qpic(const char* name, const uint8_t* data, size_t size, QpicView* out);

}  // namespace sb
