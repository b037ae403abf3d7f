#!/usr/bin/env python3
# bench/mca_a53_lit/regalloc.py: gives lit16_block's core values registers again, after the
# schedule, so that as few callee-saved registers (x19-x28) as possible are used: every
# callee-saved register the block clobbers costs its C++ function a save and a restore
# (lit16_block is out of line: 5 stp + 5 ldp for x19-x28 before this script).
#
#   regalloc.py IN.s OUT.s [--operands=N] [--live-out=R[,R..]]
#
# A block without the cbz / 1: parts (win16_block) is one straight part; --operands (13 by
# default: x0-x12) and --live-out (2,3: du / dv) give another block's operands and the
# registers the caller reads after it (win16_block: --operands=15 --live-out=2).
#
# The instruction order is kept; only core register numbers change. Values are webs (the
# definitions that reach a common use, read-modify-write destinations such as bfi and
# post-index bases joined to their input), over the block's three parts (up to the cbz, the
# cells-B part, from 1:). The operands' entry values keep their registers x0-x12 (the
# inline asm's operands, bench/to_inline.py), and so do du / dv (x2, x3) at the end (the
# flags the caller reads); other webs take the lowest register free over their live range:
# x0-x12 (every operand is read-write in the header, so a dead operand is scratch), x13-x17,
# then x19-x28. Prints the callee-saved registers used (the header's clobbers). Stops if the
# entry value of u..ddv (32-bit operands in the header) is read as an x register.
import re, sys

REG = re.compile(r"\b([xw])([0-9]|[12][0-9]|30)\b")
STORES = ("st", "stp", "str", "strb", "strh", "stur", "st1", "st2", "st3", "st4")
NODEF = ("cmp", "cmn", "tst", "ccmp", "ccmn", "cbz", "cbnz", "tbz", "tbnz", "b", "fcmp")
RMW = ("bfi", "bfxil", "movk")
OPERANDS = range(13)
W32 = range(6)  # u..ddv: 32-bit in the header (their entry values must be read as w only)
LIVE_OUT = (2, 3)
for a in sys.argv[3:]:
    if a.startswith("--operands="):
        OPERANDS = range(int(a.split("=")[1]))
    elif a.startswith("--live-out="):
        LIVE_OUT = tuple(int(x) for x in a.split("=")[1].split(","))


def parse(line):
    """(mnemonic, defs, uses, rmw_pairs) of core register numbers."""
    op, _, rest = line.partition(" ")
    regs = [(m.start(), int(m.group(2))) for m in REG.finditer(rest)]
    ops = [o.strip() for o in re.split(r",(?![^\[]*\])(?![^{]*})", rest)] if rest else []
    defs, uses, same = [], [], []
    # Base registers with writeback: "[xN], #imm" or "[xN, #imm]!".
    wb = None
    m = re.search(r"\[x(\d+)(?:, #-?\d+)?\]!|\[x(\d+)\], #", rest)
    if m:
        wb = int(m.group(1) or m.group(2))
    if op in STORES or op in NODEF or op.startswith("st"):
        uses = [r for _, r in regs]
    elif op in ("ldp",) and REG.fullmatch(ops[0]) and REG.fullmatch(ops[1]):
        defs = [int(ops[0][1:]), int(ops[1][1:])]
        uses = [r for _, r in regs[2:]]
    elif ops and REG.fullmatch(ops[0]):
        d = int(ops[0][1:])
        defs = [d]
        uses = [r for _, r in regs[1:]]
        if op in RMW:
            uses.append(d)
            same.append(d)
    else:  # vector destination (mov v.s[i], w; fmov s, w; loads to q): uses only
        uses = [r for _, r in regs]
    if wb is not None:
        defs.append(wb)
        same.append(wb)
    return op, defs, uses, same


