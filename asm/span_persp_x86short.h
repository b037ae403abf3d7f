// asm/span_persp_x86short.h: x86-64 only, the batch entry's short second-order spans
// (asm/span_persp.h: second_order with dzi != 0, 1 .. kX86ShortMax pixels), drawn by
// persp_short_x86 inlined into short_run_x86 (asm/span_persp_fast.cpp: one call a run of such
// items, not one per span), so none of persp_fast's prologue and epilogue per span (six
// pushes, a 0x128-byte frame: llvm-mca times that epilogue alone at 37 cycles on Skylake)
// and none of run_steps_uv's out-of-line jump table. Internal: included by
// asm/span_persp_fast.cpp only (asm/span_persp_run.h's runs and steps16_dd).
//
// The walker's arithmetic (asm/span_walk.h), the same bits: the samples at pixel offsets
// o_j = min(16 j, n - 1), their positions as the walker accumulates them (P_0 + o_1 for
// j = 1, P_{j-2} + (o_j - o_{j-2}) after); z = 1 / max(zi, 1e-9) (NaN -> 1e-9), to_fixed in
// select form (max(q, 0) with NaN -> 0, then min(q, max), truncated: to_fixed_sel). The
// samples two at a time in SSE2's two double lanes (mulpd, addpd, maxpd, divpd: each lane the
// scalar operation's IEEE result), so one divide instruction gives two reciprocals. Full runs'
// steps are steps16_sel's (ddf in persp_fast's loop's form), the last run's last_steps_q's
// (asm/span_persp_arm.h; the quotients delta / steps of u and v in one divpd, last_dd for
// both in SSE2 lanes).
// A last run of one pixel draws its start only: the sample after it (computed at some
// position, clamped like any other) is then never used.
#pragma once
#if defined(__x86_64__) && defined(__GNUC__) && defined(__SSE2__)
#include <emmintrin.h>

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

// A full run's steps from a = [ua, va, ..] to b = [ub, vb, ..] (steps16_sel for u and v),
// ddf = -2 (delta / 16 * curve) as delta * ck with ck = (zc * -1/16) * (za + zb), the same
// bits (persp_fast's loop computes it so; the argument is there, asm/span_persp_fast.cpp):
// one multiply after the conversion.
SB_INLINE void steps16_uv_x86(__m128i a, __m128i b, double ck, RunSteps* su, RunSteps* sv) {
  const __m128i d = _mm_sub_epi32(b, a);  // [du, dv, ..]: 0 <= u, v < 2^31, no overflow
  const __m128d f = _mm_mul_pd(_mm_cvtepi32_pd(d), _mm_set1_pd(ck));
  const __m128i i = _mm_cvttpd_epi32(f);  // cvt_sat: 0x80000000 when out of range or NaN
  *su = steps16_dd(ilane<0>(d), ilane<0>(i));
  *sv = steps16_dd(ilane<1>(d), ilane<1>(i));
}

