// engine/render/span_draw.cpp: span drawers. Lit-surface spans (whole spans, the divides
// inside: asm/span_persp.h, its reference on the walker of asm/span_walk.h, shared), the
// lit-surface run of the per-run reference path and the z fill call asm/ kernels
// (asm/kernels.h); the rest are scalar here.
//
// Sections: 1. gradients  2. the 16-pixel perspective walker  3. texel fetchers
//           (lit surface, unlit texture, turbulence)  4. sky  5. solid, z, coverage
//
// Fixed point: u and v are 16.16, clamped to [0, (extent << 16) - 1], so u >> 16 is a
// valid texel column. Within a run both ends are clamped and the step is the truncated
// quotient (toward zero), so every intermediate value lies between the two ends: the
// walk can never leave the surface.
#include "engine/render/span_draw.h"

#include <cmath>
#include <cstring>

#include <glm/geometric.hpp>

#include "asm/kernels.h"
#include "asm/span_walk.h"
#include "engine/render/surface_math.h"

namespace sb::render {

// ---------------------------------------------------------------- 1. gradients

SpanGradients face_gradients(const BspWorld& world, const Face& face, const ViewState& view, int mip) {
  const Plane& plane = world.planes[face.plane];
  const TexInfo& ti = world.texinfo[face.texinfo];
  const glm::dvec3 n(plane.normal), o(view.origin), f(view.forward), r(view.right), up(view.up);
  const double xs = view.xscale, ys = view.yscale, xc = view.xcenter, yc = view.ycenter;

  // A point on the plane seen along dir = f + a r - b u, a = (px - xc)/xs, b = (py - yc)/ys,
  // lies at depth z with n.(o + z dir) = dist, so 1/z = n.dir / (dist - n.o): affine in px, py.
  double de = double(plane.dist) - glm::dot(n, o);
  if (std::fabs(de) < 1e-6) de = de < 0 ? -1e-6 : 1e-6;  // eye on the plane: edge-on, keep finite
  const double nf = glm::dot(n, f), nr = glm::dot(n, r), nu = glm::dot(n, up);

  SpanGradients g;
  g.zix = nr / (xs * de);
  g.ziy = -nu / (ys * de);
  g.zi0 = (nf - nr * xc / xs + nu * yc / ys) / de;

  // s = vs.p + ws; at p = o + z dir: s/z = (vs.o + ws) / z + vs.dir. u = (s - smin) / 2^mip.
  const double scale = 1.0 / double(1 << mip);
  auto axis = [&](int i, int32_t tmin, double* c0, double* cx, double* cy) {
    const glm::dvec3 vs(ti.vecs[i].x, ti.vecs[i].y, ti.vecs[i].z);
    const double so = glm::dot(vs, o) + double(ti.vecs[i].w) - double(tmin);
    const double vf = glm::dot(vs, f), vr = glm::dot(vs, r), vu = glm::dot(vs, up);
    *cx = scale * (so * g.zix + vr / xs);
    *cy = scale * (so * g.ziy - vu / ys);
    *c0 = scale * (so * g.zi0 + vf - vr * xc / xs + vu * yc / ys);
  };
  axis(0, face.texture_mins[0], &g.u0, &g.ux, &g.uy);
  axis(1, face.texture_mins[1], &g.v0, &g.vx, &g.vy);
  return g;
}

void exact_uv(const SpanGradients& g, double px, double py, double* u, double* v) {
  const double zi = g.zi0 + g.zix * px + g.ziy * py;
  *u = (g.u0 + g.ux * px + g.uy * py) / zi;
  *v = (g.v0 + g.vx * px + g.vy * py) / zi;
}

// ---------------------------------------------------------------- 2. the walker

namespace {

// The walker and its arithmetic live in asm/span_walk.h: asm/span_persp.cpp's reference
// (the whole-span drawer the engine's lit surfaces go through) uses the same definitions;
// asm/span_persp_fast.cpp repeats them in select form (tests/asm/span_persp_test.cpp
// compares the bytes).
using simd::span_walk::kMinZi;
using simd::span_walk::to_fixed;
using simd::span_walk::walk_span;

inline int32_t max_fixed(int extent) {
  if (extent > 32767) extent = 32767;
  if (extent < 1) extent = 1;
  return int32_t((uint32_t(extent) << 16) - 1u);
}

// Every span of a planar surface: u, v = (u/z) / (1/z) from the gradients, clamped.
template <class Run>
void walk_spans(const Span* spans, uint32_t count, const SpanGradients& g, int32_t umax, int32_t vmax,
                Framebuffer& fb, const Run& run) {
  for (uint32_t i = 0; i < count; ++i) {
    const int x0 = spans[i].x, y = spans[i].y, total = spans[i].count;
    if (total <= 0) continue;
    const double py = y + 0.5;
    const double zrow = g.zi0 + g.ziy * py, urow = g.u0 + g.uy * py, vrow = g.v0 + g.vy * py;
    auto exact = [&](double px, int32_t* u, int32_t* v, double* zout) {
      double zi = zrow + g.zix * px;
      if (!(zi > kMinZi)) zi = kMinZi;
      const double z = 1.0 / zi;
      *u = to_fixed((urow + g.ux * px) * z, umax);
      *v = to_fixed((vrow + g.vx * px) * z, vmax);
      *zout = z;
    };
    walk_span(fb.pixels + ptrdiff_t(y) * fb.stride + x0, x0 + 0.5, total, g.second_order ? g.zix : 0.0, exact,
              run);
  }
}

inline bool is_pow2(uint32_t n) { return n != 0 && (n & (n - 1)) == 0; }

inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

// Run drawers. Each copies what it reads into locals first: the destination is a byte
// pointer, which may alias anything, so members would be reloaded after every store.

// The lit-surface run is asm/'s surface_span kernel (asm/surface_span.h): the variant
// chosen once at start, or its scalar reference (the loop that used to live here) when
// simd::force_scalar() is on. The walker keeps every u, v inside the surface, which is
// the kernel's contract. fn is read once per draw call.
struct SurfaceRun {
  const uint8_t* texels;
  int width, height;
  simd::SurfaceSpanFn fn;
  void operator()(uint8_t* dest, int n, int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu,
                  int32_t ddv) const {
    fn(dest, n, texels, width, height, u, v, du, dv, ddu, ddv);
  }
};

template <bool kPow2>
struct TextureRun {
  const uint8_t* texels;
  int tw, th, soff, toff;
  void operator()(uint8_t* __restrict dest, int n, int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu,
                  int32_t ddv) const {
    const uint8_t* __restrict t = texels;
    const int w = tw, h = th, so = soff, to = toff;
    for (int k = 0; k < n; ++k) {
      if constexpr (kPow2) {
        dest[k] = t[(((v >> 16) + to) & (h - 1)) * w + (((u >> 16) + so) & (w - 1))];
      } else {
        dest[k] = t[wrap((v >> 16) + to, h) * w + wrap((u >> 16) + so, w)];
      }
      u += du;
      v += dv;
      du += ddu;
      dv += ddv;
    }
  }
};

template <bool kPow2>
struct TurbRun {
  const uint8_t* texels;
  const int32_t* table;  // 128 entries, 16.16
  int tw, th, smin, tmin, sidx, tidx;
  void operator()(uint8_t* __restrict dest, int n, int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu,
                  int32_t ddv) const {
    const uint8_t* __restrict t = texels;
    const int32_t* __restrict tab = table;
    const int w = tw, h = th, s0 = smin, t0 = tmin, si = sidx, ti = tidx;
    for (int k = 0; k < n; ++k) {
      // s = u + smin is warped by the sine of floor(t) + phase, and vice versa.
      const int s2 = ((u + tab[((v >> 16) + ti) & 127]) >> 16) + s0;
      const int t2 = ((v + tab[((u >> 16) + si) & 127]) >> 16) + t0;
      if constexpr (kPow2) {
        dest[k] = t[(t2 & (h - 1)) * w + (s2 & (w - 1))];
      } else {
        dest[k] = t[wrap(t2, h) * w + wrap(s2, w)];
      }
      u += du;
      v += dv;
      du += ddu;
      dv += ddv;
    }
  }
};

}  // namespace

// ---------------------------------------------------------------- 3. fetchers

void draw_surface_spans(const Span* spans, uint32_t count, const SpanGradients& g, const uint8_t* surface,
                        int width, int height, Framebuffer& fb) {
  // One asm/ call per batch of up to kBatch spans (asm/span_persp.h, surface_spans_persp):
  // the kernel walks the runs and divides itself, drawing the bytes
  // draw_surface_spans_by_runs draws (the walker below, per run). Spans with no pixels are
  // left out of the batch.
  constexpr int kBatch = 32;
  const simd::SurfaceSpansPerspFn fn = simd::active().surface_spans_persp;
  simd::PerspItem items[kBatch];
  simd::PerspSpan p;
  p.dzi = g.zix;
  p.duz = g.ux;
  p.dvz = g.vx;
  p.umax = max_fixed(width);
  p.vmax = max_fixed(height);
  p.second_order = g.second_order;
  int k = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const int x0 = spans[i].x, y = spans[i].y, total = spans[i].count;
    if (total <= 0) continue;
    const double py = y + 0.5;  // the row's values exactly as walk_spans computes them
    p.zi0 = g.zi0 + g.ziy * py;
    p.uz0 = g.u0 + g.uy * py;
    p.vz0 = g.v0 + g.vy * py;
    p.px0 = x0 + 0.5;
    items[k++] = simd::PerspItem{fb.pixels + ptrdiff_t(y) * fb.stride + x0, total, p};
    if (k == kBatch) {
      fn(items, k, surface, width, height);
      k = 0;
    }
  }
  if (k > 0) fn(items, k, surface, width, height);
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

void draw_surface_spans_by_runs(const Span* spans, uint32_t count, const SpanGradients& g, const uint8_t* surface,
                                int width, int height, Framebuffer& fb) {
  walk_spans(spans, count, g, max_fixed(width), max_fixed(height), fb,
             SurfaceRun{surface, width, height, simd::active().surface_span});
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

void draw_lit_spans(const Span* spans, uint32_t count, const SpanGradients& g, const simd::LitSpanSource& src,
                    simd::LitSpanFn fn, Framebuffer& fb) {
  // The lit_span kernel has the surface_span kernel's stepping; only the fetch differs.
  struct LitRun {
    const simd::LitSpanSource* src;
    simd::LitSpanFn fn;
    void operator()(uint8_t* dest, int n, int32_t u, int32_t v, int32_t du, int32_t dv, int32_t ddu,
                    int32_t ddv) const {
      fn(dest, n, *src, u, v, du, dv, ddu, ddv);
    }
  };
  walk_spans(spans, count, g, max_fixed(src.width), max_fixed(src.height), fb, LitRun{&src, fn});
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

void draw_texture_spans(const Span* spans, uint32_t count, const SpanGradients& g, const Texture& tex, int mip,
                        int smin, int tmin, int extent_s, int extent_t, Framebuffer& fb) {
  const int tw = int(tex.width >> mip), th = int(tex.height >> mip);
  const int32_t umax = max_fixed(extent_s >> mip), vmax = max_fixed(extent_t >> mip);
  if (is_pow2(uint32_t(tw)) && is_pow2(uint32_t(th))) {
    walk_spans(spans, count, g, umax, vmax, fb, TextureRun<true>{tex.mips[mip], tw, th, smin >> mip, tmin >> mip});
  } else {
    walk_spans(spans, count, g, umax, vmax, fb, TextureRun<false>{tex.mips[mip], tw, th, smin >> mip, tmin >> mip});
  }
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

void draw_turb_spans(const Span* spans, uint32_t count, const SpanGradients& g, const Texture& tex, int smin,
                     int tmin, int extent_s, int extent_t, double time, Framebuffer& fb) {
  int32_t table[128];
  for (int i = 0; i < 128; ++i) table[i] = turb_offset(i);
  const int phase = turb_phase(time);
  const int tw = int(tex.width), th = int(tex.height);
  const int32_t umax = max_fixed(extent_s), vmax = max_fixed(extent_t);
  if (is_pow2(uint32_t(tw)) && is_pow2(uint32_t(th))) {
    walk_spans(spans, count, g, umax, vmax, fb,
               TurbRun<true>{tex.mips[0], table, tw, th, smin, tmin, smin + phase, tmin + phase});
  } else {
    walk_spans(spans, count, g, umax, vmax, fb,
               TurbRun<false>{tex.mips[0], table, tw, th, smin, tmin, smin + phase, tmin + phase});
  }
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

// ---------------------------------------------------------------- 4. sky

namespace {

struct SkyWalk {
  glm::dvec3 forward, right, up;
  double xc, yc, xs, ys;

  // kSkyScale * n.x and n.y at a pixel centre, in 16.16.
  void at(double px, double py, int32_t* q, int32_t* r) const {
    const glm::dvec3 d = forward + ((px - xc) / xs) * right - ((py - yc) / ys) * up;
    double x = d.x, y = d.y, z = 3.0 * d.z;
    const double len = std::sqrt(x * x + y * y + z * z);
    if (len > 0.0) {
      x /= len;
      y /= len;
    } else {
      x = 1.0;
      y = 0.0;
    }
    *q = int32_t(std::floor(kSkyScale * x * 65536.0));
    *r = int32_t(std::floor(kSkyScale * y * 65536.0));
  }
};

template <bool kPow2>
struct SkyRun {
  const uint8_t* texels;
  int tw, th, half;
  int32_t fs, ft, bs, bt;  // layer offsets, 16.16
  void operator()(uint8_t* __restrict dest, int n, int32_t q, int32_t r, int32_t dq, int32_t dr, int32_t,
                  int32_t) const {
    const uint8_t* __restrict t = texels;
    const int w = tw, h = th, hw = half;
    const int32_t o1 = fs, o2 = ft, o3 = bs, o4 = bt;
    for (int k = 0; k < n; ++k) {
      int s1 = (q + o1) >> 16, t1 = (r + o2) >> 16;
      int s2 = (q + o3) >> 16, t2 = (r + o4) >> 16;
      if constexpr (kPow2) {
        s1 &= hw - 1; t1 &= h - 1; s2 &= hw - 1; t2 &= h - 1;
      } else {
        s1 = wrap(s1, hw); t1 = wrap(t1, h); s2 = wrap(s2, hw); t2 = wrap(t2, h);
      }
      const uint8_t c = t[t1 * w + s1];
      dest[k] = c ? c : t[t2 * w + hw + s2];
      q += dq;
      r += dr;
    }
  }
};

template <bool kPow2>
void sky_spans(const Span* spans, uint32_t count, const SkyWalk& w, const Texture& sky, double time,
               Framebuffer& fb) {
  const int tw = int(sky.width), th = int(sky.height), half = tw / 2;
  // Layer offsets reduced modulo the layer size (exact), in 16.16.
  auto off = [](double o, int period) { return int32_t(std::floor(std::fmod(o, double(period)) * 65536.0)); };
  const SkyRun<kPow2> run{sky.mips[0], tw, th, half,
                          off(kSkyFrontSpeed * time, half), off(kSkyFrontSpeed * time, th),
                          off(kSkyBackSpeed * time, half), off(kSkyBackSpeed * time, th)};
  for (uint32_t i = 0; i < count; ++i) {
    const int x0 = spans[i].x, y = spans[i].y, total = spans[i].count;
    if (total <= 0) continue;
    const double py = y + 0.5;
    auto exact = [&](double px, int32_t* q, int32_t* r, double* z) {
      w.at(px, py, q, r);
      *z = 0.0;
    };
    walk_span(fb.pixels + ptrdiff_t(y) * fb.stride + x0, x0 + 0.5, total, 0.0, exact, run);
  }
}

}  // namespace

void draw_sky_spans(const Span* spans, uint32_t count, const ViewState& view, const Texture& sky, double time,
                    Framebuffer& fb) {
  SkyWalk w{glm::dvec3(view.forward), glm::dvec3(view.right), glm::dvec3(view.up),
            view.xcenter, view.ycenter, view.xscale, view.yscale};
  if (is_pow2(sky.width / 2) && is_pow2(sky.height)) {
    sky_spans<true>(spans, count, w, sky, time, fb);
  } else {
    sky_spans<false>(spans, count, w, sky, time, fb);
  }
  count_coverage(spans, count, fb);
}

// ---------------------------------------------------------------- 5. solid, z, coverage

void draw_solid_spans(const Span* spans, uint32_t count, uint8_t color, Framebuffer& fb) {
  for (uint32_t i = 0; i < count; ++i) {
    const int x = spans[i].x, y = spans[i].y, n = spans[i].count;
    if (n <= 0) continue;
    std::memset(fb.pixels + ptrdiff_t(y) * fb.stride + x, color, size_t(n));
    if (fb.zbuffer) std::memset(fb.zbuffer + ptrdiff_t(y) * fb.width + x, 0, size_t(n) * sizeof(uint16_t));
  }
  count_coverage(spans, count, fb);
}

void draw_z_spans(const Span* spans, uint32_t count, const SpanGradients& g, Framebuffer& fb) {
  if (!fb.zbuffer) return;
  constexpr double kScale = 0x8000 * 65536.0;  // 16.16 of zi * 0x8000
  auto clampd = [](double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); };
  const int64_t step = int64_t(clampd(g.zix * kScale, -double(1ll << 40), double(1ll << 40)));
  const simd::ZSpanFn z_span = simd::active().z_span;
  for (uint32_t i = 0; i < count; ++i) {
    const int x = spans[i].x, y = spans[i].y, n = spans[i].count;  // locals: the stores below may alias
    if (n <= 0) continue;
    uint16_t* __restrict z = fb.zbuffer + ptrdiff_t(y) * fb.width + x;
    const double zi = g.zi0 + g.zix * (x + 0.5) + g.ziy * (y + 0.5);
    int64_t izi = int64_t(clampd(zi * kScale, -double(1ll << 40), double(1ll << 40)));
    // 1/z is linear along the span: when both ends are in range, every pixel is.
    const int64_t last = izi + step * (n - 1);
    constexpr int64_t kMax = (int64_t(0xffff) << 16) | 0xffff;
    if (izi >= 0 && izi <= kMax && last >= 0 && last <= kMax) {
      // asm/z_span.h: every value in 0..kMax, so the kernel's 32-bit modular walk is exact.
      z_span(z, n, uint32_t(izi), uint32_t(step));
      continue;
    }
    for (int k = 0; k < n; ++k) {
      int64_t v = izi >> 16;
      z[k] = uint16_t(v < 0 ? 0 : (v > 0xffff ? 0xffff : v));
      izi += step;
    }
  }
}

void count_coverage(const Span* spans, uint32_t count, Framebuffer& fb) {
  if (!fb.coverage) return;
  for (uint32_t i = 0; i < count; ++i) {
    const int x = spans[i].x, y = spans[i].y, n = spans[i].count;
    uint8_t* __restrict c = fb.coverage + ptrdiff_t(y) * fb.width + x;
    for (int k = 0; k < n; ++k) ++c[k];
  }
}

}  // namespace sb::render
