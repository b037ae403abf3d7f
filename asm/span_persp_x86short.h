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
// From samples a = [ua, va, ..], b = [ub, vb, ..] and their depths z = [za, zb]. In one asm
// statement, for the reason last_int_x86 gives (inputs read, never written; GCC's code
// carried the curve's register through the divide from one llvm-mca iteration to the next).
// The operations, each the C++'s: d = b - a; q = double(d) / double(s) (s = max(steps, 1));
// lin = trunc(q); curve = (zc * 0.5) * (za + zb) (the walker's zix * 0.5 * (z0 + z1));
// fi = trunc((q * curve) * -2.0); dd = fi where -1e9 < fi < 1e9 and steps > 1, else 0.
SB_INLINE LastVec last_vec_x86(int steps, __m128i a, __m128i b, __m128d z, double zc) {
  const double sd = double(steps > 1 ? steps : 1);
  const int32_t two = (1 - steps) >> 31;  // steps > 1 as a mask (steps = 0 .. 15)
  static const double kHalf = 0.5;
  static const __m128d kMinus2 = {-2.0, -2.0};
  static const __m128i kLo = {int64_t(0xc4653601c4653601ull), int64_t(0xc4653601c4653601ull)};  // -999999999
  static const __m128i kHi = {int64_t(0x3b9aca003b9aca00ull), int64_t(0x3b9aca003b9aca00ull)};  // 1000000000
  __m128i d, lin, dd, t1, t2;
  __m128d q, t, c;
  __asm__(
      "movdqa %[b], %[d]\n\t"
      "movapd %[sd], %[t]\n\t"
      "psubd %[a], %[d]\n\t"                  // [du, dv, ..]
      "unpcklpd %[t], %[t]\n\t"
      "cvtdq2pd %[d], %[q]\n\t"
      "movapd %[z], %[c]\n\t"
      "divpd %[t], %[q]\n\t"                  // [du / s, dv / s]
      "unpckhpd %[c], %[c]\n\t"
      "movapd %[zc], %[t]\n\t"
      "addsd %[z], %[c]\n\t"                  // zb + za
      "mulsd %[half], %[t]\n\t"               // zc * 0.5
      "mulsd %[c], %[t]\n\t"                  // curve
      "movd %[two], %[t2]\n\t"
      "unpcklpd %[t], %[t]\n\t"
      "pshufd $0, %[t2], %[t2]\n\t"
      "cvttpd2dq %[q], %[lin]\n\t"
      "mulpd %[q], %[t]\n\t"                  // q * curve
      "mulpd %[m2], %[t]\n\t"                 // * -2
      "cvttpd2dq %[t], %[dd]\n\t"             // fi
      "movdqa %[dd], %[t1]\n\t"
      "pand %[t2], %[dd]\n\t"
      "movdqa %[hi], %[t2]\n\t"
      "pcmpgtd %[lo], %[t1]\n\t"              // fi > -1e9 (fi >= -999999999)
      "pcmpgtd %[dd], %[t2]\n\t"              // 1e9 > fi
      "pand %[t1], %[dd]\n\t"
      "pand %[t2], %[dd]"
      : [d] "=&x"(d), [lin] "=&x"(lin), [dd] "=&x"(dd), [t1] "=&x"(t1), [t2] "=&x"(t2), [q] "=&x"(q), [t] "=&x"(t),
        [c] "=&x"(c)
      : [a] "x"(a), [b] "x"(b), [z] "x"(z), [zc] "x"(zc), [sd] "x"(sd), [two] "r"(two), [half] "m"(kHalf),
        [m2] "m"(kMinus2), [lo] "m"(kLo), [hi] "m"(kHi));
  return LastVec{d, lin, dd};
}
// last_dd for u and v in SSE2 lanes (lanes 0 and 2 of [u, u, v, v], pmuludq's), its
// operations in the same order on the same 32-bit values; T |dd| <= pd on the 64-bit
// product (pmuludq, psubq: T |dd| < 2^37) by the sign of pd - T |dd|. Returns the steps
// packed as draw16 and draw_last take them (pack_steps: v 2^32 + u, u sign-extended).
struct StepsPacked {
  uint64_t d, dd;
};
SB_INLINE uint64_t pack_lanes02(__m128i x) {  // lanes 0, 2 as pack_steps(lane 2, lane 0)
  const __m128i uv = _mm_shuffle_epi32(x, _MM_SHUFFLE(3, 3, 2, 0));  // [u, v, ..]
  const __m128i su = _mm_slli_si128(_mm_srai_epi32(uv, 31), 4);       // [0, u < 0 ? -1 : 0, ..]
  return uint64_t(_mm_cvtsi128_si64(_mm_add_epi32(uv, su)));
}
SB_INLINE StepsPacked last_int_x86(int steps, const LastVec& l) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  // In one asm statement: its inputs (the lanes [u, v, ..] of l) are read, never written,
  // and every temporary is its own register, so llvm-mca (bench/count.sh), which times the
  // block as a loop, sees no register carried from one iteration to the next (GCC's
  // allocation reused the inputs' registers for the results: a false chain through the
  // whole block, znver3 23 cycles for its 70 instructions). Per lane pair (u in lanes 0
  // and 1, v in 2 and 3 after pshufd 0x50), last_dd's operations as in the C++ above:
  //   sg = delta >> 31; pd = |delta|; pdd = dd mirrored by sg; add = |dd|
  //   reject = sign(pd - add T) (64-bit: pmuludq, psubq; pd zero-extended)
  //   Q = lin mirrored; r = pd - s Q; m = (s - 1) pdd; c = 2 r < s
  //   d0 = Q - (m >> 1) - (m & c & 1); d = reject ? lin : d0 mirrored; dd = reject ? 0 : dd
  // then lanes 0 and 2 packed (pack_steps: the v lane + the u lane's sign, above u).
  uint64_t od, odd;
  __m128i t0, t1, t2, t3, t4, t5, t6, t7;
  __asm__(
      "pshufd $0x50, %[d], %[t0]\n\t"         // delta
      "pshufd $0x50, %[dd], %[t1]\n\t"        // ddi
      "pshufd $0x50, %[lin], %[t2]\n\t"       // lin
      "movd %[T], %[t5]\n\t"
      "movdqa %[t0], %[t3]\n\t"
      "psrad $31, %[t3]\n\t"                  // sg
      "movdqa %[t1], %[t4]\n\t"
      "psrad $31, %[t4]\n\t"                  // sd
      "pshufd $0, %[t5], %[t5]\n\t"           // T
      "pxor %[t3], %[t0]\n\t"
      "movdqa %[t1], %[t6]\n\t"
      "pxor %[t4], %[t6]\n\t"
      "psubd %[t3], %[t0]\n\t"                // pd
      "psubd %[t4], %[t6]\n\t"                // add = |dd|
      "movd %[s], %[t7]\n\t"
      "pmuludq %[t5], %[t6]\n\t"              // add T (64-bit lanes)
      "pshufd $0, %[t7], %[t7]\n\t"           // s
      "movdqa %[t0], %[t4]\n\t"
      "pand %[lo], %[t4]\n\t"                 // pd zero-extended
      "movdqa %[t2], %[t5]\n\t"
      "psubq %[t6], %[t4]\n\t"                // pd - add T
      "pxor %[t3], %[t5]\n\t"
      "psrad $31, %[t4]\n\t"
      "psubd %[t3], %[t5]\n\t"                // Q
      "pshufd $0xf5, %[t4], %[t4]\n\t"        // reject, both halves of each lane pair
      "movdqa %[t5], %[t6]\n\t"
      "pmuludq %[t7], %[t6]\n\t"              // s Q (low halves)
      "psubd %[t6], %[t0]\n\t"                // r = pd - s Q
      "movdqa %[t1], %[t6]\n\t"
      "pxor %[t3], %[t6]\n\t"
      "paddd %[t0], %[t0]\n\t"                // 2 r
      "psubd %[t3], %[t6]\n\t"                // pdd
      "pmuludq %[sm1], %[t6]\n\t"             // m = (s - 1) pdd (low halves)
      "pcmpgtd %[t0], %[t7]\n\t"              // c = s > 2 r
      "pand %[t6], %[t7]\n\t"
      "psrad $1, %[t6]\n\t"
      "pand %[one], %[t7]\n\t"                // m & c & 1
      "psubd %[t6], %[t5]\n\t"
      "psubd %[t7], %[t5]\n\t"                // d0
      "movdqa %[t4], %[t6]\n\t"
      "pxor %[t3], %[t5]\n\t"
      "pand %[t4], %[t2]\n\t"                 // reject & lin
      "psubd %[t3], %[t5]\n\t"                // d0 mirrored back
      "pandn %[t1], %[t4]\n\t"                // dd = ~reject & ddi
      "pandn %[t5], %[t6]\n\t"                // ~reject & d0
      "pshufd $0xf8, %[t4], %[t4]\n\t"        // [ddu, ddv, ..]
      "por %[t2], %[t6]\n\t"                  // d
      "movdqa %[t4], %[t0]\n\t"
      "pshufd $0xf8, %[t6], %[t6]\n\t"        // [du, dv, ..]
      "psrad $31, %[t0]\n\t"
      "movdqa %[t6], %[t7]\n\t"
      "pslldq $4, %[t0]\n\t"
      "psrad $31, %[t7]\n\t"
      "paddd %[t4], %[t0]\n\t"
      "pslldq $4, %[t7]\n\t"
      "movq %[t0], %[odd]\n\t"
      "paddd %[t6], %[t7]\n\t"
      "movq %[t7], %[od]"
      : [od] "=r"(od), [odd] "=r"(odd), [t0] "=&x"(t0), [t1] "=&x"(t1), [t2] "=&x"(t2), [t3] "=&x"(t3),
        [t4] "=&x"(t4), [t5] "=&x"(t5), [t6] "=&x"(t6), [t7] "=&x"(t7)
      : [d] "x"(l.d), [dd] "x"(l.dd), [lin] "x"(l.lin), [T] "r"(T), [s] "r"(s),
        [sm1] "x"(_mm_set1_epi32(int32_t(s - 1))), [lo] "x"(_mm_set_epi32(0, -1, 0, -1)), [one] "x"(_mm_set1_epi32(1)));
  return StepsPacked{od, odd};
}
// draw_last<true> from packed values (tail_pos's): x = v 2^32 + u, d and dd as pack_steps.
SB_INLINE void draw_last_packed(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w,
                                TailPos p) {
  auto chunk = [&](auto cc) SB_LAMBDA_INLINE {
    constexpr int C = decltype(cc)::value;
    uint8_t t[C];
    p = tail_load<C, true>(t, texels, w, p);
    tail_store<C>(dest, t);
    dest += C;
  };
  if (n & 8) chunk(std::integral_constant<int, 8>{});
  if (n & 4) chunk(std::integral_constant<int, 4>{});
  if (n & 2) chunk(std::integral_constant<int, 2>{});
  if (n & 1) chunk(std::integral_constant<int, 1>{});
}
// Keeps x computed before this point (an empty asm that takes it in a register).
SB_INLINE void pin_x86(__m128i& x) { __asm__ volatile("" : "+x"(x)); }
// The last run's steps (last_int_x86) and pixels from l, the run of `last` = 1 .. 16 pixels
// starting at start = [u, v, ..]. The integer steps inside each branch (pinned: the compiler
// hoists common code above a branch otherwise): bench/count.sh times each block alone as a
// loop, so the block holding the two divides' latency chain then ends after the quotients.
SB_INLINE void last_run_x86(uint8_t* dest, int last, const uint8_t* texels, uint32_t w, __m128i start, LastVec l) {
  const uint64_t x = uint64_t(_mm_cvtsi128_si64(start));  // v0 2^32 + u0 (both >= 0)
  if (last == 16) {
    pin_x86(l.d), pin_x86(l.lin), pin_x86(l.dd);
    const StepsPacked st = last_int_x86(15, l);
    Run16<true>(x, st.d, st.dd, Run16<true>::Packed{}).draw(dest, texels, w);
  } else {
    pin_x86(l.d), pin_x86(l.lin), pin_x86(l.dd);
    const StepsPacked st = last_int_x86(last - 1, l);
    draw_last_packed(dest, last, texels, w, TailPos{x, st.d, st.dd});
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
    last_run_x86(dest, n, texels, w, a.iuv, last_vec_x86(n - 1, a.iuv, _mm_srli_si128(a.iuv, 8), a.z, zc));
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
  __m128d lz = _mm_shuffle_pd(a.z, b.z, 1);  // [z_1, z_2]
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
    lz = b.z;
  }
  last_run_x86(dest, last, texels, w, la, last_vec_x86(last - 1, la, lb, lz, zc));
}

}  // namespace
}  // namespace sb::simd
#endif
