// asm/variants.h: internal to asm/: the variant tables each instruction-set file defines,
// and small helpers the tuned variants share. Each table exists only where its file
// compiles its code (see asm/CMakeLists.txt); a missing kernel falls back to the scalar one.
#pragma once
#include "asm/kernels.h"

namespace sb::simd::detail {

extern const Kernels kScalar;
#if defined(__x86_64__)
#define SB_SIMD_X86 1
extern const Kernels kSse2;
extern const Kernels kAvx2;
extern const Kernels kAvx2Gather;
#endif
#if defined(SB_SIMD_HAVE_NEON)
extern const Kernels kNeon;
#endif

// Positive modulo (n > 0).
inline int wrap(int i, int n) {
  int r = i % n;
  return r < 0 ? r + n : r;
}

// The number of texels of a surface row that can be read contiguously from texture column
// c onwards: up to the texture row's end (the builders walk a row in such segments).
inline int segment_length(int left, int c, int tex_width) { return left < tex_width - c ? left : tex_width - c; }

}  // namespace sb::simd::detail
