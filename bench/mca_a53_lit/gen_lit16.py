#!/usr/bin/env python3
# bench/mca_a53_lit/gen_lit16.py: writes lit16_in.s, the aarch64 block that draws one full
# 16-pixel run of the single-pass lit span kernel (asm/lit_span.h; asm/lit_span_a64.h,
# lit16_block), in a plain dependency order; list_sched.py and bench/order_search.py then
# order it for the Cortex-A53 model (README.md).
#
# Each group of 8 pixels takes its light from two cells: A, its first pixel's, and B, its
# last pixel's; a lane uses B when its cell differs from A's. When both groups lie in one
# cell each (their first and last pixels' cells agree) the block skips cells B (branch to 1:). That is
# exact when every pixel of the group is in A or B: the positions are monotonic within the
# group (the steps keep their sign: the first and last steps' signs agree) and the cells
# differ by at most one column or one row, not both. Otherwise the block flags the group
# and the caller draws it again.
#
# Operand placeholders (bench/to_inline.py maps them to the inline asm's operands):
#   x0 u, x1 v, x2 du, x3 dv, x4 ddu, x5 ddv (read-write; x2 and x3 return the flags of
#   pixels 0-7 and 8-15: nonzero = draw again), x6 texels, x7 colormap, x8 grid (16-bit),
#   x9 grid row stride in bytes, x10 dest, x11 frame (texel indices, light, wrap: see
#   LitA64Frame), x12 the mip's table (LitA64Tab; read-write: reused once read).
# Core scratch: x13-x17, x19-x28 (core values are named %name here and given registers by a
# linear scan in program order); vectors: v0-v7, v16-v31 (v8-v15 untouched: callee-saved).
import sys

from lit_gen import allocate, head, pixels

L = []


def e(s):
    L.append(s)


head(e)
# ---------------------------------------------------------------- NEON: weights
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

# ---------------------------------------------------------------- core: cells and tests
e("ldp w%l16, w%s, [x%tab, #176]")    # 16 + log B, S = 2 log B


def track(c, d, dd):
    """Positions 7, 8, 15 of coordinate c and the steps' sign changes within each group."""
    e(f"add w%{c}t3, w%{dd}, w%{dd}, lsl #1")            # 3 dd
    e(f"add w%{c}sa, w%{d}, w%{c}t3, lsl #1")            # d_6 = d + 6 dd
    e(f"eor w%{c}sa, w%{c}sa, w%{d}")
    e(f"add w%{c}q, w%{d}, w%{c}t3")
    e(f"lsl w%{c}7, w%{c}q, #3")
    e(f"sub w%{c}7, w%{c}7, w%{c}q")                     # 7 d + 21 dd
    e(f"add w%{c}7, w%{c}, w%{c}7")                      # position 7
    e(f"add w%{c}d8, w%{d}, w%{dd}, lsl #3")             # d_8
    e(f"sub w%{c}8, w%{c}d8, w%{dd}")                    # d + 7 dd
    e(f"add w%{c}8, w%{c}7, w%{c}8")                     # position 8
    e(f"add w%{c}r, w%{c}d8, w%{c}t3")
    e(f"lsl w%{c}15, w%{c}r, #3")
    e(f"sub w%{c}15, w%{c}15, w%{c}r")                   # 7 d_8 + 21 dd
    e(f"add w%{c}15, w%{c}8, w%{c}15")                   # position 15
    e(f"add w%{c}sb, w%{c}d8, w%{c}t3, lsl #1")          # d_14
    e(f"eor w%{c}sb, w%{c}sb, w%{c}d8")


def cellxy(g, pu, pv):
    e(f"lsr w%{g}x, w%{pu}, w%l16")
    e(f"lsr w%{g}y, w%{pv}, w%l16")


def cell(g, cvec, acc0, acc1):
    """Corners of the cell (%{g}x, %{g}y): C = [cx, cy, dd, 0] (16-bit) in d{cvec},
    B^2 g00 in v{acc0}, v{acc1}."""
    e(f"madd x%{g}p, x%{g}y, x9, x8")
    e(f"add x%{g}p, x%{g}p, x%{g}x, lsl #1")
    e(f"ldrh w%{g}00, [x%{g}p]")
    e(f"ldrh w%{g}10, [x%{g}p, #2]")
    e(f"add x%{g}p, x%{g}p, x9")
    e(f"ldrh w%{g}01, [x%{g}p]")
    e(f"ldrh w%{g}11, [x%{g}p, #2]")
    e(f"sub w%{g}11, w%{g}11, w%{g}10")     # g11 - g10
    e(f"sub w%{g}10, w%{g}10, w%{g}00")     # cx = g10 - g00
    e(f"sub w%{g}01, w%{g}01, w%{g}00")     # cy = g01 - g00
    e(f"sub w%{g}11, w%{g}11, w%{g}01")     # dd = g11 - g10 - g01 + g00
    e(f"lsl w%{g}00, w%{g}00, w%s")         # B^2 g00
    e(f"bfi w%{g}10, w%{g}01, #16, #16")
    e(f"bfi x%{g}10, x%{g}11, #32, #16")
    e(f"fmov d{cvec}, x%{g}10")
    e(f"dup v{acc0}.4s, w%{g}00")
    e(f"dup v{acc1}.4s, w%{g}00")


def test(a, b, out):
    """out |= nonzero when cells a, b differ by more than one step or in both axes."""
    e(f"sub w%{out}dx, w%{b}x, w%{a}x")
    e(f"sub w%{out}dy, w%{b}y, w%{a}y")
    e(f"add w%{out}ax, w%{out}dx, #1")
    e(f"add w%{out}ay, w%{out}dy, #1")
    e(f"cmp w%{out}ax, #2")
    e(f"cset w%{out}t, hi")
    e(f"cmp w%{out}ay, #2")
    e(f"cinc w%{out}t, w%{out}t, hi")
    e(f"cmp w%{out}dx, #0")
    e(f"ccmp w%{out}dy, #0, #4, ne")
    e(f"cinc w%{out}t, w%{out}t, ne")
    e(f"orr w%{out}, w%{out}, w%{out}t")


