// asm/span_persp_a64longspan.h: aarch64 only, persp_long_a64_inl: one second-order span of
// more than 64 pixels (persp_fast's operations, the same bits), its set-up and passes as
// long_passes2's asm (asm/span_persp_a64long.h), then the tail. Internal: included by
// asm/span_persp_fast.cpp (anonymous namespace: internal linkage), which calls it from
// persp_long_a64 (the batch's loop over consecutive long items).
#pragma once
#include <cstdint>
#include <type_traits>

#include "asm/span_persp.h"
#include "asm/span_persp_arm.h"
#include "asm/span_persp_run.h"
#include "asm/span_persp_a64long.h"
#include "asm/span_persp_a64longlast.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include <arm_neon.h>

namespace sb::simd {
namespace {

// The left > 32 tail's steps (last < 16) as one asm block with fixed scratch registers (x9 -
// x17, v16 - v25), in an order from bench/order_search.py (bench/mca_a53_persp/tail2_steps.s,
// written in by tail_inline.py (tail2_steps) there): run r + 1's steps packed (b_d, b_dd as pack_steps: ddf =
// double(d1u) cc, dd = fcvtzs(ddf), then steps16_dd in the long loop's 12-op form) beside the
// last run's step groups 0 .. 6 of persp_long_a64_inl's tail (the same operations: du, dv the
// last run's deltas, y = kRecipSteps[s], sf = double(s), z23 its two depths [z1, z2] as the
// loop leaves them (their sum by faddp: no lane moves in the block before), zc (the curve
// factor c2 = -(zc (z1 + z2)) by one fnmul: the same bits as step groups 2, 3's -2 ((zc / 2)
// (z1 + z2)), the scalings by 1/2 and -2 being exact unless c2 is subnormal or overflows, where
// both give the same infinity or a dd of 0; no zc / 2 multiply in the block before);
// outputs lnu, lnv = trunc(q), ddu, ddv = the range-masked dd, for last_steps_ddi).
SB_INLINE void tail2_steps(int32_t du, int32_t dv, int32_t d1u, int32_t d1v, double cc, double y, double sf,
                           float64x2_t z23, double zc, uint64_t& b_d, uint64_t& b_dd, int32_t& l_u,
                           int32_t& l_v, int32_t& dd_u, int32_t& dd_v) {
  __asm__(
      // BEGIN tail2_steps
      "sxtw x11, %w[d1u]\n\t"
      "cmp x11, #0\n\t"
      "sxtw x12, %w[d1v]\n\t"
      "scvtf d24, %w[d1u]\n\t"
      "scvtf d16, %w[du]\n\t"
      "scvtf d17, %w[dv]\n\t"
      "cneg x15, x11, lt\n\t"
      "cmp x12, #0\n\t"
      "scvtf d25, %w[d1v]\n\t"
      "fmul d24, d24, %d[cc]\n\t"
      "fmul d18, d16, %d[y]\n\t"
      "faddp d20, %[z23].2d\n\t"
      "fmul d19, d17, %d[y]\n\t"
      "cneg x16, x12, lt\n\t"
      "fmul d25, d25, %d[cc]\n\t"
      "fcvtzs w9, d24\n\t"
      "fmsub d21, d18, %d[sf], d16\n\t"
      "fmsub d22, d19, %d[sf], d17\n\t"
      "fnmul d20, %d[zc], d20\n\t"
      "fcvtzs w10, d25\n\t"
      "sbfiz x13, x9, #7, #32\n\t"
      "sub x13, x13, w9, sxtw #3\n\t"
      "add x17, x13, x15\n\t"
      "sbfiz x14, x10, #7, #32\n\t"
      "sub x14, x14, w10, sxtw #3\n\t"
      "cmp x17, x15, lsl #1\n\t"
      "fmadd d19, d22, %d[y], d19\n\t"
      "fmadd d18, d21, %d[y], d18\n\t"
      "csel x13, x13, xzr, ls\n\t"
      "add %[bdd], x14, x16\n\t"
      "csel w9, w9, wzr, ls\n\t"
      "cmp %[bdd], x16, lsl #1\n\t"
      "sub x11, x11, x13\n\t"
      "mov w13, #0xc9ff\n\t"
      "asr x17, x11, #63\n\t"
      "csel x14, x14, xzr, ls\n\t"
      "csel w10, w10, wzr, ls\n\t"
      "sub x12, x12, x14\n\t"
      "asr %[bdd], x12, #63\n\t"
      "fmul d22, d19, d20\n\t"
      "fcvtzs %w[lu], d18\n\t"
      "fmul d21, d18, d20\n\t"
      "fcvtzs %w[lv], d19\n\t"
      "add x12, x12, %[bdd], lsr #60\n\t"
      "movk w13, #0x3b9a, lsl #16\n\t"
      "asr x12, x12, #4\n\t"
      "add x11, x11, x17, lsr #60\n\t"
      "lsl x14, x10, #32\n\t"
      "fcvtzs %w[ddu], d21\n\t"
      "fcvtzs %w[ddv], d22\n\t"
      "add %[bdd], x14, w9, sxtw\n\t"
      "mov w14, #0x93ff\n\t"
      "asr x11, x11, #4\n\t"
      "movk w14, #0x7735, lsl #16\n\t"
      "add %[bd], x11, x12, lsl #32\n\t"
      "add w11, %w[ddu], w13\n\t"
      "add w12, %w[ddv], w13\n\t"
      "cmp w11, w14\n\t"
      "csel %w[ddu], %w[ddu], wzr, lo\n\t"
      "cmp w12, w14\n\t"
      "csel %w[ddv], %w[ddv], wzr, lo"
      // END tail2_steps
      : [bd] "=&r"(b_d), [bdd] "=&r"(b_dd), [lu] "=&r"(l_u), [lv] "=&r"(l_v), [ddu] "=&r"(dd_u), [ddv] "=&r"(dd_v)
      : [du] "r"(du), [dv] "r"(dv), [d1u] "r"(d1u), [d1v] "r"(d1v), [cc] "w"(cc), [y] "w"(y), [sf] "w"(sf),
        [z23] "w"(z23), [zc] "w"(zc)
      : "x9", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17", "v16", "v17", "v18", "v19", "v20", "v21",
        "v22", "v23", "v24", "v25", "cc");
}

// The left <= 32 tail's last-run steps (last < 16) as one asm block with fixed scratch
// registers (x3 - x5, x9 - x17, x19, v16 - v23), in an order from bench/order_search.py
// (bench/mca_a53_persp/tail1_steps.s, written in by tail_inline.py (tail1_steps) there): the step groups 0 ..
// 6 of persp_long_a64_inl's tail (du, dv the last run's deltas, y = kRecipSteps[s], sf =
// double(s), s = max(steps, 1), z1 and z2's lane 0 its two depths (z2: the loop's z23 as it
// leaves it, read as its d register: no lane move), zc (c2 = -(zc (z1 + z2)) by one fnmul, as
// tail2_steps)) then last_steps_ddi's
// operations (asm/span_persp_arm.h; s, T = steps (steps - 1) / 2, s - 1 and the steps > 1 mask
// computed here from steps); outputs the last run's steps lu = {l_u, dd_u}, lv = {l_v, dd_v}.
SB_INLINE void tail1_steps(int32_t du, int32_t dv, int steps, double y, double sf, double z1, float64x2_t z2, double zc,
                           int32_t& l_u, int32_t& l_v, int32_t& dd_u, int32_t& dd_v) {
  // du, dv in registers the code after the asm (runs_k3) does not write: where qemu cuts the
  // two into one block, llvm-mca times it as a loop, and an input written later in the block
  // is a false loop-carried dependence (the Cortex-A57 model then runs the block as one
  // chain: persp192 A72 5.670 with GCC's choice, 5.625 with these).
  register int32_t r_du __asm__("x27") = du;
  register int32_t r_dv __asm__("x28") = dv;
  __asm__(
      // BEGIN tail1_steps
      "cmp %w[st], #1\n\t"
      "scvtf d16, %w[du]\n\t"
      "scvtf d17, %w[dv]\n\t"
      "csetm w10, gt\n\t"
      "sub w11, %w[st], #1\n\t"
      "fadd d20, %d[z1], %d[z2]\n\t"
      "fmul d18, d16, %d[y]\n\t"
      "fmul d19, d17, %d[y]\n\t"
      "mov w13, #0xc9ff\n\t"
      "fnmul d20, %d[zc], d20\n\t"
      "fmsub d21, d18, %d[sf], d16\n\t"
      "fmsub d22, d19, %d[sf], d17\n\t"
      "movk w13, #0x3b9a, lsl #16\n\t"
      "fmadd d18, d21, %d[y], d18\n\t"
      "fmadd d19, d22, %d[y], d19\n\t"
      "csinc w9, %w[st], wzr, gt\n\t"
      "fmul d21, d18, d20\n\t"
      "fcvtzs %w[lv], d19\n\t"
      "fmul d22, d19, d20\n\t"
      "mul w11, w11, %w[st]\n\t"
      "fcvtzs %w[lu], d18\n\t"
      "sub w12, w9, #1\n\t"
      "fcvtzs %w[ddu], d21\n\t"
      "fcvtzs %w[ddv], d22\n\t"
      "mov w14, #0x93ff\n\t"
      "asr w4, %w[dv], #31\n\t"
      "lsr w11, w11, #1\n\t"
      "movk w14, #0x7735, lsl #16\n\t"
      "add w15, %w[ddu], w13\n\t"
      "add w16, %w[ddv], w13\n\t"
      "cmp w15, w14\n\t"
      "asr w3, %w[du], #31\n\t"
      "eor w13, %w[du], w3\n\t"
      "eor w17, %w[lu], w3\n\t"
      "csel %w[ddu], %w[ddu], wzr, lo\n\t"
      "cmp w16, w14\n\t"
      "eor w14, %w[dv], w4\n\t"
      "and %w[ddu], %w[ddu], w10\n\t"
      "eor w19, %w[lv], w4\n\t"
      "asr w5, %w[ddu], #31\n\t"
      "sub w17, w17, w3\n\t"
      "csel %w[ddv], %w[ddv], wzr, lo\n\t"
      "eor w15, %w[ddu], w5\n\t"
      "sub w15, w15, w5\n\t"
      "and %w[ddv], %w[ddv], w10\n\t"
      "asr w10, %w[ddv], #31\n\t"
      "eor w16, %w[ddv], w10\n\t"
      "sub w13, w13, w3\n\t"
      "sub w16, w16, w10\n\t"
      "eor w5, %w[ddu], w3\n\t"
      "umsubl x15, w15, w11, x13\n\t"
      "sub w14, w14, w4\n\t"
      "msub w13, w9, w17, w13\n\t"
      "sub w19, w19, w4\n\t"
      "eor w10, %w[ddv], w4\n\t"
      "sub w5, w5, w3\n\t"
      "umsubl x16, w16, w11, x14\n\t"
      "cmp w9, w13, lsl #1\n\t"
      "msub w14, w9, w19, w14\n\t"
      "mul w5, w12, w5\n\t"
      "sub w10, w10, w4\n\t"
      "cset w13, hi\n\t"
      "cmp w9, w14, lsl #1\n\t"
      "sub w17, w17, w5, asr #1\n\t"
      "and w13, w13, w5\n\t"
      "sub w17, w17, w13\n\t"
      "mul w10, w12, w10\n\t"
      "cset w14, hi\n\t"
      "cmp x15, #0\n\t"
      "eor w17, w17, w3\n\t"
      "sub w19, w19, w10, asr #1\n\t"
      "and w14, w14, w10\n\t"
      "csel %w[ddu], wzr, %w[ddu], lt\n\t"
      "sub w17, w17, w3\n\t"
      "csel %w[lu], %w[lu], w17, lt\n\t"
      "cmp x16, #0\n\t"
      "sub w19, w19, w14\n\t"
      "eor w19, w19, w4\n\t"
      "csel %w[ddv], wzr, %w[ddv], lt\n\t"
      "sub w19, w19, w4\n\t"
      "csel %w[lv], %w[lv], w19, lt"
      // END tail1_steps
      : [lu] "=&r"(l_u), [lv] "=&r"(l_v), [ddu] "=&r"(dd_u), [ddv] "=&r"(dd_v)
      : [du] "r"(r_du), [dv] "r"(r_dv), [st] "r"(steps), [y] "w"(y), [sf] "w"(sf), [z1] "w"(z1), [z2] "w"(z2),
        [zc] "w"(zc)
      : "x3", "x4", "x5", "x9", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17", "x19", "v16", "v17",
        "v18", "v19", "v20", "v21", "v22", "v23", "cc");
}

// aarch64, second-order spans of more than 64 pixels (one pass for 65 .. 80, else two or more): persp_fast's
// samples, steps and runs with its passes as one asm block (asm/span_persp_a64long.h: the
// first samples in 2-lane vectors, each lane persp_fast's scalar operation, the same bits:
// positions P_0, P_1 = P_0 + 16, sample j + 2 at P_j + 32; zrow + zix pos and uvrow + uvx pos
// fused as there; to_fixed as the vector loop's unsigned conversion, fcvtzu #16, uqxtn, umin;
// run 0's steps as the loop's); the tail after the passes as persp_fast's.
SB_INLINE void persp_long_a64_inl(uint8_t* dest, int n, const uint8_t* texels, int width, const PerspSpan& p) {
  const double zc = p.dzi;
  // The first samples and run 0's steps are the asm's set-up (asm/span_persp_a64long.h), from
  // p and n; the passes leave n - 32 (k + 1) = 17 .. 48 pixels (k full passes, see there).
  LongPass st;
  st.d = reinterpret_cast<uint64_t>(dest), st.tx = reinterpret_cast<uint64_t>(texels), st.w = uint64_t(width);
  long_passes2(st, p, n);
  // texels and w for the tail from the asm's registers (in-out operands, unchanged), not
  // reloaded from the compiler's stack copies.
  texels = reinterpret_cast<const uint8_t*>(st.tx);
  const uint32_t w = uint32_t(st.w);
  // left = n - 32 (k + 1), k = (n - 49) / 32 (n > 64; k = 0 for 65 .. 80): (n - 81) mod 32 + 17
  // (the unsigned wrap of n - 81 < 0 keeps the residue: n = 65 .. 80 leave n - 32 = 33 .. 48).
  int left = int(uint32_t(n - 81) & 31u) + 17;
  dest = reinterpret_cast<uint8_t*>(st.d);
  // Run r's steps from its chains (c1 - c0 = its packed step, dd4 = 4 times its packed second
  // step, |parts| < 2^31), packed (c0 its packed start); unpacked (run0_parts) only where
  // Run16 draws run r (left > 32 with last == 16), not in the loop-exit block of every span.
  const uint64_t dp = st.c1 - st.c0;
  const int64_t ddp = int64_t(st.dd4) >> 2;
  const Sample s1{int32_t(uint32_t(st.nA)), int32_t(uint32_t(st.nA >> 32)), vgetq_lane_f64(st.zsn, 0)};
  const double z2 = vgetq_lane_f64(st.z23, 0), z3 = vgetq_lane_f64(st.z23, 1);
  // The tail (left = 17 .. 48), persp_fast's; samples r + 2, r + 3 (sample(pos2, z2),
  // sample(pos3, z3)) as the last pass converted them (nB, nC: to_fixed, see persp_fast).
  const Sample sB{int32_t(uint32_t(st.nB)), int32_t(uint32_t(st.nB >> 32)), z2};
  const Sample sC{int32_t(uint32_t(st.nC)), int32_t(uint32_t(st.nC >> 32)), z3};
  // The last run's steps are last_steps' (the same results) with scalar operations, u and v
  // two interleaved chains (fewer dependent NEON levels: on the modelled Cortex-A53 each
  // stalls the core instructions after it): q = div_steps' operations on du, dv; lin =
  // trunc(q) straight to a core register (|q| < 2^31); ddf = q (-2 curve) = -2 (q curve)
  // where |ddf| < 1e9 (scaling by -2 commutes with rounding; where either form overflows,
  // underflows or is NaN both give dd = 0); dd = cvt_sat(ddf) kept iff |dd| < 1e9, which is
  // |ddf| < 1e9 (last_ddi). In steps (step<0> .. step<6>, each depending on the one before).
  // The tail: kTwo when left > 32 (runs r, r + 1, then the last run), t1 / tB the last run's
  // first sample and the one after it (s1, sB; with kTwo sB, sC).
  auto tail = [&](auto two, const Sample& t1, const Sample& tB) SB_LAMBDA_INLINE {
    constexpr bool kTwo = decltype(two)::value;
    const int last = left - (kTwo ? 32 : 16), steps = last - 1;
    // steps == 0 (last == 1, 1 span in 16) marked unlikely as last == 16 is below: the
    // compiler's copy of the tail for it then sits out of the way (A72 persp72 6.7234 ->
    // 6.6916, persp192 5.5386 -> 5.5322; A53 unchanged).
    const Sample s2 = __builtin_expect(steps > 0, 1) ? tB : t1;
    RunSteps lu, lv;
    const int32_t du = s2.u - t1.u, dv = s2.v - t1.v;  // 0 <= u, v < 2^31: no overflow
    const uint32_t sd = uint32_t(steps > 1 ? steps : 1);
    double au, av, y, sf, qu, qv, tu, tv, cz, ch, c2;
    int32_t lnu = 0, lnv = 0, ddu = 0, ddv = 0;
    uint32_t k1 = 999999999u, k2 = 1999999999u;  // group 6's constants, set in group 1 (while fmsub waits)
    // Groups 1 .. 4 as asm (each operation the C++ one's: fmsub = vfms_f64, fmadd = vfma_f64,
    // fused), c2 = -2 (zc 0.5 (s1.z + s2.z)) one operation a group after that group's quotient
    // work: in-order issue, none waits in front of the u, v chain; outputs early-clobber in
    // registers of their own (no copies between the groups).
    auto step = [&](auto g) SB_LAMBDA_INLINE {
      constexpr int G = decltype(g)::value;
      if constexpr (G == 0) {
        au = double(du), av = double(dv);
        y = kRecipSteps[sd], sf = double(sd);
        pin(au), pin(av), pin(y), pin(sf);
      } else if constexpr (G == 1) {
        __asm__ volatile("fmul %d0, %d3, %d5\n\tfmul %d1, %d4, %d5\n\tfadd %d2, %d6, %d7"  // div_steps
                         : "=&w"(qu), "=&w"(qv), "=&w"(cz)
                         : "w"(au), "w"(av), "w"(y), "w"(t1.z), "w"(s2.z));
        pin(k1), pin(k2);
      } else if constexpr (G == 2) {
        __asm__ volatile("fmsub %d0, %d3, %d5, %d6\n\tfmsub %d1, %d4, %d5, %d7\n\tfmul %d2, %d8, %d9"
                         : "=&w"(tu), "=&w"(tv), "=&w"(ch)
                         : "w"(qu), "w"(qv), "w"(sf), "w"(au), "w"(av), "w"(zc * 0.5), "w"(cz));
      } else if constexpr (G == 3) {
        double u2, v2;
        __asm__ volatile("fmadd %d0, %d3, %d5, %d6\n\tfmadd %d1, %d4, %d5, %d7\n\tfmul %d2, %d8, %d9"
                         : "=&w"(u2), "=&w"(v2), "=&w"(c2)
                         : "w"(tu), "w"(tv), "w"(y), "w"(qu), "w"(qv), "w"(ch), "w"(-2.0));
        qu = u2, qv = v2;
      } else if constexpr (G == 4) {
        double u2, v2;
        __asm__ volatile("fcvtzs %w0, %d4\n\tfcvtzs %w1, %d5\n\tfmul %d2, %d4, %d6\n\tfmul %d3, %d5, %d6"
                         : "=&r"(lnu), "=&r"(lnv), "=&w"(u2), "=&w"(v2)
                         : "w"(qu), "w"(qv), "w"(c2));
        tu = u2, tv = v2;
      } else if constexpr (G == 5) {
        ddu = cvt_sat(tu), ddv = cvt_sat(tv);
        pin(ddu), pin(ddv);
      } else if constexpr (G == 6) {
        ddu = (uint32_t(ddu) + k1 < k2) ? ddu : 0;
        ddv = (uint32_t(ddv) + k1 < k2) ? ddv : 0;
        pin(ddu), pin(ddv);
      } else if constexpr (G == 9) {
        last_steps_ddi(steps, du, dv, lnu, lnv, ddu, ddv, &lu, &lv);
      }
    };
    using std::integral_constant;
    if constexpr (kTwo) {
      // Runs r, r + 1, then the last run. Run r + 1's steps (steps16<true>(s1, sB, c1)'s
      // result, sB = t1) and the last run's step groups, then (last < 16) runs r, r + 1 and the
      // last run as one asm block (pass_last), or (last == 16) run r with the step groups in its
      // stage slots, then run r + 1 and the last run as one short_pass.
      RunSteps u1, v1;
      int32_t d1u = 0, d1v = 0, i1u = 0, i1v = 0;
      double f1u = 0, f1v = 0;
      // Run r + 1's ddf in the loop's form, delta (zck (z_{r+1} + z_{r+2})) with the asm's cc[0]
      // (the same dd as steps16_sel's -2 ((delta / 16) (zc / 2 (z1 + z2))): the scalings by
      // 1/16, 1/2 and -2 are exact wherever dd is kept; elsewhere both give a rejected dd).
      const double cc1 = vgetq_lane_f64(st.cc, 0);
      auto r1steps = [&](auto g) SB_LAMBDA_INLINE {
        constexpr int G = decltype(g)::value;
        if constexpr (G == 0) {
          d1u = t1.u - s1.u, d1v = t1.v - s1.v;
          pin(d1u), pin(d1v);
        } else if constexpr (G == 1) {
          f1u = double(d1u), f1v = double(d1v);
          pin(f1u), pin(f1v);
        } else if constexpr (G == 2) {
          f1u = f1u * cc1, f1v = f1v * cc1;
          pin(f1u), pin(f1v);
        } else if constexpr (G == 3) {
          i1u = cvt_sat(f1u), i1v = cvt_sat(f1v);
          pin(i1u), pin(i1v);
        } else if constexpr (G == 4) {
          u1 = steps16_dd(d1u, i1u), v1 = steps16_dd(d1v, i1v);
        }
      };
      uint64_t b_d = 0, b_dd = 0;  // run r + 1's steps packed (tail2_steps)
      auto stage1 = [&](auto g) SB_LAMBDA_INLINE {
        constexpr int G = decltype(g)::value;
        if constexpr (G >= 4) step(integral_constant<int, G - 4>{});
        r1steps(g);
      };
      // last == 16 (1 span in 16) marked unlikely: the compiler then lays the common tail out
      // straight after its tests, with no block of its own ending in a `b` to it (persp72 A53
      // 10.2399 -> 10.1954, persp192 8.2538 -> 8.2474; A72 6.7063 -> 6.7229, 5.5287 -> 5.5386,
      // persp1920 4.8257 -> 4.8127: its one span takes the last == 16 path).
      if (__builtin_expect(last != 16, 1)) {
        // Run r + 1's steps and the last run's step groups side by side (two independent
        // chains, tail2_steps), last_steps_ddi, then runs r, r + 1 and the last run as one asm
        // block (pass_last: short_pass's two runs, then runs_k3's chunks of the last run).
        // The depths t1.z, s2.z as the loop's z23 = [sB.z, sC.z] (t1 = sB, s2 = sC but for steps
        // == 0: du = dv = 0 there, so dd is 0 whatever the depths, and steps <= 1 masks it).
        tail2_steps(du, dv, t1.u - s1.u, t1.v - s1.v, cc1, kRecipSteps[sd], double(sd), st.z23, zc, b_d,
                    b_dd, lnu, lnv, ddu, ddv);
        step(integral_constant<int, 9>{});
        // run r from the loop's packed start and steps (c0, dp, ddp: pack_steps(sv.d, su.d) ==
        // dp and pack_steps(sv.dd, su.dd) == ddp, su and sv being their halves), run r + 1 from
        // s1 and tail2_steps' b_d, b_dd, the last run from t1 (= sB: st.nB) and lu, lv.
        pass_last(dest, texels, uint64_t(width), last, st.c0, dp, uint64_t(ddp),
                  uint64_t(uint32_t(s1.v)) << 32 | uint32_t(s1.u), b_d, b_dd,
                  uint64_t(uint32_t(t1.v)) << 32 | uint32_t(t1.u), lu.d, lv.d, lu.dd, lv.dd);
        return;
      } else {
        // last == 16: run r + 1's steps in run r's stage slots 0 .. 4, one dependent step a
        // group, and the last run's step groups 0 .. 5 in slots 4 .. 9.
        const RunSteps su{int32_t(uint32_t(dp)), int32_t(uint32_t(ddp))};
        const RunSteps sv{int32_t(uint32_t((dp - uint64_t(int64_t(int32_t(uint32_t(dp))))) >> 32)),
                          int32_t(uint32_t(uint64_t(ddp - int64_t(int32_t(uint32_t(ddp)))) >> 32))};
        Run16<true> run0(int32_t(uint32_t(st.c0)), int32_t(uint32_t(st.c0 >> 32)), su, sv);
        run0.draw(dest, texels, w, stage1);
        dest += 16;
        step(integral_constant<int, 6>{}), step(integral_constant<int, 9>{});
        short_pass<true>(dest, texels, uint64_t(width), uint64_t(uint32_t(s1.v)) << 32 | uint32_t(s1.u),
                         pack_steps(v1.d, u1.d), pack_steps(v1.dd, u1.dd),
                         uint64_t(uint32_t(t1.v)) << 32 | uint32_t(t1.u),
                         pack_steps(lv.d, lu.d), pack_steps(lv.dd, lu.dd));
        return;
      }
    } else {
      if (__builtin_expect(last == 16, 0)) {  // (as above)
        // Two full runs left: the steps first, then both runs as one short_pass.
        step(integral_constant<int, 0>{}), step(integral_constant<int, 1>{}), step(integral_constant<int, 2>{});
        step(integral_constant<int, 3>{}), step(integral_constant<int, 4>{}), step(integral_constant<int, 5>{});
        step(integral_constant<int, 6>{}), step(integral_constant<int, 9>{});
        // run r from the loop's packed c0, dp, ddp (as pass_last and runs_k3 take it).
        short_pass<true>(dest, texels, uint64_t(width), st.c0, dp, uint64_t(ddp),
                         uint64_t(uint32_t(s1.v)) << 32 | uint32_t(s1.u), pack_steps(lv.d, lu.d),
                         pack_steps(lv.dd, lu.dd));
        return;
      }
      // Otherwise (last = 1 .. 15) the steps first, then run r and the last run as one asm
      // block: runs_k3 (asm/span_persp_a64mid.h; its d is the span's pixel 32 before run r:
      // it writes d[32 .. 47 + last] only), run r from the loop's packed c0, dp, ddp (as
      // short_pass takes it above), the last run packed as Run16 packs it.
      // s2.z as lane 0 of the loop's z23 (sB.z; s2 = s1 only for steps == 0, where du = dv = 0
      // make dd 0 whatever the depth, and the steps > 1 mask clears it).
      tail1_steps(du, dv, steps, kRecipSteps[sd], double(sd), t1.z, st.z23, zc, lnu, lnv, ddu, ddv);
      lu = RunSteps{lnu, ddu}, lv = RunSteps{lnv, ddv};
      runs_k3(dest - 32, texels, uint64_t(width), last, st.c0, dp, uint64_t(ddp),
              uint64_t(uint32_t(t1.v)) << 32 | uint32_t(t1.u), pack_steps(lv.d, lu.d), pack_steps(lv.dd, lu.dd));
      return;
    }
  };
  if (left > 32) {
    tail(std::true_type{}, sB, sC);
  } else {
    tail(std::false_type{}, s1, sB);
  }
}

}  // namespace
}  // namespace sb::simd
#endif
