// asm/span_persp.cpp: the whole-span lit-surface drawer's reference (asm/span_persp.h):
// the engine's run walker (asm/span_walk.h, which engine/render/span_draw.cpp uses too) over
// surface_span_scalar. The tuned version: asm/span_persp_fast.cpp.
#include "asm/span_persp.h"

#include "asm/span_walk.h"
#include "asm/surface_span.h"

namespace sb::simd {

void surface_span_persp_scalar(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                               const PerspSpan& p) {
  using span_walk::kMinZi;
  using span_walk::to_fixed;
  if (n <= 0) return;
  const double zrow = p.zi0, zix = p.dzi, urow = p.uz0, ux = p.duz, vrow = p.vz0, vx = p.dvz;
  const int32_t umax = p.umax, vmax = p.vmax;
  auto exact = [&](double px, int32_t* u, int32_t* v, double* zout) {
    double zi = zrow + zix * px;
    if (!(zi > kMinZi)) zi = kMinZi;
    const double z = 1.0 / zi;
    *u = to_fixed((urow + ux * px) * z, umax);
    *v = to_fixed((vrow + vx * px) * z, vmax);
    *zout = z;
  };
  auto run = [&](uint8_t* d, int k, int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
    surface_span_scalar(d, k, texels, width, height, u, v, du, dv, ddu, ddv);
  };
  span_walk::walk_span(dest, p.px0, n, p.second_order ? zix : 0.0, exact, run);
}

void surface_spans_persp_scalar(const PerspItem* items, int count, const uint8_t* texels, int width, int height) {
  for (int i = 0; i < count; ++i)
    surface_span_persp_scalar(items[i].dest, items[i].n, texels, width, height, items[i].span);
}

}  // namespace sb::simd
