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

// Two samples at positions pos = [x0, x1]: the clamped 16.16 values iuv = [u0, v0, u1, v1]
// (int32 lanes) and the depths z = [z0, z1].
struct Samples2 {
  __m128i iuv;
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
  return Samples2{_mm_unpacklo_epi32(_mm_cvttpd_epi32(qu), _mm_cvttpd_epi32(qv)), z};
}

SB_INLINE double lane0(__m128d x) { return _mm_cvtsd_f64(x); }
SB_INLINE double lane1(__m128d x) { return _mm_cvtsd_f64(_mm_unpackhi_pd(x, x)); }
template <int L>
SB_INLINE int32_t ilane(__m128i x) {
  if constexpr (L == 0) return _mm_cvtsi128_si32(x);
  return _mm_cvtsi128_si32(_mm_shuffle_epi32(x, L));
}

// A full run's steps from a = [ua, va, ..] to b = [ub, vb, ..] (steps16_sel for u and v:
// ddf = -2 (delta / 16 * curve); delta / 16 exact as delta * 0.0625).
SB_INLINE void steps16_uv_x86(__m128i a, __m128i b, double curve, RunSteps* su, RunSteps* sv) {
  const __m128i d = _mm_sub_epi32(b, a);  // [du, dv, ..]: 0 <= u, v < 2^31, no overflow
  const __m128d f =
      _mm_mul_pd(_mm_mul_pd(_mm_mul_pd(_mm_cvtepi32_pd(d), _mm_set1_pd(0.0625)), _mm_set1_pd(curve)), _mm_set1_pd(-2.0));
  const __m128i i = _mm_cvttpd_epi32(f);  // cvt_sat: 0x80000000 when out of range or NaN
  *su = steps16_dd(ilane<0>(d), ilane<0>(i));
  *sv = steps16_dd(ilane<1>(d), ilane<1>(i));
}

// The last run's steps (steps = 0 .. 15 pixels from a = [ua, va, ..] to b): last_steps_q with
// both quotients delta / max(steps, 1) in one divpd, both conversions in one cvttpd2dq, and
// the range test -1e9 < ddf < 1e9 on the converted value (last_ddi's: |trunc(ddf)| < 1e9
// iff |ddf| < 1e9; out of range and NaN convert to 0x80000000, rejected too), two lanes
// compared at once. In two parts: the vector part (last_vec_x86: delta, trunc(q) and the
// range-masked dd as int32 lanes [u, v, ..]) and last_dd's integer part (last_int_x86).
struct LastVec {
  __m128i d, lin, dd;
};
SB_INLINE LastVec last_vec_x86(int steps, __m128i a, __m128i b, double curve) {
  const __m128i d = _mm_sub_epi32(b, a);  // 0 <= u, v < 2^31: no overflow
  const __m128d q = _mm_div_pd(_mm_cvtepi32_pd(d), _mm_set1_pd(double(steps > 1 ? steps : 1)));
  const __m128i lin = _mm_cvttpd_epi32(q);  // trunc(q): delta / steps truncated
  const __m128i fi = _mm_cvttpd_epi32(_mm_mul_pd(_mm_mul_pd(q, _mm_set1_pd(curve)), _mm_set1_pd(-2.0)));
  const __m128i ok = _mm_and_si128(_mm_cmpgt_epi32(fi, _mm_set1_epi32(-1000000000)),
                                   _mm_cmplt_epi32(fi, _mm_set1_epi32(1000000000)));
  // steps > 1 as a mask without a branch: 1 - steps < 0 (steps = 0 .. 15).
  return LastVec{d, lin, _mm_and_si128(_mm_and_si128(fi, ok), _mm_set1_epi32((1 - steps) >> 31))};
}
SB_INLINE void last_int_x86(int steps, const LastVec& l, RunSteps* su, RunSteps* sv) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  *su = last_dd(ilane<0>(l.d), ilane<0>(l.lin), ilane<0>(l.dd), s, T);
  *sv = last_dd(ilane<1>(l.d), ilane<1>(l.lin), ilane<1>(l.dd), s, T);
}
// Keeps x computed before this point (an empty asm that takes it in a register).
SB_INLINE void pin_x86(__m128i& x) { __asm__ volatile("" : "+x"(x)); }
// The last run's steps (last_int_x86) and pixels from l, the run of `last` = 1 .. 16 pixels
// starting at start = [u, v, ..]. The integer steps inside each branch (pinned: the compiler
// hoists common code above a branch otherwise): bench/count.sh times each block alone as a
// loop, so the block holding the two divides' latency chain then ends after the quotients.
SB_INLINE void last_run_x86(uint8_t* dest, int last, const uint8_t* texels, uint32_t w, __m128i start, LastVec l) {
  const int32_t u0 = ilane<0>(start), v0 = ilane<1>(start);
  RunSteps su, sv;
  if (last == 16) {
    pin_x86(l.d), pin_x86(l.lin), pin_x86(l.dd);
    last_int_x86(15, l, &su, &sv);
    draw16<true>(dest, texels, w, u0, v0, su, sv);
  } else {
    pin_x86(l.d), pin_x86(l.lin), pin_x86(l.dd);
    last_int_x86(last - 1, l, &su, &sv);
    draw_last<true>(dest, last, texels, w, uint32_t(u0), uint32_t(v0), uint32_t(su.d), uint32_t(sv.d), uint32_t(su.dd),
                    uint32_t(sv.dd));
  }
}

