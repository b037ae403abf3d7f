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
// allocation cost 1.5-2x there); on ARMv7 row y's scalar work first, then row y + 1's NEON
// work, so an in-order core never waits on a NEON result; on AArch64 a whole strip per call,
// two rows per iteration (see there; mip 3 keeps n >> 6 in 16-bit lanes, weighed from the
// grid in the loop). The last, partial group of a row is C++.
// neon_a53 (kInOrder, for in-order cores: Cortex-A53/A35/A55) keeps the rest but runs its own
// row loops at mips 0-2: 16-bit indices, colormap bytes loaded straight into output lanes
// (see there); mip 3 runs the shared loop.
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

#define SB_TILE_INLINE inline __attribute__((always_inline))  // a call costs more than a row at mips 2-3
// dst[x] = row[(c0 + x) mod tw] for x < n (a multiple of 16); writes up to n + 15 (and at
// least 32 bytes must be writable).
SB_TILE_INLINE void tile_row(uint8_t* dst, const uint8_t* row, int tw, int c0, int n, const uint8_t* tex_end,
                             const uint8x16_t* period, [[maybe_unused]] const uint8_t* texels = nullptr) {
  int d;  // a period of the run, >= 16
  if (tw > 16) {
    const int a = tw - c0 < n ? tw - c0 : n, b = a < n ? (c0 < n - a ? c0 : n - a) : 0;
#if defined(__aarch64__)
    // 16-byte copies when their reads stay inside the texture (a library call per row costs
    // more than the row at the small mips).
    if (row + c0 + ((a + 15) & ~15) <= tex_end && row + ((b + 15) & ~15) <= tex_end) {
      for (int x = 0; x < a; x += 16) {
        uint8x16_t v = vld1q_u8(row + c0 + x);
        asm("" : "+w"(v));  // (else GCC turns the loop back into a memcpy call)
        vst1q_u8(dst + x, v);
      }
      for (int x = 0; x < b; x += 16) {
        uint8x16_t v = vld1q_u8(row + x);
        asm("" : "+w"(v));
        vst1q_u8(dst + a + x, v);
      }
    } else
#endif
    {
      std::memcpy(dst, row + c0, size_t(a));
      if (b) std::memcpy(dst + a, row, size_t(b));
    }
    d = tw;
  } else {
    d = tw;
    while (d < 16) d += tw;  // (no divide); at most 30
    if (row + 16 <= tex_end) {  // the first 32 bytes by two table lookups of the row
      const uint8x16_t v = vld1q_u8(row);
#if defined(__aarch64__)
      const uint8x16_t p0 = vqtbl1q_u8(v, period[0]);
#else
      uint8x8x2_t t;
      t.val[0] = vget_low_u8(v);
      t.val[1] = vget_high_u8(v);
      const uint8x16_t p0 = vcombine_u8(vtbl2_u8(t, vget_low_u8(period[0])), vtbl2_u8(t, vget_high_u8(period[0])));
#endif
      vst1q_u8(dst, p0);
      if (n <= 16) return;
#if defined(__aarch64__)
      vst1q_u8(dst + 16, vqtbl1q_u8(v, period[1]));
#else
      vst1q_u8(dst + 16, vcombine_u8(vtbl2_u8(t, vget_low_u8(period[1])), vtbl2_u8(t, vget_high_u8(period[1]))));
#endif
#if defined(__aarch64__)
      if (tw == 16) {  // (the same every 16 bytes)
        for (int x = 32; x < n; x += 16) vst1q_u8(dst + x, p0);
        return;
      }
      for (int x = 32; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
#else
      for (int x = 32; x < n; x += 16) vst1q_u8(dst + x, tw == 16 ? p0 : vld1q_u8(dst + x - d));  // (p0: every 16)
#endif
      return;
    }
    if (texels && tex_end - 16 >= texels) {  // the texture's last 16 bytes, indices moved up
      const uint8x16_t v = vld1q_u8(tex_end - 16), o = vdupq_n_u8(uint8_t(row - (tex_end - 16)));
#if defined(__aarch64__)
      vst1q_u8(dst, vqtbl1q_u8(v, vaddq_u8(period[0], o)));
      vst1q_u8(dst + 16, vqtbl1q_u8(v, vaddq_u8(period[1], o)));
#else
      uint8x8x2_t t;
      t.val[0] = vget_low_u8(v);
      t.val[1] = vget_high_u8(v);
      for (int h = 0; h < 2; ++h) {
        const uint8x16_t i = vaddq_u8(period[h], o);
        vst1q_u8(dst + 16 * h, vcombine_u8(vtbl2_u8(t, vget_low_u8(i)), vtbl2_u8(t, vget_high_u8(i))));
      }
#endif
      for (int x = 32; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
      return;
    }
    for (int k = 0, c = c0; k < d; ++k) {
      dst[k] = row[c];
      if (++c == tw) c = 0;
    }
  }
  int x = d;
#if defined(__aarch64__)
  if (d >= 32)  // 32 bytes a step (a step's loads never read its own stores)
    for (; x + 16 < n; x += 32) {
      const uint8x16_t v0 = vld1q_u8(dst + x - d), v1 = vld1q_u8(dst + x + 16 - d);
      vst1q_u8(dst + x, v0);
      vst1q_u8(dst + x + 16, v1);
    }
#endif
  for (; x < n; x += 16) vst1q_u8(dst + x, vld1q_u8(dst + x - d));
}

// Every row of a texture whose width divides 16, as far as a row's 16-byte read stays inside
// (ARMv7 with kTail, mip 3's narrow textures: every row when the texture has 16 bytes):
// run[t] = buf + 16 t, the row's bytes (c0 + k) mod tw (k < 16) by one lookup of period.
// Returns the rows done.
template <bool kTail>
SB_TILE_INLINE int tile_rows16(const uint8_t* texels, int tw, int th, uint8x16_t period, uint8_t* buf,
                               const uint8_t** run) {
  int n = th + 1 - (16 >> __builtin_ctz(unsigned(tw)));  // rows t: t tw + 16 <= th tw
  if (n < 0) n = 0;
#if defined(__aarch64__)
  const uint8_t* row = texels;
  uint8_t* o = buf;
  for (const uint8_t** r = run; r != run + n; ++r, row += tw, o += 16) {
    vst1q_u8(o, vqtbl1q_u8(vld1q_u8(row), period));
    *r = o;
  }
#else
  // (GCC copies the table pair a row; assembly keeps it in d16-d17.) The rows past n, when
  // the texture has 16 bytes, from its last 16 with the indices moved up (as tile_row).
  const bool tail = kTail && n < th && th * tw >= 16;
  if (n > 0 || tail) {
    const uint8_t* row = texels;
    uint8_t* o = buf;
    const uint8_t** r = run;
    const uint8_t** const r_end = run + n;
    const uint8_t** const r_tail = tail ? run + th : r_end;
    asm volatile(
        "vmov d20, %P[i0]\n\t"
        "vmov d21, %P[i1]\n\t"
        "cmp %[r], %[r_end]\n\t"
        "beq 2f\n"
        "1:\n\t"
        "vld1.8 {d16-d17}, [%[row]], %[tw]\n\t"
        "str %[o], [%[r]], #4\n\t"
        "vtbl.8 d18, {d16-d17}, d20\n\t"
        "vtbl.8 d19, {d16-d17}, d21\n\t"
        "cmp %[r], %[r_end]\n\t"
        "vst1.8 {d18-d19}, [%[o]:128]!\n\t"
        "bne 1b\n"
        "2:\n\t"
        "cmp %[r], %[r_tail]\n\t"
        "beq 4f\n\t"
        "sub %[row], %[row], %[end]\n\t"  // the first tail row's offset in the last 16 bytes
        "vld1.8 {d16-d17}, [%[end]]\n\t"
        "vdup.8 q11, %[tw]\n\t"
        "vdup.8 q9, %[row]\n\t"
        "vadd.i8 q10, q10, q9\n"
        "3:\n\t"
        "vtbl.8 d18, {d16-d17}, d20\n\t"
        "vtbl.8 d19, {d16-d17}, d21\n\t"
        "str %[o], [%[r]], #4\n\t"
        "vadd.i8 q10, q10, q11\n\t"
        "cmp %[r], %[r_tail]\n\t"
        "vst1.8 {d18-d19}, [%[o]:128]!\n\t"
        "bne 3b\n"
        "4:\n\t"
        : [row] "+r"(row), [o] "+r"(o), [r] "+r"(r)
        : [tw] "r"(tw), [r_end] "r"(r_end), [r_tail] "r"(r_tail), [end] "r"(texels + th * tw - 16),
          [i0] "w"(vget_low_u8(period)), [i1] "w"(vget_high_u8(period))
        : "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "cc", "memory");
    if (tail) n = th;
  }
#endif
  return n;
}

#if !defined(__aarch64__)
// kMod[t][x] = x mod t (t <= 16, x < 48): the narrow textures' periods.
struct ModTable {
  uint8_t m[17][48];
  constexpr ModTable() : m{} {
    for (int t = 1; t <= 16; ++t)
      for (int x = 0; x < 48; ++x) m[t][x] = uint8_t(x % t);
  }
};
constexpr ModTable kModTable{};
constexpr const uint8_t (&kMod)[17][48] = kModTable.m;
#endif

constexpr int kTileBytes = 16 * (kMaxBlockColumns * 16 + 32);  // B runs of the widest surface

constexpr int kMaxRuns = 2064;  // run pointers: >= kTileBytes / (smallest stride, 32)

#if defined(__aarch64__)
constexpr int kStripRows = 512;  // rows of a strip at most (aarch64: the assembly's row and step tables)
#endif

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
  if constexpr (LB == 1) {
    static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
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
    if constexpr (LB == 1) {
      static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
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
  static_assert(LB != 1, "mip 3 lays out grid rows instead (grid_rows3)");
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

// Mip 3 (B = 2): for up to ng full groups (as many as fit before tab_end; returns how many),
// grid rows r = 0..nb from g (group k's nine entries at g + 8 k), 32 bytes a row: the group's
// entries p_j and sums s_j = p_j + p_j+1 (j < 8, 16 bits), group after group. A band's lanes
// 2j, 2j + 1 have numerators 4 p_j, 2 s_j (row 0) and 2 (p_j + q_j), s_j + t_j (row 1; q, t:
// the next grid row's), each < 2^16 (entries < 2^14): the row is their bits 10-15 (see the
// strip's assembly).
__attribute__((noinline)) int grid_rows3(const uint16_t* g, int gw, int nb, int ng, uint8_t* tab,
                                         const uint8_t* tab_end) {
  int k = 0;
  for (; k < ng && tab + 32 * nb + 64 <= tab_end; ++k, g += 8) {  // (the strip reads a row past)
    const uint16_t *g0 = g, *g1 = g + 1;
    int n = nb - 1;  // rows 0..nb, two a pass
    asm volatile(
        "1:\n\t"
        "vld1.16 {d16-d17}, [%[g0]], %[st]\n\t"
        "vld1.16 {d18-d19}, [%[g1]], %[st]\n\t"
        "vld1.16 {d20-d21}, [%[g0]], %[st]\n\t"
        "vld1.16 {d22-d23}, [%[g1]], %[st]\n\t"
        "vadd.i16 q9, q8, q9\n\t"
        "vadd.i16 q11, q10, q11\n\t"
        "subs %[n], %[n], #2\n\t"
        "vst1.16 {d16-d19}, [%[o]:128]!\n\t"
        "vst1.16 {d20-d23}, [%[o]:128]!\n\t"
        "bge 1b\n\t"
        "cmn %[n], #1\n\t"
        "bne 2f\n\t"
        "vld1.16 {d16-d17}, [%[g0]]\n\t"
        "vld1.16 {d18-d19}, [%[g1]]\n\t"
        "vadd.i16 q9, q8, q9\n\t"
        "vst1.16 {d16-d19}, [%[o]:128]!\n"
        "2:\n\t"
        : [g0] "+r"(g0), [g1] "+r"(g1), [n] "+r"(n), [o] "+r"(tab)
        : [st] "r"(2 * gw)
        : "d16", "d17", "d18", "d19", "d20", "d21", "d22", "d23", "cc", "memory");
  }
  return k;
}
#endif

// Per-lane weights (see surface_block_groups), lanes k = 0..15 of a group.
template <int kMip>
struct BlockWeights {
  uint16_t w[4][16];
  constexpr BlockWeights() : w{} {
    constexpr int B = 16 >> kMip;
    for (int k = 0; k < 16; ++k) {
      w[0][k] = uint16_t((B - k % B) << (4 + kMip));
      w[1][k] = uint16_t((k % B) << (4 + kMip));
      w[2][k] = uint16_t((B - k % B) << (2 * kMip));
      w[3][k] = uint16_t((k % B) << (2 * kMip));
    }
  }
};
template <int kMip>
constexpr BlockWeights<kMip> kBlockWeights{};

#if defined(__aarch64__)

constexpr uint8_t kIota32[32] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15,
                                 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31};
// Lanes 4j..4j+3: num >> 8 is (fraction, row, 0, 0) bytewise; its byte 0 becomes the texel.
constexpr uint8_t kIdx[4][16] = {{0, 255, 255, 255, 1, 255, 255, 255, 2, 255, 255, 255, 3, 255, 255, 255},
                                 {4, 255, 255, 255, 5, 255, 255, 255, 6, 255, 255, 255, 7, 255, 255, 255},
                                 {8, 255, 255, 255, 9, 255, 255, 255, 10, 255, 255, 255, 11, 255, 255, 255},
                                 {12, 255, 255, 255, 13, 255, 255, 255, 14, 255, 255, 255, 15, 255, 255, 255}};
// The assembly's table lookups: lanes 4j..4j+3 of (texel, row, 0, 0) from the texel vector T
// and the numerators N0..N3 held as {N3, T, N0, N1, N2} in consecutive registers (row: a
// lane's byte 2). Quarters 0, 1, 3 read {T, N0}, {T, N0, N1}, {N3, T}; quarter 2 is N2 >> 8
// with the texels put in by kIdx[2] (a four-register lookup costs Cortex-A57/A72 9 uops, the
// pair 4; Cortex-A53 one instruction more). Row 2 here is unused.
constexpr uint8_t kTix[4][16] = {{0, 18, 255, 255, 1, 22, 255, 255, 2, 26, 255, 255, 3, 30, 255, 255},
                                 {4, 34, 255, 255, 5, 38, 255, 255, 6, 42, 255, 255, 7, 46, 255, 255},
                                 {8, 50, 255, 255, 9, 54, 255, 255, 10, 58, 255, 255, 11, 62, 255, 255},
                                 {28, 2, 255, 255, 29, 6, 255, 255, 30, 10, 255, 255, 31, 14, 255, 255}};
// The in-order variant's lookups (mips 0-1): 16-bit lanes texel | row << 8, lanes 0-7 from
// {T, N0, N1}, lanes 8-15 from {N2, N3, T} (row: byte 2 of a numerator lane).
constexpr uint8_t kTix16[2][16] = {{0, 18, 1, 22, 2, 26, 3, 30, 4, 34, 5, 38, 6, 42, 7, 46},
                                   {40, 2, 41, 6, 42, 10, 43, 14, 44, 18, 45, 22, 46, 26, 47, 30}};
#endif

// kInOrder: the row loops scheduled for in-order cores (surface_block_neon_inorder).
template <int kMip, bool kInOrder = false>
void surface_block_groups(const uint16_t* grid, int grid_width, const uint8_t* texels, int tw, int th, int soff,
                          int toff, int width, int height, const uint8_t* __restrict colormap,
                          uint8_t* __restrict out) {
  constexpr int B = 16 >> kMip, LB = 4 - kMip, G = 16 / B;
  const int bw = width / B, bh = height / B;
  const int n16 = (width + 15) & ~15, stride = n16 + 16, groups = n16 / 16;
  // (no divide for power-of-two sizes: Cortex-A9 has none, a library call)
  auto wrap2 = [](int i, int n) { return (n & (n - 1)) == 0 ? i & (n - 1) : wrap(i, n); };
  const int c0 = wrap2(soff, tw), t0 = wrap2(toff, th);
  alignas(16) uint8_t buf[kTileBytes];  // 64 KiB of stack
  const uint8_t* run[kMaxRuns + 3];     // texel run of each row (cyclic, see below; 3 read past)
  const uint8_t* const tex_end = texels + tw * th;
  // Texture row t's run: in place when it needs no wrap (and 16-lane reads stay inside).
  // Widths dividing 16: every 16 bytes of a run are its first 16, which every group reads (gs:
  // a group's offset step in a run); only they are laid out, none when the row is they.
  const bool p16 = tw <= 16 && (tw & (tw - 1)) == 0;
  const int gs = p16 ? 0 : 16, tile_n = p16 ? 16 : n16, wlim = p16 ? 16 : width;
  auto in_place = [&](int t) { return c0 + wlim <= tw && texels + t * tw + c0 + tile_n <= tex_end; };
  // Narrow textures (tw <= 16): byte k of a run's first 32 is the row's byte (c0 + k) mod tw.
  uint8x16_t period[2];
#if defined(__aarch64__)
  period[0] = period[1] = vdupq_n_u8(0);  // (unused when tw > 16)
  if (tw <= 16 && (tw & (tw - 1)) == 0) {  // x mod tw = x & (tw - 1)
    for (int h = 0; h < 2; ++h)
      period[h] = vandq_u8(vaddq_u8(vld1q_u8(kIota32 + 16 * h), vdupq_n_u8(uint8_t(c0))), vdupq_n_u8(uint8_t(tw - 1)));
  } else if (tw <= 16) {  // x mod tw = x - tw floor(x m / 2^16), m = ceil(2^16 / tw): exact for x = c0 + k < 47
    const uint16x8_t m = vdupq_n_u16(uint16_t((65536 + tw - 1) / tw)), twv = vdupq_n_u16(uint16_t(tw));
    for (int h = 0; h < 2; ++h) {
      const uint8x16_t x8 = vaddq_u8(vld1q_u8(kIota32 + 16 * h), vdupq_n_u8(uint8_t(c0)));
      uint16x8_t x[2] = {vmovl_u8(vget_low_u8(x8)), vmovl_high_u8(x8)};
      for (int i = 0; i < 2; ++i) {
        const uint16x8_t q = vuzp2q_u16(vreinterpretq_u16_u32(vmull_u16(vget_low_u16(x[i]), vget_low_u16(m))),
                                        vreinterpretq_u16_u32(vmull_high_u16(x[i], m)));
        x[i] = vmlsq_u16(x[i], q, twv);
      }
      period[h] = vuzp1q_u8(vreinterpretq_u8_u16(x[0]), vreinterpretq_u8_u16(x[1]));
    }
  }
#else
  if (tw <= 16) {
    period[0] = vld1q_u8(kMod[tw] + c0);
    period[1] = vld1q_u8(kMod[tw] + c0 + 16);
  } else {
    period[0] = period[1] = vdupq_n_u8(0);  // (unused)
  }
#endif
  // Rows repeat every th: when the texture is shorter than the surface and all its rows fit,
  // they are laid out once and the whole surface is one strip reading run[] cyclically from
  // t0. Else strips of as many bands as the buffer holds, their rows laid out per strip.
  const bool all_rows = th < height && th * stride <= kTileBytes && th <= kMaxRuns;
  if (all_rows) {
    if (p16) {  // (rows left over, at the texture's end, laid out past the table's: t stride >= 16 t)
      int t = in_place(0) ? 0 : tile_rows16<kMip == 3>(texels, tw, th, period[0], buf, run);
      for (; t < th; ++t)
        run[t] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + t * stride, texels + t * tw, tw, c0, 16, tex_end, period, texels),
                                buf + t * stride);
    } else {
      for (int t = 0; t < th; ++t)
        run[t] = c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end
                     ? texels + t * tw + c0
                     : (tile_row(buf + t * stride, texels + t * tw, tw, c0, n16, tex_end, period, texels),
                        buf + t * stride);
    }
  }
  int strip_bands = bh;
  if (!all_rows) {
    const int fit = (kTileBytes / stride < kMaxRuns ? kTileBytes / stride : kMaxRuns) / B;  // >= 1
    strip_bands = fit < bh ? fit : bh;
  }
#if defined(__aarch64__)
  if (strip_bands > kStripRows / B) strip_bands = kStripRows / B;  // the assembly's tables
#endif

  // Per-lane weights (halves 0 and 1): (B - fx, fx) << (4 + mip) for the first numerator
  // (the scaled B T), << 2 mip for the row steps (U - T, then each next grid row's difference).
  const auto& w = kBlockWeights<kMip>.w;  // (a table: setup counts at the small mips)
#if defined(__aarch64__)
  // (opaque: else GCC reloads the table's lanes inside the loops instead of keeping registers)
  auto ld = [](const uint16_t* p) {
    uint16x8_t v = vld1q_u16(p);
    asm("" : "+w"(v));
    return v;
  };
  const uint16x8_t BX0[2] = {ld(w[0]), ld(w[0] + 8)}, FX0[2] = {ld(w[1]), ld(w[1] + 8)};
  const uint16x8_t BX1[2] = {ld(w[2]), ld(w[2] + 8)}, FX1[2] = {ld(w[3]), ld(w[3] + 8)};
#endif
#if defined(__aarch64__)
  const uint8x16_t IDX[4] = {vld1q_u8(kIdx[0]), vld1q_u8(kIdx[1]), vld1q_u8(kIdx[2]), vld1q_u8(kIdx[3])};
  const uint8x16_t TIX[4] = {vld1q_u8(kTix[0]), vld1q_u8(kTix[1]), vld1q_u8(kIdx[2]), vld1q_u8(kTix[3])};
  const uint8_t* lin[kStripRows + 2 + 3];  // the strip's texel runs in row order, two rows beyond
  uint32x4_t dtab[(kStripRows / B + 1) * 4];  // each band's row step, one more (unused)
#endif
  uint16_t pad[24];  // a last group's grid entries, zero padded (never read past a grid row)
#if !defined(__aarch64__)
  // ARMv7 full groups run a strip at a time in assembly: at most kStripBands bands, their
  // rows' texel runs (strip_rows, then srcs per group), first numerators and deltas (blk;
  // mip 3: grid_rows3's rows of as many full groups as it holds).
  constexpr int kStripBands = 32;
  if (strip_bands > kStripBands) strip_bands = kStripBands;
  const uint8_t* strip_rows_buf[kStripBands * B + 8];
  alignas(64) const uint8_t* sbuf[16 + kStripBands * B + 8];
  // Mip 2: blk holds the numerators, the row-step weights w0 (B - fx), w1 (fx) of a quarter,
  // the group's first band in etab, then etab: row b (at b width bytes) the grid's band b
  // differences e, entries 0..4 F of the F full groups; group g weighs entries 4g..4g + 4 of
  // it (16 bytes read at 8g: inside the row). (A bigger frame leaves GCC no registers for the
  // strip's assembly.)
  constexpr int kEBytes = 4096;
  alignas(16) uint32x4_t blk[LB == 2 ? 6 + kEBytes / 16 : 8 + 4 * kStripBands];
  static_assert(sizeof blk >= 32 * kStripBands + 64, "mip 3: a group's grid rows fit blk");
  uint8_t* const etab = reinterpret_cast<uint8_t*>(blk + 6);
  if constexpr (LB == 2) {
    uint16_t w2[8];
    for (int k = 0; k < 4; ++k) w2[k] = w[2][k], w2[4 + k] = w[3][k];
    std::memcpy(blk + 4, w2, sizeof w2);
  }
  if (LB == 2 && strip_bands * width > kEBytes) strip_bands = kEBytes / width;  // (width <= 1024)
#endif

  for (int by0 = 0; by0 < bh; by0 += strip_bands) {
    const int nb = bh - by0 < strip_bands ? bh - by0 : strip_bands;
    int first = 0, count = th;  // run[first] is the strip's first row; run[] wraps at count
    if (all_rows) {
      first = t0 + by0 * B;
      if (first >= th) first = wrap2(first, th);
    } else {
      count = nb * B;
      int t = t0 + by0 * B;
      if (t >= th) t = wrap2(t, th);
      for (int r = 0; r < count; ++r) {
        run[r] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + r * stride, texels + t * tw, tw, c0, tile_n, tex_end, period, texels),
                                buf + r * stride);
        if (++t == th) t = 0;
      }
    }
#if defined(__aarch64__)
    {  // lin: the strip's runs, two rows beyond
      const int total = nb * B + 2;
      int r = 0;
      // (mip 3, the most rows per texel: one period, then copies of it)
      for (int t = first; r < total && (r < count || count < 4 || kMip != 3); t = 0) {  // run[] from first, cyclic
        const int n = count - t < total - r ? count - t : total - r;
        for (int i = 0; i < n; i += 4) {  // (up to 3 past n: the next piece overwrites them)
          uint64x2_t v0, v1;
          std::memcpy(&v0, run + t + i, sizeof v0);
          std::memcpy(&v1, run + t + i + 2, sizeof v1);
          asm("" : "+w"(v0), "+w"(v1));  // (else GCC makes this loop a memcpy call)
          std::memcpy(lin + r + i, &v0, sizeof v0);
          std::memcpy(lin + r + i + 2, &v1, sizeof v1);
        }
        r += n;
      }
      for (; r < total; r += 4) {  // (count >= 4: the reads precede the writes)
        uint64x2_t v0, v1;
        std::memcpy(&v0, lin + r - count, sizeof v0);
        std::memcpy(&v1, lin + r - count + 2, sizeof v1);
        asm("" : "+w"(v0), "+w"(v1));
        std::memcpy(lin + r, &v0, sizeof v0);
        std::memcpy(lin + r + 2, &v1, sizeof v1);
      }
    }
#endif
    uint8_t* const strip = out + by0 * B * width;
#if !defined(__aarch64__)
    // The strip's rows in order, four past its end (run[first..] cyclically, period count);
    // when gs = 0 they are every group's srcs (below) and go there directly.
    const uint8_t** const strip_rows = gs ? strip_rows_buf : sbuf + 15;
    {
      auto copy4 = [](const uint8_t** o, const uint8_t* const* r, int k) {  // (up to 3 past k)
        for (int i = 0; i < k; i += 4)
          vst1q_u32(reinterpret_cast<uint32_t*>(o + i), vld1q_u32(reinterpret_cast<const uint32_t*>(r + i)));
      };
      const int n = nb * B + 4, c = count < n ? count : n, m = count - first < c ? count - first : c;
      copy4(strip_rows, run + first, m);
      copy4(strip_rows + m, run, c - m);
      if (count >= 4) {
        for (int y = c; y < n; y += 4)
          vst1q_u32(reinterpret_cast<uint32_t*>(strip_rows + y),
                    vld1q_u32(reinterpret_cast<const uint32_t*>(strip_rows + y - count)));
      } else {
        for (int y = c; y < n; ++y) strip_rows[y] = strip_rows[y - count];
      }
      if (!gs) sbuf[16 + nb * B] = nullptr;
    }
    if (LB == 2 && width >= 16) {  // etab (see there): a column of eight entries (F = 1: four) at a time
      const int ne = 4 * (width >> 4) + 1;
      for (int i = 0;; i += 8) {  // the last column ends at entry 4 F
        const int j = ne < 8 ? i : i + 8 < ne ? i : ne - 8;
        const uint16_t* r = grid + by0 * grid_width + j;
        uint8_t* o = etab + 2 * j;
        if (ne < 8) {
          uint16x4_t p = vld1_u16(r);
          for (int b = 0; b < nb; ++b, o += width) {
            r += grid_width;
            const uint16x4_t q = vld1_u16(r);
            vst1_u16(reinterpret_cast<uint16_t*>(o), vsub_u16(q, p));
            p = q;
          }
          if (i == 1) break;
          i = 1 - 8;
          continue;
        }
        uint16x8_t p = vld1q_u16(r);
        const uint8_t* const o_end = o + nb * width;
        for (; o + width < o_end; o += 2 * width) {  // two bands a step (no register moves)
          const uint16x8_t q = vld1q_u16(r + grid_width);
          r += 2 * grid_width;
          vst1q_u16(reinterpret_cast<uint16_t*>(o), vsubq_u16(q, p));
          p = vld1q_u16(r);
          vst1q_u16(reinterpret_cast<uint16_t*>(o + width), vsubq_u16(p, q));
        }
        if (o != o_end) vst1q_u16(reinterpret_cast<uint16_t*>(o), vsubq_u16(vld1q_u16(r + grid_width), p));
        if (j != i) break;
      }
    }
#endif
#if !defined(__aarch64__)
    int rows3_left = 0;  // mip 3: groups left in blk (grid_rows3), rows3 the next's grid rows
    const uint32x4_t* rows3 = blk;
#endif
#if !defined(__aarch64__)
    int g = 0;
    for (; 16 * g + 16 <= width; ++g) {
      const int b0 = g * G;
      {
        // Full groups: the whole strip in one assembly loop, two rows a pass. Row y: the step
        // to row y + 1 (numerators q4-q7 += the delta of row y's band, q8-q11), the scalar work
        // of row y (its indices moved from q12-q15 by vmov, colormap bytes, packed words, str:
        // the output has any alignment) interleaved with the NEON work of row y + 1 (16-bit
        // row << 8 | texel by vshrn and vsli, widened into q12-q15 once row y's are read).
        // The delta changes (the next 64 bytes at dp) at each band's first row: srcs[y] lies at
        // a multiple of 4 B bytes exactly then; a null srcs[y] ends the strip.
// The first part of a row, the same for both output forms.
#define SB_ROW7_HEAD \
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
  "ldrb lr, [%[cm], lr]\n\t"
#define SB_ROW7 \
  SB_ROW7_HEAD \
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
  SB_ROW7_HEAD \
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
        if constexpr (LB == 1) {  // the grid rows of as many full groups as blk holds
          if (rows3_left == 0) {
            rows3_left = grid_rows3(r0, grid_width, nb, (width >> 4) - g, reinterpret_cast<uint8_t*>(blk),
                                    reinterpret_cast<const uint8_t*>(blk + sizeof blk / 16));
            rows3 = blk;
          } else {
            rows3 += 2 * (nb + 1);
          }
          --rows3_left;
        } else if constexpr (LB == 2) {
          first_numerators<LB>(r0, w[0], w[1], blk);
          const uint8_t* const ep = etab + 8 * g;
          std::memcpy(blk + 5, &ep, sizeof ep);
        } else {  // (mips 0-1 read four entries a row: past the grid only in its last row's last group)
          first_numerators<LB>(r0, w[0], w[1], blk);
          band_deltas<LB>(r0, grid_width, nb, b0 + 4 <= grid_width || by0 + nb < bh ? nb : nb - 1, w[2], w[3], blk + 4);
        }
        const int rows = nb * B;
        // srcs[y] = row y + 1's texels (srcs[-1]: row 0; srcs[rows - 1]: a readable row past the
        // strip), then a null. srcs[y] lies at a multiple of 4 B bytes exactly when y % B == 0.
        const uint8_t** const srcs = sbuf + 16;
        if (gs) {  // (gs = 0: every group's, laid out per strip)
          const uint32x4_t off = vdupq_n_u32(uint32_t(gs * g));
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
        const uint32x4_t* dp = LB == 1 ? rows3 : blk;
        // Prologue: row 0's indices (no step) and the first delta. The loop lies inside one
        // 512-byte block (no page crossing).
#define SB_STRIP7(ROW, TEST, PD, BD0, BD) \
  "sub %[d], %[d], %[st]\n\t" \
  "ldr r0, [%[sa], #-4]\n\t" \
  "vld1.32 {d8-d11}, [%[dp]:128]!\n\t" \
  "vld1.32 {d12-d15}, [%[dp]:128]!\n\t" \
  PD \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "vshrn.i32 d4, q4, #16\n\t" \
  "vshrn.i32 d5, q5, #16\n\t" \
  "vshrn.i32 d6, q6, #16\n\t" \
  "vshrn.i32 d7, q7, #16\n\t" \
  "vmovl.u8 q1, d1\n\t" \
  "vmovl.u8 q0, d0\n\t" \
  BD0 \
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
  BD \
  "b 1b\n\t" \
  "3:\n\t"
#define SB_STRIP7_OPS_(...) \
  : [sa] "+r"(sa), [d] "+r"(d), [dp] "+r"(dp) \
  : [cm] "r"(colormap), [st] "r"(width), [bm] "I"(4 * B - 1) __VA_ARGS__ \
  : "r0", "r1", "r2", "r3", "r8", "ip", "lr", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d8", "d9", \
  "d10", "d11", "d12", "d13", "d14", "d15", "d16", "d17", \
  "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", \
  "cc", "memory"
        // A band ends where srcs is 4 B-aligned.
#define SB_BAND_TEST "tst %[sa], %[bm]\n\tbne 1b\n\t"
        // The next band's delta (q8-q11): loaded; at mip 2 weighed from e, e1, w0, w1 (d0-d3,
        // free between rows): quarter j is w0 e[j] + w1 e1[j].
#define SB_LD_DELTA "vld1.32 {d16-d19}, [%[dp]:128]!\n\tvld1.32 {d20-d23}, [%[dp]:128]!\n\t"
        // (mip 2: after the numerators dp reads the weights, pushed on the stack for the loop as
        // no register is left, and the group's first band in etab; then a row of etab a band)
#define SB_EP2 \
  "vld1.16 {d2-d3}, [%[dp]:128]\n\t" \
  "ldr %[dp], [%[dp], #16]\n\t" \
  "sub sp, sp, #16\n\t" \
  "vst1.16 {d2-d3}, [sp]\n\t"
#define SB_DELTA2 \
  "vld1.8 {d0-d1}, [%[dp]], %[st]\n\t" \
  "vld1.16 {d2-d3}, [sp]\n\t" \
  "vmull.s16 q8, d2, d0[0]\n\t" \
  "vmull.s16 q9, d2, d0[1]\n\t" \
  "vmull.s16 q10, d2, d0[2]\n\t" \
  "vmull.s16 q11, d2, d0[3]\n\t" \
  "vmlal.s16 q8, d3, d0[1]\n\t" \
  "vmlal.s16 q9, d3, d0[2]\n\t" \
  "vmlal.s16 q10, d3, d0[3]\n\t" \
  "vmlal.s16 q11, d3, d1[0]\n\t"
        // Mip 3: a pass is a band. Row 0's colormap rows: vshr(s, 1) with its low byte replaced
        // (vsri) by p >> 8, i.e. 16-bit lanes (2 s >> 10) << 8 | 4 p >> 10; row 1's: vshr(s + t, 2)
        // with vhadd(p, q) >> 8 (p, s and q, t: grid_rows3's rows, in q10-q11 and q2-q3 by turns,
        // one loaded a pass; row 1's rows made in q8 during row 0's). Each zipped with the
        // texels into row << 8 | texel. Slots S1..S8 take the NEON work (x0: the next band's
        // row 0, x1: row 1), ZA or ZB the zip (the A9 model pairs them so).
#define SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "ldr r0, [%[sa]], #4\n\t" \
  "vmov r1, r2, d24\n\t" \
  "add %[d], %[d], %[st]\n\t" \
  "vmov r3, ip, d25\n\t" \
  "ldrb r1, [%[cm], r1]\n\t" \
  S1 \
  "ldrb r2, [%[cm], r2]\n\t" \
  S2 \
  "ldrb r3, [%[cm], r3]\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "ldrb ip, [%[cm], ip]\n\t" \
  S3 \
  "orr r1, r1, r2, lsl #8\n\t" \
  S4 \
  "orr r3, r3, ip, lsl #8\n\t" \
  "vmov r0, r2, d26\n\t" \
  "orr r1, r1, r3, lsl #16\n\t" \
  "vmov ip, lr, d27\n\t" \
  "ldrb r0, [%[cm], r0]\n\t" \
  S5 \
  "ldrb r2, [%[cm], r2]\n\t" \
  S6 \
  "ldrb ip, [%[cm], ip]\n\t" \
  "ldrb lr, [%[cm], lr]\n\t"
#define SB_ROW3A(S1, S2, S3, S4, S5, S6, S7, S8, ZA, ZB, DLO, DHI) \
  SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "orr r0, r0, r2, lsl #8\n\t" \
  S7 \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r8, r2, d28\n\t" \
  "strd r1, r0, [%[d], #0]\n\t" \
  "vmov r3, lr, d29\n\t" \
  ZA \
  "ldrb r8, [%[cm], r8]\n\t" \
  ZB \
  "ldrb r2, [%[cm], r2]\n\t" \
  S8 \
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
  "vmovl.u16 q14, " DLO "\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, " DHI "\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "strd r8, r0, [%[d], #8]\n\t"
#define SB_ROW3(S1, S2, S3, S4, S5, S6, S7, S8, ZA, ZB, DLO, DHI) \
  SB_ROW3_HEAD(S1, S2, S3, S4, S5, S6) \
  "str r1, [%[d], #0]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  S7 \
  "orr ip, ip, lr, lsl #8\n\t" \
  "vmov r1, r2, d28\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "vmov r3, lr, d29\n\t" \
  ZA \
  "ldrb r1, [%[cm], r1]\n\t" \
  ZB \
  "ldrb r2, [%[cm], r2]\n\t" \
  S8 \
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
  "vmovl.u16 q14, " DLO "\n\t" \
  "ldrb lr, [%[cm], lr]\n\t" \
  "vmovl.u16 q15, " DHI "\n\t" \
  "str r1, [%[d], #8]\n\t" \
  "orr r0, r0, r2, lsl #8\n\t" \
  "orr ip, ip, lr, lsl #8\n\t" \
  "orr r0, r0, ip, lsl #16\n\t" \
  "str r0, [%[d], #12]\n\t"
#define SB_X1 "", "", "", "", "", "", "", "", "", "vzip.8 q0, q8\n\t", "d16", "d17"
#define SB_X0A \
  "vld1.16 {d20-d23}, [%[dp]:128]!\n\t", "", "vshr.u16 q1, q3, #1\n\t", "vadd.i16 q8, q3, q11\n\t", \
  "vsri.16 q1, q2, #8\n\t", "vhadd.u16 q9, q2, q10\n\t", "vshr.u16 q8, q8, #2\n\t", "vsri.16 q8, q9, #8\n\t", \
  "vzip.8 q0, q1\n\t", "", "d2", "d3"
#define SB_X0B \
  "vld1.16 {d4-d7}, [%[dp]:128]!\n\t", "", "vshr.u16 q1, q11, #1\n\t", "vadd.i16 q8, q11, q3\n\t", \
  "vsri.16 q1, q10, #8\n\t", "vhadd.u16 q9, q10, q2\n\t", "vshr.u16 q8, q8, #2\n\t", "vsri.16 q8, q9, #8\n\t", \
  "vzip.8 q0, q1\n\t", "", "d2", "d3"
#define SB_CALL3(M, ...) M(__VA_ARGS__)
#define SB_STRIP3(ROW) \
  "sub %[d], %[d], %[st]\n\t" \
  "ldr r0, [%[sa], #-4]\n\t" \
  "vld1.16 {d20-d23}, [%[dp]:128]!\n\t" \
  "vld1.16 {d4-d7}, [%[dp]:128]!\n\t" \
  "vld1.8 {d0-d1}, [r0]\n\t" \
  "vshr.u16 q1, q11, #1\n\t" \
  "vadd.i16 q8, q11, q3\n\t" \
  "vhadd.u16 q9, q10, q2\n\t" \
  "vsri.16 q1, q10, #8\n\t" \
  "vshr.u16 q8, q8, #2\n\t" \
  "vzip.8 q0, q1\n\t" \
  "vsri.16 q8, q9, #8\n\t" \
  "vmovl.u16 q12, d0\n\t" \
  "vmovl.u16 q13, d1\n\t" \
  "vmovl.u16 q14, d2\n\t" \
  "vmovl.u16 q15, d3\n\t" \
  "b 1f\n\t" \
  ".balign 512\n" \
  "1:\n\t" SB_CALL3(ROW, SB_X1) SB_CALL3(ROW, SB_X0A) \
  "ldr r0, [%[sa]]\n\t" \
  "cmp r0, #0\n\t" \
  "beq 3f\n\t" \
  SB_CALL3(ROW, SB_X1) SB_CALL3(ROW, SB_X0B) \
  "ldr r0, [%[sa]]\n\t" \
  "cmp r0, #0\n\t" \
  "bne 1b\n" \
  "3:\n\t"
#define SB_STRIP3_OPS_ \
  : [sa] "+r"(sa), [d] "+r"(d), [dp] "+r"(dp) \
  : [cm] "r"(colormap), [st] "r"(width) \
  : "r0", "r1", "r2", "r3", "r8", "ip", "lr", "d0", "d1", "d2", "d3", "d4", "d5", "d6", "d7", "d16", "d17", \
    "d18", "d19", "d20", "d21", "d22", "d23", "d24", "d25", "d26", "d27", "d28", "d29", "d30", "d31", "cc", \
    "memory"
        constexpr bool kPassIsBand = B == 2;
        if (((uintptr_t(d) | uintptr_t(width)) & 3) == 0) {
          if constexpr (kPassIsBand)
            asm volatile(SB_STRIP3(SB_ROW3A) SB_STRIP3_OPS_);
          else if constexpr (LB == 2)
            asm volatile(SB_STRIP7(SB_ROW7A, SB_BAND_TEST, SB_EP2 SB_DELTA2, "", SB_DELTA2) "add sp, sp, #16\n\t" SB_STRIP7_OPS_());
          else
            asm volatile(SB_STRIP7(SB_ROW7A, SB_BAND_TEST, "", SB_LD_DELTA, SB_LD_DELTA) SB_STRIP7_OPS_());
        } else {
          if constexpr (kPassIsBand)
            asm volatile(SB_STRIP3(SB_ROW3) SB_STRIP3_OPS_);
          else if constexpr (LB == 2)
            asm volatile(SB_STRIP7(SB_ROW7, SB_BAND_TEST, SB_EP2 SB_DELTA2, "", SB_DELTA2) "add sp, sp, #16\n\t" SB_STRIP7_OPS_());
          else
            asm volatile(SB_STRIP7(SB_ROW7, SB_BAND_TEST, "", SB_LD_DELTA, SB_LD_DELTA) SB_STRIP7_OPS_());
        }
#undef SB_LD_DELTA
#undef SB_DELTA2
#undef SB_EP2
#undef SB_BAND_TEST
#undef SB_STRIP7
#undef SB_STRIP7_OPS_
#undef SB_ROW7A
#undef SB_ROW7
#undef SB_ROW7_HEAD
#undef SB_STRIP3
#undef SB_STRIP3_OPS_
#undef SB_ROW3A
#undef SB_ROW3
#undef SB_ROW3_HEAD
#undef SB_X0A
#undef SB_X0B
#undef SB_X1
#undef SB_CALL3
      }
    }
    for (; g < groups; ++g) {
#else
    for (int g = 0; g < groups; ++g) {
#endif
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
      // (ARMv7: the weights loaded here, for the last partial group only)
      const uint16x8_t BX0[2] = {vld1q_u16(w[0]), vld1q_u16(w[0] + 8)}, FX0[2] = {vld1q_u16(w[1]), vld1q_u16(w[1] + 8)};
      const uint16x8_t BX1[2] = {vld1q_u16(w[2]), vld1q_u16(w[2] + 8)}, FX1[2] = {vld1q_u16(w[3]), vld1q_u16(w[3] + 8)};
#endif
      uint32x4_t num[4], delta[4], prev[4];
#if defined(__aarch64__)
      const bool weighs = LB != 1 || width - 16 * g < 16;  // (mip 3's full groups weigh in their loop)
#else
      const bool weighs = true;
#endif
      if (weighs) {
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
        const uint8x16_t t = vld1q_u8(src + gs * g);
#pragma GCC unroll 4
        for (int j = 0; j < 4; ++j) {
          const uint64x2_t v =
              vreinterpretq_u64_u8(vqtbx1q_u8(vreinterpretq_u8_u32(vshrq_n_u32(num[j], 8)), t, IDX[j]));
          P[2 * j] = vgetq_lane_u64(v, 0);
          P[2 * j + 1] = vgetq_lane_u64(v, 1);
          num[j] = vaddq_u32(num[j], delta[j]);
        }
      };
      if (m >= 16) {
        // Full groups: the whole strip in assembly, two rows per iteration. Each iteration
        // first forms both rows' indices (table lookups or shift and lookup, steps, 64-bit
        // moves into x0-x7 and x19-x26) in one run of NEON instructions, then does their scalar
        // work (colormap loads, packing, stores) with the next iteration's texel rows (and
        // step) loaded in between: an in-order core (Cortex-A53) retires in order, so a NEON
        // instruction (6 cycles) holds the ALU and load instructions after it; one run per
        // iteration pays that once. The second row's store comes first in the next iteration.
        // v19-v23 / v24-v28: {N3, T, N0, N1, N2} of the even / odd row (the odd row's
        // numerators are the even row's plus the step); v16-v18, v29: the step; x8: texel run
        // (and step) addresses; x9-x12, x18 (and x30): high halves of the index pairs. The
        // scalar halves are ordered for llvm-mca's Cortex-A53 model (ALU before load in a cycle).
        // dtab entries a band (mip 2 and the in-order mips 0-1: e, e1 in 16-bit lanes)
        constexpr int kDs = LB == 2 || (kInOrder && LB >= 3) ? 1 : 4;
        constexpr int kDo = kInOrder && LB >= 3 ? 4 : 0;  // (in-order mips 0-1: the numerators first)
        if constexpr (LB == 1) {  // (mip 3: no table, see its loop)
        } else if (direct) {
          // Band b's step from the grid rows' differences e (|e| < 2^14): lanes
          // ((B - fx) e[blk] + fx e[blk + 1]) << 2 mip, as signed products (mod 2^32 they are
          // the difference of the two rows' weighed values).
          const int16x8_t W0 = vreinterpretq_s16_u16(BX1[0]), W0h = vreinterpretq_s16_u16(BX1[1]);
          const int16x8_t W1 = vreinterpretq_s16_u16(FX1[0]), W1h = vreinterpretq_s16_u16(FX1[1]);
          const int16x4_t w0[4] = {vget_low_s16(W0), vget_high_s16(W0), vget_low_s16(W0h), vget_high_s16(W0h)};
          const int16x4_t w1[4] = {vget_low_s16(W1), vget_high_s16(W1), vget_low_s16(W1h), vget_high_s16(W1h)};
          // Band b from grid rows b (p: entries 0.., p1: entries 1..) and b + 1 (q, q1). Two bands
          // a step with the rows' roles swapped (no register copies).
          auto band = [&](uint16x8_t p, uint16x8_t p1, uint16x8_t q, uint16x8_t q1, uint32x4_t* dt)
              __attribute__((always_inline)) {
            // e: lanes e[0..3], e1: e[1..4] (only those a group reads are loaded)
            const int16x4_t e = vreinterpret_s16_u16(vsub_u16(vget_low_u16(q), vget_low_u16(p)));
            const int16x4_t e1 = vreinterpret_s16_u16(vsub_u16(vget_low_u16(q1), vget_low_u16(p1)));
            if constexpr (LB == 2 || kInOrder) {  // e, e1 (16 bytes a band): the assembly weighs them
              vst1q_s16(reinterpret_cast<int16_t*>(dt), vcombine_s16(e, e1));
            } else if constexpr (LB == 3) {  // quarters 0-1: block 0, 2-3: block 1
              dt[0] = vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(w0[0], e, 0), w1[0], e1, 0));
              dt[1] = vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(w0[1], e, 0), w1[1], e1, 0));
              dt[2] = vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(w0[2], e, 1), w1[2], e1, 1));
              dt[3] = vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(w0[3], e, 1), w1[3], e1, 1));
            } else {  // one block: e[1] is e's lane 1
#pragma GCC unroll 4
              for (int j = 0; j < 4; ++j)
                dt[j] = vreinterpretq_u32_s32(vmlal_lane_s16(vmull_lane_s16(w0[j], e, 0), w1[j], e, 1));
            }
          };
          auto ldg = [](const uint16_t* p) {  // the group's entries p[0..G] a band reads
            if constexpr (LB == 2) {
              return vcombine_u16(vld1_u16(p), vdup_n_u16(0));
            } else {
              uint32_t x;
              std::memcpy(&x, p, sizeof x);
              return vreinterpretq_u16_u32(vdupq_n_u32(x));
            }
          };
          const uint16_t* r = grid + by0 * grid_width + b0;  // the next band's upper grid row
          uint16x8_t p = ldg(r), p1 = LB <= 3 ? ldg(r + 1) : p;
          uint32x4_t* dt = dtab + kDo;
          int b = 0;
#pragma GCC unroll 2
          for (; b + 2 <= nb; b += 2, dt += 2 * kDs) {
            r += grid_width;
            const uint16x8_t q = ldg(r), q1 = LB <= 3 ? ldg(r + 1) : q;
            band(p, p1, q, q1, dt);
            r += grid_width;
            p = ldg(r);
            p1 = LB <= 3 ? ldg(r + 1) : p;
            band(q, q1, p, p1, dt + kDs);
          }
          if (b < nb) {
            r += grid_width;
            const uint16x8_t q = ldg(r), q1 = LB <= 3 ? ldg(r + 1) : q;
            band(p, p1, q, q1, dt);
          }
        } else {
          for (int b = 0; b < nb; ++b) {
            if constexpr (LB == 2 || (kInOrder && LB >= 3)) {  // e, e1 as above, from the zero-padded rows
              uint16_t a[5];
              std::memcpy(a, row_of(by0 + b), sizeof a);
              const uint16_t* const c = row_of(by0 + b + 1);
              int16_t ee[8];
              for (int j = 0; j < 4; ++j) {
                ee[j] = int16_t(c[j] - a[j]);
                ee[4 + j] = int16_t(c[j + 1] - a[j + 1]);
              }
              std::memcpy(dtab + kDo + b, ee, sizeof ee);
              continue;
            }
            step_for(by0 + b + 1);
            for (int j = 0; j < 4; ++j) dtab[4 * b + j] = delta[j];
          }
        }
        if constexpr (LB != 1)
          for (int j = 0; j < 4; ++j) dtab[kDo + kDs * nb + j] = vdupq_n_u32(0);
  #define SB_PAIR_LOOP(T0, TOP, MID, A, E1, E2, E3, E4, BR) \
    "stp x19, x23, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "2:\n\t" T0 \
    "add v28.4s, v23.4s, v18.4s\n\t" \
    "ushr v2.4s, v23.4s, #8\n\t" \
    "add v26.4s, v21.4s, v16.4s\n\t" \
    "add v27.4s, v22.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v29.4s\n\t" \
    "tbl v0.16b, {v20.16b, v21.16b}, %[i0].16b\n\t" \
    "ushr v6.4s, v28.4s, #8\n\t" \
    "tbl v1.16b, {v20.16b, v21.16b, v22.16b}, %[i1].16b\n\t" \
    "tbx v2.16b, {v20.16b}, %[i2].16b\n\t" \
    "tbl v3.16b, {v19.16b, v20.16b}, %[i3].16b\n\t" \
    "tbl v4.16b, {v25.16b, v26.16b}, %[i0].16b\n\t" \
    "tbl v5.16b, {v25.16b, v26.16b, v27.16b}, %[i1].16b\n\t" \
    "tbx v6.16b, {v25.16b}, %[i2].16b\n\t" \
    "tbl v7.16b, {v24.16b, v25.16b}, %[i3].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x3, v1.d[1]\n\t" TOP \
    "fmov x4, d2\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "add v21.4s, v26.4s, v16.4s\n\t" \
    "add v22.4s, v27.4s, v17.4s\n\t" \
    "add v23.4s, v28.4s, v18.4s\n\t" \
    "add v19.4s, v24.4s, v29.4s\n\t" MID \
    "fmov x19, d4\n\t" \
    "fmov x20, v4.d[1]\n\t" \
    "fmov x21, d5\n\t" \
    "fmov x22, v5.d[1]\n\t" \
    "fmov x23, d6\n\t" \
    "fmov x24, v6.d[1]\n\t" \
    "fmov x25, d7\n\t" \
    "fmov x26, v7.d[1]\n\t" \
    "add x10, %[cm], x1, lsr #32\n\t" \
    "ldrb w1, [%[cm], w1, uxtw]\n\t" \
    "add x9, %[cm], x0, lsr #32\n\t" \
    "ldrb w0, [%[cm], w0, uxtw]\n\t" \
    "add x11, %[cm], x2, lsr #32\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x30, %[cm], x5, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x18, %[cm], x4, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x12, %[cm], x3, lsr #32\n\t" \
    "ldrb w4, [%[cm], w4, uxtw]\n\t" \
    "adds %[q], %[q], #2\n\t" \
    "ldrb w2, [%[cm], w2, uxtw]\n\t" \
    "orr x1, x1, x10, lsl #8\n\t" \
    "ldrb w3, [%[cm], w3, uxtw]\n\t" \
    "add x10, %[cm], x7, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x0, x0, x9, lsl #8\n\t" \
    "ldrb w30, [x30]\n\t" \
    "add x9, %[cm], x6, lsr #32\n\t" \
    "ldrb w7, [%[cm], w7, uxtw]\n\t" \
    "ldrb w6, [%[cm], w6, uxtw]\n\t" \
    "orr x4, x4, x18, lsl #8\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x18, %[cm], x23, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x0, x0, x1, lsl #16\n\t" \
    "ldrb w11, [x11]\n\t" \
    "ldrb w12, [x12]\n\t" \
    "orr x7, x7, x10, lsl #8\n\t" \
    "ldr q20, [x8, %[goff]]\n\t" \
    "orr x6, x6, x9, lsl #8\n\t" \
    "ldrb w5, [%[cm], w5, uxtw]\n\t" \
    "add x9, %[cm], x19, lsr #32\n\t" \
    "ldrb w19, [%[cm], w19, uxtw]\n\t" \
    "add x10, %[cm], x20, lsr #32\n\t" \
    "ldrb w20, [%[cm], w20, uxtw]\n\t" \
    "orr x3, x3, x12, lsl #8\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "orr x2, x2, x11, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x12, %[cm], x22, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "add x11, %[cm], x21, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x5, x5, x30, lsl #8\n\t" \
    "ldrb w23, [%[cm], w23, uxtw]\n\t" \
    "orr x19, x19, x9, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x9, %[cm], x25, lsr #32\n\t" \
    "ldrb w22, [%[cm], w22, uxtw]\n\t" \
    "add x30, %[cm], x24, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "orr x20, x20, x10, lsl #8\n\t" \
    "ldrb w24, [%[cm], w24, uxtw]\n\t" \
    "add x10, %[cm], x26, lsr #32\n\t" \
    "ldrb w25, [%[cm], w25, uxtw]\n\t" \
    "orr x6, x6, x7, lsl #16\n\t" \
    "ldrb w26, [%[cm], w26, uxtw]\n\t" \
    "orr x4, x4, x5, lsl #16\n\t" \
    "ldrb w30, [x30]\n\t" \
    "orr x2, x2, x3, lsl #16\n\t" \
    "ldrb w21, [%[cm], w21, uxtw]\n\t" \
    "orr x22, x22, x12, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x23, x23, x18, lsl #8\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x4, x4, x6, lsl #32\n\t" \
    "ldr q25, [x8, %[goff]]\n\t" \
    "orr x24, x24, x30, lsl #8\n\t" \
    "orr x21, x21, x11, lsl #8\n\t" \
    A \
    "orr x25, x25, x9, lsl #8\n\t" \
    "orr x26, x26, x10, lsl #8\n\t" \
    "orr x0, x0, x2, lsl #32\n\t" \
    "orr x23, x23, x24, lsl #16\n\t" \
    "orr x19, x19, x20, lsl #16\n\t" \
    E1 \
    "orr x21, x21, x22, lsl #16\n\t" \
    "orr x25, x25, x26, lsl #16\n\t" \
    "stp x0, x4, [%[d]]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "orr x19, x19, x21, lsl #32\n\t" \
    E2 \
    "orr x23, x23, x25, lsl #32\n\t" \
    E3 \
    E4 \
    BR
  #define SB_PAIR_LOOP_N \
    "stp x19, x23, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "2:\n\t" \
    "add v28.4s, v23.4s, v18.4s\n\t" \
    "ushr v2.4s, v23.4s, #8\n\t" \
    "add v26.4s, v21.4s, v16.4s\n\t" \
    "add v27.4s, v22.4s, v17.4s\n\t" \
    "add v24.4s, v19.4s, v29.4s\n\t" \
    "tbl v0.16b, {v20.16b, v21.16b}, %[i0].16b\n\t" \
    "ushr v6.4s, v28.4s, #8\n\t" \
    "tbl v1.16b, {v20.16b, v21.16b, v22.16b}, %[i1].16b\n\t" \
    "tbx v2.16b, {v20.16b}, %[i2].16b\n\t" \
    "tbl v3.16b, {v19.16b, v20.16b}, %[i3].16b\n\t" \
    "tbl v4.16b, {v25.16b, v26.16b}, %[i0].16b\n\t" \
    "tbl v5.16b, {v25.16b, v26.16b, v27.16b}, %[i1].16b\n\t" \
    "tbx v6.16b, {v25.16b}, %[i2].16b\n\t" \
    "tbl v7.16b, {v24.16b, v25.16b}, %[i3].16b\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "add v21.4s, v26.4s, v16.4s\n\t" \
    "add v22.4s, v27.4s, v17.4s\n\t" \
    "add v23.4s, v28.4s, v18.4s\n\t" \
    "add v19.4s, v24.4s, v29.4s\n\t" \
    "fmov x19, d4\n\t" \
    "fmov x20, v4.d[1]\n\t" \
    "fmov x21, d5\n\t" \
    "fmov x22, v5.d[1]\n\t" \
    "fmov x23, d6\n\t" \
    "fmov x24, v6.d[1]\n\t" \
    "fmov x25, d7\n\t" \
    "fmov x26, v7.d[1]\n\t" \
    "add x11, %[cm], x2, lsr #32\n\t" \
    "ldrb w2, [%[cm], w2, uxtw]\n\t" \
    "add x9, %[cm], x0, lsr #32\n\t" \
    "ldrb w0, [%[cm], w0, uxtw]\n\t" \
    "add x10, %[cm], x1, lsr #32\n\t" \
    "ldrb w1, [%[cm], w1, uxtw]\n\t" \
    "add x12, %[cm], x3, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x18, %[cm], x4, lsr #32\n\t" \
    "ldrb w9, [x9]\n\t" \
    "subs %[q], %[q], #1\n\t" \
    "ldrb w10, [x10]\n\t" \
    "ldrb w4, [%[cm], w4, uxtw]\n\t" \
    "orr x2, x2, x11, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x11, %[cm], x7, lsr #32\n\t" \
    "ldrb w7, [%[cm], w7, uxtw]\n\t" \
    "orr x1, x1, x10, lsl #8\n\t" \
    "ldrb w3, [%[cm], w3, uxtw]\n\t" \
    "orr x0, x0, x9, lsl #8\n\t" \
    "ldrb w18, [x18]\n\t" \
    "add x10, %[cm], x6, lsr #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x9, %[cm], x5, lsr #32\n\t" \
    "ldrb w6, [%[cm], w6, uxtw]\n\t" \
    "orr x3, x3, x12, lsl #8\n\t" \
    "ldrb w5, [%[cm], w5, uxtw]\n\t" \
    "add x12, %[cm], x22, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x4, x4, x18, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x7, x7, x11, lsl #8\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x11, %[cm], x21, lsr #32\n\t" \
    "ldrb w21, [%[cm], w21, uxtw]\n\t" \
    "orr x6, x6, x10, lsl #8\n\t" \
    "ldrb w12, [x12]\n\t" \
    "add x10, %[cm], x20, lsr #32\n\t" \
    "ldrb w20, [%[cm], w20, uxtw]\n\t" \
    "orr x5, x5, x9, lsl #8\n\t" \
    "ldrb w11, [x11]\n\t" \
    "add x9, %[cm], x19, lsr #32\n\t" \
    "ldrb w19, [%[cm], w19, uxtw]\n\t" \
    "add x18, %[cm], x23, lsr #32\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x0, x0, x1, lsl #16\n\t" \
    "ldrb w22, [%[cm], w22, uxtw]\n\t" \
    "orr x21, x21, x11, lsl #8\n\t" \
    "ldrb w9, [x9]\n\t" \
    "add x11, %[cm], x26, lsr #32\n\t" \
    "ldrb w18, [x18]\n\t" \
    "orr x20, x20, x10, lsl #8\n\t" \
    "ldrb w26, [%[cm], w26, uxtw]\n\t" \
    "add x10, %[cm], x25, lsr #32\n\t" \
    "ldrb w25, [%[cm], w25, uxtw]\n\t" \
    "orr x19, x19, x9, lsl #8\n\t" \
    "ldr q20, [x8, %[goff]]\n\t" \
    "add x9, %[cm], x24, lsr #32\n\t" \
    "ldrb w23, [%[cm], w23, uxtw]\n\t" \
    "orr x2, x2, x3, lsl #16\n\t" \
    "ldrb w24, [%[cm], w24, uxtw]\n\t" \
    "orr x4, x4, x5, lsl #16\n\t" \
    "ldrb w10, [x10]\n\t" \
    "orr x6, x6, x7, lsl #16\n\t" \
    "ldrb w9, [x9]\n\t" \
    "orr x0, x0, x2, lsl #32\n\t" \
    "ldrb w11, [x11]\n\t" \
    "orr x19, x19, x20, lsl #16\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "orr x25, x25, x10, lsl #8\n\t" \
    "orr x23, x23, x18, lsl #8\n\t" \
    "orr x24, x24, x9, lsl #8\n\t" \
    "orr x22, x22, x12, lsl #8\n\t" \
    "orr x4, x4, x6, lsl #32\n\t" \
    "orr x26, x26, x11, lsl #8\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ldr q25, [x8, %[goff]]\n\t" \
    "orr x21, x21, x22, lsl #16\n\t" \
    "orr x23, x23, x24, lsl #16\n\t" \
    "orr x25, x25, x26, lsl #16\n\t" \
    "stp x0, x4, [%[d]]\n\t" \
    "add %[d], %[d], %[w]\n\t" \
    "orr x19, x19, x21, lsl #32\n\t" \
    "orr x23, x23, x25, lsl #32\n\t" \
    "b.ne 1b\n\t"
        const int64_t goff = gs * g, wstride = width;
        const uint8_t* const* rp = lin;
        if constexpr (LB >= 3 && kInOrder) {
          // In-order cores (Cortex-A53 model): llvm-mca writes results back in program order, so
          // core instructions after a NEON one wait for it and the NEON run costs its length
          // in full; this loop keeps it short (20 instructions for two rows). The indices leave
          // as 16-bit lanes, four a 64-bit move (x0-x3 the even row, x4-x7 the odd one, texels
          // 4i..4i + 3 in xi). Each index becomes an address (cm + lane: uxth, and + add, or
          // lsr #48) and its colormap byte is loaded straight into an output lane (ld1 lane),
          // no packing: v4 / v5 the even row's bytes 0-7 / 8-15, v6 / v7 the odd row's, four
          // chains taken in turn (a lane load waits for the previous one into its register).
          // Rows are stored at the next iteration's start (d: the even row, x8: the odd).
          // Numerators {N2, N3, T, N0, N1}: v19-v23 (even row), v24-v28 (odd); steps v16-v18,
          // v29 as in the loop below; x26 = 0xffff. (Order from bench/mca_a53_block.)
#define SB_PAIR_LOOP_16 \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "2:\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "fmov x0, d0\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x6, d3\n\t" \
    "add x18, %[cm], w0, uxth\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "and x22, x26, x0, lsr #32\n\t" \
    "and x24, x26, x4, lsr #32\n\t" \
    "and x23, x26, x2, lsr #32\n\t" \
    "and x9, x26, x0, lsr #16\n\t" \
    "add x19, %[cm], w2, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x21, %[cm], w6, uxth\n\t" \
    "ld1 {v4.b}[0], [x18]\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "and x11, x26, x4, lsr #16\n\t" \
    "and x10, x26, x2, lsr #16\n\t" \
    "add x9, %[cm], x9\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "and x12, x26, x6, lsr #16\n\t" \
    "ld1 {v5.b}[0], [x19]\n\t" \
    "and x25, x26, x6, lsr #32\n\t" \
    "ld1 {v7.b}[0], [x21]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "add x10, %[cm], x10\n\t" \
    "add x12, %[cm], x12\n\t" \
    "add x11, %[cm], x11\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v5.b}[1], [x10]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v6.b}[1], [x11]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x12]\n\t" \
    "and x18, x26, x1, lsr #16\n\t" \
    "ld1 {v4.b}[2], [x22]\n\t" \
    "ld1 {v5.b}[2], [x23]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "and x20, x26, x5, lsr #16\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "and x24, x26, x5, lsr #32\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "and x21, x26, x7, lsr #16\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "and x19, x26, x3, lsr #16\n\t" \
    "and x22, x26, x1, lsr #32\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x19, %[cm], x19\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "add x21, %[cm], x21\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x18, %[cm], x18\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "and x23, x26, x3, lsr #32\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "add x20, %[cm], x20\n\t" \
    "ld1 {v5.b}[5], [x19]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "and x25, x26, x7, lsr #32\n\t" \
    "ld1 {v6.b}[5], [x20]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v4.b}[6], [x22]\n\t" \
    "ld1 {v5.b}[6], [x23]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v6.b}[6], [x24]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "subs %[q], %[q], #1\n\t" \
    "b.ne 1b\n\t"
