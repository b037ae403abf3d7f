// asm/span_persp_arm.h: the whole-span drawer's ARM paths (asm/span_persp.h): the aarch64
// two-run pass pipeline (lin_slot), the last run's branch-free steps (ARM) and the aarch64
// short-span path (persp_short). Internal: included by asm/span_persp_fast.cpp only, after
// asm/span_persp_run.h (anonymous namespace, as when this was part of that file).
#pragma once
#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64pass.h"
#endif

namespace sb::simd {
namespace {
#if defined(__aarch64__) && defined(__GNUC__)
// aarch64, persp_fast's long spans: the two runs of a loop pass (32 pixels) as one software
// pipeline of eight groups of four pixels, written in asm so that each slot keeps its order:
// the shifts and steps of group j (latency 2), the caller's stage (double / vector work,
// latency 6), then the multiply-adds of group j beside the loads of group j - 1 (latency 4)
// and the gather and store of groups j - 2, j - 3: in-order issue (llvm-mca's Cortex-A53
// model also completes in order) seldom waits. u, v packed as pack_steps says (v 2^32 + u).
//   linear: pixel 4 g + i of a run on chain i, stepped by e = 4 duv: chain i holds
//           uv_0 + (4 g + i) duv (mod 2^64), the packed recurrence's value.
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
// one-pixel last run): the steps are never used (draw_last draws the start only).
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
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_ARCH) && __ARM_ARCH >= 7
// ARMv7: the same in asm (GCC's masks and 64-bit compare cost some 35 instructions a
// component). d0' as below; then the test T |dd| <= pd on the 64-bit umull product
// (lo <= pd and hi = 0: eq after cmp / cmpls), rejected: linear and dd = 0.
SB_INLINE RunSteps last_dd(int32_t delta, int32_t linear, int32_t ddi, uint32_t s, uint32_t T) {
  uint32_t sg, pd, r, m, t, d, ddo = uint32_t(ddi);
  __asm__(
      "asr %[sg], %[delta], #31\n\t"
      "eor %[pd], %[delta], %[sg]\n\t"
      "eor %[d], %[lin], %[sg]\n\t"
      "sub %[pd], %[pd], %[sg]\n\t"
      "sub %[d], %[d], %[sg]\n\t"                // Q = |linear|
      "eor %[m], %[dd], %[sg]\n\t"
      "mls %[r], %[s], %[d], %[pd]\n\t"          // r = pd - s Q
      "sub %[m], %[m], %[sg]\n\t"                // pdd
      "sub %[t], %[s], #1\n\t"
      "mul %[m], %[m], %[t]\n\t"                 // m = (s - 1) pdd
      "sub %[d], %[d], %[m], asr #1\n\t"
      "and %[t], %[m], #1\n\t"
      "cmp %[s], %[r], lsl #1\n\t"
      "it ls\n\t"
      "movls %[t], #0\n\t"                       // b and 2 r < s
      "sub %[d], %[d], %[t]\n\t"                 // d0'
      "eor %[m], %[dd], %[dd], asr #31\n\t"
      "eor %[d], %[d], %[sg]\n\t"
      "sub %[m], %[m], %[dd], asr #31\n\t"       // |dd|
      "sub %[d], %[d], %[sg]\n\t"                // d0 (mirrored back)
      "umull %[r], %[t], %[m], %[T]\n\t"
      "cmp %[r], %[pd]\n\t"
      "it ls\n\t"
      "cmpls %[t], #0\n\t"
      "itt ne\n\t"
      "movne %[d], %[lin]\n\t"
      "movne %[ddo], #0"
      : [sg] "=&r"(sg), [pd] "=&r"(pd), [r] "=&r"(r), [m] "=&r"(m), [t] "=&r"(t), [d] "=&r"(d), [ddo] "+&r"(ddo)
      : [delta] "r"(delta), [lin] "r"(linear), [dd] "r"(ddi), [s] "r"(s), [T] "r"(T)
      : "cc");
  return RunSteps{int32_t(d), int32_t(ddo)};
}
#else
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
#endif
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__)
// ARMv7: keeps a value computed where it is written (an empty volatile asm that takes it),
// so that the compiler does not sink a divide or conversion to its use, where the
// modelled Cortex-A9's in-order FP pipe would wait for it (as pin above, for aarch64).
template <class T>
SB_INLINE void pin7(T& x) {
  if constexpr (std::is_integral_v<T>) {
    __asm__ volatile("" : "+r"(x));
  } else {
    __asm__ volatile("" : "+w"(x));
  }
}
#endif
#if !defined(__aarch64__)
// The quotients double(delta) / max(steps, 1), as last_steps takes them (ARMv7: the tail
// issues them early, beside the run before the last).
SB_INLINE double last_quotient(int steps, int32_t delta) {
  return double(delta) / double(int(uint32_t(steps > 1 ? steps : 1)));
}
SB_INLINE void last_steps_q(int steps, int32_t du, int32_t dv, double qu, double qv, double curve, RunSteps* su,
                            RunSteps* sv) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  const uint32_t two = steps > 1 ? ~0u : 0u;
  const int32_t lu = int32_t(qu), lv = int32_t(qv);
  const double fu = -2.0 * (qu * curve), fv = -2.0 * (qv * curve);
  const int32_t du2 = cvt_sat(fu) & -int32_t(fu > -1e9 && fu < 1e9), dv2 = cvt_sat(fv) & -int32_t(fv > -1e9 && fv < 1e9);
  *su = last_dd(du, lu, du2 & int32_t(two), s, T);
  *sv = last_dd(dv, lv, dv2 & int32_t(two), s, T);
}
// last_steps_q in two parts, for stage slots (ARMv7 tails): the conversion of
// ddf = -2 (q curve) (last_ddi) and the integer rest (last_steps_i). The range test
// -1e9 < ddf < 1e9 on the converted i = cvt_sat(ddf) instead (no vcmpe / vmrs): |ddf| < 1e9
// iff |i| < 1e9 (trunc keeps |ddf| < 1e9 below 1e9 and 1e9 and more at 1e9 or more, or
// saturated), i = 0 for NaN, and dd = 0 gives last_dd's linear result as a rejection does
// (T 0 <= pd accepts, m = 0, d0 = Q). (AsmSpanPersp.LastRunStepsMatchTheWalker checks it.)
SB_INLINE int32_t last_ddi_tail(int32_t i) { return (uint32_t(i) + 999999999u < 1999999999u) ? i : 0; }
SB_INLINE int32_t last_ddi(double q, double curve) { return last_ddi_tail(cvt_sat(-2.0 * (q * curve))); }
SB_INLINE void last_steps_i(int steps, int32_t du, int32_t dv, int32_t lu, int32_t lv, int32_t iu, int32_t iv,
                            RunSteps* su, RunSteps* sv) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  const uint32_t two = steps > 1 ? ~0u : 0u;
  *su = last_dd(du, lu, iu & int32_t(two), s, T);
  *sv = last_dd(dv, lv, iv & int32_t(two), s, T);
}
#endif
#if defined(__aarch64__)
// last_steps' integer part, from lin = [linear_u, linear_v] and dd = [ddi_u, ddi_v] (int64
// lanes: trunc(q), and trunc(ddf) masked by |ddf| < 1e9) as last_steps computes them.
SB_INLINE void last_steps_dd(int steps, int32_t du, int32_t dv, int64x2_t lin, int64x2_t dd, RunSteps* su,
                             RunSteps* sv);
