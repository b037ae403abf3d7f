// asm/span_persp.cpp: the whole-span lit-surface drawer (asm/span_persp.h): the reference
// (the engine's run walker over surface_span_scalar) and the tuned portable version. Both
// are one template; they differ only in how a run's steps divide and how a run is drawn.
//
// The double arithmetic below must stay operation for operation what
// engine/render/span_draw.cpp's walk_span / exact / run_steps do: the kernel promises the
// engine's bytes (tests/asm/span_persp_test.cpp checks it).
#include "asm/span_persp.h"

#include <type_traits>

#include "asm/surface_span.h"

namespace sb::simd {
namespace {

constexpr double kMinZi = 1e-9;

// v * 65536 in 16.16, clamped to [0, max]; NaN and negatives go to 0.
inline int32_t to_fixed(double v, int32_t max) {
  const double q = v * 65536.0;
  if (!(q > 0.0)) return 0;
  if (q > double(max)) return max;
  return int32_t(q);
}

// Makes the compiler compute x here (an empty asm that claims to read and write it).
inline void pin(double& x) {
#if defined(__GNUC__) && (defined(__aarch64__) || defined(__arm__))
  __asm__ volatile("" : "+w"(x));
#elif defined(__GNUC__) && defined(__x86_64__)
  __asm__ volatile("" : "+x"(x));
#else
  (void)x;
#endif
}

struct RunSteps {
  int32_t d, dd;
};

// span_draw.cpp's run_steps. Steps is int (any run) or std::integral_constant<int, 16>
// (a full run): then every division below is by a constant and compiles to shifts and
// multiplies, with the same results (integer division truncates toward zero either way;
// double / 16 is exact, as is double * 0.0625).
template <class Steps>
inline RunSteps run_steps(int32_t a, int32_t b, Steps steps_, double curve) {
  const int steps = steps_;
  if (steps <= 0) return {0, 0};
  const int64_t delta = int64_t(b) - int64_t(a);
  const int32_t linear = int32_t(delta / steps);  // truncation: never overshoots b
  if (curve == 0.0 || steps < 2) return {linear, 0};
  const double c = double(delta) / steps * curve;
  const double ddf = -2.0 * c;
  if (!(ddf > -1e9 && ddf < 1e9)) return {linear, 0};
  const int64_t dd = int64_t(ddf);
  const int64_t bend = dd * steps * (steps - 1) / 2;
  const int64_t d0 = (delta - bend) / steps;
  const int64_t last_step = d0 + dd * (steps - 1);
  const int64_t reach = d0 * steps + bend;
  const bool monotone = delta >= 0 ? (d0 >= 0 && last_step >= 0 && reach >= 0 && reach <= delta)
                                   : (d0 <= 0 && last_step <= 0 && reach <= 0 && reach >= delta);
  if (!monotone || d0 > INT32_MAX || d0 < INT32_MIN) return {linear, 0};
  return {int32_t(d0), int32_t(dd)};
}

// One run: surface_span's loop, inlined, with u and v in one 64-bit register: uv = v 2^32 + u,
// stepped by duv = dv 2^32 + du (du sign-extended), itself stepped by ddv 2^32 + ddu. The
// contract keeps every drawn u_k in 0 .. 2^32 - 1 and v_k >= 0, so uv_k is exactly the
// integer v_k 2^32 + u_k (the recurrences are linear: the packed sums are the sums of the
// packed terms) and its halves are u_k and v_k: two adds per pixel instead of four.
inline void draw_run(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w, uint32_t u,
                     uint32_t v, uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  auto pack = [](uint32_t hi, uint32_t lo) { return (uint64_t(hi) << 32) + uint64_t(int64_t(int32_t(lo))); };
  uint64_t uv = (uint64_t(v) << 32) + u, duv = pack(dv, du);
  auto texel = [&](uint64_t x) { return texels[uint32_t(x >> 48) * w + (uint32_t(x) >> 16)]; };
  // Two pixels per step, their address arithmetic independent, and software-pipelined for
  // in-order cores (Cortex-A53): each step loads the texels of the NEXT pair (which exists:
  // k + 4 <= n, so no texel beyond the n pixels is read) and stores the pair loaded one step
  // earlier, so no store waits on the load just issued.
  //   linear:       uv_{k+2} = uv_k + 2 duv
  //   second order: uv_{k+2} = uv_k + 2 duv_k + dduv, duv_{k+2} = duv_k + 2 dduv
  int k = 0;
  if (n >= 2) {
    uint8_t t0 = texel(uv), t1 = texel(uv + duv);
    if ((ddu | ddv) == 0) {
      const uint64_t step2 = 2 * duv;
      uv += step2;
      for (; k + 4 <= n; k += 2) {
        const uint8_t n0 = texel(uv), n1 = texel(uv + duv);
        dest[k] = t0;
        dest[k + 1] = t1;
        t0 = n0;
        t1 = n1;
        uv += step2;
      }
    } else {
      const uint64_t dduv = pack(ddv, ddu), dduv2 = 2 * dduv;
      uv += 2 * duv + dduv;
      duv += dduv2;
      for (; k + 4 <= n; k += 2) {
        const uint64_t uv1 = uv + duv;
        const uint8_t n0 = texel(uv), n1 = texel(uv1);
        dest[k] = t0;
        dest[k + 1] = t1;
        t0 = n0;
        t1 = n1;
        uv = uv1 + duv + dduv;
        duv += dduv2;
      }
    }
    dest[k] = t0;  // the last loaded pair; uv is now pixel k + 2's
    dest[k + 1] = t1;
    k += 2;
  }
  if (k < n) dest[k] = texel(uv);
}

template <bool kFast>
void persp(uint8_t* dest, int n, const uint8_t* texels, int width, int height, const PerspSpan& p) {
  if (n <= 0) return;
  const double zrow = p.zi0, zix = p.dzi, urow = p.uz0, ux = p.duz, vrow = p.vz0, vx = p.dvz;
  const int32_t umax = p.umax, vmax = p.vmax;
  const double zc = p.second_order ? zix : 0.0;  // the walker's curve factor
  auto exact = [&](double px, int32_t* u, int32_t* v, double* zout) {
    double zi = zrow + zix * px;
    if (!(zi > kMinZi)) zi = kMinZi;
    const double z = 1.0 / zi;
    *u = to_fixed((urow + ux * px) * z, umax);
    *v = to_fixed((vrow + vx * px) * z, vmax);
    *zout = z;
  };
  // Pixel offset (from a run's first pixel) of the exact sample that ends a run with
  // `left` pixels still to draw: 16 for a full run, else the run's last pixel.
  auto end_offset = [](int left) { return left > 16 ? 16 : left - 1; };
  double px = p.px0;
  int left = n;
  int32_t u0, v0, u1, v1;
  double z0, z1;
  exact(px, &u0, &v0, &z0);
  u1 = u0;
  v1 = v0;
  z1 = z0;
  if (end_offset(left) > 0) exact(px + end_offset(left), &u1, &v1, &z1);
  for (;;) {
    const int run = left > 16 ? 16 : left;
    const int after = left - run;
    // The divide for the end of the next run, issued before this run is drawn. The fast
    // version only starts it here (the reciprocal, pinned in a register so the compiler
    // cannot sink it past the loop) and finishes the sample after the loop: on in-order
    // cores (Cortex-A53, A7) the divide's latency then runs under the integer loop instead
    // of stalling the multiplies that need it. The same operations, so the same bits.
    int32_t u2 = u1, v2 = v1;
    double z2 = z1;
    const bool next = after > 0 && end_offset(after) > 0;
    const double px2 = px + double(run + end_offset(after));
    if (kFast) {
      if (next) {
        double zi = zrow + zix * px2;
        if (!(zi > kMinZi)) zi = kMinZi;
        z2 = 1.0 / zi;
        pin(z2);
      }
    } else if (next) {
      exact(px2, &u2, &v2, &z2);
    }
    const int steps = end_offset(left);
    const double curve = zc * 0.5 * (z0 + z1);
    RunSteps su, sv;
    if (kFast && steps == 16) {
      su = run_steps(u0, u1, std::integral_constant<int, 16>{}, curve);
      sv = run_steps(v0, v1, std::integral_constant<int, 16>{}, curve);
    } else {
      su = run_steps(u0, u1, steps, curve);
      sv = run_steps(v0, v1, steps, curve);
    }
    if constexpr (kFast) {
      draw_run(dest, run, texels, uint32_t(width), uint32_t(u0), uint32_t(v0), uint32_t(su.d), uint32_t(sv.d),
               uint32_t(su.dd), uint32_t(sv.dd));
    } else {
      surface_span_scalar(dest, run, texels, width, height, u0, v0, su.d, sv.d, su.dd, sv.dd);
    }
    if (after <= 0) break;
    if (kFast && next) {
      u2 = to_fixed((urow + ux * px2) * z2, umax);
      v2 = to_fixed((vrow + vx * px2) * z2, vmax);
    }
    dest += run;
    px += double(run);
    left = after;
    u0 = u1;
    v0 = v1;
    z0 = z1;
    u1 = u2;
    v1 = v2;
    z1 = z2;
  }
}

}  // namespace

void surface_span_persp_scalar(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                               const PerspSpan& span) {
  persp<false>(dest, n, texels, width, height, span);
}

void surface_span_persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                             const PerspSpan& span) {
  persp<true>(dest, n, texels, width, height, span);
}

}  // namespace sb::simd