// The last run's steps (steps = 0 .. 15 pixels from sample a = [ua, va, ..] to b = [ub, vb,
// ..], their depths z = [za, zb]): last_steps_q's (asm/span_persp_arm.h), u and v in SSE2
// lanes, returned packed as draw16 and draw_last take them (pack_steps: v 2^32 + u, u
// sign-extended). One asm statement: its inputs are read, never written, its temporaries are
// xmm7 .. xmm15 (clobbered: no input there) and its outputs early-clobbered (steps passed
// too, so that they do not take its register either): llvm-mca (bench/count.sh), which times
// each block as a loop, then sees no register carried through the block from one iteration
// to the next (GCC's allocation had reused the inputs' registers for later values: a false
// chain through the divide, znver3 23 cycles for 70 instructions). The operations, each the
// C++'s:
//   d = b - a; q = double(d) / double(s), s = max(steps, 1) (both quotients in one divpd);
//   lin = trunc(q); curve = (zc * 0.5) * (za + zb) (the walker's zix * 0.5 * (z0 + z1));
//   fi = trunc(q * (curve * -2.0)); dd = fi where -1e9 < fi < 1e9 and steps > 1, else 0
//   (last_ddi's range test on the converted value: |trunc(ddf)| < 1e9 iff |ddf| < 1e9; out
//   of range and NaN convert to 0x80000000, rejected too). q * (curve * -2) for the walker's
//   (q * curve) * -2, so that the multiply by -2 runs beside the divide: the same dd. Scaling
//   by -2 is exact and commutes with rounding, so both are -2 RN(q curve) when q curve is
//   normal and 2 q curve finite; |q curve| < 2^-1021 (subnormal, 0) truncates to 0 either
//   way; an overflow in either form (curve * -2, q curve or its double) leaves |ddf| >= 1e9
//   or inf in both (|q| >= 1 / 15 when q != 0), rejected; q = 0 with curve * -2 infinite
//   gives NaN, rejected, where the walker's gives 0: dd 0 both; NaN or infinite curve: the
//   same NaN or infinity in both;
// then last_dd per lane pair (u in lanes 0 and 1, v in 2 and 3 after pshufd 0x50; pmuludq
// uses lanes 0 and 2), its operations in the same order on the same 32-bit values:
//   sg = delta >> 31; pd = |delta|; pdd = dd mirrored by sg; add = |dd|
//   reject = sign(pd - add T) (64-bit: pmuludq, psubq, pd zero-extended; T |dd| < 2^37)
//   Q = lin mirrored; r = pd - s Q; m = (s - 1) pdd; c = 2 r < s
//   d0 = Q - (m >> 1) - (m & c & 1); d = reject ? lin : d0 mirrored; dd = reject ? 0 : dd
// and lanes 0 and 2 packed (the v lane plus the u lane's sign, above u).
struct StepsPacked {
  uint64_t d, dd;
};
SB_INLINE StepsPacked last_steps_x86(int steps, __m128i a, __m128i b, __m128d z, double zc) {
  const uint32_t s = uint32_t(steps > 1 ? steps : 1), T = uint32_t(steps * (steps - 1)) >> 1;
  const double sd = double(int32_t(s));
  const int32_t two = (1 - steps) >> 31;  // steps > 1 as a mask (steps = 0 .. 15)
  static const double kHalf = 0.5;
  static const __m128d kMinus2 = {-2.0, -2.0};
  static const __m128i kLo = {int64_t(0xc4653601c4653601ull), int64_t(0xc4653601c4653601ull)};  // -999999999
  static const __m128i kHi = {int64_t(0x3b9aca003b9aca00ull), int64_t(0x3b9aca003b9aca00ull)};  // 1000000000
  static const __m128i kLow32 = {int64_t(0xffffffffull), int64_t(0xffffffffull)};  // lanes 0, 2
  static const __m128i kOnes = {int64_t(0x100000001ull), int64_t(0x100000001ull)};
  uint64_t od, odd;
  __asm__(
      "movdqa %[b], %%xmm8\n\t"
      "movapd %[sd], %%xmm10\n\t"
      "psubd %[a], %%xmm8\n\t"              // d = [du, dv, ..]
      "unpcklpd %%xmm10, %%xmm10\n\t"
      "cvtdq2pd %%xmm8, %%xmm9\n\t"
      "movapd %[z], %%xmm11\n\t"
      "divpd %%xmm10, %%xmm9\n\t"           // q = [du / s, dv / s]
      "unpckhpd %%xmm11, %%xmm11\n\t"
      "movapd %[zc], %%xmm10\n\t"
      "addsd %[z], %%xmm11\n\t"             // zb + za
      "mulsd %[half], %%xmm10\n\t"          // zc * 0.5
      "mulsd %%xmm11, %%xmm10\n\t"          // curve
      "movd %[two], %%xmm15\n\t"
      "unpcklpd %%xmm10, %%xmm10\n\t"
      "pshufd $0, %%xmm15, %%xmm15\n\t"
      "mulpd %[m2], %%xmm10\n\t"            // curve * -2 (beside the divide)
      "cvttpd2dq %%xmm9, %%xmm12\n\t"       // lin = trunc(q)
      "mulpd %%xmm9, %%xmm10\n\t"           // q * (curve * -2)
      "cvttpd2dq %%xmm10, %%xmm13\n\t"      // fi
      "movdqa %%xmm13, %%xmm14\n\t"
      "pand %%xmm15, %%xmm13\n\t"
      "movdqa %[hi], %%xmm15\n\t"
      "pcmpgtd %[lo], %%xmm14\n\t"          // fi > -1e9 (fi >= -999999999)
      "pcmpgtd %%xmm13, %%xmm15\n\t"        // 1e9 > fi
      "pand %%xmm14, %%xmm13\n\t"
      "pand %%xmm15, %%xmm13\n\t"           // dd
      "pshufd $0x50, %%xmm8, %%xmm8\n\t"     // delta
      "pshufd $0x50, %%xmm13, %%xmm9\n\t"    // ddi
      "pshufd $0x50, %%xmm12, %%xmm10\n\t"   // lin
      "movd %[T], %%xmm13\n\t"
      "movdqa %%xmm8, %%xmm11\n\t"
      "psrad $31, %%xmm11\n\t"                // sg
      "movdqa %%xmm9, %%xmm12\n\t"
      "psrad $31, %%xmm12\n\t"                // sd
      "pshufd $0, %%xmm13, %%xmm13\n\t"       // T
      "pxor %%xmm11, %%xmm8\n\t"
      "movdqa %%xmm9, %%xmm14\n\t"
      "pxor %%xmm12, %%xmm14\n\t"
      "psubd %%xmm11, %%xmm8\n\t"             // pd
      "psubd %%xmm12, %%xmm14\n\t"            // add = |dd|
      "movd %[s], %%xmm15\n\t"
      "pmuludq %%xmm13, %%xmm14\n\t"          // add T (64-bit lanes)
      "pshufd $0, %%xmm15, %%xmm15\n\t"       // s
      "movdqa %%xmm15, %%xmm7\n\t"
      "psubd %[one], %%xmm7\n\t"              // s - 1
      "movdqa %%xmm8, %%xmm12\n\t"
      "pand %[low32], %%xmm12\n\t"            // pd zero-extended
      "movdqa %%xmm10, %%xmm13\n\t"
      "psubq %%xmm14, %%xmm12\n\t"            // pd - add T
      "pxor %%xmm11, %%xmm13\n\t"
      "psrad $31, %%xmm12\n\t"
      "psubd %%xmm11, %%xmm13\n\t"            // Q
      "pshufd $0xf5, %%xmm12, %%xmm12\n\t"    // reject, both halves of each lane pair
      "movdqa %%xmm13, %%xmm14\n\t"
      "pmuludq %%xmm15, %%xmm14\n\t"          // s Q (low halves)
      "psubd %%xmm14, %%xmm8\n\t"             // r = pd - s Q
      "movdqa %%xmm9, %%xmm14\n\t"
      "pxor %%xmm11, %%xmm14\n\t"
      "paddd %%xmm8, %%xmm8\n\t"              // 2 r
      "psubd %%xmm11, %%xmm14\n\t"            // pdd
      "pmuludq %%xmm7, %%xmm14\n\t"           // m = (s - 1) pdd (low halves)
      "pcmpgtd %%xmm8, %%xmm15\n\t"           // c = s > 2 r
      "pand %%xmm14, %%xmm15\n\t"
      "psrad $1, %%xmm14\n\t"
      "pand %[one], %%xmm15\n\t"              // m & c & 1
      "psubd %%xmm14, %%xmm13\n\t"
      "psubd %%xmm15, %%xmm13\n\t"            // d0
      "movdqa %%xmm12, %%xmm14\n\t"
      "pxor %%xmm11, %%xmm13\n\t"
      "pand %%xmm12, %%xmm10\n\t"             // reject & lin
      "psubd %%xmm11, %%xmm13\n\t"            // d0 mirrored back
      "pandn %%xmm9, %%xmm12\n\t"             // dd = ~reject & ddi
      "pandn %%xmm13, %%xmm14\n\t"            // ~reject & d0
      "pshufd $0xf8, %%xmm12, %%xmm12\n\t"    // [ddu, ddv, ..]
      "por %%xmm10, %%xmm14\n\t"              // d
      "movdqa %%xmm12, %%xmm8\n\t"
      "pshufd $0xf8, %%xmm14, %%xmm14\n\t"    // [du, dv, ..]
      "psrad $31, %%xmm8\n\t"
      "movdqa %%xmm14, %%xmm15\n\t"
      "pslldq $4, %%xmm8\n\t"
      "psrad $31, %%xmm15\n\t"
      "paddd %%xmm12, %%xmm8\n\t"
      "pslldq $4, %%xmm15\n\t"
      "movq %%xmm8, %[odd]\n\t"
      "paddd %%xmm14, %%xmm15\n\t"
      "movq %%xmm15, %[od]"
      : [od] "=&r"(od), [odd] "=&r"(odd)
      : [a] "x"(a), [b] "x"(b), [z] "x"(z), [zc] "x"(zc), [sd] "x"(sd), [two] "r"(two), [T] "r"(T), [s] "r"(s),
        [steps] "r"(steps), [half] "m"(kHalf), [m2] "m"(kMinus2), [lo] "m"(kLo), [hi] "m"(kHi), [low32] "m"(kLow32),
        [one] "m"(kOnes)
      : "xmm7", "xmm8", "xmm9", "xmm10", "xmm11", "xmm12", "xmm13", "xmm14", "xmm15");
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
// The last run of `last` = 1 .. 16 pixels from sample a = [u, v, ..] to b, their depths z:
// its steps (last_steps_x86) and pixels. The steps inside each branch (an asm statement
// each, steps differing): bench/count.sh times each block alone as a loop, so the samples'
// block, which holds the first divide's latency chain, ends before the quotients' divide
// (skylake persp32 6.93 -> 6.73, persp16 10.62 -> 10.59; znver3 4.77 -> 4.85, 7.93 -> 7.96).
SB_INLINE void last_run_x86(uint8_t* dest, int last, const uint8_t* texels, uint32_t w, __m128i a, __m128i b,
                            __m128d z, double zc) {
  const uint64_t x = uint64_t(_mm_cvtsi128_si64(a));  // v0 2^32 + u0 (both >= 0)
  if (last == 16) {
    const StepsPacked st = last_steps_x86(15, a, b, z, zc);
    Run16<true>(x, st.d, st.dd, Run16<true>::Packed{}).draw(dest, texels, w);
  } else {
    const StepsPacked st = last_steps_x86(last - 1, a, b, z, zc);
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
    last_run_x86(dest, n, texels, w, a.iuv, _mm_srli_si128(a.iuv, 8), a.z, zc);
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
  const double c0 = (zc * -0.0625) * (lane0(a.z) + lane1(a.z));
  RunSteps su0, sv0;
  steps16_uv_x86(s0, s1, c0, &su0, &sv0);
  draw16<true>(dest, texels, w, ilane<0>(s0), ilane<1>(s0), su0, sv0);
  // The last run: from sample 1 to 2 (n <= 32), or run 1 (samples 1 to 2) and then 2 to 3.
  __m128i la = s1, lb = s2;
  __m128d lz = _mm_shuffle_pd(a.z, b.z, 1);  // [z_1, z_2]
  int last = n - 16;
  dest += 16;
  if (n > 32) {
    const double c1 = (zc * -0.0625) * (lane1(a.z) + lane0(b.z));
    RunSteps su1, sv1;
    steps16_uv_x86(s1, s2, c1, &su1, &sv1);
    draw16<true>(dest, texels, w, ilane<0>(s1), ilane<1>(s1), su1, sv1);
    dest += 16;
    last -= 16;
    la = s2, lb = s3;
    lz = b.z;
  }
  last_run_x86(dest, last, texels, w, la, lb, lz, zc);
}

}  // namespace
}  // namespace sb::simd
#endif
