// asm/neon.cpp: NEON variants for aarch64 and for armv7 with NEON (armhf: this file alone
// is compiled with -mfpu=neon when STARBOW_ARM_NEON is on; see asm/CMakeLists.txt).
// NEON has no gather: the lanes' coordinates, light and addresses are computed in vectors,
// the texel and colormap loads are scalar, and stores are vector where the output is.
//
// Sections: 1. surface span  2. surface block builder  3. z span  4. palette expansion
#include "asm/variants.h"

#if defined(SB_SIMD_HAVE_NEON)
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "SB_SIMD_HAVE_NEON is set but this file is not compiled for NEON"
#endif
#include <arm_neon.h>

#include <cstring>

namespace sb::simd::detail {
namespace {

// Lanes k = 0..3 of a + k d + k (k - 1) / 2 dd (mod 2^32).
inline uint32x4_t lanes4(uint32_t a, uint32_t d, uint32_t dd) {
  const uint32_t v[4] = {a, a + d, a + 2 * d + dd, a + 3 * d + 3 * dd};
  return vld1q_u32(v);
}

// ---------------------------------------------------------------- 1. surface span
//
// The NEON table's surface_span is the portable surface_span_fast (asm/surface_span.h): a
// lane-based loop (addresses in vectors, each lane moved to a core register for its load)
// lost to scalar code on 16-pixel runs on every modelled core (bench/counts.md).

// ---------------------------------------------------------------- 2. surface block builder
//
// Sixteen lanes at a time: 16 >> LB blocks side by side (one block at mip 0, eight at mip 3)
// walked down a whole strip of bands, the light numerators in 32-bit lanes stepped by a
// per-lane delta (one vector add per four texels and row). The numerators are kept scaled by
// 4^mip,
//   n(fx, fy) = (B T(fx) + fy (U(fx) - T(fx))) << 2 mip,  T = g00 (B - fx) + g10 fx,
//   U = g01 (B - fx) + g11 fx,
// so the colormap row (num >> (S + 8)) is byte 2 of every lane at every mip (n < 2^22: byte 3
// is zero). After a band's B steps the numerators are exactly the next band's first (B U),
// so crossing a band edge only takes the next row step (one grid row weighed per band).
// Indices texel | row << 8 (32-bit lanes) leave the vector two at a time; the colormap bytes
// are read by sixteen independent scalar loads, packed into words, and stored. The row loop
// of full groups is assembly on both ARM targets (the compilers' schedules and register
// allocation cost 1.5-2x there): row y's scalar work first, then row y + 1's NEON work, so an
// in-order core never waits on a NEON result. The last, partial group of a row is C++.
// Texture rows are laid out wrapped first ("tiled": surface column x reads run[x]); rows that
// need no wrap are read in place. Every texture row once per call when the texture is shorter
// than the surface (rows repeat) and fits the buffer, else a strip of bands' rows at a time.

// Lanes k = 0..7 (half 0) or 8..15 (half 1) of g[k >> LB].
template <int LB>
inline uint16x8_t spread(const uint16_t* g, int half) {
  if constexpr (LB == 4) {
    return vdupq_n_u16(g[0]);
  } else if constexpr (LB == 3) {
    return vdupq_n_u16(g[half]);
  } else if constexpr (LB == 2) {
    return vcombine_u16(vdup_n_u16(g[2 * half]), vdup_n_u16(g[2 * half + 1]));
  } else {
    const uint16x4_t x = vld1_u16(g + 4 * half);
    const uint16x4x2_t z = vzip_u16(x, x);
    return vcombine_u16(z.val[0], z.val[1]);
  }
}

// dst[x] = row[(c0 + x) mod tw] for x < n (a multiple of 16); writes up to n + 15 (and at
// least 32 bytes must be writable).
inline void tile_row(uint8_t* dst, const uint8_t* row, int tw, int c0, int n, const uint8_t* tex_end,
                     const uint8x16_t* period) {
  int d;  // a period of the run, >= 16
  if (tw >= 16) {
    const int a = tw - c0 < n ? tw - c0 : n;
    std::memcpy(dst, row + c0, size_t(a));
    if (a < n) std::memcpy(dst + a, row, size_t(c0 < n - a ? c0 : n - a));
    d = tw;
  } else {
    d = tw;
    while (d < 16) d += tw;  // (no divide); at most 30
    if (row + 16 <= tex_end) {  // the first 32 bytes by two table lookups of the row
      const uint8x16_t v = vld1q_u8(row);
#if defined(__aarch64__)
      vst1q_u8(dst, vqtbl1q_u8(v, period[0]));
      vst1q_u8(dst + 16, vqtbl1q_u8(v, period[1]));
#else
      uint8x8x2_t t;
      t.val[0] = vget_low_u8(v);
      t.val[1] = vget_high_u8(v);
      for (int h = 0; h < 2; ++h)
        vst1q_u8(dst + 16 * h, vcombine_u8(vtbl2_u8(t, vget_low_u8(period[h])), vtbl2_u8(t, vget_high_u8(period[h]))));
#endif
      for (int x = 32; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
      return;
    }
    for (int k = 0, c = c0; k < d; ++k) {
      dst[k] = row[c];
      if (++c == tw) c = 0;
    }
  }
  for (int x = d; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
}

constexpr int kTileBytes = 16 * (kMaxBlockColumns * 16 + 32);  // B runs of the widest surface

constexpr int kMaxRuns = 2064;  // run pointers: >= kTileBytes / (smallest stride, 32)

// Lanes k of the group's weighted grid row: g[k >> LB] (B - fx) + g[(k >> LB) + 1] fx with
// weights pre-shifted (bx = (B - fx) << s, fx = fx << s), quarter j = lanes 4j .. 4j + 3.
template <int LB>
inline void weigh(const uint16_t* g, const uint16x8_t* bx, const uint16x8_t* fx, uint32x4_t* out) {
#pragma GCC unroll 2
  for (int h = 0; h < 2; ++h) {
    const uint16x8_t e0 = spread<LB>(g, h), e1 = spread<LB>(g + 1, h);
    out[2 * h] = vmlal_u16(vmull_u16(vget_low_u16(e0), vget_low_u16(bx[h])), vget_low_u16(e1), vget_low_u16(fx[h]));
    out[2 * h + 1] =
        vmlal_u16(vmull_u16(vget_high_u16(e0), vget_high_u16(bx[h])), vget_high_u16(e1), vget_high_u16(fx[h]));
  }
}

#if !defined(__aarch64__)
// out[0..3] = the numerators of a full group's first row: g's entries weighted by bx, fx
// (16 lanes each; (B - fx) << (4 + mip) and fx << (4 + mip), <= 256). Reads four entries at
// g and g + 1 (mips 0-1: past the group's, inside the grid as g is never its last row).
template <int LB>
__attribute__((noinline)) void first_numerators(const uint16_t* g, const uint16_t* bx, const uint16_t* fx,
                                                uint32x4_t* out) {
  if constexpr (LB == 1) {  // lanes 2j, 2j + 1: g_j << 8, (g_j + g_j+1) << 7, stored interleaved
    asm volatile(
        "vld1.16 {d16-d17}, [%[g]]!\n\t"
        "sub %[g], %[g], #14\n\t"
        "vld1.16 {d18-d19}, [%[g]]\n\t"
        "vshll.u16 q0, d16, #8\n\t"
        "vadd.i16 q9, q9, q8\n\t"
        "vshll.u16 q2, d17, #8\n\t"
        "vshll.u16 q1, d18, #7\n\t"
        "vshll.u16 q3, d19, #7\n\t"
        "vst2.32 {d0-d3}, [%[o]:128]!\n\t"
        "vst2.32 {d4-d7}, [%[o]:128]\n\t"
        : [g] "+r"(g), [o] "+r"(out)
        :
        : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d16", "d17", "d18", "d19", "memory");
    (void)bx, (void)fx;
  } else {  // quarter q: entries j = 4 q >> LB and j + 1 as scalars (lanes of d0 and d1)
    asm volatile(
        "vld1.16 {d0}, [%[g]]!\n\t"
        "sub %[g], %[g], #6\n\t"
        "vld1.16 {d1}, [%[g]]\n\t"
        "vld1.16 {d16-d19}, [%[bx]]\n\t"
        "vld1.16 {d20-d23}, [%[fx]]\n\t"
        "vmull.u16 q2, d16, d0[%c[j0]]\n\t"
        "vmull.u16 q3, d17, d0[%c[j1]]\n\t"
        "vmull.u16 q12, d18, d0[%c[j2]]\n\t"
        "vmull.u16 q13, d19, d0[%c[j3]]\n\t"
        "vmlal.u16 q2, d20, d1[%c[j0]]\n\t"
        "vmlal.u16 q3, d21, d1[%c[j1]]\n\t"
        "vmlal.u16 q12, d22, d1[%c[j2]]\n\t"
        "vmlal.u16 q13, d23, d1[%c[j3]]\n\t"
        "vst1.32 {d4-d7}, [%[o]:128]!\n\t"
        "vst1.32 {d24-d27}, [%[o]:128]\n\t"
        : [g] "+r"(g), [o] "+r"(out)
        : [bx] "r"(bx), [fx] "r"(fx), [j0] "i"(0), [j1] "i"(4 >> LB), [j2] "i"(8 >> LB), [j3] "i"(12 >> LB)
        : "d0", "d1", "d4", "d5", "d6", "d7", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24",
          "d25", "d26", "d27", "memory");
  }
}

// band_deltas' bands one at a time (the rest after its two-band passes).
template <int LB>
__attribute__((noinline)) void band_deltas_one(const uint16_t* g, int gw, int n, const uint16_t* bxp,
                                               const uint16_t* fxp, uint32x4_t* D) {
  const int16x4_t bx0 = vreinterpret_s16_u16(vld1_u16(bxp)), bx1 = vreinterpret_s16_u16(vld1_u16(bxp + 4));
  const int16x4_t bx2 = vreinterpret_s16_u16(vld1_u16(bxp + 8)), bx3 = vreinterpret_s16_u16(vld1_u16(bxp + 12));
  const int16x4_t fx0 = vreinterpret_s16_u16(vld1_u16(fxp)), fx1 = vreinterpret_s16_u16(vld1_u16(fxp + 4));
  const int16x4_t fx2 = vreinterpret_s16_u16(vld1_u16(fxp + 8)), fx3 = vreinterpret_s16_u16(vld1_u16(fxp + 12));
  auto put = [&](int16x4_t a0, int16x4_t a1, int16x4_t a2, int16x4_t a3, int16x4_t c0, int16x4_t c1,
                 int16x4_t c2, int16x4_t c3, uint32x4_t* o) __attribute__((always_inline)) {
    // quarter q: v_j bx + v_j+1 fx (a: v_j, c: v_j+1 in every lane)
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 0), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a0, bx0), c0, fx0)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 1), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a1, bx1), c1, fx1)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 2), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a2, bx2), c2, fx2)));
    vst1q_u32(reinterpret_cast<uint32_t*>(o + 3), vreinterpretq_u32_s32(vmlal_s16(vmull_s16(a3, bx3), c3, fx3)));
  };
  for (int b = 0; b < n; ++b, g += gw, D += 4) {
    if constexpr (LB == 1) {  // lanes 2j, 2j + 1: (2 v_j, v_j + v_j+1) << 6
      const int16x8_t a = vreinterpretq_s16_u16(vsubq_u16(vld1q_u16(g + gw), vld1q_u16(g)));
      const int16x8_t c = vreinterpretq_s16_u16(vsubq_u16(vld1q_u16(g + gw + 1), vld1q_u16(g + 1)));
      const int16x8x2_t z = vzipq_s16(vshlq_n_s16(a, 1), vaddq_s16(a, c));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 0), vreinterpretq_u32_s32(vshll_n_s16(vget_low_s16(z.val[0]), 6)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 1), vreinterpretq_u32_s32(vshll_n_s16(vget_high_s16(z.val[0]), 6)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 2), vreinterpretq_u32_s32(vshll_n_s16(vget_low_s16(z.val[1]), 6)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 3), vreinterpretq_u32_s32(vshll_n_s16(vget_high_s16(z.val[1]), 6)));
    } else if constexpr (LB == 2) {  // quarter q: v_q, v_q+1
      const int16x4_t a = vreinterpret_s16_u16(vsub_u16(vld1_u16(g + gw), vld1_u16(g)));
      const int16x4_t c = vreinterpret_s16_u16(vsub_u16(vld1_u16(g + gw + 1), vld1_u16(g + 1)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 0),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx0, a, 0), fx0, c, 0)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 1),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx1, a, 1), fx1, c, 1)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 2),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx2, a, 2), fx2, c, 2)));
      vst1q_u32(reinterpret_cast<uint32_t*>(D + 3),
                vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(bx3, a, 3), fx3, c, 3)));
    } else {  // v_0 .. v_2 (mip 0: v_0, v_1) by scalar loads
      const int16x4_t v0 = vdup_n_s16(int16_t(g[gw] - g[0])), v1 = vdup_n_s16(int16_t(g[gw + 1] - g[1]));
      if constexpr (LB == 3) {
        const int16x4_t v2 = vdup_n_s16(int16_t(g[gw + 2] - g[2]));
        put(v0, v0, v1, v1, v1, v1, v2, v2, D);
      } else {
        put(v0, v0, v0, v0, v1, v1, v1, v1, D);
      }
    }
  }
}

