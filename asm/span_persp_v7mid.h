// asm/span_persp_v7mid.h: the whole-span drawer's ARMv7 path for second-order spans of
// 50 .. 64 pixels (asm/span_persp.h): four runs, the last of n - 48 = 2 .. 16 pixels.
// Internal: included by asm/span_persp_fast.cpp only, after asm/span_persp_arm.h
// (anonymous namespace).
//
// persp_fast computes a pass's samples beside the runs before it; for four runs that
// pipeline costs more than it hides. Here: one asm prologue (fixed VFP registers; the
// fields' copies that the destructive vfma needs loaded again from p, not moved) computes
// the five samples (the divides back to back, the other samples' work in their latency),
// run 0's ddf and the last run's quotients; runs 1 and 2's steps (ddf and
// steps16_dd in NEON lanes) are computed beside run 0's pixels, the last run's (last_ddi,
// last_dd in NEON lanes) beside run 1's and run 2's (each run one asm statement whose
// values stay in registers, with VFP / NEON work between its pixel groups). Every double
// operation is the walker's (asm/span_walk.h), as persp_fast performs it:
//   positions   P, P + 16, P + 32, (P + 16) + 32, ((P + 16) + 16) + (n - 33): the walker's
//               accumulated run starts plus the sample offsets (persp_fast's pos0 .. pos4)
//   depth       z = 1 / max(zrow + zix x, kMinZi) (fused, as compiled; vcmpe / vmovle)
//   u           fix((urow + ux x) z) = usat32(trunc((urow + ux x) (z 2^16))), min umax:
//               (t z) 2^16 = t (z 2^16) exactly (a power-of-two scaling commutes with
//               rounding; when t z is subnormal both give |value| < 1, fix 0; overflow gives
//               infinity either way; NaN -> 0 either way; z 2^16 <= 2^46 is exact and
//               finite), so vcvt.u32.f64 #16 (fixed point: truncating, saturating, NaN -> 0,
//               of t z times 2^16 exactly) is min_ufixed16 / cvt_ufixed16's value; v
//               likewise; the conversions (each in the low half of its register) paired by
//               vtrn.32 into [u, v] per d register, clamped by vmin.u32 against [umax, vmax]
//   full runs   ddf = delta (zck (z_a + z_b)), zck = zix * -1/16 (persp_fast's argument:
//               the walker's -2 (delta / 16 * curve), same bits), cvt_sat, steps16_dd
//   last run    q = double(delta) / (n - 49) (last_quotient), curve = (zix * 0.5) (z_3 + z_4),
//               last_ddi (cvt_sat(-2 (q curve)), the range test) and last_steps_i's test
// delta: u_b - u_a in int32 (both in [0, 2^31)), converted exactly.
#pragma once
#include <cstddef>

#include "asm/span_persp_arm.h"
#include "asm/span_persp_run.h"

