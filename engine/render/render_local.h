// engine/render/render_local.h: the contract between the renderer's front end
// (view setup, PVS marking, BSP walk, edge list, spans) and its back end
// (surface cache, span drawers, sky, turbulence). Not for use outside render/
// except by tests.
//
// Screen conventions (both ends and the reference renderer agree on them):
//   pixel (x, y) covers [x, x+1) x [y, y+1); it is sampled at its centre (x+0.5, y+0.5).
//   A view-space direction d (world vector) projects to
//     sx = xcenter + xscale * dot(d, right) / dot(d, forward)
//     sy = ycenter - yscale * dot(d, up)    / dot(d, forward)
//   and the pixel centre (sx, sy) looks along
//     dir(sx, sy) = forward + ((sx - xcenter) / xscale) * right - ((sy - ycenter) / yscale) * up
//   whose depth z is dot(point - origin, forward) (so dir has unit depth).
//   A polygon covers a pixel when the pixel centre lies inside it (top-left rule
//   for centres exactly on an edge: left and top edges include, right and bottom exclude).
#pragma once
#include <cstdint>

#include <glm/vec3.hpp>

#include "engine/formats/bsp.h"
#include "engine/render/render.h"
#include "memory/arena.h"

namespace sb::render {

struct ViewState {
  glm::vec3 origin, forward, right, up;
  float xcenter, ycenter;  // width / 2, height / 2
  float xscale, yscale;    // xscale = xcenter / tan(fov_x / 2); yscale = xscale (square pixels)
  int width, height;
  Plane frustum[4];        // left, right, top, bottom; normals point into the view volume
  uint32_t frame;          // frame number, also the visframe stamp
  int view_leaf;           // leaf index containing origin
};

ViewState setup_view(const BspWorld& world, const ViewParams& params, int width, int height, uint32_t frame);

// Pixels [x, x + count) of row y.
struct Span {
  int16_t x, y, count, pad;
};

constexpr uint32_t kBackgroundFace = 0xffffffffu;  // pixels no face covers: drawn in colour 0

struct SurfaceDraw {
  uint32_t face;      // index into world.faces, or kBackgroundFace
  float nearzi;       // largest 1/z among the surface's clipped, projected vertices
  uint32_t first_span, num_spans;  // into FrameSpans::spans, contiguous per surface
};

struct FrameSpans {
  Span* spans = nullptr;
  uint32_t num_spans = 0;
  SurfaceDraw* surfaces = nullptr;
  uint32_t num_surfaces = 0;
};

// Front end: marks visible leaves/nodes, walks the BSP and scans out spans.
// Arrays come from `frame`. Sizes come from the space left in `frame`; on
// overflow the stats flags are set and what fits is returned, every pixel still
// covered by some surface (background where nothing else is).
Status build_spans(BspWorld& world, const ViewState& view, mem::Arena& frame, FrameSpans* out,
                   RenderStats* stats);

// Back end: draws every surface's spans (sky, turbulent, lit through the cache, background).
void draw_surfaces(BspWorld& world, const ViewState& view, const FrameSpans& spans, const RenderInputs& in,
                   Framebuffer& fb, mem::MemorySystem& memory, RenderStats* stats);

}  // namespace sb::render
