// engine/render/surface_draw.cpp: the back end's entry point. For every surface the front
// end scanned out, pick its drawer: background colour, sky, turbulence, or a lit surface
// from the cache (unlit texture when the cache cannot hold it this frame), or, with
// RenderInputs::single_pass, texture and light combined in the span drawer (single_pass.h).
#include <cstdint>

#include "engine/core/log.h"
#include "engine/render/render_local.h"
#include "engine/render/single_pass.h"
#include "engine/render/span_draw.h"
#include "engine/render/surface_cache.h"
#include "engine/render/surface_math.h"

namespace sb::render {

namespace {

bool g_logged_bad_spans = false;

// The front end's spans must lie inside the framebuffer; a surface that breaks the
// contract is skipped (and reported once) rather than written out of bounds.
bool spans_valid(const Span* spans, uint32_t count, const Framebuffer& fb) {
  for (uint32_t i = 0; i < count; ++i) {
    const Span& s = spans[i];
    if (s.y < 0 || s.y >= fb.height || s.x < 0 || s.count < 0 || s.x + s.count > fb.width) return false;
  }
  return true;
}

}  // namespace

void draw_surfaces(BspWorld& world, const ViewState& view, const FrameSpans& frame, const RenderInputs& in,
                   Framebuffer& fb, mem::MemorySystem& memory, RenderStats* stats_out) {
  RenderStats local;
  RenderStats& stats = stats_out ? *stats_out : local;
  const simd::LitSpanFn lit_span = in.single_pass ? simd::lit_span_active() : nullptr;  // once per frame

  for (uint32_t si = 0; si < frame.num_surfaces; ++si) {
    const SurfaceDraw& sd = frame.surfaces[si];
    if (sd.first_span > frame.num_spans || sd.num_spans > frame.num_spans - sd.first_span) continue;
    const Span* spans = frame.spans + sd.first_span;
    const uint32_t n = sd.num_spans;
    if (n == 0) continue;
    if (!spans_valid(spans, n, fb)) {
      if (!g_logged_bad_spans) {
        g_logged_bad_spans = true;
        log_error("draw_surfaces: surface %u has spans outside the %dx%d framebuffer; skipped", si, fb.width,
                  fb.height);
      }
      continue;
    }

    if (sd.face == kBackgroundFace || sd.face >= world.num_faces) {
      draw_solid_spans(spans, n, 0, fb);
      continue;
    }

    Face& face = world.faces[sd.face];
    const TexInfo& ti = world.texinfo[face.texinfo];
    const Texture& tex = world.textures[animated_texture(world, ti.texture, in.time)];

    if (face.flags & kFaceSky) {
      draw_sky_spans(spans, n, view, tex, in.time, fb);
      if (fb.zbuffer) draw_z_spans(spans, n, face_gradients(world, face, view, 0), fb);
      continue;
    }
    if (face.flags & kFaceTurb) {
      SpanGradients g = face_gradients(world, face, view, 0);
      g.second_order = in.span_second_order;
      draw_turb_spans(spans, n, g, tex, face.texture_mins[0], face.texture_mins[1], face.extents[0],
                      face.extents[1], in.time, fb);
      continue;
    }

    const int mip = choose_mip(sd.nearzi, view.xscale, ti.mipadjust);
    ++stats.mip_counts[mip];
    SpanGradients g = face_gradients(world, face, view, mip);
    g.second_order = in.span_second_order;
    if (lit_span &&
        draw_single_pass_surface(world, sd.face, mip, tex, g, spans, n, in, lit_span, memory, stats, fb)) {
      continue;  // RenderInputs::single_pass: no surface cache (single_pass.h)
    }
    SurfaceHeader h;
    const uint8_t* surface = fetch_surface(world, sd.face, mip, in, memory, stats, &h);
    if (surface) {
      draw_surface_spans(spans, n, g, surface, h.width, h.height, fb);
    } else {
      draw_texture_spans(spans, n, g, tex, mip, face.texture_mins[0], face.texture_mins[1], face.extents[0],
                         face.extents[1], fb);
    }
  }
}

void draw_surfaces_new_level() { g_logged_bad_spans = false; }

}  // namespace sb::render
