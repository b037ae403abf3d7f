// tools/content/textures_special.cpp: sky, turbulent liquids and the compiler markers.
#include <algorithm>
#include <cmath>

#include "tools/content/texture_kit.h"
#include "tools/content/textures.h"

namespace sb::content {
using namespace kit;

// Sky, 2H x H: left half the front layer (cloud wisps; index 0 where clear), right half
// the back layer (a dusk nebula gradient with stars). Both halves tile on their own.
Image make_sky(const PaletteData& pal, int w, int h, uint32_t seed) {
  const int half = w / 2;
  return generate(w, h, [&](int x, int y, float, float v) {
    float lu = (float(x % half) + 0.5f) / float(half);
    if (x < half) {
      // Wisps: streaky fractal (stretched across), thresholded; cores white, edges lilac.
      float warp = fbm_gradient(lu, v, 2, 3, 0.5f, seed + 5);
      float streak = fbm_value_xy(lu + 0.1f * warp, v, 2, 6, 4, 0.55f, seed + 6);
      float mass = fbm_value(lu, v, 2, 3, 0.5f, seed);
      float density = smoothstep(0.58f, 0.74f, streak * 0.75f + mass * 0.35f);
      if (density < 0.3f) return clear();
      float core = density * (0.8f + 0.2f * fbm_value(lu, v, 8, 2, 0.5f, seed + 7));
      Rgb c = lerp(ramp_color(pal, kRampPurple, 0.5f), ramp_color(pal, kRampSky, 0.97f), core);
      return lit(c);
    }
    // Back layer: deep blue night with violet nebula clouds and stars.
    float n = fbm_value(lu, v, 2, 5, 0.55f, seed + 1);
    float m = fbm_value(lu, v, 4, 4, 0.5f, seed + 3);
    Rgb c = ramp_color(pal, kRampBlue, 0.1f + 0.14f * m);
    c = lerp(c, ramp_color(pal, kRampPurple, 0.25f + 0.12f * m), smoothstep(0.42f, 0.68f, n) * 0.85f);
    uint32_t s = hash3(x, y, seed + 2);
    if (hash01(s) > 0.993f) c = ramp_color(pal, kRampSky, 0.8f + 0.2f * hash01(rehash(s, 3)));
    else if (hash01(s) > 0.985f) c = c * 1.5f;
    return lit(c);
  });
}

// Water: deep blue-green with bright caustic lines along cell borders.
Image make_water(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int, int, float u, float v) {
    float warp = fbm_gradient(u, v, 2, 3, 0.5f, seed + 1) * 0.06f;
    Cells c = cellular(u + warp, v - warp, 4, 0.9f, seed);
    float caustic = smoothstep(0.12f, 0.0f, c.f2 - c.f1);
    float n = fbm_value(u, v, 4, 4, 0.5f, seed + 2);
    Rgb base = lerp(ramp_color(pal, kRampBlue, 0.28f + 0.12f * n), ramp_color(pal, kRampTeal, 0.3f + 0.1f * n), 0.4f);
    return lit(lerp(base, ramp_color(pal, kRampSky, 0.7f), caustic * 0.7f));
  });
}

// Slime: murky green with bubbles (lighter rims around cellular centres).
Image make_slime(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int, int, float u, float v) {
    float n = fbm_value(u, v, 4, 5, 0.55f, seed);
    Cells c = cellular(u, v, 4, 0.8f, seed + 1);
    float r = 0.2f + 0.15f * hash01(c.cell);
    bool bubble = hash01(rehash(c.cell, 7)) > 0.35f;
    float rim = bubble ? smoothstep(0.09f, 0.0f, std::fabs(c.f1 - r)) : 0.0f;
    float inside = bubble && c.f1 < r ? 1.0f : 0.0f;
    Rgb base = lerp(ramp_color(pal, kRampGreen, 0.15f + 0.35f * n), ramp_color(pal, kRampTeal, 0.25f + 0.25f * n), 0.3f);
    base = lerp(base, ramp_color(pal, kRampMoss, 0.45f), inside * 0.5f);
    return lit(lerp(base, ramp_color(pal, kRampMoss, 0.85f), rim * 0.85f));
  });
}

// Lava: dark crust plates floating on glowing cracks (the hot part is fullbright).
Image make_lava(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int, int, float u, float v) {
    float warp = fbm_gradient(u, v, 2, 3, 0.5f, seed + 1) * 0.08f;
    Cells c = cellular(u + warp, v + warp, 4, 1.0f, seed);
    float heat = smoothstep(0.16f, 0.0f, c.f2 - c.f1);
    float n = fbm_value(u, v, 8, 4, 0.5f, seed + 2);
    heat = clamp01(heat + 0.35f * smoothstep(0.6f, 0.85f, n));
    if (heat > 0.35f) return glow(fullbright_color(pal, kFbFire, 8, (heat - 0.35f) / 0.65f));
    return lit(lerp(ramp_color(pal, kRampRed, 0.12f + 0.15f * n), ramp_color(pal, kRampRust, 0.35f), heat * 1.6f));
  });
}

// Teleporter: swirling violet and cyan energy.
Image make_teleport(const PaletteData& pal, int w, int h, uint32_t seed) {
  return generate(w, h, [&](int, int, float u, float v) {
    float a = fbm_gradient(u, v, 2, 4, 0.6f, seed);
    float b = fbm_gradient(u, v, 3, 4, 0.6f, seed + 1);
    float swirl = 0.5f + 0.5f * std::sin((u + v + a * 0.8f) * 6.2831853f * 2 + b * 4);
    float spark = smoothstep(0.9f, 1.0f, swirl) * smoothstep(0.3f, 0.6f, (b + 1) * 0.5f);
    Rgb c = lerp(ramp_color(pal, kRampPurple, 0.2f + 0.3f * swirl), ramp_color(pal, kRampSky, 0.7f), spark);
    return lit(c);
  });
}

// Compiler markers: striped fields with a label, obvious in an editor.
namespace {
Image marker(const PaletteData& pal, int w, int h, int ramp, const char* label, int scale) {
  Image img = generate(w, h, [&](int x, int y, float, float) {
    float m = std::fmod(float(x - y + 4 * h), 16.0f);
    Rgb c = ramp_color(pal, ramp, m < 8 ? 0.45f : 0.6f);
    if (x == 0 || y == 0 || x == w - 1 || y == h - 1) c = ramp_color(pal, ramp, 0.85f);
    return lit(c);
  });
  int tw = text_width(label, scale), th = 7 * scale;
  int x0 = (w - tw) / 2, y0 = (h - th) / 2;
  for (int y = y0 - 2; y < y0 + th + 2; ++y)
    for (int x = x0 - 2; x < x0 + tw + 2; ++x) img.at(x, y).c = ramp_color(pal, ramp, 0.15f);
  draw_text(img, x0, y0, label, scale, ramp_color(pal, kRampGrey, 1.0f));
  return img;
}
}  // namespace

Image make_clip(const PaletteData& pal, int w, int h, uint32_t) { return marker(pal, w, h, kRampPurple, "CLIP", 2); }
Image make_trigger(const PaletteData& pal, int w, int h, uint32_t) { return marker(pal, w, h, kRampRust, "TRIGGER", 1); }
Image make_skip(const PaletteData& pal, int w, int h, uint32_t) { return marker(pal, w, h, kRampGrey, "SKIP", 2); }

}  // namespace sb::content