// D[4 b .. 4 b + 3], b < n: the row step of the band between grid rows g + b gw and
// g + (b + 1) gw (a full group: its G + 1 entries inside each row), from the rows'
// difference (|difference| < 2^14); bxp, fxp: the row-step weights of the 16 lanes.
// Two bands a pass in assembly (d0-d7, d16-d31: no callee-saved registers to keep); over:
// bands whose four-entry reads (mips 0-1) stay inside the grid.
template <int LB>
__attribute__((noinline)) void band_deltas(const uint16_t* g, int gw, int n, int over, const uint16_t* bxp,
                                           const uint16_t* fxp, uint32x4_t* D) {
  if constexpr (LB == 1) {  // lanes 2j, 2j + 1: v_j << 7, (v_j + v_j+1) << 6, stored interleaved (vst2)
    if (n >= 2) {
      const uint16_t *g1 = g + gw, *g2 = g1 + gw, *h0 = g + 1, *h1 = g1 + 1, *h2 = g2 + 1;
      int k = n >> 1;
      asm volatile(
          "1:\n\t"
          "vld1.16 {d16-d17}, [%[g0]], %[st]\n\t"
          "vld1.16 {d18-d19}, [%[g1]], %[st]\n\t"
          "vld1.16 {d20-d21}, [%[g2]], %[st]\n\t"
          "vld1.16 {d22-d23}, [%[h0]], %[st]\n\t"
          "vld1.16 {d24-d25}, [%[h1]], %[st]\n\t"
          "vld1.16 {d26-d27}, [%[h2]], %[st]\n\t"
          "vsub.i16 q14, q9, q8\n\t"
          "vsub.i16 q15, q10, q9\n\t"
          "vsub.i16 q11, q12, q11\n\t"
          "vsub.i16 q12, q13, q12\n\t"
          "vadd.i16 q11, q11, q14\n\t"
          "vadd.i16 q12, q12, q15\n\t"
          "vshll.s16 q0, d28, #7\n\t"
          "vshll.s16 q1, d22, #6\n\t"
          "vshll.s16 q2, d29, #7\n\t"
          "vshll.s16 q3, d23, #6\n\t"
          "vshll.s16 q8, d30, #7\n\t"
          "vshll.s16 q9, d24, #6\n\t"
          "vshll.s16 q10, d31, #7\n\t"
          "vshll.s16 q11, d25, #6\n\t"
          "vst2.32 {d0-d3}, [%[D]:128]!\n\t"
          "vst2.32 {d4-d7}, [%[D]:128]!\n\t"
          "vst2.32 {d16-d19}, [%[D]:128]!\n\t"
          "vst2.32 {d20-d23}, [%[D]:128]!\n\t"
          "subs %[k], %[k], #1\n\t"
          "bne 1b\n\t"
          : [g0] "+r"(g), [g1] "+r"(g1), [g2] "+r"(g2), [h0] "+r"(h0), [h1] "+r"(h1), [h2] "+r"(h2), [D] "+r"(D),
            [k] "+r"(k)
          : [st] "r"(4 * gw)
          : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23",
            "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", "cc", "memory");
      n &= 1;
    }
  }
  if constexpr (LB == 2) {  // two bands a pass: quarter q from lane q of a (v_j) and c (v_j+1)
    if (n >= 2) {
      const uint16_t *g1 = g + gw, *g2 = g1 + gw, *h0 = g + 1, *h1 = g1 + 1, *h2 = g2 + 1;
      int k = n >> 1;
      asm volatile(
          "vld1.16 {d16-d19}, [%[bx]]\n\t"
          "vld1.16 {d20-d23}, [%[fx]]\n\t"
          "1:\n\t"
          "vld1.16 {d24}, [%[g0]], %[st]\n\t"
          "vld1.16 {d25}, [%[g1]], %[st]\n\t"
          "vld1.16 {d26}, [%[g2]], %[st]\n\t"
          "vld1.16 {d27}, [%[h0]], %[st]\n\t"
          "vld1.16 {d28}, [%[h1]], %[st]\n\t"
          "vld1.16 {d29}, [%[h2]], %[st]\n\t"
          "vsub.i16 d0, d25, d24\n\t"
          "vsub.i16 d2, d26, d25\n\t"
          "vsub.i16 d1, d28, d27\n\t"
          "vsub.i16 d3, d29, d28\n\t"
          "vmull.s16 q2, d16, d0[0]\n\t"
          "vmull.s16 q3, d17, d0[1]\n\t"
          "vmull.s16 q12, d18, d0[2]\n\t"
          "vmull.s16 q13, d19, d0[3]\n\t"
          "vmull.s16 q14, d16, d2[0]\n\t"
          "vmull.s16 q15, d17, d2[1]\n\t"
          "vmlal.s16 q2, d20, d1[0]\n\t"
          "vmlal.s16 q3, d21, d1[1]\n\t"
          "vmlal.s16 q12, d22, d1[2]\n\t"
          "vmlal.s16 q13, d23, d1[3]\n\t"
          "vmlal.s16 q14, d20, d3[0]\n\t"
          "vmlal.s16 q15, d21, d3[1]\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "vmull.s16 q2, d18, d2[2]\n\t"
          "vmull.s16 q3, d19, d2[3]\n\t"
          "vst1.32 {d24-d27}, [%[D]:128]!\n\t"
          "vmlal.s16 q2, d22, d3[2]\n\t"
          "vmlal.s16 q3, d23, d3[3]\n\t"
          "vst1.32 {d28-d31}, [%[D]:128]!\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "subs %[k], %[k], #1\n\t"
          "bne 1b\n\t"
          : [g0] "+r"(g), [g1] "+r"(g1), [g2] "+r"(g2), [h0] "+r"(h0), [h1] "+r"(h1), [h2] "+r"(h2), [D] "+r"(D),
            [k] "+r"(k)
          : [st] "r"(4 * gw), [bx] "r"(bxp), [fx] "r"(fxp)
          : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7",
            "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29",
            "d30", "d31", "cc", "memory");
      n &= 1;
    }
  }
  if constexpr (LB >= 3) {  // two bands a pass; reads four entries a row (up to two past the group's)
    const int pairs = (n < over ? n : over) >> 1;
    if (pairs > 0) {
      const uint16_t* g1 = g + gw;
      const uint16_t* g2 = g1 + gw;
      int k = pairs;
      asm volatile(
          "vld1.16 {d16-d19}, [%[bx]]\n\t"
          "vld1.16 {d20-d23}, [%[fx]]\n\t"
          "1:\n\t"
          "vld1.16 {d24}, [%[g0]], %[st]\n\t"
          "vld1.16 {d25}, [%[g1]], %[st]\n\t"
          "vld1.16 {d26}, [%[g2]], %[st]\n\t"
          "vsub.i16 d0, d25, d24\n\t"
          "vsub.i16 d1, d26, d25\n\t"
          "vmull.s16 q2, d16, d0[0]\n\t"
          "vmull.s16 q3, d17, d0[0]\n\t"
          "vmull.s16 q12, d18, d0[%c[la]]\n\t"
          "vmull.s16 q13, d19, d0[%c[la]]\n\t"
          "vmull.s16 q14, d16, d1[0]\n\t"
          "vmull.s16 q15, d17, d1[0]\n\t"
          "vmull.s16 q1, d18, d1[%c[la]]\n\t"
          "vmlal.s16 q2, d20, d0[1]\n\t"
          "vmlal.s16 q3, d21, d0[1]\n\t"
          "vmlal.s16 q12, d22, d0[%c[lc]]\n\t"
          "vmlal.s16 q13, d23, d0[%c[lc]]\n\t"
          "vmlal.s16 q14, d20, d1[1]\n\t"
          "vmlal.s16 q15, d21, d1[1]\n\t"
          "vmlal.s16 q1, d22, d1[%c[lc]]\n\t"
          "vst1.32 {d4-d7}, [%[D]:128]!\n\t"
          "vmull.s16 q2, d19, d1[%c[la]]\n\t"
          "vst1.32 {d24-d27}, [%[D]:128]!\n\t"
          "vmlal.s16 q2, d23, d1[%c[lc]]\n\t"
          "vst1.32 {d28-d31}, [%[D]:128]!\n\t"
          "vst1.32 {d2-d5}, [%[D]:128]!\n\t"
          "subs %[k], %[k], #1\n\t"
          "bne 1b\n\t"
          : [g0] "+r"(g), [g1] "+r"(g1), [g2] "+r"(g2), [D] "+r"(D), [k] "+r"(k)
          : [st] "r"(4 * gw), [bx] "r"(bxp), [fx] "r"(fxp), [la] "i"(LB == 3 ? 1 : 0), [lc] "i"(LB == 3 ? 2 : 1)
          : "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7",
            "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29",
            "d30", "d31", "cc", "memory");
      n -= 2 * pairs;
    }
  }
  if (n > 0) band_deltas_one<LB>(g, gw, n, bxp, fxp, D);
}
#endif

