// tests/support/png_image.cpp: PNG reading and writing through libpng's classic API.
#include "tests/support/png_image.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

namespace sb::test {
namespace {

struct FileCloser {
  void operator()(FILE* f) const {
    if (f) std::fclose(f);
  }
};
using FilePtr = std::unique_ptr<FILE, FileCloser>;

void set_error(std::string* error, const std::string& msg) {
  if (error) *error = msg;
}

bool write_png(const std::string& path, int width, int height, int color_type, int bytes_per_pixel,
               const uint8_t* pixels, const std::vector<uint8_t>* palette, std::string* error) {
  FilePtr f(std::fopen(path.c_str(), "wb"));
  if (!f) {
    set_error(error, path + ": cannot open for writing");
    return false;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    set_error(error, path + ": libpng init failed");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    set_error(error, path + ": libpng write failed");
    return false;
  }
  png_init_io(png, f.get());
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, color_type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_color pal[256];
  if (palette) {
    for (int i = 0; i < 256; ++i) pal[i] = {(*palette)[i * 3], (*palette)[i * 3 + 1], (*palette)[i * 3 + 2]};
    png_set_PLTE(png, info, pal, 256);
  }
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(pixels + size_t(y) * width * bytes_per_pixel));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

std::vector<uint8_t> read_file_bytes(const std::string& path) {
  FilePtr f(std::fopen(path.c_str(), "rb"));
  if (!f) return {};
  std::vector<uint8_t> data;
  uint8_t buf[65536];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f.get())) > 0) data.insert(data.end(), buf, buf + n);
  return data;
}

std::vector<uint8_t> load_palette(const std::string& path) {
  std::vector<uint8_t> p = read_file_bytes(path);
  if (p.size() != 768) return {};
  return p;
}

bool write_indexed_png(const std::string& path, const IndexedImage& image, const std::vector<uint8_t>& palette,
                       std::string* error) {
  if (palette.size() != 768 || image.pixels.size() != size_t(image.width) * image.height) {
    set_error(error, path + ": bad palette or image size");
    return false;
  }
  return write_png(path, image.width, image.height, PNG_COLOR_TYPE_PALETTE, 1, image.pixels.data(), &palette,
                   error);
}

bool write_rgb_png(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb,
                   std::string* error) {
  if (rgb.size() != size_t(width) * height * 3) {
    set_error(error, path + ": bad image size");
    return false;
  }
  return write_png(path, width, height, PNG_COLOR_TYPE_RGB, 3, rgb.data(), nullptr, error);
}

bool read_indexed_png(const std::string& path, IndexedImage* image, std::string* error) {
  FilePtr f(std::fopen(path.c_str(), "rb"));
  if (!f) {
    set_error(error, path + ": cannot open");
    return false;
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    set_error(error, path + ": libpng init failed");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    set_error(error, path + ": not a readable PNG");
    return false;
  }
  png_init_io(png, f.get());
  png_read_info(png, info);
  png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
  int color_type = png_get_color_type(png, info), depth = png_get_bit_depth(png, info);
  if (color_type != PNG_COLOR_TYPE_PALETTE || depth != 8 || w == 0 || h == 0 || w > 8192 || h > 8192) {
    png_destroy_read_struct(&png, &info, nullptr);
    set_error(error, path + ": not an 8-bit paletted PNG");
    return false;
  }
  image->width = int(w);
  image->height = int(h);
  image->pixels.assign(size_t(w) * h, 0);
  for (png_uint_32 y = 0; y < h; ++y) png_read_row(png, image->pixels.data() + size_t(y) * w, nullptr);
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

}  // namespace sb::test
