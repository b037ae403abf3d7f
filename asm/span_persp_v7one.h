// asm/span_persp_v7one.h: the whole-span drawer's ARMv7 path for second-order spans of one
// run (1 .. 16 pixels, dzi != 0) in a batch (asm/span_persp.h), two neighbouring ones at a
// time. Internal: included by asm/span_persp_fast.cpp only, after asm/span_persp_v7pass.h
// (anonymous namespace).
//
// Such spans are the drawer's most numerous (bench/span_hist.md: 880-960 a frame at 320x240,
// mean 7 pixels, 95% next to another one in the batch). Each is two samples and one last run;
// its cost is the latency chain of the set-up (depth, two divides, to_fixed, the last run's
// quotient, another divide, its steps), not the pixels. persp_fast<true>'s one-run branch ran
// it with the chains one after the other, behind the batch loop's dispatch tests. Here the
// set-ups of two neighbouring spans are one straight sequence, the two spans' operations
// interleaved step by step (each step pinned: the modelled Cortex-A9's in-order FP pipe waits
// on every dependent step, so the other span's step fills the wait), the four divides for the
// depths back to back and then the four for the last runs' quotients back to back. Then both
// spans are drawn. Every double operation is the walker's (asm/span_walk.h), as persp_fast's
// one-run branch performs it:
//   positions   P = px0 and P + (n - 1)
//   depth       z = 1 / max(zrow + zix x, kMinZi) (fused as compiled; vcmpe / vmovle: NaN
//               -> kMinZi)
//   u, v        min_ufixed16(cvt_ufixed16((urow + ux x) z), umax) (persp_fast's sample():
//               the walker's to_fixed, see min_ufixed16), likewise v
//   steps       last_steps over n - 1 steps: q = double(delta) / max(n - 1, 1) (delta: the
//               clamped samples' int32 difference, exact; v7_sub_lo), curve =
//               (zix * 0.5) (z_0 + z_1), lin = trunc(q), last_ddi(q, curve), then
//               last_steps_i's integer test. One pixel (n = 1): both samples are the same
//               (delta 0), the steps are never read (draw_last draws the start only).
#pragma once
#include <cstdint>

#include "asm/span_persp_run.h"
#include "asm/span_persp_v7pass.h"

