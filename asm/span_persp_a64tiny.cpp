// asm/span_persp_a64tiny.cpp: aarch64 only (empty elsewhere): second-order spans of 1 .. 16
// pixels (one run; second_order with dzi != 0), two neighbouring ones of a batch at a time
// (tiny_curve_run_a64, asm/span_persp_a64tiny.h: batch_from's runs of them in
// asm/span_persp_fast.cpp; tiny_one_a64: persp_fast<true>'s lone ones). Notes and figures:
// bench/mca_a53_tiny/README.md. Its own translation unit: in span_persp_fast.cpp this code changed
// GCC's inlining budget for the other functions there (the single entry shrank by 1.3 KiB,
// spans_range grew by 2.4 KiB: A53 persp64single 9.49 -> 9.54, persp32 18.31 -> 18.37).
//
// Such spans are a surface's edges (bench/span_hist.md: at 320x240 880-960 a frame, mean 7
// pixels, 95% next to another in the same batch). Before this path each went through
// persp_fast<true> (out of line: the long-span loop's register saves), one fdiv.2d for its
// two samples (the A53 model's divider: 29 cycles a divide), a scalar last_steps and
// draw_last: A53 persp16 54.50 c/px (~460 cycles a span).
//
// Here two spans a, b (b = a for a lone span) are computed in 2-lane vectors, lane 0 span a,
// lane 1 span b, every lane the walker's operation (asm/span_walk.h: the same bits):
//   sample 0 at P = px0, sample 1 at P + (n - 1) (n = 1: P + 0 = P, the same sample, as the
//   walker's single sample); zi = zrow + zix pos (fmla, as the engine's contracted code),
//   b = max(zi, kMinZi) (fmaxnm: NaN -> kMinZi), z = 1 / b by frecpe and Newton steps,
//   correctly rounded (the proof and its divide fallback: asm/span_persp_a64short.h; the
//   fallback here divides all four lanes when any needs it);
//   [u, v] = fix((uvrow + uvx pos) z): fcvtzu #16 (trunc(q 2^16), negatives and NaN 0,
//   saturating), uqxtn, umin with [umax, vmax] (to_fixed's bits: see short_samples2);
//   the run's steps as last_steps (asm/span_persp_arm.h): q = delta / steps by div_steps'
//   three operations (correctly rounded, no divide), ddf = q (-dzi (z_0 + z_1)) (= (q curve)
//   -2 with curve = (dzi 0.5) (z_0 + z_1): TinySamples), lin = trunc(q), dd = trunc(ddf) where
//   |ddf| < 1e9 else 0, then last_dd's integer test and d0 for the four lanes [u_a, v_a,
//   u_b, v_b] at once;
//   steps < 2 (n = 1, 2): T = 0 and S = 1 make d = lin; dd is then never used (a run of one
//   or two pixels adds no second difference), so no mask for it.
// Then each span drawn from its packed position and steps (draw_tiny: draw_last's chunks by
// the bits of n, 16 as two chunks of 8: the same recurrence, so the same bytes).
#include "asm/span_persp_a64tiny.h"

#if defined(__aarch64__) && defined(__GNUC__)
#include <cstddef>
#include <cstdint>

#include "asm/span_persp.h"
#include "asm/span_persp_arm.h"
#include "asm/span_persp_run.h"
#include "asm/span_walk.h"

