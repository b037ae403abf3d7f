// asm/span_persp.cpp: the whole-span lit-surface drawer (asm/span_persp.h): the reference
// (the engine's run walker over surface_span_scalar) and the tuned portable version.
//
// The double arithmetic below must stay operation for operation what
// engine/render/span_draw.cpp's walk_span / exact / run_steps do: the kernel promises the
// engine's bytes (tests/asm/span_persp_test.cpp checks it). The tuned version computes the
// same operations in select form (clamps as max / min, the run-step test as masks; each
// rewrite argued where it is made), with the samples' positions accumulated as the walker
// accumulates them.
#include "asm/span_persp.h"

#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__aarch64__)
#include <arm_neon.h>
#endif

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

// ---------------------------------------------------------------- the pipelined loop
//
// A long span's full runs go through one straight-line block per run: the run's 16 pixels
// fully unrolled, and beside them, with no branch, everything the NEXT run needs (its end
// sample's to_fixed, its steps) plus the divide for the run after that. In-order cores
// (Cortex-A53, A7, A9) then overlap the double-precision chains and the divide with the
// texel loads instead of stalling on them run after run. The same operations as above, in
// select form: the same bits.

// max(x, lo) with NaN -> lo, and min(x, hi) for x not NaN, without branches.
inline double max_or_lo(double x, double lo) {
#if defined(__aarch64__)
  return __builtin_fmax(x, lo);  // fmaxnm
#elif defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(x), _mm_set_sd(lo)));  // NaN -> the second operand
#else
  return x > lo ? x : lo;
#endif
}
inline double min_hi(double x, double hi) {
#if defined(__aarch64__)
  return __builtin_fmin(x, hi);
#elif defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(x), _mm_set_sd(hi)));
#else
  return x > hi ? hi : x;
#endif
}

// to_fixed without branches: clamp in double, then convert (exact for 0 and max).
inline int32_t to_fixed_sel(double v, double max) {
  return int32_t(min_hi(max_or_lo(v * 65536.0, 0.0), max));
}

// double -> int32 by truncation, saturating, NaN -> 0 or INT32_MIN: the instruction's own
// (defined) behaviour. Only in-range values are ever used (see steps16_sel).
inline int32_t cvt_sat(double x) {
#if defined(__GNUC__) && defined(__aarch64__)
  int32_t r;
  __asm__("fcvtzs %w0, %d1" : "=r"(r) : "w"(x));
  return r;
#elif defined(__SSE2__)
  return _mm_cvttsd_si32(_mm_set_sd(x));
#else
  return x > -2147483648.0 && x < 2147483647.0 ? int32_t(x) : INT32_MIN;
#endif
}

// run_steps(a, b, 16, curve) without branches. a, b lie in [0, 2^31 - 2^16) (the clamps),
// so delta = b - a fits 32 bits. The walker's test, mirrored to delta >= 0 (the
// arithmetic is odd-symmetric in delta and dd: truncating divisions): with
// num = |delta| - 120 dd', d0' = num / 16, it accepts iff d0' >= 0, d0' + 15 dd' >= 0 and
// 0 <= reach' = 16 d0' + 120 dd' = |delta| - (num & 15) <= |delta| (for num >= 0 the
// division is a floor, so num = 16 d0' + (num & 15); for num < 0 the walker rejects too:
// then 120 dd' > |delta| >= reach' fails or d0' < 0). Accepted steps have
// |dd| <= |delta| / 120 < 2^25 and |d0| < 2^28, so the range checks on ddf (|ddf| < 1e9)
// and d0 (int32) never decide anything that this test does not: a saturated or NaN
// conversion of ddf is rejected here, or gives dd = 0, which yields the linear step too.
inline RunSteps steps16_dd(int32_t delta, int64_t dd);
inline RunSteps steps16_sel(int32_t a, int32_t b, double curve) {
  const int32_t delta = b - a;
  const double c = double(delta) / 16 * curve;
  const double ddf = -2.0 * c;
  return steps16_dd(delta, cvt_sat(ddf));
}
// steps16_sel's integer part, from delta and dd = cvt_sat(ddf).
inline RunSteps steps16_dd(int32_t delta, int64_t dd) {
  // Masks, not conditions: the compiler turns those into branches on the signs.
  const int64_t s = int64_t(delta >> 31);  // -1 when delta < 0
  const int64_t pd = (int64_t(delta) ^ s) - s, pdd = (dd ^ s) - s;
  const int64_t num = pd - pdd * 120;
  const int64_t q = num >> 4;
  const int64_t last_step = q + pdd * 15;
  // The reach' test is implied: reach' = 16 d0' + 120 dd' = 8 (d0' + last_step) >= 0 when
  // num >= 0 (then d0' >= 0) and last_step >= 0, and reach' = |delta| - (num & 15) <= |delta|.
  const int64_t reject = (num | last_step) >> 63;  // -1: linear
  const int64_t pick = q ^ ((q ^ (pd >> 4)) & reject);  // d0' or the linear step, mirrored
  return {int32_t((pick ^ s) - s), int32_t(dd & ~reject)};
}

