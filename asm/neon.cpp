// asm/neon.cpp: NEON variants for aarch64 and for armv7 with NEON (armhf: this file alone
// is compiled with -mfpu=neon when STARBOW_ARM_NEON is on; see asm/CMakeLists.txt).
// NEON has no gather: the lanes' coordinates, light and addresses are computed in vectors,
// the texel and colormap loads are scalar, and stores are vector where the output is.
//
// Sections: 1. surface span  2. surface block builder  3. z span  4. palette expansion (asm/neon_palette.h)
#include "asm/variants.h"

#if defined(SB_SIMD_HAVE_NEON)
#if !defined(__ARM_NEON) && !defined(__ARM_NEON__)
#error "SB_SIMD_HAVE_NEON is set but this file is not compiled for NEON"
#endif
#include <arm_neon.h>

#include <cstring>

#include "asm/neon_block_util.h"
#include "asm/neon_block_a32.h"
#include "asm/neon_block_a53.h"
#include "asm/neon_block_a53g.h"
#include "asm/neon_block_a64.h"
#include "asm/neon_block_mip3.h"
#include "asm/neon_block_mip2l.h"
#include "asm/neon_block_mip3l.h"
#include "asm/neon_palette.h"

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
// row loops at mips 0-2, every full group of a strip in one call (asm/neon_block_a53g.h):
// 16-bit indices, colormap bytes loaded straight into output lanes (asm/neon_block_a53.h);
// mip 3 its own function (asm/neon_block_mip3.h, the shared loop as fallback). AArch64 keeps
// rows of widths a multiple of 16 unrotated (group g at (c0 + 16 g) mod tw, see umod).
// Texture rows are laid out wrapped first ("tiled": surface column x reads run[x]); rows that
// need no wrap are read in place. Every texture row once per call when the texture is shorter
// than the surface (rows repeat) and fits the buffer, else a strip of bands' rows at a time.

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

// kInOrder: the row loops scheduled for in-order cores (surface_block_neon_inorder); kFull
// (with it, mips 0-2): width a multiple of 16, no partial group (none of its set-up).
template <int kMip, bool kInOrder = false, bool kFull = false>
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
#if defined(__aarch64__)
  // Textures wider than 16 but narrower than the surface (no run in place): a run repeats
  // every tw bytes, so group g reads its 16 bytes at (16 g) mod tw and only the first tw + 15
  // (rounded up to 16) are laid out (not mip 3's loop: it steps its runs by gs a group).
  // Widths a multiple of 16 (the usual case) instead keep rows unrotated: group g reads at
  // (c0 + 16 g) mod tw, in place when c0 is a multiple of 16 too (every group's 16 bytes lie
  // inside the row), else from the row laid out tw + 16 bytes (the row, then its first 16).
  const int umod = kMip != 3 && tw > 16 && (tw & 15) == 0 && c0 + width > tw && tw + 16 <= stride ? tw : 0;
  const bool uplace = umod && (c0 & 15) == 0;
  const int gper = !umod && kMip != 3 && !p16 && tw > 16 && width > tw && ((tw + 30) & ~15) < n16 ? tw : 0;
  const int gs = p16 ? 0 : 16, tile_n = gper ? (tw + 30) & ~15 : p16 ? 16 : n16, wlim = p16 ? 16 : width;
  auto goff_of = [&](int g) {  // group g's offset in a run
    return umod ? (c0 + 16 * g) % umod : gper ? 16 * g % gper : gs * g;
  };
  // Row t's run in the unrotated layout (umod), at dst when laid out.
  auto urun = [&](int t, uint8_t* dst) -> const uint8_t* {
    const uint8_t* const row = texels + t * tw;
    if (uplace) return row;
    tile_row_u(dst, row, tw);
    return dst;
  };
#else
  constexpr int gper = 0;
  const int gs = p16 ? 0 : 16, tile_n = p16 ? 16 : n16, wlim = p16 ? 16 : width;
#endif
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
#if defined(__aarch64__)
  const bool run_ext = all_rows && kMip != 3 && th + height + 2 + 7 <= kMaxRuns + 3;  // (see below)
#endif
  if (all_rows) {
    if (p16) {  // (rows left over, at the texture's end, laid out past the table's: t stride >= 16 t)
      int t = in_place(0) ? 0 : tile_rows16<kMip == 3>(texels, tw, th, period[0], buf, run);
      for (; t < th; ++t)
        run[t] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + t * stride, texels + t * tw, tw, c0, 16, tex_end, period, texels),
                                buf + t * stride);
