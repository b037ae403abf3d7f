// asm/span_persp_v7five.h: the last run's set-up and run 3 of the ARMv7 five-run second-order
// spans (65 .. 80 pixels, persp_five_run_v7 in asm/span_persp_fast_v7five.inc). Internal:
// included by asm/span_persp_fast.cpp only, after asm/span_persp_v7one.h (anonymous namespace).
//
// The last run (m = n - 64 = 1 .. 16 pixels) goes from sample 4 (X4 = ((P + 16) + 16) + 32,
// the mid prologue's [u, v], an input) to sample 5 (X5 = (((P + 16) + 16) + 16) + (n - 49), the
// last pixel): the walker's positions, accumulated as it does. Its set-up is the one-run
// path's chain (asm/span_persp_v7one.h, one_setup2_v7: the header there says why each
// operation is the walker's), over s = max(m - 1, 1): both depths (z4 again: the prologue's
// is not kept), sample 5, the quotients q = double(delta) / s, ddf = q c2 (c2 = -2 curve,
// curve = (zix * 0.5) (z4 + z5)), the range and acceptance tests in NEON lanes, then dd' and
// d. In two statements: five_head_v7 (positions, both depth divides, sample 5's multiply-adds)
// between persp_mid_v7's runs 0 and 1 (its hook), then the rest between run 3's pixel groups
// (five_tail_v7; bench/gen_v7five.py generates it). The Cortex-A9 model issues VFP / NEON
// in order: a chain there stalls the FP work after it but not the integer pixels, so each
// chain goes where pixels follow it. A9 model persp72: the set-up in C++ in Run16's stage
// slots 8.55; all of it in run 3's statement 8.08 (its chain, about 135 cycles, is longer
// than run 3's pixels, about 68); the head between runs 0 and 1 7.74 (between the prologue
// and run 0, 7.81).
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#include "asm/span_persp_v7mid.h"

