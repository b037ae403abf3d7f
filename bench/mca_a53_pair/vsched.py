#!/usr/bin/env python3
# bench/mca_a53_pair/vsched.py: list_sched.py's greedy in-order schedule (bench/mca_a53_persp)
# on a .vs block with virtual vector registers (`v@name`), so the order is free of the false
# dependences a register allocation adds; then alloc.py allocates the result. Regions between
# a branch and a label are scheduled separately (the branch ends its region, the fallback
# lines up to the label stay as they are). Latencies from llvm-mca -instruction-info (on an
# allocation of the input order).
#   vsched.py IN.vs OUT.vs [LIMIT] [--hard]
# LIMIT: live virtual vectors to aim at (default 30). --hard makes it hard (bench/mca_a53_tiny's
# pair block: the plain limit gave up and kept 31-34 live against a pool of 29): pinned names
# (in_*, s0, s1, c2: outside the allocation pool) are not counted, and where no candidate fits
# only those that free the most registers are taken.
import re, subprocess, sys, os
HARD = "--hard" in sys.argv
ARGS = [a for a in sys.argv[1:] if a != "--hard"]
src, dst = ARGS[0:2]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "../mca_a53_persp"))
import list_sched  # greedy(): the schedule itself
PINNED = lambda x: x.startswith("Vin_") or x in ("Vs0", "Vs1", "Vc2")  # --hard only
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
LIMIT = int(ARGS[2]) if len(ARGS) > 2 else 30


def sched(idx):
    body = [code[i] for i in idx]
    order, span = list_sched.greedy(body, [lat[i] for i in idx], [regs(l) for l in body], unit, CAP, LIMIT,
                                    pinned=PINNED if HARD else (lambda x: False), hard=HARD)
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