template <int kMip>
void surface_block_groups(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                          int toff, int width, int height, const uint8_t* __restrict colormap,
                          uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, G = 16 / B;
  const int bw = width / B, bh = height / B;
  const int n16 = (width + 15) & ~15, stride = n16 + 16, groups = n16 / 16;
  const int c0 = wrap(soff, tw), t0 = wrap(toff, th);
  alignas(16) uint8_t buf[kTileBytes];  // 64 KiB of stack
  const uint8_t* run[kMaxRuns];         // texel run of each row (cyclic, see below)
  const uint8_t* const tex_end = texels + tw * th;
  // Texture row t's run: in place when it needs no wrap (and 16-lane reads stay inside).
  auto in_place = [&](int t) { return c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end; };
  // Narrow textures (tw < 16): byte k of a run's first 32 is the row's byte (c0 + k) mod tw.
  uint8x16_t period[2];
  {
    uint8_t k8[32];
    for (int k = 0, c = c0; k < 32; ++k) {
      k8[k] = uint8_t(c);
      if (++c == tw) c = 0;
    }
    period[0] = vld1q_u8(k8);
    period[1] = vld1q_u8(k8 + 16);
  }
  // Rows repeat every th: when the texture is shorter than the surface and all its rows fit,
  // they are laid out once and the whole surface is one strip reading run[] cyclically from
  // t0. Else strips of as many bands as the buffer holds, their rows laid out per strip.
  const bool all_rows = th < height && th * stride <= kTileBytes && th <= kMaxRuns;
  if (all_rows)
    for (int t = 0; t < th; ++t)
      run[t] = in_place(t) ? texels + t * tw + c0 : (tile_row(buf + t * stride, texels + t * tw, tw, c0, n16, tex_end, period),
                                                     buf + t * stride);
  int strip_bands = bh;
  if (!all_rows) {
    const int fit = (kTileBytes / stride < kMaxRuns ? kTileBytes / stride : kMaxRuns) / B;  // >= 1
    strip_bands = fit < bh ? fit : bh;
  }

  // Per-lane weights (halves 0 and 1): (B - fx, fx) << (4 + mip) for the first numerator
  // (the scaled B T), << 2 mip for the row steps (U - T, then each next grid row's difference).
  uint16_t w[4][16];
  for (int k = 0; k < 16; ++k) {
    w[0][k] = uint16_t((B - k % B) << (4 + kMip));
    w[1][k] = uint16_t((k % B) << (4 + kMip));
    w[2][k] = uint16_t((B - k % B) << (2 * kMip));
    w[3][k] = uint16_t((k % B) << (2 * kMip));
  }
  const uint16x8_t BX0[2] = {vld1q_u16(w[0]), vld1q_u16(w[0] + 8)}, FX0[2] = {vld1q_u16(w[1]), vld1q_u16(w[1] + 8)};
  const uint16x8_t BX1[2] = {vld1q_u16(w[2]), vld1q_u16(w[2] + 8)}, FX1[2] = {vld1q_u16(w[3]), vld1q_u16(w[3] + 8)};
#if defined(__aarch64__)
  // Lanes 4j..4j+3: num >> 8 is (fraction, row, 0, 0) bytewise; its byte 0 becomes the texel.
  uint8x16_t IDX[4];
  for (int j = 0; j < 4; ++j) {
    uint8_t b[16];
    for (int l = 0; l < 4; ++l) {
      b[4 * l] = uint8_t(4 * j + l);
      b[4 * l + 1] = b[4 * l + 2] = b[4 * l + 3] = 0xff;
    }
    IDX[j] = vld1q_u8(b);
  }
#endif
  uint16_t pad[24];  // a last group's grid entries, zero padded (never read past a grid row)
#if !defined(__aarch64__)
  // ARMv7 full groups run a strip at a time in assembly: at most kStripBands bands, their
  // rows' texel runs (strip_rows, then srcs per group), first numerators and deltas (blk).
  constexpr int kStripBands = 32;
  if (strip_bands > kStripBands) strip_bands = kStripBands;
  const uint8_t* strip_rows[kStripBands * B + 4];
  alignas(64) const uint8_t* sbuf[16 + kStripBands * B + 8];
  alignas(16) uint32x4_t blk[8 + 4 * kStripBands];
#endif

  for (int by0 = 0; by0 < bh; by0 += strip_bands) {
    const int nb = bh - by0 < strip_bands ? bh - by0 : strip_bands;
    int first = 0, count = th;  // run[first] is the strip's first row; run[] wraps at count
    if (all_rows) {
      first = (t0 + by0 * B) % th;
    } else {
      count = nb * B;
      int t = (t0 + by0 * B) % th;
      for (int r = 0; r < count; ++r) {
        run[r] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + r * stride, texels + t * tw, tw, c0, n16, tex_end, period),
                                buf + r * stride);
        if (++t == th) t = 0;
      }
    }
    uint8_t* const strip = out + by0 * B * width;
