#!/usr/bin/env python3
# bench/mca_a53_persp/list_sched.py: a greedy list schedule of one loop body (first line a
# label, last line the loop branch) for an in-order, dual-issue core whose results write back
# in program order (LLVM 14's Cortex-A53 model as llvm-mca runs it: latencies taken from
# llvm-mca -instruction-info), as a starting order for bench/order_search.py.
#   list_sched.py IN.s OUT.s
import re, subprocess, sys
import os
args = sys.argv[1:]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from order_search import parse  # bench/order_search.py's dependence rules
src = [l.strip() for l in open(args[0]) if l.strip()]
label, body, br = src[0], src[1:-1], src[-1]
txt = "\n".join(l.split("//")[0].replace(".Lloop", ".+4") for l in body) + "\n"
o = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", "-mcpu=cortex-a53", "-iterations=1", "-instruction-info"],
                   input=txt, capture_output=True, text=True).stdout
lat = [int(m.group(1)) for m in re.finditer(r"^\s*\d+\s+(\d+)\s+[\d.]+", o, re.M)][:len(body)]
assert len(lat) == len(body), (len(lat), len(body))


def unit(l):
    op = l.split()[0]
    if op in ("ldr", "ldrb", "str", "ldp", "stp", "ldur", "stur"):
        return "ls"
    if op in ("madd", "msub", "mul", "smull", "umull"):
        return "mac"
    if re.search(r"\b[vqd]\d+", l.split("//")[0]) or op.startswith("f") or op in ("scvtf", "ucvtf", "uqxtn", "uqxtn2", "umin", "ext"):
        return "fp"
    if op.startswith("b") or op.startswith("tb") or op.startswith("cb"):
        return "br"
    return "alu"


CAP = dict(alu=2, mac=1, ls=1, fp=1, br=1)
info = [parse(l) for l in body]
n = len(body)
preds = [[] for _ in range(n)]  # (pred, min distance in issue cycles)
for j in range(n):
    rj, wj, sj, xj = info[j]
    for i in range(j):
        ri, wi, si, xi = info[i]
        if wi & rj:
            preds[j].append((i, lat[i]))
        elif (wi & wj) or (ri & wj) or (si and sj) or xi or xj:
            preds[j].append((i, 0))
succ = [[] for _ in range(n)]
for j in range(n):
    for i, d in preds[j]:
        succ[i].append((j, d))
prio = [0] * n
for i in reversed(range(n)):
    prio[i] = lat[i] + max([prio[j] for j, d in succ[i]] + [0])
done, issue, order = set(), {}, []
t, used, lastW = 0, {}, 0
while len(order) < n:
    best = None
    for j in range(n):
        if j in done or any(i not in done for i, _ in preds[j]):
            continue
        e = max([t] + [issue[i] + d for i, d in preds[j]] + [lastW - lat[j]])
        while True:
            u = used.get(e, {})
            if sum(u.values()) < 2 and u.get(unit(body[j]), 0) < CAP[unit(body[j])]:
                break
            e += 1
        key = (e, -prio[j], j)
        if best is None or key < best[0]:
            best = (key, j, e)
    (_, j, e) = best
    done.add(j)
    issue[j] = e
    order.append(j)
    t = e
    used.setdefault(e, {})
    used[e][unit(body[j])] = used[e].get(unit(body[j]), 0) + 1
    lastW = max(lastW, e + lat[j])
open(args[1], "w").write("\n".join([label] + [body[j] for j in order] + [br]) + "\n")
print("list schedule span", t + 1)
