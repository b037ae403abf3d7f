#!/usr/bin/env python3
# bench/mca_a53_few/rename_k1.py IN.s OUT.s: steps_k1v_pass's block (k1vp_s.s: steps_k3v_pass's
# lines with the two-run span's inputs) reading those inputs where short_rest keeps them: its
# S23' (= S01) from v5 instead of v19 and its S44' (= S23) from v19 instead of v7 (v7 then only
# its scratch: written by the first ext before any read), and its c23' (= c01) from v3, where
# c01 is (the one read of v16 before the block writes it: v16 then only its scratch). No line
# moves; the caller then copies no vector before the block (three 128-bit moves a span).
import re, sys

out = []
for l in open(sys.argv[1]):
    l = l.rstrip("\n")
    if l.startswith("ext v7.16b, v19.16b, v7.16b"):
        l = l.replace("ext v7.16b, v19.16b, v7.16b", "ext v7.16b, v5.16b, v19.16b")
    else:
        l = re.sub(r"\b([vqds])19\b", r"\g<1>5", l)
    if l == "fmul v28.2d, v28.2d, v16.d[0]":
        l = "fmul v28.2d, v28.2d, v3.d[0]"
    out.append(l)
open(sys.argv[2], "w").write("\n".join(out) + "\n")
