// asm/variants.h: internal to asm/: the variant tables each instruction-set file defines,
// and small helpers the tuned variants share. Each table exists only where its file
// compiles its code (see asm/CMakeLists.txt); a missing kernel falls back to the scalar one.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "asm/kernels.h"

namespace sb::simd::detail {

extern const Kernels kScalar;
// asm/alias_span_simd.cpp's variants (declared here so the instruction-set tables can list them).
void alias_span_sse2(uint8_t* dest, uint16_t* zbuf, int n, const uint8_t* skin, int skin_width,
                     const uint8_t* colormap, const AliasSpan& span);
void alias_span_neon(uint8_t* dest, uint16_t* zbuf, int n, const uint8_t* skin, int skin_width,
                     const uint8_t* colormap, const AliasSpan& span);
#if defined(__x86_64__)
#define SB_SIMD_X86 1
extern const Kernels kSse2;
extern const Kernels kAvx2;
extern const Kernels kAvx2Gather;
// asm/sse2.cpp's palette expansion (avx2's takes it for scales 3 and up).
void expand_palette_sse2(const uint8_t* src, ptrdiff_t src_stride, int width, int height, const uint32_t* palette,
                         uint32_t* dst, ptrdiff_t dst_stride, int scale);
#endif
#if defined(SB_SIMD_HAVE_NEON)
extern const Kernels kNeon;
#if defined(__aarch64__)
#define SB_SIMD_NEON_INORDER 1
extern const Kernels kNeonInOrder;  // "neon_a53": the block builder's row loop for in-order cores
#endif
#endif

// Reads a Linux /proc/cpuinfo text from f (not closed): true iff it names at least one core
// ("CPU part") and every one is an in-order Arm core (Cortex-A53, A35, A55, A510, A520),
// where asm/dispatch.cpp picks neon_a53 for the block builder. Compiled on every target.
bool cpuinfo_in_order(std::FILE* f);

// Positive modulo (n > 0).
inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

// The texels of one surface row (texture row trow from column c0, wrapping at tex_width) as
// one contiguous run: trow + c0 itself when the row does not wrap, else a copy in buf
// (width + 16 bytes; the 16 after the row are zeroed). *end gets the run's readable end.
constexpr int kRowBufferBytes = kMaxBlockColumns * 16 + 16;
inline const uint8_t* texel_row(const uint8_t* trow, int c0, int tex_width, int width, const uint8_t* tex_end,
                                uint8_t* buf, const uint8_t** end) {
  if (width <= tex_width - c0) {
    *end = tex_end;
    return trow + c0;
  }
  int x = 0, c = c0;
  while (x < width) {
    const int len = width - x < tex_width - c ? width - x : tex_width - c;
    std::memcpy(buf + x, trow + c, size_t(len));
    x += len;
    c = 0;
  }
  std::memset(buf + width, 0, 16);
  *end = buf + width + 16;
  return buf;
}

// d[k] = table[idx[k]] for k < 16 (or < m): the builders' colormap lookups, unrolled.
inline void lookup16(uint8_t* __restrict d, const uint8_t* __restrict table, const uint16_t* __restrict idx) {
#pragma GCC unroll 16
  for (int k = 0; k < 16; ++k) d[k] = table[idx[k]];
}
inline void lookup_n(uint8_t* __restrict d, const uint8_t* __restrict table, const uint16_t* __restrict idx, int m) {
  if (m >= 16) {
    lookup16(d, table, idx);
  } else {
    for (int k = 0; k < m; ++k) d[k] = table[idx[k]];
  }
}

// Texels src[0 .. 15] into buf when only m < 16 of them may be read (the rest zero), or src
// itself when all 16 lie before `end`.
inline const uint8_t* texels16(const uint8_t* src, int m, const uint8_t* end, uint8_t* buf) {
  if (m >= 16 || src + 16 <= end) return src;
  for (int k = 0; k < 16; ++k) buf[k] = k < m ? src[k] : 0;
  return buf;
}

}  // namespace sb::simd::detail
