// engine/render/render.cpp: render_world (validate, set up the view, front end, back end)
// and the per-level reset.
#include "engine/render/render.h"

#include <cmath>

#include "engine/render/render_local.h"
#include "engine/render/surface_cache.h"

namespace sb::render {
void draw_surfaces_new_level();  // surface_draw.cpp
}

namespace sb {

Status render_world(const RenderInputs& in, Framebuffer& fb, mem::MemorySystem& memory, RenderStats* stats) {
  RenderStats local;
  RenderStats& st = stats ? *stats : local;
  st = RenderStats{};

  if (!in.world) return make_error("render_world: RenderInputs.world is null");
  if (!in.colormap) return make_error("render_world: RenderInputs.colormap is null");
  if (!fb.pixels) return make_error("render_world: Framebuffer.pixels is null");
  if (fb.width < 1 || fb.width > 4096 || fb.height < 1 || fb.height > 4096) {
    return make_error("render_world: framebuffer size %dx%d outside 1..4096", fb.width, fb.height);
  }
  if (fb.stride < fb.width) {
    return make_error("render_world: Framebuffer.stride %d is less than width %d", fb.stride, fb.width);
  }
  const ViewParams& v = in.view;
  if (!(v.fov_x >= 10.0f && v.fov_x <= 170.0f)) {
    return make_error("render_world: ViewParams.fov_x %g outside 10..170 degrees", double(v.fov_x));
  }
  if (!std::isfinite(v.origin.x) || !std::isfinite(v.origin.y) || !std::isfinite(v.origin.z) ||
      !std::isfinite(v.yaw) || !std::isfinite(v.pitch) || !std::isfinite(v.roll)) {
    return make_error("render_world: ViewParams origin or angles are not finite");
  }
  if (in.world->num_faces == 0 || in.world->num_nodes == 0 || in.world->num_leaves == 0) {
    return make_error("render_world: world '%s' has no faces, nodes or leaves", in.world->name);
  }

  // The world's per-face renderer state (visframes, cache handles) is mutable by design;
  // the arrays live in the level arena, never in const storage.
  BspWorld& world = *in.world;
  const render::ViewState view = render::setup_view(world, v, fb.width, fb.height, memory.frame_number());
  render::FrameSpans spans;
  SB_TRY(render::build_spans(world, view, memory.frame(), &spans, &st));
  render::draw_surfaces(world, view, spans, in, fb, memory, &st);
  return Status::ok();
}

void render_new_level(BspWorld& world) {
  for (uint32_t i = 0; i < world.num_faces; ++i) {
    Face& f = world.faces[i];
    f.visframe = 0;
    f.draw_frame = 0;
    for (int m = 0; m < 4; ++m) {
      f.cache[m] = mem::CacheHandle{};
      f.cache_light_key[m] = 0;
    }
  }
  for (uint32_t i = 0; i < world.num_nodes; ++i) world.nodes[i].visframe = 0;
  for (uint32_t i = 0; i < world.num_leaves; ++i) world.leaves[i].visframe = 0;
  render::surface_cache_new_level();
  render::draw_surfaces_new_level();
}

}  // namespace sb