// The band's last pair: the next band's step weighed after its NEON run from e, e1 (v8,
// loaded a band ahead at x30 + 32; lanes 0 / 4 for quarters 0-1, 0 / 4 (mip 0) or 1 / 5
// (mip 1) for quarters 2-3), then x30 moves to the next band's entry.
#define SB_PAIR_LOOP_16W0 \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "smull2 v29.4s, %[wb].8h, v8.h[0]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
    "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "smull v18.4s, %[wb].4h, v8.h[0]\n\t" \
    "fmov x4, d2\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "smlal2 v17.4s, %[wc].8h, v8.h[1]\n\t" \
    "smlal v16.4s, %[wc].4h, v8.h[1]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "smlal v18.4s, %[wd].4h, v8.h[1]\n\t" \
    "smlal2 v29.4s, %[wd].8h, v8.h[1]\n\t" \
    "and x9, x26, x0, lsr #16\n\t" \
    "and x11, x26, x4, lsr #16\n\t" \
    "add x19, %[cm], w2, uxth\n\t" \
    "and x23, x26, x2, lsr #32\n\t" \
    "add x18, %[cm], w0, uxth\n\t" \
    "and x22, x26, x0, lsr #32\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x21, %[cm], w6, uxth\n\t" \
    "ld1 {v5.b}[0], [x19]\n\t" \
    "and x10, x26, x2, lsr #16\n\t" \
    "ld1 {v4.b}[0], [x18]\n\t" \
    "and x24, x26, x4, lsr #32\n\t" \
    "and x25, x26, x6, lsr #32\n\t" \
    "add x9, %[cm], x9\n\t" \
    "add x11, %[cm], x11\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "add x10, %[cm], x10\n\t" \
    "and x12, x26, x6, lsr #16\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "mov %[q], %[hp1]\n\t" \
    "ld1 {v7.b}[0], [x21]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "add x12, %[cm], x12\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "ld1 {v5.b}[1], [x10]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[1], [x11]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x12]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v4.b}[2], [x22]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v5.b}[2], [x23]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "and x18, x26, x1, lsr #16\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "and x19, x26, x3, lsr #16\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "and x20, x26, x5, lsr #16\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "add x20, %[cm], x20\n\t" \
    "and x21, x26, x7, lsr #16\n\t" \
    "ldr q8, [x30, #32]\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x19, %[cm], x19\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "and x22, x26, x1, lsr #32\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "and x24, x26, x5, lsr #32\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x18, %[cm], x18\n\t" \
    "and x25, x26, x7, lsr #32\n\t" \
    "and x23, x26, x3, lsr #32\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "add x21, %[cm], x21\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x19]\n\t" \
    "add x30, x30, #16\n\t" \
    "add x25, %[cm], x25\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[5], [x20]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x22]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x23]\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "ld1 {v6.b}[6], [x24]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "cmp x30, %[ete]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "b.ne 1b\n\t"
