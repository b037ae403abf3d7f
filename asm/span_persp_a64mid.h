// asm/span_persp_a64mid.h: aarch64 only, persp_short_inl's second-order path for four runs
// (49 .. 64 pixels): short_steps_k3v computes every run's steps, the last run's last_dd
// included, in one vector asm block; steps_k3v_pass is the same block with the first pass
// (runs 0, 1) in it, and persp_mid_k3 draws the span with it. Internal: included by
// asm/span_persp_a64short.h (it uses asm/span_persp_arm.h's kRecipSteps,
// asm/span_persp_run.h's draw_last and Run16, asm/span_persp_a64pass.h's short_pass).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64pass.h"
#endif

namespace sb::simd {
namespace {

#if defined(__aarch64__)
// The block's constants: 120 (4 lanes), 2^25 (4 lanes), the deltas' double bias 2^52 + 2^51
// (2 lanes), then last_steps' |ddf| < 1e9 range as a bound on |dd| (uint32 lanes 2^32 - 1, 2^32
// - 1 for run 2, 1e9, 1e9 for the last run: cmhi against |dd|): two ldp. For a finite ddf,
// |ddf| < 1e9 iff |dd| < 1e9 (dd = trunc(ddf), saturated to int32; 1e9 is an integer); +-inf
// gives |dd| >= 2^31 - 1; NaN gives dd = 0, accepted here where facgt rejected it, with the
// same results (d = lin - 0, dd & accept = 0).
static_assert(1000000000 == 0x3b9aca00);
static_assert(__builtin_bit_cast(uint64_t, 6755399441055744.0) == 0x4338000000000000);
// Per last-run step count s (1 .. 15; index 0 as 1), the constants of the D23 vector [du_2,
// dv_2, du_3, dv_3] (run 2 full, run 3 the last run): per lane s, s - 1, T = s (s - 1) / 2,
// the clamp C = floor((2^32 - 1) / T) (2^32 - 1 for T = 0: min(|dd|, C) T < 2^32, and C T >
// 2^31 > |delta|, so the clamped test T |dd| <= |delta| is the exact one), h = (s + 1) / 2
// (2 r < s iff r < h), then [RN(1/s), s] (div_steps) and [k, 0] with k = -2 for s > 1 and 0
// else (ddf = q (curve k): the last run's dd is 0 when steps <= 1, as last_steps_ddi's mask).
// Padded to 128 bytes: steps_k3v_pass addresses row s as kp + 128 s (one add from kMidTable's
// base, no multiply).
struct alignas(16) MidSteps {
  uint32_t s[4], sm1[4], t[4], c[4], h[4];
  double y[2], k[2];
  uint32_t pad[4];
};
static_assert(sizeof(MidSteps) == 128 && offsetof(MidSteps, s) == 0 && offsetof(MidSteps, t) == 32 &&
              offsetof(MidSteps, h) == 64 && offsetof(MidSteps, y) == 80 && offsetof(MidSteps, k) == 96);
constexpr MidSteps mid_steps(uint32_t s) {
  const uint32_t t = s * (s - 1) / 2, c = t ? 0xffffffffu / t : 0xffffffffu;
  return MidSteps{{16, 16, s, s}, {15, 15, s - 1, s - 1}, {120, 120, t, t}, {35791394, 35791394, c, c},
                  {8, 8, (s + 1) / 2, (s + 1) / 2}, {kRecipSteps[s], double(s)}, {s > 1 ? -2.0 : 0.0, 0.0}};
}
// The constants then the MidSteps rows in one table: steps_k3v_pass takes one base register
// (kp) for both, row s at kp + 64 + 128 s.
struct alignas(64) MidTable {
  uint64_t c[8];
  MidSteps steps[16];
};
static_assert(offsetof(MidTable, steps) == 64 && sizeof(MidSteps) == 128);
constexpr MidTable kMidTable = {
    {0x0000007800000078, 0x0000007800000078, 0x0200000002000000, 0x0200000002000000, 0x4338000000000000,
     0x4338000000000000, 0xffffffffffffffff, 0x3b9aca003b9aca00},
    {mid_steps(1), mid_steps(1), mid_steps(2), mid_steps(3), mid_steps(4), mid_steps(5), mid_steps(6), mid_steps(7),
     mid_steps(8), mid_steps(9), mid_steps(10), mid_steps(11), mid_steps(12), mid_steps(13), mid_steps(14),
     mid_steps(15)}};
constexpr const uint64_t (&kMidConsts)[8] = kMidTable.c;
constexpr const MidSteps (&kMidSteps)[16] = kMidTable.steps;
// A pass's arguments (short_pass's run a and run b). short_steps_k3v: the first pass's (runs
// 0 and 1), the steps unpacked ([du, dv] as v 2^32 + u, each 32-bit); the second pass's
// stored: st = {c_uv, luv, c_d, ld, c_dd, ldd} (run 2's start, run 3's start, then their
// steps and second-order steps, unpacked). steps_k3v_pass: the second pass's (runs 2 and 3),
// the steps packed by mid_pack.
struct MidFirst {
  uint64_t a_uv, a_d, a_dd, b_uv, b_d, b_dd;
};
// Four runs, second order, from the samples S01 = [u_0, v_0, u_1, v_1], S23, S44 (sample 4
// twice), the full runs' curve factors c01, c23, zs23 = [z_2 + z_3, z_3 + z_4], s = max(1,
// last - 1) (the last run's steps), zh = zc / 2 (zc the span's dzi). Runs 0, 1 (D01): delta, ddf, dd
// and steps16_dd's 32-bit form, as the two- and three-run steps block of
// asm/span_persp_a64short.h computes them. The last run: last_steps' vector part (div_steps'
// quotient q, lin = trunc(q), ddf = q (curve k), curve = (zc / 2)(z_3 + z_4); q (curve k)
// is (q curve) k bit for bit: k = -2
// scales exactly, and an inf / NaN product gives dd = 0 either way), its lin and dd put into
// lanes 2, 3 of run 2's vectors, then last_dd (asm/span_persp_arm.h) in those four lanes
// (for s = 16, T = 120 it is steps16_dd): with sg = delta's sign, Q = |delta| / s truncated
// (|delta| >> 4 for run 2; |lin| for run 3: q has delta's sign and trunc(q) = trunc(delta /
// s)), lin = mirror(Q), accept iff T |dd| <= |delta| (and |ddf| < 1e9 for run 3: a rejected
// lane gives lin and dd 0, as last_dd does with dd masked to 0), r = |delta| - s Q. last_dd's
// d = mirror(Q - (m >> 1) - (m & 1 & (2 r < s))), m = mirror(M), M = (s - 1) dd, is
// lin - (M >> 1) - (M & 1 & ((r < h) ^ sg)) (floor(-M / 2) = -(M >> 1) - (M & 1); |M| < 2^31
// wherever accepted), so no mirroring on the dd chain; d = accept ? that : lin, dd & accept.
// One asm block, fixed registers, the order from bench/order_search.py (steps_k3v.s in
// bench/mca_a53_p64; its registers from alloc.py on steps_k3v.vs).
// AsmSpanPersp.ShortStepsK3vMatchTheirParts checks it against steps16_dd and last_steps.
SB_INLINE MidFirst short_steps_k3v(int32x4_t S01, int32x4_t S23, int32x4_t S44, float64x2_t c01, float64x2_t c23,
                                   float64x2_t zs23, int s, double zh, uint64_t (&st)[6]) {
  register int32x4_t rS44 __asm__("v7") = S44;
  register int32x4_t rS01 __asm__("v5") = S01;
  register int32x4_t rS23 __asm__("v19") = S23;
  register float64x2_t rc01 __asm__("v3") = c01;
  register float64x2_t rc23 __asm__("v16") = c23;
  register float64x2_t rzs __asm__("v1") = zs23;
  register double rzc __asm__("v31") = zh;  // zc / 2
  uint64_t ra_uv, ra_d, ra_dd, rb_uv, rb_d, rb_dd;
  __asm__(
// BEGIN short_steps_k3v
      "ext v7.16b, v19.16b, v7.16b, #8\n\t"
      "ext v0.16b, v5.16b, v19.16b, #8\n\t"
      "ldp q23, q24, [%[y], #64]\n\t"
      "ldp q6, q17, [%[kp], #32]\n\t"
      "sub v7.4s, v7.4s, v19.4s\n\t"
      "sub v0.4s, v0.4s, v5.4s\n\t"
      "ldp q2, q4, [%[kp]]\n\t"
      "saddw2 v29.2d, v6.2d, v7.4s\n\t"
      "saddw v26.2d, v6.2d, v0.2s\n\t"
      "saddw2 v27.2d, v6.2d, v0.4s\n\t"
      "saddw v28.2d, v6.2d, v7.2s\n\t"
      "ldr q25, [%[y], #96]\n\t"
      "fmul d31, d31, v1.d[1]\n\t"
      "fsub v29.2d, v29.2d, v6.2d\n\t"
      "fsub v26.2d, v26.2d, v6.2d\n\t"
      "fsub v27.2d, v27.2d, v6.2d\n\t"
      "fsub v28.2d, v28.2d, v6.2d\n\t"
      "ldp q18, q20, [%[y]]\n\t"
      "fmul v30.2d, v29.2d, v24.d[0]\n\t"
      "fmul v26.2d, v26.2d, v3.d[0]\n\t"
      "fmul d31, d31, v25.d[0]\n\t"
      "fmul v27.2d, v27.2d, v3.d[1]\n\t"
      "fmul v28.2d, v28.2d, v16.d[0]\n\t"
      "fmov %[a_uv], d5\n\t"
      "mov %[b_uv], v5.d[1]\n\t"
      "fmls v29.2d, v30.2d, v24.d[1]\n\t"
      "fcvtzs v26.2d, v26.2d\n\t"
      "ldp q21, q22, [%[y], #32]\n\t"
      "fcvtzs v28.2d, v28.2d\n\t"
      "sqxtn v6.2s, v26.2d\n\t"
      "fmla v30.2d, v29.2d, v24.d[0]\n\t"
      "fcvtzs v27.2d, v27.2d\n\t"
      "str q19, [%[st]]\n\t"
      "sqxtn v1.2s, v28.2d\n\t"
      "sshr v28.4s, v0.4s, #31\n\t"
      "abs v26.4s, v0.4s\n\t"
      "sshr v29.4s, v7.4s, #31\n\t"
      "fcvtzs v25.2d, v30.2d\n\t"
      "fmul v30.2d, v30.2d, v31.d[0]\n\t"
      "sqxtn2 v6.4s, v27.2d\n\t"
      "abs v27.4s, v7.4s\n\t"
      "mov v7.16b, v26.16b\n\t"
      "ushr v24.4s, v26.4s, #4\n\t"
      "abs v25.2d, v25.2d\n\t"
      "fcvtzs v30.2d, v30.2d\n\t"
      "ushr v31.4s, v27.4s, #4\n\t"
      "eor v24.16b, v24.16b, v28.16b\n\t"
      "sqxtn2 v1.4s, v30.2d\n\t"
      "xtn2 v31.4s, v25.2d\n\t"
      "abs v3.4s, v6.4s\n\t"
      "mov v25.16b, v27.16b\n\t"
      "eor v30.16b, v6.16b, v28.16b\n\t"
      "abs v0.4s, v1.4s\n\t"
      "cmhi v16.4s, v17.4s, v0.4s\n\t"
      "eor v9.16b, v31.16b, v29.16b\n\t"
      "umin v3.4s, v3.4s, v4.4s\n\t"
      "mul v4.4s, v20.4s, v1.4s\n\t"
      "sub v30.4s, v30.4s, v28.4s\n\t"
      "mls v25.4s, v18.4s, v31.4s\n\t"
      "sub v24.4s, v24.4s, v28.4s\n\t"
      "umin v0.4s, v0.4s, v22.4s\n\t"
      "mul v3.4s, v3.4s, v2.4s\n\t"
      "mls v7.4s, v30.4s, v2.s[0]\n\t"
      "sshr v22.4s, v4.4s, #1\n\t"
      "sub v9.4s, v9.4s, v29.4s\n\t"
      "cmhi v25.4s, v23.4s, v25.4s\n\t"
      "shl v4.4s, v4.4s, #31\n\t"
      "mul v0.4s, v0.4s, v21.4s\n\t"
      "ushr v7.4s, v7.4s, #4\n\t"
      "cmhs v3.4s, v26.4s, v3.4s\n\t"
      "sub v21.4s, v9.4s, v22.4s\n\t"
      "eor v25.16b, v25.16b, v29.16b\n\t"
      "eor v7.16b, v7.16b, v28.16b\n\t"
      "and v6.16b, v6.16b, v3.16b\n\t"
      "cmhs v0.4s, v27.4s, v0.4s\n\t"
      "and v25.16b, v25.16b, v4.16b\n\t"
      "sub v7.4s, v7.4s, v28.4s\n\t"
      "fmov %[a_dd], d6\n\t"
      "and v0.16b, v0.16b, v16.16b\n\t"
      "ssra v21.4s, v25.4s, #31\n\t"
      "mov %[b_dd], v6.d[1]\n\t"
      "bit v24.16b, v7.16b, v3.16b\n\t"
      "and v1.16b, v1.16b, v0.16b\n\t"
      "bit v9.16b, v21.16b, v0.16b\n\t"
      "mov %[b_d], v24.d[1]\n\t"
      "fmov %[a_d], d24\n\t"
      "stp q9, q1, [%[st], #16]"
// END short_steps_k3v
      : [a_uv] "=&r"(ra_uv), [a_d] "=&r"(ra_d), [a_dd] "=&r"(ra_dd), [b_uv] "=&r"(rb_uv), [b_d] "=&r"(rb_d),
        [b_dd] "=&r"(rb_dd), "+&w"(rS44), "+&w"(rc01), "+&w"(rc23), "+&w"(rzs), "+&w"(rzc), "=m"(st)
      : "w"(rS01), "w"(rS23), [kp] "r"(kMidConsts), [y] "r"(&kMidSteps[s]), [st] "r"(st), "m"(kMidConsts),
        "m"(kMidSteps)
      : "v0", "v2", "v4", "v6", "v9", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29",
        "v30");
  return MidFirst{ra_uv, ra_d, ra_dd, rb_uv, rb_d, rb_dd};
}
// short_steps_k3v and the first pass (short_pass<true> of runs 0 and 1, its arguments packed
// by mid_pack, asm/span_persp_a64pass.h) in one asm block: the pass's first slots run in the
// latency gaps of the steps' last vector levels (the block is bench/mca_a53_p64/steps_pass.s,
// the two blocks one after the other plus the packing, then ordered by
// bench/order_search.py; its first 132 lines since searched again as the pair loop's qemu
// block, bench/mca_a53_pair/steps_pair_s.s; lines 133 .. 332, the first pass's tail, as its three
// inlined copies' qemu blocks cut them, bench/mca_a53_pair/steps_tail_s2.s).
// Draws dest[0 .. 31]; st as short_steps_k3v's. Returns the second
// pass's arguments (st's values, the steps packed) in x13, x9, x10, x23, x24, x25, where
// short_pass takes them: loaded back from st (stored by the block before the first pass) and
// packed after the first pass's last reads of those registers (b_d, b_dd once run 1 has
// started, the rest in the tail); loads, not lane moves: in LLVM's Cortex-A53 model a move
// out of a vector holds back the core instructions behind it. Sets
// full iff s == 15 (last == 16: kMidSteps[s].s[2] loaded and compared in the block's tail, the
// flags returned as an asm flag output, so the caller branches without reloading last). The
// same instructions as short_steps_k3v (steps_k3v.s) and short_pass<true>, reordered with
// their dependences kept, but for runs 0, 1's d (D01's lanes), computed in 8 vector instructions
// instead of 12 (the same int32 values): with sg = delta >> 31 and Dc = delta + (sg >>> 28)
// (delta + 15 when negative: no overflow), lin = trunc(delta / 16) = Dc >> 4 (arithmetic) and
// the accepted d = mirror((pd - 120 pdd) >> 4) = trunc(x / 16), x = delta - 120 dd, which has
// delta's sign or is 0 and |x| <= 2 |delta| (it may not fit an int32): shsub gives h =
// floor((Dc - 120 dd) / 2) exactly (a 33-bit difference halved), h >> 3 = floor((x + 15 or 0)
// / 16) = trunc(x / 16); 120 dd (mul) wraps only where accept fails (|dd| >= 2^25). One scratch
// vector more (v9). Run 3's lanes likewise: lin - (M >> 1) - (M & 1 & c) (c = (r < h) ^ sg, a
// lane mask) as lin - (c ? (M + 1) >> 1 : M >> 1), the rounding shift srshr and a bit select
// (6 instructions, not 7; the same bits mod 2^32). AsmSpanPersp.ShortStepsK3vMatchTheirParts checks its st, its packed
// results, full and the pixels of runs 0, 1 against the parts, FourRunSpansMatchOnExtremeGradients
// (lengths 49 .. 64) and MatchesTheRunWalkerOnShortSpans the span against the walker.
SB_INLINE MidFirst steps_k3v_pass(uint8_t* __restrict dest, const uint8_t* __restrict texels, uint64_t width,
                                  int32x4_t S01, int32x4_t S23, int32x4_t S44, float64x2_t c01, float64x2_t c23,
                                  float64x2_t zs23, int s, double zh, uint64_t (&st)[6], bool& full) {
  // zh = zc * 0.5 (zc the span's dzi: the caller's multiply, or the sample block's).
  register uint64_t ra_uv __asm__("x13"), ra_d __asm__("x9"), ra_dd __asm__("x10");
  register uint64_t rb_uv __asm__("x23"), rb_d __asm__("x24"), rb_dd __asm__("x25");
  register int32x4_t rS44 __asm__("v7") = S44;
  register int32x4_t rS01 __asm__("v5") = S01;
  register int32x4_t rS23 __asm__("v19") = S23;
  register float64x2_t rc01 __asm__("v3") = c01;
  register float64x2_t rc23 __asm__("v16") = c23;
  register float64x2_t rzs __asm__("v1") = zs23;
  register double rzc __asm__("v31") = zh;  // zc / 2
  // s in, the row's address kp + 128 s out (the block's first line); the block reads row s at
  // [y, #64 + offset] (MidTable: the rows after the 64 bytes of constants).
  uint64_t ys = uint32_t(s);
  __asm__ volatile(
// BEGIN steps_k3v_pass
      "ext v7.16b, v19.16b, v7.16b, #8\n\t"
      "fmov x13, d5\n\t"
      "ext v0.16b, v5.16b, v19.16b, #8\n\t"
      "ldp q6, q17, [%[kp], #32]\n\t"
      "str q19, [%[st]]\n\t"
      "add %[y], %[kp], %[y], lsl #7\n\t"
      "sub v7.4s, v7.4s, v19.4s\n\t"
      "sub v0.4s, v0.4s, v5.4s\n\t"
      "ldp q23, q24, [%[y], #128]\n\t"
      "ldp q21, q22, [%[y], #96]\n\t"
      "saddw2 v29.2d, v6.2d, v7.4s\n\t"
      "saddw v26.2d, v6.2d, v0.2s\n\t"
      "saddw v28.2d, v6.2d, v7.2s\n\t"
      "saddw2 v27.2d, v6.2d, v0.4s\n\t"
      "fsub v29.2d, v29.2d, v6.2d\n\t"
      "fmul d31, d31, v1.d[1]\n\t"
      "fsub v26.2d, v26.2d, v6.2d\n\t"
      "fsub v27.2d, v27.2d, v6.2d\n\t"
      "fsub v28.2d, v28.2d, v6.2d\n\t"
      "fmul v30.2d, v29.2d, v24.d[0]\n\t"
      "ldr q25, [%[y], #160]\n\t"
      "fmul v26.2d, v26.2d, v3.d[0]\n\t"
      "fmul v27.2d, v27.2d, v3.d[1]\n\t"
      "fmul v28.2d, v28.2d, v16.d[0]\n\t"
      "fmul d31, d31, v25.d[0]\n\t"
      "fmls v29.2d, v30.2d, v24.d[1]\n\t"
      "fcvtzs v26.2d, v26.2d\n\t"
      "fcvtzs v27.2d, v27.2d\n\t"
      "fcvtzs v28.2d, v28.2d\n\t"
      "ldp q18, q20, [%[y], #64]\n\t"
      "sqxtn v6.2s, v26.2d\n\t"
      "fmla v30.2d, v29.2d, v24.d[0]\n\t"
      "sqxtn v1.2s, v28.2d\n\t"
      "sshr v28.4s, v0.4s, #31\n\t"
      "ldp q2, q4, [%[kp]]\n\t"
      "sqxtn2 v6.4s, v27.2d\n\t"
      "fcvtzs v25.2d, v30.2d\n\t"
      "fmul v30.2d, v30.2d, v31.d[0]\n\t"
      "abs v27.4s, v7.4s\n\t"
      "sshr v29.4s, v7.4s, #31\n\t"
      "ushr v9.4s, v28.4s, #28\n\t"
      "abs v25.2d, v25.2d\n\t"
      "fcvtzs v30.2d, v30.2d\n\t"
      "ushr v31.4s, v27.4s, #4\n\t"
      "mov x23, v5.d[1]\n\t"
      "add v9.4s, v0.4s, v9.4s\n\t"
      "abs v3.4s, v6.4s\n\t"
      "abs v26.4s, v0.4s\n\t"
      "sqxtn2 v1.4s, v30.2d\n\t"
      "xtn2 v31.4s, v25.2d\n\t"
      "mov v25.16b, v27.16b\n\t"
      "mul v7.4s, v6.4s, v2.s[0]\n\t"
      "umin v3.4s, v3.4s, v4.4s\n\t"
      "abs v0.4s, v1.4s\n\t"
      "mul v4.4s, v20.4s, v1.4s\n\t"
      "mls v25.4s, v18.4s, v31.4s\n\t"
      "sshr v24.4s, v9.4s, #4\n\t"
      "shsub v9.4s, v9.4s, v7.4s\n\t"
      "mul v3.4s, v3.4s, v2.4s\n\t"
      "cmhi v16.4s, v17.4s, v0.4s\n\t"
      "umin v0.4s, v0.4s, v22.4s\n\t"
      "cmhi v25.4s, v23.4s, v25.4s\n\t"
      "sshr v22.4s, v4.4s, #1\n\t"
      "eor v30.16b, v31.16b, v29.16b\n\t"
      "srshr v4.4s, v4.4s, #1\n\t"
      "cmhs v3.4s, v26.4s, v3.4s\n\t"
      "mul v0.4s, v0.4s, v21.4s\n\t"
      "eor v25.16b, v25.16b, v29.16b\n\t"
      "sshr v9.4s, v9.4s, #3\n\t"
      "sub v30.4s, v30.4s, v29.4s\n\t"
      "cmhs v0.4s, v27.4s, v0.4s\n\t"
      "bit v22.16b, v4.16b, v25.16b\n\t"
      "and v6.16b, v6.16b, v3.16b\n\t"
      "bit v24.16b, v9.16b, v3.16b\n\t"
      "and v0.16b, v0.16b, v16.16b\n\t"
      "sub v21.4s, v30.4s, v22.4s\n\t"
      "fmov x10, d6\n\t"
      "mov x24, v24.d[1]\n\t"
      "fmov x9, d24\n\t"
      "mov x25, v6.d[1]\n\t"
      "and v1.16b, v1.16b, v0.16b\n\t"
      "bit v30.16b, v21.16b, v0.16b\n\t"
      "and x1, x9, #0xffffffff00000000\n\t"
      "and x2, x10, #0xffffffff00000000\n\t"
      "and x4, x25, #0xffffffff00000000\n\t"
      "add x10, x2, w10, sxtw\n\t"
      "lsl x20, x10, #2\n\t"
      "add x9, x1, w9, sxtw\n\t"
      "lsr x1, x13, #48\n\t"
      "stp q30, q1, [%[st], #16]\n\t"
      "and x3, x24, #0xffffffff00000000\n\t"
      "add x17, x10, x9, lsl #1\n\t"
      "add x14, x13, x9\n\t"
      "add x19, x17, x10, lsl #1\n\t"
      "add x15, x13, x17\n\t"
      "lsr w9, w13, #16\n\t"
      "add x24, x3, w24, sxtw\n\t"
      "lsr x2, x14, #48\n\t"
      "add x17, x17, x20\n\t"
      "lsr w10, w14, #16\n\t"
      "add x13, x15, x17\n\t"
      "lsr x3, x15, #48\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "add x16, x14, x19\n\t"
      "add x19, x19, x20\n\t"
      "lsr w11, w15, #16\n\t"
      "lsr x5, x13, #48\n\t"
      "lsr w9, w13, #16\n\t"
      "add x17, x17, x20\n\t"
      "add x15, x13, x17\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "add x14, x16, x19\n\t"
      "lsr x7, x15, #48\n\t"
      "add x19, x19, x20\n\t"
      "add x13, x15, x17\n\t"
      "add x25, x4, w25, sxtw\n\t"
      "lsr x4, x16, #48\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr x6, x14, #48\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "add x16, x14, x19\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "add x19, x19, x20\n\t"
      "add x17, x17, x20\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x8, x16, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "add x15, x13, x17\n\t"
      "add x17, x17, x20\n\t"
      "lsr w9, w13, #16\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "add x14, x16, x19\n\t"
      "lsr x1, x13, #48\n\t"
      "add x13, x15, x17\n\t"
      "lsr x3, x15, #48\n\t"
      "add x19, x19, x20\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr w11, w15, #16\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "add x16, x14, x19\n\t"
      "str w15, [%[d]]\n\t"
      "add x19, x19, x20\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "add x15, x13, x17\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "lsr x2, x14, #48\n\t"
      "lsr w10, w14, #16\n\t"
      "add x14, x16, x19\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "add x17, x25, x24, lsl #1\n\t"
      "add x19, x19, x20\n\t"
      "lsr x4, x16, #48\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr x6, x14, #48\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x5, x13, #48\n\t"
      "lsr w9, w13, #16\n\t"
      "lsr x7, x15, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "add x16, x14, x19\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "add x14, x23, x24\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "str w15, [%[d], #4]\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "add x19, x17, x25, lsl #1\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "add x15, x23, x17\n\t"
      "lsl x20, x25, #2\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "lsr x8, x16, #48\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "lsr x2, x14, #48\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr w11, w15, #16\n\t"
      "lsr x3, x15, #48\n\t"
      "lsr x1, x23, #48\n\t"
      "lsr w9, w23, #16\n\t"
      "add x23, x15, x17\n\t"
      "add x16, x14, x19\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "lsr x5, x23, #48\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "add x17, x17, x20\n\t"
      "str w15, [%[d], #8]\n\t"
      "add x15, x23, x17\n\t"
      "add x19, x19, x20\n\t"
      "lsr w9, w23, #16\n\t"
      "add x17, x17, x20\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "ldr x24, [%[st], #24]\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "add x23, x15, x17\n\t"
      "add x17, x17, x20\n\t"
      "lsr w11, w15, #16\n\t"
      "lsr w10, w14, #16\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "add x14, x16, x19\n\t"
      "lsr w9, w23, #16\n\t"
      "lsr x7, x15, #48\n\t"
      "add x19, x19, x20\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "lsr x4, x16, #48\n\t"
      "lsr w12, w16, #16\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "str w15, [%[d], #12]\n\t"
      "add x16, x14, x19\n\t"
      "add x19, x19, x20\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "add x15, x23, x17\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "add x17, x17, x20\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x8, x16, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "lsr x6, x14, #48\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "add x14, x16, x19\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "lsr w12, w16, #16\n\t"
      "lsr x1, x23, #48\n\t"
      "lsr x3, x15, #48\n\t"
      "lsr x2, x14, #48\n\t"
      "add x23, x15, x17\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "ldr x25, [%[st], #40]\n\t"
      "madd w3, w3, %w[w], w11\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "add x19, x19, x20\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "add x16, x14, x19\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "madd w1, w1, %w[w], w9\n\t"
      "str w15, [%[d], #16]\n\t"
      "add x17, x17, x20\n\t"
      "add x19, x19, x20\n\t"
      "lsr w12, w16, #16\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "lsr w10, w14, #16\n\t"
      "add x14, x16, x19\n\t"
      "lsr x4, x16, #48\n\t"
      "lsr w9, w23, #16\n\t"
      "lsr x5, x23, #48\n\t"
      "madd w4, w4, %w[w], w12\n\t"
      "madd w2, w2, %w[w], w10\n\t"
      "ldrb w1, [%[tx], w1, uxtw]\n\t"
      "add x19, x19, x20\n\t"
      "ldrb w3, [%[tx], w3, uxtw]\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "add x15, x23, x17\n\t"
      "lsr x7, x15, #48\n\t"
      "lsr w11, w15, #16\n\t"
      "ldrb w2, [%[tx], w2, uxtw]\n\t"
      "madd w5, w5, %w[w], w9\n\t"
      "ldrb w4, [%[tx], w4, uxtw]\n\t"
      "madd w7, w7, %w[w], w11\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "add x16, x14, x19\n\t"
      "lsr w10, w14, #16\n\t"
      "lsr x8, x16, #48\n\t"
      "lsr x6, x14, #48\n\t"
      "lsr w12, w16, #16\n\t"
      "madd w6, w6, %w[w], w10\n\t"
      "ldrb w5, [%[tx], w5, uxtw]\n\t"
      "madd w8, w8, %w[w], w12\n\t"
      "ldrb w7, [%[tx], w7, uxtw]\n\t"
      "orr x21, x1, x2, lsl #8\n\t"
      "orr x22, x3, x4, lsl #8\n\t"
      "str w15, [%[d], #20]\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "ldrb w6, [%[tx], w6, uxtw]\n\t"
      "and x13, x24, #0xffffffff00000000\n\t"
      "ldrb w8, [%[tx], w8, uxtw]\n\t"
      "add x24, x13, w24, sxtw\n\t"
      "and x13, x25, #0xffffffff00000000\n\t"
      "ldr x9, [%[st], #16]\n\t"
      "add x25, x13, w25, sxtw\n\t"
      "str w15, [%[d], #24]\n\t"
      "orr x22, x7, x8, lsl #8\n\t"
      "ldr w1, [%[y], #72]\n\t"
      "orr x21, x5, x6, lsl #8\n\t"
      "ldr x10, [%[st], #32]\n\t"
      "orr x15, x21, x22, lsl #16\n\t"
      "ldr x13, [%[st]]\n\t"
      "and x11, x9, #0xffffffff00000000\n\t"
      "ldr x23, [%[st], #8]\n\t"
      "add x9, x11, w9, sxtw\n\t"
      "cmp w1, #0xf\n\t"
      "and x11, x10, #0xffffffff00000000\n\t"
      "str w15, [%[d], #28]\n\t"
      "add x10, x11, w10, sxtw"
// END steps_k3v_pass
      : "=&r"(ra_uv), "=&r"(ra_d), "=&r"(ra_dd), "=&r"(rb_uv), "=&r"(rb_d), "=&r"(rb_dd), "+&w"(rS44), "+&w"(rc01),
        "+&w"(rc23), "+&w"(rzs), "+&w"(rzc), "=@cceq"(full), [y] "+&r"(ys)
      : "w"(rS01), "w"(rS23), [kp] "r"(kMidTable.c), [st] "r"(st), [d] "r"(dest),
        [tx] "r"(texels), [w] "r"(width)
      : "memory", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x11", "x12", "x14", "x15", "x16", "x17", "x19",
        "x20", "x21", "x22", "v0", "v2", "v4", "v6", "v9", "v17", "v18", "v20", "v21", "v22", "v23", "v24", "v25", "v26",
        "v27", "v28", "v29", "v30");
  return MidFirst{ra_uv, ra_d, ra_dd, rb_uv, rb_d, rb_dd};
}
// Run16's packing of an unpacked [du, dv] lane x: (x & (2^64 - 2^32)) + sext(x mod 2^32).
SB_INLINE uint64_t mid_pack(uint64_t x) {
  return (x & 0xffffffff00000000) + uint64_t(int64_t(int32_t(uint32_t(x))));
}
// Runs 2 and 3 of a four-run span whose last run is partial (persp_mid_k3: last = 1 .. 15
// pixels): dest[32 .. 47] (run 2) from steps_k3v_pass's second-pass registers uv = x13, duv =
// x9, dduv = x10 and dest[48 .. 47 + last] from x23, x24, x25 (the last run's start and steps;
// all Run16's packing, taken where the block leaves them: no reload of st, no packing). Each
// pixel's position as Run16 / draw_last compute it (the walker's recurrence, two chains c0 =
// uv_k, c1 = uv_{k+1} stepped by e0 = 2 duv + dduv, e1 = 2 duv + 3 dduv, each e by 4 dduv a
// pixel pair: the same integers modulo 2^64). Run 2's 16 pixels in four 32-bit stores, the
// last run's chains set up among them; then the last run in chunks of 8, 4, 2, 1 pixels by
// last's bits (draw_last's order), each behind a tbz, the chains going on from chunk to
// chunk (every chunk but the last is even: no closed-form restart as draw_last's). Each
// region also computes the texel offsets of the next chunk's first two pixels (that chunk's
// first loads issue at once; chunk 1 is a load and a store); an offset past the span's end
// is computed but never loaded from. x13, x9, x10 are only read (each block timed as a loop
// does not wait on its own writes of them). Generated by bench/mca_a53_pair/gen_run2l.py
// (`pre w4`), each region ordered by bench/order_search.py (bench/mca_a53_pair/run2l_s.s;
// x18, x26, x28, w0 the operands w, tx, d, n).
// AsmSpanPersp.EveryPartialLastRunLengthMatchesOnEveryPath and the four-run span tests check it.
SB_INLINE void runs_k3(uint8_t* __restrict d, const uint8_t* __restrict tx, uint64_t w, int last, uint64_t uv,
                       uint64_t duv, uint64_t dduv, uint64_t l_uv, uint64_t l_d, uint64_t l_dd) {
  register uint64_t r13 __asm__("x13") = uv;
  register uint64_t r9 __asm__("x9") = duv;
  register uint64_t r10 __asm__("x10") = dduv;
  register uint64_t r23 __asm__("x23") = l_uv;
  register uint64_t r24 __asm__("x24") = l_d;
  register uint64_t r25 __asm__("x25") = l_dd;
  __asm__ volatile(
// BEGIN runs_k3
      "add x1, x13, x9\n\t"
      "add x2, x10, x9, lsl #1\n\t"
      "lsl x4, x10, #2\n\t"
      "add x11, x13, x2\n\t"
      "lsr x5, x13, #48\n\t"
      "lsr w8, w1, #16\n\t"
      "lsr x7, x1, #48\n\t"
      "lsr w16, w11, #16\n\t"
      "lsr w6, w13, #16\n\t"
      "madd w12, w5, %w[w], w6\n\t"
      "add x3, x2, x10, lsl #1\n\t"
      "madd w14, w7, %w[w], w8\n\t"
      "add x1, x1, x3\n\t"
      "add x3, x3, x4\n\t"
      "lsr x17, x1, #48\n\t"
      "lsr w19, w1, #16\n\t"
      "lsr x15, x11, #48\n\t"
      "ldrb w20, [%[tx], w12, uxtw]\n\t"
      "add x2, x2, x4\n\t"
      "ldrb w21, [%[tx], w14, uxtw]\n\t"
      "add x1, x1, x3\n\t"
      "madd w22, w15, %w[w], w16\n\t"
      "add x11, x11, x2\n\t"
      "add x3, x3, x4\n\t"
      "lsr x8, x1, #48\n\t"
      "lsr x6, x11, #48\n\t"
      "lsr w7, w11, #16\n\t"
      "madd w5, w17, %w[w], w19\n\t"
      "orr x14, x20, x21, lsl #8\n\t"
      "add x2, x2, x4\n\t"
      "lsr w12, w1, #16\n\t"
      "ldrb w15, [%[tx], w22, uxtw]\n\t"
      "add x11, x11, x2\n\t"
      "madd w19, w8, %w[w], w12\n\t"
      "add x1, x1, x3\n\t"
      "ldrb w16, [%[tx], w5, uxtw]\n\t"
      "add x2, x2, x4\n\t"
      "add x3, x3, x4\n\t"
      "lsr w21, w11, #16\n\t"
      "lsr x20, x11, #48\n\t"
      "add x11, x11, x2\n\t"
      "madd w17, w6, %w[w], w7\n\t"
      "add x2, x2, x4\n\t"
      "orr x6, x15, x16, lsl #8\n\t"
      "lsr x22, x1, #48\n\t"
      "lsr w5, w1, #16\n\t"
      "orr x7, x14, x6, lsl #16\n\t"
      "ldrb w12, [%[tx], w19, uxtw]\n\t"
      "add x1, x1, x3\n\t"
      "add x3, x3, x4\n\t"
      "madd w15, w20, %w[w], w21\n\t"
      "ldrb w8, [%[tx], w17, uxtw]\n\t"
      "str w7, [%[d], #32]\n\t"
      "madd w16, w22, %w[w], w5\n\t"
      "add x21, x23, x24\n\t"
      "lsr w6, w11, #16\n\t"
      "lsr x14, x11, #48\n\t"
      "lsr w17, w1, #16\n\t"
      "lsr x7, x1, #48\n\t"
      "orr x19, x8, x12, lsl #8\n\t"
      "add x22, x25, x24, lsl #1\n\t"
      "lsl x8, x25, #2\n\t"
      "add x11, x11, x2\n\t"
      "madd w24, w14, %w[w], w6\n\t"
      "ldrb w20, [%[tx], w15, uxtw]\n\t"
      "add x2, x2, x4\n\t"
      "add x5, x22, x25, lsl #1\n\t"
      "ldrb w15, [%[tx], w16, uxtw]\n\t"
      "madd w25, w7, %w[w], w17\n\t"
      "add x1, x1, x3\n\t"
      "add x3, x3, x4\n\t"
      "lsr w7, w1, #16\n\t"
      "lsr w14, w11, #16\n\t"
      "lsr x16, x11, #48\n\t"
      "lsr x6, x1, #48\n\t"
      "orr x17, x20, x15, lsl #8\n\t"
      "add x1, x1, x3\n\t"
      "add x11, x11, x2\n\t"
      "ldrb w20, [%[tx], w24, uxtw]\n\t"
      "add x3, x3, x4\n\t"
      "add x2, x2, x4\n\t"
      "orr x4, x19, x17, lsl #16\n\t"
      "lsr w24, w11, #16\n\t"
      "madd w17, w6, %w[w], w7\n\t"
      "madd w19, w16, %w[w], w14\n\t"
      "ldrb w15, [%[tx], w25, uxtw]\n\t"
      "str w4, [%[d], #36]\n\t"
      "lsr w16, w1, #16\n\t"
      "lsr x4, x11, #48\n\t"
      "lsr x25, x1, #48\n\t"
      "add x1, x1, x3\n\t"
      "ldrb w7, [%[tx], w17, uxtw]\n\t"
      "madd w3, w25, %w[w], w16\n\t"
      "orr x14, x20, x15, lsl #8\n\t"
      "add x11, x11, x2\n\t"
      "madd w2, w4, %w[w], w24\n\t"
      "ldrb w6, [%[tx], w19, uxtw]\n\t"
      "lsr w15, w11, #16\n\t"
      "lsr x20, x11, #48\n\t"
      "lsr w17, w1, #16\n\t"
      "lsr x19, x1, #48\n\t"
      "orr x4, x6, x7, lsl #8\n\t"
      "madd w11, w20, %w[w], w15\n\t"
      "madd w1, w19, %w[w], w17\n\t"
      "ldrb w16, [%[tx], w3, uxtw]\n\t"
      "ldrb w25, [%[tx], w2, uxtw]\n\t"
      "lsr w3, w23, #16\n\t"
      "ldrb w7, [%[tx], w11, uxtw]\n\t"
      "orr x24, x14, x4, lsl #16\n\t"
      "ldrb w14, [%[tx], w1, uxtw]\n\t"
      "orr x6, x25, x16, lsl #8\n\t"
      "lsr w19, w21, #16\n\t"
      "add x12, %[d], #48\n\t"
      "lsr x2, x23, #48\n\t"
      "orr x4, x7, x14, lsl #8\n\t"
      "str w24, [%[d], #40]\n\t"
      "orr x24, x6, x4, lsl #16\n\t"
      "lsr x15, x21, #48\n\t"
      "madd w20, w2, %w[w], w3\n\t"
      "madd w17, w15, %w[w], w19\n\t"
      "str w24, [%[d], #44]\n\t"
      "tbz %w[n], #3, 1f\n\t"
      "add x23, x23, x22\n\t"
      "add x22, x22, x8\n\t"
      "add x21, x21, x5\n\t"
      "lsr w1, w21, #16\n\t"
      "lsr w16, w23, #16\n\t"
      "lsr x25, x23, #48\n\t"
      "add x23, x23, x22\n\t"
      "lsr x11, x21, #48\n\t"
      "madd w6, w25, %w[w], w16\n\t"
      "add x5, x5, x8\n\t"
      "ldrb w14, [%[tx], w17, uxtw]\n\t"
      "madd w4, w11, %w[w], w1\n\t"
      "ldrb w7, [%[tx], w20, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "add x21, x21, x5\n\t"
      "lsr x3, x21, #48\n\t"
      "lsr x24, x23, #48\n\t"
      "add x5, x5, x8\n\t"
      "lsr w2, w23, #16\n\t"
      "lsr w15, w21, #16\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w16, [%[tx], w4, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "orr x19, x7, x14, lsl #8\n\t"
      "lsr w14, w23, #16\n\t"
      "madd w11, w24, %w[w], w2\n\t"
      "madd w1, w3, %w[w], w15\n\t"
      "ldrb w25, [%[tx], w6, uxtw]\n\t"
      "add x5, x5, x8\n\t"
      "lsr x7, x23, #48\n\t"
      "add x22, x22, x8\n\t"
      "lsr w4, w21, #16\n\t"
      "lsr x6, x21, #48\n\t"
      "orr x24, x25, x16, lsl #8\n\t"
      "madd w25, w7, %w[w], w14\n\t"
      "ldrb w3, [%[tx], w11, uxtw]\n\t"
      "madd w16, w6, %w[w], w4\n\t"
      "orr x2, x19, x24, lsl #16\n\t"
      "ldrb w15, [%[tx], w1, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w24, [%[tx], w25, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "ldrb w11, [%[tx], w16, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "lsr w4, w23, #16\n\t"
      "orr x19, x3, x15, lsl #8\n\t"
      "lsr x3, x21, #48\n\t"
      "lsr x6, x23, #48\n\t"
      "orr x1, x24, x11, lsl #8\n\t"
      "lsr w15, w21, #16\n\t"
      "orr x7, x19, x1, lsl #16\n\t"
      "madd w17, w3, %w[w], w15\n\t"
      "madd w20, w6, %w[w], w4\n\t"
      "orr x14, x2, x7, lsl #32\n\t"
      "add x5, x5, x8\n\t"
      "str x14, [x12], #8\n\t"
      "1:\n\t"
      "tbz %w[n], #2, 2f\n\t"
      "add x23, x23, x22\n\t"
      "lsr w16, w23, #16\n\t"
      "lsr x25, x23, #48\n\t"
      "add x21, x21, x5\n\t"
      "lsr x24, x21, #48\n\t"
      "lsr w11, w21, #16\n\t"
      "add x5, x5, x8\n\t"
      "madd w2, w25, %w[w], w16\n\t"
      "madd w7, w24, %w[w], w11\n\t"
      "ldrb w19, [%[tx], w20, uxtw]\n\t"
      "add x21, x21, x5\n\t"
      "lsr w16, w21, #16\n\t"
      "ldrb w1, [%[tx], w17, uxtw]\n\t"
      "add x22, x22, x8\n\t"
      "ldrb w6, [%[tx], w2, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w4, [%[tx], w7, uxtw]\n\t"
      "add x5, x5, x8\n\t"
      "lsr x25, x21, #48\n\t"
      "lsr x5, x23, #48\n\t"
      "orr x14, x19, x1, lsl #8\n\t"
      "madd w17, w25, %w[w], w16\n\t"
      "add x22, x22, x8\n\t"
      "orr x3, x6, x4, lsl #8\n\t"
      "lsr w8, w23, #16\n\t"
      "madd w20, w5, %w[w], w8\n\t"
      "orr x15, x14, x3, lsl #16\n\t"
      "str w15, [x12], #4\n\t"
      "2:\n\t"
      "tbz %w[n], #1, 3f\n\t"
      "ldrb w11, [%[tx], w17, uxtw]\n\t"
      "add x23, x23, x22\n\t"
      "ldrb w24, [%[tx], w20, uxtw]\n\t"
      "lsr x1, x23, #48\n\t"
      "lsr w2, w23, #16\n\t"
      "madd w20, w1, %w[w], w2\n\t"
      "orr x19, x24, x11, lsl #8\n\t"
      "strh w19, [x12], #2\n\t"
      "3:\n\t"
      "tbz %w[n], #0, 4f\n\t"
      "ldrb w7, [%[tx], w20, uxtw]\n\t"
      "strb w7, [x12]\n\t"
      "4:"
// END runs_k3
      : "+r"(r23), "+r"(r24), "+r"(r25)
      : [d] "r"(d), [tx] "r"(tx), [w] "r"(w), [n] "r"(last), "r"(r13), "r"(r9), "r"(r10)
      : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x11", "x12", "x14", "x15", "x16", "x17", "x19", "x20",
        "x21", "x22", "memory");
}
// Draws a second-order span of 49 .. 64 pixels (4 runs; last = n - 48 pixels in the last
// run) from the sample block's results (persp_short_inl): the steps with runs 0, 1
// (steps_k3v_pass), then runs 2, 3 as one short_pass (last == 16) or by runs_k3 (run 2 and the
// partial last run). zh = zc * 0.5; width's value as an int (int64_t: the single-span
// entry hands it on sign-extended).
SB_INLINE void persp_mid_k3(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01, int32x4_t S23,
                            int32x4_t S44, float64x2_t c01, float64x2_t c23, float64x2_t zs23, double zh) {
  uint64_t st[6];
  bool full;  // last == 16
  // s = last - 1 indexes the same MidSteps as max(last - 1, 1) (kMidSteps[0] == kMidSteps[1]:
  // mid_steps(1)), without a compare and select before the block's table loads.
  const MidFirst second = steps_k3v_pass(dest, texels, uint64_t(width), S01, S23, S44, c01, c23, zs23,
                                         last - 1, zh, st, full);
  if (full) {
    short_pass<true>(dest + 32, texels, uint64_t(width), second.a_uv, second.a_d, second.a_dd, second.b_uv,
                     second.b_d, second.b_dd);
    return;
  }
  runs_k3(dest, texels, uint64_t(width), last, second.a_uv, second.a_d, second.a_dd, second.b_uv, second.b_d,
          second.b_dd);
}
#endif

}  // namespace
}  // namespace sb::simd
