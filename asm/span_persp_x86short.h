// asm/span_persp_x86short.h: x86-64 only, the batch loop's short second-order spans
// (asm/span_persp.h: second_order with dzi != 0, 1 .. kX86ShortMax pixels), drawn inline in
// surface_spans_persp_fast's loop (spans_range): no call per span, so none of persp_fast's
// prologue and epilogue (six pushes, a 0x128-byte frame: llvm-mca times the epilogue alone
// at 37 cycles on Skylake), and none of run_steps_uv's out-of-line jump table. Internal:
// included by asm/span_persp_fast.cpp only, after asm/span_persp_arm.h (its last_steps_q and
// asm/span_persp_run.h's runs).
//
// The walker's arithmetic (asm/span_walk.h), the same bits: the samples at pixel offsets
// o_j = min(16 j, n - 1), their positions as the walker accumulates them (P_0 + o_1 for
// j = 1, P_{j-2} + (o_j - o_{j-2}) after); z = 1 / max(zi, 1e-9) (NaN -> 1e-9), to_fixed in
// select form (max(q, 0) with NaN -> 0, then min(q, max), truncated: to_fixed_sel). The
// samples two at a time in SSE2's two double lanes (mulpd, addpd, maxpd, divpd: each lane the
// scalar operation's IEEE result), so one divide instruction gives two reciprocals. Full runs'
// steps are steps16_sel's (delta / 16 * curve exact as delta * 0.0625), the last run's
// last_steps_q's (the quotients delta / steps of u and v in one divpd).
// A last run of one pixel draws its start only: the sample after it (computed at some
// position, clamped like any other) is then never used.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>

#include "asm/span_persp_arm.h"
#include "asm/span_persp_run.h"

namespace sb::simd {
namespace {

constexpr int kX86ShortMax = 48;

// Two samples at positions pos = [x0, x1]: [u0, u1], [v0, v1] (16.16, clamped) and [z0, z1].
struct Samples2 {
  int32_t u0, u1, v0, v1;
  __m128d z;
};
SB_INLINE Samples2 samples2_x86(const PerspSpan& p, __m128d pos, __m128d umax, __m128d vmax) {
  const __m128d zi = _mm_add_pd(_mm_set1_pd(p.zi0), _mm_mul_pd(_mm_set1_pd(p.dzi), pos));
  const __m128d z = _mm_div_pd(_mm_set1_pd(1.0), _mm_max_pd(zi, _mm_set1_pd(kMinZi)));  // NaN -> kMinZi
  const __m128d tu = _mm_add_pd(_mm_set1_pd(p.uz0), _mm_mul_pd(_mm_set1_pd(p.duz), pos));
  const __m128d tv = _mm_add_pd(_mm_set1_pd(p.vz0), _mm_mul_pd(_mm_set1_pd(p.dvz), pos));
  const __m128d k = _mm_set1_pd(65536.0), zero = _mm_setzero_pd();
  // max(q, 0): NaN -> 0 (maxpd returns its second operand when either is NaN).
  const __m128d qu = _mm_min_pd(_mm_max_pd(_mm_mul_pd(_mm_mul_pd(tu, z), k), zero), umax);
  const __m128d qv = _mm_min_pd(_mm_max_pd(_mm_mul_pd(_mm_mul_pd(tv, z), k), zero), vmax);
  const __m128i iu = _mm_cvttpd_epi32(qu), iv = _mm_cvttpd_epi32(qv);  // [x0, x1, 0, 0]
  const __m128i uv = _mm_unpacklo_epi64(iu, iv);                        // [u0, u1, v0, v1]
  Samples2 s;
  s.u0 = _mm_cvtsi128_si32(uv);
  s.u1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(uv, 1));
  s.v0 = _mm_cvtsi128_si32(_mm_shuffle_epi32(uv, 2));
  s.v1 = _mm_cvtsi128_si32(_mm_shuffle_epi32(uv, 3));
  s.z = z;
  return s;
}

SB_INLINE double lane0(__m128d x) { return _mm_cvtsd_f64(x); }
SB_INLINE double lane1(__m128d x) { return _mm_cvtsd_f64(_mm_unpackhi_pd(x, x)); }

// A full run's steps from a to b (steps16_sel for u and v: ddf = -2 (delta / 16 * curve)).
SB_INLINE void steps16_uv_x86(int32_t au, int32_t bu, int32_t av, int32_t bv, double curve, RunSteps* su,
                              RunSteps* sv) {
  const int32_t du = bu - au, dv = bv - av;
  const __m128d d = _mm_set_pd(double(dv), double(du));
  const __m128d f = _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(d, _mm_set1_pd(0.0625)), _mm_set1_pd(curve)), _mm_set1_pd(-2.0));
  const __m128i i = _mm_cvttpd_epi32(f);  // cvt_sat: 0x80000000 when out of range or NaN
  *su = steps16_dd(du, _mm_cvtsi128_si32(i));
  *sv = steps16_dd(dv, _mm_cvtsi128_si32(_mm_shuffle_epi32(i, 1)));
}

