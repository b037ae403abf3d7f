// asm/neon_palette.h: expand_palette_neon (asm/palette_expand.h's contract), section 4 of
// asm/neon.cpp, kept apart for the file's size. Only asm/neon.cpp includes this (the
// definition is internal to it).
#pragma once
#include <arm_neon.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace sb::simd::detail {
namespace {

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
    if (scale == 1) {
      // Core loads and stores: the indices read 8 or 16 at a time as 64-bit words, the palette
      // words loaded into core registers and stored in pairs. Lane inserts into a vector
      // (four() below) cost more than they save here (Cortex-A72 model: 7.6 cycles a pixel).
#if defined(__aarch64__)
      // 16 pixels an iteration, the order searched for the Cortex-A53 model
      // (bench/mca_a53_palette/README.md).
      if (width >= 16) {
        const uint8_t* sp = s;
        uint32_t* dp = d;
        const uint32_t* const end = d + (width & ~15);
        __asm__ volatile(
            "1:\n\t"
            // BEGIN palette_loop16
            "ldp x4, x14, [%[s]], #16\n\t"
            "ubfx x5, x4, #8, #8\n\t"
            "ubfx x3, x14, #40, #8\n\t"
            "ubfx x13, x4, #48, #8\n\t"
            "ubfx x8, x4, #24, #8\n\t"
            "ubfx x7, x4, #32, #8\n\t"
            "ubfx x11, x4, #16, #8\n\t"
            "ubfx x2, x14, #32, #8\n\t"
            "ldr w5, [%[pal], x5, lsl #2]\n\t"
            "ldr w11, [%[pal], x11, lsl #2]\n\t"
            "and x16, x14, #0xff\n\t"
            "ldr w13, [%[pal], x13, lsl #2]\n\t"
            "and x6, x4, #0xff\n\t"
            "ubfx x12, x4, #40, #8\n\t"
            "lsr x4, x4, #56\n\t"
            "ubfx x1, x14, #24, #8\n\t"
            "ubfx x10, x14, #48, #8\n\t"
            "ubfx x17, x14, #16, #8\n\t"
            "ubfx x15, x14, #8, #8\n\t"
            "lsr x14, x14, #56\n\t"
            "ldr w12, [%[pal], x12, lsl #2]\n\t"
            "ldr w6, [%[pal], x6, lsl #2]\n\t"
            "add %[d], %[d], #0x40\n\t"
            "ldr w8, [%[pal], x8, lsl #2]\n\t"
            "ldr w16, [%[pal], x16, lsl #2]\n\t"
            "ldr w7, [%[pal], x7, lsl #2]\n\t"
            "stp w6, w5, [%[d], #-64]\n\t"
            "ldr w10, [%[pal], x10, lsl #2]\n\t"
            "ldr w17, [%[pal], x17, lsl #2]\n\t"
            "stp w11, w8, [%[d], #-56]\n\t"
            "cmp %[e], %[d]\n\t"
            "ldr w4, [%[pal], x4, lsl #2]\n\t"
            "ldr w1, [%[pal], x1, lsl #2]\n\t"
            "stp w7, w12, [%[d], #-48]\n\t"
            "ldr w15, [%[pal], x15, lsl #2]\n\t"
            "ldr w3, [%[pal], x3, lsl #2]\n\t"
            "ldr w2, [%[pal], x2, lsl #2]\n\t"
            "ldr w14, [%[pal], x14, lsl #2]\n\t"
            "stp w13, w4, [%[d], #-40]\n\t"
            "stp w16, w15, [%[d], #-32]\n\t"
            "stp w17, w1, [%[d], #-24]\n\t"
            "stp w2, w3, [%[d], #-16]\n\t"
            "stp w10, w14, [%[d], #-8]\n\t"
            // END palette_loop16
            "b.ne 1b\n\t"
            : [d] "+r"(dp), [s] "+r"(sp)
            : [e] "r"(end), [pal] "r"(palette)
            : "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x10", "x11", "x12", "x13", "x14", "x15", "x16", "x17",
              "cc", "memory");
        x = width & ~15;
      }
#else
      for (; x + 8 <= width; x += 8) {
        uint64_t b;
        std::memcpy(&b, s + x, 8);
        uint32_t* p = d + x;
#pragma GCC unroll 8
        for (int i = 0; i < 8; ++i) p[i] = palette[(b >> (8 * i)) & 255];
      }
#endif
    } else if (scale <= 4) {
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
}  // namespace sb::simd::detail