#if !defined(__aarch64__)
    {  // the strip's rows in order, four past its end (read cyclically from run[first])
      const int n = nb * B + 4;
      for (int y = 0, k = first; y < n;) {
        const int m = count - k < n - y ? count - k : n - y;  // rows before run[] wraps
        int i = 0;
        for (; i + 4 <= m; i += 4)
          vst1q_u32(reinterpret_cast<uint32_t*>(strip_rows + y + i),
                    vld1q_u32(reinterpret_cast<const uint32_t*>(run + k + i)));
        for (; i < m; ++i) strip_rows[y + i] = run[k + i];
        y += m;
        k = 0;
      }
    }
#endif
    for (int g = 0; g < groups; ++g) {
      const int b0 = g * G;
      const bool direct = b0 + G + 1 <= grid_width;  // the group's G + 1 entries inside each row
      auto row_of = [&](int by) -> const uint16_t* {  // grid row by from the group's first block
        const uint16_t* r = grid + by * grid_width + b0;
        if (direct) return r;
        const int n = bw + 1 - b0;
        for (int k = 0; k < 24; ++k) pad[k] = k < n ? r[k] : 0;
        return pad;
      };
#if !defined(__aarch64__)
      if (width - 16 * g >= 16) {
        // Full groups: the whole strip in one assembly loop, two rows a pass. Row y: the step
        // to row y + 1 (numerators q4-q7 += the delta of row y's band, q8-q11), the scalar work
        // of row y (its indices moved from q12-q15 by vmov, colormap bytes, packed words, str:
        // the output has any alignment) interleaved with the NEON work of row y + 1 (16-bit
        // row << 8 | texel by vshrn and vsli, widened into q12-q15 once row y's are read).
        // The delta changes (the next 64 bytes at dp) at each band's first row: srcs[y] lies at
        // a multiple of 4 B bytes exactly then; a null srcs[y] ends the strip.
#define SB_ROW7 \
  "ldr r0, [%[sa]], #4\n\t" \
  "vmov r1, r2, d24\n\t" \
  "add %[d], %[d], %[st]\n\t" \
  "vmov r3, ip, d25\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  "vadd.i32 q4, q4, q8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vadd.i32 q5, q5, q9\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vadd.i32 q6, q6, q10\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vadd.i32 q7, q7, q11\n\t" \
  "orr r3, r3, ip, lsl #8\n\t" \
  "vmov r0, r2, d26\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "vmov ip, lr, d27\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "str r1, [%[d], #0]\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmov r1, r2, d28\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r3, lr, d29\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vsli.16 q0, q2, #8\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "str r0, [%[d], #4]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "str r1, [%[d], #8]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "str r0, [%[d], #12]\n\t"

        // Word-aligned output (the usual case): the same with strd (r8 holds a third word).
#define SB_ROW7A \
  "ldr r0, [%[sa]], #4\n\t" \
  "vmov r1, r2, d24\n\t" \
  "add %[d], %[d], %[st]\n\t" \
  "vmov r3, ip, d25\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  "vadd.i32 q4, q4, q8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vadd.i32 q5, q5, q9\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vadd.i32 q6, q6, q10\n\t" \
  "orr r1, r1, r2, lsl #8\n\t" \
  "vadd.i32 q7, q7, q11\n\t" \
  "orr r3, r3, ip, lsl #8\n\t" \
  "vmov r0, r2, d26\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "vmov ip, lr, d27\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r8, r2, d28\n\t" \
  "strd r1, r0, [%[d], #0]\n\t" \
  "vmov r3, lr, d29\n\t" \
  "ldrb r8, [%[cm], r8]\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vsli.16 q0, q2, #8\n\t" \
  "ldrb r3, [%[cm], r3]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "orr r8, r8, r2, lsl #8\n\t" \
  "vmov r0, r2, d30\n\t" \
  "orr r3, r3, lr, lsl #8\n\t" \
  "vmov ip, lr, d31\n\t" \
  "orr r8, r8, r3, lsl #16\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "ldrb r2, [%[cm], r2]\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "strd r8, r0, [%[d], #8]\n\t"
        // blk: the first row's numerators, then the bands' deltas (D[b]: band b, the step after
        // each of its rows).
        const uint16_t* const r0 = grid + by0 * grid_width + b0;
        first_numerators<LB>(r0, w[0], w[1], blk);
        // (mips 0-1 read four entries a row: past the grid only in its last row's last group)
        band_deltas<LB>(r0, grid_width, nb, b0 + 4 <= grid_width || by0 + nb < bh ? nb : nb - 1, w[2], w[3], blk + 4);
        const int rows = nb * B;
        // srcs[y] = row y + 1's texels (srcs[-1]: row 0; srcs[rows - 1]: a readable row past the
        // strip), then a null. srcs[y] lies at a multiple of 4 B bytes exactly when y % B == 0.
        const uint8_t** const srcs = sbuf + 16;
        {
          const uint32x4_t off = vdupq_n_u32(uint32_t(16 * g));
          const uint32_t* r = reinterpret_cast<const uint32_t*>(strip_rows);
          const uint32_t* const r_end = r + rows;
          uint32_t* o = reinterpret_cast<uint32_t*>(srcs - 1);
          do {
            vst1q_u32(o, vaddq_u32(vld1q_u32(r), off));
            r += 4, o += 4;
          } while (r <= r_end);
          srcs[rows] = nullptr;
        }
        uint8_t* d = strip + 16 * g;
        const uint8_t** sa = srcs;
        const uint32x4_t* dp = blk;
        // Prologue: row 0's indices (no step) and the first delta. The loop lies inside one
        // 512-byte block (no page crossing).
#define SB_STRIP7(ROW, TEST) \
  "sub %[d], %[d], %[st]\n\t" \
  "ldr r0, [%[sa], #-4]\n\t" \
  "vld1.32 {d8-d11}, [%[dp]:128]!\n\t" \
  "vld1.32 {d12-d15}, [%[dp]:128]!\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  "vld1.32 {d16-d19}, [%[dp]:128]!\n\t" \
  "vld1.32 {d20-d23}, [%[dp]:128]!\n\t" \
  "vsli.16 q0, q2, #8\n\t" \
  "vsli.16 q1, q3, #8\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "b 1f\n\t" \
  ".balign 512\n" \
  "1:\n\t" ROW ROW TEST \
  "ldr r0, [%[sa]]\n\t" \
  "cbz r0, 3f\n\t" \
  "vld1.32 {d16-d19}, [%[dp]:128]!\n\t" \
  "vld1.32 {d20-d23}, [%[dp]:128]!\n\t" \
  "b 1b\n\t" \
  "3:\n\t"
#define SB_STRIP7_OPS \
  : [sa] "+r"(sa), [d] "+r"(d), [dp] "+r"(dp) \
  : [cm] "r"(colormap), [st] "r"(width), [bm] "I"(4 * B - 1) \
  : "r0", "r1", "r2", "r3", "r8", "ip", "lr", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", \
  "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", \
  "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", \
  "cc", "memory"
        // Every pass ends a band when B = 2; else a band ends where srcs is 4 B-aligned.
#define SB_BAND_TEST "tst %[sa], %[bm]\n\tbne 1b\n\t"
        constexpr bool kPassIsBand = B == 2;
        if (((uintptr_t(d) | uintptr_t(width)) & 3) == 0) {
          if constexpr (kPassIsBand)
            asm volatile(SB_STRIP7(SB_ROW7A, "") SB_STRIP7_OPS);
          else
            asm volatile(SB_STRIP7(SB_ROW7A, SB_BAND_TEST) SB_STRIP7_OPS);
        } else {
          if constexpr (kPassIsBand)
            asm volatile(SB_STRIP7(SB_ROW7, "") SB_STRIP7_OPS);
          else
            asm volatile(SB_STRIP7(SB_ROW7, SB_BAND_TEST) SB_STRIP7_OPS);
        }
#undef SB_BAND_TEST
#undef SB_STRIP7
#undef SB_STRIP7_OPS
#undef SB_ROW7A
#undef SB_ROW7
        continue;
      }
#endif
      uint32x4_t num[4], delta[4], prev[4];
      {
        const uint16_t* r0 = row_of(by0);
        weigh<LB>(r0, BX0, FX0, num);
        weigh<LB>(r0, BX1, FX1, prev);
      }
      auto step_for = [&](int by) {  // delta = the band above grid row by's row step
        uint32x4_t next[4];
        weigh<LB>(row_of(by), BX1, FX1, next);
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          delta[j] = vsubq_u32(next[j], prev[j]);
          prev[j] = next[j];
        }
      };
      const int m = width - 16 * g;  // lanes on the surface (16 but in the last group)
      uint8_t* d = strip + 16 * g;
      int k = first;
      auto next_run = [&]() {
        const uint8_t* r = run[k];
        if (++k == count) k = 0;
        return r;
      };
      // Software-pipelined: row y + 1's indices are formed while row y's colormap loads are
      // in flight (after the strip's last row they are formed again from a readable row, unused).
      // step_for may run at any point of a row before the next row's indices: it changes only
      // the step that follows them.
#if defined(__aarch64__)
      // The rows' colormap indices travel as eight 64-bit index pairs P (lanes 2i, 2i + 1)
      // from one row to the next. Full groups run a band at a time in hand-scheduled assembly
      // (below); the last partial group of a row runs this C++ version.
      uint64_t P[8];
      auto indices = [&](const uint8_t* src) {  // P = the indices of the row at src
        const uint8x16_t t = vld1q_u8(src + 16 * g);
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          const uint64x2_t v =
              vreinterpretq_u64_u8(vqtbx1q_u8(vreinterpretq_u8_u32(vshrq_n_u32(num[j], 8)), t, IDX[j]));
          P[2 * j] = vgetq_lane_u64(v, 0);
          P[2 * j + 1] = vgetq_lane_u64(v, 1);
          num[j] = vaddq_u32(num[j], delta[j]);
        }
      };
      step_for(by0 + 1);
      indices(next_run());
      if (m >= 16) {
        // Each row: the scalar work of its pairs first (ALU and load/store only: the
        // colormap loads, packing, one stp), then the NEON work of the next row (ushr, tbx,
        // step, and the 64-bit moves into the pairs). An in-order core (Cortex-A53) never
        // waits on a NEON result inside a row, nor has a short instruction held behind a long
        // NEON one. x0-x7: pairs; x9-x16: high indices; x17: texel run; v16-v19: the step;
        // v20-v23: IDX; v27: texels; v28-v31: index vectors. A band's last row steps with the
        // next band's delta (dn).
#define SB_BLOCK_ROW \
  "orr x9, xzr, x0, lsr #32\n\t" \
  "orr x10, xzr, x1, lsr #32\n\t" \
  "orr x11, xzr, x2, lsr #32\n\t" \
  "orr x12, xzr, x3, lsr #32\n\t" \
  "orr x13, xzr, x4, lsr #32\n\t" \
  "ldr x17, [%[rp]], #8\n\t" \
  "orr x14, xzr, x5, lsr #32\n\t" \
  "ldrb w0, [%[cm], w0, uxtw]\n\t" \
  "orr x15, xzr, x6, lsr #32\n\t" \
  "ldrb w9, [%[cm], x9]\n\t" \
  "orr x16, xzr, x7, lsr #32\n\t" \
  "ldrb w1, [%[cm], w1, uxtw]\n\t" \
  "cmp %[rp], %[re]\n\t" \
  "ldrb w10, [%[cm], x10]\n\t" \
  "csel %[rp], %[rb], %[rp], eq\n\t" \
  "ldrb w2, [%[cm], w2, uxtw]\n\t" \
  "add x17, x17, %[goff]\n\t" \
  "ldrb w11, [%[cm], x11]\n\t" \
  "orr x0, x0, x9, lsl #8\n\t" \
  "ldrb w3, [%[cm], w3, uxtw]\n\t" \
  "orr x1, x1, x10, lsl #8\n\t" \
  "ldrb w12, [%[cm], x12]\n\t" \
  "ldr q27, [x17]\n\t" \
  "orr x2, x2, x11, lsl #8\n\t" \
  "ldrb w4, [%[cm], w4, uxtw]\n\t" \
  "orr x0, x0, x1, lsl #16\n\t" \
  "ldrb w13, [%[cm], x13]\n\t" \
  "orr x3, x3, x12, lsl #8\n\t" \
  "ldrb w5, [%[cm], w5, uxtw]\n\t" \
  "ldrb w14, [%[cm], x14]\n\t" \
  "orr x2, x2, x3, lsl #16\n\t" \
  "ldrb w6, [%[cm], w6, uxtw]\n\t" \
  "orr x4, x4, x13, lsl #8\n\t" \
  "ldrb w15, [%[cm], x15]\n\t" \
  "orr x5, x5, x14, lsl #8\n\t" \
  "ldrb w7, [%[cm], w7, uxtw]\n\t" \
  "orr x0, x0, x2, lsl #32\n\t" \
  "ldrb w16, [%[cm], x16]\n\t" \
  "orr x4, x4, x5, lsl #16\n\t" \
  "orr x6, x6, x15, lsl #8\n\t" \
  "orr x7, x7, x16, lsl #8\n\t" \
  "orr x6, x6, x7, lsl #16\n\t" \
  "orr x4, x4, x6, lsl #32\n\t" \
  "stp x0, x4, [%[d]]\n\t" \
  "add %[d], %[d], %[w]\n\t" \
  "ushr v28.4s, %[n0].4s, #8\n\t"                     \
  "ushr v29.4s, %[n1].4s, #8\n\t"                     \
  "ushr v30.4s, %[n2].4s, #8\n\t"                     \
  "ushr v31.4s, %[n3].4s, #8\n\t"                     \
  "add %[n0].4s, %[n0].4s, v16.4s\n\t"                \
  "add %[n1].4s, %[n1].4s, v17.4s\n\t"                \
  "tbx v28.16b, {v27.16b}, v20.16b\n\t"               \
  "tbx v29.16b, {v27.16b}, v21.16b\n\t"               \
  "add %[n2].4s, %[n2].4s, v18.4s\n\t"                \
  "add %[n3].4s, %[n3].4s, v19.4s\n\t"                \
  "tbx v30.16b, {v27.16b}, v22.16b\n\t"               \
  "tbx v31.16b, {v27.16b}, v23.16b\n\t"               \
  "fmov x0, d28\n\t"                                  \
  "mov x1, v28.d[1]\n\t"                              \
  "fmov x2, d29\n\t"                                  \
  "mov x3, v29.d[1]\n\t"                              \
  "fmov x4, d30\n\t"                                  \
  "mov x5, v30.d[1]\n\t"                              \
  "fmov x6, d31\n\t"                                  \
  "mov x7, v31.d[1]\n\t"
        const int64_t goff = 16 * g, wstride = width;
        for (int band = 0; band < nb; ++band) {
          uint32x4_t cur[4];
          for (int j = 0; j < 4; ++j) cur[j] = delta[j];
          if (band + 1 < nb) step_for(by0 + band + 2);  // delta = the next band's step
          const uint8_t* const* rp = run + k;
          int64_t rows = B - 1;
          asm volatile(
              "ldp x0, x1, [%[P]]\n\t"
              "ldp x2, x3, [%[P], #16]\n\t"
              "ldp x4, x5, [%[P], #32]\n\t"
              "ldp x6, x7, [%[P], #48]\n\t"
              "ldp q20, q21, [%[ix]]\n\t"
              "ldp q22, q23, [%[ix], #32]\n\t"
              "ldp q16, q17, [%[dl]]\n\t"
              "ldp q18, q19, [%[dl], #32]\n\t"
              "1:\n\t" SB_BLOCK_ROW
              "subs %[rows], %[rows], #1\n\t"
              "b.ne 1b\n\t"
              "ldp q16, q17, [%[dn]]\n\t"
              "ldp q18, q19, [%[dn], #32]\n\t" SB_BLOCK_ROW
              "stp x0, x1, [%[P]]\n\t"
              "stp x2, x3, [%[P], #16]\n\t"
              "stp x4, x5, [%[P], #32]\n\t"
              "stp x6, x7, [%[P], #48]\n\t"
              : [n0] "+w"(num[0]), [n1] "+w"(num[1]), [n2] "+w"(num[2]), [n3] "+w"(num[3]), [rp] "+r"(rp),
                [d] "+r"(d), [rows] "+r"(rows)
              : [P] "r"(P), [ix] "r"(IDX), [dl] "r"(cur), [dn] "r"(band + 1 < nb ? delta : cur),
                [rb] "r"(run), [re] "r"(run + count), [goff] "r"(goff), [cm] "r"(colormap), [w] "r"(wstride)
              : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x9", "x10", "x11", "x12", "x13", "x14", "x15",
                "x16", "x17", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v27", "v28", "v29", "v30",
                "v31", "cc", "memory");
          k = int(rp - run);
        }
#undef SB_BLOCK_ROW
        continue;
      }
      auto row = [&](bool band_end, int next_grid_row) __attribute__((always_inline)) {
        if (band_end) step_for(next_grid_row);
        uint64_t p[8];
        std::memcpy(p, P, sizeof p);
        indices(next_run());
        uint8_t wd[16];
        for (int i = 0; i < 8; ++i) {
          wd[2 * i] = colormap[uint32_t(p[i])];
          wd[2 * i + 1] = colormap[p[i] >> 32];
        }
        std::memcpy(d, wd, size_t(m));
        d += width;
      };
#else
      // Software-pipelined: row y + 1's indices are formed while row y's colormap loads are
      // in flight (after the strip's last row they are formed again from a readable row, unused).
      // ARMv7 (out-of-order Cortex-A9, few registers): row y + 1's 32-bit indices
      // row << 8 | texel (vsli of the row onto the widened texel) are stored to a small
      // aligned buffer while row y's colormap loads run from the previous one.
      alignas(16) uint32_t ib[2][16];
      int cur = 0;
      auto indices = [&](const uint8_t* src) {
        const uint8x16_t t = vld1q_u8(src + 16 * g);
        const uint16x8_t lo = vmovl_u8(vget_low_u8(t)), hi = vmovl_u8(vget_high_u8(t));
        const uint32x4_t t32[4] = {vmovl_u16(vget_low_u16(lo)), vmovl_u16(vget_high_u16(lo)),
                                   vmovl_u16(vget_low_u16(hi)), vmovl_u16(vget_high_u16(hi))};
        uint32_t* const o = ib[cur ^ 1];
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          vst1q_u32(o + 4 * j, vsliq_n_u32(t32[j], vshrq_n_u32(num[j], 16), 8));
          num[j] = vaddq_u32(num[j], delta[j]);
        }
        cur ^= 1;
      };
      step_for(by0 + 1);
      indices(next_run());
      auto row = [&](bool band_end, int next_grid_row) __attribute__((always_inline)) {
        if (band_end) step_for(next_grid_row);
        const uint32_t* const p = ib[cur];
        indices(next_run());
        uint32_t wd[4];
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j)
          wd[j] = uint32_t(colormap[p[4 * j]]) | uint32_t(colormap[p[4 * j + 1]]) << 8 |
                  uint32_t(colormap[p[4 * j + 2]]) << 16 | uint32_t(colormap[p[4 * j + 3]]) << 24;
        if (m >= 16) {
          std::memcpy(d, wd, 16);
        } else {
          std::memcpy(d, wd, size_t(m));
        }
        d += width;
      };