#if defined(__aarch64__)
    } else if (umod) {  // rows in place or laid out at buf + t stride: run[] by pointer steps
      if (uplace) {
      } else if (tw == 32) {  // (the common width: two rows a step, th even, the loads first)
        const uint8_t* r = texels;
        for (uint8_t* o = buf; o < buf + th * stride; o += 2 * stride, r += 64) {
          uint8x16_t a = vld1q_u8(r), b = vld1q_u8(r + 16), c = vld1q_u8(r + 32), d = vld1q_u8(r + 48);
          asm("" : "+w"(a), "+w"(b), "+w"(c), "+w"(d));
          vst1q_u8(o, a);
          vst1q_u8(o + 16, b);
          vst1q_u8(o + 32, a);
          vst1q_u8(o + stride, c);
          vst1q_u8(o + stride + 16, d);
          vst1q_u8(o + stride + 32, c);
        }
      } else {
        for (int t = 0; t < th; ++t) tile_row_u(buf + t * stride, texels + t * tw, tw);
      }
      const int step = uplace ? tw : stride;
      const uint8_t *p0 = uplace ? texels : buf, *p1 = p0 + step, *p2 = p1 + step, *p3 = p2 + step;
      for (int t = 0; t < th; t += 4) {  // (th is a multiple of 4)
        run[t] = p0, run[t + 1] = p1, run[t + 2] = p2, run[t + 3] = p3;
        p0 += 4 * step, p1 += 4 * step, p2 += 4 * step, p3 += 4 * step;
        asm("" : "+r"(p0), "+r"(p1), "+r"(p2), "+r"(p3));  // (else GCC vectorizes: stalls in order)
      }
#endif
    } else {
      for (int t = 0; t < th; ++t)
        run[t] = c0 + width <= tw && texels + t * tw + c0 + n16 <= tex_end
                     ? texels + t * tw + c0
                     : (tile_row(buf + t * stride, texels + t * tw, tw, c0, gper ? tile_n : n16, tex_end, period, texels),
                        buf + t * stride);
    }
  }
#if defined(__aarch64__)
  // All rows laid out and run[] long enough: run[] continued cyclically once (th + height + 2
  // entries, eight a step), so a strip's runs in row order are run + first (mip 3's loop
  // changes its copy).
  if (run_ext && th < 8) {
    for (int t = th; t < th + height + 2; ++t) run[t] = run[t - th];
  } else if (run_ext) {
    for (int t = th; t < th + height + 2; t += 8) {  // (th >= 8: the reads precede the writes)
      const uint64_t* const src = reinterpret_cast<const uint64_t*>(run + t - th);
      uint64_t* const dst = reinterpret_cast<uint64_t*>(run + t);
      uint64x2_t v0 = vld1q_u64(src), v1 = vld1q_u64(src + 2), v2 = vld1q_u64(src + 4), v3 = vld1q_u64(src + 6);
      asm("" : "+w"(v0), "+w"(v1), "+w"(v2), "+w"(v3));
      vst1q_u64(dst, v0);
      vst1q_u64(dst + 2, v1);
      vst1q_u64(dst + 4, v2);
      vst1q_u64(dst + 6, v3);
    }
  }
#endif
  int strip_bands = bh;
  if (!all_rows) {
    const int fit = (kTileBytes / stride < kMaxRuns ? kTileBytes / stride : kMaxRuns) / B;  // >= 1
    strip_bands = fit < bh ? fit : bh;
  }
#if defined(__aarch64__)
  if (strip_bands > kStripRows / B) strip_bands = kStripRows / B;  // the assembly's tables
  if (kInOrder && LB >= 2 && strip_bands > kA53TableBytes / width - 3) strip_bands = kA53TableBytes / width - 3;
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
  // each band's row step, one more (unused); (the in-order mips 0-2 use a53t instead)
  uint32x4_t dtab[kInOrder && LB >= 2 ? 1 : (kStripRows / B + 1) * 4];
  alignas(16) uint8_t a53t[kInOrder && LB >= 2 ? kA53TableBytes : 16];  // (asm/neon_block_a53g.h's table)
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
#if defined(__aarch64__)
        if (umod) {
          run[r] = urun(t, buf + r * stride);
          if (++t == th) t = 0;
          continue;
        }
#endif
        run[r] = in_place(t) ? texels + t * tw + c0
                             : (tile_row(buf + r * stride, texels + t * tw, tw, c0, tile_n, tex_end, period, texels),
                                buf + r * stride);
        if (++t == th) t = 0;
      }
    }
