// engine/render/single_pass.h: world surfaces drawn in one pass, texture and light combined
// by the span drawer (RenderInputs::single_pass; issue 4), with no surface cache.
//
// Per surface and frame: the face's light grid (light_grid_size(face) shades, the styles
// summed with this frame's values by face_light_grid, and its widened copy from
// simd::lit_span_prepare) is computed into the frame arena and popped when the surface is drawn; the spans then go through asm/lit_span.h's kernel,
// which evaluates shade_at() and texture_texel() per pixel at the texel the cached path's
// surface holds there. The picture equals the cached path's (tests/render_back/
// single_pass_test.cpp measures it), the work per pixel is larger, and nothing is built or
// kept between frames: a light style change costs nothing extra.
// Internal to render/ (and tests).
#pragma once
#include <cstdint>

#include "asm/lit_span.h"
#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "engine/render/render_local.h"
#include "engine/render/span_draw.h"
#include "memory/memory_system.h"

namespace sb::render {

// Draws the spans of lit surface world.faces[face] at `mip` single pass with kernel `fn`
// (normally simd::lit_span_active()). g: the face's gradients at `mip`; tex: the texture to
// draw (after animation). Returns false, drawing nothing, when the surface cannot be drawn
// this way (zero or over-4096 extents, or the frame arena cannot hold the light grid: the
// caller then draws it unlit, as the cached path does). Counts stats.single_pass_surfaces.
bool draw_single_pass_surface(const BspWorld& world, uint32_t face, int mip, const Texture& tex,
                              const SpanGradients& g, const Span* spans, uint32_t count, const RenderInputs& in,
                              simd::LitSpanFn fn, mem::MemorySystem& memory, RenderStats& stats, Framebuffer& fb);

}  // namespace sb::render
