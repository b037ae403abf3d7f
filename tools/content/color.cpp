// tools/content/color.cpp: sRGB <-> OkLab (see color.h).
#include "tools/content/color.h"

#include <cmath>

namespace sb::content {
namespace {

float to_linear(float v) {
  v = clamp01(v);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
float to_gamma(float v) {
  if (v <= 0.0031308f) return 12.92f * v;  // negative values stay negative (out of gamut)
  return 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

OkLab to_oklab(Rgb c) {
  float r = to_linear(c.r), g = to_linear(c.g), b = to_linear(c.b);
  float l = std::cbrt(0.4122214708f * r + 0.5363325363f * g + 0.0514459929f * b);
  float m = std::cbrt(0.2119034982f * r + 0.6806995451f * g + 0.1073969566f * b);
  float s = std::cbrt(0.0883024619f * r + 0.2817188376f * g + 0.6299787005f * b);
  return {0.2104542553f * l + 0.7936177850f * m - 0.0040720468f * s,
          1.9779984951f * l - 2.4285922050f * m + 0.4505937099f * s,
          0.0259040371f * l + 0.7827717662f * m - 0.8086757660f * s};
}

Rgb from_oklab(OkLab c) {
  float l = c.L + 0.3963377774f * c.a + 0.2158037573f * c.b;
  float m = c.L - 0.1055613458f * c.a - 0.0638541728f * c.b;
  float s = c.L - 0.0894841775f * c.a - 1.2914855480f * c.b;
  l = l * l * l;
  m = m * m * m;
  s = s * s * s;
  return {to_gamma(4.0767416621f * l - 3.3077115913f * m + 0.2309699292f * s),
          to_gamma(-1.2684380046f * l + 2.6097574011f * m - 0.3413193965f * s),
          to_gamma(-0.0041960863f * l - 0.7034186147f * m + 1.7076147010f * s)};
}

Rgb from_oklch_clipped(float L, float C, float hue_degrees) {
  float h = hue_degrees * 3.14159265f / 180.0f;
  float ca = std::cos(h), sb = std::sin(h);
  // Bisection on chroma: the largest C' <= C whose colour is inside the gamut.
  Rgb best = from_oklab({L, 0, 0});
  float lo = 0, hi = C;
  Rgb full = from_oklab({L, C * ca, C * sb});
  if (in_gamut(full)) return clamp01(full);
  for (int i = 0; i < 24; ++i) {
    float mid = 0.5f * (lo + hi);
    Rgb t = from_oklab({L, mid * ca, mid * sb});
    if (in_gamut(t)) {
      lo = mid;
      best = t;
    } else {
      hi = mid;
    }
  }
  return clamp01(best);
}

}  // namespace sb::content