def main(inp, out):
    lines = [l.rstrip("\n") for l in open(inp) if l.strip()]
    n = len(lines)
    cbz = next((i for i, l in enumerate(lines) if l.startswith("cbz")), None)
    lab = lines.index("1:") if cbz is not None else None
    ins = [parse(l) if i != lab else ("label", [], [], []) for i, l in enumerate(lines)]
    succ = {i: [i + 1] for i in range(n - 1)}
    succ[n - 1] = []
    if cbz is not None:
        succ[cbz] = [cbz + 1, lab]
    pred = {i: [] for i in range(n)}
    for i, s in succ.items():
        for j in s:
            pred[j].append(i)
    # Reaching definitions: def ids are (instruction, reg); entry defs are (-1, reg).
    rin = {i: {} for i in range(n)}
    rout = {i: {} for i in range(n)}
    entry = {r: {(-1, r)} for r in OPERANDS}
    changed = True
    while changed:
        changed = False
        for i in range(n):
            cur = {}
            srcs = [rout[p] for p in pred[i]] if pred[i] else [entry]
            for s in srcs:
                for r, ds in s.items():
                    cur.setdefault(r, set()).update(ds)
            o = dict(cur)
            for d in ins[i][1]:
                o[d] = {(i, d)}
            if cur != rin[i] or o != rout[i]:
                rin[i], rout[i], changed = cur, o, True
    parent = {}

    def find(a):
        parent.setdefault(a, a)
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    def union(a, b):
        parent[find(a)] = find(b)

    use_defs = {}  # (i, reg) -> representative def
    for i in range(n):
        _, defs, uses, same = ins[i]
        for r in uses:
            ds = rin[i].get(r)
            if not ds:
                sys.exit(f"line {i + 1}: x{r} read before any definition: {lines[i]}")
            ds = list(ds)
            for d in ds[1:]:
                union(ds[0], d)
            use_defs[(i, r)] = ds[0]
        for d in defs:
            find((i, d))
        for r in same:
            union((i, r), use_defs[(i, r)])
    for r in LIVE_OUT:  # the caller reads du / dv: the definitions reaching the end are one web
        ds = list(rout[n - 1].get(r, ()))
        for d in ds[1:]:
            union(ds[0], d)
    # Liveness per instruction (backward) on webs.
    live_in = {i: set() for i in range(n)}
    live_out = {i: set() for i in range(n)}
    end_live = {find(d) for r in LIVE_OUT for d in rout[n - 1].get(r, ())}
    changed = True
    while changed:
        changed = False
        for i in reversed(range(n)):
            lo = set(end_live) if not succ[i] else set().union(*(live_in[s] for s in succ[i]))
            _, defs, uses, _ = ins[i]
            li = lo - {find((i, d)) for d in defs} | {find(use_defs[(i, r)]) for r in uses}
            if li != live_in[i] or lo != live_out[i]:
                live_in[i], live_out[i], changed = li, lo, True
    # Interference: a def's web against every web live after it (and the other defs).
    webs = {find(a) for a in parent}
    adj = {w: set() for w in webs}
    for i in range(n):
        dw = {find((i, d)) for d in ins[i][1]}
        for a in dw:
            for b in live_out[i] | dw:
                if a != b:
                    adj[a].add(b)
                    adj[b].add(a)
    for a in live_in[0]:  # entry values interfere with each other
        for b in live_in[0]:
            if a != b:
                adj[a].add(b)
    color = {}
    for r in OPERANDS:
        w = find((-1, r))
        if w in color and color[w] != r:
            sys.exit(f"entry x{r} joined to x{color[w]}")
        color[w] = r
    for w in end_live:
        rs = {r for r in LIVE_OUT if any(find(d) == w for d in rout[n - 1].get(r, ()))}
        r = rs.pop()
        if w in color and color[w] != r:
            sys.exit(f"live-out x{r}'s web is pinned to x{color[w]}")
        color[w] = r
    for w in color:
        for b in adj[w]:
            if b in color and color[b] == color[w]:
                sys.exit(f"pinned webs clash on x{color[w]}: {w} {b}")
    pool = list(range(0, 18)) + list(range(19, 29))
    first = lambda w: min(i for (i, r) in parent if find((i, r)) == w)
    for w in sorted(webs - set(color), key=first):
        taken = {color[b] for b in adj[w] if b in color}
        color[w] = next(r for r in pool if r not in taken)
    maxlive = max(len(live_out[i]) for i in range(n))
    for i in range(n):
        for r in ins[i][2] if i != lab else ():
            if any(find(use_defs[(i, r)]) == find((-1, q)) for q in W32) and \
                    re.search(r"\bx%d\b" % r, lines[i].partition(" ")[2]):
                sys.exit(f"line {i + 1}: a 32-bit operand's entry value read as x{r}: {lines[i]}")
    # Rewrite.
    res = []
    for i, l in enumerate(lines):
        if i == lab:
            res.append(l)
            continue
        op, defs, uses, same = ins[i]
        rest = l[len(op):]
        new = {}
        # Map each register occurrence: defs take their own web, uses their reaching web.
        dmap = {d: color[find((i, d))] for d in defs}
        umap = {r: color[find(use_defs[(i, r)])] for r in uses}
        for d in dmap:
            if d in umap and d not in same and umap[d] != dmap[d]:
                # The same register read and written (orr x, x, ...): positions decide.
                pass
        out_parts = []
        pos = 0
        occ = list(REG.finditer(rest))
        # Destination occurrences: the first len(defs) (minus writeback) register operands.
        ndest = len([d for d in defs if d not in same or op in RMW]) if op not in STORES and not op.startswith("st") else 0
        wbs = [d for d in same if op not in RMW]
        for k, m in enumerate(occ):
            r = int(m.group(2))
            if k < ndest:
                nr = dmap[r]
            elif r in wbs:
                nr = dmap[r]
            else:
                nr = umap[r]
            out_parts.append(rest[pos:m.start()] + m.group(1) + str(nr))
            pos = m.end()
        out_parts.append(rest[pos:])
        res.append(op + "".join(out_parts))
    open(out, "w").write("\n".join(res) + "\n")
    used = sorted({c for c in color.values() if c >= 19})
    print(f"max live {maxlive}; callee-saved used: {' '.join(f'x{c}' for c in used) or 'none'}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
