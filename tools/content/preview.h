// tools/content/preview.h: PNG previews of the generated content (libpng), for people to
// look at; nothing in the engine reads them.
#pragma once
#include <string>
#include <vector>

#include "tools/content/image.h"
#include "tools/content/palette.h"

namespace sb::content {

// 24-bit RGB PNG, rgb = width * height * 3 bytes. False (and *error) on failure.
bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string* error);

// One texture: its four mips side by side (through the palette), then the same mip 0
// lit through colormap rows 8, 32 (normal) and 48 (dark), each magnified `scale` times.
bool write_texture_preview(const std::string& path, const PaletteData& pal, const std::vector<uint8_t>& colormap,
                           const Miptex& tex, int scale, std::string* error);
// All textures' mip 0 on one contact sheet (scale 2, wrapped rows).
bool write_contact_sheet(const std::string& path, const PaletteData& pal, const std::vector<Miptex>& textures,
                         std::string* error);
// The palette as 16 x 16 swatches (ramps are rows) and the colormap as a 256 x 64 image
// (each entry drawn in its colour), magnified.
bool write_palette_preview(const std::string& path, const PaletteData& pal, std::string* error);
bool write_colormap_preview(const std::string& path, const PaletteData& pal, const std::vector<uint8_t>& colormap,
                            std::string* error);

}  // namespace sb::content
