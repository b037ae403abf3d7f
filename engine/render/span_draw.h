// engine/render/span_draw.h: the back end's span drawers. The lit-surface run and the z
// fill go through asm/ kernels (asm/kernels.h: tuned variant or, when forced, the scalar
// reference); the other drawers are scalar.
//
// Perspective: over a planar surface 1/z, u/z and v/z are affine in screen space.
// SpanGradients holds them as functions of the pixel-centre coordinates (px, py) =
// (x + 0.5, y + 0.5) (render_local.h conventions):
//   zi(px, py) = zi0 + zix * px + ziy * py          (1/z, world units^-1)
//   uz(px, py) = u0  + ux  * px + uy  * py          (u/z; u in texels of the chosen mip,
//   vz(px, py) = v0  + vx  * px + vy  * py           measured from texture_mins >> mip)
// The drawers divide exactly at the first pixel of every 16-pixel run (and at the last pixel
// of a span's final partial run) and step in 16.16 fixed point in between; the divide for
// the next run is issued before the current run is drawn. Between the exact ends the step is
// either linear (Quake's way) or, when second_order is set (the default), linear plus a
// parabola that follows the perspective curve (one more add per coordinate per pixel; see
// run_steps in asm/span_walk.h). Either way a run never leaves the range between its two
// (clamped) exact ends.
// Every drawer writes only the pixels of the spans it is given, then (when fb.zbuffer /
// fb.coverage are set) the 16-bit 1/z and the coverage count of those pixels.
#pragma once
#include <cstdint>

#include "asm/lit_span.h"
#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "engine/render/render_local.h"

namespace sb::render {

struct SpanGradients {
  double zi0, zix, ziy;
  double u0, ux, uy;
  double v0, vx, vy;
  bool second_order = true;  // false: Quake's linear stepping between the exact samples
};

// Gradients of face `face` seen from `view`, texture coordinates at `mip`.
SpanGradients face_gradients(const BspWorld& world, const Face& face, const ViewState& view, int mip);

// Exact (u, v) at a pixel centre per the gradients (tests and reference checks).
void exact_uv(const SpanGradients& g, double px, double py, double* u, double* v);

// Lit surface from the cache: texel (u, v) clamped to [0, width-1] x [0, height-1].
// asm/ surface_spans_persp calls, a batch of up to 32 spans each (the runs and divides inside
// the kernel).
void draw_surface_spans(const Span* spans, uint32_t count, const SpanGradients& g, const uint8_t* surface,
                        int width, int height, Framebuffer& fb);

// The same bytes through the engine's own run walker: one asm/ surface_span call per run of
// 16 pixels (the path before asm/span_persp.h; kept as its reference for tests and benches).
void draw_surface_spans_by_runs(const Span* spans, uint32_t count, const SpanGradients& g, const uint8_t* surface,
                                int width, int height, Framebuffer& fb);

// Single pass (RenderInputs::single_pass): texture and light combined per pixel by the
// lit_span kernel `fn` (asm/lit_span.h) from `src`; u, v clamped exactly as
// draw_surface_spans clamps them to a src.width x src.height surface, so the kernel reads
// the texel and light the cached path's surface holds there.
void draw_lit_spans(const Span* spans, uint32_t count, const SpanGradients& g, const simd::LitSpanSource& src,
                    simd::LitSpanFn fn, Framebuffer& fb);

// Unlit texture at `mip` (fallback when the cache cannot hold a surface): u, v clamped to
// the face's extents >> mip, then wrapped into the texture like texture_texel().
void draw_texture_spans(const Span* spans, uint32_t count, const SpanGradients& g, const Texture& tex, int mip,
                        int smin, int tmin, int extent_s, int extent_t, Framebuffer& fb);

// Turbulent: g must be mip-0 gradients; u, v clamped to the face's extents, then
// turb_texel's rule on s = u + smin, t = v + tmin.
void draw_turb_spans(const Span* spans, uint32_t count, const SpanGradients& g, const Texture& tex, int smin,
                     int tmin, int extent_s, int extent_t, double time, Framebuffer& fb);

// Sky: sky_texel's rule along dir(x + 0.5, y + 0.5), the layer coordinates computed exactly
// every 16 pixels and stepped linearly in between. Writes coverage but not z (the sky has no
// texture gradients; the caller writes z from the face's plane with draw_z_spans).
void draw_sky_spans(const Span* spans, uint32_t count, const ViewState& view, const Texture& sky, double time,
                    Framebuffer& fb);

// One colour (the background). z (when kept) is written as 0: infinitely far.
void draw_solid_spans(const Span* spans, uint32_t count, uint8_t color, Framebuffer& fb);

// 1/z of the spans into fb.zbuffer as floor(zi * 0x8000), clamped to 0..0xffff, stepped in
// 16.16 fixed point along each span. No-op when fb.zbuffer is null.
void draw_z_spans(const Span* spans, uint32_t count, const SpanGradients& g, Framebuffer& fb);

// Adds one to fb.coverage for every pixel of the spans. No-op when fb.coverage is null.
void count_coverage(const Span* spans, uint32_t count, Framebuffer& fb);

}  // namespace sb::render