#define SB_PAIR_LOOP_16W1 \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "smull2 v29.4s, %[wb].8h, v8.h[1]\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
    "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "smull v18.4s, %[wb].4h, v8.h[1]\n\t" \
    "fmov x4, d2\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "smlal2 v17.4s, %[wc].8h, v8.h[4]\n\t" \
    "smlal v16.4s, %[wc].4h, v8.h[4]\n\t" \
    "fmov x2, d1\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "smlal v18.4s, %[wd].4h, v8.h[5]\n\t" \
    "smlal2 v29.4s, %[wd].8h, v8.h[5]\n\t" \
    "and x9, x26, x0, lsr #16\n\t" \
    "and x11, x26, x4, lsr #16\n\t" \
    "add x19, %[cm], w2, uxth\n\t" \
    "and x23, x26, x2, lsr #32\n\t" \
    "add x18, %[cm], w0, uxth\n\t" \
    "and x22, x26, x0, lsr #32\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x21, %[cm], w6, uxth\n\t" \
    "ld1 {v5.b}[0], [x19]\n\t" \
    "and x10, x26, x2, lsr #16\n\t" \
    "ld1 {v4.b}[0], [x18]\n\t" \
    "and x24, x26, x4, lsr #32\n\t" \
    "and x25, x26, x6, lsr #32\n\t" \
    "add x9, %[cm], x9\n\t" \
    "add x11, %[cm], x11\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "add x10, %[cm], x10\n\t" \
    "and x12, x26, x6, lsr #16\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "mov %[q], %[hp1]\n\t" \
    "ld1 {v7.b}[0], [x21]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "add x12, %[cm], x12\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "ld1 {v5.b}[1], [x10]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[1], [x11]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ld1 {v7.b}[1], [x12]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v4.b}[2], [x22]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v5.b}[2], [x23]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "and x18, x26, x1, lsr #16\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "and x19, x26, x3, lsr #16\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "and x20, x26, x5, lsr #16\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "add x20, %[cm], x20\n\t" \
    "and x21, x26, x7, lsr #16\n\t" \
    "ldr q8, [x30, #32]\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "add x19, %[cm], x19\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "and x22, x26, x1, lsr #32\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "and x24, x26, x5, lsr #32\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x18, %[cm], x18\n\t" \
    "and x25, x26, x7, lsr #32\n\t" \
    "and x23, x26, x3, lsr #32\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "add x21, %[cm], x21\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[5], [x19]\n\t" \
    "add x30, x30, #16\n\t" \
    "add x25, %[cm], x25\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[5], [x20]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x22]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x23]\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "ld1 {v6.b}[6], [x24]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "cmp x30, %[ete]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "b.ne 1b\n\t"
