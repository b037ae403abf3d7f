// engine/render/span_draw.cpp: scalar span drawers (the references for later SIMD kernels).
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

#include <glm/geometric.hpp>

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

constexpr double kMinZi = 1e-9;

// (num / zi) in 16.16, clamped to [0, max]; NaN and negatives go to 0.
inline int32_t to_fixed(double num, double zi, int32_t max) {
  if (!(zi > kMinZi)) zi = kMinZi;
  double q = num / zi * 65536.0;
  if (!(q > 0.0)) return 0;
  if (q > double(max)) return max;
  return int32_t(q);
}

inline int32_t max_fixed(int extent) {
  if (extent > 32767) extent = 32767;
  if (extent < 1) extent = 1;
  return int32_t((uint32_t(extent) << 16) - 1u);
}

// Walks every span in 16-pixel runs: exact u, v at each run's ends, linear in between.
// plot(u, v) returns the palette index for 16.16 texel coordinates.
template <class Plot>
void walk_spans(const Span* spans, uint32_t count, const SpanGradients& g, int32_t umax, int32_t vmax,
                Framebuffer& fb, Plot plot) {
  for (uint32_t i = 0; i < count; ++i) {
    const Span& sp = spans[i];
    if (sp.count <= 0) continue;
    uint8_t* dest = fb.pixels + ptrdiff_t(sp.y) * fb.stride + sp.x;
    const double py = sp.y + 0.5;
    const double zrow = g.zi0 + g.ziy * py, urow = g.u0 + g.uy * py, vrow = g.v0 + g.vy * py;
    double px = sp.x + 0.5;
    int32_t u = to_fixed(urow + g.ux * px, zrow + g.zix * px, umax);
    int32_t v = to_fixed(vrow + g.vx * px, zrow + g.zix * px, vmax);
    int left = sp.count;
    while (left > 0) {
      // Issue the divide for the end of this run (the start of the next) before drawing it.
      int n;
      int32_t un, vn, du, dv;
      if (left > 16) {
        n = 16;
        px += 16.0;
        const double zi = zrow + g.zix * px;
        un = to_fixed(urow + g.ux * px, zi, umax);
        vn = to_fixed(vrow + g.vx * px, zi, vmax);
        du = (un - u) / 16;
        dv = (vn - v) / 16;
      } else {
        n = left;
        un = u;
        vn = v;
        du = dv = 0;
        if (n > 1) {
          const double pl = px + double(n - 1);
          const double zi = zrow + g.zix * pl;
          un = to_fixed(urow + g.ux * pl, zi, umax);
          vn = to_fixed(vrow + g.vx * pl, zi, vmax);
          du = (un - u) / (n - 1);
          dv = (vn - v) / (n - 1);
        }
      }
      for (int k = 0; k < n; ++k) {
        dest[k] = plot(u, v);
        u += du;
        v += dv;
      }
      dest += n;
      u = un;
      v = vn;
      left -= n;
    }
  }
}

inline bool is_pow2(uint32_t n) { return n != 0 && (n & (n - 1)) == 0; }

inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

}  // namespace

// ---------------------------------------------------------------- 3. fetchers

void draw_surface_spans(const Span* spans, uint32_t count, const SpanGradients& g, const uint8_t* surface,
                        int width, int height, Framebuffer& fb) {
  walk_spans(spans, count, g, max_fixed(width), max_fixed(height), fb,
             [surface, width](int32_t u, int32_t v) { return surface[(v >> 16) * width + (u >> 16)]; });
  draw_z_spans(spans, count, g, fb);
  count_coverage(spans, count, fb);
}