#if defined(__aarch64__)
    const uint8_t* const* const linp = run_ext ? run + first : lin;
    if (!run_ext) {  // lin: the strip's runs, two rows beyond
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
    int g = 0;
    if constexpr (kInOrder && LB >= 2) {  // the full groups (asm/neon_block_a53g.h)
      if (width >= 16) {
        const int64_t gmod = umod ? umod : gper ? gper : int64_t(1) << 40;  // (goff_of's steps)
        const A53Groups st{strip, nullptr, 0, linp, gmod, umod || gper ? 16 : gs, strip + 16 * (width >> 4), 0};
        a53_full_groups<kMip>(grid + by0 * grid_width, grid_width, nb, width, st, goff_of(0), a53t, colormap, BX1, FX1,
                              vld1q_u8(kTix16[0]), vld1q_u8(kTix16[1]));
        g = width >> 4;
      }
      if constexpr (kFull) continue;
    }
    for (; g < groups; ++g) {
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
        const uint8x16_t t = vld1q_u8(src + goff_of(g));
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
        if constexpr (kInOrder && LB >= 2) continue;  // (never: a53_full_groups ran them)
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
        // dtab entries a band (mip 2: e, e1 in 16-bit lanes)
        constexpr int kDs = LB == 2 ? 1 : 4;
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
            if constexpr (LB == 3) {  // quarters 0-1: block 0, 2-3: block 1
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
          if constexpr (LB == 2) {  // e, e1 (16 bytes a band): the assembly weighs them
            grid_row_diffs<LB>(r, 2 * int64_t(grid_width), nb, dtab);
          } else {
          uint16x8_t p = ldg(r), p1 = LB <= 3 ? ldg(r + 1) : p;
          uint32x4_t* dt = dtab;
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
          }
        } else {
          for (int b = 0; b < nb; ++b) {
            if constexpr (LB == 2) {  // e, e1 as above, from the zero-padded rows
              uint16_t a[5];
              std::memcpy(a, row_of(by0 + b), sizeof a);
              const uint16_t* const c = row_of(by0 + b + 1);
              int16_t ee[8];
              for (int j = 0; j < 4; ++j) {
                ee[j] = int16_t(c[j] - a[j]);
                ee[4 + j] = int16_t(c[j + 1] - a[j + 1]);
              }
              std::memcpy(dtab + b, ee, sizeof ee);
              continue;
            }
            step_for(by0 + b + 1);
            for (int j = 0; j < 4; ++j) dtab[4 * b + j] = delta[j];
          }
        }
        if constexpr (LB != 1)
          for (int j = 0; j < 4; ++j) dtab[kDs * nb + j] = vdupq_n_u32(0);
        const int64_t goff = goff_of(g), wstride = width;
        const uint8_t* const* rp = linp;
        if constexpr (LB >= 3) {
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
        } else if constexpr (LB == 2) {
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
              SB_MIP3_LOOP
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
// The in-order variant (Cortex-A53/A55/A35): its own row loops at every mip. Entered from
// surface_block_neon_inorder (asm/neon_block_mip3l.h: the lean mip-3 path in assembly) by a
// branch, under this symbol name.
namespace {
__attribute__((noipa, used)) void surface_block_inorder(const uint16_t* grid, int grid_width, const uint8_t* texels,
                                                        int tex_width, int tex_height, int mip, int soff, int toff,
                                                        int width, int height, const uint8_t* colormap,
                                                        uint8_t* out) asm(SB_MIP3L_REST);
void surface_block_inorder(const uint16_t* grid, int grid_width, const uint8_t* texels, int tex_width, int tex_height,
                           int mip, int soff, int toff, int width, int height, const uint8_t* colormap,
                           uint8_t* out) {
  if (width > 0 && height > 0 && mip >= 0 && mip <= 3 && width / (16 >> mip) <= kMaxBlockColumns) {
    if (mip == 0)
      return (width & 15 ? surface_block_groups<0, true> : surface_block_groups<0, true, true>)(
          grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    if (mip == 1)
      return (width & 15 ? surface_block_groups<1, true> : surface_block_groups<1, true, true>)(
          grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    if (mip == 2)
      return (width & 15 ? surface_block_groups<2, true> : surface_block_groups<2, true, true>)(
          grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out);
    if (surface_block_mip3(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height, colormap, out))
      return;
    return surface_block_groups<3, true>(grid, grid_width, texels, tex_width, tex_height, soff, toff, width, height,
                                         colormap, out);
  }
  surface_block_neon(grid, grid_width, texels, tex_width, tex_height, mip, soff, toff, width, height, colormap, out);
}
}  // namespace

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

}  // namespace

const Kernels kNeon = {"neon", surface_span_fast, surface_block_neon, z_span_neon, expand_palette_neon, alias_span_neon,
                        surface_span_persp_fast, surface_spans_persp_fast};
#if defined(__aarch64__)
const Kernels kNeonInOrder = {"neon_a53", surface_span_fast, surface_block_neon_inorder, z_span_neon,
                              expand_palette_neon, alias_span_neon, surface_span_persp_fast,
                              surface_spans_persp_fast};
#endif

}  // namespace sb::simd::detail

#endif  // SB_SIMD_HAVE_NEON
