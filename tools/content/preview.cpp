// tools/content/preview.cpp: see preview.h.
#include "tools/content/preview.h"

#include <png.h>

#include <algorithm>
#include <cstdio>

namespace sb::content {
namespace {

struct Canvas {
  int w, h;
  std::vector<uint8_t> rgb;
  Canvas(int width, int height, uint8_t fill) : w(width), h(height), rgb(size_t(width) * height * 3, fill) {}
  void put(int x, int y, const PaletteData& pal, int index) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    for (int c = 0; c < 3; ++c) rgb[(size_t(y) * w + x) * 3 + c] = pal.bytes[size_t(index) * 3 + c];
  }
  // Blits width x height indices at (x0, y0), each index a scale x scale block.
  void blit(int x0, int y0, const uint8_t* idx, int width, int height, int scale, const PaletteData& pal,
            const uint8_t* colormap_row = nullptr) {
    for (int y = 0; y < height * scale; ++y)
      for (int x = 0; x < width * scale; ++x) {
        int i = idx[size_t(y / scale) * width + x / scale];
        put(x0 + x, y0 + y, pal, colormap_row ? colormap_row[i] : i);
      }
  }
};

}  // namespace

bool write_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb, std::string* error) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    *error = path + ": cannot open for writing";
    return false;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    *error = path + ": libpng failed";
    return false;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) png_write_row(png, rgb.data() + size_t(y) * width * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(f) == 0;
}

bool write_texture_preview(const std::string& path, const PaletteData& pal, const std::vector<uint8_t>& colormap,
                           const Miptex& tex, int scale, std::string* error) {
  const int gap = 4;
  int mips_w = 0;
  for (int m = 0; m < 4; ++m) mips_w += (tex.width >> m) * scale + gap;
  int lit_w = 3 * (tex.width * scale + gap);
  Canvas c(std::max(mips_w, lit_w), 2 * (tex.height * scale + gap), 40);
  int x = 0;
  for (int m = 0; m < 4; ++m) {
    c.blit(x, 0, tex.mips[size_t(m)].data(), tex.width >> m, tex.height >> m, scale, pal);
    x += (tex.width >> m) * scale + gap;
  }
  int rows[3] = {8, 32, 48};
  for (int k = 0; k < 3; ++k)
    c.blit(k * (tex.width * scale + gap), tex.height * scale + gap, tex.mips[0].data(), tex.width, tex.height, scale,
           pal, colormap.data() + size_t(rows[k]) * 256);
  return write_png(path, c.w, c.h, c.rgb, error);
}

bool write_contact_sheet(const std::string& path, const PaletteData& pal, const std::vector<Miptex>& textures,
                         std::string* error) {
  const int scale = 2, gap = 6, max_w = 1200;
  int x = 0, y = 0, row_h = 0, total_w = 0;
  std::vector<std::pair<int, int>> at;
  for (const Miptex& t : textures) {
    int w = t.width * scale, h = t.height * scale;
    if (x + w > max_w) {
      x = 0;
      y += row_h + gap;
      row_h = 0;
    }
    at.push_back({x, y});
    x += w + gap;
    row_h = std::max(row_h, h);
    total_w = std::max(total_w, x);
  }
  Canvas c(total_w, y + row_h, 40);
  for (size_t i = 0; i < textures.size(); ++i)
    c.blit(at[i].first, at[i].second, textures[i].mips[0].data(), textures[i].width, textures[i].height, scale, pal);
  return write_png(path, c.w, c.h, c.rgb, error);
}

bool write_palette_preview(const std::string& path, const PaletteData& pal, std::string* error) {
  const int cell = 16;
  Canvas c(16 * cell, 16 * cell, 0);
  for (int i = 0; i < 256; ++i)
    for (int y = 0; y < cell - 1; ++y)
      for (int x = 0; x < cell - 1; ++x) c.put((i % 16) * cell + x, (i / 16) * cell + y, pal, i);
  return write_png(path, c.w, c.h, c.rgb, error);
}

bool write_colormap_preview(const std::string& path, const PaletteData& pal, const std::vector<uint8_t>& colormap,
                            std::string* error) {
  Canvas c(256 * 3, 64 * 4, 0);
  for (int y = 0; y < 64 * 4; ++y)
    for (int x = 0; x < 256 * 3; ++x) c.put(x, y, pal, colormap[size_t(y / 4) * 256 + x / 3]);
  return write_png(path, c.w, c.h, c.rgb, error);
}

}  // namespace sb::content