namespace sb::simd {
namespace {

static_assert(offsetof(PerspSpan, zi0) == 0 && offsetof(PerspSpan, dzi) == 8 && offsetof(PerspSpan, uz0) == 16 &&
                  offsetof(PerspSpan, duz) == 24 && offsetof(PerspSpan, vz0) == 32 && offsetof(PerspSpan, dvz) == 40 &&
                  offsetof(PerspSpan, px0) == 48 && offsetof(PerspSpan, umax) == 56 && offsetof(PerspSpan, vmax) == 60,
              "tiny_samples' loads: [zi0, dzi], [uz0, duz], [vz0, dvz], [px0, umax | vmax] as 16-byte pairs");

// Per span length n (1 .. 16): the second sample's offset n - 1, the step count's reciprocal
// y = RN(1 / s) and s = max(n - 1, 1) (div_steps); s, T = steps (steps - 1) / 2 and
// K = ceil(2^31 / T) (0 for T = 0) as 32-bit integers, each twice (the u and v lanes).
// K: T min(|dd|, K) <= pd in 32 bits is last_dd's T |dd| <= pd (pd = |delta| < 2^31): equal
// for |dd| <= K, and for |dd| > K both reject (T K >= 2^31 > pd); T K < 2^31 + T: no wrap.
struct alignas(16) TinyRow {
  double off, y;
  double s;
  uint32_t s2[2];
  uint32_t t2[2], k2[2];
};
// The loop block's constants (asm/span_persp_a64tiny_pair.h loads them from kTiny.c, the
// rows' base register: no vector register held across the loop for them): kBiasBits, kMinZi,
// the fallback's significand mask and 2^1000's bits (as tiny_samples), 999999999 (last_dd's
// range).
struct alignas(16) TinyConsts {
  uint64_t bias[2];
  double kmin[2];
  uint64_t mask[2], big[2];
  uint32_t c999[4];
};
struct TinyTable {
  TinyRow at[17];
  TinyConsts c;
  constexpr TinyTable()
      : at{},
        c{{kBiasBits, kBiasBits},
          {span_walk::kMinZi, span_walk::kMinZi},
          {0xfff0000000000000, 0xfff0000000000000},
          {0x7e70000000000000, 0x7e70000000000000},
          {999999999, 999999999, 999999999, 999999999}} {
    for (int n = 1; n <= 16; ++n) {
      const int steps = n - 1, s = steps > 1 ? steps : 1;
      const uint32_t t = uint32_t(steps * (steps - 1) / 2), k = t ? uint32_t(((1ull << 31) + t - 1) / t) : 0u;
      at[n] = TinyRow{double(steps), kRecipSteps[s], double(s), {uint32_t(s), uint32_t(s)}, {t, t}, {k, k}};
    }
  }
};
static_assert(sizeof(TinyRow) == 48 && offsetof(TinyRow, t2) == 32);
static_assert(offsetof(TinyTable, c) == 816 && offsetof(PerspItem, span) == 16 && sizeof(PerspItem) == 88 &&
                  offsetof(PerspItem, n) == 8 && offsetof(PerspItem, span.second_order) == 80,
              "asm/span_persp_a64tiny_pair.h's offsets: kTiny.c at 816; an item's n at 8, span at 16, "
              "second_order at 80, dzi at 24; items 88 bytes apart");
constexpr TinyTable kTiny;

#include "asm/span_persp_a64tinydraw.h"

// One run of n = 1 .. 16 pixels from the packed position x (v 2^32 + u), steps d, dd (Run16's
// packing): all n pixels in one asm block, tiny_tail<n> (asm/span_persp_a64tinydraw.h and
// span_persp_a64tinydraw2.h: draw_last's chunks as straight-line code, its order searched
// against llvm-mca's A53 model), reached by a tree of bit tests on n. draw_last's chunks as
// blocks of their own (one a chunk of 8, 4, 2 or 1 pixels) ran each chunk's latency chain
// alone: A53 persp16 22.22 -> 21.34 with the chunk of 8 and the last n & 7 pixels as asm
// blocks, -> 21.22 with one block a span (bench/mca_a53_tinydraw/README.md).
template <int B>
SB_INLINE void draw_tiny_low(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const TailPos& p) {
  if (n & 4) {
    if (n & 2) {
      if (n & 1) tiny_tail<B + 7>(dest, texels, w, p); else tiny_tail<B + 6>(dest, texels, w, p);
    } else {
      if (n & 1) tiny_tail<B + 5>(dest, texels, w, p); else tiny_tail<B + 4>(dest, texels, w, p);
    }
  } else if (n & 2) {
    if (n & 1) tiny_tail<B + 3>(dest, texels, w, p); else tiny_tail<B + 2>(dest, texels, w, p);
  } else if (n & 1) {
    tiny_tail<B + 1>(dest, texels, w, p);
  } else if constexpr (B == 8) {
    tiny_tail<8>(dest, texels, w, p);
  }
}
SB_INLINE void draw_tiny(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w, uint64_t x,
                         uint64_t d, uint64_t dd) {
  const TailPos p{x, d, dd};
  if (n & 24) {
    if (n & 16) tiny_tail<16>(dest, texels, w, p); else draw_tiny_low<8>(dest, n, texels, w, p);
  } else {
    draw_tiny_low<0>(dest, n, texels, w, p);
  }
}

// What tiny_samples gives for spans a (lane 0) and b (lane 1): the clamped samples as packed
// positions s0 = [u_a, v_a, u_b, v_b] at pixel 0, s1 the same at pixel n - 1; c2 = -2 curve
// per span (below); the table rows' [y_a, y_b], [s_a, s_b], and sv, tv, kv = [x_a, x_a, x_b,
// x_b] of s, T, K; fb: all ones in some word iff some reciprocal needs the divide
// (tiny_samples_div then).
// c2 = RN(-dzi (z_0 + z_1)) = -2 RN((dzi 0.5) (z_0 + z_1)) = -2 curve: scaling by powers of two
// is exact and commutes with rounding; where it does not (dzi 0.5 subnormal, or the product
// overflowing in one form only) |ddf| < 1 or >= 1e9 (or NaN) in both forms, so dd is 0 and
// the steps linear either way. ddf = RN(q c2) = RN(-2 RN(q curve)) = last_steps' ddf.
struct TinySamples {
  uint32x4_t s0, s1, sv, tv, kv;
  float64x2_t c2, Y, S;
  uint32x4_t fb;
};
// kDiv: the reciprocals by fdiv (the fallback; the same bits as the Newton steps where those
// are exact).
template <bool kDiv>
SB_INLINE TinySamples tiny_samples(const PerspSpan& a, int na, const PerspSpan& b, int nb) {
  const float64x2_t a0 = vld1q_f64(&a.zi0), b0 = vld1q_f64(&b.zi0);
  const float64x2_t a1 = vld1q_f64(&a.uz0), b1 = vld1q_f64(&b.uz0);
  const float64x2_t a2 = vld1q_f64(&a.vz0), b2 = vld1q_f64(&b.vz0);
  const float64x2_t a3 = vld1q_f64(&a.px0), b3 = vld1q_f64(&b.px0);
  const TinyRow& ra = kTiny.at[na];
  const TinyRow& rb = kTiny.at[nb];
  const float64x2_t ta = vld1q_f64(&ra.off), tb = vld1q_f64(&rb.off);
  const float64x2_t sa = vld1q_f64(&ra.s), sb = vld1q_f64(&rb.s);
  const uint64x2_t ka = vld1q_u64(reinterpret_cast<const uint64_t*>(ra.t2));
  const uint64x2_t kb = vld1q_u64(reinterpret_cast<const uint64_t*>(rb.t2));
  const float64x2_t zr = vzip1q_f64(a0, b0), zx = vzip2q_f64(a0, b0);
  const float64x2_t ur = vzip1q_f64(a1, b1), ux = vzip2q_f64(a1, b1);
  const float64x2_t vr = vzip1q_f64(a2, b2), vx = vzip2q_f64(a2, b2);
  const float64x2_t P = vzip1q_f64(a3, b3);
  const uint32x4_t M = vreinterpretq_u32_f64(vzip2q_f64(a3, b3));  // [umax_a, vmax_a, umax_b, vmax_b]
  TinySamples r;
  const float64x2_t off = vzip1q_f64(ta, tb);
  r.Y = vzip2q_f64(ta, tb), r.S = vzip1q_f64(sa, sb);
  r.sv = vreinterpretq_u32_f64(vzip2q_f64(sa, sb));
  r.tv = vreinterpretq_u32_u64(vzip1q_u64(ka, kb)), r.kv = vreinterpretq_u32_u64(vzip2q_u64(ka, kb));
  const float64x2_t P1 = vaddq_f64(P, off);
  const float64x2_t kmin = vdupq_n_f64(span_walk::kMinZi), one = vdupq_n_f64(1.0);
  const float64x2_t zb0 = vmaxnmq_f64(vfmaq_f64(zr, zx, P), kmin);
  const float64x2_t zb1 = vmaxnmq_f64(vfmaq_f64(zr, zx, P1), kmin);
  float64x2_t z0, z1;
  if constexpr (kDiv) {
    z0 = vdivq_f64(one, zb0), z1 = vdivq_f64(one, zb1);
    r.fb = vdupq_n_u32(0);
  } else {
    // 1 / b (asm/span_persp_a64short.h's steps and proof).
    float64x2_t y0 = vrecpeq_f64(zb0), y1 = vrecpeq_f64(zb1);
    y0 = vmulq_f64(y0, vrecpsq_f64(zb0, y0)), y1 = vmulq_f64(y1, vrecpsq_f64(zb1, y1));
    y0 = vmulq_f64(y0, vrecpsq_f64(zb0, y0)), y1 = vmulq_f64(y1, vrecpsq_f64(zb1, y1));
    y0 = vfmaq_f64(y0, y0, vfmsq_f64(one, zb0, y0)), y1 = vfmaq_f64(y1, y1, vfmsq_f64(one, zb1, y1));
    z0 = vfmaq_f64(y0, y0, vfmsq_f64(one, zb0, y0)), z1 = vfmaq_f64(y1, y1, vfmsq_f64(one, zb1, y1));
    // The fallback: some b with a significand of all ones (b's bits OR 0xfff0000000000000 all
    // ones: both words, uminp), or b >= 2^1000 (+inf too; b > 0: the bits order as the
    // values, fmax of the two).
    const uint64x2_t mask = vdupq_n_u64(0xfff0000000000000), big = vdupq_n_u64(0x7e70000000000000);
    const uint32x4_t w = vpminq_u32(vreinterpretq_u32_u64(vorrq_u64(vreinterpretq_u64_f64(zb0), mask)),
                                    vreinterpretq_u32_u64(vorrq_u64(vreinterpretq_u64_f64(zb1), mask)));
    r.fb = vorrq_u32(w, vreinterpretq_u32_u64(vcgeq_u64(vreinterpretq_u64_f64(vmaxq_f64(zb0, zb1)), big)));
  }
  // The samples: [u_a, u_b] and [v_a, v_b] at P (z0) and P1 (z1), converted and clamped, then
  // zipped to the packed positions [u_a, v_a, u_b, v_b] of sample 0 (s0) and sample 1 (s1).
  const uint32x2_t u0 = vqmovn_u64(vcvtq_n_u64_f64(vmulq_f64(vfmaq_f64(ur, ux, P), z0), 16));
  const uint32x2_t v0 = vqmovn_u64(vcvtq_n_u64_f64(vmulq_f64(vfmaq_f64(vr, vx, P), z0), 16));
  const uint32x4_t U = vqmovn_high_u64(u0, vcvtq_n_u64_f64(vmulq_f64(vfmaq_f64(ur, ux, P1), z1), 16));
  const uint32x4_t V = vqmovn_high_u64(v0, vcvtq_n_u64_f64(vmulq_f64(vfmaq_f64(vr, vx, P1), z1), 16));
  r.s0 = vminq_u32(vzip1q_u32(U, V), M), r.s1 = vminq_u32(vzip2q_u32(U, V), M);
  r.c2 = vmulq_f64(vnegq_f64(zx), vaddq_f64(z0, z1));
  return r;
}
// The divide fallback's samples (out of line: almost never taken).
__attribute__((noinline)) TinySamples tiny_samples_div(const PerspSpan& a, int na, const PerspSpan& b, int nb) {
  return tiny_samples<true>(a, na, b, nb);
}

// The packed positions and steps of spans a (lane 0) and b (lane 1): pos = [x_a, x_b],
// d = [d_a, d_b], dd = [dd_a, dd_b] (v 2^32 + u, Run16's packing of the steps).
struct TinyOut {
  uint64x2_t pos, d, dd;
};
SB_INLINE TinyOut tiny_steps(const TinySamples& r) {
  const uint32x4_t s0 = r.s0, s1 = r.s1, sv = r.sv, tv = r.tv, kv = r.kv;
  const float64x2_t Y = r.Y, S = r.S, c2 = r.c2;
  // The steps (last_steps): deltas [du_a, dv_a, du_b, dv_b] (0 <= u, v < 2^31: no overflow),
  // as doubles without scvtf: the int64 2^52 + 2^51 + x (saddw) is that double's bits, minus
  // 2^52 + 2^51 exactly x (asm/span_persp_a64short.h's kBiasBits).
  const int32x4_t D = vreinterpretq_s32_u32(vsubq_u32(s1, s0));
  const int64x2_t bias = vdupq_n_s64(int64_t(kBiasBits));
  const float64x2_t biasd = vreinterpretq_f64_s64(bias);
  const float64x2_t Da = vsubq_f64(vreinterpretq_f64_s64(vaddw_s32(bias, vget_low_s32(D))), biasd);
  const float64x2_t Db = vsubq_f64(vreinterpretq_f64_s64(vaddw_high_s32(bias, D)), biasd);
  // div_steps per span (its y and s in lane 0 / 1).
  float64x2_t qa = vmulq_laneq_f64(Da, Y, 0), qb = vmulq_laneq_f64(Db, Y, 1);
  qa = vfmaq_laneq_f64(qa, vfmsq_laneq_f64(Da, qa, S, 0), Y, 0);
  qb = vfmaq_laneq_f64(qb, vfmsq_laneq_f64(Db, qb, S, 1), Y, 1);
  const float64x2_t fa = vmulq_laneq_f64(qa, c2, 0), fb = vmulq_laneq_f64(qb, c2, 1);  // ddf
  const int32x4_t L = vmovn_high_s64(vmovn_s64(vcvtq_s64_f64(qa)), vcvtq_s64_f64(qb));  // trunc(q)
  // dd = trunc(ddf) saturated to int32 (NaN 0): |ddf| < 1e9 iff |dd| <= 999999999.
  const int32x4_t DD = vqmovn_high_s64(vqmovn_s64(vcvtq_s64_f64(fa)), vcvtq_s64_f64(fb));
  // last_dd for the four lanes (asm/span_persp_arm.h): sg, pd = |delta|, pdd = dd mirrored,
  // accept iff |dd| <= 999999999 (else last_steps' dd is 0: accepted, d = lin, as here) and
  // T |dd| <= pd (T min(|dd|, K) <= pd: TinyRow), Q = |lin|, r = pd - s Q, m = (s - 1) pdd,
  // d0' = Q - (m >> 1) - (m & 1 & (2 r < s)); d = accept ? mirror(d0') : lin, dd & accept.
  const int32x4_t sg = vshrq_n_s32(D, 31);
  const uint32x4_t usg = vreinterpretq_u32_s32(sg);
  const uint32x4_t pd = vreinterpretq_u32_s32(vabsq_s32(D));
  const uint32x4_t pdd = vsubq_u32(veorq_u32(vreinterpretq_u32_s32(DD), usg), usg);
  const uint32x4_t add = vreinterpretq_u32_s32(vabsq_s32(DD));
  const uint32x4_t accept = vbicq_u32(vcleq_u32(vmulq_u32(vminq_u32(add, kv), tv), pd),
                                      vcgtq_u32(add, vdupq_n_u32(999999999)));
  const uint32x4_t Q = vsubq_u32(veorq_u32(vreinterpretq_u32_s32(L), usg), usg);
  const uint32x4_t rr = vmlsq_u32(pd, sv, Q);
  const uint32x4_t m = vmulq_u32(vsubq_u32(sv, vdupq_n_u32(1)), pdd);
  const uint32x4_t c = vcgtq_u32(sv, vshlq_n_u32(rr, 1));
  const uint32x4_t d0 = vsubq_u32(vsubq_u32(Q, vreinterpretq_u32_s32(vshrq_n_s32(vreinterpretq_s32_u32(m), 1))),
                                  vandq_u32(vandq_u32(m, vdupq_n_u32(1)), c));
  const uint32x4_t dm = vsubq_u32(veorq_u32(d0, usg), usg);
  const uint32x4_t dres = vbslq_u32(accept, dm, vreinterpretq_u32_s32(L));
  const uint32x4_t ddres = vandq_u32(vreinterpretq_u32_s32(DD), accept);
  // Packed: (x & (2^64 - 2^32)) + (x << 32 >> 32, arithmetic) per 64-bit lane x = [du, dv].
  const uint64x2_t hi = vdupq_n_u64(0xffffffff00000000);
  auto pack = [&](uint32x4_t v) SB_LAMBDA_INLINE {
    const int64x2_t x = vreinterpretq_s64_u32(v);
    return vreinterpretq_u64_s64(
        vsraq_n_s64(vreinterpretq_s64_u64(vandq_u64(vreinterpretq_u64_s64(x), hi)), vshlq_n_s64(x, 32), 32));
  };
  return TinyOut{vreinterpretq_u64_u32(s0), pack(dres), pack(ddres)};
}
SB_INLINE bool tiny_fallback(const TinySamples& r) {
  return __builtin_expect(vmaxvq_u32(r.fb) == ~0u, 0);
}

// tiny_pair_block's scalar outputs: this pair's packed positions and steps, the fallback flag.
struct TinyPairOut {
  uint64_t posa, posb, da, db, dda, ddb;
  uint32_t fb;
};
#include "asm/span_persp_a64tiny_pair.h"

}  // namespace

void tiny_one_a64(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  TinySamples r = tiny_samples<false>(p, n, p, n);
  if (tiny_fallback(r)) r = tiny_samples_div(p, n, p, n);
  const TinyOut o = tiny_steps(r);
  draw_tiny(dest, n, texels, uint32_t(width), vgetq_lane_u64(o.pos, 0), vgetq_lane_u64(o.d, 0),
            vgetq_lane_u64(o.dd, 0));
}

// Items from it on (it is one: tiny_curve_a64), while they are such items: two at a time
// (it[0], it[1] both, it + 1 < end), a lone one as a pair with itself (drawn once); returns
// the first item that is not one (or end). Software-pipelined: one asm block
// (asm/span_persp_a64tiny_pair.h, bench/mca_a53_tiny/gen_pair_asm.py, order searched against
// llvm-mca) computes this pair's steps, the next pair's tests (tiny_curve_a64's, without
// branches) and the next pair's samples, these speculatively on b + 1, b + 2 (a past end),
// so that the in-order A53 runs the latency chains side by side (A53 persp16 26.09 -> 22.39,
// A72 12.70 -> 11.55: bench/mca_a53_tiny/README.md); the divide fallback's test after it.
// Page-aligned (its code's place against qemu's 4 KiB page cuts does not move with the code
// before it); the attributes schedule the C++ around the block (t16a's figures with the
// C++ block: A53 26.83 -> 26.19, A72 13.32 -> 12.78).
__attribute__((aligned(4096))) const PerspItem*
tiny_curve_run_a64(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width) {
  const uint32_t w = uint32_t(width);
  const PerspItem* a = it;
  const PerspItem* b = it + 1 != end && tiny_curve_a64(it[1]) ? it + 1 : it;
  TinySamples cur = tiny_samples<false>(a->span, a->n, b->span, b->n);
  if (tiny_fallback(cur)) cur = tiny_samples_div(a->span, a->n, b->span, b->n);
  uint32x4_t s0 = cur.s0, s1 = cur.s1;
  float64x2_t c2 = cur.c2;
  for (;;) {
    // The next pair's tests and samples and this pair's steps: asm/span_persp_a64tiny_pair.h.
    const PerspItem* xa;
    const PerspItem* xb;
    TinyPairOut o;
    tiny_pair_block(s0, s1, c2, a, b, end, xa, xb, o);
    // Both spans' n and a's dest loaded beside the fallback test: the first test on n then
    // waits for no load (A53 persp16 21.22 -> 20.96; b's dest too: 21.12, GCC spills).
    const int na = a->n, nb = b->n;
    uint8_t* const desta = a->dest;
    if (__builtin_expect(o.fb == ~0u, 0) && xa != a) {
      const TinySamples r = tiny_samples_div(xa->span, xa->n, xb->span, xb->n);
      s0 = r.s0, s1 = r.s1, c2 = r.c2;
    }
    draw_tiny(desta, na, texels, w, o.posa, o.da, o.dda);
    if (b != a) draw_tiny(b->dest, nb, texels, w, o.posb, o.db, o.ddb);
    if (xa == a) return b + 1;
    a = xa, b = xb;
  }
}

}  // namespace sb::simd
#endif