// The last run's steps (steps = 0 .. 15 pixels between a and b): last_steps_q, its two
// quotients in one divide.
SB_INLINE void last_uv_x86(int steps, int32_t au, int32_t bu, int32_t av, int32_t bv, double curve, RunSteps* su,
                           RunSteps* sv) {
  const int32_t du = bu - au, dv = bv - av;
  const double s = double(steps > 1 ? steps : 1);
  const __m128d q = _mm_div_pd(_mm_set_pd(double(dv), double(du)), _mm_set1_pd(s));
  last_steps_q(steps, du, dv, lane0(q), lane1(q), curve, su, sv);
}

// One second-order span of 1 .. kX86ShortMax pixels (dzi != 0), as persp_fast<true> draws it.
SB_INLINE void persp_short_x86(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const PerspSpan& p) {
  const double P = p.px0, zc = p.dzi;
  const __m128d umax = _mm_set1_pd(double(p.umax)), vmax = _mm_set1_pd(double(p.vmax));
  if (n <= 16) {  // one run: samples at pixels 0 and n - 1
    const Samples2 a = samples2_x86(p, _mm_set_pd(P + double(n - 1), P), umax, vmax);
    const double curve = zc * 0.5 * (lane0(a.z) + lane1(a.z));
    RunSteps su, sv;
    last_uv_x86(n - 1, a.u0, a.u1, a.v0, a.v1, curve, &su, &sv);
    if (n == 16) {
      draw16<true>(dest, texels, w, a.u0, a.v0, su, sv);
    } else {
      draw_last<true>(dest, n, texels, w, uint32_t(a.u0), uint32_t(a.v0), uint32_t(su.d), uint32_t(sv.d),
                      uint32_t(su.dd), uint32_t(sv.dd));
    }
    return;
  }
  // Samples 0, 1 (pixels 0, 16) and 2, 3: pixels min(32, n - 1) from P_0, and (for n > 32)
  // min(32, n - 17) from P_1 = P_0 + 16.
  const double P1 = P + double(16);
  const Samples2 a = samples2_x86(p, _mm_set_pd(P1, P), umax, vmax);
  const int o2 = n - 1 < 32 ? n - 1 : 32;
  const Samples2 b = samples2_x86(p, _mm_set_pd(P1 + double(n - 17), P + double(o2)), umax, vmax);
  const double c0 = zc * 0.5 * (lane0(a.z) + lane1(a.z));
  RunSteps su0, sv0;
  steps16_uv_x86(a.u0, a.u1, a.v0, a.v1, c0, &su0, &sv0);
  draw16<true>(dest, texels, w, a.u0, a.v0, su0, sv0);
  // The last run: from sample 1 to 2 (n <= 32), or run 1 (samples 1 to 2) and then 2 to 3.
  int32_t lu0 = a.u1, lv0 = a.v1, lu1 = b.u0, lv1 = b.v0;
  double lz0 = lane1(a.z), lz1 = lane0(b.z);
  int last = n - 16;
  dest += 16;
  if (n > 32) {
    const double c1 = zc * 0.5 * (lane1(a.z) + lane0(b.z));
    RunSteps su1, sv1;
    steps16_uv_x86(a.u1, b.u0, a.v1, b.v0, c1, &su1, &sv1);
    draw16<true>(dest, texels, w, a.u1, a.v1, su1, sv1);
    dest += 16;
    last -= 16;
    lu0 = b.u0, lv0 = b.v0, lu1 = b.u1, lv1 = b.v1;
    lz0 = lane0(b.z), lz1 = lane1(b.z);
  }
  const double curve = zc * 0.5 * (lz0 + lz1);
  RunSteps su, sv;
  last_uv_x86(last - 1, lu0, lu1, lv0, lv1, curve, &su, &sv);
  if (last == 16) {
    draw16<true>(dest, texels, w, lu0, lv0, su, sv);
  } else {
    draw_last<true>(dest, last, texels, w, uint32_t(lu0), uint32_t(lv0), uint32_t(su.d), uint32_t(sv.d),
                    uint32_t(su.dd), uint32_t(sv.dd));
  }
}

}  // namespace
}  // namespace sb::simd
#endif
