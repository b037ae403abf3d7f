#!/usr/bin/env python3
# bench/mca_a53_tiny/vsched_hard.py: bench/mca_a53_pair/vsched.py with list_sched.py's greedy
# copied in and its register limit made hard: pinned names (in_*, s0, s1, c2: outside the
# allocation pool) not counted, and where no candidate fits the limit only those that free the
# most registers are taken (vsched.py's limit gave up there: the tiny pair block's schedules
# kept 31-34 scratch vectors live against a pool of 24).
#   vsched_hard.py IN.vs OUT.vs LIMIT
import re, subprocess, sys, os
src, dst = sys.argv[1:3]
here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../mca_a53_pair")
sys.path.insert(0, os.path.join(here, "../mca_a53_persp"))
import list_sched  # unit tables
PINNED = lambda x: x.startswith("Vin_") or x in ("Vs0", "Vs1", "Vc2")
def greedy(body, lat, info, unit, cap, limit=None):
    """The greedy in-order list schedule of body (one region, no branch targets inside):
    info[j] = (reads, writes, is_store[, barrier]) as sets of register names; a consumer waits
    for its producer's latency, other orderings (write after read or write, store after store,
    barriers) only keep their order; two issues a cycle within cap[unit]; results write back in
    order. limit: at most that many virtual vector names ("V..." in info) live where a
    candidate that fits exists (vsched.py). Returns (order, span in cycles)."""
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
    live = set(x for x in uses if not any(x in info[j][1] for j in range(n)) and not PINNED(x))
    left = dict(uses)

    def net(j):
        r, w = info[j][:2]
        new = len([x for x in w if x.startswith("V") and x not in live and not PINNED(x)])
        dead = len([x for x in (r | w) if x.startswith("V") and not PINNED(x) and left[x] == 1 and (x in live or x in w)])
        return new - dead
    done, issue, order = set(), {}, []
    t, used, lastW = 0, {}, 0
    while len(order) < n:
        best = None
        ok = [j for j in range(n) if j not in done and all(i in done for i, _ in preds[j])]
        fit = [j for j in ok if limit is None or len(live) + net(j) <= limit]
        if not fit:  # over the limit: only the candidates that free the most
            low = min(net(j) for j in ok)
            fit = [j for j in ok if net(j) == low]
        for j in fit:
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
            if x.startswith("V") and not PINNED(x):
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



lines = [l.rstrip() for l in open(src)]
code = [l for l in lines if l.strip() and not l.strip().startswith("//")]
hdr = [l for l in lines if l.strip().startswith("//")]
subprocess.run([sys.executable, os.path.join(here, "../mca_a53_p64/alloc.py"), src, "/tmp/vsched_alloc.s", "",
                ",".join(map(str, range(32)))], check=True, capture_output=True)
alloc = [l for l in open("/tmp/vsched_alloc.s").read().split("\n") if l.strip() and not l.strip().startswith("//")]
assert len(alloc) == len(code)
txt = "\n".join(re.sub(r"\b(b\.\w+|cbz|cbnz|tbz|tbnz)\b(.*)\b\d+[fb]$", r"\1\2.+4", l) for l in alloc if not re.match(r"^\d+:$", l)) + "\n"
o = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", "-mcpu=cortex-a53", "-iterations=1", "-instruction-info"],
                   input=txt, capture_output=True, text=True).stdout
lat_list = [int(m.group(1)) for m in re.finditer(r"^\s*\d+\s+(\d+)\s+[\d.]+", o, re.M)]
lat, k = [], 0
for l in code:
    if re.match(r"^\d+:$", l):
        lat.append(0)
    else:
        lat.append(lat_list[k]); k += 1
ACC = ("fmla", "fmls", "mla", "mls", "bit", "bif", "bsl", "ssra", "usra", "sqxtn2", "uqxtn2", "xtn2", "ins", "sli", "sri", "tbx")


def regs(l):
    body = l.split("//")[0]
    op = body.split()[0]
    toks = [t for t in re.split(r"[\s,\[\]{}]+", body.split(None, 1)[1] if " " in body.strip() else "") if t]
    names = []
    for t in toks:
        m = re.match(r"[vqds]@(\w+)", t)
        if m:
            names.append("V" + m.group(1)); continue
        m = re.fullmatch(r"[xw](\d+)", t)
        if m:
            names.append("x" + m.group(1)); continue
        if t == "sp":
            names.append("sp")
    if not names:
        return set(), set(), False
    store = op.startswith("st")
    lane = op == "ld1" and re.search(r"\}\[\d\]", body) is not None
    if store:
        return set(names), set(), True
    if op in ("ldr", "ldp", "ld1", "ld1r", "ld2", "ld2r"):
        nd = 2 if op in ("ldp",) else (len(re.findall(r"@", body.split("[")[0])) if "{" in body else 1)
        w = set(names[:nd]); r = set(names[nd:])
        if lane:
            r |= w
        return r, w, False
    if op in ("cmp", "cmn", "tst"):
        return set(names) | set(), {"flags"}, False
    if op in ("ccmp", "ccmn"):
        return set(names) | {"flags"}, {"flags"}, False
    if op in ("csel", "cset", "csinc"):
        return set(names[1:]) | {"flags"}, {names[0]}, False
    if op.startswith("b."):
        return {"flags"}, set(), False
    w = {names[0]}; r = set(names[1:])
    if op in ACC:
        r |= w
    return r, w, False


def unit(l):
    op = l.split()[0]
    if op.startswith("ld") or op.startswith("st"):
        return "ls"
    if "@" in l or op.startswith("f") or op in ("scvtf", "umaxv", "uminp"):
        return "fp"
    if op.startswith("b"):
        return "br"
    return "alu"


CAP = dict(alu=2, ls=1, fp=1, br=1)
LIMIT = int(sys.argv[3]) if len(sys.argv) > 3 else 30


def sched(idx):
    body = [code[i] for i in idx]
    order, span = greedy(body, [lat[i] for i in idx], [regs(l) for l in body], unit, CAP, LIMIT)
    print("region of", len(body), "list schedule span", span, file=sys.stderr)
    return [idx[j] for j in order]


out, reg = [], []
i = 0
while i < len(code):
    l = code[i]
    op = l.split()[0]
    if op.startswith("b.") or op in ("cbz", "cbnz", "tbz", "tbnz"):
        out += sched(reg) + [i]
        reg = []
        i += 1
        while not re.match(r"^\d+:$", code[i]):
            out.append(i); i += 1
        out.append(i); i += 1
        continue
    reg.append(i); i += 1
out += sched(reg)
open(dst, "w").write("\n".join(hdr + [code[j] for j in out]) + "\n")
