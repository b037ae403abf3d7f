#!/usr/bin/env python3
# bench/mca_a53_palette/gen_scales.py: writes the naive (unsearched) aarch64 loop bodies of
# expand_palette_neon at scales 2, 3 and 4 (asm/neon_palette.h) as scaleS_in.s, the input of
# bench/order_search.py. Registers as the header binds them (to_inline.py operands):
#   x0 row 0, x20 / x21 / x22 rows 1 .. 3 (32-bit words, post-incremented), x9 indices,
#   x18 row 0's end, x27 palette; scratch x1 .. x8, x10 .. x17.
# Scale 2: 16 pixels an iteration, each colour c doubled to (c, c) by one orr and stored by stp
# to both rows. Scale 3: 8 pixels, a pair of colours a, b as three words (a, a) (a, b) (b, b).
# Scale 4: 8 pixels, (c, c) stored twice on each of the four rows.
import sys

Q = "--q" in sys.argv  # scales 2 and 3 stored from q registers

SCRATCH = [1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17]
ROWS = [0, 20, 21, 22]


def extract(word_reg, i, dst):
    if i == 0:
        return f"and x{dst}, x{word_reg}, #0xff"
    if i == 7:
        return f"lsr x{dst}, x{word_reg}, #56"
    return f"ubfx x{dst}, x{word_reg}, #{8 * i}, #8"