#define SB_WEIGH01(L0, L1, L4) \
  "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
  "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
  "smull v18.4s, %[wb].4h, v8.h[" L0 "]\n\t" \
  "smull2 v29.4s, %[wb].8h, v8.h[" L0 "]\n\t" \
  "smlal v16.4s, %[wc].4h, v8.h[" L1 "]\n\t" \
  "smlal2 v17.4s, %[wc].8h, v8.h[" L1 "]\n\t" \
  "smlal v18.4s, %[wd].4h, v8.h[" L4 "]\n\t" \
  "smlal2 v29.4s, %[wd].8h, v8.h[" L4 "]\n\t"
// Bands of B / 2 pairs: B / 2 - 1 of SB_PAIR_LOOP_16 (q counts them), then the last one.
#define SB_INORDER01(LAST, L0, L1, L4) \
  "add x30, %[ete], %[q]\n\t" \
  "ldp q22, q23, [x30, #-64]\n\t" \
  "ldp q19, q20, [x30, #-32]\n\t" \
  "mov x26, #0xffff\n\t" \
  "sub %[d], %[d], %[w], lsl #1\n\t" \
  "ldr x8, [%[rp]]\n\t" \
  "ldr q21, [x8, %[goff]]\n\t" \
  "ldr x8, [%[rp], #8]\n\t" \
  "ldr q26, [x8, %[goff]]\n\t" \
  "add %[rp], %[rp], #16\n\t" \
  "ldr q8, [x30]\n\t" SB_WEIGH01(L0, L1, L4) \
  "ldr q8, [x30, #16]\n\t" \
  "mov %[q], %[hp1]\n\t" \
  "b 2f\n\t" \
  ".p2align 10\n\t" \
  "1:\n\t" SB_PAIR_LOOP_16 LAST \
  "stp d4, d5, [%[d]]\n\t" \
  "stp d6, d7, [x8]\n\t"
          const uint8x16_t J0 = vld1q_u8(kTix16[0]), J1 = vld1q_u8(kTix16[1]);
          const int16x8_t WA = vreinterpretq_s16_u16(BX1[0]), WB = vreinterpretq_s16_u16(BX1[1]);
          const int16x8_t WC = vreinterpretq_s16_u16(FX1[0]), WD = vreinterpretq_s16_u16(FX1[1]);
          // dtab: the numerators (64 bytes), then e, e1 of each band (x30: the band's).
          std::memcpy(dtab, num, sizeof num);
          const uint8_t* const ete = reinterpret_cast<const uint8_t*>(dtab + kDo + nb);
          int64_t q = -16 * int64_t(nb);
