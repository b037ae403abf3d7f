// tools/content/texture_kit.h: small shading helpers shared by the texture generators
// (internal to tools/content). All pure; coordinates in texels unless stated.
#pragma once
#include <algorithm>
#include <cmath>

#include "tools/content/color.h"
#include "tools/content/image.h"
#include "tools/content/noise.h"

namespace sb::content::kit {

inline float smoothstep(float e0, float e1, float x) {
  float t = clamp01((x - e0) / (e1 - e0));
  return t * t * (3 - 2 * t);
}
inline Texel lit(Rgb c) { return {clamp01(c), TexelClass::kLit}; }
inline Texel glow(Rgb c) { return {clamp01(c), TexelClass::kFullbright}; }
inline Texel clear() { return {{0, 0, 0}, TexelClass::kTransparent}; }

// Bevel of a w x h block for a texel at (lx, ly) inside it: light comes from the top
// left, so texels within `size` of the top or left edge brighten and those near the
// bottom or right edge darken. Returns a multiplier around 1.
inline float bevel(float lx, float ly, float w, float h, float size, float strength) {
  float top = std::min(lx, ly), bottom = std::min(w - 1 - lx, h - 1 - ly);
  if (top < size && top <= bottom) return 1.0f + strength * (1.0f - top / size);
  if (bottom < size) return 1.0f - strength * (1.0f - bottom / size);
  return 1.0f;
}

// A round rivet (or bolt) of radius r centred at (cx, cy): returns 0 outside, otherwise
// a shading multiplier (highlight towards the top left, shadow below right). *inside
// says whether the texel is on the rivet.
inline float rivet(float x, float y, float cx, float cy, float r, bool* inside) {
  float dx = x - cx, dy = y - cy;
  float d2 = dx * dx + dy * dy;
  *inside = d2 <= r * r;
  if (!*inside) {
    // A soft drop shadow below right of the rivet.
    float sx = dx - 1.0f, sy = dy - 1.0f;
    return (sx * sx + sy * sy <= r * r) ? 0.7f : 1.0f;
  }
  float nz = std::sqrt(std::max(0.0f, 1.0f - d2 / (r * r)));
  float light = (-dx - dy) / (r * 1.4142f) * 0.6f + nz * 0.5f;
  return 0.75f + 0.6f * light;
}

// Distance from (x, y) to the nearest point of a periodic grid of lines spaced `step`
// (texels), used for grout and seams.
inline float grid_dist(float x, float step) {
  float m = std::fmod(x, step);
  if (m < 0) m += step;
  return std::min(m, step - m);
}

}  // namespace sb::content::kit
