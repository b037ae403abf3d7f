// engine/formats/lmp.cpp: palette, colormap and qpic checks.
#include "engine/formats/lmp.h"

#include <cstring>

namespace sb {

Status parse_palette(const char* name, const uint8_t* data, size_t size, Palette* out) {
  if (size != kPaletteBytes) return make_error("%s: palette is %zu bytes (expected 768)", name, size);
  std::memcpy(out->rgb, data, kPaletteBytes);
  return Status::ok();
}

Status parse_colormap(const char* name, const uint8_t* data, size_t size, uint8_t* out, int* extra_byte) {
  if (size != kColormapBytes && size != kColormapBytes + 1)
    return make_error("%s: colormap is %zu bytes (expected %zu = 64 rows x 256, optionally + 1)", name, size,
                      kColormapBytes);
  std::memcpy(out, data, kColormapBytes);
  if (extra_byte) *extra_byte = size > kColormapBytes ? data[kColormapBytes] : -1;
  return Status::ok();
}

Status parse_qpic(const char* name, const uint8_t* data, size_t size, QpicView* out) {
  if (size < 8) return make_error("%s: qpic is %zu bytes, too short for its header (8)", name, size);
  int32_t w, h;
  std::memcpy(&w, data, 4);
  std::memcpy(&h, data + 4, 4);
  if (w < 1 || w > kMaxQpicSize) return make_error("%s: qpic field 'width' = %d out of range (1..%d)", name, w, kMaxQpicSize);
  if (h < 1 || h > kMaxQpicSize) return make_error("%s: qpic field 'height' = %d out of range (1..%d)", name, h, kMaxQpicSize);
  if (8 + uint64_t(w) * uint64_t(h) > size)
    return make_error("%s: qpic %dx%d needs %llu bytes of pixels, file has %zu", name, w, h,
                      (unsigned long long)(uint64_t(w) * uint64_t(h)), size - 8);
  out->width = w;
  out->height = h;
  out->pixels = data + 8;
  return Status::ok();
}

}  // namespace sb