// One 16-pixel run, straight-line: u, v stepped with their second-order terms (0 when
// linear), even and odd pixels in two independent chains (u_{k+2} = u_k + e_k,
// e_{k+2} = e_k + 4 dd with e_k = 2 du_k + dd: the recurrence two steps at a time, equal
// modulo 2^32), so the adds do not form one 16-deep dependency chain. 64-bit targets: u, v
// packed in one register (see draw_run); ARM: texels gathered into words (orr with a
// shifted operand), one store per 8 (aarch64) or 4 (armhf).
#if defined(__aarch64__) || defined(__x86_64__)
#define SB_SPAN_PACKED 1
#endif
#if defined(__aarch64__) || defined(__arm__)
#define SB_SPAN_WORDS 1
#endif
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__ && defined(SB_SPAN_WORDS)
#error "draw16 gathers texels little-endian"
#endif
// A full run's steps: the curved ones, or (kCurve false: curve 0) run_steps' linear step.
template <bool kCurve>
inline RunSteps steps16(int32_t a, int32_t b, double curve) {
  if constexpr (kCurve) {
    return steps16_sel(a, b, curve);
  } else {
    (void)curve;
    return {(b - a) / 16, 0};  // |b - a| < 2^31 (the clamps)
  }
}

#define SB_INLINE inline __attribute__((always_inline))

// Ends a group of the software-pipelined run below. ARM (in-order cores): an empty volatile
// asm, which the compiler's scheduler does not move instructions across, so each group's
// independent instructions stay together; x86-64 (out of order): nothing.
inline void group_end() {
#if defined(__GNUC__) && (defined(__aarch64__) || defined(__arm__))
  __asm__ volatile("");
#endif
}

