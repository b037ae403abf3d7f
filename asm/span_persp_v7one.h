// asm/span_persp_v7one.h: the whole-span drawer's ARMv7 paths for short second-order spans
// (dzi != 0) in a batch (asm/span_persp.h): one-run spans (1 .. 16 pixels) two at a time, and
// spans of 17 .. 48 pixels (two or three runs) one at a time. Internal: included by
// asm/span_persp_fast.cpp only, after asm/span_persp_v7pass.h (anonymous namespace).
//
// Such spans are the drawer's most numerous (bench/span_hist.md: 880-960 one-run spans a frame
// at 320x240, mean 7 pixels, 95% next to another one in the batch; 17 .. 48 pixel spans in
// pairs draw 11-21% of the pixels). Their cost is the latency chain of the set-up (depths,
// divides, to_fixed, the last run's quotient, another divide, the steps), not the pixels.
// persp_fast<true> ran those chains one after the other, with core <-> VFP transfers and the
// steps' tests in core registers. Here each set-up is one asm statement in VFP / NEON
// registers only (bench/gen_v7one.py generates them), results stored by vst1: for one-run
// spans the two spans' chains list-scheduled together (the four depth divides, then the four
// quotient divides, each set close together), for 17 .. 48 pixel spans list-scheduled (the four depth divides, the full
// runs' steps beside the last run's quotient divides). Then the runs are drawn as
// persp_fast draws them (draw16, draw_last). Every double operation is the walker's
// (asm/span_walk.h), as persp_fast performs it:
//   positions   one run: P = px0, P + (n - 1); 17 .. 48: see mid_setup_v7
//   depth       z = 1 / max(zrow + zix x, kMinZi) (fused as compiled; vcmpe / vmovle: NaN
//               -> kMinZi)
//   u, v        min_ufixed16(cvt_ufixed16((urow + ux x) z), umax) (persp_fast's sample():
//               the walker's to_fixed, see min_ufixed16), likewise v, paired [u, v]
//   last run    over its s = max(steps, 1): q = double(delta) / s (delta: the clamped
//               samples' int32 difference, exact), curve = (zix * 0.5) (z_a + z_b), then
//               last_steps' ddf, dd, its tests and d (one_setup2_v7 says how). One pixel:
//               both samples are the same (delta 0), the steps are never read.
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#include "asm/span_persp_v7pass.h"