#define SB_INORDER01_OPERANDS \
  : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q) \
  : [cm] "r"(colormap), [w] "r"(wstride), [goff] "r"(goff), [ete] "r"(ete), [j0] "w"(J0), [j1] "w"(J1), \
    [wa] "w"(WA), [wb] "w"(WB), [wc] "w"(WC), [wd] "w"(WD), [hp1] "i"(B / 2 - 1) \
  : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20", "x21", \
    "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8", "v16", "v17", \
    "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc", "memory"
          if constexpr (LB == 4) {
            asm volatile(SB_INORDER01(SB_PAIR_LOOP_16W0, "0", "1", "1") SB_INORDER01_OPERANDS);
          } else {
            asm volatile(SB_INORDER01(SB_PAIR_LOOP_16W1, "1", "4", "5") SB_INORDER01_OPERANDS);
          }
#undef SB_INORDER01_OPERANDS
#undef SB_INORDER01
#undef SB_WEIGH01
#undef SB_PAIR_LOOP_16W0
#undef SB_PAIR_LOOP_16W1
#undef SB_PAIR_LOOP_16
        } else if constexpr (LB >= 3) {
          // Mips 0-1 (B / 2 >= 4 iterations a band): the band's step is loaded once, between
          // the bands (x30: its address), not in every iteration. q: iterations left in the band.
          int64_t q = -int64_t(nb) * 64;
          asm volatile(
              "mov v21.16b, %[n0].16b\n\t"
              "mov v22.16b, %[n1].16b\n\t"
              "mov v23.16b, %[n2].16b\n\t"
              "mov v19.16b, %[n3].16b\n\t"
              "ldr x8, [%[rp]]\n\t"
              "ldr q20, [x8, %[goff]]\n\t"
              "ldr x8, [%[rp], #8]\n\t"
              "ldr q25, [x8, %[goff]]\n\t"
              "add %[rp], %[rp], #16\n\t"
              "add x30, %[dte], %[q]\n\t"
              "ldp q16, q17, [x30]\n\t"
              "ldr q18, [x30, #32]\n\t"
              "ldr q29, [x30, #48]\n\t"
              "mov %[q], %[hp]\n\t"
              "b 2f\n\t"
              ".p2align 9\n\t"
              "1:\n\t" SB_PAIR_LOOP_N
              "add x30, x30, #64\n\t"
              "ldp q16, q17, [x30]\n\t"
              "ldr q18, [x30, #32]\n\t"
              "ldr q29, [x30, #48]\n\t"
              "mov %[q], %[hp]\n\t"
              "cmp x30, %[dte]\n\t"
              "b.ne 1b\n\t"
              "stp x19, x23, [%[d]]\n\t"
              "add %[d], %[d], %[w]\n\t"
              : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q)
              : [cm] "r"(colormap), [w] "r"(wstride), [goff] "r"(goff), [dte] "r"(dtab + 4 * nb), [i0] "w"(TIX[0]),
                [i1] "w"(TIX[1]), [i2] "w"(TIX[2]), [i3] "w"(TIX[3]), [n0] "w"(num[0]), [n1] "w"(num[1]),
                [n2] "w"(num[2]), [n3] "w"(num[3]), [hp] "i"(B / 2)
              : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20",
                "x21", "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16",
                "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc",
                "memory");
        } else if constexpr (LB == 2 && kInOrder) {
          // Mip 2, in-order cores: the loop above, a band (two pairs) an iteration as in the
          // mip 2 loop below: the first pair loads the next band's e, e1 (v8, at x30 + 16),
          // the second weighs them into the step after its last use of the current one.
#define SB_PAIR16_A \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "2:\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "fmov x0, d0\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x2, d1\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "fmov x4, d2\n\t" \
    "fmov x6, d3\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "add x19, %[cm], w2, uxth\n\t" \
    "add x18, %[cm], w0, uxth\n\t" \
    "and x12, x26, x6, lsr #16\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "and x9, x26, x0, lsr #16\n\t" \
    "and x11, x26, x4, lsr #16\n\t" \
    "and x10, x26, x2, lsr #16\n\t" \
    "ld1 {v4.b}[0], [x18]\n\t" \
    "add x21, %[cm], w6, uxth\n\t" \
    "ld1 {v5.b}[0], [x19]\n\t" \
    "and x23, x26, x2, lsr #32\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "add x10, %[cm], x10\n\t" \
    "and x22, x26, x0, lsr #32\n\t" \
    "and x24, x26, x4, lsr #32\n\t" \
    "add x9, %[cm], x9\n\t" \
    "add x30, %[dte], %[q], lsl #2\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "ld1 {v7.b}[0], [x21]\n\t" \
    "add x11, %[cm], x11\n\t" \
    "ld1 {v5.b}[1], [x10]\n\t" \
    "add x12, %[cm], x12\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "and x25, x26, x6, lsr #32\n\t" \
    "add x22, %[cm], x22\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[1], [x11]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v7.b}[1], [x12]\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x22]\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v5.b}[2], [x23]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "and x19, x26, x3, lsr #16\n\t" \
    "and x18, x26, x1, lsr #16\n\t" \
    "and x22, x26, x1, lsr #32\n\t" \
    "ldr q8, [x30, #16]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "and x20, x26, x5, lsr #16\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "and x21, x26, x7, lsr #16\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "and x24, x26, x5, lsr #32\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "add x18, %[cm], x18\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "and x23, x26, x3, lsr #32\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x21, %[cm], x21\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "add x19, %[cm], x19\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x20, %[cm], x20\n\t" \
    "and x25, x26, x7, lsr #32\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v6.b}[5], [x20]\n\t" \
    "ld1 {v5.b}[5], [x19]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "add x25, %[cm], x25\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "ld1 {v4.b}[6], [x22]\n\t" \
    "ld1 {v6.b}[6], [x24]\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x23]\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "b 3f\n\t" \
    "3:\n\t"
#define SB_PAIR16_B \
    "stp d4, d5, [%[d]]\n\t" \
    "stp d6, d7, [x8]\n\t" \
    "tbl v0.16b, {v21.16b, v22.16b, v23.16b}, %[j0].16b\n\t" \
    "tbl v1.16b, {v19.16b, v20.16b, v21.16b}, %[j1].16b\n\t" \
    "add v28.4s, v23.4s, v17.4s\n\t" \
    "add v27.4s, v22.4s, v16.4s\n\t" \
    "add v25.4s, v20.4s, v29.4s\n\t" \
    "add v24.4s, v19.4s, v18.4s\n\t" \
    "fmov x1, v0.d[1]\n\t" \
    "fmov x3, v1.d[1]\n\t" \
    "add v23.4s, v28.4s, v17.4s\n\t" \
    "add v22.4s, v27.4s, v16.4s\n\t" \
    "add v20.4s, v25.4s, v29.4s\n\t" \
    "smull v17.4s, %[wt].4h, v8.h[1]\n\t" \
    "fmov x0, d0\n\t" \
    "tbl v2.16b, {v26.16b, v27.16b, v28.16b}, %[j0].16b\n\t" \
    "tbl v3.16b, {v24.16b, v25.16b, v26.16b}, %[j1].16b\n\t" \
    "smull v29.4s, %[wt].4h, v8.h[3]\n\t" \
    "fmov x2, d1\n\t" \
    "smull v16.4s, %[wt].4h, v8.h[0]\n\t" \
    "add v19.4s, v24.4s, v18.4s\n\t" \
    "smull v18.4s, %[wt].4h, v8.h[2]\n\t" \
    "fmov x5, v2.d[1]\n\t" \
    "fmov x4, d2\n\t" \
    "smlal2 v29.4s, %[wt].8h, v8.h[7]\n\t" \
    "fmov x7, v3.d[1]\n\t" \
    "smlal2 v17.4s, %[wt].8h, v8.h[5]\n\t" \
    "fmov x6, d3\n\t" \
    "smlal2 v16.4s, %[wt].8h, v8.h[4]\n\t" \
    "smlal2 v18.4s, %[wt].8h, v8.h[6]\n\t" \
    "and x22, x26, x0, lsr #32\n\t" \
    "add x20, %[cm], w4, uxth\n\t" \
    "and x11, x26, x4, lsr #16\n\t" \
    "and x9, x26, x0, lsr #16\n\t" \
    "add %[d], %[d], %[w], lsl #1\n\t" \
    "add x18, %[cm], w0, uxth\n\t" \
    "add x19, %[cm], w2, uxth\n\t" \
    "and x10, x26, x2, lsr #16\n\t" \
    "add x21, %[cm], w6, uxth\n\t" \
    "ld1 {v6.b}[0], [x20]\n\t" \
    "and x24, x26, x4, lsr #32\n\t" \
    "ld1 {v4.b}[0], [x18]\n\t" \
    "add x9, %[cm], x9\n\t" \
    "ld1 {v5.b}[0], [x19]\n\t" \
    "and x12, x26, x6, lsr #16\n\t" \
    "add x11, %[cm], x11\n\t" \
    "and x23, x26, x2, lsr #32\n\t" \
    "ld1 {v7.b}[0], [x21]\n\t" \
    "add x10, %[cm], x10\n\t" \
    "and x25, x26, x6, lsr #32\n\t" \
    "add x12, %[cm], x12\n\t" \
    "ld1 {v4.b}[1], [x9]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v6.b}[1], [x11]\n\t" \
    "ld1 {v5.b}[1], [x10]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ldr x8, [%[rp]]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v7.b}[1], [x12]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "add x0, %[cm], x0, lsr #48\n\t" \
    "add x2, %[cm], x2, lsr #48\n\t" \
    "ld1 {v4.b}[2], [x22]\n\t" \
    "and x18, x26, x1, lsr #16\n\t" \
    "ld1 {v5.b}[2], [x23]\n\t" \
    "ld1 {v6.b}[2], [x24]\n\t" \
    "add x4, %[cm], x4, lsr #48\n\t" \
    "ld1 {v7.b}[2], [x25]\n\t" \
    "add x6, %[cm], x6, lsr #48\n\t" \
    "ld1 {v4.b}[3], [x0]\n\t" \
    "and x19, x26, x3, lsr #16\n\t" \
    "ld1 {v5.b}[3], [x2]\n\t" \
    "add x9, %[cm], w1, uxth\n\t" \
    "ld1 {v6.b}[3], [x4]\n\t" \
    "add x11, %[cm], w5, uxth\n\t" \
    "ld1 {v7.b}[3], [x6]\n\t" \
    "and x21, x26, x7, lsr #16\n\t" \
    "add x10, %[cm], w3, uxth\n\t" \
    "and x20, x26, x5, lsr #16\n\t" \
    "ldr q21, [x8, %[goff]]\n\t" \
    "and x22, x26, x1, lsr #32\n\t" \
    "ld1 {v4.b}[4], [x9]\n\t" \
    "add x12, %[cm], w7, uxth\n\t" \
    "ld1 {v5.b}[4], [x10]\n\t" \
    "and x23, x26, x3, lsr #32\n\t" \
    "add x18, %[cm], x18\n\t" \
    "add x21, %[cm], x21\n\t" \
    "ld1 {v6.b}[4], [x11]\n\t" \
    "add x19, %[cm], x19\n\t" \
    "ldr x8, [%[rp], #8]\n\t" \
    "and x24, x26, x5, lsr #32\n\t" \
    "add x20, %[cm], x20\n\t" \
    "and x25, x26, x7, lsr #32\n\t" \
    "ld1 {v4.b}[5], [x18]\n\t" \
    "add x22, %[cm], x22\n\t" \
    "ld1 {v7.b}[4], [x12]\n\t" \
    "add x23, %[cm], x23\n\t" \
    "ld1 {v5.b}[5], [x19]\n\t" \
    "add x24, %[cm], x24\n\t" \
    "ld1 {v6.b}[5], [x20]\n\t" \
    "add %[rp], %[rp], #16\n\t" \
    "ld1 {v4.b}[6], [x22]\n\t" \
    "add x25, %[cm], x25\n\t" \
    "ld1 {v7.b}[5], [x21]\n\t" \
    "add x1, %[cm], x1, lsr #48\n\t" \
    "add x5, %[cm], x5, lsr #48\n\t" \
    "add x7, %[cm], x7, lsr #48\n\t" \
    "ld1 {v5.b}[6], [x23]\n\t" \
    "ld1 {v6.b}[6], [x24]\n\t" \
    "add x3, %[cm], x3, lsr #48\n\t" \
    "ld1 {v7.b}[6], [x25]\n\t" \
    "ld1 {v4.b}[7], [x1]\n\t" \
    "ldr q26, [x8, %[goff]]\n\t" \
    "ld1 {v5.b}[7], [x3]\n\t" \
    "add x8, %[d], %[w]\n\t" \
    "ld1 {v7.b}[7], [x7]\n\t" \
    "ld1 {v6.b}[7], [x5]\n\t" \
    "adds %[q], %[q], #4\n\t" \
    "b.ne 1b\n\t"
#define SB_WEIGH_STEP8 \
  "smull v16.4s, %[wt].4h, v8.h[0]\n\t" \
  "smull v17.4s, %[wt].4h, v8.h[1]\n\t" \
  "smull v18.4s, %[wt].4h, v8.h[2]\n\t" \
  "smull v29.4s, %[wt].4h, v8.h[3]\n\t" \
  "smlal2 v16.4s, %[wt].8h, v8.h[4]\n\t" \
  "smlal2 v17.4s, %[wt].8h, v8.h[5]\n\t" \
  "smlal2 v18.4s, %[wt].8h, v8.h[6]\n\t" \
  "smlal2 v29.4s, %[wt].8h, v8.h[7]\n\t"
          const int16x8_t wt = vcombine_s16(vget_low_s16(vreinterpretq_s16_u16(BX1[0])),
                                            vget_low_s16(vreinterpretq_s16_u16(FX1[0])));
          const uint8x16_t J0 = vld1q_u8(kTix16[0]), J1 = vld1q_u8(kTix16[1]);
          int64_t q = -int64_t(nb) * B;
          asm volatile(
              "mov v22.16b, %[n0].16b\n\t"
              "mov v23.16b, %[n1].16b\n\t"
              "mov v19.16b, %[n2].16b\n\t"
              "mov v20.16b, %[n3].16b\n\t"
              "mov x26, #0xffff\n\t"
              "sub %[d], %[d], %[w], lsl #1\n\t"
              "ldr x8, [%[rp]]\n\t"
              "ldr q21, [x8, %[goff]]\n\t"
              "ldr x8, [%[rp], #8]\n\t"
              "ldr q26, [x8, %[goff]]\n\t"
              "add %[rp], %[rp], #16\n\t"
              "add x8, %[dte], %[q], lsl #2\n\t"
              "ldr q8, [x8]\n\t" SB_WEIGH_STEP8
              "b 2f\n\t"
              ".p2align 10\n\t"
              "1:\n\t" SB_PAIR16_A SB_PAIR16_B
              "stp d4, d5, [%[d]]\n\t"
              "stp d6, d7, [x8]\n\t"
              : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q)
              : [cm] "r"(colormap), [w] "r"(wstride), [goff] "r"(goff), [dte] "r"(dtab + nb), [j0] "w"(J0),
                [j1] "w"(J1), [n0] "w"(num[0]), [n1] "w"(num[1]), [n2] "w"(num[2]), [n3] "w"(num[3]), [wt] "w"(wt)
              : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20",
                "x21", "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8",
                "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc",
                "memory");
