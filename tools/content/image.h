// tools/content/image.h: full-colour texture images and their conversion to 8-bit
// miptex (four mip levels of palette indices).
//
// An Image holds, per texel, a gamma sRGB colour and a class that decides which palette
// entries the quantiser may use (palette.h):
//   kLit          0..223 (or 1..223 when QuantizeOptions::opaque_zero: sky front layer)
//   kFullbright   224..254, unchanged by light
//   kTransparent  index 0 (sky front layer holes)
// Mip m (0..3) of a W x H image is (W >> m) x (H >> m): each texel is the box average
// (in gamma RGB) of the opaque texels among the 2^m x 2^m full-resolution texels of its
// block, fullbright when at least half of those are, transparent when most of the block
// is; then quantised. So every mip is filtered from the original colours, not from an
// already quantised level, and keeps the mean colour.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tools/content/color.h"
#include "tools/content/palette.h"

namespace sb::content {

enum class TexelClass : uint8_t { kLit, kFullbright, kTransparent };

struct Texel {
  Rgb c;
  TexelClass cls = TexelClass::kLit;
};

struct Image {
  int width = 0, height = 0;
  std::vector<Texel> texels;  // row-major

  Image() = default;
  Image(int w, int h) : width(w), height(h), texels(size_t(w) * h) {}
  // Wrapping access (tileable textures): any x, y.
  Texel& at(int x, int y) { return texels[size_t(wrap(y, height)) * width + wrap(x, width)]; }
  const Texel& at(int x, int y) const { return texels[size_t(wrap(y, height)) * width + wrap(x, width)]; }
  static int wrap(int i, int n) { return ((i % n) + n) % n; }
};

// Calls f(x, y, u, v) for every texel (u, v = texel centre in 0..1) and stores the Texel
// it returns.
template <class F>
Image generate(int width, int height, F f) {
  Image img(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img.texels[size_t(y) * width + x] = f(x, y, (x + 0.5f) / float(width), (y + 0.5f) / float(height));
  return img;
}

// Colour at position t (0 dark .. 1 light) along a palette ramp, interpolating between
// the ramp's 16 shades, so generated colours sit on (or between) palette entries.
Rgb ramp_color(const PaletteData& pal, int ramp, float t);
// Colour of fullbright group `first` (kFb*), `count` entries, at t 0..1.
Rgb fullbright_color(const PaletteData& pal, int first, int count, float t);

struct QuantizeOptions {
  float dither = 0.0f;       // ordered (4x4 Bayer) dither amplitude in gamma units, 0 = off
  bool opaque_zero = false;  // lit texels avoid index 0 (sky front layer)
};

// A texture ready for a WAD or BSP: name (<= 15 chars), size (multiples of 16) and four
// mip levels of palette indices.
struct Miptex {
  std::string name;
  int width = 0, height = 0;
  std::array<std::vector<uint8_t>, 4> mips;
};

// Averages one mip level from `img` (level 0 returns a copy).
Image downsample(const Image& img, int level);
// Quantises an image (one level) to palette indices.
std::vector<uint8_t> quantize(const PaletteData& pal, const Image& img, const QuantizeOptions& opt);
// All four levels of `img` as a Miptex.
Miptex build_miptex(const PaletteData& pal, const std::string& name, const Image& img, const QuantizeOptions& opt);

// Tiny bitmap font (5 x 7 texels per glyph, upper-case letters, digits and a few marks)
// for the editor-only marker textures. Draws `text` with its top-left corner at (x, y),
// each font texel a scale x scale block, into texels with colour c (class unchanged).
void draw_text(Image& img, int x, int y, const char* text, int scale, Rgb c);
// Pixel width of `text` at `scale` (6 texels per glyph including spacing, minus one).
int text_width(const char* text, int scale);

}  // namespace sb::content
