// asm/span_persp_v7pass.h: ARMv7 (armhf NEON) helpers for persp_fast's long-span pass
// (asm/span_persp_fast.cpp): the second run's-next steps (run r + 2's, from samples r + 2 and
// r + 3) computed in NEON lanes beside the pixels instead of steps16_dd's 32 core
// instructions. Internal: included by asm/span_persp_fast.cpp only, after
// asm/span_persp_run.h (anonymous namespace).
//
// Each helper is one small asm statement on doubles (d registers) that the pass's stage slots
// place one dependent step per pixel group (the modelled Cortex-A9 issues VFP / NEON in
// order, one a cycle, beside the integer pixels). The operations and their bits:
//   delta = [du, dv]: the clamped fixed-point samples' low 32-bit lanes subtracted
//           (vsub.i32: 0 <= u, v < 2^31, so the int32 difference is exact);
//   ddf   = double(delta) * c (vcvt.f64.s32, vmul.f64: the pass's fu2 * c2, same bits);
//   dd    = cvt_sat(ddf) (vcvt.s32.f64: truncating, saturating, NaN -> 0);
//   steps16_dd per lane (asm/span_persp_run.h's 32-bit form, as asm/span_persp_v7mid.h's run
//           0 computes it): pd = |delta|; accepted iff 120 min(|dd|, 2^25) <= pd (unsigned);
//           dd' = accepted ? dd : 0; d = (delta + (delta < 0 ? 15 : 0) - 120 dd') >> 4
//           (arithmetic), the difference halved exactly by vhsub.s32 (it needs 33 bits when
//           dd' and delta differ in sign), then >> 3: floor(floor(x / 2) / 8) = floor(x / 16).
//           That is mirror((pd - 120 mirror(dd')) >> 4), steps16_dd's d (rejected: dd' = 0,
//           trunc(delta / 16), the linear step).
#pragma once
#include <cstdint>

#include "asm/span_persp_run.h"
#include "asm/span_persp_v7mid.h"

#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_NEON) && defined(__ARM_FP) && \
    (__ARM_FP & 8)