#undef SB_PAIR16_A
#undef SB_PAIR16_B
#undef SB_WEIGH_STEP8
        } else if constexpr (LB == 2) {
          // Mip 2: a band (two pairs of rows) an iteration, q counting -rows + 4 up to 0. The
          // band's step from its e, e1 (16 bytes at dte + 4 q): lanes of quarter j
          // (4 - fx) e[j] + fx e1[j], << 4 (wt: the weights, low half 4 - fx, high half fx).
          // The second pair computes the next band's (after its last use of the step). (The
          // branch between the pairs ends a translation block of the qemu block profiler
          // there, not inside the second pair's NEON run: its pieces are then one pair each.)
#define SB_WEIGH_STEP \
  "smull v16.4s, %[wt].4h, v0.h[0]\n\t" \
  "smull v17.4s, %[wt].4h, v0.h[1]\n\t" \
  "smull v18.4s, %[wt].4h, v0.h[2]\n\t" \
  "smull v29.4s, %[wt].4h, v0.h[3]\n\t" \
  "smlal2 v16.4s, %[wt].8h, v0.h[4]\n\t" \
  "smlal2 v17.4s, %[wt].8h, v0.h[5]\n\t" \
  "smlal2 v18.4s, %[wt].8h, v0.h[6]\n\t" \
  "smlal2 v29.4s, %[wt].8h, v0.h[7]\n\t"
          const int16x8_t wt = vcombine_s16(vget_low_s16(vreinterpretq_s16_u16(BX1[0])),
                                            vget_low_s16(vreinterpretq_s16_u16(FX1[0])));
          int64_t q = -int64_t(nb) * B;
          asm volatile(
              "mov v21.16b, %[n0].16b\n\t"
              "mov v22.16b, %[n1].16b\n\t"
              "mov v23.16b, %[n2].16b\n\t"
              "mov v19.16b, %[n3].16b\n\t"
              "ldr x8, [%[rp]]\n\t"
              "ldr q20, [x8, %[goff]]\n\t"
              "ldr x8, [%[rp], #8]\n\t"
              "ldr q25, [x8, %[goff]]\n\t"
              "add %[rp], %[rp], #16\n\t"
              "add x8, %[dte], %[q], lsl #2\n\t"
              "ldr q0, [x8]\n\t" SB_WEIGH_STEP
              "b 2f\n\t"
              ".p2align 10\n\t"  // (the loop, 1004 bytes, then never straddles a page)
              "1:\n\t" SB_PAIR_LOOP("", "", "", "", "", "", "", "", "b 3f\n3:\n\t")
              SB_PAIR_LOOP("", "add x9, %[dte], %[q], lsl #2\n\tldr q0, [x9, #8]\n\t", SB_WEIGH_STEP, "", "", "", "", "",
                           "b.ne 1b\n\t")
              "stp x19, x23, [%[d]]\n\t"
              "add %[d], %[d], %[w]\n\t"
              : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q)
              : [cm] "r"(colormap), [w] "r"(wstride), [goff] "r"(goff), [dte] "r"(dtab + nb), [i0] "w"(TIX[0]),
                [i1] "w"(TIX[1]), [i2] "w"(TIX[2]), [i3] "w"(TIX[3]), [n0] "w"(num[0]), [n1] "w"(num[1]),
                [n2] "w"(num[2]), [n3] "w"(num[3]), [wt] "w"(wt)
              : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20",
                "x21", "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16",
                "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc",
                "memory");