// The run in ten groups, software-pipelined two pixels per group: group g computes the
// texel addresses of pixels 2g, 2g + 1, loads those of pixels 2g - 2, 2g - 1 and gathers
// (or stores) those of pixels 2g - 4, 2g - 3, so that no instruction waits for one of its
// own group (the load-to-use and multiply latencies of in-order cores are covered).
template <bool kCurve = true>
class Run16 {
 public:
  SB_INLINE Run16(int32_t u0, int32_t v0, const RunSteps& su, const RunSteps& sv) {
#if defined(SB_SPAN_PACKED)
    auto pack = [](uint32_t hi, uint32_t lo) { return (uint64_t(hi) << 32) + uint64_t(int64_t(int32_t(lo))); };
    const T a0 = (uint64_t(uint32_t(v0)) << 32) + uint32_t(u0), d0 = pack(uint32_t(sv.d), uint32_t(su.d));
    const T dd = pack(uint32_t(sv.dd), uint32_t(su.dd));
    x_[0] = a0;
    x_[1] = a0 + d0;
    e_[0] = 2 * d0 + dd;
    e_[1] = 2 * d0 + 3 * dd;
    dd4_ = 4 * dd;
#else
    // 32-bit: one chain (u, v, du, dv, ddu, ddv: six registers; two chains would spill).
    u_ = uint32_t(u0), du_ = uint32_t(su.d), ddu_ = uint32_t(su.dd);
    v_ = uint32_t(v0), dv_ = uint32_t(sv.d), ddv_ = uint32_t(sv.dd);
#endif
  }
  template <int G>
  SB_INLINE void group(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w) {
    if constexpr (G < 8) {
      address<2 * G>(w);
      address<2 * G + 1>(w);
    }
    if constexpr (G >= 1 && G <= 8) {
      t_[2 * G - 2] = texels[a_[2 * G - 2]];
      t_[2 * G - 1] = texels[a_[2 * G - 1]];
    }
    if constexpr (G >= 2 && G <= 9) {
      put<2 * G - 4>(dest);
      put<2 * G - 3>(dest);
    }
    if constexpr (G == 9) finish(dest);
  }
  SB_INLINE void draw(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w) {
    draw(dest, texels, w, [](auto) {});
  }
  // The same, with stage(std::integral_constant<int, G>) placed inside group G: other work
  // (the next runs' setup) interleaved with the pixels, one dependent step per group, so
  // in-order cores cover its latencies with the texel loads.
  template <class Stage>
  SB_INLINE void draw(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w, Stage&& stage) {
    using std::integral_constant;
    group<0>(dest, texels, w), stage(integral_constant<int, 0>{}), group_end();
    group<1>(dest, texels, w), stage(integral_constant<int, 1>{}), group_end();
    group<2>(dest, texels, w), stage(integral_constant<int, 2>{}), group_end();
    group<3>(dest, texels, w), stage(integral_constant<int, 3>{}), group_end();
    group<4>(dest, texels, w), stage(integral_constant<int, 4>{}), group_end();
    group<5>(dest, texels, w), stage(integral_constant<int, 5>{}), group_end();
    group<6>(dest, texels, w), stage(integral_constant<int, 6>{}), group_end();
    group<7>(dest, texels, w), stage(integral_constant<int, 7>{}), group_end();
    group<8>(dest, texels, w), stage(integral_constant<int, 8>{}), group_end();
    group<9>(dest, texels, w), stage(integral_constant<int, 9>{});
  }

 private:
#if defined(SB_SPAN_PACKED)
  using T = uint64_t;
  T x_[2], e_[2], dd4_;
#else
  using T = uint32_t;
  T u_, du_, ddu_, v_, dv_, ddv_;
#endif
  // x86-64: 64-bit offsets (no zero-extension before addressing); ARM: 32-bit (uxtw).
#if defined(__x86_64__)
  using Addr = uint64_t;
#else
  using Addr = uint32_t;
#endif
  Addr a_[16];
  uint8_t t_[16];
#if defined(SB_SPAN_WORDS)
  using Word = uintptr_t;
  static constexpr int kPer = int(sizeof(Word));
  Word out_[4] = {0, 0, 0, 0};
#endif
  template <int K>
  SB_INLINE void address(uint32_t w) {
    constexpr int c = K & 1;
#if defined(SB_SPAN_PACKED)
    a_[K] = Addr(uint32_t(x_[c] >> 48)) * w + (uint32_t(x_[c]) >> 16);
    x_[c] += e_[c];
    if constexpr (kCurve) e_[c] += dd4_;
#else
    (void)c;
    a_[K] = (v_ >> 16) * w + (u_ >> 16);
    u_ += du_;
    v_ += dv_;
    if constexpr (kCurve) {
      du_ += ddu_;
      dv_ += ddv_;
    }
#endif
  }
  template <int K>
  SB_INLINE void put(uint8_t* __restrict dest) {
#if defined(SB_SPAN_WORDS)
    out_[K / kPer] |= Word(t_[K]) << (8 * (K % kPer));  // little-endian
    if constexpr (K % kPer == kPer - 1) __builtin_memcpy(dest + (K - kPer + 1), &out_[K / kPer], sizeof(Word));
#else
    dest[K] = t_[K];
#endif
  }
  SB_INLINE void finish(uint8_t* __restrict dest) { (void)dest; }  // put stores each word when full
};