#define SB_V7_NEON_STEPS 1
namespace sb::simd {
namespace {
// The low 32-bit lanes' difference a - b, in a d0 .. d15 register ("t": its low single is
// the asm's %n, for vcvt).
SB_INLINE double v7_sub_lo(double a, double b) {
  double r;
  __asm__("vsub.i32 %P0, %P1, %P2" : "=t"(r) : "w"(a), "w"(b));
  return r;
}
// double(int32 low lane of x).
SB_INLINE double v7_cvt_lo(double x) {
  double r;
  __asm__("vcvt.f64.s32 %P0, %1" : "=w"(r) : "t"(x));
  return r;
}
// cvt_sat(x) into the low lane of a d0 .. d15 register (the high lane left undefined).
SB_INLINE double v7_sat_lo(double x) {
  double r;
  __asm__("vcvt.s32.f64 %0, %P1" : "=t"(r) : "w"(x));
  return r;
}
// [lo(a), lo(b)]: b's low lane inserted as the high lane of a (vsli.64 #32).
SB_INLINE double v7_pack(double a, double b) {
  __asm__("vsli.64 %P0, %P1, #32" : "+w"(a) : "w"(b));
  return a;
}
// The NEON steps16_dd in four parts for four stage slots (see the header). State: d (delta,
// then delta + bias), pd, t (sign), dd, a, x, k120, k25.
struct V7Steps {
  double d, pd, t, dd, a, x, k120, k25;
};
// Part 1: pd = |delta|, t = sign mask, the two constants.
SB_INLINE void v7_steps_1(V7Steps& s) {
  __asm__("vabs.s32 %P[pd], %P[d]\n\t"
          "vshr.s32 %P[t], %P[d], #31\n\t"
          "vmov.i32 %P[k120], #120\n\t"
          "vmov.i32 %P[k25], #33554432"
          : [pd] "=&w"(s.pd), [t] "=&w"(s.t), [k120] "=&w"(s.k120), [k25] "=&w"(s.k25)
          : [d] "w"(s.d));
}
// Part 2: a = |dd|, x = 120 dd, delta + bias (vsra: t >> 28 is 15 for delta < 0, else 0).
SB_INLINE void v7_steps_2(V7Steps& s) {
  __asm__("vabs.s32 %P[a], %P[dd]\n\t"
          "vmul.i32 %P[x], %P[dd], %P[k120]\n\t"
          "vsra.u32 %P[d], %P[t], #28"
          : [a] "=&w"(s.a), [x] "=&w"(s.x), [d] "+w"(s.d)
          : [dd] "w"(s.dd), [k120] "w"(s.k120), [t] "w"(s.t));
}
// Part 3: a = min(|dd|, 2^25); part 3b: a = 120 a.
SB_INLINE void v7_steps_3(V7Steps& s) { __asm__("vmin.u32 %P[a], %P[a], %P[k25]" : [a] "+w"(s.a) : [k25] "w"(s.k25)); }
SB_INLINE void v7_steps_3b(V7Steps& s) {
  __asm__("vmul.i32 %P[a], %P[a], %P[k120]" : [a] "+w"(s.a) : [k120] "w"(s.k120));
}
// Part 4: the accept mask (a = pd >= a); part 4b: dd' = dd & mask, 120 dd' = x & mask.
SB_INLINE void v7_steps_4(V7Steps& s) {
  __asm__("vcge.u32 %P[a], %P[pd], %P[a]" : [a] "+w"(s.a) : [pd] "w"(s.pd));
}
SB_INLINE void v7_steps_4b(V7Steps& s) {
  __asm__("vand %P[dd], %P[dd], %P[a]\n\t"
          "vand %P[x], %P[x], %P[a]"
          : [dd] "+w"(s.dd), [x] "+w"(s.x)
          : [a] "w"(s.a));
}
// Part 5: h = (delta + bias - 120 dd') / 2 (vhsub: floor, exact in 33 bits); part 5b:
// d = h >> 3.
SB_INLINE void v7_steps_5(V7Steps& s) {
  __asm__("vhsub.s32 %P[d], %P[d], %P[x]" : [d] "+w"(s.d) : [x] "w"(s.x));
}
SB_INLINE void v7_steps_5b(V7Steps& s) { __asm__("vshr.s32 %P[d], %P[d], #3" : [d] "+w"(s.d)); }
// The lanes into RunSteps (u: lane 0, v: lane 1).
SB_INLINE void v7_steps_out(const V7Steps& s, RunSteps* su, RunSteps* sv) {
  int32_t d0, d1, e0, e1;
  __asm__("vmov %[d0], %[d1], %P[d]" : [d0] "=r"(d0), [d1] "=r"(d1) : [d] "w"(s.d));
  __asm__("vmov %[e0], %[e1], %P[dd]" : [e0] "=r"(e0), [e1] "=r"(e1) : [dd] "w"(s.dd));
  *su = RunSteps{d0, e0}, *sv = RunSteps{d1, e1};
}
#if defined(SB_V7_MID)
// The long tail's extra run (persp_long_run_v7's, left 33 .. 48): run r's pixels as
// draw16_v7 draws them (one asm statement: the run's values stay in registers), with run
// r + 1's ddf in its VFP slots: delta = lo(cq2) - lo(cq1) per component (dA, dB: vsub.i32
// on the clamped samples r + 2 and r + 1, exact, computed by the caller), c1 = zck (z1 + z2), ddf = double(delta) c1,
// dd = cvt_sat(ddf) into the low single of ia / ib (the pass's stage_a operations, in its
// order: the same bits).
SB_INLINE void v7_tail_run(uint8_t* dest, const uint8_t* texels, uint32_t w, RunRegs rr, double dA, double dB,
                           double z1, double z2, double zck, int32_t* iu, int32_t* iv) {
  uint32_t u = rr.u, v = rr.v, du = rr.du, dv = rr.dv, a, b;
  const uint32_t ddu = rr.ddu, ddv = rr.ddv;
  double fu, fv, c, ia, ib;
  __asm__ volatile(SB_V7_RUN("vadd.f64 %P[c], %P[z1], %P[z2]\n\t",
                             "vcvt.f64.s32 %P[fu], %[dA]\n\tvcvt.f64.s32 %P[fv], %[dB]\n\t"
                             "vmul.f64 %P[c], %P[zck], %P[c]\n\t",
                             "vmul.f64 %P[fu], %P[fu], %P[c]\n\t", "vmul.f64 %P[fv], %P[fv], %P[c]\n\t",
                             "vcvt.s32.f64 %[ia], %P[fu]\n\t", "vcvt.s32.f64 %[ib], %P[fv]\n\t", "", "")
                   : SB_V7_RUN_OPERANDS(dest), [fu] "=&w"(fu), [fv] "=&w"(fv),
                     [c] "=&w"(c), [ia] "=&t"(ia), [ib] "=&t"(ib)
                   : SB_V7_RUN_INPUTS(dest), [dA] "t"(dA), [dB] "t"(dB),
                     [z1] "w"(z1), [z2] "w"(z2), [zck] "w"(zck)
                   : "memory");
  *iu = fixed16_bits_v(ia), *iv = fixed16_bits_v(ib);
}
#endif
}  // namespace
}  // namespace sb::simd
#endif
#undef SB_V7_RUN_INPUTS
#undef SB_V7_RUN_OPERANDS
#undef SB_V7_RUN
#undef SB_V7_HI_END
#undef SB_V7_HI
#undef SB_V7_LO
#undef SB_V7_PX
