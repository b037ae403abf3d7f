// asm/neon_block_a53g.h: the neon_a53 surface block builder's full groups at mips 0-2 on
// AArch64: every full 16-texel group of a strip in one assembly call (asm/neon.cpp's
// surface_block_groups calls a53_full_groups; the row loops are asm/neon_block_a53.h's).
// Only asm/neon.cpp includes this (after asm/neon_block_a53.h).
//
// Per strip, one table T of nb + 3 rows of es = width bytes (rows = grid rows' entries as
// 16-bit lanes, group g's G + 1 entries at byte 2 G g): row 0 the strip's first grid row,
// row 1 + b band b's differences e = grid row b + 1 - grid row b, rows nb + 1.. read, unused.
// A group reads 16 bytes at 2 G g of a row (entries G g .. G g + 7: lanes 0..G of them used),
// inside the row as width >= 16 F >= 2 G (F - 1) + 16 for F full groups. Its numerators are
// row 0 weighed, its band steps rows 1.. weighed (one row a band, at the band's last pair).
// The group loop keeps its state on the stack (A53Groups, copied there at entry): the group's
// output and row 0 in T, the end of the outputs, the table offset each group starts from (-nb es), the
// strip's texel runs (lin), and how goff steps (gstep, wrapped at gmod: asm/neon.cpp's
// goff_of); in registers its table end (ete: one row past the last read, + 2 G g) and goff.
#pragma once
#include <arm_neon.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "asm/neon_block_a53m1.h"
#include "asm/neon_block_util.h"
#include "asm/variants.h"

