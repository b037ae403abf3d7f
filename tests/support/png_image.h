// tests/support/png_image.h: 8-bit images in and out of PNG files, for golden-image tests
// and for looking at renders (test code: heap and exceptions allowed; errors are returned
// as false with a message).
//
// Paletted PNGs keep the palette indices themselves, so a golden image compares exactly
// by index even where the palette repeats a colour.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace sb::test {

struct IndexedImage {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // palette indices, row-major, no padding
};

// Reads a 768-byte palette (gfx/palette.lmp). Empty on failure.
std::vector<uint8_t> load_palette(const std::string& path);
// Reads a whole file. Empty on failure.
std::vector<uint8_t> read_file_bytes(const std::string& path);

// Writes an 8-bit paletted PNG (palette: 256 RGB triples).
bool write_indexed_png(const std::string& path, const IndexedImage& image, const std::vector<uint8_t>& palette,
                       std::string* error = nullptr);
// Reads an 8-bit paletted PNG written by write_indexed_png (indices, not colours).
bool read_indexed_png(const std::string& path, IndexedImage* image, std::string* error = nullptr);
// Writes a 24-bit RGB PNG (rgb: width * height * 3 bytes).
bool write_rgb_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb,
                   std::string* error = nullptr);

}  // namespace sb::test