#endif
      for (int band = 0; band < nb; ++band) {
        for (int fy = 0; fy < B - 1; ++fy) row(false, 0);
        row(band + 1 < nb, by0 + band + 2);
      }
    }
  }
}

void surface_block_neon(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width, int tex_height,
                        int mip, int soff, int toff, int width, int height, const uint8_t* colormap, uint8_t* out) {
  if (width <= 0 || height <= 0) return;
  if (width / (16 >> mip) > kMaxBlockColumns || mip < 0 || mip > 3) {
    surface_block_scalar(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap,
                         out);
    return;
  }
  switch (mip) {
    case 0: return surface_block_groups<0>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 1: return surface_block_groups<1>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    case 2: return surface_block_groups<2>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    default: return surface_block_groups<3>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
  }
}

// ---------------------------------------------------------------- 3. z span

void z_span_neon(uint16_t* __restrict z, int n, uint32_t zi, uint32_t step) {
  int k = 0;
  if (n >= 8) {
    uint32x4_t z0 = lanes4(zi, step, 0);
    uint32x4_t z1 = vaddq_u32(z0, vdupq_n_u32(4 * step));
    const uint32x4_t s8 = vdupq_n_u32(8 * step);
    for (; k + 8 <= n; k += 8) {
      vst1q_u16(z + k, vcombine_u16(vshrn_n_u32(z0, 16), vshrn_n_u32(z1, 16)));
      z0 = vaddq_u32(z0, s8);
      z1 = vaddq_u32(z1, s8);
    }
    zi += uint32_t(k) * step;
  }
  for (; k < n; ++k) {
    z[k] = uint16_t(zi >> 16);
    zi += step;
  }
}

