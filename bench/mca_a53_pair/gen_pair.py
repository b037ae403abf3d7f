#!/usr/bin/env python3
# bench/mca_a53_pair/gen_pair.py: writes pair.vs, the paired short-span sample block
# (asm/span_persp_a64pair.h, short_samples2) with virtual vector registers, in a level-by-level
# order (the five reciprocal chains interleaved) for alloc.py and the order search.
L = []
a = L.append
a("// persp_short_inl's sample block for two spans A, B at once (asm/span_persp_a64pair.h,")
a("// short_samples2): each vector [span A's value, span B's value] of one sample k (0 .. 4).")
a("// x0 = &A (PerspSpan), x1 = &B, x2 = out (two ShortSamples), x3 = kPairConsts,")
a("// x4 = kShortOffsets + 32 nA, x5 = kShortOffsets + 32 nB; x6 .. x15 scratch.")
for l in ["add x6, x0, #32", "add x7, x0, #40", "add x8, x0, #56", "add x9, x1, #8", "add x10, x1, #32",
          "add x11, x1, #40", "add x12, x1, #48", "add x13, x1, #56", "add x14, x5, #8", "add x15, x5, #16"]:
    a(l)
a("ldr q@k16, [x3]")
a("ldr d@P0, [x0, #48]"); a("ld1 {v@P0.d}[1], [x12]")
a("ldr d@O0, [x4]"); a("ld1 {v@O0.d}[1], [x5]")
a("ldr d@O1, [x4, #8]"); a("ld1 {v@O1.d}[1], [x14]")
a("ldr d@O2, [x4, #16]"); a("ld1 {v@O2.d}[1], [x15]")
a("ldr d@zix, [x0, #8]"); a("ld1 {v@zix.d}[1], [x9]")
a("ldr d@b4, [x0]"); a("ld1 {v@b4.d}[1], [x1]")
a("ldr q@one, [x3, #16]")
for k in range(4):
    a(f"mov v@b{k}.16b, v@b4.16b")
a("ldp q@kq, q@kmin, [x3, #64]")
a("fadd v@P1.2d, v@P0.2d, v@k16.2d")
a("fadd v@pos2.2d, v@P0.2d, v@O0.2d")
a("fmla v@b0.2d, v@zix.2d, v@P0.2d")
a("fadd v@P2.2d, v@P1.2d, v@k16.2d")
a("fadd v@pos3.2d, v@P1.2d, v@O1.2d")
a("fmla v@b1.2d, v@zix.2d, v@P1.2d")
a("fmla v@b2.2d, v@zix.2d, v@pos2.2d")
a("fadd v@pos4.2d, v@P2.2d, v@O2.2d")
a("fmla v@b3.2d, v@zix.2d, v@pos3.2d")
a("fmla v@b4.2d, v@zix.2d, v@pos4.2d")
pos = ["P0", "P1", "pos2", "pos3", "pos4"]
for k in range(5):
    a(f"fmaxnm v@b{k}.2d, v@b{k}.2d, v@kmin.2d")
# The uv products (positions only), spread over the chains' levels below.
uv = []
for X, px, pxo, uvxr in [("A", "x0", "x6", "x7"), ("B", "x1", "x10", "x11")]:
    uv.append([f"ldr d@uvx{X}, [{px}, #24]", f"ld1 {{v@uvx{X}.d}}[1], [{uvxr}]",
               f"ldr d@uv{X}4, [{px}, #16]", f"ld1 {{v@uv{X}4.d}}[1], [{pxo}]"])
    lane = 0 if X == "A" else 1
    for k in range(5):
        uv.append(([f"mov v@uv{X}{k}.16b, v@uv{X}4.16b"] if k < 4 else []) +
                  [f"fmla v@uv{X}{k}.2d, v@uvx{X}.2d, v@{pos[k]}.d[{lane}]"])
chk = [[f"orr v@h{k}.16b, v@b{k}.16b, v@mask.16b"] for k in range(5)]
chk = [["ldp q@mask, q@big, [x3, #32]"]] + chk + [
    ["fmax v@m01.2d, v@b0.2d, v@b1.2d"], ["fmax v@m23.2d, v@b2.2d, v@b3.2d"],
    ["fmax v@m01.2d, v@m01.2d, v@m23.2d"], ["fmax v@m01.2d, v@m01.2d, v@b4.2d"],
    ["cmhs v@m01.2d, v@m01.2d, v@big.2d"], ["uminp v@u01.4s, v@h0.4s, v@h1.4s"],
    ["uminp v@u23.4s, v@h2.4s, v@h3.4s"], ["uminp v@u4.4s, v@h4.4s, v@m01.4s"],
    ["umax v@u01.4s, v@u01.4s, v@u23.4s"], ["umax v@u01.4s, v@u01.4s, v@u4.4s"], ["umaxv s@u01, v@u01.4s"]]