#if defined(SB_V7_NEON_STEPS)
#define SB_V7_ONE 1
#define SB_V7_MID2_CLOBBERS "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
#define SB_V7_ONE_CLOBBERS "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
namespace sb::simd {
namespace {

// An item persp_one_v7 draws: second order, dzi != 0 (on its bits), 1 <= n <= 16.
// dzi != 0 on its bits as is_zero_v7 (asm/span_persp_fast.cpp) tests it.
SB_INLINE bool one_v7(const PerspItem& x) {
  uint32_t lo, hi;
  __builtin_memcpy(&lo, &x.span.dzi, 4);
  __builtin_memcpy(&hi, reinterpret_cast<const char*>(&x.span.dzi) + 4, 4);
  return x.span.second_order && (lo | (hi << 1)) != 0 && uint32_t(x.n) - 1u < 16u;
}

// The pair set-up's results per span, as its asm stores them: u0, v0, the second-order steps
// (ddu, ddv) and the steps (du, dv) of the run.
struct OneSetup {
  int32_t u, v, ddu, ddv, du, dv;
};
// Its constants: kMinZi, 1, 1/2, -2, [1e9, 1e9] (u32); and per n (1 .. 16) n - 1, s =
// max(n - 1, 1), k = (s - 1) / 2 (doubles: exact) and [T, T], T = s (s - 1) / 2.
struct alignas(16) OneConsts {
  double c[4];
  uint32_t big[2];
};
// In their own section: in .rodata they moved the batch loop's other tables against its section
// anchor (GCC then addressed kMidN with another add: A9 persp64 7.24 -> 7.26).
__attribute__((section(".rodata.sb_v7one"))) constexpr OneConsts kOneConsts = {{kMinZi, 1.0, 0.5, -2.0}, {1000000000u, 1000000000u}};
struct alignas(32) OneRow {
  double f, s, k;
  uint32_t t[2];
};
__attribute__((section(".rodata.sb_v7one"))) constexpr auto kOneRows = [] {
  struct Table {
    OneRow row[17];
  } t{};
  for (int n = 1; n <= 16; ++n) {
    const int s = n > 2 ? n - 1 : 1;
    const uint32_t T = uint32_t(s * (s - 1) / 2);
    t.row[n] = OneRow{double(n - 1), double(s), double(s - 1) / 2, {T, T}};
  }
  return t;
}();
static_assert(sizeof(OneRow) == 32 && offsetof(PerspItem, n) == 4 && offsetof(PerspItem, span) == 8 &&
                  sizeof(PerspItem) == 80,
              "the pair set-up's loads (row n at 32 n; the item's n and gradients)");

// The set-ups of spans A and B (both one_v7's; B may be A itself) in one asm statement
// (bench/gen_v7one.py; see the header for the operations). Per span: the item's n picks
// its row; its gradients loaded by vld1 (zi0, uz0, vz0 twice: the fused multiply-adds
// accumulate in place); positions, depths (clamped, the two divides), the samples (vcvt.u32
// #16, [u, v] paired by vsli, vmin.u32 with [umax, vmax]), delta = [du, dv] (vsub.i32), the
// quotients q = double(delta) / s (two divides), then:
//   ddf   q c2 with c2 = -2 curve (exact), not -2 (q curve): the same int32 after vcvt (trunc,
//         saturating, NaN -> 0). Scaling by -2 commutes with rounding except where a product
//         is subnormal (then |ddf| < 1: 0 either way) or overflows (c2 infinite with
//         curve finite: q = 0 gives NaN for 0, both 0; else |ddf| > 2^31 either way, both
//         saturate and are rejected below).
//   dd'   dd where |dd| < 1e9 and T |dd| <= |delta| (the walker's range and acceptance
//         tests, last_ddi and last_dd's; the 64-bit product by vmull.u32, vqsub.u64), else 0.
//   d     accepted: trunc(q - dd k), else trunc(q) (last_dd's linear). Accepted, last_dd's
//         d0 is trunc(x), x = (delta - T dd) / s = delta / s - dd k exactly; q = RN(delta / s)
//         and q - dd k (dd k exact, < 2^35) rounded once differ from x by under 2^-20, and
//         x, a multiple of 1 / (2 s), is either an integer (then delta / s is a multiple of
//         1/2: q and q - dd k exact) or over 1/30 from one: the same trunc.
// For n <= 2 (T = 0, k = 0) dd' may be nonzero where the walker's is 0: the run draws at most
// two pixels and never reads it. The results are stored by vst1 (OneSetup's order).
SB_INLINE void one_setup2_v7(const PerspItem& A, const PerspItem& B, OneSetup* out) {
  const PerspItem* ia = &A;
  const PerspItem* ib = &B;
  int32_t* oa = &out[0].u;
  int32_t* ob = &out[1].u;
  const OneConsts* kc = &kOneConsts;
  const OneRow* kr = kOneRows.row;
  uint32_t ra, rb;
  __asm__ volatile(
    // Generated by bench/gen_v7one.py (do not edit by hand).
    "ldr %[ra], [%[ia], #4]\n\t"
    "ldr %[rb], [%[ib], #4]\n\t"
    "add %[ia], %[ia], #8\n\t"
    "add %[ib], %[ib], #8\n\t"
    "vld1.64 {d18}, [%[ib]]\n\t"
    "add %[ra], %[kr], %[ra], lsl #5\n\t"
    "vld1.64 {d16}, [%[ia]]\n\t"
    "vld1.64 {d19, d20, d21, d22}, [%[ib]]!\n\t"
    "vld1.64 {d5, d6, d7, d8}, [%[ia]]!\n\t"
    "vld1.64 {d9, d10, d11, d12}, [%[ia]]\n\t"
    "vld1.64 {d13, d14}, [%[ra]]!\n\t"
    "add %[rb], %[kr], %[rb], lsl #5\n\t"
    "vfma.f64 d5, d6, d11\n\t"
    "vadd.f64 d17, d11, d13\n\t"
    "vld1.64 {d25, d26, d27, d28}, [%[ib]]\n\t"
    "vfma.f64 d7, d8, d11\n\t"
    "vld1.64 {d23, d24}, [%[rb]]!\n\t"
    "vld1.64 {d0, d1, d2, d3}, [%[kc]]!\n\t"
    "vadd.f64 d29, d27, d23\n\t"
    "vfma.f64 d16, d6, d17\n\t"
    "vfma.f64 d19, d20, d27\n\t"
    "vld1.64 {d23}, [%[ia]]\n\t"
    "vfma.f64 d25, d26, d27\n\t"
    "vfma.f64 d21, d22, d27\n\t"
    "vfma.f64 d18, d20, d29\n\t"
    "vld1.64 {d27}, [%[ib]]\n\t"
    "vld1.64 {d4}, [%[kc]]\n\t"
    "vcmpe.f64 d5, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d5, d0\n\t"
    "sub %[ib], %[ib], #16\n\t"
    "vdiv.f64 d5, d1, d5\n\t"
    "vcmpe.f64 d16, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "sub %[ia], %[ia], #16\n\t"
    "vcmpe.f64 d19, d0\n\t"
    "it le\n\t"
    "vmovle.f64 d16, d0\n\t"
    "vdiv.f64 d16, d1, d16\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d19, d0\n\t"
    "vcmpe.f64 d18, d0\n\t"
    "vdiv.f64 d19, d1, d19\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "vld1.64 {d30}, [%[ia]]\n\t"
    "it le\n\t"
    "vmovle.f64 d18, d0\n\t"
    "vdiv.f64 d18, d1, d18\n\t"
    "vfma.f64 d9, d10, d11\n\t"
    "vmul.f64 d6, d6, d2\n\t"
    "vfma.f64 d27, d26, d29\n\t"
    "vld1.64 {d31}, [%[ib]]\n\t"
    "vfma.f64 d23, d10, d17\n\t"
    "vmul.f64 d20, d20, d2\n\t"
    "vfma.f64 d30, d8, d17\n\t"
    "vmul.f64 d9, d9, d5\n\t"
    "vfma.f64 d31, d22, d29\n\t"
    "vmul.f64 d7, d7, d5\n\t"
    "vadd.f64 d5, d5, d16\n\t"
    "vcvt.u32.f64 d9, d9, #16\n\t"
    "vmul.f64 d23, d23, d16\n\t"
    "vmul.f64 d30, d30, d16\n\t"
    "vmul.f64 d25, d25, d19\n\t"
    "vmul.f64 d21, d21, d19\n\t"
    "vcvt.u32.f64 d7, d7, #16\n\t"
    "vmul.f64 d31, d31, d18\n\t"
    "vcvt.u32.f64 d23, d23, #16\n\t"
    "vmul.f64 d27, d27, d18\n\t"
    "vsli.64 d7, d9, #32\n\t"
    "vcvt.u32.f64 d30, d30, #16\n\t"
    "vcvt.u32.f64 d21, d21, #16\n\t"
    "vcvt.u32.f64 d31, d31, #16\n\t"
    "vcvt.u32.f64 d25, d25, #16\n\t"
    "vsli.64 d30, d23, #32\n\t"
    "vcvt.u32.f64 d27, d27, #16\n\t"
    "vmin.u32 d7, d7, d12\n\t"
    "vst1.32 {d7}, [%[oa]]!\n\t"
    "vmin.u32 d30, d30, d12\n\t"
    "vsli.64 d21, d25, #32\n\t"
    "vsli.64 d31, d27, #32\n\t"
    "vmin.u32 d21, d21, d28\n\t"
    "vmin.u32 d31, d31, d28\n\t"
    "vsub.i32 d15, d30, d7\n\t"
    "vadd.f64 d19, d19, d18\n\t"
    "vsub.i32 d7, d31, d21\n\t"
    "vcvt.f64.s32 d18, s30\n\t"
    "vst1.32 {d21}, [%[ob]]!\n\t"
    "vcvt.f64.s32 d21, s31\n\t"
    "vcvt.f64.s32 d25, s14\n\t"
    "vcvt.f64.s32 d16, s15\n\t"
    "vdiv.f64 d18, d18, d14\n\t"
    "vdiv.f64 d21, d21, d14\n\t"
    "vdiv.f64 d25, d25, d24\n\t"
    "vdiv.f64 d16, d16, d24\n\t"
    "vmul.f64 d6, d6, d5\n\t"
    "vmul.f64 d20, d20, d19\n\t"
    "vabs.s32 d17, d15\n\t"
    "vabs.s32 d19, d7\n\t"
    "vmovl.u32 q11, d17\n\t"
    "vmovl.u32 q13, d19\n\t"
    "vmul.f64 d6, d6, d3\n\t"
    "vmul.f64 d20, d20, d3\n\t"
    "vmul.f64 d17, d18, d6\n\t"
    "vmul.f64 d19, d21, d6\n\t"
    "vld1.64 {d7, d8}, [%[ra]]\n\t"
    "vmul.f64 d24, d25, d20\n\t"
    "vcvt.s32.f64 s10, d18\n\t"
    "vmul.f64 d28, d16, d20\n\t"
    "vld1.64 {d9, d10}, [%[rb]]\n\t"
    "vcvt.s32.f64 s12, d25\n\t"
    "vcvt.s32.f64 s22, d17\n\t"
    "vcvt.s32.f64 s23, d19\n\t"
    "vcvt.s32.f64 s24, d24\n\t"
    "vcvt.s32.f64 s11, d21\n\t"
    "vcvt.s32.f64 s25, d28\n\t"
    "vabs.s32 d17, d11\n\t"
    "vcvt.f64.s32 d19, s22\n\t"
    "vabs.s32 d20, d12\n\t"
    "vmull.u32 q14, d17, d8\n\t"
    "vcvt.f64.s32 d24, s24\n\t"
    "vfms.f64 d18, d19, d7\n\t"
    "vmull.u32 q15, d20, d10\n\t"
    "vcvt.s32.f64 s13, d16\n\t"
    "vcvt.f64.s32 d8, s23\n\t"
    "vcvt.f64.s32 d19, s25\n\t"
    "vqsub.u64 q14, q14, q11\n\t"
    "vqsub.u64 q15, q15, q13\n\t"
    "vfms.f64 d25, d24, d9\n\t"
    "vfms.f64 d16, d19, d9\n\t"
    "vcgt.u32 d22, d4, d17\n\t"
    "vfms.f64 d21, d8, d7\n\t"
    "vqmovn.u64 d24, q15\n\t"
    "vcgt.u32 d17, d4, d20\n\t"
    "vqmovn.u64 d19, q14\n\t"
    "vtst.32 d24, d24, d24\n\t"
    "vcvt.s32.f64 s14, d18\n\t"
    "vcvt.s32.f64 s20, d25\n\t"
    "vtst.32 d19, d19, d19\n\t"
    "vcvt.s32.f64 s21, d16\n\t"
    "vcvt.s32.f64 s15, d21\n\t"
    "vbic d22, d22, d19\n\t"
    "vbic d17, d17, d24\n\t"
    "vand d11, d11, d22\n\t"
    "vst1.32 {d11}, [%[oa]]!\n\t"
    "vbsl d22, d7, d5\n\t"
    "vand d12, d12, d17\n\t"
    "vst1.32 {d22}, [%[oa]]\n\t"
    "vbsl d17, d10, d6\n\t"
    "vst1.32 {d12}, [%[ob]]!\n\t"
    "vst1.32 {d17}, [%[ob]]"
    // clobbers: "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
      : [ia] "+r"(ia), [ib] "+r"(ib), [ra] "=&r"(ra), [rb] "=&r"(rb), [oa] "+r"(oa), [ob] "+r"(ob), [kc] "+r"(kc)
      : [kr] "r"(kr)
      : "memory", "cc", SB_V7_ONE_CLOBBERS);
}

// Spans of 17 .. 48 pixels (second order, dzi != 0): two or three runs, set up by one asm
// statement (mid_setup_v7, bench/gen_v7one.py's span_mid), then drawn. Samples 0 .. 3 at P,
// P + 16, P + A2, (P + 16) + A3 (the walker's positions: A2 = n - 1, and sample 3 unused, for
// n <= 32; A2 = 32, A3 = n - 17 for n > 32), each as the one-run path's; the full runs' steps
// (samples 0 -> 1, 1 -> 2) as persp_fast's: ddf = double(delta) (zck (z_a + z_b)),
// zck = zix * -1/16 (the walker's -2 (delta / 16 curve), same bits), dd = trunc (saturating),
// steps16_dd in NEON lanes as asm/span_persp_v7pass.h computes it; the last run's (samples
// 1 -> 2 for n <= 32, 2 -> 3 for n > 32: the row's mask selects z_a + z_b and delta by vbit) as
// the one-run path's over its n - 17 or n - 33 steps. Stored in V7ShortSetup's order.
SB_INLINE bool mid_v7(const PerspItem& x) {
  uint32_t lo, hi;
  __builtin_memcpy(&lo, &x.span.dzi, 4);
  __builtin_memcpy(&hi, reinterpret_cast<const char*>(&x.span.dzi) + 4, 4);
  return x.span.second_order && (lo | (hi << 1)) != 0 && uint32_t(x.n) - 17u < 32u;
}
struct V7ShortSetup {
  int32_t s0[2], s1[2], s2[2];    // samples 0 .. 2: [u, v]
  int32_t d0[2], dd0[2];          // run 0's steps [du, dv], [ddu, ddv]
  int32_t d1[2], dd1[2];          // run 1's (full: used for n > 32)
  int32_t ddl[2], dl[2];          // the last run's
};
// mid_setup_v7's constants, in the order it loads them: kMinZi, 1, 16; 1/2, -1/16, -2;
// [1e9, 1e9], [120, 120], [2^25, 2^25] (u32).
struct alignas(16) V7ShortConsts {
  double c[6];
  uint32_t big[2], k120[2], k25[2];
};
__attribute__((section(".rodata.sb_v7one"))) constexpr V7ShortConsts kV7ShortConsts = {
    {kMinZi, 1.0, 16.0, 0.5, -0.0625, -2.0}, {1000000000u, 1000000000u}, {120, 120}, {1u << 25, 1u << 25}};
struct alignas(64) V7ShortRow {
  double a2, a3, s, k;
  uint32_t t[2], mask[2];
};
__attribute__((section(".rodata.sb_v7one"))) constexpr auto kV7ShortRows = [] {
  struct Table {
    V7ShortRow row[49];
  } t{};
  for (int n = 17; n <= 48; ++n) {
    const bool three = n > 32;
    const int steps = three ? n - 33 : n - 17, s = steps > 1 ? steps : 1;
    const uint32_t T = uint32_t(s * (s - 1) / 2), m = three ? ~0u : 0u;
    t.row[n] = V7ShortRow{three ? 32.0 : double(n - 1), three ? double(n - 17) : 0.0, double(s), double(s - 1) / 2,
                      {T, T}, {m, m}};
  }
  return t;
}();
static_assert(sizeof(V7ShortRow) == 64 && sizeof(V7ShortSetup) == 72, "mid_setup_v7's row and stores");

SB_INLINE void mid_setup_v7(const PerspItem& A, V7ShortSetup* out) {
  const PerspItem* ia = &A;
  int32_t* oa = out->s0;
  const V7ShortConsts* kc = &kV7ShortConsts;
  const V7ShortRow* kr = kV7ShortRows.row;
  uint32_t ra;
  __asm__ volatile(
    // Generated (mid) by bench/gen_v7one.py (do not edit by hand).
    "ldr %[ra], [%[ia], #4]\n\t"
    "add %[ia], %[ia], #8\n\t"
    "vld1.64 {d17}, [%[ia]]\n\t"
    "vld1.64 {d16}, [%[ia]]\n\t"
    "vld1.64 {d18}, [%[ia]]\n\t"
    "vld1.64 {d0, d1, d2, d3}, [%[ia]]!\n\t"
    "add %[ra], %[kr], %[ra], lsl #6\n\t"
    "vld1.64 {d7, d8, d9, d10}, [%[ia]]\n\t"
    "vfma.f64 d0, d1, d9\n\t"
    "vld1.64 {d4, d5, d6}, [%[kc]]!\n\t"
    "vadd.f64 d19, d9, d6\n\t"
    "vfma.f64 d2, d3, d9\n\t"
    "vld1.64 {d11, d12}, [%[ra]]!\n\t"
    "vld1.64 {d22}, [%[ia]]\n\t"
    "vadd.f64 d20, d9, d11\n\t"
    "vfma.f64 d16, d1, d19\n\t"
    "vadd.f64 d21, d19, d12\n\t"
    "vfma.f64 d17, d1, d20\n\t"
    "vcmpe.f64 d0, d4\n\t"
    "vld1.64 {d24}, [%[ia]]\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "vfma.f64 d18, d1, d21\n\t"
    "it le\n\t"
    "vmovle.f64 d0, d4\n\t"
    "vdiv.f64 d0, d5, d0\n\t"
    "vld1.64 {d11, d12, d13}, [%[kc]]!\n\t"
    "vcmpe.f64 d16, d4\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d16, d4\n\t"
    "vcmpe.f64 d17, d4\n\t"
    "vld1.64 {d23}, [%[ia]]\n\t"
    "vdiv.f64 d16, d5, d16\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "vcmpe.f64 d18, d4\n\t"
    "it le\n\t"
    "vmovle.f64 d17, d4\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "sub %[ia], %[ia], #16\n\t"
    "vld1.64 {d27}, [%[ia]]\n\t"
    "it le\n\t"
    "vmovle.f64 d18, d4\n\t"
    "vdiv.f64 d18, d5, d18\n\t"
    "vdiv.f64 d17, d5, d17\n\t"
    "vfma.f64 d24, d8, d21\n\t"
    "vld1.64 {d26}, [%[ia]]\n\t"
    "vfma.f64 d7, d8, d9\n\t"
    "vld1.64 {d25}, [%[ia]]\n\t"
    "vfma.f64 d25, d3, d19\n\t"
    "vfma.f64 d22, d8, d19\n\t"
    "vmul.f64 d2, d2, d0\n\t"
    "vmul.f64 d7, d7, d0\n\t"
    "vfma.f64 d23, d8, d20\n\t"
    "vfma.f64 d26, d3, d20\n\t"
    "vfma.f64 d27, d3, d21\n\t"
    "vmul.f64 d22, d22, d16\n\t"
    "vmul.f64 d25, d25, d16\n\t"
    "vcvt.u32.f64 d7, d7, #16\n\t"
    "vld1.64 {d3, d4}, [%[ra]]!\n\t"
    "vcvt.u32.f64 d2, d2, #16\n\t"
    "vadd.f64 d0, d0, d16\n\t"
    "vmul.f64 d19, d1, d11\n\t"
    "vmul.f64 d24, d24, d18\n\t"
    "vmul.f64 d26, d26, d17\n\t"
    "vmul.f64 d23, d23, d17\n\t"
    "vsli.64 d2, d7, #32\n\t"
    "vmul.f64 d27, d27, d18\n\t"
    "vcvt.u32.f64 d22, d22, #16\n\t"
    "vcvt.u32.f64 d25, d25, #16\n\t"
    "vcvt.u32.f64 d26, d26, #16\n\t"
    "vld1.64 {d5, d6}, [%[ra]]\n\t"
    "vcvt.u32.f64 d23, d23, #16\n\t"
    "vcvt.u32.f64 d24, d24, #16\n\t"
    "vcvt.u32.f64 d27, d27, #16\n\t"
    "vsli.64 d25, d22, #32\n\t"
    "vsli.64 d26, d23, #32\n\t"
    "vmin.u32 d25, d25, d10\n\t"
    "vsli.64 d27, d24, #32\n\t"
    "vmin.u32 d26, d26, d10\n\t"
    "vmin.u32 d27, d27, d10\n\t"
    "vadd.f64 d16, d16, d17\n\t"
    "vmul.f64 d1, d1, d12\n\t"
    "vsub.i32 d11, d26, d25\n\t"
    "vsub.i32 d24, d27, d26\n\t"
    "vadd.f64 d17, d17, d18\n\t"
    "vbit d11, d24, d6\n\t"
    "vmin.u32 d2, d2, d10\n\t"
    "vmul.f64 d18, d1, d16\n\t"
    "vcvt.f64.s32 d24, s22\n\t"
    "vcvt.f64.s32 d27, s23\n\t"
    "vst1.32 {d2}, [%[oa]]!\n\t"
    "vst1.32 {d25}, [%[oa]]!\n\t"
    "vbit d16, d17, d6\n\t"
    "vst1.32 {d26}, [%[oa]]!\n\t"
    "vmul.f64 d0, d1, d0\n\t"
    "vdiv.f64 d24, d24, d3\n\t"
    "vld1.64 {d6, d7, d8}, [%[kc]]\n\t"
    "vdiv.f64 d27, d27, d3\n\t"
    "vsub.i32 d3, d25, d2\n\t"
    "vmul.f64 d19, d19, d16\n\t"
    "vsub.i32 d1, d26, d25\n\t"
    "vcvt.f64.s32 d25, s6\n\t"
    "vcvt.f64.s32 d26, s7\n\t"
    "vcvt.f64.s32 d17, s3\n\t"
    "vcvt.f64.s32 d16, s2\n\t"
    "vmul.f64 d25, d25, d0\n\t"
    "vmul.f64 d19, d19, d13\n\t"
    "vmul.f64 d26, d26, d0\n\t"
    "vmul.f64 d16, d16, d18\n\t"
    "vabs.s32 d20, d11\n\t"
    "vmul.f64 d17, d17, d18\n\t"
    "vcvt.s32.f64 s0, d25\n\t"
    "vabs.s32 d18, d3\n\t"
    "vmovl.u32 q11, d20\n\t"
    "vcvt.s32.f64 s4, d16\n\t"
    "vcvt.s32.f64 s1, d26\n\t"
    "vcvt.s32.f64 s5, d17\n\t"
    "vshr.s32 d25, d3, #31\n\t"
    "vmul.i32 d21, d0, d7\n\t"
    "vabs.s32 d17, d0\n\t"
    "vabs.s32 d16, d1\n\t"
    "vmul.f64 d26, d24, d19\n\t"
    "vmin.u32 d17, d17, d8\n\t"
    "vmul.f64 d20, d27, d19\n\t"
    "vabs.s32 d19, d2\n\t"
    "vmul.i32 d17, d17, d7\n\t"
    "vcvt.s32.f64 s20, d26\n\t"
    "vsra.u32 d3, d25, #28\n\t"
    "vcvt.s32.f64 s18, d24\n\t"
    "vmin.u32 d19, d19, d8\n\t"
    "vcvt.s32.f64 s21, d20\n\t"
    "vcvt.f64.s32 d28, s20\n\t"
    "vmul.i32 d19, d19, d7\n\t"
    "vcge.u32 d17, d18, d17\n\t"
    "vmul.i32 d26, d2, d7\n\t"
    "vabs.s32 d18, d10\n\t"
    "vand d21, d21, d17\n\t"
    "vfms.f64 d24, d28, d4\n\t"
    "vshr.s32 d20, d1, #31\n\t"
    "vmull.u32 q15, d18, d5\n\t"
    "vcvt.f64.s32 d29, s21\n\t"
    "vsra.u32 d1, d20, #28\n\t"
    "vhsub.s32 d3, d3, d21\n\t"
    "vcge.u32 d19, d16, d19\n\t"
    "vqsub.u64 q15, q15, q11\n\t"
    "vcvt.s32.f64 s19, d27\n\t"
    "vand d26, d26, d19\n\t"
    "vfms.f64 d27, d29, d4\n\t"
    "vqmovn.u64 d16, q15\n\t"
    "vhsub.s32 d1, d1, d26\n\t"
    "vcgt.u32 d25, d6, d18\n\t"
    "vand d0, d0, d17\n\t"
    "vtst.32 d16, d16, d16\n\t"
    "vshr.s32 d1, d1, #3\n\t"
    "vshr.s32 d3, d3, #3\n\t"
    "vst1.32 {d3}, [%[oa]]!\n\t"
    "vst1.32 {d0}, [%[oa]]!\n\t"
    "vcvt.s32.f64 s16, d24\n\t"
    "vbic d25, d25, d16\n\t"
    "vcvt.s32.f64 s17, d27\n\t"
    "vst1.32 {d1}, [%[oa]]!\n\t"
    "vand d2, d2, d19\n\t"
    "vst1.32 {d2}, [%[oa]]!\n\t"
    "vand d10, d10, d25\n\t"
    "vst1.32 {d10}, [%[oa]]!\n\t"
    "vbsl d25, d8, d9\n\t"
    "vst1.32 {d25}, [%[oa]]!"
    // clobbers: "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
      : [ia] "+r"(ia), [ra] "=&r"(ra), [oa] "+r"(oa), [kc] "+r"(kc)
      : [kr] "r"(kr)
      : "memory", "cc", SB_V7_MID2_CLOBBERS);
}
SB_INLINE void last_draw_v7(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const int32_t* s,
                            const int32_t* d, const int32_t* dd) {
  if (n == 16) {
    draw16<true>(dest, texels, w, s[0], s[1], RunSteps{d[0], dd[0]}, RunSteps{d[1], dd[1]});
  } else {
    draw_last<true, true>(dest, n, texels, w, uint32_t(s[0]), uint32_t(s[1]), uint32_t(d[0]), uint32_t(d[1]),
                    uint32_t(dd[0]), uint32_t(dd[1]));
  }
}
// One such item: set up, then its runs drawn.
SB_INLINE void mid_draw_v7(const PerspItem& it, const uint8_t* texels, uint32_t w) {
  V7ShortSetup s;
  mid_setup_v7(it, &s);
  uint8_t* const dest = it.dest;
  const int n = it.n;
  draw16<true>(dest, texels, w, s.s0[0], s.s0[1], RunSteps{s.d0[0], s.dd0[0]}, RunSteps{s.d0[1], s.dd0[1]});
  if (n > 32) {
    draw16<true>(dest + 16, texels, w, s.s1[0], s.s1[1], RunSteps{s.d1[0], s.dd1[0]}, RunSteps{s.d1[1], s.dd1[1]});
    last_draw_v7(dest + 32, n - 32, texels, w, s.s2, s.dl, s.ddl);
  } else {
    last_draw_v7(dest + 16, n - 16, texels, w, s.s1, s.dl, s.ddl);
  }
}

// The last runs' pixels 0 .. 7 as two chunks of 4 (draw_last's kHalves: the 8-chunk's
// positions were spilled here too; A9 persp16 17.67 -> 16.98, persp32 9.71 -> 9.59).
SB_INLINE void one_draw_v7(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const OneSetup& s) {
  if (n == 16) {
    draw16<true>(dest, texels, w, s.u, s.v, RunSteps{s.du, s.ddu}, RunSteps{s.dv, s.ddv});
  } else {
    draw_last<true, true>(dest, n, texels, w, uint32_t(s.u), uint32_t(s.v), uint32_t(s.du), uint32_t(s.dv),
                    uint32_t(s.ddu), uint32_t(s.ddv));
  }
}

// A one-run or 17 .. 48 pixel second-order item (persp_short_run_v7's).
SB_INLINE bool short_v7(const PerspItem& x) {
  uint32_t lo, hi;
  __builtin_memcpy(&lo, &x.span.dzi, 4);
  __builtin_memcpy(&hi, reinterpret_cast<const char*>(&x.span.dzi) + 4, 4);
  return x.span.second_order && (lo | (hi << 1)) != 0 && uint32_t(x.n) - 1u < 48u;
}
// Items from it on (defined at the end of asm/span_persp_fast.cpp: see there).
const PerspItem* persp_one_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
const PerspItem* persp_mid_run_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);
const PerspItem* persp_short_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);

}  // namespace
}  // namespace sb::simd
#endif