// ---------------------------------------------------------------- 4. palette expansion

void expand_palette_neon(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale) {
  const size_t row_bytes = size_t(width) * size_t(scale) * sizeof(uint32_t);
  for (int y = 0; y < height; ++y) {
    const uint8_t* s = src + y * src_stride;
    uint32_t* d = dst + ptrdiff_t(y) * scale * dst_stride;
    int x = 0;
    auto four = [&](int at) {
      uint32x4_t c = vdupq_n_u32(palette[s[at]]);
      c = vsetq_lane_u32(palette[s[at + 1]], c, 1);
      c = vsetq_lane_u32(palette[s[at + 2]], c, 2);
      return vsetq_lane_u32(palette[s[at + 3]], c, 3);
    };
    if (scale <= 4) {
      // vst2q/vst3q/vst4q of copies interleave: c0 c0 c1 c1 ..., c0 c0 c0 c1 ...
      for (; x + 4 <= width; x += 4) {
        const uint32x4_t c = four(x);
        uint32_t* p = d + x * scale;
        if (scale == 1) {
          vst1q_u32(p, c);
        } else if (scale == 2) {
          vst2q_u32(p, (uint32x4x2_t{{c, c}}));
        } else if (scale == 3) {
          vst3q_u32(p, (uint32x4x3_t{{c, c, c}}));
        } else {
          vst4q_u32(p, (uint32x4x4_t{{c, c, c, c}}));
        }
      }
    } else {
      const int q = (scale + 3) / 4;  // as in the SSE2 version: spills overwritten later
      for (; x * scale + 4 * q <= width * scale; ++x) {
        const uint32x4_t c = vdupq_n_u32(palette[s[x]]);
        uint32_t* p = d + x * scale;
        for (int i = 0; i < q; ++i) vst1q_u32(p + 4 * i, c);
      }
    }
    for (; x < width; ++x) {
      const uint32_t c = palette[s[x]];
      for (int i = 0; i < scale; ++i) d[x * scale + i] = c;
    }
    for (int j = 1; j < scale; ++j) std::memcpy(d + j * dst_stride, d, row_bytes);
  }
}

}  // namespace

const Kernels kNeon = {"neon", surface_span_fast, surface_block_neon, z_span_neon, expand_palette_neon, alias_span_neon,
                        surface_span_persp_fast};

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