void draw_texture_spans(const Span* spans, uint32_t count, const SpanGradients& g, const Texture& tex, int mip,
                        int smin, int tmin, int extent_s, int extent_t, Framebuffer& fb) {
  const int tw = int(tex.width >> mip), th = int(tex.height >> mip);
  const uint8_t* texels = tex.mips[mip];
  const int soff = smin >> mip, toff = tmin >> mip;
  const int32_t umax = max_fixed(extent_s >> mip), vmax = max_fixed(extent_t >> mip);
  if (is_pow2(uint32_t(tw)) && is_pow2(uint32_t(th))) {
    walk_spans(spans, count, g, umax, vmax, fb, [=](int32_t u, int32_t v) {
      return texels[(((v >> 16) + toff) & (th - 1)) * tw + (((u >> 16) + soff) & (tw - 1))];
    });
  } else {
    walk_spans(spans, count, g, umax, vmax, fb, [=](int32_t u, int32_t v) {
      return texels[wrap((v >> 16) + toff, th) * tw + wrap((u >> 16) + soff, tw)];
    });
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
  const uint8_t* texels = tex.mips[0];
  // s = u + smin: the warp of s is indexed by floor(t) + phase, and vice versa.
  const int sidx = smin + phase, tidx = tmin + phase;
  const int32_t umax = max_fixed(extent_s), vmax = max_fixed(extent_t);
  if (is_pow2(uint32_t(tw)) && is_pow2(uint32_t(th))) {
    walk_spans(spans, count, g, umax, vmax, fb, [&](int32_t u, int32_t v) {
      const int s2 = ((u + table[((v >> 16) + tidx) & 127]) >> 16) + smin;
      const int t2 = ((v + table[((u >> 16) + sidx) & 127]) >> 16) + tmin;
      return texels[(t2 & (th - 1)) * tw + (s2 & (tw - 1))];
    });
  } else {
    walk_spans(spans, count, g, umax, vmax, fb, [&](int32_t u, int32_t v) {
      const int s2 = ((u + table[((v >> 16) + tidx) & 127]) >> 16) + smin;
      const int t2 = ((v + table[((u >> 16) + sidx) & 127]) >> 16) + tmin;
      return texels[wrap(t2, th) * tw + wrap(s2, tw)];
    });
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
void sky_spans(const Span* spans, uint32_t count, const SkyWalk& w, const Texture& sky, double time,
               Framebuffer& fb) {
  const int tw = int(sky.width), th = int(sky.height), half = tw / 2;
  const uint8_t* texels = sky.mips[0];
  // Layer offsets reduced modulo the layer size (exact), in 16.16.
  auto off = [](double o, int period) { return int32_t(std::floor(std::fmod(o, double(period)) * 65536.0)); };
  const int32_t fs = off(kSkyFrontSpeed * time, half), ft = off(kSkyFrontSpeed * time, th);
  const int32_t bs = off(kSkyBackSpeed * time, half), bt = off(kSkyBackSpeed * time, th);
  auto fetch = [&](int32_t q, int32_t r) -> uint8_t {
    int s1 = (q + fs) >> 16, t1 = (r + ft) >> 16;
    int s2 = (q + bs) >> 16, t2 = (r + bt) >> 16;
    if constexpr (kPow2) {
      s1 &= half - 1; t1 &= th - 1; s2 &= half - 1; t2 &= th - 1;
    } else {
      s1 = wrap(s1, half); t1 = wrap(t1, th); s2 = wrap(s2, half); t2 = wrap(t2, th);
    }
    const uint8_t c = texels[t1 * tw + s1];
    return c ? c : texels[t2 * tw + half + s2];
  };
  for (uint32_t i = 0; i < count; ++i) {
    const Span& sp = spans[i];
    if (sp.count <= 0) continue;
    uint8_t* dest = fb.pixels + ptrdiff_t(sp.y) * fb.stride + sp.x;
    const double py = sp.y + 0.5;
    double px = sp.x + 0.5;
    int32_t q, r;
    w.at(px, py, &q, &r);
    int left = sp.count;
    while (left > 0) {
      const int n = left > 16 ? 16 : left;
      int32_t qn = q, rn = r, dq = 0, dr = 0;
      if (left > 16) {
        px += 16.0;
        w.at(px, py, &qn, &rn);
        dq = (qn - q) / 16;
        dr = (rn - r) / 16;
      } else if (n > 1) {
        w.at(px + double(n - 1), py, &qn, &rn);
        dq = (qn - q) / (n - 1);
        dr = (rn - r) / (n - 1);
      }
      for (int k = 0; k < n; ++k) {
        dest[k] = fetch(q, r);
        q += dq;
        r += dr;
      }
      dest += n;
      q = qn;
      r = rn;
      left -= n;
    }
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
    const Span& sp = spans[i];
    if (sp.count <= 0) continue;
    uint8_t* dest = fb.pixels + ptrdiff_t(sp.y) * fb.stride + sp.x;
    for (int k = 0; k < sp.count; ++k) dest[k] = color;
    if (fb.zbuffer) {
      uint16_t* z = fb.zbuffer + ptrdiff_t(sp.y) * fb.width + sp.x;
      for (int k = 0; k < sp.count; ++k) z[k] = 0;
    }
  }
  count_coverage(spans, count, fb);
}

void draw_z_spans(const Span* spans, uint32_t count, const SpanGradients& g, Framebuffer& fb) {
  if (!fb.zbuffer) return;
  constexpr double kScale = 0x8000 * 65536.0;  // 16.16 of zi * 0x8000
  auto clampd = [](double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); };
  const int64_t step = int64_t(clampd(g.zix * kScale, -double(1ll << 40), double(1ll << 40)));
  for (uint32_t i = 0; i < count; ++i) {
    const Span& sp = spans[i];
    if (sp.count <= 0) continue;
    uint16_t* z = fb.zbuffer + ptrdiff_t(sp.y) * fb.width + sp.x;
    const double zi = g.zi0 + g.zix * (sp.x + 0.5) + g.ziy * (sp.y + 0.5);
    int64_t izi = int64_t(clampd(zi * kScale, -double(1ll << 40), double(1ll << 40)));
    for (int k = 0; k < sp.count; ++k) {
      int64_t v = izi >> 16;
      z[k] = uint16_t(v < 0 ? 0 : (v > 0xffff ? 0xffff : v));
      izi += step;
    }
  }
}

void count_coverage(const Span* spans, uint32_t count, Framebuffer& fb) {
  if (!fb.coverage) return;
  for (uint32_t i = 0; i < count; ++i) {
    const Span& sp = spans[i];
    uint8_t* c = fb.coverage + ptrdiff_t(sp.y) * fb.width + sp.x;
    for (int k = 0; k < sp.count; ++k) ++c[k];
  }
}

}  // namespace sb::render
