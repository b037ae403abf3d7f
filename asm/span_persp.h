// asm/span_persp.h: the whole-span lit-surface drawer with the perspective divide inside:
// one call per span (x0 .. x0 + n - 1 of a scanline) instead of one surface_span call per
// 16-pixel run. Contract, the reference, and the tuned version. Variants: asm/kernels.h.
//
// It draws exactly the bytes engine/render/span_draw.cpp's run walker draws through
// surface_span (tests/asm/span_persp_test.cpp compares them on real and random spans):
//
//   exact(px):  zi = zi0 + dzi * px;  zi = max(zi, 1e-9) (NaN -> 1e-9);  z = 1 / zi
//               u = fix((uz0 + duz * px) * z, umax),  v = fix((vz0 + dvz * px) * z, vmax)
//               fix(q, m) = 0 when !(q * 65536 > 0), m when q * 65536 > m, else
//               int32(q * 65536) (truncation)
//   runs:       16 pixels each, the last one n % 16 (or 16); the exact samples are taken
//               at each run's first pixel and at the next run's first pixel (16 on), or for
//               the last run at its own last pixel; px = px0 + pixel offset.
//   steps:      linear: d = (b - a) / steps (64-bit, truncated toward zero), dd = 0; with
//               second_order, the parabola of span_draw.cpp's run_steps (curve = dzi / 2 *
//               (z_a + z_b)), accepted only when it stays monotone between a and b.
//   pixels:     dest[k] = texels[(v_k >> 16) * width + (u_k >> 16)] within each run,
//               u_{k+1} = u_k + du_k, du_{k+1} = du_k + ddu (asm/surface_span.h).
// Every double operation is the engine's, in the engine's order, so the results are the
// same bits; the next run's divide is issued before the current run is drawn, so its
// latency hides behind the integer loop.
//
// Contract: n >= 0 (any length); 1 <= width, height <= 32767; texels: width * height bytes;
// umax = (width << 16) - 1 and vmax = (height << 16) - 1 or smaller, >= 0 (then every
// u, v lies inside the surface: no read outside texels); dest: n bytes, no alignment;
// gradients any finite values (infinities and NaN are clamped like the engine clamps them).
#pragma once
#include <cstdint>

namespace sb::simd {

// One span's perspective gradients along its scanline, in the engine's units
// (engine/render/span_draw.h): 1/z, u/z and v/z as affine functions of the pixel-centre
// screen x: value(px) = value0 + step * px. u, v in texels (16.16 after the divide).
struct PerspSpan {
  double zi0, dzi;
  double uz0, duz;
  double vz0, dvz;
  double px0;            // the first pixel's centre: x0 + 0.5
  int32_t umax, vmax;    // the clamps, 16.16
  bool second_order;     // false: linear steps between the exact samples (Quake's way)
};

using SurfaceSpanPerspFn = void (*)(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                                    const PerspSpan& span);

// One span of a batch: dest, its length n and its gradients (SurfaceSpanPerspFn's arguments).
struct PerspItem {
  uint8_t* dest;
  int32_t n;
  PerspSpan span;
};

// A batch of spans of one surface (engine/render/span_draw.cpp draws a surface's spans so):
// the same as count calls of a SurfaceSpanPerspFn, items[0] first, with these texels, width
// and height. Contract: count >= 0; each item as SurfaceSpanPerspFn's contract above; the
// items' dest ranges overlap neither each other nor texels. A batch lets a variant share
// per-call work between spans (register saves; on aarch64 two short spans' samples in one
// block).
using SurfaceSpansPerspFn = void (*)(const PerspItem* items, int count, const uint8_t* texels, int width,
                                     int height);

// Reference (asm/span_persp.cpp): the engine's run walker (asm/span_walk.h), calling
// surface_span_scalar per run, its run steps dividing by the run's step count like the
// engine does.
void surface_span_persp_scalar(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                               const PerspSpan& span);
// Batch reference: surface_span_persp_scalar per item, in order.
void surface_spans_persp_scalar(const PerspItem* items, int count, const uint8_t* texels, int width, int height);

// Tuned, portable C++ (asm/span_persp_fast.cpp), in every non-scalar table. Per 16-pixel run
// only the linear inner loop's work plus the run's setup: two runs per loop pass, each run
// fully unrolled and software-pipelined two pixels at a time (u and v packed in one 64-bit
// register on 64-bit targets; texels gathered into words for one store per 8 / 4 on ARM);
// the setup (to_fixed of the next samples, the next runs' steps) branch-free and
// interleaved with the drawing, one dependent step per pixel group; the divides for the samples two runs ahead issued in pairs (one vector divide on
// aarch64) so their latency runs under the drawing; full runs' divisions by the constant 16,
// the last run's by constants too (no 64-bit divide instruction or armhf library call; on
// ARM second-order last runs branch-free, from the quotient of one divide; on aarch64 that
// quotient correctly rounded from a table of 1 / steps and two fused multiply-adds).
// aarch64, spans of 17 .. 64 pixels: every sample's reciprocal first (second order: Newton
// steps from frecpe, correctly rounded, proof in asm/span_persp_a64short.h), then the
// conversions (and second-order steps) in vectors; linear: one asm block from the samples to
// every run's step in integer registers (asm/span_persp_a64lin.h); then the runs (pairs as
// one fixed-register asm pass). Longer spans (linear over 48
// pixels, second-order over 80): each pass of 32 pixels one pipeline of eight 4-pixel groups
// in inline asm, ordered for in-order cores, with the samples' double arithmetic in 2-lane
// vectors and to_fixed as saturating integer clamps.
void surface_span_persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                             const PerspSpan& span);
// Batch, tuned: surface_span_persp_fast per item, in order, in one function (register saves
// once per batch); on aarch64 two neighbouring short second-order items (17 .. 64 pixels)
// take their samples from one asm block (asm/span_persp_a64pair.h), the rest per item.
void surface_spans_persp_fast(const PerspItem* items, int count, const uint8_t* texels, int width, int height);

}  // namespace sb::simd
