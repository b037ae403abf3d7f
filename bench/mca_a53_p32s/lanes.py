#!/usr/bin/env python3
# bench/mca_a53_p32s/lanes.py: drops the lines of steps_k1v_pass / steps_k2v_pass
# (asm/span_persp_a64few.h, as bench/mca_a53_few/names.py gives them) that only compute
# vector lanes nothing reads (bench/mca_a53_few/dce.py keeps them: it sees registers, not lanes).
#   lanes.py k1|k2 IN.s OUT.s
# D23's lanes 0, 1 (v28: run 0 again in the two-run block, read from D01 by its pass; an
# undrawn run 2 in the three-run block): saddw, fsub, fmul, fcvtzs of v28 and sqxtn v1.2s (v1's
# low half is then zs's bits, read by no lane that is kept). The two-run block's D01 lanes 2, 3
# (S_0 - S_1: its pass reads D01's low half only): saddw2, fsub, fmul, fcvtzs of v27 and
# sqxtn2 v6.
import sys

D23_LO = ["saddw v28.2d, v6.2d, v7.2s", "fsub v28.2d, v28.2d, v6.2d", "fmul v28.2d, v28.2d, v3.d[0]",
          "fcvtzs v28.2d, v28.2d", "sqxtn v1.2s, v28.2d"]
D01_HI = ["saddw2 v27.2d, v6.2d, v0.4s", "fsub v27.2d, v27.2d, v6.2d", "fmul v27.2d, v27.2d, v3.d[1]",
          "fcvtzs v27.2d, v27.2d", "sqxtn2 v6.4s, v27.2d"]
which, src, dst = sys.argv[1:4]
drop = D23_LO + (D01_HI if which == "k1" else [])
lines = [l.rstrip("\n") for l in open(src) if l.strip()]
for d in drop:
    assert lines.count(d) == 1, d
out = [l for l in lines if l not in drop]
open(dst, "w").write("\n".join(out) + "\n")
print(f"{len(lines) - len(out)} lines dropped", file=sys.stderr)
