#!/usr/bin/env python3
# bench/mca_a53_pair/assemble_run2l.py: runs_k3's block from its five searched regions (as
# gen_run2l.py's output splits at each tbz: region 0 run 2, regions 1 .. 4 the chunks of 8, 4,
# 2, 1 pixels; each region's branch timed as `.+4`), with the labels put back.
#   assemble_run2l.py R0.s R1.s R2.s R3.s R4.s OUT.s
import sys
regs = [[l.strip() for l in open(f) if l.strip()] for f in sys.argv[1:6]]
out = []
for i, r in enumerate(regs):
    if i < 4:
        assert r[-1].startswith("tbz"), r[-1]
        body, br = r[:-1], r[-1].replace(".+4", f"{i + 1}f")
    else:
        body, br = r, None
    out += body
    if i > 0:
        out.append(f"{i}:")  # after chunk i (region 4: the block's end)
    if br:
        out.append(br)
open(sys.argv[6], "w").write("\n".join(out) + "\n")
