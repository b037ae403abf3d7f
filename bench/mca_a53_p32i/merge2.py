#!/usr/bin/env python3
# bench/mca_a53_p32i/merge2.py: two asm blocks (plain lines, bench/order_search.py's syntax) as
# one: every value renamed (SSA), the two instruction streams zipped in a simulated in-order
# dual issue (each stream keeps its own order: the blocks' searched orders), registers
# allocated again on the zipped order. For the paired second-order spans (span a three runs,
# span b two runs): each block alone is latency-bound, the other's instructions fill its gaps.
#
#   merge2.py A.s B.s OUT.s [--bias=K] [--free=N]   (--free: registers B leaves to A)
#
# A's and B's registers: A keeps its live-in registers (PIN_A); B's live-ins that A shares
# (SHARED) are A's values; B's other live-ins get registers of their own (printed). Live-out:
# each block's x23, x24, x25 (the last run packed). Memory: each block's loads and stores keep
# their order within the block; the two blocks' memory is disjoint (other spans, other scratch).
# The simulated issue: latencies from llvm-mca -instruction-info (cortex-a53), two a cycle, one
# load/store, one NEON/FP; among the two streams' next lines the one that issues first (ties:
# --bias towards A). A line is taken only when its new values find free registers.
import re, subprocess, sys

sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(__file__)), ".."))
from order_search import parse, reg  # noqa: E402

GPR = [f"x{i}" for i in range(29)] + ["x30"]  # x29 (frame pointer) left alone
VEC = [f"v{i}" for i in range(32)]
TOK = re.compile(r"\b([xw])(\d+)\b|\b([vqdsbh])(\d+)\b")


def lines_of(p):
    return [l.split("//")[0].strip() for l in open(p) if l.split("//")[0].strip()]


def latencies(lines, cpu="cortex-a53"):
    text = "\n".join(lines) + "\n"
    r = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", f"-mcpu={cpu}", "-iterations=1", "-instruction-info"],
                       input=text, capture_output=True, text=True)
    lat = []
    sec = r.stdout.split("Instruction Info:", 1)[1]
    for l in sec.splitlines():
        m = re.match(r"\s*(\d+)\s+(\d+)\s+([\d.]+)\s+(\*|\s)\s+(\*|\s)\s+(U|\s)?\s*(\S.*)$", l)
        if m:
            lat.append(int(m.group(2)))
    assert len(lat) == len(lines), (len(lat), len(lines))
    return lat


class Ins:
    pass


class Stuck(Exception):
    pass


SEQ = None  # a string of 'a' / 'b': the zip order (merge2_search.py)


def ssa(lines, tag, livein, vals):
    """Instructions with value ids per register token; livein: phys -> value id (created here
    when missing)."""
    cur = dict(livein)
    out = []
    last_mem = []  # memory ops so far (order kept)
    for k, l in enumerate(lines):
        reads, writes, store, barrier = parse(l)
        assert not barrier, l
        op = l.split()[0]
        ins = Ins()
        ins.text, ins.tag, ins.op = l, tag, op
        ins.is_mem = op.startswith("ld") or op.startswith("st")
        ins.is_load = op.startswith("ld")
        ins.is_vec = any(t.startswith("v") for t in reads | writes if t != "nzcv") and not ins.is_mem
        ins.deps = []
        if ins.is_mem:  # loads after stores, stores after every memory op (within the block)
            for j in last_mem:
                if not (ins.is_load and out[j].is_load):
                    ins.deps.append(out[j])
            last_mem.append(len(out))
        rv = {}
        for r in reads:
            if r == "nzcv":
                continue
            if r not in cur:
                vid = len(vals)
                vals.append({"phys": None, "cls": r[0], "livein": (tag, r)})
                cur[r] = vid
            rv[r] = cur[r]
        wv = {}
        for w in writes:
            if w == "nzcv":
                continue
            vid = len(vals)
            vals.append({"phys": None, "cls": w[0], "tied": rv.get(w) if w in reads else None})
            wv[w] = vid
        # tokens: which are writes: the first register token of a non-store, non-load, non-cmp
        # line; a load's tokens before '['
        toks = []
        addr_at = l.find("[")
        first = True
        for m in TOK.finditer(l):
            r = reg(m.group(0))
            if r is None:
                continue
            pos = m.start()
            is_w = False
            if r in writes:
                if ins.is_load:
                    is_w = addr_at < 0 or pos < addr_at
                elif not store:
                    is_w = first
            first = False
            toks.append((m.start(), m.end(), m.group(0), wv[r] if is_w else rv[r]))
        ins.toks, ins.reads, ins.writes = toks, list(rv.values()), list(wv.values())
        for w, vid in wv.items():
            cur[w] = vid
        ins.idx = k
        out.append(ins)
    return out, cur


