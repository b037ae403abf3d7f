#!/usr/bin/env python3
# bench/mca_a53_persp/lin_pass_subv.py: rewrites a (searched) linear pass body (gen_lin_pass.py's
# allocated form) so that each steps16_packed takes its v delta as (b >> 32) - (a >> 32) in
# one shifted-register sub (`lsr dv, b, #32; sub dv, dv, a, lsr #32`) instead of two shifts and
# a sub: the `lsr t, a, #32` goes, the `sub wdv, wdv, wt` reads a itself. Both operands are
# below 2^31, so the 64-bit difference's low word is the 32-bit one the rest reads.
#   lin_pass_subv.py IN.s OUT.s
import re, sys

lines = open(sys.argv[1]).read().split("\n")
samples = {"x25", "x26", "x27"}
out, dropped = list(lines), set()
for i, l in enumerate(lines):
    m = re.fullmatch(r"lsr (x\d+), (x\d+), #32", l.strip())
    if not m or m.group(2) not in samples:
        continue
    t, a = m.group(1), m.group(2)
    # the sub that reads t (as w) as its second operand, before t is written again
    for j in range(i + 1, len(lines)):
        s = lines[j].strip()
        m2 = re.fullmatch(r"sub w(\d+), w(\d+), w%s" % t[1:], s)
        if m2 and m2.group(1) == m2.group(2):
            out[j] = f"sub x{m2.group(1)}, x{m2.group(1)}, {a}, lsr #32"
            dropped.add(i)
            break
        if re.search(r"\b[xw]%s\b" % t[1:], s):
            break
open(sys.argv[2], "w").write("\n".join(l for i, l in enumerate(out) if i not in dropped))
sys.stderr.write(f"{len(dropped)} shifts folded\n")