def gen(scale):
    g = 16 if scale == 2 else 8
    out = []
    if g == 16:
        w0, w1 = 4, 14
        out.append(f"ldp x{w0}, x{w1}, [x9], #16")
        # value registers: index words last, so they are extracted from before being reused
        vals = [r for r in SCRATCH if r not in (w0, w1)] + [w0, w1]
        order = list(range(16))
        # extract pixel 7 of word 0 and pixel 15 of word 1 last (into the words themselves)
        ex = []
        for p in range(16):
            word = w0 if p < 8 else w1
            ex.append((p, word))
        regs = {}
        free = [r for r in SCRATCH if r not in (w0, w1)]
        for p, word in ex:
            if (p == 7):
                regs[p] = w0
            elif p == 15:
                regs[p] = w1
            else:
                regs[p] = free.pop(0)
        for p, word in ex:
            out.append(extract(word, p % 8, regs[p]))
    else:
        w0 = 17
        out.append(f"ldr x{w0}, [x9], #8")
        regs = {p: SCRATCH[p] for p in range(7)}
        regs[7] = w0
        for p in range(8):
            out.append(extract(w0, p, regs[p]))
    for p in range(g):
        out.append(f"ldr w{regs[p]}, [x27, x{regs[p]}, lsl #2]")
    words = []  # per row: the x registers stored in order
    if scale == 3:
        mids = {}
        spare = [r for r in SCRATCH if r not in regs.values()]
        for k in range(g // 2):
            m = spare.pop(0)
            mids[k] = m
            out.append(f"orr x{m}, x{regs[2 * k]}, x{regs[2 * k + 1]}, lsl #32")
    if scale == 4:
        # (c, c, c, c) by one dup each; each row's 32 words as four stp of q registers
        for p in range(g):
            out.append(f"dup v{p}.4s, w{regs[p]}")
        for j in range(scale):
            r = ROWS[j]
            for i in range(0, g, 2):
                out.append(f"stp q{i}, q{i + 1}, [x{r}, #{16 * i}]")
            out.append(f"add x{r}, x{r}, #{16 * g}")
        out.append("cmp x18, x0")
        out.append("b.ne 1b")
        return out
    for p in range(g):
        out.append(f"orr x{regs[p]}, x{regs[p]}, x{regs[p]}, lsl #32")
    if Q:
        # the words two at a time into q registers (fmov, ins), each row stored as stp of q
        words = [regs[p] for p in range(g)] if scale == 2 else sum(
            ([regs[2 * k], mids[k], regs[2 * k + 1]] for k in range(g // 2)), [])
        nq = len(words) // 2
        for q in range(nq):
            out.append(f"fmov d{q}, x{words[2 * q]}")
            out.append(f"mov v{q}.d[1], x{words[2 * q + 1]}")
        for j in range(scale):
            r = ROWS[j]
            for i in range(0, nq - 1, 2):
                out.append(f"stp q{i}, q{i + 1}, [x{r}, #{16 * i}]")
            if nq % 2:
                out.append(f"str q{nq - 1}, [x{r}, #{16 * (nq - 1)}]")
            out.append(f"add x{r}, x{r}, #{16 * nq}")
        out.append("cmp x18, x0")
        out.append("b.ne 1b")
        return out
    if scale == 2:
        words = [regs[p] for p in range(g)]
    elif scale == 4:
        words = [regs[p] for p in range(g) for _ in (0, 1)]
    else:
        for k in range(g // 2):
            words += [regs[2 * k], mids[k], regs[2 * k + 1]]
    nbytes = 8 * len(words)
    for j in range(scale):
        r = ROWS[j]
        for i in range(0, len(words), 2):
            off = 8 * i
            out.append(f"stp x{words[i]}, x{words[i + 1]}, [x{r}, #{off}]")
        out.append(f"add x{r}, x{r}, #{nbytes}")
    out.append("cmp x18, x0")
    out.append("b.ne 1b")
    return out


if __name__ == "__main__":
    for s in (2, 3, 4):
        open(f"scale{s}{'q' if Q and s != 4 else ''}_in.s", "w").write("\n".join(gen(s)) + "\n")


# ARMv7 (Thumb-2 + NEON), 4 source pixels an iteration: r9 indices, r8 palette, r0 the output
# pointer walking down the S rows and back (post-increments: r1 = stride - 32 bytes between a
# row's two stores, r2 = from the last row to the next group's row 0 ... as the header computes
# them), r10 the indices' end; scratch r3 .. r6, d16 .. d23. Colour c as (c, c) by vdup, scale
# 3's (a, b) by one vmov from two core registers. Memory tags for order_search.py --arch=armv7.
def gen_v7(scale):
    out = ["ldr r3, [r9], #4 @m=src", "uxtb r4, r3", "ubfx r5, r3, #8, #8", "ubfx r6, r3, #16, #8",
           "lsrs r3, r3, #24"]
    c = ["r4", "r5", "r6", "r3"]
    out += [f"ldr {r}, [r8, {r}, lsl #2] @m=pal" for r in c]
    if scale == 2:
        out += [f"vdup.32 d{16 + i}, {c[i]}" for i in range(4)]
        stores = [["{d16-d19}"]]
    elif scale == 3:
        out += ["vdup.32 d16, r4", "vmov d17, r4, r5", "vdup.32 d18, r5", "vdup.32 d19, r6", "vmov d20, r6, r3",
                "vdup.32 d21, r3"]
        stores = [["{d16-d19}", "{d20-d21}"]]
    else:
        out += [f"vdup.32 q{8 + i}, {c[i]}" for i in range(4)]
        stores = [["{d16-d19}", "{d20-d23}"]]
    for j in range(scale):
        lists = stores[0]
        last = j == scale - 1
        if len(lists) == 1:
            out.append(f"vst1.32 {lists[0]}, [r0], {'r2' if last else 'r1'} @m=dst")
        else:
            out.append(f"vst1.32 {lists[0]}, [r0]! @m=dst")
            out.append(f"vst1.32 {lists[1]}, [r0], {'r2' if last else 'r1'} @m=dst")
    out += ["cmp r9, r10", "bne 1b"]
    return out


# Scale 1 on ARMv7: 8 pixels an iteration, the indices as two core loads (the rows have no
# alignment), 8 extracts (the index words reused for pixels 3 and 7), 8 palette loads into core
# registers, 4 strd (dst is word-aligned: uint32_t). r0 dst, r9 indices, r10 their end, r8 the
# palette; scratch r1 .. r6, ip, lr.
def gen_v7_scale1():
    out = ["ldr r4, [r9, #4] @m=src", "ldr r3, [r9], #8 @m=src"]
    regs = ["r5", "r6", "r1", "r3", "r2", "ip", "lr", "r4"]
    ex = []
    for p in range(8):
        w, i, d = ("r3" if p < 4 else "r4"), p % 4, regs[p]
        ex.append(f"uxtb {d}, {w}" if i == 0 else f"lsr {d}, {w}, #24" if i == 3 else f"ubfx {d}, {w}, #{8 * i}, #8")
    out += [e for k, e in enumerate(ex) if k not in (3, 7)] + [ex[3], ex[7]]
    out += [f"ldr {r}, [r8, {r}, lsl #2] @m=pal" for r in regs]
    out += [f"strd {regs[2 * k]}, {regs[2 * k + 1]}, [r0, #{8 * k}] @m=dst" for k in range(4)]
    out += ["add r0, r0, #32", "cmp r9, r10", "bne 1b"]
    return out


if __name__ == "__main__" and "--v7" in sys.argv:
    open("v7scale1_in.s", "w").write("\n".join(gen_v7_scale1()) + "\n")
    for s in (2, 3, 4):
        open(f"v7scale{s}_in.s", "w").write("\n".join(gen_v7(s)) + "\n")
