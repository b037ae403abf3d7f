// asm/neon_block_util.h: helpers of the NEON surface block builder on both ARM targets
// (asm/neon.cpp, section 2, describes the method): lane spreading and weighing of grid
// entries, and the texture layout (tiled rows of a wrapped texture). Only asm/neon.cpp
// includes this (the definitions are internal to it).
#pragma once
#include <arm_neon.h>

#include <cstdint>
#include <cstring>

#include "asm/variants.h"

namespace sb::simd::detail {
namespace {

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

#if defined(__aarch64__)
// dst[x] = row[x mod tw] for x < tw + 16 (tw a multiple of 16, > 16): the row, then its
// first 16 bytes again (reads only the row).
SB_TILE_INLINE void tile_row_u(uint8_t* dst, const uint8_t* row, int tw) {
  const uint8x16_t first = vld1q_u8(row);
  int x = 16;
  for (; x + 16 < tw; x += 32) {  // (two a step; tw / 16 - 1 copies)
    uint8x16_t a = vld1q_u8(row + x), b = vld1q_u8(row + x + 16);
    asm("" : "+w"(a), "+w"(b));  // (else GCC turns the loop back into a memcpy call)
    vst1q_u8(dst + x, a);
    vst1q_u8(dst + x + 16, b);
  }
  if (x < tw) vst1q_u8(dst + x, vld1q_u8(row + x));
  vst1q_u8(dst, first);
  vst1q_u8(dst + tw, first);
}
#endif

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
  const uint8_t** r = run;
  // Two rows a step (in-order cores: the second row's load and lookup overlap the first's).
  for (; r + 2 <= run + n; r += 2, row += 2 * tw, o += 32) {
    uint8x16_t a = vld1q_u8(row), b = vld1q_u8(row + tw);
    asm("" : "+w"(a), "+w"(b));  // (both loads first)
    vst1q_u8(o, vqtbl1q_u8(a, period));
    vst1q_u8(o + 16, vqtbl1q_u8(b, period));
    r[0] = o;
    r[1] = o + 16;
  }
  if (r != run + n) {
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

#if defined(__aarch64__)
// Bands 0..nb-1's grid differences e = row b + 1 - row b (rows at r + b gst bytes), 16 bytes
// a band at dt: lanes 0-3 e[0..3], lanes 4-7 e[1..4] (LB = 2: entries 0..4 read); LB = 3:
// lanes 0-1 e[0..1], 4-5 e[1..2] (entries 0..2); LB = 4: lanes 0-1 e[0..1] (entries 0..1).
// Lanes beyond those are zero. Reads only those entries of rows 0..nb (nb >= 1). Four bands
// an iteration (loads, then the subtractions, Cortex-A53 model: 26 cycles), then one at a time.
template <int LB>
inline void grid_row_diffs(const uint16_t* r, int64_t gst, int nb, uint32x4_t* dt) {
  constexpr int kHi = LB == 4 ? 0 : 2;  // entries 1.. (LB = 4: unused lanes, entry 0 again)
  const uint16_t* rh = r + kHi / 2;
  int64_t n4 = nb >> 2, n1 = nb & 3;
  const int64_t g2 = 2 * gst, g3 = 3 * gst, g4 = 4 * gst;
#define SB_GRD(T)                                                                        \
  asm volatile("ldr " T "0, [%[r]]\n\t"                                                   \
               "ldr " T "1, [%[rh]]\n\t"                                                  \
               "cbz %[n4], 2f\n"                                                         \
               "1:\n\t"                                                                  \
               "ldr " T "2, [%[r], %[g1]]\n\t"                                            \
               "ldr " T "3, [%[rh], %[g1]]\n\t"                                           \
               "ldr " T "4, [%[r], %[g2]]\n\t"                                            \
               "ldr " T "5, [%[rh], %[g2]]\n\t"                                           \
               "ldr " T "18, [%[r], %[g3]]\n\t"                                           \
               "ldr " T "19, [%[rh], %[g3]]\n\t"                                          \
               "ldr " T "20, [%[r], %[g4]]\n\t"                                           \
               "ldr " T "21, [%[rh], %[g4]]\n\t"                                          \
               "add %[r], %[r], %[g4]\n\t"                                               \
               "add %[rh], %[rh], %[g4]\n\t"                                             \
               "subs %[n4], %[n4], #1\n\t"                                               \
               "sub v6.4h, v2.4h, v0.4h\n\t"                                             \
               "sub v7.4h, v3.4h, v1.4h\n\t"                                             \
               "sub v16.4h, v4.4h, v2.4h\n\t"                                            \
               "sub v17.4h, v5.4h, v3.4h\n\t"                                            \
               "sub v22.4h, v18.4h, v4.4h\n\t"                                           \
               "sub v23.4h, v19.4h, v5.4h\n\t"                                           \
               "sub v24.4h, v20.4h, v18.4h\n\t"                                          \
               "sub v25.4h, v21.4h, v19.4h\n\t"                                          \
               "mov v0.8b, v20.8b\n\t"                                                   \
               "mov v1.8b, v21.8b\n\t"                                                   \
               "stp d6, d7, [%[dt]]\n\t"                                                 \
               "stp d16, d17, [%[dt], #16]\n\t"                                          \
               "stp d22, d23, [%[dt], #32]\n\t"                                          \
               "stp d24, d25, [%[dt], #48]\n\t"                                          \
               "add %[dt], %[dt], #64\n\t"                                               \
               "b.ne 1b\n"                                                               \
               "2:\n\t"                                                                  \
               "cbz %[n1], 4f\n"                                                         \
               "3:\n\t"                                                                  \
               "ldr " T "2, [%[r], %[g1]]\n\t"                                            \
               "ldr " T "3, [%[rh], %[g1]]\n\t"                                           \
               "add %[r], %[r], %[g1]\n\t"                                               \
               "add %[rh], %[rh], %[g1]\n\t"                                             \
               "subs %[n1], %[n1], #1\n\t"                                               \
               "sub v6.4h, v2.4h, v0.4h\n\t"                                             \
               "sub v7.4h, v3.4h, v1.4h\n\t"                                             \
               "mov v0.8b, v2.8b\n\t"                                                    \
               "mov v1.8b, v3.8b\n\t"                                                    \
               "stp d6, d7, [%[dt]], #16\n\t"                                            \
               "b.ne 3b\n"                                                               \
               "4:\n\t"                                                                  \
               : [r] "+r"(r), [rh] "+r"(rh), [dt] "+r"(dt), [n4] "+r"(n4), [n1] "+r"(n1)    \
               : [g1] "r"(gst), [g2] "r"(g2), [g3] "r"(g3), [g4] "r"(g4)                    \
               : "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "v17", "v18", "v19", \
                 "v20", "v21", "v22", "v23", "v24", "v25", "cc", "memory")
  if constexpr (LB == 2) {
    SB_GRD("d");
  } else {
    SB_GRD("s");
  }
#undef SB_GRD
}
#endif

}  // namespace
}  // namespace sb::simd::detail
