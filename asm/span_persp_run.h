// asm/span_persp_run.h: the whole-span drawer's run helpers (asm/span_persp.h): the run
// steps, the generic run loop, the straight-line 16-pixel run and the branch-free sample
// arithmetic. Internal: included by asm/span_persp_fast.cpp only (anonymous namespace:
// internal linkage, as when this was part of that file).
//
// The double arithmetic must stay operation for operation what asm/span_walk.h's walker
// (the engine's) does: the kernel promises the engine's bytes (tests/asm/span_persp_test.cpp
// checks it). Here the same operations in select form (clamps as max / min, the run-step
// test as masks; each rewrite argued where it is made).
#pragma once
#include <cstdint>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__aarch64__)
#include <arm_neon.h>
#endif

#include "asm/span_persp.h"
#include "asm/span_walk.h"

namespace sb::simd {
namespace {

using span_walk::kMinZi;
using span_walk::run_steps_with;
using span_walk::RunSteps;

// run_steps with the quotient already computed (q = double(b - a) / steps; steps >= 1).
template <class Steps>
inline RunSteps run_steps_q(int32_t a, int32_t b, Steps steps_, double curve, double q) {
  return run_steps_with(a, b, steps_, curve, [q] { return q; });
}

// Run16's packing of a step pair: hi 2^32 + lo sign-extended (modulo 2^64), hi the v part,
// lo the u part (Run16, draw_last and the tuned paths in asm/span_persp_fast.cpp).
inline __attribute__((always_inline)) uint64_t pack_steps(int32_t hi, int32_t lo) {
  return (uint64_t(uint32_t(hi)) << 32) + uint64_t(int64_t(lo));
}

// The packed position: u and v in one 64-bit register, uv = v 2^32 + u, stepped by duv = dv
// 2^32 + du (du sign-extended), itself stepped by ddv 2^32 + ddu. The contract keeps every
// drawn u_k in 0 .. 2^32 - 1 and v_k >= 0, so uv_k is exactly the integer v_k 2^32 + u_k (the
// recurrences are linear: the packed sums are the sums of the packed terms) and its halves
// are u_k and v_k: two adds per pixel instead of four (Run16, draw_last and the passes).

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
// armhf: cvt_sat(q * 65536.0) by one fixed-point vcvt in place (trunc(q 2^16), saturating,
// NaN -> 0; q 2^16 is exact or overflows, and then saturates the same way), its result in
// the register's low 32 bits (fixed16_bits).
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_FP) && (__ARM_FP & 8)
constexpr bool kFixed16 = true;
inline double cvt_fixed16(double q) {
  __asm__("vcvt.s32.f64 %P0, %P0, #16" : "+w"(q));
  return q;
}
// The same clamp without leaving the VFP/NEON register: x = usat32(trunc(q 2^16))
// (vcvt.u32.f64 in place: negatives and NaN -> 0), then min(x, m) unsigned by vmin.u32 on
// the low lane, kmax holding m in its low 32 bits (bound16). Equal to to_fixed: NaN and
// q 2^16 <= 0 give 0 (trunc of (-1, 0] is 0, below saturates to 0); q 2^16 > m (an
// integer) gives x >= m -> m; else 0 < q 2^16 <= m and trunc fits. The result in the low
// 32 bits (fixed16_bits).
inline double cvt_ufixed16(double q) {
  __asm__("vcvt.u32.f64 %P0, %P0, #16" : "+w"(q));
  return q;
}
inline double min_ufixed16(double x, double kmax) {
  __asm__("vmin.u32 %P0, %P0, %P1" : "+w"(x) : "w"(kmax));
  return x;
}
// kmax for min_ufixed16: m in both 32-bit halves (one vmov from the core register; the
// clamped results are read from their low 32 bits only: fixed16_bits, ufixed16_f64).
inline double bound16(int32_t m) {
  double r;
  __asm__("vmov %P0, %1, %1" : "=w"(r) : "r"(m));
  return r;
}
// double(uint32 low bits of x) by vcvt.f64.u32 from x's low single register (the clamped
// results above: fixed16_bits(x) as a double, without moving it to a core register).
// "t": x in d0 .. d15, and GCC prints such a double operand as its low single (s2n for dn).
// 1.0 / x (vdiv.f64, IEEE: the same bits), in a volatile asm that keeps its place among
// the other volatile asm (the issue order of a prologue's divides).
inline double recip7(double x) {
  double r;
  __asm__ volatile("vdiv.f64 %P0, %P1, %P2" : "=w"(r) : "w"(1.0), "w"(x));
  return r;
}
inline double ufixed16_f64(double x) {
  double r;
  __asm__("vcvt.f64.u32 %P0, %1" : "=w"(r) : "t"(x));
  return r;
}
#else
constexpr bool kFixed16 = false;
inline double cvt_fixed16(double q) { return q; }
inline double cvt_ufixed16(double q) { return q; }
inline double min_ufixed16(double x, double) { return x; }
inline double bound16(int32_t) { return 0.0; }
inline double ufixed16_f64(double x) { return double(uint32_t(__builtin_bit_cast(uint64_t, x))); }
#endif
inline int32_t fixed16_bits(double x) { return int32_t(uint32_t(__builtin_bit_cast(uint64_t, x))); }
// fixed16_bits by one vmov from x's low single register (armhf; GCC's 64-bit bit cast goes
// through the stack there). Used where that measured better (second-order span heads).
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__)
inline int32_t fixed16_bits_v(double x) {
  int32_t r;
  __asm__("vmov %0, %1" : "=r"(r) : "t"(x));
  return r;
}
#else
inline int32_t fixed16_bits_v(double x) { return fixed16_bits(x); }
#endif
// fixed16_bits_v where kV (second-order spans), else fixed16_bits (linear spans measured
// worse with the vmov: A9 persp64lin 6.91 -> 7.01).
template <bool kV>
inline int32_t fixed16_bits_if(double x) {
  if constexpr (kV) return fixed16_bits_v(x);
  return fixed16_bits(x);
}
inline int32_t to_fixed_int(double v, int32_t max) {
  if constexpr (kFixed16) return clamp_fixed(fixed16_bits(cvt_fixed16(v)), max);
  return clamp_fixed(cvt_sat(v * 65536.0), max);
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
#if defined(__arm__) && defined(__GNUC__) && defined(__ARM_ARCH) && __ARM_ARCH >= 7
// ARMv7 in asm (GCC's masks and 64-bit compare cost some 25 instructions): the same test
// with x = ssat(dd, 26): |dd| < 2^25 gives x = dd; else |x| >= 2^25 - 1 and 120 |x| >
// 2^31 > pd rejects, as 120 |dd| does. 120 |x| < 2^32: one 32-bit mul and unsigned compare.
// num = pd - 120 pdd, the mirror (x ^ s) - s of r = delta - 120 dd (mod 2^32), is exact in
// uint32 when accepted ([0, 2 pd]); rejected, num = pd (and dd = 0) by condition; then
// d = mirror(num >> 4): d0' mirrored, or the linear step pd >> 4 mirrored.
inline RunSteps steps16_dd(int32_t delta, int32_t dd) {
  uint32_t pd, x, r, ax, ddo = uint32_t(dd);
  __asm__(
      "eor %[pd], %[delta], %[delta], asr #31\n\t"
      "ssat %[x], #26, %[dd]\n\t"
      "mls %[r], %[dd], %[c], %[delta]\n\t"
      "sub %[pd], %[pd], %[delta], asr #31\n\t"
      "eor %[ax], %[x], %[x], asr #31\n\t"
      "sub %[ax], %[ax], %[x], asr #31\n\t"
      "eor %[r], %[r], %[delta], asr #31\n\t"
      "mul %[x], %[ax], %[c]\n\t"
      "sub %[r], %[r], %[delta], asr #31\n\t"
      "cmp %[x], %[pd]\n\t"
      "itt hi\n\t"
      "movhi %[r], %[pd]\n\t"
      "movhi %[ddo], #0\n\t"
      "lsr %[r], %[r], #4\n\t"
      "eor %[r], %[r], %[delta], asr #31\n\t"
      "sub %[r], %[r], %[delta], asr #31"
      : [pd] "=&r"(pd), [x] "=&r"(x), [r] "=&r"(r), [ax] "=&r"(ax), [ddo] "+&r"(ddo)
      : [delta] "r"(delta), [dd] "r"(dd), [c] "r"(120u)
      : "cc");
  return {int32_t(r), int32_t(ddo)};
}
// The same in two asm statements (part 1: pd, 120 |x|, the mirrored r; part 2: the test
// and the pick), so that steps16_dd_uv interleaves the u and v chains.
inline __attribute__((always_inline)) void steps16_part1(int32_t delta, int32_t dd, uint32_t& pd_, uint32_t& x_,
                                                          uint32_t& r_) {
  uint32_t pd, x, r, ax;
  __asm__(
      "eor %[pd], %[delta], %[delta], asr #31\n\t"
      "ssat %[x], #26, %[dd]\n\t"
      "mls %[r], %[dd], %[c], %[delta]\n\t"
      "sub %[pd], %[pd], %[delta], asr #31\n\t"
      "eor %[ax], %[x], %[x], asr #31\n\t"
      "sub %[ax], %[ax], %[x], asr #31\n\t"
      "eor %[r], %[r], %[delta], asr #31\n\t"
      "mul %[x], %[ax], %[c]\n\t"
      "sub %[r], %[r], %[delta], asr #31"
      : [pd] "=&r"(pd), [x] "=&r"(x), [r] "=&r"(r), [ax] "=&r"(ax)
      : [delta] "r"(delta), [dd] "r"(dd), [c] "r"(120u));
  pd_ = pd, x_ = x, r_ = r;
}
inline __attribute__((always_inline)) RunSteps steps16_part2(int32_t delta, int32_t dd, uint32_t pd, uint32_t x,
                                                             uint32_t r) {
  uint32_t ddo = uint32_t(dd);
  __asm__(
      "cmp %[x], %[pd]\n\t"
      "itt hi\n\t"
      "movhi %[r], %[pd]\n\t"
      "movhi %[ddo], #0\n\t"
      "lsr %[r], %[r], #4\n\t"
      "eor %[r], %[r], %[delta], asr #31\n\t"
      "sub %[r], %[r], %[delta], asr #31"
      : [r] "+&r"(r), [ddo] "+&r"(ddo)
      : [x] "r"(x), [pd] "r"(pd), [delta] "r"(delta)
      : "cc");
  return {int32_t(r), int32_t(ddo)};
}
// u and v, the two chains interleaved (in-order cores wait on each step of one chain).
inline __attribute__((always_inline)) void steps16_dd_uv(int32_t du, int32_t iu, int32_t dv, int32_t iv, RunSteps* su,
                                                         RunSteps* sv) {
  uint32_t pu, xu, ru, pv, xv, rv;
  steps16_part1(du, iu, pu, xu, ru);
  steps16_part1(dv, iv, pv, xv, rv);
  *su = steps16_part2(du, iu, pu, xu, ru);
  *sv = steps16_part2(dv, iv, pv, xv, rv);
}
// The same with both part 1 before both part 2 (an empty volatile asm takes part 1's
// results: GCC otherwise put both parts of u before v's in the ARMv7 long-span prologue;
// in the passes its own order schedules better).
inline __attribute__((always_inline)) void steps16_dd_uv_ordered(int32_t du, int32_t iu, int32_t dv, int32_t iv,
                                                                 RunSteps* su, RunSteps* sv) {
  uint32_t pu, xu, ru, pv, xv, rv;
  steps16_part1(du, iu, pu, xu, ru);
  steps16_part1(dv, iv, pv, xv, rv);
  __asm__ volatile("" : "+r"(pu), "+r"(xu), "+r"(ru), "+r"(pv), "+r"(xv), "+r"(rv));
  *su = steps16_part2(du, iu, pu, xu, ru);
  *sv = steps16_part2(dv, iv, pv, xv, rv);
}
#define SB_STEPS16_UV 1
#else
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
#endif

// One 16-pixel run, straight-line: u, v stepped with their second-order terms (0 when
// linear), even and odd pixels in two independent chains (u_{k+2} = u_k + e_k,
// e_{k+2} = e_k + 4 dd with e_k = 2 du_k + dd: the recurrence two steps at a time, equal
// modulo 2^32), so the adds do not form one 16-deep dependency chain. 64-bit targets: u, v
// packed in one register (see pack_steps); ARM: texels gathered into words (orr with a
// shifted operand), one store per 8 (aarch64) or 4 (armhf).
#if defined(__aarch64__) || defined(__x86_64__)
#define SB_SPAN_PACKED 1
#endif
#if defined(__aarch64__) || defined(__arm__)
#define SB_SPAN_WORDS 1
#endif
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_FEATURE_DSP)
#define SB_SPAN_SMULBT 1
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
#if !defined(SB_STEPS16_UV)
inline void steps16_dd_uv(int32_t du, int32_t iu, int32_t dv, int32_t iv, RunSteps* su, RunSteps* sv) {
  *su = steps16_dd(du, iu);
  *sv = steps16_dd(dv, iv);
}
inline void steps16_dd_uv_ordered(int32_t du, int32_t iu, int32_t dv, int32_t iv, RunSteps* su, RunSteps* sv) {
  steps16_dd_uv(du, iu, dv, iv, su, sv);
}
#endif

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
    const T a0 = (uint64_t(uint32_t(v0)) << 32) + uint32_t(u0), d0 = pack_steps(sv.d, su.d);
    const T dd = pack_steps(sv.dd, su.dd);
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
#if defined(SB_SPAN_SMULBT)
    // ARMv7 (few registers; the modelled Cortex-A9 issues loads out of order): each group
    // loads its own two pixels and gathers them at once, so at most a half-word of bytes
    // is held between groups (no spills).
    if constexpr (G < 8) {
      address<2 * G>(w);
      address<2 * G + 1>(w);
      const uint32_t b0 = texels[a_[2 * G]], b1 = texels[a_[2 * G + 1]];
      // The gather in asm: three orr per word (GCC reassociated it into four).
      if constexpr (G % 2 == 0) {
        uint32_t half;
        __asm__("orr %0, %1, %2, lsl #8" : "=r"(half) : "r"(b0), "r"(b1));
        out_[0] = half;
      } else {
        uint32_t word;  // little-endian
        __asm__("orr %0, %1, %2, lsl #16\n\torr %0, %0, %3, lsl #24"
                : "=&r"(word) : "r"(uint32_t(out_[0])), "r"(b0), "r"(b1));
        __builtin_memcpy(dest + 2 * G - 2, &word, 4);
      }
    }
