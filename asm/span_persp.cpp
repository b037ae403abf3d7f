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

// span_draw.cpp's run_steps, the quotient double(b - a) / steps given by quotient() (called
// only when curve != 0 and steps >= 2). Steps is int (any run) or std::integral_constant<int, S>
// (then every integer division below is by a constant and compiles to shifts and multiplies,
// with the same results: integer division truncates toward zero either way).
template <class Steps, class Quotient>
inline RunSteps run_steps_with(int32_t a, int32_t b, Steps steps_, double curve, Quotient quotient) {
  const int steps = steps_;
  const int64_t delta = int64_t(b) - int64_t(a);
  const int32_t linear = int32_t(delta / steps);  // truncation: never overshoots b
  if (curve == 0.0 || steps < 2) return {linear, 0};
  const double c = quotient() * curve;
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

// span_draw.cpp's run_steps (double / 16 is exact, as is double * 0.0625).
template <class Steps>
inline RunSteps run_steps(int32_t a, int32_t b, Steps steps_, double curve) {
  const int steps = steps_;
  if (steps <= 0) return {0, 0};
  return run_steps_with(a, b, steps_, curve, [&] { return double(int64_t(b) - int64_t(a)) / steps; });
}

// run_steps with the quotient already computed (q = double(b - a) / steps; steps >= 1).
template <class Steps>
inline RunSteps run_steps_q(int32_t a, int32_t b, Steps steps_, double curve, double q) {
  return run_steps_with(a, b, steps_, curve, [q] { return q; });
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
#elif defined(__GNUC__) && defined(__arm__) && defined(__ARM_FP) && (__ARM_FP & 8)
  float r;  // vcvt: truncating, saturating, NaN -> 0
  __asm__("vcvt.s32.f64 %0, %P1" : "=t"(r) : "w"(x));
  return __builtin_bit_cast(int32_t, r);
#else
  return x > -2147483648.0 && x < 2147483647.0 ? int32_t(x) : INT32_MIN;
#endif
}

// armhf: to_fixed with the clamps in integers after vcvt (no vcmpe / vmrs):
// fix(q, m) = min(max(sat32(trunc(q 65536)), 0), m) (sat32: vcvt.s32.f64, NaN -> 0).
// NaN and x = q 65536 <= 0 give trunc <= 0 -> 0; x > m (an integer) gives trunc >= m,
// kept >= m by the saturation -> m; else 0 < x <= m and trunc(x) fits.
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_FP) && (__ARM_FP & 8)
constexpr bool kIntClamp = true;
#else
constexpr bool kIntClamp = false;
#endif
inline int32_t clamp_fixed(int32_t t, int32_t max) {
  t &= ~(t >> 31);
  return t < max ? t : max;
}
inline int32_t to_fixed_int(double v, int32_t max) { return clamp_fixed(cvt_sat(v * 65536.0), max); }

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
inline RunSteps steps16_dd(int32_t delta, int32_t dd);
inline RunSteps steps16_sel(int32_t a, int32_t b, double curve) {
  const int32_t delta = b - a;
  const double c = double(delta) / 16 * curve;
  const double ddf = -2.0 * c;
  return steps16_dd(delta, cvt_sat(ddf));
}
// steps16_sel's integer part, from delta and dd = cvt_sat(ddf) (an int32).
#if UINTPTR_MAX > 0xffffffffu
inline RunSteps steps16_dd(int32_t delta, int32_t dd32) {
  // Masks, not conditions: the compiler turns those into branches on the signs.
  const int64_t dd = dd32;
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
#else
// 32-bit targets: the same in 32-bit arithmetic. With pd = |delta| < 2^31 and pdd = dd
// mirrored (|pdd| = |dd| <= 2^31), the test above (num >= 0 and last_step = floor(num / 16)
// + 15 pdd >= 0) is 120 |dd| <= pd: for pdd >= 0, num >= 0 is pd >= 120 pdd and then
// last_step >= 0; for pdd < 0, num > 0 and floor(num / 16) >= 15 |pdd| (an integer) iff
// num >= 240 |pdd| iff pd >= 120 |pdd|. Then num = pd - 120 pdd lies in [0, 2 pd] < 2^32:
// its uint32 value (arithmetic mod 2^32) is exact and d0' = num >> 4. Rejected: the linear
// step (pd >> 4, mirrored) and dd = 0.
inline RunSteps steps16_dd(int32_t delta, int32_t dd) {
  const uint32_t s = uint32_t(delta >> 31);  // all ones when delta < 0
  const uint32_t pd = (uint32_t(delta) ^ s) - s, pdd = (uint32_t(dd) ^ s) - s;
  const uint32_t sd = uint32_t(dd >> 31), add = (uint32_t(dd) ^ sd) - sd;  // |dd|
  const uint32_t accept = -uint32_t(uint64_t(add) * 120 <= pd);  // all ones: second order
  const uint32_t q = (pd - pdd * 120) >> 4, lin = pd >> 4;
  const uint32_t pick = lin ^ ((q ^ lin) & accept);  // d0' or the linear step, mirrored
  return {int32_t((pick ^ s) - s), int32_t(uint32_t(dd) & accept)};
}
#endif

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
#define SB_LAMBDA_INLINE __attribute__((always_inline))

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
#if defined(SB_SPAN_PACKED)
  // From the packed start v 2^32 + u and steps dv 2^32 + du, ddv 2^32 + ddu (du, ddu
  // sign-extended), as the constructor above packs them.
  struct Packed {};
  SB_INLINE Run16(uint64_t a0, uint64_t d0, uint64_t dd, Packed) {
    x_[0] = a0;
    x_[1] = a0 + d0;
    e_[0] = 2 * d0 + dd;
    e_[1] = 2 * d0 + 3 * dd;
    dd4_ = 4 * dd;
  }
#endif
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
#if defined(__aarch64__) && defined(__GNUC__)
// aarch64, persp_fast's long spans: the two runs of a loop pass (32 pixels) as one software
// pipeline of eight groups of four pixels, written in asm so that each slot keeps its order:
// the shifts and steps of group j (latency 2), the caller's stage (double / vector work,
// latency 6), then the multiply-adds of group j beside the loads of group j - 1 (latency 4)
// and the gather and store of groups j - 2, j - 3: in-order issue (llvm-mca's Cortex-A53
// model also completes in order) seldom waits. u, v packed as in draw_run (v 2^32 + u).
//   linear: pixel 4 g + i of a run on chain i, stepped by e = 4 duv: chain i holds
//           uv_0 + (4 g + i) duv (mod 2^64), draw_run's value.
//   second order: two chains (fewer registers), c0 = uv_k, c1 = uv_{k+1}, stepped two pixels
//           at a time by e0, e1 (uv_{k+2} - uv_k), each e by dd4 = 4 dduv, as Run16 does.
// Keeps a value computed where it is written: an empty asm the compiler cannot move
// (volatile) that takes the value, so its computation is neither sunk below it nor, for an
// accumulator copy (x = constant), merged into the later instruction that overwrites it.
template <class T>
SB_INLINE void pin(T& x) {
  if constexpr (std::is_integral_v<T>) {
    __asm__ volatile("" : "+r"(x));
  } else {
    __asm__ volatile("" : "+w"(x));
  }
}
// The linear steps of a full run from packed samples a, b (v 2^32 + u, 0 <= u, v < 2^31):
// (b - a) / 16 for u and v (truncating), packed as dv 2^32 + du (du sign-extended).
// x / 16 truncated = (x + (x < 0 ? 15 : 0)) >> 4 (arithmetic shift: a floor).
SB_INLINE uint64_t steps16_packed(uint64_t a, uint64_t b) {
  uint64_t du, dv, t, u;
  __asm__(
      "sub %w[du], %w[b], %w[a]\n\t"
      "lsr %[t], %[a], #32\n\t"
      "lsr %[dv], %[b], #32\n\t"
      "asr %w[u], %w[du], #31\n\t"
      "sub %w[dv], %w[dv], %w[t]\n\t"
      "add %w[du], %w[du], %w[u], lsr #28\n\t"
      "asr %w[t], %w[dv], #31\n\t"
      "sbfx %[du], %[du], #4, #28\n\t"
      "add %w[dv], %w[dv], %w[t], lsr #28\n\t"
      "asr %w[dv], %w[dv], #4\n\t"
      "add %[du], %[du], %[dv], lsl #32"
      : [du] "=&r"(du), [dv] "=&r"(dv), [t] "=&r"(t), [u] "=&r"(u)
      : [a] "r"(a), [b] "r"(b));
  return du;
}
// The chain setup, linear: run start uv0 (v 2^32 + u), packed step duv.
SB_INLINE void lin_start(uint64_t& c0, uint64_t& c1, uint64_t& c2, uint64_t& c3, uint64_t& e, uint64_t uv0,
                         uint64_t duv) {
  const uint64_t dd = duv + duv;
  c0 = uv0;
  c1 = uv0 + duv;
  c2 = uv0 + dd;
  c3 = c1 + dd;
  e = dd + dd;
}
// The same with second-order steps dduv (uv_k = uv_0 + k duv + k (k - 1) / 2 dduv): c0 =
// uv_0, c1 = uv_1, e0 = uv_2 - uv_0 = 2 duv + dduv, e1 = uv_3 - uv_1 = 2 duv + 3 dduv.
SB_INLINE void lin_start2(uint64_t& c0, uint64_t& c1, uint64_t& e0, uint64_t& e1, uint64_t& dd4, uint64_t uv0,
                          uint64_t duv, uint64_t dduv) {
  c0 = uv0;
  c1 = uv0 + duv;
  e0 = 2 * duv + dduv;
  e1 = e0 + 2 * dduv;
  dd4 = 4 * dduv;
}
// Slot J (0 .. 9) of a pass: the shifts and steps of group J; the gather of group
// J - 2's bytes into two pairs and of group J - 3's pairs into a word; stage(2 J); the
// multiply-adds of group J beside the loads of group J - 1 (the multiply-adds write over
// their shifted v, the loads over their address: fewer registers); the store of group J - 3
// (slot 9 also gathers and stores group 7); stage(2 J + 1); then slot 3 starts the chains
// of the second run (b_uv, b_d: start and packed step, set by the stage), slot 7 those of the
// next pass's first (a_uv, a_d). The state as scalars (references): it stays in registers.
template <int J, bool kCurve, class Stage>
SB_INLINE void lin_slot(uint64_t& c0, uint64_t& c1, uint64_t& c2, uint64_t& c3, uint64_t& e, uint64_t& e1,
                        uint64_t& dd4, uint64_t& pa0,
                        uint64_t& pa1, uint64_t& pa2, uint64_t& pa3, uint64_t& b0, uint64_t& b1, uint64_t& b2,
                        uint64_t& b3, uint64_t& g0, uint64_t& g1, uint8_t* __restrict dest,
                        const uint8_t* __restrict texels, uint64_t w, const uint64_t& b_uv, const uint64_t& b_d,
                        const uint64_t& b_dd, const uint64_t& a_uv, const uint64_t& a_d, const uint64_t& a_dd,
                        Stage& stage) {
  uint64_t h0, h1, h2, h3, l0, l1, l2, l3, x = 0;
  if constexpr (J < 8 && kCurve) {
    // Second order, two chains (fewer registers): c0 = uv_k, c1 = uv_{k+1} (k = 4 g), each
    // stepped two pixels by e0, e1 (uv_{k+2} - uv_k), each e by dd = 4 dduv.
    uint64_t t0, t1;
    __asm__ volatile(
        "lsr %[h0], %[c0], #48\n\t"
        "lsr %w[l0], %w[c0], #16\n\t"
        "add %[t0], %[c0], %[e0]\n\t"
        "add %[t1], %[c1], %[e1]\n\t"
        "lsr %[h1], %[c1], #48\n\t"
        "lsr %w[l1], %w[c1], #16\n\t"
        "add %[e0], %[e0], %[dd]\n\t"
        "add %[e1], %[e1], %[dd]\n\t"
        "lsr %[h2], %[t0], #48\n\t"
        "lsr %w[l2], %w[t0], #16\n\t"
        "lsr %[h3], %[t1], #48\n\t"
        "lsr %w[l3], %w[t1], #16\n\t"
        "add %[c0], %[t0], %[e0]\n\t"
        "add %[c1], %[t1], %[e1]\n\t"
        "add %[e0], %[e0], %[dd]\n\t"
        "add %[e1], %[e1], %[dd]"
        : [h0] "=&r"(h0), [h1] "=&r"(h1), [h2] "=&r"(h2), [h3] "=&r"(h3), [l0] "=&r"(l0), [l1] "=&r"(l1),
          [l2] "=&r"(l2), [l3] "=&r"(l3), [t0] "=&r"(t0), [t1] "=&r"(t1), [c0] "+r"(c0), [c1] "+r"(c1),
          [e0] "+r"(e), [e1] "+r"(e1)
        : [dd] "r"(dd4));
  } else if constexpr (J < 8) {
    __asm__ volatile(
        "lsr %[h0], %[c0], #48\n\t"
        "lsr %w[l0], %w[c0], #16\n\t"
        "lsr %[h1], %[c1], #48\n\t"
        "lsr %w[l1], %w[c1], #16\n\t"
        "lsr %[h2], %[c2], #48\n\t"
        "lsr %w[l2], %w[c2], #16\n\t"
        "lsr %[h3], %[c3], #48\n\t"
        "lsr %w[l3], %w[c3], #16\n\t"
        "add %[c0], %[c0], %[e]\n\t"
        "add %[c1], %[c1], %[e]\n\t"
        "add %[c2], %[c2], %[e]\n\t"
        "add %[c3], %[c3], %[e]"
        : [h0] "=&r"(h0), [h1] "=&r"(h1), [h2] "=&r"(h2), [h3] "=&r"(h3), [l0] "=&r"(l0), [l1] "=&r"(l1),
          [l2] "=&r"(l2), [l3] "=&r"(l3), [c0] "+r"(c0), [c1] "+r"(c1), [c2] "+r"(c2), [c3] "+r"(c3)
        : [e] "r"(e));
  }
  if constexpr (J >= 3) {
    uint64_t n0, n1;
    __asm__ volatile(
        "orr %[x], %[g0], %[g1], lsl #16\n\t"
        "orr %[n0], %[b0], %[b1], lsl #8\n\t"
        "orr %[n1], %[b2], %[b3], lsl #8"
        : [x] "=&r"(x), [n0] "=&r"(n0), [n1] "=&r"(n1)
        : [g0] "r"(g0), [g1] "r"(g1), [b0] "r"(b0), [b1] "r"(b1), [b2] "r"(b2), [b3] "r"(b3));
    g0 = n0, g1 = n1;
  } else if constexpr (J == 2) {
    __asm__ volatile(
        "orr %[g0], %[b0], %[b1], lsl #8\n\t"
        "orr %[g1], %[b2], %[b3], lsl #8"
        : [g0] "=&r"(g0), [g1] "=&r"(g1)
        : [b0] "r"(b0), [b1] "r"(b1), [b2] "r"(b2), [b3] "r"(b3));
  }
  stage(std::integral_constant<int, 2 * J>{});
  if constexpr (J == 0) {
    __asm__ volatile(
        "madd %w[h0], %w[h0], %w[w], %w[l0]\n\t"
        "madd %w[h1], %w[h1], %w[w], %w[l1]\n\t"
        "madd %w[h2], %w[h2], %w[w], %w[l2]\n\t"
        "madd %w[h3], %w[h3], %w[w], %w[l3]"
        : [h0] "+r"(h0), [h1] "+r"(h1), [h2] "+r"(h2), [h3] "+r"(h3)
        : [l0] "r"(l0), [l1] "r"(l1), [l2] "r"(l2), [l3] "r"(l3), [w] "r"(w));
  } else if constexpr (J < 8) {
    __asm__ volatile(
        "madd %w[h0], %w[h0], %w[w], %w[l0]\n\t"
        "ldrb %w[p0], [%[tx], %w[p0], uxtw]\n\t"
        "madd %w[h1], %w[h1], %w[w], %w[l1]\n\t"
        "ldrb %w[p1], [%[tx], %w[p1], uxtw]\n\t"
        "madd %w[h2], %w[h2], %w[w], %w[l2]\n\t"
        "ldrb %w[p2], [%[tx], %w[p2], uxtw]\n\t"
        "madd %w[h3], %w[h3], %w[w], %w[l3]\n\t"
        "ldrb %w[p3], [%[tx], %w[p3], uxtw]"
        : [h0] "+r"(h0), [h1] "+r"(h1), [h2] "+r"(h2), [h3] "+r"(h3), [p0] "+r"(pa0), [p1] "+r"(pa1),
          [p2] "+r"(pa2), [p3] "+r"(pa3)
        : [l0] "r"(l0), [l1] "r"(l1), [l2] "r"(l2), [l3] "r"(l3), [w] "r"(w), [tx] "r"(texels));
  } else if constexpr (J == 8) {
    __asm__ volatile(
        "ldrb %w[p0], [%[tx], %w[p0], uxtw]\n\t"
        "ldrb %w[p1], [%[tx], %w[p1], uxtw]\n\t"
        "ldrb %w[p2], [%[tx], %w[p2], uxtw]\n\t"
        "ldrb %w[p3], [%[tx], %w[p3], uxtw]"
        : [p0] "+r"(pa0), [p1] "+r"(pa1), [p2] "+r"(pa2), [p3] "+r"(pa3)
        : [tx] "r"(texels));
  }
  if constexpr (J >= 3) {
    __asm__ volatile("str %w[x], %[m]" : [m] "=m"(*reinterpret_cast<uint32_t*>(dest + 4 * (J - 3))) : [x] "r"(x));
  }
  if constexpr (J == 9) {
    __asm__ volatile(
        "orr %[x], %[g0], %[g1], lsl #16\n\t"
        "str %w[x], %[m]"
        : [x] "=&r"(x), [m] "=m"(*reinterpret_cast<uint32_t*>(dest + 28))
        : [g0] "r"(g0), [g1] "r"(g1));
  }
  stage(std::integral_constant<int, 2 * J + 1>{});
  if constexpr (J == 3) {
    if constexpr (kCurve) {
      lin_start2(c0, c1, e, e1, dd4, b_uv, b_d, b_dd);
    } else {
      lin_start(c0, c1, c2, c3, e, b_uv, b_d);
    }
  }
  if constexpr (J == 7) {
    if constexpr (kCurve) {
      lin_start2(c0, c1, e, e1, dd4, a_uv, a_d, a_dd);
    } else {
      lin_start(c0, c1, c2, c3, e, a_uv, a_d);
    }
  }
  if constexpr (J >= 1 && J <= 8) b0 = pa0, b1 = pa1, b2 = pa2, b3 = pa3;
  if constexpr (J < 8) pa0 = h0, pa1 = h1, pa2 = h2, pa3 = h3;
}
#endif

// run_steps of a last run (steps = 0 .. 15) for u and v without branches or integer
// divides. With q = double(delta) / steps (the walker's quotient; on aarch64 by div_steps,
// no divide instruction): linear = trunc(q) (= delta / steps truncated: |delta| < 2^31,
// and a non-integer quotient lies over 1 / steps from an integer, far above the rounding
// error),
// ddf = -2 (q curve), dd = trunc(ddf) when |ddf| < 1e9, else linear. Mirrored to delta >= 0
// as in steps16_dd (pd = |delta|, dd' = dd mirrored, T = steps (steps - 1) / 2,
// num = pd - T dd'): the walker accepts iff num >= 0 and floor(num / steps) +
// (steps - 1) dd' >= 0 (the reach test is implied: reach' = (steps / 2) (d0' + last_step)
// >= 0 and reach' = pd - (num mod steps) <= pd; for num < 0, d0' < 0, or d0' = 0 and
// reach' = pd - num > pd), that is iff T |dd| <= pd (dd' >= 0: num >= 0; dd' < 0:
// num >= 2 T |dd'|). d0' = floor(num / steps) without dividing: with pd = steps Q + r
// (Q = |linear|) and m = (steps - 1) dd' = 2 k + b (b = 0, 1), num / steps =
// Q - k - b / 2 + r / steps, so d0' = Q - k - (b and 2 r < steps); accepted, |m| <= pd and
// every value fits 32 bits. steps < 2: linear, dd = 0 (T = 0, dd forced 0). steps = 0 (a
// one-pixel last run): the steps are never used (draw_run draws the start only).
// Where the tails use it (ARM; x86-64: run_steps_uv, out of order cores hide its branches).
#if defined(__aarch64__) || defined(__arm__)
constexpr bool kLastSteps = true;
#else
constexpr bool kLastSteps = false;
#endif
#if defined(__aarch64__)
// [a, b] / s correctly rounded without a divide, for integers |a|, |b| < 2^31 and
// 1 <= s <= 16: y = RN(1/s) (a table), q0 = RN(a y), e = a - s q0 (fmsub), q = RN(q0 + e y)
// (fmadd). Proof, x = a / s: |s y - 1| <= u = 2^-53 and |q0 - a y| <= u |a y|, so
// |q0 - x| <= 2.1 u |x| < 2.1 ulp(x). e is exact: a and s q0 are multiples of
// ulp(q0) <= 2^-21 (|q0| <= 2^31), and |e| <= s |x - q0| < 34 ulp(x) <= 68 ulp(q0). Then
// q0 + e y = x + (x - q0)(s y - 1) = x + eta, |eta| < 2.1 ulp(x) 2^-53, rounded once.
// A midpoint m = M 2^F between doubles near x (M odd, 2^F >= ulp(x) / 4) is never x (x
// dyadic has <= 31 significant bits) and |x - m| = |a 2^-F - s M| 2^F / s >= 2^F / 16 >
// |eta| (a nonzero integer times 2^F / s): no midpoint between x and x + eta, so
// RN(x + eta) = RN(x). s a power of two: y exact, e = 0, q = q0. a = 0: +0, as a / s.
// (AsmSpanPersp.StepQuotientWithoutDivide checks the same operations on boundaries and
// random inputs.)
constexpr double kRecipSteps[17] = {0.0,      1.0 / 1,  1.0 / 2,  1.0 / 3,  1.0 / 4,  1.0 / 5,
                                    1.0 / 6,  1.0 / 7,  1.0 / 8,  1.0 / 9,  1.0 / 10, 1.0 / 11,
                                    1.0 / 12, 1.0 / 13, 1.0 / 14, 1.0 / 15, 1.0 / 16};
SB_INLINE float64x2_t div_steps(float64x2_t a, uint32_t s) {
  const float64x2_t y = vld1q_dup_f64(&kRecipSteps[s]);
  const float64x2_t q0 = vmulq_f64(a, y);
  const float64x2_t e = vfmsq_f64(a, q0, vdupq_n_f64(double(s)));
  return vfmaq_f64(q0, e, y);
}
#endif
SB_INLINE RunSteps last_dd(int32_t delta, int32_t linear, int32_t ddi, uint32_t s, uint32_t T) {
  const uint32_t sg = uint32_t(delta >> 31);
  const uint32_t pd = (uint32_t(delta) ^ sg) - sg, pdd = (uint32_t(ddi) ^ sg) - sg;
  const uint32_t sd = uint32_t(ddi >> 31), add = (uint32_t(ddi) ^ sd) - sd;
  // T |dd| <= pd as a mask (a comparison would compile to a branch): T |dd| < 2^38.
  const uint32_t accept = uint32_t(~((int64_t(pd) - int64_t(uint64_t(add) * T)) >> 63));
  const uint32_t Q = (uint32_t(linear) ^ sg) - sg, r = pd - s * Q;
  const uint32_t m = (s - 1) * pdd;
  const uint32_t d0 = Q - uint32_t(int32_t(m) >> 1) - (m & uint32_t(2 * r < s));
  const uint32_t d = ((d0 ^ sg) - sg) & accept;
  return RunSteps{int32_t(d | (uint32_t(linear) & ~accept)), int32_t(uint32_t(ddi) & accept)};
}
#if defined(__aarch64__)
// du = b.u - a.u, dv = b.v - a.v (0 <= u, v < 2^31: no overflow), also as doubles [du, dv].
SB_INLINE void last_steps(int steps, int32_t du, int32_t dv, float64x2_t duv, double curve, RunSteps* su,
                          RunSteps* sv) {
#else
SB_INLINE void last_steps(int steps, int32_t du, int32_t dv, double curve, RunSteps* su, RunSteps* sv) {
#endif
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  const uint32_t two = steps > 1 ? ~0u : 0u;
#if defined(__aarch64__)
  const float64x2_t q = div_steps(duv, s);
  const int64x2_t lin = vcvtq_s64_f64(q);
  const float64x2_t ddf = vmulq_n_f64(vmulq_n_f64(q, curve), -2.0);
  // -1e9 < ddf < 1e9 as |ddf| < 1e9 (facgt; false for NaN, as both compares).
  const uint64x2_t ok = vcaltq_f64(ddf, vdupq_n_f64(1e9));
  const int64x2_t dd = vandq_s64(vcvtq_s64_f64(ddf), vreinterpretq_s64_u64(ok));
  const int32_t lu = int32_t(vgetq_lane_s64(lin, 0)), lv = int32_t(vgetq_lane_s64(lin, 1));
  const int32_t du2 = int32_t(vgetq_lane_s64(dd, 0)), dv2 = int32_t(vgetq_lane_s64(dd, 1));
#else
  const double qu = double(du) / double(int(s)), qv = double(dv) / double(int(s));
  const int32_t lu = int32_t(qu), lv = int32_t(qv);
  const double fu = -2.0 * (qu * curve), fv = -2.0 * (qv * curve);
  const int32_t du2 = cvt_sat(fu) & -int32_t(fu > -1e9 && fu < 1e9), dv2 = cvt_sat(fv) & -int32_t(fv > -1e9 && fv < 1e9);
#endif
#if defined(__aarch64__)
  // last_dd for u and v in one asm block, the two chains interleaved (the compiler runs
  // them one after the other; on an in-order core each step waits for the previous one).
  // Per lane, as last_dd: sg, pd, add, Q, pdd; acc = pd - add T (umsubl, 64-bit), rejected
  // iff acc < 0 (~accept); r = pd - s Q, m = (s - 1) pdd, c = 2 r < s; d0 = Q - (m >> 1) -
  // (m & c); d = rejected ? linear : (d0 ^ sg) - sg, dd = rejected ? 0 : ddi (csel).
  int32_t xu = du, xv = dv, lu_ = lu, lv_ = lv, ddu = du2 & int32_t(two), ddv = dv2 & int32_t(two);
  const uint32_t sm1 = s - 1;
  uint64_t ga, gb, a1, b1, a2, b2, a3, b3, a4, b4;
  __asm__(
      "asr %w[ga], %w[xu], #31\n\t"
      "asr %w[gb], %w[xv], #31\n\t"
      "asr %w[a1], %w[ddu], #31\n\t"
      "asr %w[b1], %w[ddv], #31\n\t"
      "eor %w[a2], %w[xu], %w[ga]\n\t"
      "eor %w[b2], %w[xv], %w[gb]\n\t"
      "eor %w[a3], %w[ddu], %w[a1]\n\t"
      "eor %w[b3], %w[ddv], %w[b1]\n\t"
      "eor %w[a4], %w[lu], %w[ga]\n\t"
      "eor %w[b4], %w[lv], %w[gb]\n\t"
      "sub %w[a2], %w[a2], %w[ga]\n\t"
      "sub %w[b2], %w[b2], %w[gb]\n\t"
      "sub %w[a3], %w[a3], %w[a1]\n\t"
      "sub %w[b3], %w[b3], %w[b1]\n\t"
      "eor %w[a1], %w[ddu], %w[ga]\n\t"
      "eor %w[b1], %w[ddv], %w[gb]\n\t"
      "sub %w[a4], %w[a4], %w[ga]\n\t"
      "sub %w[b4], %w[b4], %w[gb]\n\t"
      "sub %w[a1], %w[a1], %w[ga]\n\t"
      "sub %w[b1], %w[b1], %w[gb]\n\t"
      "umsubl %[a3], %w[a3], %w[T], %[a2]\n\t"
      "umsubl %[b3], %w[b3], %w[T], %[b2]\n\t"
      "msub %w[xu], %w[s], %w[a4], %w[a2]\n\t"
      "msub %w[xv], %w[s], %w[b4], %w[b2]\n\t"
      "mul %w[a1], %w[sm1], %w[a1]\n\t"
      "mul %w[b1], %w[sm1], %w[b1]\n\t"
      "cmp %w[s], %w[xu], lsl #1\n\t"
      "cset %w[xu], hi\n\t"
      "cmp %w[s], %w[xv], lsl #1\n\t"
      "cset %w[xv], hi\n\t"
      "sub %w[a4], %w[a4], %w[a1], asr #1\n\t"
      "sub %w[b4], %w[b4], %w[b1], asr #1\n\t"
      "and %w[xu], %w[xu], %w[a1]\n\t"
      "and %w[xv], %w[xv], %w[b1]\n\t"
      "sub %w[a4], %w[a4], %w[xu]\n\t"
      "sub %w[b4], %w[b4], %w[xv]\n\t"
      "eor %w[a4], %w[a4], %w[ga]\n\t"
      "eor %w[b4], %w[b4], %w[gb]\n\t"
      "cmp %[a3], #0\n\t"
      "sub %w[a4], %w[a4], %w[ga]\n\t"
      "csel %w[ddu], wzr, %w[ddu], lt\n\t"
      "sub %w[b4], %w[b4], %w[gb]\n\t"
      "csel %w[lu], %w[lu], %w[a4], lt\n\t"
      "cmp %[b3], #0\n\t"
      "csel %w[ddv], wzr, %w[ddv], lt\n\t"
      "csel %w[lv], %w[lv], %w[b4], lt"
      : [xu] "+&r"(xu), [xv] "+&r"(xv), [lu] "+&r"(lu_), [lv] "+&r"(lv_), [ddu] "+&r"(ddu), [ddv] "+&r"(ddv),
        [ga] "=&r"(ga), [gb] "=&r"(gb), [a1] "=&r"(a1), [b1] "=&r"(b1), [a2] "=&r"(a2), [b2] "=&r"(b2),
        [a3] "=&r"(a3), [b3] "=&r"(b3), [a4] "=&r"(a4), [b4] "=&r"(b4)
      : [s] "r"(s), [T] "r"(T), [sm1] "r"(sm1)
      : "cc");
  *su = RunSteps{lu_, ddu};
  *sv = RunSteps{lv_, ddv};
#else
  *su = last_dd(du, lu, du2 & int32_t(two), s, T);
  *sv = last_dd(dv, lv, dv2 & int32_t(two), s, T);
#endif
}
SB_INLINE void last_steps(int steps, const Sample& a, const Sample& b, double curve, RunSteps* su, RunSteps* sv) {
  const int32_t du = b.u - a.u, dv = b.v - a.v;  // 0 <= u, v < 2^31: no overflow
#if defined(__aarch64__)
  last_steps(steps, du, dv, vcvtq_f64_s64(vmovl_s32(vcreate_s32(uint64_t(uint32_t(dv)) << 32 | uint32_t(du)))), curve,
             su, sv);
#else
  last_steps(steps, du, dv, curve, su, sv);
#endif
}

#if defined(__aarch64__)
// aarch64, short spans (17 .. kShortMax pixels: 2 .. 4 runs): every sample's position,
// depth and divide first (two 2-lane divides and one scalar, back to back), the conversions
// and the full runs' steps in vectors, the last run's by last_steps, all branch-free, then
// the runs drawn straight (pairs of full runs as one lin_slot pass). Positions as the walker
// computes them: P_j = P_{j-1} + 16 (run j's first pixel), sample 1 at P_0 + 16 = P_1,
// sample j + 2 at P_j + min(32, n - 16 j - 1) (16 + end_offset of the pixels after run j).
// Samples past the last one (j > runs) are computed but unused; for a one-pixel last run
// the last sample is unused too (steps 0 whatever the samples: run_steps). Each lane is
// the long-span vector code's operation (see persp_fast): the same bits.
constexpr int kShortMax = 64;
alignas(16) constexpr uint32_t kShortConsts[8] = {120, 120, 120, 120, 1u << 25, 1u << 25, 1u << 25, 1u << 25};
template <bool kCurve>
void persp_short(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  const double zc = p.second_order ? p.dzi : 0.0;
  const uint32_t w = uint32_t(width);
  const int runs = (n + 15) >> 4, last = n - 16 * (runs - 1);
  // One asm block, each operation the vector code's lane operation (the same bits):
  // positions P_0, P_1 = P_0 + 16 ([P_0, P_1] = pA), pB = pA + [o_0, o_1], pC = (P_1 + 16)
  // + o_2 with o_j = min(32, n - 16 j - 1); zi = zrow + zix pos (fmla, fmadd); the [u, v]
  // products uvrow + uvx pos before the divides 1 / max(zi, kMinZi) (two 2-lane and one
  // scalar, back to back), then the samples: fcvtzs #16 of (uv z), sqxtn, clamps to [0, max]
  // (persp_fast's argument). Two samples per vector: S01 = [u_0, v_0, u_1, v_1], S23, S44
  // (sample 4 twice). Ordered for the in-order A53 (a consumer after its producer's latency;
  // its model also completes in order, so the first divide's inputs come first); the
  // accumulators are loaded (ld1r, ld2), not copied, and pA, o are merged with trn1 (A72:
  // latency 3, an element insert 8).
  register float64x2_t rzA __asm__("v26");
  register float64x2_t rzB __asm__("v27");
  register float64x2_t rzC __asm__("v4");
  register int32x4_t rS01 __asm__("v5");
  register int32x4_t rS23 __asm__("v6");
  register int32x4_t rS44 __asm__("v7");
  uint64_t t0, t5, t6, t7;
  __asm__ volatile(
      "fmov d1, #16.0\n\t"
      "ldr d0, [%[p], #48]\n\t"
      "sub %w[t5], %w[n], #1\n\t"
      "ld2r {v16.2d, v17.2d}, [%[p]]\n\t"
      "sub %w[t6], %w[n], #17\n\t"
      "mov %w[t7], #32\n\t"
      "cmp %w[t5], #32\n\t"
      "add %[t0], %[p], #16\n\t"
      "fadd d2, d0, d1\n\t"
      "csel %w[t5], %w[t5], %w[t7], lt\n\t"
      "cmp %w[t6], #32\n\t"
      "ld1r {v26.2d}, [%[p]]\n\t"
      "ld1r {v31.2d}, [%[km]]\n\t"
      "csel %w[t6], %w[t6], %w[t7], lt\n\t"
      "scvtf d4, %w[t5]\n\t"
      "sub %w[t7], %w[n], #33\n\t"
      "scvtf d5, %w[t6]\n\t"
      "ld2 {v18.2d, v19.2d}, [%[t0]]\n\t"
      "trn1 v0.2d, v0.2d, v2.2d\n\t"
      "fadd d3, d2, d1\n\t"
      "scvtf d6, %w[t7]\n\t"
      "ld1r {v27.2d}, [%[p]]\n\t"
      "trn1 v4.2d, v4.2d, v5.2d\n\t"
      "ld2 {v20.2d, v21.2d}, [%[t0]]\n\t"
      "fmla v26.2d, v17.2d, v0.2d\n\t"
      "fadd v7.2d, v0.2d, v4.2d\n\t"
      "fmla v18.2d, v19.2d, v0.d[0]\n\t"
      "fadd d3, d3, d6\n\t"
      "ld2 {v22.2d, v23.2d}, [%[t0]]\n\t"
      "fmla v20.2d, v21.2d, v0.d[1]\n\t"
      "fmla v27.2d, v17.2d, v7.2d\n\t"
      "fmadd d28, d17, d3, d16\n\t"
      "fmov v1.2d, #1.0\n\t"
      "ld2 {v24.2d, v25.2d}, [%[t0]]\n\t"
      "fmaxnm v26.2d, v26.2d, v31.2d\n\t"
      "fmla v22.2d, v23.2d, v7.d[0]\n\t"
      "fmla v24.2d, v25.2d, v7.d[1]\n\t"
      "ld2 {v29.2d, v30.2d}, [%[t0]]\n\t"
      "fdiv v26.2d, v1.2d, v26.2d\n\t"
      "fmaxnm v27.2d, v27.2d, v31.2d\n\t"
      "fmaxnm d28, d28, d31\n\t"
      "add %[t0], %[p], #56\n\t"
      "fdiv v27.2d, v1.2d, v27.2d\n\t"
      "fmla v29.2d, v30.2d, v3.d[0]\n\t"
      "fdiv d28, d1, d28\n\t"
      "ld1r {v31.2d}, [%[t0]]\n\t"
      "movi v2.4s, #0\n\t"
      "fmul v18.2d, v18.2d, v26.d[0]\n\t"
      "fmul v20.2d, v20.2d, v26.d[1]\n\t"
      "fmul v22.2d, v22.2d, v27.d[0]\n\t"
      "fmul v24.2d, v24.2d, v27.d[1]\n\t"
      "fmul v29.2d, v29.2d, v28.d[0]\n\t"
      "fcvtzs v18.2d, v18.2d, #16\n\t"
      "fcvtzs v20.2d, v20.2d, #16\n\t"
      "fcvtzs v22.2d, v22.2d, #16\n\t"
      "fcvtzs v24.2d, v24.2d, #16\n\t"
      "fcvtzs v29.2d, v29.2d, #16\n\t"
      "sqxtn v5.2s, v18.2d\n\t"
      "sqxtn v6.2s, v22.2d\n\t"
      "sqxtn v7.2s, v29.2d\n\t"
      "dup v4.2d, v28.d[0]\n\t"
      "sqxtn2 v5.4s, v20.2d\n\t"
      "sqxtn2 v6.4s, v24.2d\n\t"
      "sqxtn2 v7.4s, v29.2d\n\t"
      "smax v5.4s, v5.4s, v2.4s\n\t"
      "smax v6.4s, v6.4s, v2.4s\n\t"
      "smax v7.4s, v7.4s, v2.4s\n\t"
      "smin v5.4s, v5.4s, v31.4s\n\t"
      "smin v6.4s, v6.4s, v31.4s\n\t"
      "smin v7.4s, v7.4s, v31.4s"
      : "=&w"(rzA), "=&w"(rzB), "=&w"(rzC), "=&w"(rS01), "=&w"(rS23), "=&w"(rS44), [t0] "=&r"(t0), [t5] "=&r"(t5),
        [t6] "=&r"(t6), [t7] "=&r"(t7)
      : [p] "r"(&p), [n] "r"(n), [km] "r"(&kMinZi), "m"(p), "m"(kMinZi)
      : "cc", "v0", "v1", "v2", "v3", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25",
        "v28", "v29", "v30", "v31");
  const float64x2_t zA = rzA, zB = rzB, zC = rzC;
  const int32x4_t S01 = rS01, S23 = rS23, S44 = rS44;
  // Sums of neighbouring samples' z: [z_0 + z_1, z_1 + z_2], [z_2 + z_3, z_3 + z_4] (the
  // curve factors' and the last run's z_k + z_{k+1}).
  const float64x2_t zs01 = vaddq_f64(zA, vextq_f64(zA, zB, 1)), zs23 = vaddq_f64(zB, vextq_f64(zB, zC, 1));
  using L0 = std::integral_constant<int, 0>;
  using L1 = std::integral_constant<int, 1>;
  const int32x4_t kZero = vdupq_n_s32(0);
  // The rest for k = runs - 1 (1, 2, 3) as a constant: the last run's samples and deltas
  // picked without an index. The branch also ends the code block holding the asm block
  // soon after it (under 128 micro-ops: the A72 model's reorder buffer then holds the next
  // span's positions while the divides run).
  auto rest = [&](auto kc) SB_LAMBDA_INLINE {
    constexpr int k = decltype(kc)::value;
    // Full runs 0, 1, 2: deltas [du_0, dv_0, du_1, dv_1], [du_2, dv_2, -, -].
    const int32x4_t D01 = vsubq_s32(vextq_s32(S01, S23, 2), S01);
    const int32x4_t D23 = vsubq_s32(vextq_s32(S23, S44, 2), S23);
    int32x4_t d01, d23, dd01 = kZero, dd23 = kZero;
    // Deltas as doubles without scvtf (A72 latency 10): the int64 2^52 + 2^51 + x (saddw,
    // |x| < 2^31) is that double's bits, exactly (ulp 1 in [2^52, 2^53)); minus 2^52 + 2^51
    // it is x exactly (x = 0: +0, as scvtf).
    const int64x2_t kBias = vdupq_n_s64(0x4338000000000000);
    // [120 x 4], [2^25 x 4] by one ldp (the load pipe; movi takes FP-pipe slots).
    uint32x4_t k120, k2p25;
    __asm__("ldp %q[k], %q[m], [%[c]]" : [k] "=w"(k120), [m] "=w"(k2p25) : [c] "r"(kShortConsts), "m"(kShortConsts));
    auto unbias = [&](int64x2_t b) SB_LAMBDA_INLINE {
      return vsubq_f64(vreinterpretq_f64_s64(b), vreinterpretq_f64_s64(kBias));
    };
    if constexpr (kCurve) {
      // ddf = delta (zck (z_a + z_b)), zck = zc * -1/16: steps16_sel's bits (see persp_fast);
      // cvt_sat as fcvtzs to int64 then sqxtn (both saturating, NaN -> 0: the same int32).
      const double zck = zc * -0.0625;
      const float64x2_t c01 = vmulq_n_f64(zs01, zck);
      const float64x2_t c23 = vmulq_n_f64(zs23, zck);
      auto ddf = [&](int64x2_t b, float64x2_t c, auto lane) SB_LAMBDA_INLINE {
        return vcvtq_s64_f64(vmulq_laneq_f64(unbias(b), c, decltype(lane)::value));
      };
      const int32x4_t i01 = vqmovn_high_s64(vqmovn_s64(ddf(vaddw_s32(kBias, vget_low_s32(D01)), c01, L0{})),
                                            ddf(vaddw_high_s32(kBias, D01), c01, L1{}));
      const int32x4_t i23 =
          vcombine_s32(vqmovn_s64(ddf(vaddw_s32(kBias, vget_low_s32(D23)), c23, L0{})), vdup_n_s32(0));
      // steps16_dd (the 32-bit form) per lane; 120 |dd| <= pd tested as min(|dd|, 2^25) 120
      // <= pd in uint32 (no wrap: 120 2^25 < 2^32; |dd| >= 2^25 rejects either way, as
      // 120 2^25 > 2^31 > pd).
      auto steps_dd = [&](int32x4_t delta, int32x4_t dd, int32x4_t* d_out, int32x4_t* dd_out) SB_LAMBDA_INLINE {
        const uint32x4_t s = vreinterpretq_u32_s32(vshrq_n_s32(delta, 31));
        // |x| as (x ^ s) - s (s = x >> 31) is abs (wrapping: INT_MIN stays 0x80000000).
        const uint32x4_t pd = vreinterpretq_u32_s32(vabsq_s32(delta));
        const uint32x4_t pdd = vsubq_u32(veorq_u32(vreinterpretq_u32_s32(dd), s), s);
        const uint32x4_t add = vreinterpretq_u32_s32(vabsq_s32(dd));
        const uint32x4_t accept = vcleq_u32(vmulq_u32(vminq_u32(add, k2p25), k120), pd);
        // (pd - 120 pdd) >> 4 or pd >> 4: picked, then shifted (the same logical shift).
        const uint32x4_t pick = vshrq_n_u32(vbslq_u32(accept, vmlsq_laneq_u32(pd, pdd, k120, 0), pd), 4);
        *d_out = vreinterpretq_s32_u32(vsubq_u32(veorq_u32(pick, s), s));
        *dd_out = vreinterpretq_s32_u32(vandq_u32(vreinterpretq_u32_s32(dd), accept));
      };
      steps_dd(D01, i01, &d01, &dd01);
      steps_dd(D23, i23, &d23, &dd23);
    } else {
      // delta / 16 truncated: (delta + (delta < 0 ? 15 : 0)) >> 4.
      auto div16 = [](int32x4_t x) SB_LAMBDA_INLINE {
        return vshrq_n_s32(vreinterpretq_s32_u32(vsraq_n_u32(vreinterpretq_u32_s32(x),
                                                             vreinterpretq_u32_s32(vshrq_n_s32(x, 31)), 28)), 4);
      };
      d01 = div16(D01), d23 = div16(D23);
    }
    // The full runs' packed starts (a sample's [u, v] lane pair is v 2^32 + u) and steps
    // (sign-extended du plus dv 2^32: Run16's packing, modulo 2^64), for runs 0, 1 and 2, 3.
    auto packs = [](int32x4_t x01, int32x4_t x23, int64x2_t* lo, int64x2_t* hi) SB_LAMBDA_INLINE {
      const int32x4_t U = vuzp1q_s32(x01, x23), V = vuzp2q_s32(x01, x23);
      *lo = vaddq_s64(vmovl_s32(vget_low_s32(U)), vshll_n_s32(vget_low_s32(V), 32));
      *hi = vaddq_s64(vmovl_high_s32(U), vshll_high_n_s32(V, 32));
    };
    int64x2_t dlo, dhi, ddlo, ddhi;
    packs(d01, d23, &dlo, &dhi);
    packs(dd01, dd23, &ddlo, &ddhi);
    const uint64x2_t st01 = vreinterpretq_u64_s32(S01), st23 = vreinterpretq_u64_s32(S23);
    int32_t sm[8];
    double zm[4];
    vst1q_s32(sm, S01), vst1q_s32(sm + 4, S23);
    vst1q_f64(zm, zs01), vst1q_f64(zm + 2, zs23);
    const int32_t au = sm[2 * k], av = sm[2 * k + 1];
    RunSteps lu, lv;
    // The last run's deltas from D01, D23 (lanes 2 k - 2, 2 k - 1 of the pair) as doubles
    // (unbias) and as integers: one 64-bit lane move (dv 2^32 + du), split in the integer unit.
    const float64x2_t fd = unbias(k == 1 ? vaddw_high_s32(kBias, D01)
                                         : (k == 2 ? vaddw_s32(kBias, vget_low_s32(D23)) : vaddw_high_s32(kBias, D23)));
    const uint64_t dk = vgetq_lane_u64(vreinterpretq_u64_s32(k == 1 ? D01 : D23), k == 2 ? 0 : 1);
    last_steps(last - 1, int32_t(uint32_t(dk)), int32_t(dk >> 32), fd, zc * 0.5 * zm[k], &lu, &lv);
    auto full = [&](auto jc) SB_LAMBDA_INLINE {
      constexpr int j = decltype(jc)::value, l = j & 1;
      const uint64_t a0 = vgetq_lane_u64(j < 2 ? st01 : st23, l);
      const uint64_t d0 = uint64_t(vgetq_lane_s64(j < 2 ? dlo : dhi, l));
      const uint64_t dd = uint64_t(vgetq_lane_s64(j < 2 ? ddlo : ddhi, l));
      Run16<kCurve> run(a0, d0, dd, typename Run16<kCurve>::Packed{});
      run.draw(dest + 16 * j, texels, w);
    };
    // Two 16-pixel runs as one lin_slot pass (the long spans' pipeline, no stage work).
    auto pass = [&](uint8_t* d, uint64_t a_uv, uint64_t a_d, uint64_t a_dd, uint64_t b_uv, uint64_t b_d,
                    uint64_t b_dd) SB_LAMBDA_INLINE {
      uint64_t c0, c1, c2 = 0, c3 = 0, e, e1 = 0, dd4 = 0;
      uint64_t pa0 = 0, pa1 = 0, pa2 = 0, pa3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0, g0 = 0, g1 = 0;
      if constexpr (kCurve) {
        lin_start2(c0, c1, e, e1, dd4, a_uv, a_d, a_dd);
      } else {
        lin_start(c0, c1, c2, c3, e, a_uv, a_d);
      }
      auto none = [](auto) SB_LAMBDA_INLINE {};
      const uint64_t w64 = uint64_t(width);
      auto slot = [&](auto j) SB_LAMBDA_INLINE {
        lin_slot<decltype(j)::value, kCurve>(c0, c1, c2, c3, e, e1, dd4, pa0, pa1, pa2, pa3, b0, b1, b2, b3, g0, g1,
                                             d, texels, w64, b_uv, b_d, b_dd, a_uv, a_d, a_dd, none);
      };
      using std::integral_constant;
      slot(integral_constant<int, 0>{}), slot(integral_constant<int, 1>{}), slot(integral_constant<int, 2>{});
      slot(integral_constant<int, 3>{}), slot(integral_constant<int, 4>{}), slot(integral_constant<int, 5>{});
      slot(integral_constant<int, 6>{}), slot(integral_constant<int, 7>{}), slot(integral_constant<int, 8>{});
      slot(integral_constant<int, 9>{});
    };
    auto packed = [](const RunSteps& su, const RunSteps& sv) {
      return (uint64_t(uint32_t(sv.d)) << 32) + uint64_t(int64_t(su.d));
    };
    const uint64_t luv = (uint64_t(uint32_t(av)) << 32) + uint32_t(au);
    const uint64_t ld = packed(lu, lv), ldd = (uint64_t(uint32_t(lv.dd)) << 32) + uint64_t(int64_t(lu.dd));
    if (k == 1) {
      full(std::integral_constant<int, 0>{});
    } else {
      pass(dest, vgetq_lane_u64(st01, 0), uint64_t(vgetq_lane_s64(dlo, 0)), uint64_t(vgetq_lane_s64(ddlo, 0)),
           vgetq_lane_u64(st01, 1), uint64_t(vgetq_lane_s64(dlo, 1)), uint64_t(vgetq_lane_s64(ddlo, 1)));
      if (k == 3 && last == 16) {
        pass(dest + 32, vgetq_lane_u64(st23, 0), uint64_t(vgetq_lane_s64(dhi, 0)), uint64_t(vgetq_lane_s64(ddhi, 0)),
             luv, ld, ldd);
        return;
      }
      if (k > 2) full(std::integral_constant<int, 2>{});
    }
    dest += 16 * k;
    if (last == 16) {
      draw16<kCurve>(dest, texels, w, au, av, lu, lv);
    } else {
      draw_run(dest, last, texels, w, uint32_t(au), uint32_t(av), uint32_t(lu.d), uint32_t(lv.d), uint32_t(lu.dd),
               uint32_t(lv.dd));
    }
  };
  if (runs == 2) {
    rest(std::integral_constant<int, 1>{});
  } else if (runs == 3) {
    rest(std::integral_constant<int, 2>{});
  } else {
    rest(std::integral_constant<int, 3>{});
  }
}
#else
constexpr int kShortMax = 16;  // elsewhere the long-span code (its overlap wins there)
template <bool kCurve>
void persp_short(uint8_t*, int, const uint8_t*, int, const PerspSpan&) {}
#endif

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
    if constexpr (kIntClamp) {
      return Sample{to_fixed_int((urow + ux * px) * z, p.umax), to_fixed_int((vrow + vx * px) * z, p.vmax), z};
    } else {
      return Sample{to_fixed_sel((urow + ux * px) * z, umaxd), to_fixed_sel((vrow + vx * px) * z, vmaxd), z};
    }
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
    if constexpr (kCurve && kLastSteps) {
      last_steps(n - 1, s0, s1, curve, &su, &sv);
    } else {
      run_steps_uv(n - 1, s0, s1, curve, &su, &sv);
    }
    if (n == 16) {
      draw16<kCurve>(dest, texels, w, s0.u, s0.v, su, sv);
    } else {
      draw_run(dest, n, texels, w, uint32_t(s0.u), uint32_t(s0.v), uint32_t(su.d), uint32_t(sv.d), uint32_t(su.dd),
               uint32_t(sv.dd));
    }
    return;
  }
  if (n <= kShortMax) return persp_short<kCurve>(dest, n, texels, width, p);
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
#if defined(__aarch64__) && defined(__GNUC__)
  {
    // aarch64: the passes drawn by lin_slot (above); the samples' double arithmetic in
    // 2-lane vectors, each lane the scalar operation above (same bits): [u, v] of
    // one sample per vector, positions, depths and divides as [sample 4, sample 5], the
    // fused forms those of the scalar code (urow + ux * pos, zrow + zix * pos: fmadd).
    // to_fixed in integers: fix(q, m) = min(max(sat32(trunc(q 2^16)), 0), m), with fcvtzs
    // #16 (trunc(q 2^16) exactly, saturating to int64, NaN -> 0: the same as converting
    // the product q * 65536.0, a scaling by 2^16 that is exact or overflows to a saturated
    // value either way) and sqxtn to int32. Equal to to_fixed: NaN and x = q 2^16 <= 0
    // give trunc <= 0 -> 0; for x > m (m an integer >= 0) trunc(x) >= m, kept >= m by the
    // saturations -> m; else 0 < x <= m and trunc(x) fits. A sample's clamped [u, v] in
    // one 64-bit lane is v 2^32 + u: a run's packed start.
    // Pipeline: a pass (runs r, r + 1) finishes samples r + 2, r + 3 (converted a pass
    // earlier), takes the steps of runs r + 1, r + 2 from them, computes the positions and
    // divides of samples r + 4, r + 5 and converts those. Second order: the steps as the
    // loop above takes them (ddf = delta (zck (z_a + z_b))), and only for spans of two
    // passes or more (for one the vector setup costs more than it saves).
    if (left > (kCurve ? 80 : 48)) {
      const float64x2_t kZrow = vdupq_n_f64(zrow), kZix = vdupq_n_f64(zix), kMin = vdupq_n_f64(kMinZi);
      const float64x2_t kUVrow = vcombine_f64(vdup_n_f64(urow), vdup_n_f64(vrow));
      const float64x2_t kUVx = vcombine_f64(vdup_n_f64(ux), vdup_n_f64(vx));
      const float64x2_t k16 = vdupq_n_f64(16.0), k32 = vdupq_n_f64(32.0), kOne = vdupq_n_f64(1.0);
      const int32x2_t kMax = vcreate_s32(uint64_t(uint32_t(p.vmax)) << 32 | uint32_t(p.umax));
      const int32x2_t kZero = vdup_n_s32(0);
      auto pack = [](int32_t hi, int32_t lo) { return (uint64_t(uint32_t(hi)) << 32) + uint64_t(int64_t(lo)); };
      // [P_{r+2}, P_{r+3}] accumulated as the walker does (P_{r+3} = P_{r+2} + 16 exactly
      // as computed, so adding 16 twice to both lanes gives the next pass's pair, bit for
      // bit); [left - 33, left - 49] as doubles (exact integers).
      const double P2i = (P + double(16)) + double(16);
      float64x2_t pp = vcombine_f64(vdup_n_f64(P2i), vdup_n_f64(P2i + double(16)));
      float64x2_t ll = vcombine_f64(vdup_n_f64(double(left - 33)), vdup_n_f64(double(left - 49)));
      float64x2_t z23 = vcombine_f64(vdup_n_f64(z2), vdup_n_f64(z3));
      float64x2_t pos23 = vcombine_f64(vdup_n_f64(pos2), vdup_n_f64(pos3));
      // Samples r + 2, r + 3 converted, narrowed and clamped below (not yet above), as the
      // loop leaves them.
      int32x2_t n2 = vqmovn_s64(vcvtq_n_s64_f64(vmulq_n_f64(vcombine_f64(vdup_n_f64(tu2), vdup_n_f64(tv2)), z2), 16));
      int32x2_t n3 = vqmovn_s64(vcvtq_n_s64_f64(vmulq_n_f64(vcombine_f64(vdup_n_f64(tu3), vdup_n_f64(tv3)), z3), 16));
      n2 = vmax_s32(n2, kZero), n3 = vmax_s32(n3, kZero);
      if constexpr (kCurve) n2 = vmin_s32(n2, kMax), n3 = vmin_s32(n3, kMax);  // second order: clamped above too
      // Second order: the depths [z_r, z_{r+1}] and [z_{r+1}, z_{r+2}].
      float64x2_t zp = vcombine_f64(vdup_n_f64(s0.z), vdup_n_f64(s1.z));
      float64x2_t zs = vcombine_f64(vdup_n_f64(s1.z), vdup_n_f64(z2));
      // Samples r, r + 1 as [u, v] vectors (the tail reads them; few integer registers).
      int32x2_t n0 = vcreate_s32((uint64_t(uint32_t(s0.v)) << 32) + uint32_t(s0.u));
      int32x2_t n1 = vcreate_s32((uint64_t(uint32_t(s1.v)) << 32) + uint32_t(s1.u));
      // lin_slot's state: the chains of the run being addressed, the last group's
      // addresses, the bytes loaded in the last slot, the gathered byte pairs.
      uint64_t c0, c1, c2, c3, e, pa0 = 0, pa1 = 0, pa2 = 0, pa3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0, g0 = 0, g1 = 0;
      uint64_t e1 = 0, dd4 = 0;  // second order: chain 1's step, the steps' step
      if constexpr (kCurve) {
        lin_start2(c0, c1, e, e1, dd4, (uint64_t(uint32_t(s0.v)) << 32) + uint32_t(s0.u), pack(sv.d, su.d),
                   pack(sv.dd, su.dd));
      } else {
        lin_start(c0, c1, c2, c3, e, (uint64_t(uint32_t(s0.v)) << 32) + uint32_t(s0.u), pack(sv.d, su.d));
      }
      const uint64_t w64 = uint64_t(width);
      do {
        int32x2_t n4, n5;
        uint64_t x1p = 0, x2p = 0, x3p = 0;
        uint64_t b_uv = 0, b_d = 0, a_uv = 0, a_d = 0, b_dd = 0, a_dd = 0;
        float64x2_t off, pos45, zi45, z45, ts4, ts5, q4, q5, zsn;
        int64x2_t i4, i5;
        // Second order, runs r + 1, r + 2: deltas, their doubles, the products, dd.
        float64x2_t sum, c;
        int32_t du1 = 0, dv1 = 0, du2 = 0, dv2 = 0, iu1 = 0, iv1 = 0, iu2 = 0, iv2 = 0;
        double fu1 = 0, fv1 = 0, fu2 = 0, fv2 = 0;
        // Second order: the stage, the linear one's vector work (the conversion of samples
        // r + 4, r + 5 done within the pass, so that the next pass starts on clamped samples)
        // and the steps of runs r + 1, r + 2 as steps16_sel computes them (ddf = delta (zck
        // (z_a + z_b)), see above).
        auto stage2 = [&](auto g) SB_LAMBDA_INLINE {
          constexpr int G = decltype(g)::value;
          auto lanes = [](int32x2_t x) { return vget_lane_u64(vreinterpret_u64_s32(x), 0); };
          if constexpr (G == 0) {
            x1p = lanes(n1), x2p = lanes(n2), x3p = lanes(n3);
            sum = vaddq_f64(zs, z23);  // [z_{r+1} + z_{r+2}, z_{r+2} + z_{r+3}]
            off = vminnmq_f64(ll, k32);
            pin(x1p), pin(x2p), pin(x3p), pin(sum), pin(off);
          } else if constexpr (G == 1) {
            du1 = int32_t(x2p) - int32_t(x1p), dv1 = int32_t(x2p >> 32) - int32_t(x1p >> 32);
            du2 = int32_t(x3p) - int32_t(x2p), dv2 = int32_t(x3p >> 32) - int32_t(x2p >> 32);
            pin(du1), pin(dv1), pin(du2), pin(dv2);
            fu2 = double(du2), fv2 = double(dv2);
          } else if constexpr (G == 2) {
            c = vmulq_n_f64(sum, zck);
            fu1 = double(du1), fv1 = double(dv1);
            pos45 = vaddq_f64(pp, off);
            zi45 = kZrow;
            pin(c), pin(fu1), pin(fv1), pin(fu2), pin(fv2), pin(pos45), pin(zi45);
          } else if constexpr (G == 4) {
            const double ca = vgetq_lane_f64(c, 0), cb = vgetq_lane_f64(c, 1);
            fu1 = fu1 * ca, fv1 = fv1 * ca, fu2 = fu2 * cb, fv2 = fv2 * cb;
            zi45 = vfmaq_f64(zi45, kZix, pos45);
            ts4 = kUVrow, ts5 = kUVrow;
            pin(fu1), pin(fv1), pin(fu2), pin(fv2), pin(zi45), pin(ts4), pin(ts5);
          } else if constexpr (G == 6) {
            iu1 = cvt_sat(fu1), iv1 = cvt_sat(fv1);
            zi45 = vmaxnmq_f64(zi45, kMin);
            ts4 = vfmaq_laneq_f64(ts4, kUVx, pos45, 0), ts5 = vfmaq_laneq_f64(ts5, kUVx, pos45, 1);
            pin(iu1), pin(iv1), pin(zi45), pin(ts4), pin(ts5);
          } else if constexpr (G == 7) {
            const RunSteps u1 = steps16_dd(du1, iu1), v1 = steps16_dd(dv1, iv1);
            b_uv = x1p, b_d = pack(v1.d, u1.d), b_dd = pack(v1.dd, u1.dd);
          } else if constexpr (G == 8) {
            z45 = vdivq_f64(kOne, zi45);
            pin(z45);
          } else if constexpr (G == 10) {
            pp = vaddq_f64(pp, k16);
            ll = vsubq_f64(ll, k32);
            q4 = vmulq_laneq_f64(ts4, z45, 0), q5 = vmulq_laneq_f64(ts5, z45, 1);
            pin(pp), pin(ll), pin(q4), pin(q5);
          } else if constexpr (G == 12) {
            pp = vaddq_f64(pp, k16);
            i4 = vcvtq_n_s64_f64(q4, 16), i5 = vcvtq_n_s64_f64(q5, 16);
            x2p = lanes(n2), x3p = lanes(n3);
            iu2 = cvt_sat(fu2), iv2 = cvt_sat(fv2);
            pin(pp), pin(i4), pin(i5), pin(x2p), pin(x3p), pin(iu2), pin(iv2);
          } else if constexpr (G == 13) {
            const int32_t du = int32_t(x3p) - int32_t(x2p), dv = int32_t(x3p >> 32) - int32_t(x2p >> 32);
            const RunSteps u2 = steps16_dd(du, iu2), v2 = steps16_dd(dv, iv2);
            a_uv = x2p, a_d = pack(v2.d, u2.d), a_dd = pack(v2.dd, u2.dd);
            pin(a_d), pin(a_dd);
          } else if constexpr (G == 14) {
            n4 = vqmovn_s64(i4), n5 = vqmovn_s64(i5);
            pin(n4), pin(n5);
          } else if constexpr (G == 16) {
            n4 = vmax_s32(n4, kZero), n5 = vmax_s32(n5, kZero);
            pin(n4), pin(n5);
          } else if constexpr (G == 18) {
            n4 = vmin_s32(n4, kMax), n5 = vmin_s32(n5, kMax);
            zsn = vextq_f64(z23, z45, 1);  // [z_{r+3}, z_{r+4}]
            pin(n4), pin(n5), pin(zsn);
          }
        };
        auto stage = [&](auto g) SB_LAMBDA_INLINE {
          constexpr int G = decltype(g)::value;
          auto lanes = [](int32x2_t x) { return vget_lane_u64(vreinterpret_u64_s32(x), 0); };

          // Even stages (between the shifts and the loads): the vector work, two chains;
          // odd stages: integer work.
          if constexpr (G == 0) {
            n2 = vmin_s32(n2, kMax), n3 = vmin_s32(n3, kMax);
            off = vminnmq_f64(ll, k32);
            pin(n2), pin(n3), pin(off);
          } else if constexpr (G == 2) {
            x1p = lanes(n1), x2p = lanes(n2);
            pos45 = vaddq_f64(pp, off);
            zi45 = kZrow;
            pin(x1p), pin(x2p), pin(pos45), pin(zi45);
          } else if constexpr (G == 3) {
            b_uv = x1p, b_d = steps16_packed(x1p, x2p);
            pin(b_d);
          } else if constexpr (G == 4) {
            zi45 = vfmaq_f64(zi45, kZix, pos45);
            ts4 = kUVrow, ts5 = kUVrow;
            pin(zi45), pin(ts4), pin(ts5);
          } else if constexpr (G == 6) {
            zi45 = vmaxnmq_f64(zi45, kMin);
            ts4 = vfmaq_laneq_f64(ts4, kUVx, pos45, 0), ts5 = vfmaq_laneq_f64(ts5, kUVx, pos45, 1);
            pin(zi45), pin(ts4), pin(ts5);
          } else if constexpr (G == 8) {
            z45 = vdivq_f64(kOne, zi45);
            pin(z45);
          } else if constexpr (G == 10) {
            pp = vaddq_f64(pp, k16);
            ll = vsubq_f64(ll, k32);
            pin(pp), pin(ll);
          } else if constexpr (G == 12) {
            pp = vaddq_f64(pp, k16);
            q4 = vmulq_laneq_f64(ts4, z45, 0), q5 = vmulq_laneq_f64(ts5, z45, 1);
            x2p = lanes(n2), x3p = lanes(n3);
            pin(pp), pin(q4), pin(q5), pin(x2p), pin(x3p);
          } else if constexpr (G == 13) {
            a_uv = x2p, a_d = steps16_packed(x2p, x3p);
            pin(a_d);
          } else if constexpr (G == 14) {
            i4 = vcvtq_n_s64_f64(q4, 16), i5 = vcvtq_n_s64_f64(q5, 16);
            pin(i4), pin(i5);
          } else if constexpr (G == 16) {
            n4 = vqmovn_s64(i4), n5 = vqmovn_s64(i5);
            pin(n4), pin(n5);
          } else if constexpr (G == 18) {
            n4 = vmax_s32(n4, kZero), n5 = vmax_s32(n5, kZero);
            pin(n4), pin(n5);
          }
        };
        auto slot = [&](auto j) SB_LAMBDA_INLINE {
          if constexpr (kCurve) {
            lin_slot<decltype(j)::value, true>(c0, c1, c2, c3, e, e1, dd4, pa0, pa1, pa2, pa3, b0, b1, b2, b3,
                                               g0, g1, dest, texels, w64, b_uv, b_d, b_dd, a_uv, a_d, a_dd, stage2);
          } else {
            lin_slot<decltype(j)::value, false>(c0, c1, c2, c3, e, e1, dd4, pa0, pa1, pa2, pa3, b0, b1, b2, b3,
                                                g0, g1, dest, texels, w64, b_uv, b_d, b_dd, a_uv, a_d, a_dd, stage);
          }
        };
        using std::integral_constant;
        slot(integral_constant<int, 0>{}), slot(integral_constant<int, 1>{}), slot(integral_constant<int, 2>{});
        slot(integral_constant<int, 3>{}), slot(integral_constant<int, 4>{}), slot(integral_constant<int, 5>{});
        slot(integral_constant<int, 6>{}), slot(integral_constant<int, 7>{}), slot(integral_constant<int, 8>{});
        slot(integral_constant<int, 9>{});
        dest += 32;
        left -= 32;
        n0 = n2, n1 = n3, n2 = n4, n3 = n5;
        if constexpr (kCurve) zp = z23, zs = zsn;
        z23 = z45, pos23 = pos45;
      } while (left > 48);
      // The state the tail below reads (it takes no position from P); run r's steps again.
      s0 = Sample{vget_lane_s32(n0, 0), vget_lane_s32(n0, 1), vgetq_lane_f64(zp, 0)};
      s1 = Sample{vget_lane_s32(n1, 0), vget_lane_s32(n1, 1), vgetq_lane_f64(zp, 1)};
      su = steps16<kCurve>(s0.u, s1.u, zc * 0.5 * (s0.z + s1.z));
      sv = steps16<kCurve>(s0.v, s1.v, zc * 0.5 * (s0.z + s1.z));
      z2 = vgetq_lane_f64(z23, 0), z3 = vgetq_lane_f64(z23, 1);
      pos2 = vgetq_lane_f64(pos23, 0), pos3 = vgetq_lane_f64(pos23, 1);
    }
  }
#endif
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
    int32_t iu1 = 0, iv1 = 0, iu2 = 0, iv2 = 0;
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
  if constexpr (kCurve && kLastSteps) {
    last_steps(steps, s1, s2, curve, &lu, &lv);
  } else {
    run_steps_uv(steps, s1, s2, curve, &lu, &lv);
  }
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