namespace sb::simd::detail {
namespace {

#if defined(__aarch64__)

constexpr int kA53TableBytes = 16384;  // T: (nb + 3) width bytes at most (caps the strip's bands)

struct A53Groups {
  uint8_t* d;                 // group 0's output (the strip's first row)
  const uint8_t* p0;          // group 0's row 0 in T
  int64_t off;                // -nb es: the table offset a group starts from
  const uint8_t* const* lin;  // the strip's texel runs
  int64_t gmod, gstep;        // goff += gstep, then -= gmod when >= gmod
  uint8_t* dend;              // one group past the last's output (groups: (dend - d) / 16 >= 1)
  int64_t unused;
};
static_assert(offsetof(A53Groups, d) == 0 && offsetof(A53Groups, p0) == 8 && offsetof(A53Groups, off) == 16 &&
                  offsetof(A53Groups, lin) == 24 && offsetof(A53Groups, gmod) == 32 &&
                  offsetof(A53Groups, gstep) == 40 && offsetof(A53Groups, dend) == 48 && sizeof(A53Groups) == 64,
              "the assembly reads A53Groups by these offsets");

// The group loop around a strip's row loop (HEAD: the group's entry, x11 its row 0; OFF: its
// table offset register; G2: 2 G, the table step a group). ete and goff stay in their
// registers from group to group (the row loops only read them); the next group's output,
// row 0, offset and runs are set before its entry (5:).
#define SB_A53_GROUPS_X(OFF, HEAD, LOOP, EXIT) \
  "sub sp, sp, #64\n\t" \
  "ldp x0, x1, [%[q]]\n\t" \
  "ldp x2, x3, [%[q], #16]\n\t" \
  "ldp x4, x5, [%[q], #32]\n\t" \
  "ldr x6, [%[q], #48]\n\t" \
  "stp x0, x1, [sp]\n\t" \
  "stp x2, x3, [sp, #16]\n\t" \
  "stp x4, x5, [sp, #32]\n\t" \
  "str x6, [sp, #48]\n\t" \
  "ldp %[d], x11, [sp]\n\t" \
  "ldp " OFF ", %[rp], [sp, #16]\n" \
  "5:\n\t" HEAD \
  "b 2f\n\t" \
  ".p2align 10\n" \
  "1:\n\t" LOOP EXIT \
  "b.ne 5b\n\t" \
  "add sp, sp, #64\n\t"

// The group exit: the last pair's rows stored, the next group's state (output, row 0, table offset,
// runs, goff) set from the stack, flags ne while groups remain.
#define SB_A53_EXIT(OFF, G2) \
  "stp d4, d5, [%[d]]\n\t" \
  "stp d6, d7, [x8]\n\t" \
  "ldp x0, x11, [sp]\n\t" \
  "ldp x6, x7, [sp, #32]\n\t" \
  "ldr x5, [sp, #48]\n\t" \
  "ldp " OFF ", %[rp], [sp, #16]\n\t" \
  "add x0, x0, #16\n\t" \
  "add x11, x11, #" G2 "\n\t" \
  "add %[ete], %[ete], #" G2 "\n\t" \
  "add %[goff], %[goff], x7\n\t" \
  "cmp %[goff], x6\n\t" \
  "sub x4, %[goff], x6\n\t" \
  "csel %[goff], x4, %[goff], hs\n\t" \
  "stp x0, x11, [sp]\n\t" \
  "mov %[d], x0\n\t" \
  "cmp x0, x5\n\t"
#define SB_A53_GROUPS(OFF, HEAD, LOOP, G2) SB_A53_GROUPS_X(OFF, HEAD, LOOP, SB_A53_EXIT(OFF, G2))

// Mips 0-1: numerators from row 0 (v0), the first band's step from row 1 (v8, SB_WEIGH01's
// products interleaved: no accumulate waits on its product), row 2 preloaded (v8); x30 = the
// table offset (see SB_PAIR_LOOP_16W0).
#define SB_A53_HEAD01(L0, L1, L4, SH) \
  "ldr q0, [x11]\n\t" \
  "add x10, x11, %[w]\n\t" \
  "ldr x8, [%[rp]]\n\t" \
  "ldr q8, [x10]\n\t" \
  "add x9, x10, %[w]\n\t" \
  "ldr q21, [x8, %[goff]]\n\t" \
  "ldr x8, [%[rp], #8]\n\t" \
  "ldr q26, [x8, %[goff]]\n\t" \
  "add %[rp], %[rp], #16\n\t" \
  "mov %[q], %[hp1]\n\t" \
  "sub %[d], %[d], %[w], lsl #1\n\t" \
  "smull v22.4s, %[wa].4h, v0.h[0]\n\t" \
  "smull2 v23.4s, %[wa].8h, v0.h[0]\n\t" \
  "smull v19.4s, %[wb].4h, v0.h[" L0 "]\n\t" \
  "smull2 v20.4s, %[wb].8h, v0.h[" L0 "]\n\t" \
  "smull v16.4s, %[wa].4h, v8.h[0]\n\t" \
  "smull2 v17.4s, %[wa].8h, v8.h[0]\n\t" \
  "smull v18.4s, %[wb].4h, v8.h[" L0 "]\n\t" \
  "smull2 v29.4s, %[wb].8h, v8.h[" L0 "]\n\t" \
  "smlal v22.4s, %[wc].4h, v0.h[" L1 "]\n\t" \
  "smlal2 v23.4s, %[wc].8h, v0.h[" L1 "]\n\t" \
  "smlal v19.4s, %[wd].4h, v0.h[" L4 "]\n\t" \
  "smlal2 v20.4s, %[wd].8h, v0.h[" L4 "]\n\t" \
  "smlal v16.4s, %[wc].4h, v8.h[" L1 "]\n\t" \
  "smlal2 v17.4s, %[wc].8h, v8.h[" L1 "]\n\t" \
  "shl v22.4s, v22.4s, #" SH "\n\t" \
  "shl v23.4s, v23.4s, #" SH "\n\t" \
  "smlal v18.4s, %[wd].4h, v8.h[" L4 "]\n\t" \
  "smlal2 v29.4s, %[wd].8h, v8.h[" L4 "]\n\t" \
  "shl v19.4s, v19.4s, #" SH "\n\t" \
  "shl v20.4s, v20.4s, #" SH "\n\t" \
  "ldr q8, [x9]\n\t" SB_PAIR_LOOP_16_PRO

// Mip 2: as above (the step as SB_PAIR16_B weighs it) with q the table offset (see
// SB_PAIR16_A).
#define SB_A53_HEAD2 \
  "ldr q0, [x11]\n\t" \
  "add x10, x11, %[w]\n\t" \
  "ldr x8, [%[rp]]\n\t" \
  "ldr q8, [x10]\n\t" \
  "ldr q21, [x8, %[goff]]\n\t" \
  "ldr x8, [%[rp], #8]\n\t" \
  "ldr q26, [x8, %[goff]]\n\t" \
  "add %[rp], %[rp], #16\n\t" \
  "sub %[d], %[d], %[w], lsl #1\n\t" \
  "smull v22.4s, %[wt].4h, v0.h[0]\n\t" \
  "smull v23.4s, %[wt].4h, v0.h[1]\n\t" \
  "smull v19.4s, %[wt].4h, v0.h[2]\n\t" \
  "smull v20.4s, %[wt].4h, v0.h[3]\n\t" \
  "smull v16.4s, %[wt].4h, v8.h[0]\n\t" \
  "smull v17.4s, %[wt].4h, v8.h[1]\n\t" \
  "smull v18.4s, %[wt].4h, v8.h[2]\n\t" \
  "smull v29.4s, %[wt].4h, v8.h[3]\n\t" \
  "smlal2 v22.4s, %[wt].8h, v0.h[1]\n\t" \
  "smlal2 v23.4s, %[wt].8h, v0.h[2]\n\t" \
  "smlal2 v19.4s, %[wt].8h, v0.h[3]\n\t" \
  "smlal2 v20.4s, %[wt].8h, v0.h[4]\n\t" \
  "smlal2 v16.4s, %[wt].8h, v8.h[1]\n\t" \
  "smlal2 v17.4s, %[wt].8h, v8.h[2]\n\t" \
  "shl v22.4s, v22.4s, #2\n\t" \
  "shl v23.4s, v23.4s, #2\n\t" \
  "smlal2 v18.4s, %[wt].8h, v8.h[3]\n\t" \
  "smlal2 v29.4s, %[wt].8h, v8.h[4]\n\t" \
  "shl v19.4s, v19.4s, #2\n\t" \
  "shl v20.4s, v20.4s, #2\n\t"

// T (see above) for the strip's nb bands from grid row r (stride gw entries): entries
// 0..ne - 1 of rows 0..nb (ne <= gw), es bytes a row.
template <int LB>
inline void a53_table(const uint16_t* r, int gw, int nb, int ne, uint8_t* t, int64_t es) {
  if (ne < 8) {
    for (int j = 0; j < ne; ++j) {
      const uint16_t* s = r + j;
      uint16_t p = *s;
      reinterpret_cast<uint16_t*>(t)[j] = p;
      for (int b = 1; b <= nb; ++b) {
        s += gw;
        const uint16_t q = *s, e = uint16_t(q - p);
        std::memcpy(t + b * es + 2 * j, &e, sizeof e);
        p = q;
      }
    }
    return;
  }
  const int64_t g1 = 2 * int64_t(gw), g2 = 2 * g1, g3 = 3 * g1, g4 = 4 * g1;
  const int64_t e2 = 2 * es, e3 = 3 * es, e4 = 4 * es;
  for (int j = 0;; j += 8) {
    if (j > ne - 8) j = ne - 8;  // (the last column overlaps the one before)
    const uint16_t* s = r + j;
    uint8_t* o = t + 2 * j;
    int64_t n4 = nb >> 2, n1 = nb & 3;
    // Row 0, then four differences a step (the loads first: Cortex-A53 model 17 cycles), then
    // one at a time.
    asm volatile(
        "ldr q0, [%[s]]\n\t"
        "str q0, [%[o]]\n\t"
        "cbz %[n4], 2f\n"
        "1:\n\t"
        "ldr q1, [%[s], %[g1]]\n\t"
        "ldr q2, [%[s], %[g2]]\n\t"
        "ldr q3, [%[s], %[g3]]\n\t"
        "ldr q4, [%[s], %[g4]]\n\t"
        "add %[s], %[s], %[g4]\n\t"
        "subs %[n4], %[n4], #1\n\t"
        "sub v5.8h, v1.8h, v0.8h\n\t"
        "sub v6.8h, v2.8h, v1.8h\n\t"
        "sub v7.8h, v3.8h, v2.8h\n\t"
        "sub v16.8h, v4.8h, v3.8h\n\t"
        "mov v0.16b, v4.16b\n\t"
        "str q5, [%[o], %[e1]]\n\t"
        "str q6, [%[o], %[e2]]\n\t"
        "str q7, [%[o], %[e3]]\n\t"
        "str q16, [%[o], %[e4]]\n\t"
        "add %[o], %[o], %[e4]\n\t"
        "b.ne 1b\n"
        "2:\n\t"
        "cbz %[n1], 4f\n"
        "3:\n\t"
        "ldr q1, [%[s], %[g1]]\n\t"
        "add %[s], %[s], %[g1]\n\t"
        "subs %[n1], %[n1], #1\n\t"
        "sub v5.8h, v1.8h, v0.8h\n\t"
        "mov v0.16b, v1.16b\n\t"
        "str q5, [%[o], %[e1]]\n\t"
        "add %[o], %[o], %[e1]\n\t"
        "b.ne 3b\n"
        "4:\n\t"
        : [s] "+r"(s), [o] "+r"(o), [n4] "+r"(n4), [n1] "+r"(n1)
        : [g1] "r"(g1), [g2] "r"(g2), [g3] "r"(g3), [g4] "r"(g4), [e1] "r"(es), [e2] "r"(e2), [e3] "r"(e3),
          [e4] "r"(e4)
        : "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v16", "cc", "memory");
    if (j == ne - 8) break;
  }
}

// Every full group (16 g + 16 <= width, F >= 1 of them) of the strip at out (nb bands from
// grid row r): st's d, lin, gmod, gstep, dend set by the caller, goff group 0's; t: the table
// buffer (kA53TableBytes, (nb + 3) width bytes used); J0, J1: the index lookups (kTix16).
template <int kMip>
__attribute__((always_inline)) inline void a53_full_groups(const uint16_t* r, int gw, int nb, int width, A53Groups st,
                                                           int64_t goff, uint8_t* t, const uint8_t* colormap,
                                                           const uint16x8_t* BX1, const uint16x8_t* FX1,
                                                           uint8x16_t J0, uint8x16_t J1) {  // (a call costs mip 2 0.02)
  constexpr int B = 16 >> kMip, G = 16 / B;
  const int64_t es = width;
  a53_table<4 - kMip>(r, gw, nb, G * int((st.dend - st.d) >> 4) + 1, t, es);
  st.p0 = t;
  st.off = -int64_t(nb) * es;
  uint8_t* d = st.d;
  const uint8_t* const* rp = st.lin;
  const uint8_t* ete = t + (kMip == 2 ? nb + 2 : nb + 3) * es;
  int64_t q = reinterpret_cast<int64_t>(&st);
  const int64_t wstride = width;
  if constexpr (kMip <= 1) {
    const int16x8_t WA = vreinterpretq_s16_u16(BX1[0]), WB = vreinterpretq_s16_u16(BX1[1]);
    const int16x8_t WC = vreinterpretq_s16_u16(FX1[0]), WD = vreinterpretq_s16_u16(FX1[1]);
#define SB_A53_OPERANDS01 \
  : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q), [ete] "+r"(ete), [goff] "+r"(goff) \
  : [cm] "r"(colormap), [w] "r"(wstride), [j0] "w"(J0), [j1] "w"(J1), [wa] "w"(WA), [wb] "w"(WB), [wc] "w"(WC), \
    [wd] "w"(WD), [hp1] "i"(B / 2 - 1) \
  : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19", "x20", "x21", \
    "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6", "v7", "v8", "v16", "v17", \
    "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27", "v28", "v29", "cc", "memory"
    if constexpr (kMip == 0) {
      asm volatile(SB_A53_GROUPS("x30", SB_A53_HEAD01("0", "1", "1", "4"), SB_PAIR_LOOP_16 SB_PAIR_LOOP_16W0, "2")
                       SB_A53_OPERANDS01);
    } else {
      asm volatile(SB_A53_GROUPS_X("x30", SB_A53_HEAD1, SB_BAND_16W1, SB_A53_EXIT1)
                       SB_A53_OPERANDS01);
    }
#undef SB_A53_OPERANDS01
  } else {
    const int16x8_t wt = vcombine_s16(vget_low_s16(vreinterpretq_s16_u16(BX1[0])),
                                      vget_low_s16(vreinterpretq_s16_u16(FX1[0])));
    asm volatile(SB_A53_GROUPS("%[q]", SB_A53_HEAD2, SB_PAIR16_A SB_PAIR16_B, "8")
                 : [d] "+r"(d), [rp] "+r"(rp), [q] "+r"(q), [ete] "+r"(ete), [goff] "+r"(goff)
                 : [cm] "r"(colormap), [w] "r"(wstride), [j0] "w"(J0), [j1] "w"(J1), [wt] "w"(wt)
                 : "x0", "x1", "x2", "x3", "x4", "x5", "x6", "x7", "x8", "x9", "x10", "x11", "x12", "x18", "x19",
                   "x20", "x21", "x22", "x23", "x24", "x25", "x26", "x30", "v0", "v1", "v2", "v3", "v4", "v5", "v6",
                   "v7", "v8", "v16", "v17", "v18", "v19", "v20", "v21", "v22", "v23", "v24", "v25", "v26", "v27",
                   "v28", "v29", "cc", "memory");
  }
}

#undef SB_A53_GROUPS
#undef SB_A53_GROUPS_X
#undef SB_A53_EXIT
#undef SB_A53_HEAD01
#undef SB_A53_HEAD2

#endif  // __aarch64__

}  // namespace
}  // namespace sb::simd::detail
