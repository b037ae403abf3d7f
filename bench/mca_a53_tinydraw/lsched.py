#!/usr/bin/env python3
# bench/mca_a53_tinydraw/lsched.py: a greedy list schedule of one straight-line aarch64 block
# (gen_chunk_asm.py's raw blocks) for an in-order dual-issue core with the latencies of
# llvm-mca's Cortex-A53 model (add / orr 3 (shifted or not), lsr 2, madd 4, ldrb 4; two ALUs,
# one multiplier, one load / store pipe), keeping every register dependency (read after write
# with its latency, write after read and write after write in order) and the stores' order.
# The start order for ../order_search.py (its search from the generator's pixel-by-pixel order
# stalled at 77 cycles on the 15-pixel block, about 51 issue-bound).
#   lsched.py IN.s > OUT.s
import sys

sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__file__), ".."))
from order_search import parse  # (reads, writes, store, barrier) of a line

lines = [l.strip() for l in open(sys.argv[1]) if l.strip()]
info = [parse(l) for l in lines]
op = [l.split()[0] for l in lines]
lat = {"madd": 4, "ldrb": 4, "lsr": 2}
unit = {"madd": "mac", "ldrb": "ls", "str": "ls", "strh": "ls", "strb": "ls"}
n = len(lines)
# dependencies: (pred, succ, min cycle distance)
preds = [[] for _ in range(n)]
for j in range(n):
    rj, wj, sj, _ = info[j]
    for i in range(j):
        ri, wi, si, _ = info[i]
        if wi & rj:
            preds[j].append((i, lat.get(op[i], 3)))
        elif (ri & wj) or (wi & wj) or (si and sj):
            preds[j].append((i, 0))
# priority: longest latency path to the end
prio = [0] * n
for i in reversed(range(n)):
    succ = [prio[j] + d for j in range(i + 1, n) for (p, d) in preds[j] if p == i]
    prio[i] = max(succ, default=0) + lat.get(op[i], 3)
done, t_issue, order, cycle = set(), {}, [], 0
while len(order) < n:
    used, slots = set(), 0
    while slots < 2:
        ready = [j for j in range(n) if j not in done and
                 all(p in done and t_issue[p] + d <= cycle and (d > 0 or t_issue[p] <= cycle) for p, d in preds[j])
                 and unit.get(op[j], "alu" + str(slots)) not in used]
        # in order: a line whose zero-distance predecessor issued this cycle may follow it
        if not ready:
            break
        j = max(ready, key=lambda k: (prio[k], -k))
        used.add(unit.get(op[j], "alu" + str(slots)))
        done.add(j)
        t_issue[j] = cycle
        order.append(j)
        slots += 1
    cycle += 1
print("\n".join(lines[j] for j in order))
