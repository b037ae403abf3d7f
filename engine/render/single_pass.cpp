// engine/render/single_pass.cpp: one world surface drawn single pass (see single_pass.h).
#include "engine/render/single_pass.h"

#include "engine/render/surface_math.h"

namespace sb::render {

bool draw_single_pass_surface(const BspWorld& world, uint32_t face_index, int mip, const Texture& tex,
                              const SpanGradients& g, const Span* spans, uint32_t count, const RenderInputs& in,
                              simd::LitSpanFn fn, mem::MemorySystem& memory, RenderStats& stats, Framebuffer& fb) {
  const Face& face = world.faces[face_index];
  // The same surfaces the cache would refuse (surface_cache.cpp) are refused here.
  const int width = face.extents[0] >> mip, height = face.extents[1] >> mip;
  if (width <= 0 || height <= 0 || face.extents[0] > 4096 || face.extents[1] > 4096) return false;
  const int tw = int(tex.width >> mip), th = int(tex.height >> mip);
  if (tw < 1 || th < 1 || !tex.mips[mip]) return false;

  // The light grid (and its widened copy for the tuned kernel) lives in the frame arena
  // until this surface is drawn.
  mem::ArenaScope scope(memory.frame());
  const int samples = light_grid_size(face);
  mem::Arena& arena = scope.arena();
  auto* grid = static_cast<uint16_t*>(arena.push(size_t(samples) * sizeof(uint16_t), "single-pass light grid"));
  auto* wide = static_cast<uint32_t*>(arena.push(size_t(samples) * sizeof(uint32_t), "single-pass light grid"));
  if (!grid || !wide) {
    stats.cache_exhausted = true;  // same signal as the cached path's: drawn unlit
    return false;
  }
  simd::LitSpanSource src;
  src.texels = tex.mips[mip];
  src.tex_width = tw;
  src.tex_height = th;
  src.soff = face.texture_mins[0] >> mip;
  src.toff = face.texture_mins[1] >> mip;
  src.grid_width = face_light_grid(world, face, in.lightstyles, grid, nullptr);
  src.grid = grid;
  src.mip = mip;
  src.width = width;
  src.height = height;
  src.colormap = in.colormap;
  simd::lit_span_prepare(src, samples, wide);
  draw_lit_spans(spans, count, g, src, fn, fb);
  ++stats.single_pass_surfaces;
  return true;
}

}  // namespace sb::render