#if defined(SB_V7_NEON_STEPS)
#define SB_V7_ONE 1
namespace sb::simd {
namespace {

// An item persp_one_v7 draws: second order, dzi != 0 (on its bits), 1 <= n <= 16.
// dzi != 0 on its bits as is_zero_v7 (asm/span_persp_fast.cpp) tests it.
SB_INLINE bool one_v7(const PerspItem& x) {
  uint32_t lo, hi;
  __builtin_memcpy(&lo, &x.span.dzi, 4);
  __builtin_memcpy(&hi, reinterpret_cast<const char*>(&x.span.dzi) + 4, 4);
  return x.span.second_order && (lo | (hi << 1)) != 0 && uint32_t(x.n - 1) < 16u;
}

struct OneSetup {
  int32_t u, v;
  RunSteps su, sv;
};

// The set-ups of spans a and b (both one_v7's; b may be a itself), interleaved.
SB_INLINE void one_setup2_v7(const PerspItem& A, const PerspItem& B, OneSetup* ra, OneSetup* rb) {
  const PerspSpan& a = A.span;
  const PerspSpan& b = B.span;
  const int na = A.n, nb = B.n;
  // Positions and depths.
  const double Pa = a.px0, Pb = b.px0;
  double fa = double(na - 1), fb = double(nb - 1);
  const double pa1 = Pa + fa, pb1 = Pb + fb;
  double zia0 = max_or_lo_sel(a.zi0 + a.dzi * Pa, kMinZi), zib0 = max_or_lo_sel(b.zi0 + b.dzi * Pb, kMinZi);
  double zia1 = max_or_lo_sel(a.zi0 + a.dzi * pa1, kMinZi), zib1 = max_or_lo_sel(b.zi0 + b.dzi * pb1, kMinZi);
  const double za0 = recip7(zia0), zb0 = recip7(zib0);
  const double za1 = recip7(zia1), zb1 = recip7(zib1);
  // Beside the divides: the numerators, the bounds, the divisors max(n - 1, 1), zix / 2.
  double tua0 = a.uz0 + a.duz * Pa, tva0 = a.vz0 + a.dvz * Pa;
  double tub0 = b.uz0 + b.duz * Pb, tvb0 = b.vz0 + b.dvz * Pb;
  double tua1 = a.uz0 + a.duz * pa1, tva1 = a.vz0 + a.dvz * pa1;
  double tub1 = b.uz0 + b.duz * pb1, tvb1 = b.vz0 + b.dvz * pb1;
  pin7(tua0), pin7(tva0), pin7(tub0), pin7(tvb0), pin7(tua1), pin7(tva1), pin7(tub1), pin7(tvb1);
  const double kUa = bound16(a.umax), kVa = bound16(a.vmax), kUb = bound16(b.umax), kVb = bound16(b.vmax);
  double sa = double(na > 2 ? na - 1 : 1), sb = double(nb > 2 ? nb - 1 : 1);
  double zha = a.dzi * 0.5, zhb = b.dzi * 0.5;
  pin7(sa), pin7(sb), pin7(zha), pin7(zhb);
  // The samples.
  double qua0 = tua0 * za0, qva0 = tva0 * za0, qub0 = tub0 * zb0, qvb0 = tvb0 * zb0;
  pin7(qua0), pin7(qva0), pin7(qub0), pin7(qvb0);
  double qua1 = tua1 * za1, qva1 = tva1 * za1, qub1 = tub1 * zb1, qvb1 = tvb1 * zb1;
  pin7(qua1), pin7(qva1), pin7(qub1), pin7(qvb1);
  qua0 = cvt_ufixed16(qua0), qva0 = cvt_ufixed16(qva0), qub0 = cvt_ufixed16(qub0), qvb0 = cvt_ufixed16(qvb0);
  qua1 = cvt_ufixed16(qua1), qva1 = cvt_ufixed16(qva1), qub1 = cvt_ufixed16(qub1), qvb1 = cvt_ufixed16(qvb1);
  pin7(qua0), pin7(qva0), pin7(qub0), pin7(qvb0), pin7(qua1), pin7(qva1), pin7(qub1), pin7(qvb1);
  qua0 = min_ufixed16(qua0, kUa), qva0 = min_ufixed16(qva0, kVa), qub0 = min_ufixed16(qub0, kUb);
  qvb0 = min_ufixed16(qvb0, kVb);
  qua1 = min_ufixed16(qua1, kUa), qva1 = min_ufixed16(qva1, kVa), qub1 = min_ufixed16(qub1, kUb);
  qvb1 = min_ufixed16(qvb1, kVb);
  pin7(qua0), pin7(qva0), pin7(qub0), pin7(qvb0), pin7(qua1), pin7(qva1), pin7(qub1), pin7(qvb1);
  // The deltas (exact), the quotients.
  const double dua = v7_cvt_lo(v7_sub_lo(qua1, qua0)), dva = v7_cvt_lo(v7_sub_lo(qva1, qva0));
  const double dub = v7_cvt_lo(v7_sub_lo(qub1, qub0)), dvb = v7_cvt_lo(v7_sub_lo(qvb1, qvb0));
  double qua = dua / sa, qva = dva / sa, qub = dub / sb, qvb = dvb / sb;
  pin7(qua), pin7(qva), pin7(qub), pin7(qvb);
  double ca = zha * (za0 + za1), cb = zhb * (zb0 + zb1);
  pin7(ca), pin7(cb);
  const int32_t ua0 = fixed16_bits_v(qua0), va0 = fixed16_bits_v(qva0), ub0 = fixed16_bits_v(qub0);
  const int32_t vb0 = fixed16_bits_v(qvb0);
  const int32_t ua1 = fixed16_bits_v(qua1), va1 = fixed16_bits_v(qva1), ub1 = fixed16_bits_v(qub1);
  const int32_t vb1 = fixed16_bits_v(qvb1);
  const int32_t lua = cvt_sat(qua), lva = cvt_sat(qva), lub = cvt_sat(qub), lvb = cvt_sat(qvb);
  const int32_t iua = last_ddi(qua, ca), iva = last_ddi(qva, ca), iub = last_ddi(qub, cb), ivb = last_ddi(qvb, cb);
  ra->u = ua0, ra->v = va0, rb->u = ub0, rb->v = vb0;
  last_steps_i(na - 1, ua1 - ua0, va1 - va0, lua, lva, iua, iva, &ra->su, &ra->sv);
  last_steps_i(nb - 1, ub1 - ub0, vb1 - vb0, lub, lvb, iub, ivb, &rb->su, &rb->sv);
}

SB_INLINE void one_draw_v7(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const OneSetup& s) {
  if (n == 16) {
    draw16<true>(dest, texels, w, s.u, s.v, s.su, s.sv);
  } else {
    draw_last<true>(dest, n, texels, w, uint32_t(s.u), uint32_t(s.v), uint32_t(s.su.d), uint32_t(s.sv.d),
                    uint32_t(s.su.dd), uint32_t(s.sv.dd));
  }
}

// Items from it on (persp_one_v7, defined at the end of asm/span_persp_fast.cpp: see there).
const PerspItem* persp_one_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);

}  // namespace
}  // namespace sb::simd
#endif
