// tools/content/palette.cpp: the palette is designed in OkLCh: each ramp has a hue, a
// peak chroma and a lightness span; shades step evenly in lightness and chroma peaks
// a little above the middle, so dark shades stay rich and light shades turn pastel.
#include "tools/content/palette.h"

#include <cmath>

namespace sb::content {
namespace {

struct RampSpec {
  float hue;       // degrees
  float chroma;    // peak OkLab chroma
  float l_dark;    // lightness of shade 0
  float l_light;   // lightness of shade 15
  float peak;      // 0..1: where along the ramp chroma peaks
};

// Index order matches enum Ramp.
constexpr RampSpec kRamps[kRampCount] = {
    {0, 0.0f, 0.0f, 1.0f, 0.5f},         // grey: black .. white
    {250, 0.028f, 0.13f, 0.90f, 0.4f},   // stone: cool blue-grey
    {55, 0.085f, 0.13f, 0.84f, 0.45f},   // brown: wood, earth
    {78, 0.065f, 0.22f, 0.95f, 0.6f},    // tan: sand, plaster, ceramic
    {142, 0.13f, 0.14f, 0.90f, 0.55f},   // green: grass, foliage
    {112, 0.085f, 0.14f, 0.88f, 0.5f},   // moss: olive, khaki
    {258, 0.14f, 0.11f, 0.88f, 0.45f},   // blue: water, deep sky
    {225, 0.11f, 0.17f, 0.96f, 0.55f},   // sky: pale cyan-blue
    {27, 0.17f, 0.12f, 0.85f, 0.45f},    // red: brick, warning
    {48, 0.15f, 0.16f, 0.92f, 0.55f},    // rust: orange
    {92, 0.14f, 0.22f, 0.97f, 0.7f},     // gold: yellow, brass
    {305, 0.13f, 0.11f, 0.88f, 0.45f},   // purple
    {238, 0.055f, 0.14f, 0.95f, 0.5f},   // steel: metal blue
    {178, 0.10f, 0.13f, 0.92f, 0.5f},    // teal: slime, patina
};

Rgb ramp_color(const RampSpec& r, int shade) {
  float t = float(shade) / float(kRampSize - 1);
  float L = r.l_dark + (r.l_light - r.l_dark) * t;
  // Chroma: a smooth hump that peaks at r.peak and keeps 30% at the ends.
  float d = (t - r.peak) / (t < r.peak ? r.peak : 1.0f - r.peak);
  float C = r.chroma * (0.3f + 0.7f * (1.0f - d * d));
  return from_oklch_clipped(L, C, r.hue);
}

void set_fullbrights(std::array<Rgb, 256>& c) {
  for (int i = 0; i < 8; ++i) {  // amber .. white
    float t = i / 7.0f;
    c[kFbWarmWhite + i] = from_oklch_clipped(0.78f + 0.19f * t, 0.13f * (1 - t) + 0.015f, 80);
  }
  for (int i = 0; i < 8; ++i) {  // deep red .. yellow
    float t = i / 7.0f;
    c[kFbFire + i] = from_oklch_clipped(0.50f + 0.45f * t, 0.20f - 0.04f * t, 28 + 72 * t);
  }
  for (int i = 0; i < 8; ++i) {  // blue .. cyan white
    float t = i / 7.0f;
    c[kFbCyan + i] = from_oklch_clipped(0.50f + 0.48f * t, 0.17f * (1 - t) + 0.03f, 262 - 60 * t);
  }
  for (int i = 0; i < 4; ++i) c[kFbGreen + i] = from_oklch_clipped(0.62f + 0.11f * i, 0.20f, 140);
  for (int i = 0; i < 3; ++i) c[kFbMagenta + i] = from_oklch_clipped(0.60f + 0.14f * i, 0.22f, 340);
  c[kTransparentIndex] = rgb8(255, 0, 255);
}

}  // namespace

PaletteData make_palette() {
  PaletteData p;
  for (int k = 0; k < kRampCount; ++k)
    for (int s = 0; s < kRampSize; ++s) p.colors[ramp_index(k, s)] = ramp_color(kRamps[k], s);
  p.colors[0] = {0, 0, 0};
  set_fullbrights(p.colors);
  for (int i = 0; i < 256; ++i) {
    p.bytes[i * 3 + 0] = to_byte(p.colors[i].r);
    p.bytes[i * 3 + 1] = to_byte(p.colors[i].g);
    p.bytes[i * 3 + 2] = to_byte(p.colors[i].b);
    p.lab[i] = to_oklab(rgb8(p.bytes[i * 3], p.bytes[i * 3 + 1], p.bytes[i * 3 + 2]));
  }
  return p;
}

int nearest_index(const PaletteData& pal, Rgb c, IndexSet set, float lightness_weight) {
  int first = 0, last = kFirstFullbright - 1;
  if (set == IndexSet::kLitOpaque) first = 1;
  if (set == IndexSet::kFullbright) {
    first = kFirstFullbright;
    last = kTransparentIndex - 1;
  }
  OkLab q = to_oklab(clamp01(c));
  int best = first;
  float best_d = 1e30f;
  for (int i = first; i <= last; ++i) {
    float dL = (q.L - pal.lab[i].L) * lightness_weight, da = q.a - pal.lab[i].a, db = q.b - pal.lab[i].b;
    float d = dL * dL + da * da + db * db;
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

std::vector<uint8_t> make_colormap(const PaletteData& pal) {
  std::vector<uint8_t> map(size_t(kColormapRowsCount) * 256 + 1);
  for (int row = 0; row < kColormapRowsCount; ++row) {
    float f = colormap_row_factor(row);
    for (int i = 0; i < 256; ++i) {
      uint8_t out;
      if (i >= kFirstFullbright) {
        out = uint8_t(i);
      } else {
        Rgb src = rgb8(pal.bytes[i * 3], pal.bytes[i * 3 + 1], pal.bytes[i * 3 + 2]);
        out = uint8_t(nearest_index(pal, src * f, IndexSet::kLit, row < kColormapIdentityRow ? 1.0f : kColormapLightnessWeight));
        // Never brighter than the row above (lighter light): keeps light gradients free
        // of bright bands where the nearest colour jumps between ramps.
        if (row > 0) {
          uint8_t above = map[size_t(row - 1) * 256 + i];
          if (pal.lab[out].L > pal.lab[above].L) out = above;
        }
      }
      map[size_t(row) * 256 + i] = out;
    }
  }
  map[size_t(kColormapRowsCount) * 256] = uint8_t(kFullbrightCount);
  return map;
}

}  // namespace sb::content
