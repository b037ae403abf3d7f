#!/usr/bin/env python3
# bench/mca_a53_lit/gen_win16.py: writes win16_in.s, the aarch64 block that draws one full
# 16-pixel run of the single-pass lit span kernel (asm/lit_span.h; asm/lit_span_a64win.h,
# win16_block) whose 8-pixel groups cross several light cells (mips above 0 at about a
# texel a pixel), in a plain dependency order; ../mca_a53_persp/list_sched.py then orders it
# for the Cortex-A53 model (README.md, "Runs across several cells").
#
# Each group takes its light from a window of 3 x 3 cells (4 x 4 grid entries, two 16-byte
# rows pairs: a two-register tbl table) whose origin is (min gx, min gy) of the group's
# lanes, clamped to (limx, limy) so that every entry read is inside the grid the contract
# gives. The group's cell ranges come from pairwise maxima over bytes (cells < 256: the
# caller checks). The block flags the run (x2 nonzero) when a group's cells are not all in
# its window; the caller then draws the whole run again by the per-pixel kernel (the
# block has written dest: the redraw overwrites it).
#
# Per lane, with the window's entries as a table and l = 4 (gy - oy) + gx - ox, the byte
# indices of g00 are 2 l | (2 l + 1) << 8 = 514 gx + 2056 gy + 256 - 514 (ox + 4 oy)
# (16-bit lanes, exact mod 2^16), g10, g01, g11 at + 0x0202, + 0x0808, + 0x0a0a; then
#   num = B^2 g00 + B fx (g10 - g00) + B fy (g01 - g00) + fx fy (g11 - g10 - g01 + g00)
# by a widening multiply and three widening multiply-adds per half (the differences fit 16
# bits). The positions, texel indices, weights, light shift and the pixels' core part are
# gen_lit16.py's (the same frame LitA64Frame and table LitA64Tab).
#
# Operand placeholders (bench/to_inline.py maps them to the inline asm's operands):
#   x0 u, x1 v, x2 du, x3 dv, x4 ddu, x5 ddv (read-write; x2 returns the flag), x6 texels,
#   x7 colormap, x8 grid (16-bit), x9 grid row stride in bytes, x10 dest, x11 frame, x12 the
#   mip's table, x13 limx, x14 limy (the window origin's largest column / row).
# Core scratch: x15-x17, x19-x28; vectors: v0-v7, v16-v31 (v8-v15 untouched).
import sys

from lit_gen import allocate, head, pixels

L = []


def e(s):
    L.append(s)


