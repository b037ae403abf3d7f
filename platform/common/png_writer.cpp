// platform/common/png_writer.cpp: 8-bit frame + palette -> RGB PNG through libpng.
// libpng reports errors by longjmp; the setjmp frame here turns that into false.
#include <csetjmp>
#include <cstdio>
#include <cstring>

#include <png.h>

#include "platform/common/platform.h"

namespace sb::platform {
namespace {

struct PngErrorState {
  char* error;
  size_t error_size;
  const char* path;
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* st = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(st->error, st->error_size, "%s: libpng: %s", st->path, message);
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

constexpr int kMaxRow = 4096;

}  // namespace

bool write_png_rgb(const char* path, const uint8_t* pixels, int width, int height, int stride,
                   const uint8_t* palette, char* error, size_t error_size) {
  if (!pixels || !palette || width <= 0 || height <= 0 || width > kMaxRow || stride < width) {
    std::snprintf(error, error_size, "%s: bad image (%dx%d, stride %d)", path, width, height, stride);
    return false;
  }
  std::FILE* f = std::fopen(path, "wb");
  if (!f) {
    std::snprintf(error, error_size, "%s: cannot open for writing", path);
    return false;
  }
  PngErrorState st{error, error_size, path};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &st, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    std::snprintf(error, error_size, "%s: libpng could not start", path);
    png_destroy_write_struct(png ? &png : nullptr, nullptr);
    std::fclose(f);
    return false;
  }
  static thread_local uint8_t row[kMaxRow * 3];  // no per-call heap for the row
  bool ok = false;
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y) {
      const uint8_t* src = pixels + size_t(y) * size_t(stride);
      for (int x = 0; x < width; ++x) std::memcpy(row + x * 3, palette + src[x] * 3, 3);
      png_write_row(png, row);
    }
    png_write_end(png, nullptr);
    ok = true;
  }
  png_destroy_write_struct(&png, &info);
  if (std::fclose(f) != 0 && ok) {
    std::snprintf(error, error_size, "%s: write failed (disk full?)", path);
    ok = false;
  }
  return ok;
}

}  // namespace sb::platform
