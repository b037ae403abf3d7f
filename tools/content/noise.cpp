// tools/content/noise.cpp: see noise.h.
#include "tools/content/noise.h"

#include <cmath>

namespace sb::content {
namespace {

int wrap(int i, int f) { return ((i % f) + f) % f; }
float fade(float t) { return t * t * t * (t * (t * 6 - 15) + 10); }
float mixf(float a, float b, float t) { return a + (b - a) * t; }

// Splits u * f into a wrapped lattice cell and the fraction inside it.
void lattice(float u, int f, int* i0, int* i1, float* frac) {
  float x = u * float(f);
  float fl = std::floor(x);
  *frac = x - fl;
  *i0 = wrap(int(fl), f);
  *i1 = wrap(int(fl) + 1, f);
}

float grad_dot(int ix, int iy, uint32_t seed, float dx, float dy) {
  uint32_t h = hash3(ix, iy, seed);
  float angle = hash01(h) * 6.28318531f;
  return std::cos(angle) * dx + std::sin(angle) * dy;
}

}  // namespace

uint32_t hash3(int32_t x, int32_t y, uint32_t seed) {
  uint32_t h = uint32_t(x) * 0x9e3779b1u + uint32_t(y) * 0x85ebca77u + seed * 0xc2b2ae3du + 0x27d4eb2fu;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

float value_noise_xy(float u, float v, int f_x, int f_y, uint32_t seed) {
  int x0, x1, y0, y1;
  float fx, fy;
  lattice(u, f_x, &x0, &x1, &fx);
  lattice(v, f_y, &y0, &y1, &fy);
  float a = hash01(hash3(x0, y0, seed)), b = hash01(hash3(x1, y0, seed));
  float c = hash01(hash3(x0, y1, seed)), d = hash01(hash3(x1, y1, seed));
  float sx = fade(fx), sy = fade(fy);
  return mixf(mixf(a, b, sx), mixf(c, d, sx), sy);
}

float gradient_noise_xy(float u, float v, int f_x, int f_y, uint32_t seed) {
  int x0, x1, y0, y1;
  float fx, fy;
  lattice(u, f_x, &x0, &x1, &fx);
  lattice(v, f_y, &y0, &y1, &fy);
  float a = grad_dot(x0, y0, seed, fx, fy), b = grad_dot(x1, y0, seed, fx - 1, fy);
  float c = grad_dot(x0, y1, seed, fx, fy - 1), d = grad_dot(x1, y1, seed, fx - 1, fy - 1);
  float sx = fade(fx), sy = fade(fy);
  return 1.4142f * mixf(mixf(a, b, sx), mixf(c, d, sx), sy);
}

float fbm_value_xy(float u, float v, int f_x, int f_y, int octaves, float gain, uint32_t seed) {
  float sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * value_noise_xy(u, v, f_x << o, f_y << o, seed + uint32_t(o) * 101u);
    norm += amp;
    amp *= gain;
  }
  return sum / norm;
}

float fbm_gradient_xy(float u, float v, int f_x, int f_y, int octaves, float gain, uint32_t seed) {
  float sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * gradient_noise_xy(u, v, f_x << o, f_y << o, seed + uint32_t(o) * 131u);
    norm += amp;
    amp *= gain;
  }
  return sum / norm;
}

float fbm_ridged_xy(float u, float v, int f_x, int f_y, int octaves, float gain, uint32_t seed) {
  float sum = 0, amp = 1, norm = 0;
  for (int o = 0; o < octaves; ++o) {
    float n = 1.0f - std::fabs(gradient_noise_xy(u, v, f_x << o, f_y << o, seed + uint32_t(o) * 151u));
    sum += amp * n * n;
    norm += amp;
    amp *= gain;
  }
  return sum / norm;
}

Cells cellular(float u, float v, int f, float jitter, uint32_t seed) {
  float x = u * float(f), y = v * float(f);
  int cx = int(std::floor(x)), cy = int(std::floor(y));
  Cells out{1e9f, 1e9f, 0};
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      int gx = cx + dx, gy = cy + dy;
      int wx = wrap(gx, f), wy = wrap(gy, f);
      uint32_t h = hash3(wx, wy, seed);
      float px = float(gx) + 0.5f + jitter * (hash01(h) - 0.5f);
      float py = float(gy) + 0.5f + jitter * (hash01(hash3(wx, wy, seed ^ 0x5bd1e995u)) - 0.5f);
      float d = std::sqrt((px - x) * (px - x) + (py - y) * (py - y));
      if (d < out.f1) {
        out.f2 = out.f1;
        out.f1 = d;
        out.cell = h;
      } else if (d < out.f2) {
        out.f2 = d;
      }
    }
  }
  return out;
}

}  // namespace sb::content
