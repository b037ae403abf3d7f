// asm/span_persp_a64few.h: aarch64 only, persp_short_inl's second-order path for two and
// three runs (17 .. 48 pixels): the four-run path's vector steps block (short_steps_k3v /
// steps_k3v_pass, asm/span_persp_a64mid.h) on the span's samples moved down one or two runs,
// so that the block's run 2 is a full run of this span and its run 3 this span's last run.
// Internal: included by asm/span_persp_a64short.h after asm/span_persp_a64mid.h (anonymous
// namespace: internal linkage).
//
// Why: the two- and three-run spans took short_rest's generic steps (a vector block for the
// full runs, then last_steps on the core for the last run, then the runs one by one): on the
// persp32 row (pairs of 17 .. 48 px) those steps blocks were ~240 cycles a span on the A53
// model, against ~134 for steps_k3v_pass with its first pass (32 pixels) inside.
#pragma once
#include <cstddef>
#include <cstdint>

#include "asm/span_persp_run.h"
#if defined(__aarch64__) && defined(__GNUC__)
#include "asm/span_persp_a64mid.h"
#include "asm/span_persp_a64pass.h"
#endif

namespace sb::simd {
namespace {

#if defined(__aarch64__) && defined(__GNUC__)
// A partial last run (1 .. 15 pixels) from Run16's packed start x = v 2^32 + u and steps d, dd
// (as steps_k3v_pass returns its second pass's run b): draw_last's chunks without unpacking.
SB_INLINE void draw_last_packed(uint8_t* __restrict dest, int n, const uint8_t* __restrict texels, uint32_t w,
                                uint64_t x, uint64_t d, uint64_t dd) {
  TailPos p{x, d, dd};
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
// Three runs (33 .. 48 pixels; last = n - 32 = 1 .. 16 pixels in run 2), second order, from
// the sample block's S01 = [u_0, v_0, u_1, v_1], S23 = [u_2, v_2, u_3, v_3], c01 (runs 0, 1's
// curve factors), zs23 = [z_2 + z_3, ...] and zh = zc / 2. steps_k3v_pass with its inputs
// moved: S23' = [S_2, S_2], S44' = [S_3, ..]. The block takes run 1's delta from S23''s low
// half (S_2: as the four-run span's), its run 2 is S_2 - S_2 (a full run of delta 0, unused)
// and its run 3 is S_3 - S_2 from S_2, this span's last run (z_2 + z_3 in zs23'[1]). Its first
// pass draws runs 0 and 1 (S01 and c01 as the four-run span's), its second-pass run b is the
// last run. Then the last run: 16 pixels (full) or draw_last's chunks. The same bits as
// short_rest's k = 2 path: each lane is the four-run block's, which
// AsmSpanPersp.ShortStepsK3vMatchTheirParts checks against steps16_dd and last_steps.
SB_INLINE void persp_few_k2(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01,
                            int32x4_t S23, float64x2_t c01, float64x2_t zs23, double zh) {
  uint64_t st[6];
  bool full;
  const int32x4_t S22 = vreinterpretq_s32_u64(vdupq_laneq_u64(vreinterpretq_u64_s32(S23), 0));
  const int32x4_t S33 = vreinterpretq_s32_u64(vdupq_laneq_u64(vreinterpretq_u64_s32(S23), 1));
  const MidFirst second = steps_k3v_pass(dest, texels, uint64_t(width), S01, S22, S33, c01, c01,
                                         vdupq_laneq_f64(zs23, 0), last - 1, zh, st, full);
  if (full) {
    Run16<true> run(second.b_uv, second.b_d, second.b_dd, Run16<true>::Packed{});
    run.draw(dest + 32, texels, uint32_t(width));
    return;
  }
  draw_last_packed(dest + 32, last, texels, uint32_t(width), second.b_uv, second.b_d, second.b_dd);
}
// Two runs (17 .. 32 pixels; last = n - 16 = 1 .. 16 pixels in run 1): short_steps_k3v with
// S23' = S01 (its run 2 is run 0, factor c23' = c01), S44' = S23 (its low half S_2: its run 3
// is run 1, the last, with z_1 + z_2 = zs01[1] in zs23' = zs01); its runs 0, 1 (S01' = S01,
// computed, unused). Then both runs as one short_pass (last == 16) or run 0 and the partial
// last run by runs_k3 (which draws at d + 32: d = dest - 32).
SB_INLINE void persp_few_k1(uint8_t* dest, int last, const uint8_t* texels, int64_t width, int32x4_t S01,
                            int32x4_t S23, float64x2_t c01, float64x2_t zs01, double zh) {
  uint64_t st[6];
  (void)short_steps_k3v(S01, S01, S23, c01, c01, zs01, last - 1, zh, st);
  const uint64_t d0 = mid_pack(st[2]), dd0 = mid_pack(st[4]), ld = mid_pack(st[3]), ldd = mid_pack(st[5]);
  if (last == 16) {
    short_pass<true>(dest, texels, uint64_t(width), st[0], d0, dd0, st[1], ld, ldd);
    return;
  }
  runs_k3(dest - 32, texels, uint64_t(width), last, st[0], d0, dd0, st[1], ld, ldd);
}
#endif

}  // namespace
}  // namespace sb::simd