#else
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
#endif
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
#if defined(SB_SPAN_SMULBT)
    // (v >> 16) w + (u >> 16) in two instructions: smulbt multiplies w's signed low half by
    // v's signed high half, which are w and v >> 16 (the contract: 1 <= w <= 32767,
    // 0 <= v < 2^31), exactly (< 2^30); uxtah adds the low half of u rotated by 16, u >> 16.
    Addr t, a;
    __asm__("smulbt %0, %1, %2" : "=r"(t) : "r"(w), "r"(v_));
    __asm__("uxtah %0, %1, %2, ror #16" : "=r"(a) : "r"(t), "r"(u_));
    a_[K] = a;
#else
    a_[K] = (v_ >> 16) * w + (u_ >> 16);
#endif
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
#if defined(SB_SPAN_PACKED)
// The same from the packed start a0 = v 2^32 + u and linear step d0 = dv 2^32 + du (du
// sign-extended), as Run16's constructor packs them (no second-order step).
template <bool kCurve>
SB_INLINE void draw16_packed(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w, uint64_t a0,
                             uint64_t d0) {
  Run16<kCurve> run(a0, d0, 0, typename Run16<kCurve>::Packed{});
  run.draw(dest, texels, w);
}
#endif
// draw16_packed when kPacked (aarch64 linear long spans: run r as lin_passes leaves it),
// else draw16 from the start and steps.
template <bool kCurve, bool kPacked>
SB_INLINE void draw16_or_packed(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint32_t w,
                                [[maybe_unused]] uint64_t a0, [[maybe_unused]] uint64_t d0, int32_t u0, int32_t v0,
                                const RunSteps& su, const RunSteps& sv) {
#if defined(SB_SPAN_PACKED)
  if constexpr (kPacked) return draw16_packed<kCurve>(dest, texels, w, a0, d0);
#endif
  draw16<kCurve>(dest, texels, w, u0, v0, su, sv);
}

