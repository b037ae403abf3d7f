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
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#include "asm/span_persp_v7pass.h"

#if defined(SB_V7_NEON_STEPS)
#define SB_V7_ONE 1
#define SB_V7_ONE_CLOBBERS "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
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
    "vld1.64 {d0, d1, d2, d3}, [%[kc]]!\n\t"
    "vld1.64 {d4}, [%[kc]]\n\t"
    "ldr %[ra], [%[ia], #4]\n\t"
    "ldr %[rb], [%[ib], #4]\n\t"
    "add %[ia], %[ia], #8\n\t"
    "add %[ib], %[ib], #8\n\t"
    "add %[ra], %[kr], %[ra], lsl #5\n\t"
    "add %[rb], %[kr], %[rb], lsl #5\n\t"
    "vld1.64 {d16}, [%[ia]]\n\t"
    "vld1.64 {d17}, [%[ib]]\n\t"
    "vld1.64 {d5, d6, d7, d8}, [%[ia]]!\n\t"
    "vld1.64 {d9, d10, d11, d12}, [%[ib]]!\n\t"
    "vld1.64 {d18}, [%[ia]]\n\t"
    "vld1.64 {d19}, [%[ib]]\n\t"
    "vld1.64 {d20, d21, d22, d23}, [%[ia]]\n\t"
    "vld1.64 {d24, d25, d26, d27}, [%[ib]]\n\t"
    "sub %[ia], %[ia], #16\n\t"
    "sub %[ib], %[ib], #16\n\t"
    "vld1.64 {d28}, [%[ia]]\n\t"
    "vld1.64 {d29}, [%[ib]]\n\t"
    "vld1.64 {d13, d14}, [%[ra]]!\n\t"
    "vld1.64 {d30, d31}, [%[rb]]!\n\t"
    "vadd.f64 d15, d22, d13\n\t"
    "vadd.f64 d13, d26, d30\n\t"
    "vfma.f64 d5, d6, d22\n\t"
    "vfma.f64 d9, d10, d26\n\t"
    "vfma.f64 d16, d6, d15\n\t"
    "vfma.f64 d17, d10, d13\n\t"
    "vcmpe.f64 d5, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d5, d0\n\t"
    "vcmpe.f64 d9, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d9, d0\n\t"
    "vcmpe.f64 d16, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d16, d0\n\t"
    "vcmpe.f64 d17, d0\n\t"
    "vmrs APSR_nzcv, fpscr\n\t"
    "it le\n\t"
    "vmovle.f64 d17, d0\n\t"
    "vdiv.f64 d5, d1, d5\n\t"
    "vdiv.f64 d9, d1, d9\n\t"
    "vdiv.f64 d16, d1, d16\n\t"
    "vdiv.f64 d17, d1, d17\n\t"
    "vfma.f64 d7, d8, d22\n\t"
    "vfma.f64 d11, d12, d26\n\t"
    "vfma.f64 d20, d21, d22\n\t"
    "vfma.f64 d24, d25, d26\n\t"
    "vfma.f64 d28, d8, d15\n\t"
    "vfma.f64 d29, d12, d13\n\t"
    "vfma.f64 d18, d21, d15\n\t"
    "vfma.f64 d19, d25, d13\n\t"
    "vmul.f64 d6, d6, d2\n\t"
    "vmul.f64 d10, d10, d2\n\t"
    "vmul.f64 d7, d7, d5\n\t"
    "vmul.f64 d11, d11, d9\n\t"
    "vmul.f64 d20, d20, d5\n\t"
    "vmul.f64 d24, d24, d9\n\t"
    "vmul.f64 d28, d28, d16\n\t"
    "vmul.f64 d29, d29, d17\n\t"
    "vmul.f64 d18, d18, d16\n\t"
    "vmul.f64 d19, d19, d17\n\t"
    "vadd.f64 d5, d5, d16\n\t"
    "vadd.f64 d9, d9, d17\n\t"
    "vmul.f64 d6, d6, d5\n\t"
    "vmul.f64 d10, d10, d9\n\t"
    "vmul.f64 d6, d6, d3\n\t"
    "vmul.f64 d10, d10, d3\n\t"
    "vcvt.u32.f64 d7, d7, #16\n\t"
    "vcvt.u32.f64 d11, d11, #16\n\t"
    "vcvt.u32.f64 d20, d20, #16\n\t"
    "vcvt.u32.f64 d24, d24, #16\n\t"
    "vcvt.u32.f64 d28, d28, #16\n\t"
    "vcvt.u32.f64 d29, d29, #16\n\t"
    "vcvt.u32.f64 d18, d18, #16\n\t"
    "vcvt.u32.f64 d19, d19, #16\n\t"
    "vsli.64 d7, d20, #32\n\t"
    "vsli.64 d11, d24, #32\n\t"
    "vsli.64 d28, d18, #32\n\t"
    "vsli.64 d29, d19, #32\n\t"
    "vmin.u32 d7, d7, d23\n\t"
    "vmin.u32 d11, d11, d27\n\t"
    "vmin.u32 d28, d28, d23\n\t"
    "vmin.u32 d29, d29, d27\n\t"
    "vsub.i32 d5, d28, d7\n\t"
    "vst1.32 {d7}, [%[oa]]!\n\t"
    "vsub.i32 d7, d29, d11\n\t"
    "vst1.32 {d11}, [%[ob]]!\n\t"
    "vcvt.f64.s32 d16, s10\n\t"
    "vcvt.f64.s32 d17, s14\n\t"
    "vcvt.f64.s32 d18, s11\n\t"
    "vcvt.f64.s32 d19, s15\n\t"
    "vdiv.f64 d16, d16, d14\n\t"
    "vdiv.f64 d17, d17, d31\n\t"
    "vdiv.f64 d18, d18, d14\n\t"
    "vld1.64 {d8, d9}, [%[ra]]\n\t"
    "vdiv.f64 d19, d19, d31\n\t"
    "vld1.64 {d11, d12}, [%[rb]]\n\t"
    "vabs.s32 d20, d5\n\t"
    "vabs.s32 d21, d7\n\t"
    "vmovl.u32 q11, d20\n\t"
    "vmovl.u32 q12, d21\n\t"
    "vmul.f64 d20, d16, d6\n\t"
    "vmul.f64 d21, d17, d10\n\t"
    "vmul.f64 d26, d18, d6\n\t"
    "vmul.f64 d27, d19, d10\n\t"
    "vcvt.s32.f64 s10, d16\n\t"
    "vcvt.s32.f64 s12, d17\n\t"
    "vcvt.s32.f64 s11, d18\n\t"
    "vcvt.s32.f64 s13, d19\n\t"
    "vcvt.s32.f64 s14, d20\n\t"
    "vcvt.s32.f64 s20, d21\n\t"
    "vcvt.s32.f64 s15, d26\n\t"
    "vcvt.s32.f64 s21, d27\n\t"
    "vcvt.f64.s32 d20, s14\n\t"
    "vcvt.f64.s32 d21, s20\n\t"
    "vcvt.f64.s32 d26, s15\n\t"
    "vcvt.f64.s32 d27, s21\n\t"
    "vabs.s32 d28, d7\n\t"
    "vabs.s32 d29, d10\n\t"
    "vfms.f64 d16, d20, d8\n\t"
    "vfms.f64 d17, d21, d11\n\t"
    "vfms.f64 d18, d26, d8\n\t"
    "vfms.f64 d19, d27, d11\n\t"
    "vmull.u32 q10, d28, d9\n\t"
    "vmull.u32 q13, d29, d12\n\t"
    "vcgt.u32 d30, d4, d28\n\t"
    "vcgt.u32 d28, d4, d29\n\t"
    "vqsub.u64 q10, q10, q11\n\t"
    "vcvt.s32.f64 s16, d16\n\t"
    "vqsub.u64 q13, q13, q12\n\t"
    "vcvt.s32.f64 s18, d17\n\t"
    "vcvt.s32.f64 s17, d18\n\t"
    "vqmovn.u64 d16, q10\n\t"
    "vcvt.s32.f64 s19, d19\n\t"
    "vqmovn.u64 d17, q13\n\t"
    "vtst.32 d16, d16, d16\n\t"
    "vtst.32 d17, d17, d17\n\t"
    "vbic d30, d30, d16\n\t"
    "vbic d28, d28, d17\n\t"
    "vand d7, d7, d30\n\t"
    "vbsl d30, d8, d5\n\t"
    "vand d10, d10, d28\n\t"
    "vbsl d28, d9, d6\n\t"
    "vst1.32 {d7}, [%[oa]]!\n\t"
    "vst1.32 {d30}, [%[oa]]\n\t"
    "vst1.32 {d10}, [%[ob]]!\n\t"
    "vst1.32 {d28}, [%[ob]]"
    // clobbers: "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31"
      : [ia] "+r"(ia), [ib] "+r"(ib), [ra] "=&r"(ra), [rb] "=&r"(rb), [oa] "+r"(oa), [ob] "+r"(ob), [kc] "+r"(kc)
      : [kr] "r"(kr)
      : "memory", "cc", SB_V7_ONE_CLOBBERS);
}

SB_INLINE void one_draw_v7(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const OneSetup& s) {
  if (n == 16) {
    draw16<true>(dest, texels, w, s.u, s.v, RunSteps{s.du, s.ddu}, RunSteps{s.dv, s.ddv});
  } else {
    draw_last<true>(dest, n, texels, w, uint32_t(s.u), uint32_t(s.v), uint32_t(s.du), uint32_t(s.dv),
                    uint32_t(s.ddu), uint32_t(s.ddv));
  }
}

// Items from it on (persp_one_v7, defined at the end of asm/span_persp_fast.cpp: see there).
const PerspItem* persp_one_v7(const PerspItem* it, const PerspItem* end, const uint8_t* texels, int width);

}  // namespace
}  // namespace sb::simd
#endif