#undef SB_WEIGH_STEP
        } else {
          // Mip 3 (a band an iteration, no step table). A texel's light n >> 6 (< 2^16) in
          // 16-bit lanes, even texels (fx = 0) and odd ones (fx = 1) in separate vectors, so
          // the grid rows need no interleaving: T_b = (2 g_j, g_j + g_j+1) of grid row b (j the
          // block), the band's first row's light is 2 T_b, its second's T_b + T_b+1. Row
          // indices row << 8 | texel: the light shifted so that its high byte is the row
          // (T_b >> 1, (T_b + T_b+1) >> 2), the texel put in the low byte (bit: even texels;
          // sri: odd ones, of the 16-bit texel pairs); four to a 64-bit register, each
          // index taken out by ubfx or an extending add. Each iteration weighs grid row b + 2
          // (T_b+2, v28-v29) for the next, the read clamped to the strip's last row: gp (the
          // row after) compared with ge, one past that row: lo reads gp, ls continues the loop.
          // v18-v19: T_b (even, odd texels), v28-v29: T_b+1, v20 / v25: the rows' texels, v31:
          // 0x00ff lanes. The instruction order was searched against llvm-mca's Cortex-A53 model
          // (A57 no worse). A full group's G + 1 grid entries lie inside each row (grid_width >
          // width / B). The texel runs' group offset is added to lin once per group; without
          // one (gs = 0) the call runs all the full groups, their state on the stack: [sp] the
          // group's output, [sp, #8] groups left, [sp, #16] lin, [sp, #24] its grid row.
          if (gs && g)
            for (int i = 0; i < nb * B + 2; i += 2) {
              uint64x2_t v;
              std::memcpy(&v, lin + i, sizeof v);
              v = vaddq_u64(v, vdupq_n_u64(uint64_t(gs)));
              std::memcpy(lin + i, &v, sizeof v);
            }
          const uint16_t* gp = grid + by0 * grid_width + b0;
          const int64_t gst = 2 * int64_t(grid_width);
          uintptr_t ge = uintptr_t(gp) + uintptr_t(nb + 1) * uintptr_t(gst);  // past the strip's last row
          const int ng = gs ? 1 : (width >> 4) - g;  // full groups this call
          register int64_t left asm("x10") = ng;
          asm volatile(
              "sub sp, sp, #32\n\t"
              "stp %[d], x10, [sp]\n\t"
              "stp %[rp], %[gp], [sp, #16]\n\t"
              "3:\n\t"
              "ldr x8, [%[rp]]\n\t"
              "ldr x10, [%[rp], #8]\n\t"
              "add x9, %[gp], %[gst]\n\t"
              "ldr q26, [%[gp]]\n\t"
              "ldur q27, [%[gp], #2]\n\t"
              "ldr q0, [x9]\n\t"
              "ldur q1, [x9, #2]\n\t"
              "ldr q20, [x8]\n\t"
              "ldr q25, [x10]\n\t"
              "add %[gp], x9, %[gst]\n\t"
              "add %[rp], %[rp], #16\n\t"
              "cmp %[gp], %[ge]\n\t"
              "movi v31.8h, #0xff\n\t"
              "add v19.8h, v26.8h, v27.8h\n\t"
              "add v18.8h, v26.8h, v26.8h\n\t"
              "add v29.8h, v0.8h, v1.8h\n\t"
              "add v28.8h, v0.8h, v0.8h\n\t"
              "b 1f\n\t"
              ".p2align 10\n\t"  // (the loop, 520 bytes, then never straddles a page)
              "1:\n\t"
              "sub x9, %[gp], %[gst]\n\t"
              "csel x9, %[gp], x9, lo\n\t"
              "add v21.8h, v18.8h, v28.8h\n\t"
              "ushr v0.8h, v18.8h, #1\n\t"
              "add v22.8h, v19.8h, v29.8h\n\t"
              "ushr v1.8h, v19.8h, #1\n\t"
              "ldr q26, [x9]\n\t"
              "ldur q27, [x9, #2]\n\t"
              "ushr v2.8h, v21.8h, #2\n\t"
              "bit v0.16b, v20.16b, v31.16b\n\t"
              "ushr v3.8h, v22.8h, #2\n\t"
              "sri v1.8h, v20.8h, #8\n\t"
              "mov v18.16b, v28.16b\n\t"
              "add v28.8h, v26.8h, v26.8h\n\t"
              "bit v2.16b, v25.16b, v31.16b\n\t"
              "fmov x1, v0.d[1]\n\t"
              "sri v3.8h, v25.8h, #8\n\t"
              "fmov x2, d1\n\t"
              "mov v19.16b, v29.16b\n\t"
              "fmov x0, d0\n\t"
              "fmov x3, v1.d[1]\n\t"
              "fmov x4, d2\n\t"
              "fmov x6, d3\n\t"
              "add v29.8h, v26.8h, v27.8h\n\t"
              "fmov x5, v2.d[1]\n\t"
              "fmov x7, v3.d[1]\n\t"
              "ldr x8, [%[rp]]\n\t"
              "add %[gp], %[gp], %[gst]\n\t"
              "add x11, %[cm], x0, lsr #48\n\t"
              "ubfx x12, x2, #16, #16\n\t"
              "ubfx x18, x2, #32, #16\n\t"
              "ubfx x21, x4, #32, #16\n\t"
              "ubfx x24, x6, #32, #16\n\t"
              "ubfx x26, x1, #16, #16\n\t"
              "ubfx x9, x0, #16, #16\n\t"
              "ubfx x20, x4, #16, #16\n\t"
              "ubfx x10, x0, #32, #16\n\t"
              "ubfx x30, x1, #32, #16\n\t"
              "ubfx x23, x6, #16, #16\n\t"
              "ldrb w12, [%[cm], x12]\n\t"
              "add x19, %[cm], x2, lsr #48\n\t"
              "ldrb w18, [%[cm], x18]\n\t"
              "add x2, %[cm], w2, uxth\n\t"
              "ldrb w9, [%[cm], x9]\n\t"
              "add x22, %[cm], x4, lsr #48\n\t"
              "ldrb w10, [%[cm], x10]\n\t"
              "add x4, %[cm], w4, uxth\n\t"
              "ldrb w26, [%[cm], x26]\n\t"
              "add x0, %[cm], w0, uxth\n\t"
              "ldrb w2, [x2]\n\t"
              "ldrb w11, [x11]\n\t"
              "orr x9, x9, x12, lsl #8\n\t"
              "ldrb w19, [x19]\n\t"
              "cmp %[gp], %[ge]\n\t"
              "ldrb w0, [x0]\n\t"
              "add x25, %[cm], x6, lsr #48\n\t"
              "ldrb w4, [x4]\n\t"
              "orr x10, x10, x18, lsl #8\n\t"
              "ldrb w30, [%[cm], x30]\n\t"
              "orr x11, x11, x19, lsl #8\n\t"
              "ldrb w22, [x22]\n\t"
              "orr x0, x0, x2, lsl #8\n\t"
              "ldrb w25, [x25]\n\t"
              "orr x0, x0, x9, lsl #16\n\t"
              "ldrb w20, [%[cm], x20]\n\t"
              "add x12, %[cm], x3, lsr #48\n\t"
              "ldrb w23, [%[cm], x23]\n\t"
              "add x9, %[cm], x1, lsr #48\n\t"
              "ldrb w24, [%[cm], x24]\n\t"
              "ldrb w21, [%[cm], x21]\n\t"
              "add x6, %[cm], w6, uxth\n\t"
              "orr x10, x10, x11, lsl #16\n\t"
              "add x1, %[cm], w1, uxth\n\t"
              "ldrb w9, [x9]\n\t"
              "orr x0, x0, x10, lsl #32\n\t"
              "orr x22, x22, x25, lsl #8\n\t"
              "ubfx x18, x5, #16, #16\n\t"
              "ldrb w12, [x12]\n\t"
              "orr x21, x21, x24, lsl #8\n\t"
              "ldrb w6, [x6]\n\t"
              "orr x21, x21, x22, lsl #16\n\t"
              "orr x20, x20, x23, lsl #8\n\t"
              "ubfx x22, x7, #32, #16\n\t"
              "ubfx x19, x5, #32, #16\n\t"
              "ubfx x10, x3, #16, #16\n\t"
              "ubfx x11, x3, #32, #16\n\t"
              "add x23, %[cm], x7, lsr #48\n\t"
              "ldrb w19, [%[cm], x19]\n\t"
              "add x3, %[cm], w3, uxth\n\t"
              "ldrb w18, [%[cm], x18]\n\t"
              "orr x4, x4, x6, lsl #8\n\t"
              "ldrb w1, [x1]\n\t"
              "orr x4, x4, x20, lsl #16\n\t"
              "ldrb w11, [%[cm], x11]\n\t"
              "ldrb w3, [x3]\n\t"
              "add x20, %[cm], x5, lsr #48\n\t"
              "ldrb w23, [x23]\n\t"
              "orr x9, x9, x12, lsl #8\n\t"
              "ldr q20, [x8]\n\t"
              "orr x4, x4, x21, lsl #32\n\t"
              "add x5, %[cm], w5, uxth\n\t"
              "ubfx x21, x7, #16, #16\n\t"
              "ldrb w10, [%[cm], x10]\n\t"
              "add x7, %[cm], w7, uxth\n\t"
              "ldrb w20, [x20]\n\t"
              "orr x30, x30, x11, lsl #8\n\t"
              "ldrb w21, [%[cm], x21]\n\t"
              "orr x30, x30, x9, lsl #16\n\t"
              "ldrb w22, [%[cm], x22]\n\t"
              "orr x26, x26, x10, lsl #8\n\t"
              "ldrb w7, [x7]\n\t"
              "orr x1, x1, x3, lsl #8\n\t"
              "ldrb w5, [x5]\n\t"
              "orr x20, x20, x23, lsl #8\n\t"
              "orr x1, x1, x26, lsl #16\n\t"
              "orr x1, x1, x30, lsl #32\n\t"
              "orr x18, x18, x21, lsl #8\n\t"
              "orr x19, x19, x22, lsl #8\n\t"
              "ldr x8, [%[rp], #8]\n\t"
              "orr x19, x19, x20, lsl #16\n\t"
              "orr x5, x5, x7, lsl #8\n\t"
              "orr x5, x5, x18, lsl #16\n\t"
              "stp x0, x1, [%[d]]\n\t"
              "orr x5, x5, x19, lsl #32\n\t"
              "add %[d], %[d], %[w]\n\t"
              "ldr q25, [x8]\n\t"
              "stp x4, x5, [%[d]]\n\t"
              "add %[rp], %[rp], #16\n\t"
              "add %[d], %[d], %[w]\n\t"
              "b.ls 1b\n\t"
              "ldp %[d], x10, [sp]\n\t"
              "ldp %[rp], %[gp], [sp, #16]\n\t"
              "add %[d], %[d], #16\n\t"
              "add %[gp], %[gp], #16\n\t"
              "add %[ge], %[ge], #16\n\t"
              "subs x10, x10, #1\n\t"
              "stp %[d], x10, [sp]\n\t"
              "str %[gp], [sp, #24]\n\t"
              "b.ne 3b\n\t"
              "add sp, sp, #32\n\t"
              : [d] "+r"(d), [rp] "+r"(rp), [gp] "+r"(gp), [ge] "+r"(ge), "+r"(left)
              : [cm] "r"(colormap), [w] "r"(wstride), [gst] "r"(gst)
              : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x11", "x12", "x18", "x19", "x20",
                "x21", "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v18", "v19", "v20", "v21",
                "v22", "v25", "v26", "v27", "v28", "v29", "v31", "cc", "memory");
          g += ng - 1;
        }