template <bool kCurve = true>
SB_INLINE void draw16(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w, int32_t u0, int32_t v0,
                   const RunSteps& su, const RunSteps& sv) {
  Run16<kCurve> run(u0, v0, su, sv);
  run.draw(dest, texels, w);
}

// 1 / max(zi, kMinZi) for two samples (NaN -> kMinZi). aarch64: one vector divide (on
// Cortex-A53 it costs what one scalar divide costs); elsewhere two.
inline void recip2(double zia, double zib, double* za, double* zb) {
#if defined(__aarch64__)
  const float64x2_t zi = vmaxnmq_f64(vcombine_f64(vdup_n_f64(zia), vdup_n_f64(zib)), vdupq_n_f64(kMinZi));
  const float64x2_t z = vdivq_f64(vdupq_n_f64(1.0), zi);
  *za = vgetq_lane_f64(z, 0);
  *zb = vgetq_lane_f64(z, 1);
#else
  *za = 1.0 / max_or_lo(zia, kMinZi);
  *zb = 1.0 / max_or_lo(zib, kMinZi);
#endif
}

struct Sample {
  int32_t u, v;
  double z;
};

// run_steps for u and v over a run's `steps` (0 .. 16) pixels, each integer division by a
// constant (multiplies and shifts: no 64-bit divide instruction or, on armhf, library call)
// and the two double quotients delta / steps in one vector divide (aarch64, x86-64).
template <class Steps>
inline RunSteps run_steps_q(int32_t a, int32_t b, Steps steps_, double curve, double q) {
  // run_steps with double(b - a) / steps given as q.
  const int steps = steps_;
  const int64_t delta = int64_t(b) - int64_t(a);
  const int32_t linear = int32_t(delta / steps);
  if (curve == 0.0 || steps < 2) return {linear, 0};
  const double c = q * curve;
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
template <int S>
inline void run_steps_uv(const Sample& a, const Sample& b, double curve, RunSteps* su, RunSteps* sv) {
  const std::integral_constant<int, S> steps;
  const int64_t du = int64_t(b.u) - int64_t(a.u), dv = int64_t(b.v) - int64_t(a.v);
  double qu = 0.0, qv = 0.0;
  if (curve != 0.0 && S >= 2) {
#if defined(__aarch64__)
    const float64x2_t q = vdivq_f64(vcombine_f64(vdup_n_f64(double(du)), vdup_n_f64(double(dv))), vdupq_n_f64(S));
    qu = vgetq_lane_f64(q, 0);
    qv = vgetq_lane_f64(q, 1);
#elif defined(__SSE2__)
    const __m128d q = _mm_div_pd(_mm_set_pd(double(dv), double(du)), _mm_set1_pd(S));
    qu = _mm_cvtsd_f64(q);
    qv = _mm_cvtsd_f64(_mm_unpackhi_pd(q, q));
#else
    qu = double(du) / S;
    qv = double(dv) / S;
#endif
  }
  *su = run_steps_q(a.u, b.u, steps, curve, qu);
  *sv = run_steps_q(a.v, b.v, steps, curve, qv);
}
inline void run_steps_uv(int steps, const Sample& a, const Sample& b, double curve, RunSteps* su, RunSteps* sv) {
  switch (steps) {
#define SB_CASE(S) \
  case S: return run_steps_uv<S>(a, b, curve, su, sv);
    SB_CASE(1) SB_CASE(2) SB_CASE(3) SB_CASE(4) SB_CASE(5) SB_CASE(6) SB_CASE(7) SB_CASE(8)
    SB_CASE(9) SB_CASE(10) SB_CASE(11) SB_CASE(12) SB_CASE(13) SB_CASE(14) SB_CASE(15) SB_CASE(16)
#undef SB_CASE
    default: *su = *sv = RunSteps{0, 0};  // steps 0: one pixel
  }
}

// The reference: span_draw.cpp's walker, one surface_span_scalar call per run.
void persp_reference(uint8_t* dest, int n, const uint8_t* texels, int width, int height, const PerspSpan& p) {
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
    // The exact values for the end of the next run, computed before this run is drawn.
    int32_t u2 = u1, v2 = v1;
    double z2 = z1;
    if (after > 0 && end_offset(after) > 0) exact(px + double(run + end_offset(after)), &u2, &v2, &z2);
    const int steps = end_offset(left);
    const double curve = zc * 0.5 * (z0 + z1);
    const RunSteps su = run_steps(u0, u1, steps, curve), sv = run_steps(v0, v1, steps, curve);
    surface_span_scalar(dest, run, texels, width, height, u0, v0, su.d, sv.d, su.dd, sv.dd);
    if (after <= 0) break;
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

void surface_span_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int, int32_t u, int32_t v,
                       int32_t du, int32_t dv, int32_t ddu, int32_t ddv) {
  const uint32_t w = uint32_t(width);
  if (n == 16) return draw16(dest, texels, w, u, v, RunSteps{du, ddu}, RunSteps{dv, ddv});  // the engine's runs
  uint32_t uu = uint32_t(u), vv = uint32_t(v), duu = uint32_t(du), dvv = uint32_t(dv);
  const uint32_t dduu = uint32_t(ddu), ddvv = uint32_t(ddv);
  for (; n >= 16; n -= 16, dest += 16) {
    draw16(dest, texels, w, int32_t(uu), int32_t(vv), RunSteps{int32_t(duu), ddu}, RunSteps{int32_t(dvv), ddv});
    // 16 pixels on (mod 2^32): u += 16 du + 120 ddu, du += 16 ddu.
    uu += 16 * duu + 120 * dduu;
    vv += 16 * dvv + 120 * ddvv;
    duu += 16 * dduu;
    dvv += 16 * ddvv;
  }
  if (n > 0) draw_run(dest, n, texels, w, uu, vv, duu, dvv, dduu, ddvv);
}

void surface_span_persp_scalar(uint8_t* dest, int n, const uint8_t* texels, int width, int height,
                               const PerspSpan& span) {
  persp_reference(dest, n, texels, width, height, span);
}

namespace {
// kCurve false: linear steps (Quake's way: second_order off, or a constant 1/z along the
// row, whose curve factor is 0), the steps delta / 16 and no second-order adds per pixel.
template <bool kCurve>
void persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  if (n <= 0) return;
  // Long spans. Runs r = 0, 1, ... of 16 pixels; sample j (a run's first pixel, or the
  // span's last one) at pixel offset o_j = min(16 j, n - 1), its position computed as the
  // walker computes it: P_0 + o_1 for j = 1, else P_{j-2} + (o_j - o_{j-2}), where
  // P_r = P_{r-1} + 16 is run r's first pixel, accumulated. `left` = pixels from run r on.
  // The loop draws two runs per pass; the divides for the samples two runs ahead are issued
  // in pairs, their to_fixed and the following runs' steps are done beside the drawing, all
  // branch-free (one block per pass).
  const double zrow = p.zi0, zix = p.dzi, urow = p.uz0, ux = p.duz, vrow = p.vz0, vx = p.dvz;
  const double umaxd = double(p.umax), vmaxd = double(p.vmax);
  const double zc = p.second_order ? zix : 0.0;
  const uint32_t w = uint32_t(width);
  auto sample = [&](double px, double z) {
    return Sample{to_fixed_sel((urow + ux * px) * z, umaxd), to_fixed_sel((vrow + vx * px) * z, vmaxd), z};
  };
  double P = p.px0;
  int left = n;
  double z0, z1, z2, z3;
  if (n <= 16) {  // one run, from pixel 0 to pixel n - 1 (one pixel: steps 0, no second sample)
    const double pos1 = P + double(n - 1);
    recip2(zrow + zix * P, zrow + zix * pos1, &z0, &z1);
    const Sample s0 = sample(P, z0), s1 = n > 1 ? sample(pos1, z1) : s0;
    const double curve = zc * 0.5 * (s0.z + s1.z);
    RunSteps su, sv;
    run_steps_uv(n - 1, s0, s1, curve, &su, &sv);
    if (n == 16) {
      draw16<kCurve>(dest, texels, w, s0.u, s0.v, su, sv);
    } else {
      draw_run(dest, n, texels, w, uint32_t(s0.u), uint32_t(s0.v), uint32_t(su.d), uint32_t(sv.d), uint32_t(su.dd),
               uint32_t(sv.dd));
    }
    return;
  }
  recip2(zrow + zix * P, zrow + zix * (P + double(16)), &z0, &z1);
  Sample s0 = sample(P, z0), s1 = sample(P + double(16), z1);
  double pos2, pos3 = 0.0;
  if (n > 32) {  // samples 2 and 3 (o_2 = 32; o_3 - o_1 = min(32, n - 17))
    pos2 = P + double(32);
    pos3 = (P + double(16)) + double(n - 17 < 32 ? n - 17 : 32);
    recip2(zrow + zix * pos2, zrow + zix * pos3, &z2, &z3);
  } else {  // two runs: sample 2 is the last pixel, o_2 - o_0 = n - 1
    pos2 = P + double(n - 1);
    recip2(zrow + zix * pos2, zrow + zix * pos2, &z2, &z3);
  }
  RunSteps su = steps16<kCurve>(s0.u, s1.u, zc * 0.5 * (s0.z + s1.z));
  RunSteps sv = steps16<kCurve>(s0.v, s1.v, zc * 0.5 * (s0.z + s1.z));
  // Two runs per pass while runs r + 1 and r + 2 are full and not the last (their steps are
  // over 16 pixels): left > 48. Samples r + 4 and r + 5 are then at o_{r+4} - o_{r+2} =
  // min(32, left - 33) and o_{r+5} - o_{r+3} = min(32, left - 49) past P_{r+2}, P_{r+3}.
  // In the loop, ddf = -2 (delta / 16 * curve) with curve = zc / 2 * (z_a + z_b) is computed
  // as delta * (zck * (z_a + z_b)), zck = zc * -1/16: the same bits. Scaling by a power of
  // two is exact and commutes with rounding, so zck (z_a + z_b) = -curve / 8 and both ddf
  // are -round(delta * curve) / 8, whenever no value is subnormal or infinite.
  // Subnormal (|zc| < 2^-1018, or a product below 2^-1022): |ddf| < 1 either way, dd = 0.
  // Overflow: curve infinite makes ddf infinite with the sign delta * -zc, and then
  // |delta zck (z_a + z_b)| > DBL_MAX / 8 saturates to the same int32 (delta != 0); for
  // delta = 0 the walker's NaN gives dd = 0 or INT32_MIN, both rejected or 0 by
  // steps16_dd, which then returns {0, 0} like dd = 0 does. A product overflowing later
  // (delta / 16 * curve, or the * -2) overflows in both forms at the same rounding point.
  const double zck = zc * -0.0625;
  // (urow + ux * pos) of samples 2 and 3: the first half of sample(), one pass ahead.
  double tu2 = urow + ux * pos2, tv2 = vrow + vx * pos2, tu3 = urow + ux * pos3, tv3 = vrow + vx * pos3;
  // The runs' register state set up in the group before them (the second run's only on
  // 64-bit targets: armhf runs out of registers).
#if defined(SB_SPAN_PACKED)
  constexpr bool kEarlyB = true;
#else
  constexpr bool kEarlyB = false;
#endif
  Run16<kCurve> run_a(s0.u, s0.v, su, sv), run_b = run_a;
  while (left > 48) {
    const double P1 = P + double(16), P2 = P1 + double(16), P3 = P2 + double(16);
    const double pos4 = P2 + double(left - 33 < 32 ? left - 33 : 32);
    const double pos5 = P3 + double(left - 49 < 32 ? left - 49 : 32);
    // Software-pipelined setup: samples 2 and 3 (their divides issued a pass earlier), the
    // steps of runs r + 1 (needed by the second run of this pass) and r + 2 (the next pass),
    // and the divides for samples 4 and 5, one dependent operation per pixel group. Each
    // operation is sample()'s / steps16's, in their order.
    double sum1, sum2, c1 = 0.0, c2 = 0.0, zi4, zi5, tu4, tv4, tu5, tv5;
    double qu2, qv2, qu3, qv3, fu1 = 0.0, fv1 = 0.0, fu2 = 0.0, fv2 = 0.0;
    int32_t s2u = 0, s2v = 0, s3u = 0, s3v = 0;
    int64_t iu1 = 0, iv1 = 0, iu2 = 0, iv2 = 0;
    RunSteps u1{}, v1{}, u2{}, v2{};
    double z4, z5;
    auto stage_a = [&](auto g) {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        qu2 = tu2 * z2, qv2 = tv2 * z2, qu3 = tu3 * z3, qv3 = tv3 * z3;
        sum1 = s1.z + z2, sum2 = z2 + z3;
        zi4 = zrow + zix * pos4, zi5 = zrow + zix * pos5;
      } else if constexpr (G == 1) {
        qu2 = qu2 * 65536.0, qv2 = qv2 * 65536.0, qu3 = qu3 * 65536.0, qv3 = qv3 * 65536.0;
        if constexpr (kCurve) c1 = zck * sum1, c2 = zck * sum2;
      } else if constexpr (G == 2) {
        qu2 = max_or_lo(qu2, 0.0), qv2 = max_or_lo(qv2, 0.0), qu3 = max_or_lo(qu3, 0.0), qv3 = max_or_lo(qv3, 0.0);
      } else if constexpr (G == 3) {
        qu2 = min_hi(qu2, umaxd), qv2 = min_hi(qv2, vmaxd), qu3 = min_hi(qu3, umaxd), qv3 = min_hi(qv3, vmaxd);
        recip2(zi4, zi5, &z4, &z5);
      } else if constexpr (G == 4) {
        s2u = int32_t(qu2), s2v = int32_t(qv2), s3u = int32_t(qu3), s3v = int32_t(qv3);
      } else if constexpr (G == 5) {
        if constexpr (kCurve) {
          fu1 = double(s2u - s1.u), fv1 = double(s2v - s1.v);
        } else {
          u1 = {(s2u - s1.u) / 16, 0}, v1 = {(s2v - s1.v) / 16, 0};
        }
      } else if constexpr (G == 6) {
        if constexpr (kCurve) fu1 = fu1 * c1, fv1 = fv1 * c1;
      } else if constexpr (G == 7) {
        if constexpr (kCurve) iu1 = cvt_sat(fu1), iv1 = cvt_sat(fv1);
      } else if constexpr (G == 8) {
        if constexpr (kCurve) u1 = steps16_dd(s2u - s1.u, iu1), v1 = steps16_dd(s2v - s1.v, iv1);
      } else if constexpr (G == 9) {
        if constexpr (kEarlyB) run_b = Run16<kCurve>(s1.u, s1.v, u1, v1);  // the second run's setup
      }
    };
    auto stage_b = [&](auto g) {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        if constexpr (!kCurve) u2 = {(s3u - s2u) / 16, 0}, v2 = {(s3v - s2v) / 16, 0};
        tu4 = urow + ux * pos4, tv4 = vrow + vx * pos4, tu5 = urow + ux * pos5, tv5 = vrow + vx * pos5;
      } else if constexpr (G == 1) {
        if constexpr (kCurve) fu2 = double(s3u - s2u), fv2 = double(s3v - s2v);
      } else if constexpr (G == 3) {
        if constexpr (kCurve) fu2 = fu2 * c2, fv2 = fv2 * c2;
      } else if constexpr (G == 5) {
        if constexpr (kCurve) iu2 = cvt_sat(fu2), iv2 = cvt_sat(fv2);
      } else if constexpr (G == 8) {
        if constexpr (kCurve) u2 = steps16_dd(s3u - s2u, iu2), v2 = steps16_dd(s3v - s2v, iv2);
      } else if constexpr (G == 9) {
        run_a = Run16<kCurve>(s2u, s2v, u2, v2);  // the next pass's first run, set up here
      }
    };
    {
      run_a.draw(dest, texels, w, stage_a);
    }
    group_end();
    {
      if constexpr (!kEarlyB) run_b = Run16<kCurve>(s1.u, s1.v, u1, v1);
      run_b.draw(dest + 16, texels, w, stage_b);
    }
    group_end();
    dest += 32;
    P = P2;
    left -= 32;
    s0 = Sample{s2u, s2v, z2};
    s1 = Sample{s3u, s3v, z3};
    su = u2;
    sv = v2;
    z2 = z4;
    z3 = z5;
    pos2 = pos4;
    pos3 = pos5;
    tu2 = tu4, tv2 = tv4, tu3 = tu5, tv3 = tv5;
  }
  if (left > 32) {  // one run more whose next run is full and not the last
    const Sample s2 = sample(pos2, z2);
    const double c1 = zc * 0.5 * (s1.z + s2.z);
    const RunSteps u1 = steps16<kCurve>(s1.u, s2.u, c1), v1 = steps16<kCurve>(s1.v, s2.v, c1);
    draw16<kCurve>(dest, texels, w, s0.u, s0.v, su, sv);
    dest += 16;
    P += double(16);
    left -= 16;
    s0 = s1;
    s1 = s2;
    su = u1;
    sv = v1;
    z2 = z3;
    pos2 = pos3;
  }
  // left = 17 .. 32: run r (full, its steps known), then the last run of left - 16 pixels,
  // which ends at the span's last pixel, sample r + 2 (pos2 = P_r + left - 1; for a one-pixel
  // last run that is sample r + 1 itself, which the walker does not recompute).
  draw16<kCurve>(dest, texels, w, s0.u, s0.v, su, sv);
  dest += 16;
  const int last = left - 16, steps = last - 1;
  const Sample s2 = steps > 0 ? sample(pos2, z2) : s1;
  const double curve = zc * 0.5 * (s1.z + s2.z);
  RunSteps lu, lv;
  run_steps_uv(steps, s1, s2, curve, &lu, &lv);
  if (last == 16) {
    draw16<kCurve>(dest, texels, w, s1.u, s1.v, lu, lv);
  } else {
    draw_run(dest, last, texels, w, uint32_t(s1.u), uint32_t(s1.v), uint32_t(lu.d), uint32_t(lv.d), uint32_t(lu.dd),
             uint32_t(lv.dd));
  }
}
}  // namespace

void surface_span_persp_fast(uint8_t* dest, int n, const uint8_t* texels, int width, int /*height*/,
                             const PerspSpan& p) {
  // curve = zc (z_a + z_b) / 2 with zc = 0 is 0 (the depths are finite): the linear steps.
  if (!p.second_order || p.dzi == 0.0) return persp_fast<false>(dest, n, texels, width, p);
  persp_fast<true>(dest, n, texels, width, p);
}

}  // namespace sb::simd