levels = [lambda k: [f"frecpe v@y{k}.2d, v@b{k}.2d"],
          lambda k: [f"frecps v@t{k}.2d, v@b{k}.2d, v@y{k}.2d"],
          lambda k: [f"fmul v@y{k}.2d, v@y{k}.2d, v@t{k}.2d"],
          lambda k: [f"frecps v@t{k}.2d, v@b{k}.2d, v@y{k}.2d"],
          lambda k: [f"fmul v@y{k}.2d, v@y{k}.2d, v@t{k}.2d", f"mov v@r{k}.16b, v@one.16b"],
          lambda k: [f"fmls v@r{k}.2d, v@b{k}.2d, v@y{k}.2d"],
          lambda k: [f"fmla v@y{k}.2d, v@y{k}.2d, v@r{k}.2d", f"mov v@s{k}.16b, v@one.16b"],
          lambda k: [f"fmls v@s{k}.2d, v@b{k}.2d, v@y{k}.2d"],
          lambda k: [f"fmla v@y{k}.2d, v@y{k}.2d, v@s{k}.2d"]]
fill = chk + uv
for li, lev in enumerate(levels):
    for k in range(5):
        for l in lev(k):
            a(l)
    # one or two filler groups after each level
    for _ in range(3 if li < 8 else 99):
        if fill:
            for l in fill.pop(0):
                a(l)
a("fmov w6, s@u01")
a("cmn w6, #1")
a("b.ne 2f")
a("ldr q@onef, [x3, #16]")
for k in range(5):
    a(f"fdiv v@y{k}.2d, v@onef.2d, v@b{k}.2d")
a("2:")
a("ld1r {v@mA.2d}, [x8]")
a("ld1r {v@mB.2d}, [x13]")
for k in range(5):
    for X in "AB":
        lane = 0 if X == "A" else 1
        a(f"fmul v@uv{X}{k}.2d, v@uv{X}{k}.2d, v@y{k}.d[{lane}]")
a("fadd v@s01.2d, v@y0.2d, v@y1.2d")
a("fadd v@s12.2d, v@y1.2d, v@y2.2d")
a("fadd v@s23.2d, v@y2.2d, v@y3.2d")
a("fadd v@s34.2d, v@y3.2d, v@y4.2d")
a("fmul v@zck.2d, v@zix.2d, v@kq.2d")
for k in range(5):
    for X in "AB":
        a(f"fcvtzu v@uv{X}{k}.2d, v@uv{X}{k}.2d, #16")
a("trn1 v@zs01A.2d, v@s01.2d, v@s12.2d")
a("trn2 v@zs01B.2d, v@s01.2d, v@s12.2d")
a("trn1 v@zs23A.2d, v@s23.2d, v@s34.2d")
a("trn2 v@zs23B.2d, v@s23.2d, v@s34.2d")
for X in "AB":
    a(f"uqxtn v@S01{X}.2s, v@uv{X}0.2d"); a(f"uqxtn v@S23{X}.2s, v@uv{X}2.2d"); a(f"uqxtn v@S44{X}.2s, v@uv{X}4.2d")
a("fmul v@c01A.2d, v@zs01A.2d, v@zck.d[0]")
a("fmul v@c01B.2d, v@zs01B.2d, v@zck.d[1]")
a("fmul v@c23A.2d, v@zs23A.2d, v@zck.d[0]")
a("fmul v@c23B.2d, v@zs23B.2d, v@zck.d[1]")
for X in "AB":
    a(f"uqxtn2 v@S01{X}.4s, v@uv{X}1.2d"); a(f"uqxtn2 v@S23{X}.4s, v@uv{X}3.2d"); a(f"uqxtn2 v@S44{X}.4s, v@uv{X}4.2d")
for X in "AB":
    for s in ["S01", "S23", "S44"]:
        a(f"umin v@{s}{X}.4s, v@{s}{X}.4s, v@m{X}.4s")
for X, o in [("A", 0), ("B", 112)]:
    a(f"stp q@S01{X}, q@S23{X}, [x2, #{o}]")
    a(f"stp q@S44{X}, q@zs01{X}, [x2, #{o + 32}]")
    a(f"stp q@zs23{X}, q@c01{X}, [x2, #{o + 64}]")
    a(f"str q@c23{X}, [x2, #{o + 96}]")
open("pair.vs", "w").write("\n".join(L) + "\n")