// ---------------------------------------------------------------- the partial last run
//
// draw_last: a span's partial last run (1 <= n <= 15 pixels), inlined where it
// is called (no call; llvm-mca also times a call at 100 cycles) and with no loop: n's bits
// pick straight-line chunks of 8, 4, 2 and 1 pixels, in that order (pixels 0 .. 7 when
// n & 8, then the next 4 when n & 4, ...), each chunk all its texels loaded before any is
// stored, gathered into words on ARM (SB_SPAN_WORDS, little-endian; one unaligned store per
// chunk, two 4-byte ones for 8 pixels on ARMv7). Each pixel's position follows the walker's
// recurrence (uv_{k+1} = uv_k + duv_k, duv_{k+1} = duv_k + dduv; packed as above pack_steps
// modulo 2^64 on 64-bit targets, per component modulo 2^32 on 32-bit ones): its bytes.
// kCurve false: the caller's second-order steps are 0 (linear runs: no adds for them).
// Measured against two overlapping chunks (8 pixels at 0 and at n - 8 for n >= 8, 4 or 2
// likewise below; every pixel's texel loaded once or twice, one block per length class):
// the chunks by bits drew fewer texels and measured better on every core but Zen 3's
// linear rows (A53 persp64 10.41 -> 10.25, A72 5.69 -> 5.45, A9 8.12 -> 7.62, skylake
// 8.02 -> 7.54; znver3 persp64lin 4.68 -> 4.97).
struct TailPos {
#if defined(SB_SPAN_PACKED)
  uint64_t x, d, dd;  // v 2^32 + u, dv 2^32 + du, ddv 2^32 + ddu (du, ddu sign-extended)
#else
  uint32_t u, v, du, dv, ddu, ddv;
#endif
};
template <bool kCurve>
SB_INLINE TailPos tail_pos(uint32_t u, uint32_t v, uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
#if defined(SB_SPAN_PACKED)
  return {(uint64_t(v) << 32) + u, pack_steps(int32_t(dv), int32_t(du)),
          kCurve ? pack_steps(int32_t(ddv), int32_t(ddu)) : 0};
#else
  return {u, v, du, dv, kCurve ? ddu : 0, kCurve ? ddv : 0};
#endif
}
// Loads the texels of C pixels from p (the recurrence, one pixel a step) into t; returns the
// position C pixels on.
template <int C, bool kCurve>
SB_INLINE TailPos tail_load(uint8_t* t, const uint8_t* __restrict texels, uint32_t w, TailPos p) {
#if defined(__aarch64__)
  if constexpr (C >= 4) {
    // Even and odd pixels in two chains, as Run16: x_{k+2} = x_k + e_k, e_{k+2} = e_k +
    // 4 dd with e_k = 2 d_k + dd (the recurrence two steps at a time, the same integers
    // modulo 2^64), so the adds are two chains of C / 2 instead of one of C. Returns the
    // position C pixels on in closed form (x + C d + T(C) dd, d + C dd). aarch64 only
    // (A53 persp64 10.25 -> 10.16, A72 5.45 -> 5.37; persp64single 11.15 -> 11.18; from
    // C >= 8 only: 10.22; on x86-64 znver3 persp64lin 4.50 -> 4.60).
    uint64_t x[2] = {p.x, p.x + p.d};
    uint64_t e[2] = {2 * p.d + p.dd, 2 * p.d + 3 * p.dd};
    const uint64_t dd4 = 4 * p.dd;
#pragma GCC unroll 16
    for (int j = 0; j < C; ++j) {
      const int c = j & 1;
      t[j] = texels[uint32_t(x[c] >> 48) * w + (uint32_t(x[c]) >> 16)];
      x[c] += e[c];
      if constexpr (kCurve) e[c] += dd4;
    }
    constexpr uint64_t kT = uint64_t(C) * (C - 1) / 2;
    return {p.x + C * p.d + kT * p.dd, p.d + C * p.dd, p.dd};
  }
#endif
#pragma GCC unroll 16
  for (int j = 0; j < C; ++j) {
#if defined(SB_SPAN_PACKED)
#if defined(__x86_64__)
    t[j] = texels[uint64_t(uint32_t(p.x >> 48)) * w + (uint32_t(p.x) >> 16)];
#else
    t[j] = texels[uint32_t(p.x >> 48) * w + (uint32_t(p.x) >> 16)];
#endif
    p.x += p.d;
    if constexpr (kCurve) p.d += p.dd;
#else
#if defined(SB_SPAN_SMULBT)
    uint32_t a, b;  // as Run16::address (the contract: w <= 32767, 0 <= v < 2^31)
    __asm__("smulbt %0, %1, %2" : "=r"(a) : "r"(w), "r"(p.v));
    __asm__("uxtah %0, %1, %2, ror #16" : "=r"(b) : "r"(a), "r"(p.u));
    t[j] = texels[b];
#else
    t[j] = texels[(p.v >> 16) * w + (p.u >> 16)];
#endif
    p.u += p.du, p.v += p.dv;
    if constexpr (kCurve) p.du += p.ddu, p.dv += p.ddv;
#endif
  }
  return p;
}
// Stores C texels at dest: words on ARM, bytes elsewhere.
template <int C>
SB_INLINE void tail_store(uint8_t* __restrict dest, const uint8_t* t) {
#if defined(SB_SPAN_WORDS)
  if constexpr (C == 1) {
    dest[0] = t[0];
  } else {
    using Word = std::conditional_t<C == 2, uint16_t, std::conditional_t<C == 4, uint32_t, uintptr_t>>;
    constexpr int kPer = int(sizeof(Word));
#pragma GCC unroll 2
    for (int i = 0; i < C; i += kPer) {
      Word word = 0;
#pragma GCC unroll 8
      for (int j = 0; j < kPer; ++j) word |= Word(Word(t[i + j]) << (8 * j));  // little-endian
      __builtin_memcpy(dest + i, &word, sizeof(Word));
    }
  }
#else
#pragma GCC unroll 16
  for (int j = 0; j < C; ++j) dest[j] = t[j];
#endif
}
// kHalves: pixels 0 .. 7 as two chunks of 4 (ARMv7's mid path: the 8-chunk's eight positions,
// live at once, were spilled there, 16 stack loads / stores; A9 persp64 7.60 -> 7.51).
template <bool kCurve, bool kHalves = false>
SB_INLINE void draw_last(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w, uint32_t u,
                         uint32_t v, uint32_t du, uint32_t dv, uint32_t ddu, uint32_t ddv) {
  TailPos p = tail_pos<kCurve>(u, v, du, dv, ddu, ddv);
  auto chunk = [&](auto cc) SB_LAMBDA_INLINE {
    constexpr int C = decltype(cc)::value;
    uint8_t t[C];
    p = tail_load<C, kCurve>(t, texels, w, p);
    tail_store<C>(dest, t);
    dest += C;
  };
  if constexpr (kHalves) {  // the 8 pixels as two chunks of 4 in one block
    if (n & 8) chunk(std::integral_constant<int, 4>{}), chunk(std::integral_constant<int, 4>{});
  } else {
    if (n & 8) chunk(std::integral_constant<int, 8>{});
  }
  if (n & 4) chunk(std::integral_constant<int, 4>{});
  if (n & 2) chunk(std::integral_constant<int, 2>{});
  if (n & 1) chunk(std::integral_constant<int, 1>{});
}

// ARMv7: max_or_lo without a branch (vcmpe, vmrs, a conditional vmov: le is x <= lo or
// unordered, NaN -> lo), for the long spans' first divides.
inline double max_or_lo_sel(double x, double lo) {
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_FP) && (__ARM_FP & 8)
  __asm__("vcmpe.f64 %P0, %P1\n\tvmrs APSR_nzcv, fpscr\n\tit le\n\tvmovle.f64 %P0, %P1" : "+w"(x) : "w"(lo) : "cc");
  return x;
#else
  return max_or_lo(x, lo);
#endif
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

}  // namespace
}  // namespace sb::simd
