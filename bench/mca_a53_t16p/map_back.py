#!/usr/bin/env python3
# bench/mca_a53_t16p/map_back.py: the pair block's order searched on bench/count.sh's dump (the
# compiled code's registers, GCC's head and tail lines around the asm) back onto the
# generator's lines (bench/mca_a53_tiny/gen_pair_asm.py's register names), for --embed.
#   map_back.py REF.s DUMP_IN.s SEARCHED.s OUT.s HEAD TAIL
# REF.s: the asm's lines in the order DUMP_IN.s holds them (line i of REF.s is line HEAD + i of
# DUMP_IN.s); SEARCHED.s: order_search.py's output on DUMP_IN.s (--head=HEAD --tail=TAIL).
import sys
ref, din, srch, out = sys.argv[1:5]
head, tail = int(sys.argv[5]), int(sys.argv[6])
R = [l.strip() for l in open(ref) if l.strip()]
D = [l.strip() for l in open(din) if l.strip()][head:-tail or None]
S = [l.strip() for l in open(srch) if l.strip()][head:-tail or None]
assert len(R) == len(D) == len(S), (len(R), len(D), len(S))
idx = {}
for i, l in enumerate(D):
    idx.setdefault(l, []).append(i)
order = [idx[l].pop(0) for l in S]  # identical dump lines are identical generator lines
assert sorted(order) == list(range(len(R)))
open(out, "w").write("\n".join(R[i] for i in order) + "\n")
