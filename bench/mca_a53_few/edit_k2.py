#!/usr/bin/env python3
# bench/mca_a53_few/edit_k2.py IN.s OUT.s: steps_k3v_pass's block (names.py out) for a three-run
# span with its inputs where short_rest keeps them: S01 in v5, S23 = [S_2, S_3] in v19, zs23 =
# [z_2 + z_3, ..] in v1. Five lines change (the fifth: the undrawn run 2's factor read from v3,
# c01, not v16: v16 then only the block's scratch): D23 = S23 - [S_3, S_2] (ext v19, v19 then a
# reversed sub: lanes 2, 3 S_3 - S_2, the last run's delta, where the four-run block has its
# last run; lanes 0, 1 a run 2 that is not drawn), z_2 + z_3 from v1.d[0], and the last run's
# start st[0] (S_2, stored from v19's low half) instead of st[1]. D01 = [S_1, S_2] - S01 is
# the four-run block's (runs 0, 1 drawn by its first pass). Then dce.py with live out x23,
# x24, x25 (the last run, packed) and the flags (full).
import sys

EDITS = [("ext v7.16b, v19.16b, v7.16b, #8", "ext v7.16b, v19.16b, v19.16b, #8"),
         ("sub v7.4s, v7.4s, v19.4s", "sub v7.4s, v19.4s, v7.4s"),
         ("fmul d31, d31, v1.d[1]", "fmul d31, d31, v1.d[0]"),
         ("fmul v28.2d, v28.2d, v16.d[0]", "fmul v28.2d, v28.2d, v3.d[0]"),
         ("ldr x23, [x28, #8]", "ldr x23, [x28]")]
lines = [l.rstrip("\n") for l in open(sys.argv[1])]
for old, new in EDITS:
    idx = [i for i, l in enumerate(lines) if l == old]
    assert len(idx) == 1, old
    lines[idx[0]] = new
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