def main(argv=None, quiet=False):
    argv = argv or sys.argv[1:]
    args = [a for a in argv if not a.startswith("--")]
    opt = dict(a[2:].split("=", 1) for a in argv if a.startswith("--") and "=" in a)
    bias = float(opt.get("bias", 0))
    A, B = lines_of(args[0]), lines_of(args[1])
    vals = []
    ia, outa = ssa(A, "a", {}, vals)
    shared = {r: v for r, v in [(vals[i]["livein"][1], i) for i in range(len(vals)) if vals[i].get("livein")]
              if r in ("x18", "x0", "x27", "x28")}
    ib, outb = ssa(B, "b", shared, vals)
    lat = dict(zip(map(id, ia + ib), latencies(A) + latencies(B)))
    # producers
    prod = {}
    for ins in ia + ib:
        for w in ins.writes:
            prod[w] = ins
    live_out = [outa[r] for r in ("x23", "x24", "x25")] + [outb[r] for r in ("x23", "x24", "x25")]
    # last use (position in the final order: computed as we go, by counting remaining readers)
    readers = {}
    for ins in ia + ib:
        for v in set(ins.reads):
            readers[v] = readers.get(v, 0) + 1
    for v in live_out:
        readers[v] = readers.get(v, 0) + 10**6
    free = {"x": list(GPR), "v": list(VEC)}
    phys_of = {}
    # live-ins: A's where they are; B's own ones anywhere free
    pins = {}
    for i, v in enumerate(vals):
        if v.get("livein") and v["livein"][0] == "a":
            phys_of[i] = v["livein"][1]
            free[v["cls"]].remove(v["livein"][1])
    for i, v in enumerate(vals):
        if v.get("livein") and v["livein"][0] == "b" and i not in phys_of:
            want = opt.get("pin_" + v["livein"][1])
            p = want if want else free[v["cls"]][-1]
            free[v["cls"]].remove(p)
            phys_of[i] = p
            pins[v["livein"][1]] = p
    livein_phys = {i: phys_of[i] for i, v in enumerate(vals) if v.get("livein")}
    # simulation
    done_at = {}  # ins id -> cycle result ready
    issue_at = {}
    t, slots, mem_used, vec_used = 0, 0, 0, 0
    order = []
    last_wb = 0
    heads = {"a": 0, "b": 0}
    streams = {"a": ia, "b": ib}
    remaining = dict(readers)

    def ready(ins):
        r = 0
        for v in ins.reads:
            p = prod.get(v)
            if p is not None:
                if id(p) not in done_at:
                    return None
                r = max(r, done_at[id(p)])
        for d in ins.deps:
            if id(d) not in issue_at:
                return None
            r = max(r, issue_at[id(d)] + 1)
        return r

    def fits(ins):
        """The line's new values find registers (after the values it reads last are freed)."""
        tied_src = {vals[w]["tied"] for w in ins.writes if vals[w]["tied"] is not None}
        have = {c: len(free[c]) for c in "xv"}
        for v in set(ins.reads):
            if remaining[v] == 1 and v not in tied_src:
                have[vals[v]["cls"]] += 1
        for w in ins.writes:
            if vals[w]["tied"] is None:
                have[vals[w]["cls"]] -= 1
        minfree = int(opt.get("free", 0)) if ins.tag == "b" else 0
        return all(have[c] >= minfree for c in "xv")

    while heads["a"] < len(ia) or heads["b"] < len(ib):
        cands = []
        for s in "ab":
            if heads[s] < len(streams[s]):
                ins = streams[s][heads[s]]
                r = ready(ins)
                if r is None and SEQ is not None:
                    r = 0
                if r is None or not fits(ins):
                    continue
                # in-order write-back (LLVM's in-order model without RetireOOO): a line that
                # writes a register writes back no earlier than the last one issued
                if ins.writes:
                    r = max(r, last_wb - lat[id(ins)])
                cands.append((max(r, t) + (0 if s == "a" else bias), s, ins, max(r, t)))
        if SEQ is not None:
            want = SEQ[len(order)] if len(order) < len(SEQ) else "a"
            if heads[want] >= len(streams[want]):
                want = "b" if want == "a" else "a"
            cands = [c for c in cands if c[1] == want]
        if not cands:
            raise Stuck(f"stuck at {len(order)}: free x {len(free['x'])} v {len(free['v'])}")
        cands.sort(key=lambda c: (c[0], c[1]))
        _, s, ins, when = cands[0]
        if when > t:
            t, slots, mem_used, vec_used = when, 0, 0, 0
        if slots >= 2 or (ins.is_mem and mem_used) or (ins.is_vec and vec_used):
            t, slots, mem_used, vec_used = t + 1, 0, 0, 0
        slots += 1
        mem_used |= ins.is_mem
        vec_used |= ins.is_vec
        issue_at[id(ins)] = t
        done_at[id(ins)] = t + lat[id(ins)]
        if ins.writes:
            last_wb = max(last_wb, t + lat[id(ins)])
        heads[s] += 1
        # registers: free the reads that die here, then assign the writes
        dying = []
        for v in set(ins.reads):
            remaining[v] -= 1
            if remaining[v] == 0:
                dying.append(v)
        tied_src = {vals[w]["tied"] for w in ins.writes if vals[w]["tied"] is not None}
        for v in dying:
            if v not in tied_src:
                free[vals[v]["cls"]].append(phys_of[v])
        for w in ins.writes:
            if vals[w]["tied"] is not None:
                phys_of[w] = phys_of[vals[w]["tied"]]
            else:
                # prefer registers freed longest ago (fewer false dependences for later searches)
                phys_of[w] = free[vals[w]["cls"]].pop(0)
            if remaining.get(w, 0) == 0:  # dead value: its register is free again
                free[vals[w]["cls"]].append(phys_of[w])
        order.append(ins)
    # text
    res = []
    for ins in order:
        l, o = ins.text, 0
        s = ""
        for a, b, tok, v in ins.toks:
            p = phys_of[v]
            num = p[1:]
            s += l[o:a] + tok[0] + num
            o = b
        s += l[o:]
        res.append(s)
    if args[2] != "-":
        open(args[2], "w").write("\n".join(res) + "\n")
    if quiet:
        return res, "".join(i.tag for i in order)
    print("B pins:", pins, file=sys.stderr)
    print("live-in:", {vals[i]["livein"]: p for i, p in livein_phys.items()}, file=sys.stderr)
    print("live-out a:", [phys_of[v] for v in live_out[:3]], "b:", [phys_of[v] for v in live_out[3:]], file=sys.stderr)
    print("sim cycles:", t, file=sys.stderr)


if __name__ == "__main__":
    main()
