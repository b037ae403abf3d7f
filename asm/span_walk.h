// asm/span_walk.h: the perspective run walker shared by the engine's span drawers
// (engine/render/span_draw.cpp) and the whole-span drawer's reference (asm/span_persp.cpp):
// one definition, so the reference repeats the engine's arithmetic by construction.
// asm/span_persp_run.h and asm/span_persp_fast.cpp repeat it in select form (same bits).
//
// Fixed point: u and v are 16.16, clamped to [0, max]. Within a run both ends are clamped
// and the step is the truncated quotient (toward zero), so every intermediate value lies
// between the two ends: the walk never leaves the surface.
#pragma once
#include <cstdint>

namespace sb::simd::span_walk {

constexpr double kMinZi = 1e-9;  // 1/z is clamped to at least this (NaN too)

// v * 65536 in 16.16, clamped to [0, max]; NaN and negatives go to 0.
inline int32_t to_fixed(double v, int32_t max) {
  const double q = v * 65536.0;
  if (!(q > 0.0)) return 0;
  if (q > double(max)) return max;
  return int32_t(q);
}

// Steps for one run of `steps` pixels from a (at pixel 0) to b (at pixel `steps`), 16.16.
// Linear: d = (b - a) / steps, dd = 0. Second order: over a planar surface the true
// coordinate is a Moebius function of x, and the chord between two exact samples misses it
// by (delta / L) * zix * x (L - x) / zi(x). With 1/zi(x) taken as the mean of the two ends'
// depths (z0 + z1) / 2, that is a parabola: per-pixel step d, changing by dd each pixel.
// The result is accepted only when every step keeps the sign of b - a and the last pixel
// lands between a and b, so the walk stays between its clamped ends; otherwise linear.
struct RunSteps {
  int32_t d, dd;
};

// run_steps with the quotient double(b - a) / steps given by quotient() (called only when
// curve != 0 and steps >= 2). Steps is int (any run) or std::integral_constant<int, S>
// (then every integer division below is by a constant and compiles to shifts and multiplies,
// with the same results: integer division truncates toward zero either way).
template <class Steps, class Quotient>
inline RunSteps run_steps_with(int32_t a, int32_t b, Steps steps_, double curve, Quotient quotient) {
  const int steps = steps_;
  const int64_t delta = int64_t(b) - int64_t(a);
  const int32_t linear = int32_t(delta / steps);  // truncation: never overshoots b
  if (curve == 0.0 || steps < 2) return {linear, 0};
  const double c = quotient() * curve;
  const double ddf = -2.0 * c;
  if (!(ddf > -1e9 && ddf < 1e9)) return {linear, 0};
  const int64_t dd = int64_t(ddf);
  const int64_t bend = dd * steps * (steps - 1) / 2;
  const int64_t d0 = (delta - bend) / steps;
  const int64_t last_step = d0 + dd * (steps - 1);
  const int64_t reach = d0 * steps + bend;
  const bool monotone = delta >= 0 ? (d0 >= 0 && last_step >= 0 && reach >= 0 && reach <= delta)
                                   : (d0 <= 0 && last_step <= 0 && reach <= 0 && reach >= delta);
  if (!monotone || d0 > INT32_MAX || d0 < INT32_MIN) return {linear, 0};
  return {int32_t(d0), int32_t(dd)};
}

// The run's steps (double / 16 is exact, as is double * 0.0625).
template <class Steps>
inline RunSteps run_steps(int32_t a, int32_t b, Steps steps_, double curve) {
  const int steps = steps_;
  if (steps <= 0) return {0, 0};
  return run_steps_with(a, b, steps_, curve, [&] { return double(int64_t(b) - int64_t(a)) / steps; });
}

// Draws one span of `total` pixels starting at `dest`, whose first pixel centre is at
// screen x = px, in runs of 16 pixels: exact coordinates at each run's ends (a span's last
// run ends at its last pixel), interpolated in between (see run_steps). The exact values for
// the end of the next run are computed before the current run is drawn, so the divide
// overlaps the drawing.
// exact(px, &a, &b, &z) gives the 16.16 coordinates and the depth z at screen x = px;
// zix is d(1/z)/dx (0 for linear stepping);
// run(dest, n, a, b, da, db, dda, ddb) draws n pixels from (a, b), stepping (da, db) per
// pixel, the steps changing by (dda, ddb) per pixel.
template <class Exact, class Run>
inline void walk_span(uint8_t* dest, double px, int total, double zix, const Exact& exact, const Run& run) {
  // Pixel offset (from a run's first pixel) of the exact sample that ends a run with
  // `left` pixels still to draw: 16 for a full run (the next run's first pixel), else its
  // last pixel.
  auto end_offset = [](int left) { return left > 16 ? 16 : left - 1; };
  int left = total;
  int32_t u0, v0, u1, v1;
  double z0, z1;
  exact(px, &u0, &v0, &z0);
  u1 = u0;
  v1 = v0;
  z1 = z0;
  if (end_offset(left) > 0) exact(px + end_offset(left), &u1, &v1, &z1);
  for (;;) {
    const int n = left > 16 ? 16 : left;
    const int after = left - n;
    // The divide for the end of the next run, issued before drawing this one.
    int32_t u2 = u1, v2 = v1;
    double z2 = z1;
    if (after > 0 && end_offset(after) > 0) exact(px + double(n + end_offset(after)), &u2, &v2, &z2);
    const int steps = end_offset(left);
    const double curve = zix * 0.5 * (z0 + z1);
    const RunSteps su = run_steps(u0, u1, steps, curve), sv = run_steps(v0, v1, steps, curve);
    run(dest, n, u0, v0, su.d, sv.d, su.dd, sv.dd);
    if (after <= 0) break;
    dest += n;
    px += double(n);
    left = after;
    u0 = u1;
    v0 = v1;
    z0 = z1;
    u1 = u2;
    v1 = v2;
    z1 = z2;
  }
}

}  // namespace sb::simd::span_walk
