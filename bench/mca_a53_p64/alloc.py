#!/usr/bin/env python3
# bench/mca_a53_p64/alloc.py: register allocation for a straight-line block written with
# virtual vector registers: `v@name`, `d@name`, `q@name` (one name, one register from its first
# to its last mention; an accumulating op writes the name it reads). Names given in PIN
# (name=vN, comma separated) keep their register (freed after their last mention unless the
# name starts with in_: a read-only input); the others take the register freed
# longest ago (fewer false dependences for bench/order_search.py).
#   alloc.py IN.vs OUT.s PIN [POOL]   (POOL: vector register numbers, default 0-7,16-31)
import re, sys
src, out, pin = sys.argv[1:4]
pool = [int(x) for x in sys.argv[4].split(",")] if len(sys.argv) > 4 else list(range(0, 8)) + list(range(16, 32))
fixed = dict(p.split("=") for p in pin.split(",") if p)
lines = open(src).read().split("\n")
pat = re.compile(r"\b([vdqs])@(\w+)")
last = {}
for i, l in enumerate(lines):
    for m in pat.finditer(l.split("//")[0]):
        last[m.group(2)] = i
reg = {n: int(r[1:]) for n, r in fixed.items()}
busy = set(reg.values())
free = [r for r in pool if r not in busy]
res = []
for i, l in enumerate(lines):
    code = l.split("//")[0]
    for m in pat.finditer(code):
        n = m.group(2)
        if n not in reg:
            if not free:
                sys.exit(f"line {i + 1}: no free register for {n}")
            reg[n] = free.pop(0)
    res.append(pat.sub(lambda m: m.group(1) + str(reg[m.group(2)]), l))
    for m in set(mm.group(2) for mm in pat.finditer(code)):
        if last[m] == i and not m.startswith("in_"):
            free.append(reg[m])
open(out, "w").write("\n".join(res))
print({n: r for n, r in reg.items()})