#if defined(SB_V7_MID) && defined(SB_V7_NEON_STEPS)
#define SB_V7_FIVE 1
#define SB_V7_FIVE_HOOK 1  // persp_mid_v7's hook point for five_head_v7 (after run 0)
#define SB_V7_FIVE_CLOBBERS "d0", "d1", "d2", "d3", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25"
namespace sb::simd {
namespace {

// Per last-run length m (1 .. 16; row 0 unused). The head (five_head_v7): n - 49 = m + 15
// (X5's offset from (P + 16) + 16), 16, 32, kMinZi; 1, 1/2. The tail (the run-3 statement, from
// the row + 64): s = max(m - 1, 1), k = (s - 1) / 2, [T, T] (T = s (s - 1) / 2), -2; [1e9, 1e9]
// (u32).
struct alignas(64) FiveRow {
  double off, c16, c32, kmin, one, half, pad[2];
  double s, k;
  uint32_t t[2];
  double m2;
  uint32_t big[2];
  double pad2[3];
};
__attribute__((section(".rodata.sb_v7one"))) constexpr auto kFiveRows = [] {
  struct Table {
    FiveRow row[17];
  } t{};
  for (int m = 1; m <= 16; ++m) {
    const int s = m > 2 ? m - 1 : 1;
    const uint32_t T = uint32_t(s * (s - 1) / 2);
    t.row[m] = FiveRow{double(m + 15), 16.0, 32.0, kMinZi, 1.0, 0.5, {}, double(s), double(s - 1) / 2, {T, T}, -2.0,
                       {1000000000u, 1000000000u}, {}};
  }
  return t;
}();
static_assert(sizeof(FiveRow) == 128 && offsetof(FiveRow, one) == 32 && offsetof(FiveRow, s) == 64 &&
                  offsetof(FiveRow, big) == 96 && offsetof(PerspSpan, zi0) == 0 && offsetof(PerspSpan, vz0) == 32 &&
                  offsetof(PerspSpan, umax) == 56,
              "the statements' loads (lists of consecutive d registers)");

// The head of the last run's set-up (issued between two of persp_mid_v7's statements: its
// latency under the runs after it): X4, X5; z4 = 1 / max(zrow + zix X4, kMinZi), likewise z5
// (fused, NaN -> kMinZi); urow + ux X5, vrow + vx X5 (fused); zh = zix * 0.5; [umax, vmax].
// Results in d8 .. d15 (which the prologue's outputs and runs 0 .. 2 leave alone), scratch
// d16 .. d23 (free after the prologue and after run 0).
struct FiveHead {
  double z4, z5, u5, v5, zh, uv;
};
SB_INLINE FiveHead five_head_v7(const PerspSpan& p, const FiveRow* row) {
  register double v5 __asm__("d8"), z5 __asm__("d10"), uv __asm__("d11"), z4 __asm__("d12"), zh __asm__("d13"),
      u5 __asm__("d14");
  const PerspSpan* pp = &p;
  __asm__ volatile(
      "vld1.64 {d16, d17, d18, d19}, [%[r]]!\n\t"  // n - 49, 16, 32, kMinZi
      "vld1.64 {d12, d13, d14, d15}, [%[p]]!\n\t"  // zrow, zix, urow, ux
      "vld1.64 {d8, d9, d10, d11}, [%[p]]\n\t"     // vrow, vx, P, [umax, vmax]
      "vld1.64 {d20, d21}, [%[r]]\n\t"             // 1, 1/2
      "vadd.f64 d10, d10, d17\n\t"                 // P + 16
      "vmov.f64 d22, d12\n\t"
      "vadd.f64 d10, d10, d17\n\t"                 // (P + 16) + 16
      "vadd.f64 d18, d10, d18\n\t"                 // X4
      "vadd.f64 d10, d10, d17\n\t"
      "vfma.f64 d12, d13, d18\n\t"
      "vadd.f64 d16, d10, d16\n\t"                 // X5
      "vfma.f64 d22, d13, d16\n\t"
      "vfma.f64 d14, d15, d16\n\t"
      "vfma.f64 d8, d9, d16\n\t"
      "vmul.f64 d13, d13, d21\n\t"                 // zh
      "vcmpe.f64 d12, d19\n\t"
      "vmrs APSR_nzcv, fpscr\n\t"
      "it le\n\t"
      "vmovle.f64 d12, d19\n\t"
      "vdiv.f64 d12, d20, d12\n\t"
      "vcmpe.f64 d22, d19\n\t"
      "vmrs APSR_nzcv, fpscr\n\t"
      "it le\n\t"
      "vmovle.f64 d22, d19\n\t"
      "vdiv.f64 d10, d20, d22"
      : "=&w"(z4), "=&w"(z5), "=&w"(u5), "=&w"(v5), "=&w"(zh), "=&w"(uv), [p] "+r"(pp), [r] "+r"(row)
      :
      : "cc", "memory", "d9", "d15", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23");
  return FiveHead{z4, z5, u5, v5, zh, uv};
}

// Run 3 (r3: its registers from persp_mid_v7<false, true>) drawn at dest + 48, and the last
// run's set-up; then the last run drawn at dest + 64 (draw16 or draw_last, as one_draw_v7).
// s4: sample 4's [u, v] (the prologue's d4), bound to d4 here.
SB_INLINE void five_tail_v7(uint8_t* dest, int n, const uint8_t* texels, uint32_t w, const RunRegs& r3,
                            double s4in, const FiveHead& h) {
  const int m = n - 64;
  uint32_t u = r3.u, v = r3.v, du = r3.du, dv = r3.dv;
  const uint32_t ddu = r3.ddu, ddv = r3.ddv;
  uint32_t a = 0;
  uint32_t b = uint32_t(reinterpret_cast<uintptr_t>(&kFiveRows.row[m].s));
  register double s4 __asm__("d4") = s4in;
  register double v5 __asm__("d8") = h.v5, z5 __asm__("d10") = h.z5, uv __asm__("d11") = h.uv,
                  z4 __asm__("d12") = h.z4, zh __asm__("d13") = h.zh, u5 __asm__("d14") = h.u5;
  uint8_t* const d3 = dest + 48;
  __asm__ volatile(
    // Generated by bench/gen_v7five.py (do not edit by hand).
    "vmul.f64 d14, d14, d10\n\t"
    "vmul.f64 d8, d8, d10\n\t"
    "vadd.f64 d12, d12, d10\n\t"
    "vcvt.u32.f64 d14, d14, #16\n\t"
    "vld1.64 {d0, d1, d2, d3}, [%[b]]!\n\t"
    "smulbt %[a], %[w], %[v]\n\t"
    "uxtah %[a], %[a], %[u], ror #16\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vld1.64 {d16}, [%[b]]\n\t"
    "vcvt.u32.f64 d8, d8, #16\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "vmul.f64 d13, d13, d12\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "vsli.64 d14, d8, #32\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "ldrb %[a], [%[tx], %[a]]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "vmin.u32 d14, d14, d11\n\t"
    "add %[u], %[u], %[du]\n\t"
    "orr %[a], %[a], %[b], lsl #8\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "vmul.f64 d13, d13, d3\n\t"
    "vsub.i32 d3, d14, d4\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vcvt.f64.s32 d17, s6\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "orr %[a], %[a], %[b], lsl #16\n\t"
    "vcvt.f64.s32 d18, s7\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "vdiv.f64 d17, d17, d0\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "orr %[a], %[a], %[b], lsl #24\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "str %[a], [%[d], #0]\n\t"
    "smulbt %[a], %[w], %[v]\n\t"
    "vabs.s32 d19, d3\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "vdiv.f64 d18, d18, d0\n\t"
    "uxtah %[a], %[a], %[u], ror #16\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "ldrb %[a], [%[tx], %[a]]\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "orr %[a], %[a], %[b], lsl #8\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "orr %[a], %[a], %[b], lsl #16\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "orr %[a], %[a], %[b], lsl #24\n\t"
    "str %[a], [%[d], #4]\n\t"
    "smulbt %[a], %[w], %[v]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "uxtah %[a], %[a], %[u], ror #16\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "ldrb %[a], [%[tx], %[a]]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "vcvt.s32.f64 s0, d17\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "vmovl.u32 q10, d19\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "vmul.f64 d22, d18, d13\n\t"
    "orr %[a], %[a], %[b], lsl #8\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "vmul.f64 d19, d17, d13\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vcvt.s32.f64 s6, d19\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "orr %[a], %[a], %[b], lsl #16\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "orr %[a], %[a], %[b], lsl #24\n\t"
    "vcvt.s32.f64 s7, d22\n\t"
    "str %[a], [%[d], #8]\n\t"
    "smulbt %[a], %[w], %[v]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vcvt.s32.f64 s1, d18\n\t"
    "uxtah %[a], %[a], %[u], ror #16\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "vabs.s32 d19, d3\n\t"
    "vcvt.f64.s32 d22, s6\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vcvt.f64.s32 d23, s7\n\t"
    "add %[dv], %[dv], %[ddv]\n\t"
    "vmull.u32 q12, d19, d2\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "ldrb %[a], [%[tx], %[a]]\n\t"
    "add %[u], %[u], %[du]\n\t"
    "vfms.f64 d18, d23, d1\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "vfms.f64 d17, d22, d1\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[du], %[du], %[ddu]\n\t"
    "vqsub.u64 q12, q12, q10\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "orr %[a], %[a], %[b], lsl #8\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "orr %[a], %[a], %[b], lsl #16\n\t"
    "vcgt.u32 d22, d16, d19\n\t"
    "add %[u], %[u], %[du]\n\t"
    "add %[v], %[v], %[dv]\n\t"
    "vqmovn.u64 d16, q12\n\t"
    "smulbt %[b], %[w], %[v]\n\t"
    "vtst.32 d16, d16, d16\n\t"
    "uxtah %[b], %[b], %[u], ror #16\n\t"
    "ldrb %[b], [%[tx], %[b]]\n\t"
    "orr %[a], %[a], %[b], lsl #24\n\t"
    "vmov %[u], %[v], d4\n\t"
    "vcvt.s32.f64 s2, d17\n\t"
    "vbic d22, d22, d16\n\t"
    "str %[a], [%[d], #12]\n\t"
    "vcvt.s32.f64 s3, d18\n\t"
    "vand d3, d3, d22\n\t"
    "vbsl d22, d1, d0\n\t"
    "vmov %[a], %[b], d3\n\t"
    "vmov %[du], %[dv], d22"
    // clobbers: "d0", "d1", "d2", "d3", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25"
      : [u] "+&r"(u), [v] "+&r"(v), [du] "+&r"(du), [dv] "+&r"(dv), [a] "+&r"(a), [b] "+&r"(b), "+w"(z4),
        "+w"(z5), "+w"(u5), "+w"(v5), "+w"(zh)
      : [ddu] "r"(ddu), [ddv] "r"(ddv), [w] "r"(w), [tx] "r"(texels), [d] "r"(d3), "w"(s4), "w"(uv)
      : "memory", "cc", SB_V7_FIVE_CLOBBERS);
  // Now u, v: sample 4's [u, v]; a, b: [ddu, ddv]; du, dv: the last run's steps.
  if (m == 16) {
    draw16<true>(dest + 64, texels, w, int32_t(u), int32_t(v), RunSteps{int32_t(du), int32_t(a)},
                 RunSteps{int32_t(dv), int32_t(b)});
  } else {
    draw_last<true, true>(dest + 64, m, texels, w, u, v, du, dv, a, b);
  }
}

}  // namespace
}  // namespace sb::simd
#endif
