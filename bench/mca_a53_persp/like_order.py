#!/usr/bin/env python3
# bench/mca_a53_persp/like_order.py: a changed long pass (gen_long_pass.py with its switches set)
# in the order of a searched body of the unchanged one: each line kept takes its searched
# position, a replaced line the position of the line it replaces (difflib over the slot-order
# bodies), an inserted one follows its slot-order predecessor; registers allocated anew
# over that order (gen_long_pass.py's linear scan). A start for bench/order_search.py that keeps what the last search found.
#   like_order.py OLD_SEARCHED.s OUT.s SWITCH=1 [SWITCH=1 ..]   (e.g. REUSE=1)
import difflib, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_long_pass as g


def named(**sw):
    g.body.clear()
    for k, v in sw.items():
        setattr(g, k, v)
    return g.build()


old = named()
old_alloc, _ = g.allocate(old)
searched = [l.strip() for l in open(sys.argv[1]) if l.strip() and not l.strip().endswith(":")]
assert sorted(searched) == sorted(old_alloc), "the searched body is not this generator's unchanged body"
queue = {}
for i, l in enumerate(old_alloc):
    queue.setdefault(l, []).append(i)
pos = [0] * len(old)
for k, l in enumerate(searched):
    pos[queue[l].pop(0)] = k
sw = dict(a.split("=") for a in sys.argv[3:])
new = named(**{k: bool(int(v)) for k, v in sw.items()})
norm = [l.replace("{X:fdv1}", "{X:dv1}").replace("{X:fdv2}", "{X:dv2}") for l in new]
key = [None] * len(new)
sm = difflib.SequenceMatcher(None, old, norm, autojunk=False)
for op, i1, i2, j1, j2 in sm.get_opcodes():
    for t, j in enumerate(range(j1, j2)):
        if op in ("equal", "replace") and i1 + t < i2:
            key[j] = pos[i1 + t]
for j in range(len(new)):
    if key[j] is None:
        key[j] = (key[j - 1] if j else -1) + 0.001
order = sorted(range(len(new)), key=lambda j: (key[j], j))
lines = [new[j] for j in order]
br = [l for l in lines if l.startswith("b.lo")]
lines = [l for l in lines if not l.startswith("b.lo")] + br
out, reg = g.allocate(lines)  # over this order (an allocation in slot order need not hold in it)
open(sys.argv[2], "w").write(".Lloop:\n" + "\n".join(out) + "\n")
print(len(old), "->", len(new), "lines")