def light(acc0, acc1, c, bx, by, xy):
    """num = B^2 g00 + B fx cx + B fy cy + fx fy dd (32-bit lanes) from the cell in d{c}."""
    e(f"smlal v{acc0}.4s, v{bx}.4h, v{c}.h[0]")
    e(f"smlal2 v{acc1}.4s, v{bx}.8h, v{c}.h[0]")
    e(f"smlal v{acc0}.4s, v{by}.4h, v{c}.h[1]")
    e(f"smlal2 v{acc1}.4s, v{by}.8h, v{c}.h[1]")
    e(f"smlal v{acc0}.4s, v{xy}.4h, v{c}.h[2]")
    e(f"smlal2 v{acc1}.4s, v{xy}.8h, v{c}.h[2]")


track("u", "du", "ddu")
track("v", "dv", "ddv")
# a step changing sign within a group: flag it (the caller draws it again)
e("orr w%fa, w%usa, w%vsa")
e("orr w%fb, w%usb, w%vsb")
e("lsr w%fa, w%fa, #31")
e("lsr w%fb, w%fb, #31")
# any group not in one cell (its first and last pixels' cells differ)?
e("eor w%x1, w%u, w%u7")
e("eor w%x2, w%v, w%v7")
e("eor w%x3, w%u8, w%u15")
e("eor w%x4, w%v8, w%v15")
e("orr w%x1, w%x1, w%x2")
e("orr w%x3, w%x3, w%x4")
e("orr w%x1, w%x1, w%x3")
e("lsr w%nb, w%x1, w%l16")
cellxy("aa", "u", "v")                # group a, cell A (pixel 0), B (pixel 7)
cellxy("ab", "u7", "v7")
cellxy("ba", "u8", "v8")              # group b, cell A (pixel 8), B (pixel 15)
cellxy("bb", "u15", "v15")
cell("aa", 0, 26, 27)
cell("ba", 2, 28, 29)
# ---------------------------------------------------------------- NEON: light of cells A
# num = B^2 g00 + B fx cx + B fy cy + fx fy dd, then (num >> S + 8) (16-bit): group a in v26,
# group b in v27
for acc0, acc1, c, bx, by, xy in ((26, 27, 0, 18, 19, 5), (28, 29, 2, 20, 21, 30)):
    light(acc0, acc1, c, bx, by, xy)
for r in (26, 27, 28, 29):
    e(f"ushl v{r}.4s, v{r}.4s, v31.4s")
e("uzp1 v26.8h, v26.8h, v27.8h")
e("uzp1 v27.8h, v28.8h, v29.8h")
e("cbz w%nb, 1f")
# ---------------------------------------------------------------- cells B (groups that cross)
cell("ab", 1, 22, 23)
cell("bb", 3, 24, 25)
test("aa", "ab", "fa")
test("ba", "bb", "fb")
for acc0, acc1, c, bx, by, xy in ((22, 23, 1, 18, 19, 5), (24, 25, 3, 20, 21, 30)):
    light(acc0, acc1, c, bx, by, xy)
for r in (22, 23, 24, 25):
    e(f"ushl v{r}.4s, v{r}.4s, v31.4s")
e("uzp1 v22.8h, v22.8h, v23.8h")
e("uzp1 v24.8h, v24.8h, v25.8h")
# lanes whose cell differs from the group's first pixel's: (U ^ U_0) | (V ^ V_0) > B - 1
e("ldr q29, [x%tab, #128]")           # B - 1
e("dup v0.8h, v6.h[0]")
e("dup v2.8h, v16.h[0]")
e("eor v0.16b, v0.16b, v6.16b")
e("eor v2.16b, v2.16b, v16.16b")
e("orr v0.16b, v0.16b, v2.16b")
e("cmhi v0.8h, v0.8h, v29.8h")
e("dup v4.8h, v7.h[0]")
e("dup v2.8h, v17.h[0]")
e("eor v4.16b, v4.16b, v7.16b")
e("eor v2.16b, v2.16b, v17.16b")
e("orr v4.16b, v4.16b, v2.16b")
e("cmhi v4.8h, v4.8h, v29.8h")
e("bit v26.16b, v22.16b, v0.16b")
e("bit v27.16b, v24.16b, v4.16b")
e("1:")
e("shl v26.8h, v26.8h, #8")
e("shl v27.8h, v27.8h, #8")
e("add x%lp, x%fr, #32")                # the light's loads depend on %lp, as above
e("st1 {v26.8h, v27.8h}, [x%lp], #32")


pixels(e, "pa", 0)
pixels(e, "pb", 16)
e("stp x%pat0, x%pbt0, [x10]")

# ---------------------------------------------------------------- registers
PIN = {"u": 0, "v": 1, "du": 2, "dv": 3, "ddu": 4, "ddv": 5, "fr": 11, "tab": 12, "fa": 2, "fb": 3}
POOL = [13, 14, 15, 16, 17, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28]
FREEABLE = {"u": 0, "v": 1, "du": 2, "dv": 3, "ddu": 4, "ddv": 5, "tab": 12}  # operands reusable once read
KEEP = {2, 3}  # the flags' registers: not given out once the steps are read


out = allocate(L, PIN, POOL, FREEABLE, KEEP, ("fa", "fb"), ("du", "dv"))
open(sys.argv[1] if len(sys.argv) > 1 else "lit16_in.s", "w").write("\n".join(out) + "\n")