head(e)  # positions and texel indices (lit_gen.py, as gen_lit16.py)
# ---------------------------------------------------------------- NEON: cells and their ranges
e("neg v29.8h, v31.8h")               # -log B
e("ushl v24.8h, v6.8h, v29.8h")       # gx, group a
e("ushl v25.8h, v7.8h, v29.8h")       # gx, group b
e("ushl v26.8h, v16.8h, v29.8h")      # gy, group a
e("ushl v27.8h, v17.8h, v29.8h")      # gy, group b
e("uzp1 v0.16b, v24.16b, v26.16b")    # bytes: gx a, gy a
e("uzp1 v1.16b, v25.16b, v27.16b")    # gx b, gy b
e("mvn v2.16b, v0.16b")
e("mvn v3.16b, v1.16b")
e("umaxp v0.16b, v0.16b, v1.16b")
e("umaxp v2.16b, v2.16b, v3.16b")
e("umaxp v0.16b, v0.16b, v2.16b")
e("umaxp v0.16b, v0.16b, v0.16b")
# bytes 0..3: max gx a, max gy a, max gx b, max gy b; 4..7: their ~min
e("fmov x%rg, d0")
# ---------------------------------------------------------------- NEON: weights (gen_lit16.py)
e("and v18.16b, v6.16b, v30.16b")    # fx, fy of group a; b
e("and v19.16b, v16.16b, v30.16b")
e("and v20.16b, v7.16b, v30.16b")
e("and v21.16b, v17.16b, v30.16b")
e("mul v5.8h, v18.8h, v19.8h")       # fx fy
e("mul v30.8h, v20.8h, v21.8h")
e("ushl v18.8h, v18.8h, v31.8h")     # B fx, B fy
e("ushl v19.8h, v19.8h, v31.8h")
e("ushl v20.8h, v20.8h, v31.8h")
e("ushl v21.8h, v21.8h, v31.8h")
e("ldr q31, [x%tab, #160]")           # -(S + 8) (u32 lanes)
# v4 = [514, 2056, B^2, ..] (16-bit lanes: multipliers by element; LitA64Tab::win)
e("ldr q4, [x%tab, #192]")
# ---------------------------------------------------------------- core: window origins, the test
e("mvn x%nrg, x%rg")
e("ubfx x%xa, x%nrg, #32, #8")        # min gx a
e("ubfx x%ya, x%nrg, #40, #8")        # min gy a
e("ubfx x%xb, x%nrg, #48, #8")        # min gx b
e("lsr x%yb, x%nrg, #56")             # min gy b
e("cmp w%xa, w13")
e("csel w%xa, w%xa, w13, lt")         # ox a = min(min gx a, limx)
e("cmp w%ya, w14")
e("csel w%ya, w%ya, w14, lt")
e("cmp w%xb, w13")
e("csel w%xb, w%xb, w13, lt")
e("cmp w%yb, w14")
e("csel w%yb, w%yb, w14, lt")
# the spans D = max - min of the four coordinates, bytewise: max + ~min + 1 with the carries
# chained (each byte sum is 256 + max - min: its carry is the next byte's + 1); some D >= 3?
# D >= 4 sets a bit of 0xfc, D = 3 (bits 0 and 1) sets bit 2 of (D & D >> 1) << 2 (its other
# bits there only where D >= 4, or in bit 1 of a byte: outside the mask). (Equivalent to
# max - ox <= 2 with the clamped origin: max <= limx + 2.)
e("lsr x%hi, x%rg, #32")
e("add w%sp, w%rg, w%hi")
e("add w%sp, w%sp, #1")
e("and w%s3, w%sp, w%sp, lsr #1")
e("orr w%sp, w%sp, w%s3, lsl #2")
e("tst w%sp, #0xfcfcfcfc")
e("cset w%fl, ne")                      # a span beyond 2 cells: draw again
# ---------------------------------------------------------------- windows: v0, v1 (a); v2, v3 (b)
for g, t0, t1 in (("a", 0, 1), ("b", 2, 3)):
    e(f"madd x%p{g}, x%y{g}, x9, x8")
    e(f"add x%p{g}, x%p{g}, x%x{g}, lsl #1")
    e(f"ldr d{t0}, [x%p{g}]")
    e(f"add x%p{g}, x%p{g}, x9")
    e(f"ld1 {{v{t0}.d}}[1], [x%p{g}]")
    e(f"add x%p{g}, x%p{g}, x9")
    e(f"ldr d{t1}, [x%p{g}]")
    e(f"add x%p{g}, x%p{g}, x9")
    e(f"ld1 {{v{t1}.d}}[1], [x%p{g}]")
# 256 - 514 (ox + 4 oy) per group
e("mov w%k514, #514")
for g in "ab":
    e(f"add w%o{g}, w%x{g}, w%y{g}, lsl #2")
    e(f"mov w%k{g}, #256")
    e(f"msub w%k{g}, w%o{g}, w%k514, w%k{g}")
