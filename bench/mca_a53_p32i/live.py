#!/usr/bin/env python3
# bench/mca_a53_p32i/live.py BLOCK.s ..: the core (x) and vector (v) registers live along each
# block (bench/order_search.py's syntax; live out x23 x24 x25): the peak and the peak of each
# tenth of the block (why two span blocks' vector parts do not fit side by side: README.md).
import sys
sys.path.insert(0, '/work/wt-p32i/bench')
from order_search import parse
for f in sys.argv[1:]:
    L = [l.strip() for l in open(f) if l.strip()]
    # backward liveness
    live = {'x23', 'x24', 'x25'}
    prof = []
    for l in reversed(L):
        r, w, st, b = parse(l)
        live = (live - {x for x in w if x not in r}) | (r - {'nzcv'})
        prof.append((sum(1 for x in live if x[0] == 'x'), sum(1 for x in live if x[0] == 'v')))
    prof.reverse()
    print(f, "peak x", max(p[0] for p in prof), "peak v", max(p[1] for p in prof))
    print(" v by tenth:", [max(p[1] for p in prof[i:i + len(L)//10]) for i in range(0, len(L), len(L)//10)])
    print(" x by tenth:", [max(p[0] for p in prof[i:i + len(L)//10]) for i in range(0, len(L), len(L)//10)])
