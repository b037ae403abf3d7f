// tools/content/noise.h: deterministic, seeded, tileable noise for the texture generator.
//
// All functions take texture coordinates u, v in texture units of "one tile" (0..1 covers
// the texture once) and an integer lattice frequency f >= 1: the lattice has f cells across
// the tile and wraps, so every function here tiles seamlessly at u, v = 0 and 1.
// Results are pure functions of (inputs, seed): no global state, identical on every run
// and platform that uses IEEE float (the hashing is integer only).
#pragma once
#include <cstdint>

namespace sb::content {

// 32-bit integer hash of a lattice point and a seed (avalanching multiply-xorshift mix).
uint32_t hash3(int32_t x, int32_t y, uint32_t seed);
// Uniform float in [0, 1) from a hash.
inline float hash01(uint32_t h) { return float(h >> 8) * (1.0f / 16777216.0f); }
// A second, independent hash derived from h (use instead of shifting h, which would
// shrink hash01's range).
inline uint32_t rehash(uint32_t h, uint32_t salt) { return hash3(int32_t(h), int32_t(salt), 0x68e31da4u); }

// Value noise: random values on the lattice, quintic interpolation. Range 0..1.
// The *_xy forms take separate lattice frequencies across (fx) and down (fy) the tile,
// for stretched patterns (wood grain, brushed metal); the plain forms use f for both.
float value_noise_xy(float u, float v, int fx, int fy, uint32_t seed);
// Gradient (Perlin-style) noise: random unit gradients on the lattice. Range about -1..1.
float gradient_noise_xy(float u, float v, int fx, int fy, uint32_t seed);
// Fractal sums: `octaves` layers, frequency doubling and amplitude times `gain` each
// layer; normalised to 0..1 (fbm_value) or about -1..1 (fbm_gradient).
float fbm_value_xy(float u, float v, int fx, int fy, int octaves, float gain, uint32_t seed);
float fbm_gradient_xy(float u, float v, int fx, int fy, int octaves, float gain, uint32_t seed);
// Ridged fractal: 1 - |gradient| summed; sharp creases (rock strata, cracks). 0..1.
float fbm_ridged_xy(float u, float v, int fx, int fy, int octaves, float gain, uint32_t seed);

inline float value_noise(float u, float v, int f, uint32_t seed) { return value_noise_xy(u, v, f, f, seed); }
inline float gradient_noise(float u, float v, int f, uint32_t seed) { return gradient_noise_xy(u, v, f, f, seed); }
inline float fbm_value(float u, float v, int f, int octaves, float gain, uint32_t seed) {
  return fbm_value_xy(u, v, f, f, octaves, gain, seed);
}
inline float fbm_gradient(float u, float v, int f, int octaves, float gain, uint32_t seed) {
  return fbm_gradient_xy(u, v, f, f, octaves, gain, seed);
}
inline float fbm_ridged(float u, float v, int f, int octaves, float gain, uint32_t seed) {
  return fbm_ridged_xy(u, v, f, f, octaves, gain, seed);
}

// Cellular (Worley) noise: one jittered feature point per lattice cell (jitter 0..1).
// f1/f2: distances (in cell units) to the nearest and second nearest point; cell: a hash
// identifying the nearest point's cell (stable per cell, useful for per-stone colour).
struct Cells {
  float f1, f2;
  uint32_t cell;
};
Cells cellular(float u, float v, int f, float jitter, uint32_t seed);

}  // namespace sb::content
