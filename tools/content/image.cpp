// tools/content/image.cpp: ramps, mip filtering, quantisation and the marker font.
#include "tools/content/image.h"

#include <cmath>
#include <cstring>

namespace sb::content {

Rgb ramp_color(const PaletteData& pal, int ramp, float t) {
  float x = clamp01(t) * float(kRampSize - 1);
  int i = int(x);
  if (i >= kRampSize - 1) return pal.colors[ramp_index(ramp, kRampSize - 1)];
  return lerp(pal.colors[ramp_index(ramp, i)], pal.colors[ramp_index(ramp, i + 1)], x - float(i));
}

Rgb fullbright_color(const PaletteData& pal, int first, int count, float t) {
  float x = clamp01(t) * float(count - 1);
  int i = int(x);
  if (i >= count - 1) return pal.colors[first + count - 1];
  return lerp(pal.colors[first + i], pal.colors[first + i + 1], x - float(i));
}

Image downsample(const Image& img, int level) {
  int step = 1 << level;
  Image out(img.width >> level, img.height >> level);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      Rgb sum[3] = {};
      int count[3] = {0, 0, 0};
      for (int j = 0; j < step; ++j) {
        for (int i = 0; i < step; ++i) {
          const Texel& t = img.at(x * step + i, y * step + j);
          int k = int(t.cls);
          sum[k] = sum[k] + t.c;
          ++count[k];
        }
      }
      // Transparent only where most of the block is; otherwise the colour is the mean of
      // every opaque texel (so the mean colour survives), fullbright when at least half
      // of the opaque texels are.
      Texel& o = out.texels[size_t(y) * out.width + x];
      if (count[2] > count[0] + count[1]) {
        o = {{0, 0, 0}, TexelClass::kTransparent};
        continue;
      }
      o.cls = count[1] >= count[0] ? TexelClass::kFullbright : TexelClass::kLit;
      o.c = (sum[0] + sum[1]) * (1.0f / float(count[0] + count[1]));
    }
  }
  return out;
}

std::vector<uint8_t> quantize(const PaletteData& pal, const Image& img, const QuantizeOptions& opt) {
  static constexpr int kBayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
  std::vector<uint8_t> out(size_t(img.width) * img.height);
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const Texel& t = img.texels[size_t(y) * img.width + x];
      size_t o = size_t(y) * img.width + x;
      if (t.cls == TexelClass::kTransparent) {
        out[o] = 0;
        continue;
      }
      Rgb c = t.c;
      if (opt.dither > 0) {
        float d = (float(kBayer[y & 3][x & 3]) + 0.5f) / 16.0f - 0.5f;
        c = c + Rgb{d, d, d} * opt.dither;
      }
      IndexSet set = t.cls == TexelClass::kFullbright ? IndexSet::kFullbright
                     : opt.opaque_zero                ? IndexSet::kLitOpaque
                                                      : IndexSet::kLit;
      out[o] = uint8_t(nearest_index(pal, c, set));
    }
  }
  return out;
}

Miptex build_miptex(const PaletteData& pal, const std::string& name, const Image& img, const QuantizeOptions& opt) {
  Miptex m;
  m.name = name;
  m.width = img.width;
  m.height = img.height;
  m.mips[0] = quantize(pal, img, opt);
  for (int level = 1; level < 4; ++level) m.mips[size_t(level)] = quantize(pal, downsample(img, level), opt);
  return m;
}

// ---- marker font: 5 x 7 glyphs, one string per glyph row, '#' = ink. Designed for
// these textures only (letters needed by the editor marker textures plus digits).
namespace {

struct Glyph {
  char ch;
  const char* rows[7];
};

constexpr Glyph kGlyphs[] = {
    {'A', {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'B', {"####.", "#...#", "####.", "#...#", "#...#", "#...#", "####."}},
    {'C', {".####", "#....", "#....", "#....", "#....", "#....", ".####"}},
    {'D', {"####.", "#...#", "#...#", "#...#", "#...#", "#...#", "####."}},
    {'E', {"#####", "#....", "#....", "####.", "#....", "#....", "#####"}},
    {'G', {".####", "#....", "#....", "#.###", "#...#", "#...#", ".###."}},
    {'H', {"#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"}},
    {'I', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "#####"}},
    {'K', {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"}},
    {'L', {"#....", "#....", "#....", "#....", "#....", "#....", "#####"}},
    {'N', {"#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#", "#...#"}},
    {'O', {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'P', {"####.", "#...#", "#...#", "####.", "#....", "#....", "#...."}},
    {'R', {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"}},
    {'S', {".####", "#....", "#....", ".###.", "....#", "....#", "####."}},
    {'T', {"#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."}},
    {'U', {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."}},
    {'W', {"#...#", "#...#", "#...#", "#.#.#", "#.#.#", "##.##", "#...#"}},
    {'0', {".###.", "#..##", "#.#.#", "#.#.#", "##..#", "#...#", ".###."}},
    {'1', {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."}},
    {'2', {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"}},
    {'-', {".....", ".....", ".....", "#####", ".....", ".....", "....."}},
    {' ', {".....", ".....", ".....", ".....", ".....", ".....", "....."}},
};

const Glyph* find_glyph(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.ch == c) return &g;
  return nullptr;
}

}  // namespace

int text_width(const char* text, int scale) {
  int n = int(std::strlen(text));
  return n == 0 ? 0 : (n * 6 - 1) * scale;
}

void draw_text(Image& img, int x, int y, const char* text, int scale, Rgb c) {
  for (int k = 0; text[k]; ++k) {
    const Glyph* g = find_glyph(text[k]);
    if (!g) continue;
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col)
        if (g->rows[row][col] == '#')
          for (int j = 0; j < scale; ++j)
            for (int i = 0; i < scale; ++i)
              img.at(x + (k * 6 + col) * scale + i, y + row * scale + j).c = c;
  }
}

}  // namespace sb::content