// The span's fields loaded after this point, in the block that uses them (a compiler memory
// barrier: no code). bench/count.sh times each block as a loop, llvm-mca carrying a register
// the block reads and later overwrites from one iteration to the next: fields loaded into
// registers in the dispatch blocks made the two divides one chain across iterations (Skylake
// 83 cycles for the one-run block's 83 instructions).
SB_INLINE void barrier_x86() { __asm__ volatile("" ::: "memory"); }

// One second-order span of 1 .. kX86ShortMax pixels (dzi != 0), as persp_fast<true> draws it.
SB_INLINE void persp_short_x86(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const PerspSpan& p) {
  if (n <= 16) {  // one run: samples at pixels 0 and n - 1
    barrier_x86();
    const double P = p.px0, zc = p.dzi;
    const __m128d umax = _mm_set1_pd(double(p.umax)), vmax = _mm_set1_pd(double(p.vmax));
    const Samples2 a = samples2_x86(p, _mm_set_pd(P + double(n - 1), P), umax, vmax);
    const double curve = zc * 0.5 * (lane0(a.z) + lane1(a.z));
    last_run_x86(dest, n, texels, w, a.iuv, last_vec_x86(n - 1, a.iuv, _mm_srli_si128(a.iuv, 8), curve));
    return;
  }
  // Samples 0, 1 (pixels 0, 16) and 2, 3: pixels min(32, n - 1) from P_0, and (for n > 32)
  // min(32, n - 17) from P_1 = P_0 + 16.
  barrier_x86();
  const double P = p.px0, zc = p.dzi;
  const __m128d umax = _mm_set1_pd(double(p.umax)), vmax = _mm_set1_pd(double(p.vmax));
  const double P1 = P + double(16);
  const Samples2 a = samples2_x86(p, _mm_set_pd(P1, P), umax, vmax);
  const int o2 = n - 1 < 32 ? n - 1 : 32;
  const Samples2 b = samples2_x86(p, _mm_set_pd(P1 + double(n - 17), P + double(o2)), umax, vmax);
  const __m128i s0 = a.iuv, s1 = _mm_srli_si128(a.iuv, 8), s2 = b.iuv, s3 = _mm_srli_si128(b.iuv, 8);
  const double c0 = zc * 0.5 * (lane0(a.z) + lane1(a.z));
  RunSteps su0, sv0;
  steps16_uv_x86(s0, s1, c0, &su0, &sv0);
  draw16<true>(dest, texels, w, ilane<0>(s0), ilane<1>(s0), su0, sv0);
  // The last run: from sample 1 to 2 (n <= 32), or run 1 (samples 1 to 2) and then 2 to 3.
  __m128i la = s1, lb = s2;
  double lz0 = lane1(a.z), lz1 = lane0(b.z);
  int last = n - 16;
  dest += 16;
  if (n > 32) {
    const double c1 = zc * 0.5 * (lane1(a.z) + lane0(b.z));
    RunSteps su1, sv1;
    steps16_uv_x86(s1, s2, c1, &su1, &sv1);
    draw16<true>(dest, texels, w, ilane<0>(s1), ilane<1>(s1), su1, sv1);
    dest += 16;
    last -= 16;
    la = s2, lb = s3;
    lz0 = lane0(b.z), lz1 = lane1(b.z);
  }
  const double curve = zc * 0.5 * (lz0 + lz1);
  last_run_x86(dest, last, texels, w, la, last_vec_x86(last - 1, la, lb, curve));
}

}  // namespace
}  // namespace sb::simd
#endif