// The same from the lanes as 32-bit core values (lu, lv: trunc(q); du2, dv2: the masked dd).
SB_INLINE void last_steps_ddi(int steps, int32_t du, int32_t dv, int32_t lu, int32_t lv, int32_t du2, int32_t dv2,
                              RunSteps* su, RunSteps* sv);
// du = b.u - a.u, dv = b.v - a.v (0 <= u, v < 2^31: no overflow), also as doubles [du, dv].
SB_INLINE void last_steps(int steps, int32_t du, int32_t dv, float64x2_t duv, double curve, RunSteps* su,
                          RunSteps* sv) {
#else
SB_INLINE void last_steps(int steps, int32_t du, int32_t dv, double curve, RunSteps* su, RunSteps* sv) {
  last_steps_q(steps, du, dv, last_quotient(steps, du), last_quotient(steps, dv), curve, su, sv);
}
#endif
#if defined(__aarch64__)
  const float64x2_t q = div_steps(duv, uint32_t(steps > 1 ? steps : 1));
  const int64x2_t lin = vcvtq_s64_f64(q);
  const float64x2_t ddf = vmulq_n_f64(vmulq_n_f64(q, curve), -2.0);
  // -1e9 < ddf < 1e9 as |ddf| < 1e9 (facgt; false for NaN, as both compares).
  const uint64x2_t ok = vcaltq_f64(ddf, vdupq_n_f64(1e9));
  const int64x2_t dd = vandq_s64(vcvtq_s64_f64(ddf), vreinterpretq_s64_u64(ok));
  last_steps_dd(steps, du, dv, lin, dd, su, sv);
}
SB_INLINE void last_steps_dd(int steps, int32_t du, int32_t dv, int64x2_t lin, int64x2_t dd, RunSteps* su,
                             RunSteps* sv) {
  last_steps_ddi(steps, du, dv, int32_t(vgetq_lane_s64(lin, 0)), int32_t(vgetq_lane_s64(lin, 1)),
                 int32_t(vgetq_lane_s64(dd, 0)), int32_t(vgetq_lane_s64(dd, 1)), su, sv);
}
SB_INLINE void last_steps_ddi(int steps, int32_t du, int32_t dv, int32_t lu, int32_t lv, int32_t du2, int32_t dv2,
                              RunSteps* su, RunSteps* sv) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  const uint32_t two = steps > 1 ? ~0u : 0u;
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
}
#endif
SB_INLINE void last_steps(int steps, const Sample& a, const Sample& b, double curve, RunSteps* su, RunSteps* sv) {
  const int32_t du = b.u - a.u, dv = b.v - a.v;  // 0 <= u, v < 2^31: no overflow
#if defined(__aarch64__)
  last_steps(steps, du, dv, vcvtq_f64_s64(vmovl_s32(vcreate_s32(uint64_t(uint32_t(dv)) << 32 | uint32_t(du)))), curve,
             su, sv);
#else
  last_steps(steps, du, dv, curve, su, sv);
#endif
}

}  // namespace
}  // namespace sb::simd

// The aarch64 short-span path (persp_short_inl, kShortMax), which uses the helpers above.
#include "asm/span_persp_a64short.h"