namespace sb::simd {
namespace {
#if defined(__arm__) && !defined(__aarch64__) && defined(__GNUC__) && defined(__ARM_FEATURE_DSP) && \
    defined(__ARM_FP) && (__ARM_FP & 8) && defined(__ARM_NEON)
#define SB_V7_MID 1
constexpr int kMidMin = 50, kMidMax = 64;
static_assert(offsetof(PerspSpan, zi0) == 0 && offsetof(PerspSpan, dzi) == 8 && offsetof(PerspSpan, uz0) == 16 &&
              offsetof(PerspSpan, duz) == 24 && offsetof(PerspSpan, vz0) == 32 && offsetof(PerspSpan, dvz) == 40 &&
              offsetof(PerspSpan, px0) == 48 && offsetof(PerspSpan, umax) == 56 && offsetof(PerspSpan, vmax) == 60,
              "the prologue loads zi0 / dzi, uz0 / duz, vz0 / dvz, px0 / [umax, vmax] in pairs (vld1.64)");
// kMinZi, -1/16, 1/2, 1: the prologue's constants (in kMidN's rows).
constexpr double kMidConsts[4] = {kMinZi, -0.0625, 0.5, 1.0};
// Per span length n (kMidMin .. kMidMax), as the prologue loads them (three vld1.64 from the
// row, + 16, + 32): 16, 32, L = n - 49 (the last run's divisor), n - 33 (the last sample's
// offset from P + 32), then kMidConsts; exact doubles (no conversion in the prologue).
// Row kMidFour (after them): L = 16, offset 32, the four runs of a longer span
// (persp_mid_v7<.., true>: run 3 full, its steps over 16 pixels to sample 4 at
// ((P + 16) + 16) + 32, the walker's run 4 start).
constexpr int kMidFour = kMidMax - kMidMin + 1;
struct MidNTable {
  alignas(16) double row[kMidFour + 1][8];
};
constexpr MidNTable kMidN = [] {
  MidNTable t{};
  for (int n = kMidMin; n <= kMidMax + 1; ++n) {
    const bool four = n > kMidMax;
    const double r[8] = {16.0, 32.0, four ? 16.0 : double(n - 49), four ? 32.0 : double(n - 33), kMidConsts[0],
                         kMidConsts[1], kMidConsts[2], kMidConsts[3]};
    for (int i = 0; i < 8; ++i) t.row[n - kMidMin][i] = r[i];
  }
  return t;
}();

// The int32 a conversion (vcvt.s32.f64) left in a single register.
SB_INLINE int32_t int_bits(float x) { return __builtin_bit_cast(int32_t, x); }
// Per last-run step count s (1 .. 15, and 16: kMidFour's full run 3): [s, s], [1e9, 1e9]
// (last_ddi's bound), [s - 1, s - 1], [T, T] with T = s (s - 1) / 2, as the last run's NEON
// steps load them.
constexpr auto kMidLast = [] {
  struct Table {
    alignas(8) uint32_t row[17][8];
    constexpr const uint32_t* operator[](int s) const { return row[s]; }
  } t{};
  for (uint32_t s = 1; s <= 16; ++s) {
    const uint32_t r[8] = {s, s, 1000000000u, 1000000000u, s - 1, s - 1, s * (s - 1) / 2, s * (s - 1) / 2};
    for (int i = 0; i < 8; ++i) t.row[s][i] = r[i];
  }
  return t;
}();
// A NEON quad register's worth (two d registers), for asm operands.
typedef int32_t V4 __attribute__((vector_size(16)));
// The two int32 lanes of a d register (one vmov r, r, d).
SB_INLINE void lanes(double x, int32_t* lo, int32_t* hi) {
  int32_t a, b;
  __asm__("vmov %0, %1, %P2" : "=r"(a), "=r"(b) : "w"(x));
  *lo = a, *hi = b;
}
// lanes() on a register variable itself (the asm operand is the variable: the compiler then
// reads it where it is bound, with no copy into another register, e.g. a callee-saved one).
#define SB_V7_LANES(x, lo, hi) __asm__("vmov %0, %1, %P2" : "=r"(lo), "=r"(hi) : "w"(x))

// One 16-pixel second-order run in one asm statement: surface_span's pixels
// (u_{k+1} = u_k + du_k, du_{k+1} = du_k + ddu, likewise v; texel (v_k >> 16) w + (u_k >> 16)),
// as Run16's ARMv7 groups compute them (smulbt, uxtah: the contract keeps w <= 32767 and
// 0 <= v < 2^31), the bytes gathered into four little-endian words (str: ARMv7 allows an
// unaligned dest). Eight groups of two pixels; F0 .. F7: VFP instructions placed after each
// group (other runs' work, issued beside the integer pixels: the modelled Cortex-A9 dispatches
// them with the integer instructions), with the caller's operands (named after the run's
// eleven). One statement, so that the run's values stay in registers throughout.
#define SB_V7_PX(t)                       \
  "smulbt " t ", %[w], %[v]\n\t"          \
  "uxtah " t ", " t ", %[u], ror #16\n\t" \
  "add %[u], %[u], %[du]\n\t"             \
  "add %[v], %[v], %[dv]\n\t"             \
  "add %[du], %[du], %[ddu]\n\t"          \
  "add %[dv], %[dv], %[ddv]\n\t"          \
  "ldrb " t ", [%[tx], " t "]\n\t"
#define SB_V7_LO SB_V7_PX("%[a]") SB_V7_PX("%[b]") "orr %[a], %[a], %[b], lsl #8\n\t"
#define SB_V7_HI(off) \
  SB_V7_PX("%[b]") "orr %[a], %[a], %[b], lsl #16\n\t" SB_V7_PX("%[b]") "orr %[a], %[a], %[b], lsl #24\n\t" \
  "str %[a], [%[d], #" off "]\n\t"
// The last two pixels: their steps are never read (pixel 14 steps u and v only, 15 none).
#define SB_V7_HI_END(off)                                                                         \
  "smulbt %[b], %[w], %[v]\n\tuxtah %[b], %[b], %[u], ror #16\n\tadd %[u], %[u], %[du]\n\t" \
  "add %[v], %[v], %[dv]\n\tldrb %[b], [%[tx], %[b]]\n\torr %[a], %[a], %[b], lsl #16\n\t"    \
  "smulbt %[b], %[w], %[v]\n\tuxtah %[b], %[b], %[u], ror #16\n\tldrb %[b], [%[tx], %[b]]\n\t"  \
  "orr %[a], %[a], %[b], lsl #24\n\tstr %[a], [%[d], #" off "]\n\t"
#define SB_V7_RUN(F0, F1, F2, F3, F4, F5, F6, F7) \
  SB_V7_LO F0 SB_V7_HI("0") F1 SB_V7_LO F2 SB_V7_HI("4") F3 SB_V7_LO F4 SB_V7_HI("8") F5 SB_V7_LO F6 \
      SB_V7_HI_END("12") F7
// persp_mid_v7's runs 0 .. 2 are written out: each the instructions SB_V7_RUN gives it (the
// pixel groups, the last two pixels without their unread steps, and its F0 .. F7 work), in an
// order bench/order_search.py --arch=armv7 --runs found within the statement against the
// Cortex-A9 model (on the blocks as qemu cuts them; every reordering keeps each register's and
// memory's order of reads and writes). The VFP / NEON registers are
// named as bound (uv1 .. uv4 = d1 .. d4, curve = d5, c1 = d28, c2 = d29, L = sd = d0; those
// stay listed as operands).
#define SB_V7_RUN_OPERANDS(dst)                                                               \
  [u] "+&r"(u), [v] "+&r"(v), [du] "+&r"(du), [dv] "+&r"(dv), [a] "=&r"(a), [b] "=&r"(b), \
      "=m"(*reinterpret_cast<uint8_t(*)[16]>(dst))
#define SB_V7_RUN_INPUTS(dst) [ddu] "r"(ddu), [ddv] "r"(ddv), [w] "r"(w), [tx] "r"(texels), [d] "r"(dst)
struct RunRegs {
  uint32_t u, v, du, dv, ddu, ddv;
};
SB_INLINE void draw16_v7(uint8_t* dest, const uint8_t* texels, uint32_t w, RunRegs r) {
  uint32_t u = r.u, v = r.v, du = r.du, dv = r.dv, a, b;
  const uint32_t ddu = r.ddu, ddv = r.ddv;
  __asm__ volatile(SB_V7_RUN("", "", "", "", "", "", "", "")
                   : SB_V7_RUN_OPERANDS(dest)
                   : SB_V7_RUN_INPUTS(dest)
                   : "memory");
}

// The prologue. Loads (vld1.64: the model dual-issues them, unlike vmov / vldr): zrow into
// each depth's accumulator d16, d18 .. d21 (zix with the first, d17), urow into t_0 .. t_4 =
// d0 .. d4 (ux with t_4, d5), vrow into s_0 .. s_4 = d6, d7, d30, d31, d17 (vx with s_1,
// d8), [P, [umax, vmax]] into d22, d23 ([umax, vmax] again into d22 once P is read),
// kMidN's row for n (the row, + 16, + 32): 16, 32 into d28, d29, L, n - 33 into d10,
// d11, kMinZi, -1/16, 1/2, 1 into d24 .. d27. Positions x0 .. x4 in d22, d30, d31, d9, d6;
// depths (clamped, then 1 / zi in place) d16, d18 .. d21; zck = zix * -1/16 in d25,
// zh = zix * 0.5 in d26; depth sums z_0 + z_1 .. z_3 + z_4 in d24, d28, d29, d5, made c_0,
// c_1, c_2 (times zck) and curve (times zh); t = urow + ux x, s = vrow + vx x (fused), times z in place, converted in
// place (vcvt.u32.f64 #16); vtrn.32 pairs q0 / q3, q1 / q15, d4 / d17 (sample j's [u, v]
// in d_j), clamped by vmin.u32 with q11 / d23; run 0's [u_1 - u_0, v_1 - v_0] in d11,
// converted (d30, d31), times c_0, cvt_sat into d6; the last run's [du, dv] in d7,
// converted (d8, d9), divided by L into d25, d24 (qu after zck's last read). A register is
// reused only after its value's last read. d8 .. d11 are the prologue's own (see mid_prologue).
// The multiply-adds are fused, as the compiled walker's are (GCC contracts them; the tests
// compare bit for bit). Then run 0's steps16_dd for u and v in the same statement (its
// integer work issued beside the VFP work): the deltas from d11 (one lane at a time into
// t1), [iu, iv] from d6 into ddu, ddv; steps16_dd's operations (asm/span_persp_run.h) with
// delta - 120 dd as delta - (dd << 7) + (dd << 3) (mod 2^32, as mls) and 120 |x| as
// (16 |x| - |x|) << 3 inside the compare (|x| <= 2^25: 15 |x| < 2^29, 120 |x| < 2^32, the
// same unsigned compare: lo here is hi there with the operands swapped); the address
// registers (p + 16 .. p + 56, the row + 16, + 32) are the outputs' registers until then.
// r: the samples [u, v] (d0 .. d4), c_1, c_2, curve; su, sv: run 0's steps; returns the
// quotients [qv, qu] (d24, d25).
// The prologue's instructions (mid_prologue), one string.
#define SB_V7_PROLOGUE \
  "add %[t2], %[nt], #32\n\t" \
  "add %[ddu], %[pz], #48\n\t" \
  "vld1.64 {d22, d23}, [%[ddu]]\n\t" \
  "add %[dv], %[pz], #32\n\t" \
  "vld1.64 {d16, d17}, [%[pz]]\n\t" \
  "vld1.64 {d24-d27}, [%[t2]]\n\t" \
  "vld1.64 {d20}, [%[pz]]\n\t" \
  "vld1.64 {d28, d29}, [%[nt]]\n\t" \
  "vfma.f64 d16, d17, d22\n\t" \
  "add %[t1], %[nt], #16\n\t" \
  "vadd.f64 d30, d22, d28\n\t" \
  "vld1.64 {d21}, [%[pz]]\n\t" \
  "vadd.f64 d31, d22, d29\n\t" \
  "vmul.f64 d25, d17, d25\n\t" \
  "vld1.64 {d18}, [%[pz]]\n\t" \
  "vfma.f64 d18, d17, d30\n\t" \
  "vld1.64 {d19}, [%[pz]]\n\t" \
  "add %[du], %[pz], #16\n\t" \
  "vld1.64 {d2}, [%[du]]\n\t" \
  "vadd.f64 d9, d30, d29\n\t" \
  "vld1.64 {d10, d11}, [%[t1]]\n\t" \
  "vadd.f64 d6, d30, d28\n\t" \
  "vfma.f64 d19, d17, d31\n\t" \
  "vcmpe.f64 d16, d24\n\t" \
  "vld1.64 {d7, d8}, [%[dv]]\n\t" \
  "vfma.f64 d20, d17, d9\n\t" \
  "vmrs APSR_nzcv, fpscr\n\t" \
  "vadd.f64 d6, d6, d11\n\t" \
  "it le\n\t" \
  "vmovle.f64 d16, d24\n\t" \
  "vcmpe.f64 d18, d24\n\t" \
  "vdiv.f64 d16, d27, d16\n\t" \
  "vmrs APSR_nzcv, fpscr\n\t" \
  "vld1.64 {d3}, [%[du]]\n\t" \
  "vcmpe.f64 d19, d24\n\t" \
  "it le\n\t" \
  "vmovle.f64 d18, d24\n\t" \
  "vdiv.f64 d18, d27, d18\n\t" \
  "vld1.64 {d0}, [%[du]]\n\t" \
  "vfma.f64 d21, d17, d6\n\t" \
  "vmrs APSR_nzcv, fpscr\n\t" \
  "it le\n\t" \
  "vmovle.f64 d19, d24\n\t" \
  "vcmpe.f64 d20, d24\n\t" \
  "vld1.64 {d4, d5}, [%[du]]\n\t" \
  "vmrs APSR_nzcv, fpscr\n\t" \
  "vfma.f64 d0, d5, d22\n\t" \
  "it le\n\t" \
  "vmovle.f64 d20, d24\n\t" \
  "vld1.64 {d1}, [%[du]]\n\t" \
  "vdiv.f64 d20, d27, d20\n\t" \
  "vmul.f64 d26, d17, d26\n\t" \
  "vcmpe.f64 d21, d24\n\t" \
  "vdiv.f64 d19, d27, d19\n\t" \
  "vfma.f64 d1, d5, d30\n\t" \
  "vmrs APSR_nzcv, fpscr\n\t" \
  "it le\n\t" \
  "vmovle.f64 d21, d24\n\t" \
  "vld1.64 {d17}, [%[dv]]\n\t" \
  "vdiv.f64 d21, d27, d21\n\t" \
  "vfma.f64 d7, d8, d30\n\t" \
  "vld1.64 {d30}, [%[dv]]\n\t" \
  "vfma.f64 d2, d5, d31\n\t" \
  "vfma.f64 d17, d8, d6\n\t" \
  "vfma.f64 d30, d8, d31\n\t" \
  "vfma.f64 d3, d5, d9\n\t" \
  "vfma.f64 d4, d5, d6\n\t" \
  "vld1.64 {d31}, [%[dv]]\n\t" \
  "vfma.f64 d31, d8, d9\n\t" \
  "vld1.64 {d6}, [%[dv]]\n\t" \
  "vmul.f64 d0, d0, d16\n\t" \
  "vmul.f64 d7, d7, d18\n\t" \
  "vmul.f64 d1, d1, d18\n\t" \
  "vadd.f64 d24, d16, d18\n\t" \
  "vfma.f64 d6, d8, d22\n\t" \
  "vcvt.u32.f64 d7, d7, #16\n\t" \
  "vcvt.u32.f64 d1, d1, #16\n\t" \
  "vmul.f64 d31, d31, d20\n\t" \
  "add %[ddv], %[pz], #56\n\t" \
  "vmul.f64 d3, d3, d20\n\t" \
  "vmul.f64 d24, d24, d25\n\t" \
  "vld1.64 {d22}, [%[ddv]]\n\t" \
  "vmul.f64 d2, d2, d19\n\t" \
  "vmul.f64 d6, d6, d16\n\t" \
  "vmul.f64 d30, d30, d19\n\t" \
  "vcvt.u32.f64 d31, d31, #16\n\t" \
  "vmul.f64 d4, d4, d21\n\t" \
  "vmul.f64 d17, d17, d21\n\t" \
  "vcvt.u32.f64 d0, d0, #16\n\t" \
  "vcvt.u32.f64 d2, d2, #16\n\t" \
  "vcvt.u32.f64 d6, d6, #16\n\t" \
  "vcvt.u32.f64 d3, d3, #16\n\t" \
  "vcvt.u32.f64 d4, d4, #16\n\t" \
  "vcvt.u32.f64 d17, d17, #16\n\t" \
  "vcvt.u32.f64 d30, d30, #16\n\t" \
  "vtrn.32 q0, q3\n\t" \
  "vmin.u32 q0, q0, q11\n\t" \
  "vtrn.32 d4, d17\n\t" \
  "vtrn.32 q1, q15\n\t" \
  "vsub.i32 d11, d1, d0\n\t" \
  "vadd.f64 d5, d20, d21\n\t" \
  "vadd.f64 d29, d19, d20\n\t" \
  "vcvt.f64.s32 d30, s22\n\t" \
  "vmin.u32 d4, d4, d23\n\t" \
  "vmin.u32 q1, q1, q11\n\t" \
  "vcvt.f64.s32 d31, s23\n\t" \
  "vmul.f64 d30, d30, d24\n\t" \
  "vmov %[t1], s22\n\t" \
  "vsub.i32 d7, d4, d3\n\t" \
  "vmul.f64 d31, d31, d24\n\t" \
  "vmul.f64 d5, d5, d26\n\t" \
  "vcvt.f64.s32 d9, s15\n\t" \
  "vcvt.f64.s32 d8, s14\n\t" \
  "vadd.f64 d28, d18, d19\n\t" \
  "vcvt.s32.f64 s12, d30\n\t" \
  "eor %[pz], %[t1], %[t1], asr #31\n\t" \
  "vcvt.s32.f64 s13, d31\n\t" \
  "sub %[pz], %[pz], %[t1], asr #31\n\t" \
  "vmov %[ddu], %[ddv], d6\n\t" \
  "ssat %[t2], #26, %[ddu]\n\t" \
  "eor %[t3], %[t2], %[t2], asr #31\n\t" \
  "sub %[t3], %[t3], %[t2], asr #31\n\t" \
  "sub %[du], %[t1], %[ddu], lsl #7\n\t" \
  "ssat %[t2], #26, %[ddv]\n\t" \
  "add %[du], %[du], %[ddu], lsl #3\n\t" \
  "rsb %[t3], %[t3], %[t3], lsl #4\n\t" \
  "vdiv.f64 d24, d9, d10\n\t" \
  "eor %[du], %[du], %[t1], asr #31\n\t" \
  "sub %[du], %[du], %[t1], asr #31\n\t" \
  "cmp %[pz], %[t3], lsl #3\n\t" \
  "itt lo\n\t" \
  "movlo %[ddu], #0\n\t" \
  "movlo %[du], %[pz]\n\t" \
  "lsr %[du], %[du], #4\n\t" \
  "eor %[du], %[du], %[t1], asr #31\n\t" \
  "sub %[du], %[du], %[t1], asr #31\n\t" \
  "eor %[t3], %[t2], %[t2], asr #31\n\t" \
  "vmul.f64 d28, d28, d25\n\t" \
  "vmov %[t1], s23\n\t" \
  "sub %[dv], %[t1], %[ddv], lsl #7\n\t" \
  "eor %[pz], %[t1], %[t1], asr #31\n\t" \
  "add %[dv], %[dv], %[ddv], lsl #3\n\t" \
  "sub %[t3], %[t3], %[t2], asr #31\n\t" \
  "eor %[dv], %[dv], %[t1], asr #31\n\t" \
  "sub %[dv], %[dv], %[t1], asr #31\n\t" \
  "rsb %[t3], %[t3], %[t3], lsl #4\n\t" \
  "sub %[pz], %[pz], %[t1], asr #31\n\t" \
  "cmp %[pz], %[t3], lsl #3\n\t" \
  "itt lo\n\t" \
  "movlo %[dv], %[pz]\n\t" \
  "movlo %[ddv], #0\n\t" \
  "vmul.f64 d29, d29, d25\n\t" \
  "vdiv.f64 d25, d8, d10\n\t" \
  "lsr %[dv], %[dv], #4\n\t" \
  "eor %[dv], %[dv], %[t1], asr #31\n\t" \
  "sub %[dv], %[dv], %[t1], asr #31"
#define SB_V7_PRO_OUT                                                                                       \
  "=w"(o0), "=w"(o1), "=w"(o2), "=w"(o3), "=w"(o4), "=w"(o6), "=w"(o7), "=w"(o8), "=w"(o9), [du] "=&r"(du), \
      [ddu] "=&r"(ddu), [dv] "=&r"(dv), [ddv] "=&r"(ddv), [t1] "=&r"(t1), [t2] "=&r"(t2), [t3] "=&r"(t3),  \
      [pz] "+r"(pz)
#define SB_V7_PRO_IN [nt] "r"(nt), "m"(p), "m"(kMidN)
#define SB_V7_PRO_CLOB                                                                                     \
  "cc", "d6", "d7", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d26", "d27", "d30", "d31"
template <bool kOwnSave, bool kFour = false>
SB_INLINE V4 mid_prologue(const PerspSpan& p, int n, double r[9], RunSteps* su, RunSteps* sv) {
  register double o0 __asm__("d0"), o1 __asm__("d1"), o2 __asm__("d2"), o3 __asm__("d3"), o4 __asm__("d4");
  register double o6 __asm__("d28"), o7 __asm__("d29"), o8 __asm__("d5");
  register V4 o9 __asm__("d24");
  uint32_t du, ddu, dv, ddv, t1, t2, t3;
  const double* pz = &p.zi0;
  const double* nt = kMidN.row[kFour ? kMidFour : n - kMidMin];
  // d8 .. d11 (callee-saved) are scratch in the prologue: kOwnSave saves and restores them
  // inside the statement (vst1.64 / vld1.64: the single-span entry then saves none), else
  // they are clobbers (saved once by the batch function).
      // In the order a search against llvm-mca's Cortex-A9 model found (bench/order_search.py
      // --arch=armv7; the model issues VFP / NEON in order: each waits least on its inputs).
  if constexpr (kOwnSave) {
    alignas(16) double save[4];
    __asm__ volatile("vst1.64 {d8-d11}, [%[sv]:128]\n\t" SB_V7_PROLOGUE "\n\tvld1.64 {d8-d11}, [%[sv]:128]"
                     : SB_V7_PRO_OUT, "=m"(save)
                     : SB_V7_PRO_IN, [sv] "r"(save)
                     : SB_V7_PRO_CLOB);
  } else {
    __asm__ volatile(SB_V7_PROLOGUE : SB_V7_PRO_OUT : SB_V7_PRO_IN : SB_V7_PRO_CLOB, "d8", "d9", "d10", "d11");
  }
  r[0] = o0, r[1] = o1, r[2] = o2, r[3] = o3, r[4] = o4, r[6] = o6, r[7] = o7, r[8] = o8;
  *su = RunSteps{int32_t(du), int32_t(ddu)}, *sv = RunSteps{int32_t(dv), int32_t(ddv)};
  return o9;
}

SB_INLINE RunRegs run_regs(int32_t u, int32_t v, const RunSteps& su, const RunSteps& sv) {
  return {uint32_t(u), uint32_t(v), uint32_t(su.d), uint32_t(sv.d), uint32_t(su.dd), uint32_t(sv.dd)};
}

// kOwnSave: the prologue saves the d8 .. d11 it uses (the single-span entry; see mid_prologue).
// kFour (n = 64 then): the first four runs of a longer span, run 3 full (kMidFour's row; its
// steps over 16 pixels, the walker's for a full run: q = delta / 16 exactly as the walker's
// quotient, curve = (zix / 2) (z_3 + z_4), then run_steps' test, which last_steps_i computes
// for any step count); runs 0 .. 2 drawn, run 3's registers returned in *run3 (the caller
// draws it, with its own work beside: persp_five_run_v7).
// Hook (kFour): called with std::integral_constant<int, K>: K = 0 after the prologue's
// statement, 1 after run 0's, 2 after run 1's (persp_five_run_v7 starts the last run's
// set-up there, in d8 .. d15, which the prologue's outputs and runs 0 .. 2 leave alone).
struct MidNoHook {
  template <typename K>
  SB_INLINE void operator()(K) const {}
};
template <bool kOwnSave = false, bool kFour = false, typename Hook = MidNoHook>
SB_INLINE void persp_mid_v7(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p,
                            RunRegs* run3 = nullptr, double* uv4out = nullptr, Hook hook = {}) {
  const uint32_t w = uint32_t(width);
  const int steps = kFour ? 16 : n - 49;  // the last run's (1 .. 15; kFour: 16)
  if (kFour && n != 64) __builtin_unreachable();
  double r[9];
  RunSteps su, sv;
  register V4 qd __asm__("d24") = mid_prologue<kOwnSave, kFour>(p, n, r, &su, &sv);
  hook(std::integral_constant<int, 0>{});
  // The quotients [qv, qu] (d24, d25: q12, which run 0 leaves alone) until run 1 reads them.
  // The prologue's registers kept (asm operands bound to them: no copies or spills).
  register double uv1 __asm__("d1") = r[1];
  register double uv2 __asm__("d2") = r[2];
  register double uv3 __asm__("d3") = r[3];
  register double uv4 __asm__("d4") = r[4];
  if constexpr (kFour) *uv4out = r[4];  // sample 4's [u, v] (the caller's last run starts there)
  register double curve __asm__("d5") = r[8];
  register double c1 __asm__("d28") = r[6];
  register double c2 __asm__("d29") = r[7];
  int32_t u0, v0, u1, v1;
  lanes(r[0], &u0, &v0), lanes(uv1, &u1, &v1);
  // Run 0; beside it runs 1 and 2's steps: their deltas [du_1, dv_1, du_2, dv_2] (vsub.i32
  // on the packed samples, exact as doubles), ddf = delta c_r, cvt_sat, then steps16_dd per
  // lane in one q register (the 32-bit form: pd = |delta|; accepted iff
  // 120 min(|dd|, 2^25) <= pd, as ssat(dd, 26) decides it there: |dd| >= 2^25 rejects either
  // way; dd' = accepted ? dd : 0; d = mirror((pd - 120 mirror(dd')) >> 4), mirror by delta's
  // sign, computed as (delta + (delta < 0 ? 15 : 0) - 120 dd') >> 4 (arithmetic: the shift
  // rounds down, the bias makes it round toward zero). delta + bias and 120 dd' fit int32
  // (120 |dd'| <= pd < 2^31), their difference only in 33 bits (up to 2 pd when dd' and
  // delta differ in sign: deltas near +-2^31 on textures 32767 texels wide): vhsub.s32
  // halves it exactly (floor), then >> 3 (floor(floor(x / 2) / 8) = floor(x / 16)). Outputs: q0 = the four d (d0 run 1's, d1 run 2's: uv1 is dead after its
  // lanes), q3 = the four dd (d6, d7): registers run 1 leaves alone, so no copies.
  register double d1r __asm__("d0"), dd1r __asm__("d6"), dd2r __asm__("d7");
  {
    RunRegs rr = run_regs(u0, v0, su, sv);
    uint32_t u = rr.u, v = rr.v, du = rr.du, dv = rr.dv, a, b;
    const uint32_t ddu = rr.ddu, ddv = rr.ddv;
    __asm__ volatile("smulbt %[a], %[w], %[v]\n\t"
                     "vsub.i32 d6, d2, d1\n\t"
                     "add %[v], %[dv]\n\t"
                     "vmov.i32 q10, #120\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vsub.i32 d7, d3, d2\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vabs.s32 q13, q3\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vcvt.f64.s32 d17, s13\n\t"
                     "add %[v], %[dv]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "vcvt.f64.s32 d16, s12\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vcvt.f64.s32 d18, s14\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vshr.s32 q15, q3, #31\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[v], %[dv]\n\t"
                     "vshr.u32 q15, q15, #28\n\t"
                     "add %[u], %[du]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "str %[a], [%[d]]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vadd.i32 q15, q15, q3\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[u], %[du]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "vmul.f64 d16, d16, d28\n\t"
                     "add %[u], %[du]\n\t"
                     "vcvt.f64.s32 d19, s15\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[u], %[du]\n\t"
                     "vcvt.s32.f64 s12, d16\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vmul.f64 d18, d18, d29\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "vmul.f64 d19, d19, d29\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vmov.i32 q11, #33554432\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "vmul.f64 d17, d17, d28\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "str %[a], [%[d], #4]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vcvt.s32.f64 s14, d18\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "vcvt.s32.f64 s15, d19\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "vcvt.s32.f64 s13, d17\n\t"
                     "add %[u], %[du]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "vabs.s32 q8, q3\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "vmin.u32 q8, q8, q11\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[u], %[du]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vmul.i32 q8, q8, q10\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "add %[du], %[ddu]\n\t"
                     "str %[a], [%[d], #8]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vmul.i32 q9, q3, q10\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "vcge.u32 q8, q13, q8\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[u], %[du]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "vand q9, q9, q8\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vand q3, q3, q8\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "vhsub.s32 q9, q15, q9\n\t"
                     "vshr.s32 q0, q9, #3\n\t"
                     "str %[a], [%[d], #12]\n\t"
                     : SB_V7_RUN_OPERANDS(dest), "=&w"(d1r), [uv1] "+w"(uv1), "=&w"(dd1r), "=&w"(dd2r)
                     : SB_V7_RUN_INPUTS(dest), [uv2] "w"(uv2), [uv3] "w"(uv3), [c1] "w"(c1), [c2] "w"(c2), [qd] "w"(qd)
                     : "memory", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d26", "d27",
                       "d30", "d31");
  }
  const double sd1 = d1r, sd2 = uv1, sdd1 = dd1r, sdd2 = dd2r;
  auto steps_of = [](double d, double dd, RunSteps* ou, RunSteps* ov) SB_LAMBDA_INLINE {
    int32_t a, b, c, e;
    lanes(d, &a, &b), lanes(dd, &c, &e);
    *ou = RunSteps{a, c}, *ov = RunSteps{b, e};
  };
  // d6: the last run's ddf, converted (I); d0: trunc(q) (L); d2: scratch (delta in run 1).
  hook(std::integral_constant<int, 1>{});
  // Runs 1 and 2 keep to d0 .. d7, d16 .. d31 (no callee-saved register: see mid_prologue).
  register double qi __asm__("d6");
  register double sdr __asm__("d0");
  // The last run's steps (last_ddi, last_steps_i: last_dd per lane, u and v in one d
  // register), beside runs 1 and 2: ddf = -2 (q curve) converted (cvt_sat) and kept if
  // |i| < 1e9 (and steps > 1), linear = trunc(q) (|q| < 2^31), delta [du, dv] (vsub.i32);
  // sg = delta >> 31, pd = |delta|, Q = |linear| (linear has delta's sign or is 0),
  // r = pd - s Q, m = (s - 1) pdd (pdd = dd mirrored by sg; masking and mirroring commute
  // with the product), d0 = Q - (m >> 1) - (m & 1 and s > 2 r), mirrored; rejected iff
  // T |dd| > pd (T = s (s - 1) / 2; the 64-bit product minus pd, saturating, is not 0): then
  // linear and 0, else d0 and dd. Handed from run 1 to run 2 in fixed registers: d6 = I
  // (ranged), d0 = L, d31 = |I| ranged, d27 = T, d19 = m (masked), d21 = sg, d22 = pd,
  // d23 = Q, d24 = S, d28 = r, d29 = [1, 1]. The results leave through a, b (d) and du, dv
  // (dd), free once the pixels are drawn.
  // Hand-off quads (d18 .. d31 in pairs; only the named halves carry values).
  register V4 h9 __asm__("d18"), h10 __asm__("d20"), h11 __asm__("d22"), h12 __asm__("d24") = qd;
  register V4 h13 __asm__("d26"), h14 __asm__("d28"), h15 __asm__("d30");
  u0 = u1, v0 = v1;
  SB_V7_LANES(uv2, u1, v1);
  steps_of(sd1, sdd1, &su, &sv);
  {
    RunRegs rr = run_regs(u0, v0, su, sv);
    uint32_t u = rr.u, v = rr.v, du = rr.du, dv = rr.dv, a, b;
    const uint32_t ddu = rr.ddu, ddv = rr.ddv;
    uint8_t* const d1 = dest + 16;
    const uint32_t* const kk = kMidLast[steps];
    __asm__ volatile("smulbt %[a], %[w], %[v]\n\t"
                     "vmul.f64 d16, d25, d5\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vcvt.s32.f64 s0, d25\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "vcvt.s32.f64 s1, d24\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "vmul.f64 d17, d24, d5\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vmov.f64 d18, #-2.0\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vmov.i32 d29, #1\n\t"
                     "add %[v], %[dv]\n\t"
                     "vabs.s32 d23, d0\n\t"
                     "str %[a], [%[d]]\n\t"
                     "vsub.i32 d2, d4, d3\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vld1.32 {d24-d27}, [%[k]]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "vmul.f64 d17, d18, d17\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vmul.f64 d16, d18, d16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vmul.i32 d28, d23, d24\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "vcvt.s32.f64 s12, d16\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vcvt.s32.f64 s13, d17\n\t"
                     "vmul.i32 d19, d6, d26\n\t"
                     "add %[du], %[ddu]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "add %[v], %[dv]\n\t"
                     "str %[a], [%[d], #4]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vabs.s32 d30, d6\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "vshr.s32 d21, d2, #31\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vcgt.u32 d20, d25, d30\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[u], %[du]\n\t"
                     "vcgt.u32 d18, d24, d29\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vabs.s32 d22, d2\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vand d20, d20, d18\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "str %[a], [%[d], #8]\n\t"
                     "add %[v], %[dv]\n\t"
                     "vand d19, d19, d20\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[v], %[dv]\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[u], %[du]\n\t"
                     "vand d31, d30, d20\n\t"
                     "vsub.i32 d28, d22, d28\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vand d6, d6, d20\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "str %[a], [%[d], #12]\n\t"
                     : SB_V7_RUN_OPERANDS(d1), [qi] "=w"(qi), [sd] "=w"(sdr), "=w"(h9), "=w"(h10), "=w"(h11),
                       "+w"(h12), "=w"(h13), "=w"(h14), "=w"(h15)
                     : SB_V7_RUN_INPUTS(d1), [cv] "w"(curve), [uv3] "w"(uv3), [uv4] "w"(uv4), [k] "r"(kk)
                     : "memory", "d2", "d16", "d17");
  }
  hook(std::integral_constant<int, 2>{});
  // Run 2; beside it the rest of the last run's steps.
  u0 = u1, v0 = v1;
  SB_V7_LANES(uv3, u1, v1);
  steps_of(sd2, sdd2, &su, &sv);
  RunSteps lu, lv;
  {
    RunRegs rr = run_regs(u0, v0, su, sv);
    uint32_t u = rr.u, v = rr.v, du = rr.du, dv = rr.dv, a, b;
    const uint32_t ddu = rr.ddu, ddv = rr.ddv;
    uint8_t* const d2 = dest + 32;
    __asm__ volatile("smulbt %[a], %[w], %[v]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vmull.u32 q8, d31, d27\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "vshl.s32 d28, d28, #1\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "veor d19, d19, d21\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "add %[u], %[du]\n\t"
                     "vmovl.u32 q15, d22\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[u], %[du]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[v], %[dv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "str %[a], [%[d]]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[u], %[du]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vcgt.u32 d28, d24, d28\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "vsub.i32 d19, d19, d21\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vqsub.u64 q8, q8, q15\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vshr.s32 d25, d19, #1\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vand d2, d19, d28\n\t"
                     "add %[v], %[dv]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "vsub.i32 d25, d23, d25\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vand d2, d2, d29\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vqmovn.u64 d16, q8\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "vsub.i32 d25, d25, d2\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "str %[a], [%[d], #4]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "veor d25, d25, d21\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[v], %[dv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[v], %[dv]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vtst.32 d16, d16, d16\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "vbic d6, d6, d16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "vsub.i32 d25, d25, d21\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "add %[u], %[du]\n\t"
                     "add %[du], %[ddu]\n\t"
                     "vbsl d16, d0, d25\n\t"
                     "str %[a], [%[d], #8]\n\t"
                     "smulbt %[a], %[w], %[v]\n\t"
                     "add %[v], %[dv]\n\t"
                     "uxtah %[a], %[a], %[u], ror #16\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "add %[u], %[du]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[v], %[dv]\n\t"
                     "add %[dv], %[ddv]\n\t"
                     "ldrb %[a], [%[tx], %[a]]\n\t"
                     "add %[u], %[du]\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #8\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "add %[v], %[dv]\n\t"
                     "orr %[a], %[a], %[b], lsl #16\n\t"
                     "add %[du], %[ddu]\n\t"
                     "add %[u], %[du]\n\t"
                     "smulbt %[b], %[w], %[v]\n\t"
                     "vmov %[du], %[dv], d6\n\t"
                     "uxtah %[b], %[b], %[u], ror #16\n\t"
                     "ldrb %[b], [%[tx], %[b]]\n\t"
                     "orr %[a], %[a], %[b], lsl #24\n\t"
                     "str %[a], [%[d], #12]\n\t"
                     "vmov %[a], %[b], d16\n\t"
                     : SB_V7_RUN_OPERANDS(d2), [qi] "+w"(qi), "+w"(h9), "+w"(h12), "+w"(h14), "+w"(h15)
                     : SB_V7_RUN_INPUTS(d2), [L] "w"(sdr), "w"(h10), "w"(h11), "w"(h13)
                     : "memory", "d2", "d16", "d17");
    lu = RunSteps{int32_t(a), int32_t(du)}, lv = RunSteps{int32_t(b), int32_t(dv)};
  }
  // The last run (n - 48 pixels from sample 3 to sample 4).
  u0 = u1, v0 = v1;
  if constexpr (kFour) {
    *run3 = run_regs(u0, v0, lu, lv);
  } else if (n == 64) {
    draw16_v7(dest + 48, texels, w, run_regs(u0, v0, lu, lv));
  } else {
    draw_last<true, true>(dest + 48, n - 48, texels, w, uint32_t(u0), uint32_t(v0), uint32_t(lu.d), uint32_t(lv.d),
                          uint32_t(lu.dd), uint32_t(lv.dd));
  }
}
#undef SB_V7_PRO_CLOB
#undef SB_V7_PRO_IN
#undef SB_V7_PRO_OUT
#undef SB_V7_PROLOGUE
#undef SB_V7_LANES
// SB_V7_RUN and its parts (SB_V7_RUN_OPERANDS, SB_V7_RUN_INPUTS, SB_V7_PX ..) stay defined
// for asm/span_persp_v7pass.h (which undefines them).
#endif

}  // namespace
}  // namespace sb::simd