# ---------------------------------------------------------------- NEON: byte indices, corners
e("dup v22.8h, w%ka")
e("mla v22.8h, v24.8h, v4.h[0]")       # + 514 gx
e("mla v22.8h, v26.8h, v4.h[1]")       # + 2056 gy: g00's byte indices, group a
e("dup v23.8h, w%kb")
e("mla v23.8h, v25.8h, v4.h[0]")
e("mla v23.8h, v27.8h, v4.h[1]")       # group b
e("movi v29.16b, #2")
e("movi v6.16b, #8")
e("movi v7.16b, #10")
e("add v24.8h, v22.8h, v29.8h")        # g10, g01, g11 of group a
e("add v25.8h, v22.8h, v6.8h")
e("add v26.8h, v22.8h, v7.8h")
e("add v27.8h, v23.8h, v29.8h")        # group b
e("add v16.8h, v23.8h, v6.8h")
e("add v17.8h, v23.8h, v7.8h")
e("tbl v22.16b, {v0.16b, v1.16b}, v22.16b")
e("tbl v24.16b, {v0.16b, v1.16b}, v24.16b")
e("tbl v25.16b, {v0.16b, v1.16b}, v25.16b")
e("tbl v26.16b, {v0.16b, v1.16b}, v26.16b")
e("tbl v23.16b, {v2.16b, v3.16b}, v23.16b")
e("tbl v27.16b, {v2.16b, v3.16b}, v27.16b")
e("tbl v16.16b, {v2.16b, v3.16b}, v16.16b")
e("tbl v17.16b, {v2.16b, v3.16b}, v17.16b")
# differences: g10 - g00, g01 - g00, g11 - g10 - g01 + g00
for g00, g10, g01, g11 in ((22, 24, 25, 26), (23, 27, 16, 17)):
    e(f"sub v{g11}.8h, v{g11}.8h, v{g10}.8h")
    e(f"sub v{g10}.8h, v{g10}.8h, v{g00}.8h")
    e(f"sub v{g01}.8h, v{g01}.8h, v{g00}.8h")
    e(f"sub v{g11}.8h, v{g11}.8h, v{g01}.8h")
# ---------------------------------------------------------------- NEON: light
for acc0, acc1, g00, cx, cy, dd, bx, by, xy in ((6, 7, 22, 24, 25, 26, 18, 19, 5), (28, 29, 23, 27, 16, 17, 20, 21, 30)):
    e(f"umull v{acc0}.4s, v{g00}.4h, v4.h[2]")     # B^2 g00
    e(f"umull2 v{acc1}.4s, v{g00}.8h, v4.h[2]")
    e(f"smlal v{acc0}.4s, v{bx}.4h, v{cx}.4h")
    e(f"smlal2 v{acc1}.4s, v{bx}.8h, v{cx}.8h")
    e(f"smlal v{acc0}.4s, v{by}.4h, v{cy}.4h")
    e(f"smlal2 v{acc1}.4s, v{by}.8h, v{cy}.8h")
    e(f"smlal v{acc0}.4s, v{xy}.4h, v{dd}.4h")
    e(f"smlal2 v{acc1}.4s, v{xy}.8h, v{dd}.8h")
for r in (6, 7, 28, 29):
    e(f"ushl v{r}.4s, v{r}.4s, v31.4s")
e("uzp1 v6.8h, v6.8h, v7.8h")
e("uzp1 v7.8h, v28.8h, v29.8h")
e("shl v6.8h, v6.8h, #8")
e("shl v7.8h, v7.8h, #8")
e("add x%lp, x%fr, #32")                # the light's loads depend on %lp
e("st1 {v6.8h, v7.8h}, [x%lp], #32")


pixels(e, "pa", 0)
pixels(e, "pb", 16)
e("stp x%pat0, x%pbt0, [x10]")

# ---------------------------------------------------------------- registers
PIN = {"u": 0, "v": 1, "du": 2, "dv": 3, "ddu": 4, "ddv": 5, "fr": 11, "tab": 12, "fl": 2}
POOL = [15, 16, 17, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28]
FREEABLE = {"u": 0, "v": 1, "dv": 3, "ddu": 4, "ddv": 5, "tab": 12}  # operands reusable once read
KEEP = {2}  # the flag's register: not given out once du is read


out = allocate(L, PIN, POOL, FREEABLE, KEEP, ("fl",), ("du",))
open(sys.argv[1] if len(sys.argv) > 1 else "win16_in.s", "w").write("\n".join(out) + "\n")
