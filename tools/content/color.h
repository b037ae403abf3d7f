// tools/content/color.h: colours as the content generator sees them.
//
//   Rgb     gamma-encoded sRGB, each channel a float in 0..1 (values outside are
//           clamped where they are converted to bytes or compared).
//   OkLab   Ottosson's perceptual space (public formulas): L in 0..1 (black..white),
//           a, b roughly -0.4..0.4. Distances in it are the generator's "perceptual-ish"
//           colour metric: palette matching, colormap rows and texture quantisation all use it.
// Pure functions, no allocation. Tools code: may use the heap elsewhere, never throws.
#pragma once
#include <cstdint>

namespace sb::content {

struct Rgb {
  float r = 0, g = 0, b = 0;
};
struct OkLab {
  float L = 0, a = 0, b = 0;
};

inline float clamp01(float v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }
inline Rgb clamp01(Rgb c) { return {clamp01(c.r), clamp01(c.g), clamp01(c.b)}; }
inline Rgb operator+(Rgb x, Rgb y) { return {x.r + y.r, x.g + y.g, x.b + y.b}; }
inline Rgb operator-(Rgb x, Rgb y) { return {x.r - y.r, x.g - y.g, x.b - y.b}; }
inline Rgb operator*(Rgb x, float s) { return {x.r * s, x.g * s, x.b * s}; }
inline Rgb lerp(Rgb x, Rgb y, float t) { return x + (y - x) * t; }
// 0..255 bytes to Rgb and back (rounded, clamped).
inline Rgb rgb8(int r, int g, int b) { return {r / 255.0f, g / 255.0f, b / 255.0f}; }
inline uint8_t to_byte(float v) { return uint8_t(clamp01(v) * 255.0f + 0.5f); }

// sRGB (gamma) <-> OkLab. from_oklab does not clamp: callers test in_gamut().
OkLab to_oklab(Rgb c);
Rgb from_oklab(OkLab c);
inline bool in_gamut(Rgb c, float eps = 1e-4f) {
  return c.r >= -eps && c.r <= 1 + eps && c.g >= -eps && c.g <= 1 + eps && c.b >= -eps && c.b <= 1 + eps;
}
// Lightness/chroma/hue (hue in degrees) to sRGB, reducing chroma until the colour fits
// the sRGB gamut (so a ramp keeps its lightness and hue and loses saturation at the ends).
Rgb from_oklch_clipped(float L, float C, float hue_degrees);

// Squared OkLab distance.
inline float lab_dist2(OkLab x, OkLab y) {
  float dL = x.L - y.L, da = x.a - y.a, db = x.b - y.b;
  return dL * dL + da * da + db * db;
}
// Rec. 709 luma of gamma values (0..1); a cheap brightness for tests and ordering.
inline float luma(Rgb c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace sb::content