#undef SB_PAIR_LOOP
#undef SB_PAIR_LOOP_N
        continue;
      }
      step_for(by0 + 1);
      indices(next_run());
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
        const uint8x16_t t = vld1q_u8(src + gs * g);
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

#if defined(__aarch64__)
// The in-order variant (Cortex-A53/A55/A35): its own row loops at every mip.
void surface_block_neon_inorder(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width,
                                int tex_height, int mip, int soff, int toff, int width, int height,
                                const uint8_t* colormap, uint8_t* out) {
  if (width > 0 && height > 0 && mip >= 0 && mip <= 3 && width / (16 >> mip) <= kMaxBlockColumns) {
    if (mip == 0)
      return surface_block_groups<0, true>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height,
                                           colormap, out);
    if (mip == 1)
      return surface_block_groups<1, true>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height,
                                           colormap, out);
    if (mip == 2)
      return surface_block_groups<2, true>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height,
                                           colormap, out);
    return surface_block_groups<3, true>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height,
                                         colormap, out);
  }
  surface_block_neon(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap, out);
}
#endif

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
#if defined(__aarch64__)
const Kernels kNeonInOrder = {"neon_a53", surface_span_fast, surface_block_neon_inorder, z_span_neon,
                              expand_palette_neon, alias_span_neon, surface_span_persp_fast};
#endif

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
