#!/usr/bin/env python3
# bench/mca_a53_persp/list_sched.py: a greedy list schedule of one loop body (first line a
# label, last line the loop branch) for an in-order, dual-issue core whose results write back
# in program order (LLVM 14's Cortex-A53 model as llvm-mca runs it: latencies taken from
# llvm-mca -instruction-info), as a starting order for bench/order_search.py.
#   list_sched.py IN.s OUT.s
import re, subprocess, sys
import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from order_search import parse  # bench/order_search.py's dependence rules


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


def greedy(body, lat, info, unit, cap, limit=None, pinned=lambda x: False, hard=False):
    """The greedy in-order list schedule of body (one region, no branch targets inside):
    info[j] = (reads, writes, is_store[, barrier]) as sets of register names; a consumer waits
    for its producer's latency, other orderings (write after read or write, store after store,
    barriers) only keep their order; two issues a cycle within cap[unit]; results write back in
    order. limit: at most that many virtual vector names ("V..." in info) live where a
    candidate that fits exists (vsched.py). pinned(name): names outside the allocation pool,
    not counted against the limit. hard: where no candidate fits the limit, only those that free
    the most registers are taken (otherwise any ready one). Returns (order, span in cycles)."""
    n = len(body)
    bar = [len(x) > 3 and x[3] for x in info]
    preds = [[] for _ in range(n)]  # (pred, min distance in issue cycles)
    for j in range(n):
        rj, wj, sj = info[j][:3]
        for i in range(j):
            ri, wi, si = info[i][:3]
            if wi & rj:
                preds[j].append((i, lat[i]))
            elif (wi & wj) or (ri & wj) or (si and sj) or bar[i] or bar[j]:
                preds[j].append((i, 0))
    succ = [[] for _ in range(n)]
    for j in range(n):
        for i, d in preds[j]:
            succ[i].append((j, d))
    prio = [0] * n
    for i in reversed(range(n)):
        prio[i] = lat[i] + max([prio[j] for j, d in succ[i]] + [0])
    # register pressure (limit): vector names live (written, uses left)
    uses = {}
    for j in range(n):
        for x in info[j][0] | info[j][1]:
            if x.startswith("V"):
                uses[x] = uses.get(x, 0) + 1
    live = set(x for x in uses if not any(x in info[j][1] for j in range(n)) and not pinned(x))
    left = dict(uses)

    def net(j):
        r, w = info[j][:2]
        new = len([x for x in w if x.startswith("V") and x not in live and not pinned(x)])
        dead = len([x for x in (r | w) if x.startswith("V") and not pinned(x) and left[x] == 1 and (x in live or x in w)])
        return new - dead
    done, issue, order = set(), {}, []
    t, used, lastW = 0, {}, 0
    while len(order) < n:
        best = None
        ok = [j for j in range(n) if j not in done and all(i in done for i, _ in preds[j])]
        fit = [j for j in ok if limit is None or len(live) + net(j) <= limit]
        if not fit and hard:  # over the limit: only the candidates that free the most
            low = min(net(j) for j in ok)
            fit = [j for j in ok if net(j) == low]
        for j in (fit or ok):
            e = max([t] + [issue[i] + d for i, d in preds[j]] + [lastW - lat[j]])
            while True:
                u = used.get(e, {})
                if sum(u.values()) < 2 and u.get(unit(body[j]), 0) < cap[unit(body[j])]:
                    break
                e += 1
            key = (e, -prio[j], j)
            if best is None or key < best[0]:
                best = (key, j, e)
        (_, j, e) = best
        for x in info[j][0] | info[j][1]:
            if x.startswith("V") and not pinned(x):
                left[x] -= 1
                if left[x] == 0:
                    live.discard(x)
                else:
                    live.add(x)
        done.add(j)
        issue[j] = e
        order.append(j)
        t = e
        used.setdefault(e, {})
        used[e][unit(body[j])] = used[e].get(unit(body[j]), 0) + 1
        lastW = max(lastW, e + lat[j])
    return order, t + 1


if __name__ == "__main__":
    args = sys.argv[1:]
    src = [l.strip() for l in open(args[0]) if l.strip()]
    label, body, br = src[0], src[1:-1], src[-1]
    txt = "\n".join(l.split("//")[0].replace(".Lloop", ".+4") for l in body) + "\n"
    o = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", "-mcpu=cortex-a53", "-iterations=1", "-instruction-info"],
                       input=txt, capture_output=True, text=True).stdout
    lat = [int(m.group(1)) for m in re.finditer(r"^\s*\d+\s+(\d+)\s+[\d.]+", o, re.M)][:len(body)]
    assert len(lat) == len(body), (len(lat), len(body))
    order, span = greedy(body, lat, [parse(l) for l in body], unit, CAP)
    open(args[1], "w").write("\n".join([label] + [body[j] for j in order] + [br]) + "\n")
    print("list schedule span", span)
