#!/usr/bin/env python3
# bench/mca_a53_persp/order_search.py (bench/mca_a53_block/order_search.py with flag readers
# csel / cneg / ccmp and the accumulating fmla, fmls, xtn2 forms): searches an instruction order of one loop body (AArch64,
# operands as plain registers, last line the loop branch) against llvm-mca: Cortex-A53 cycles
# first, Cortex-A57 (the A72 column) to break ties.
#
#   order_search.py IN.s OUT.s [--evals=N] [--head=K] [--seed=S]
#
# Moves keep every register, flag and store order (a lane load ld1 {vN.b}[k] reads and writes
# vN). --head=K pins the first K lines (e.g. stores a loop entry label must follow). Each step
# takes one instruction, times every legal position for it in one llvm-mca run, keeps the
# best (ties: any); after 150 steps without a gain it restarts from the best order moved a
# little. Writes OUT.s at every gain. A model search: check the result's tests on hardware.
import os, random, re, subprocess, sys

args = [a for a in sys.argv[1:] if not a.startswith("--")]
opt = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--"))
inp, outp = args
evals, head = int(opt.get("evals", 20000)), int(opt.get("head", 0))
random.seed(int(opt.get("seed", 1)))
ITER = int(opt.get("iter", 60))
lines = [l.strip() for l in open(inp) if l.strip() and not l.strip().startswith("//")]


def reg(tok):
    m = re.fullmatch(r"[xw](\d+)", tok)
    if m:
        return "x" + m.group(1)
    m = re.fullmatch(r"[vqdsbh](\d+)(\.\w+)?(\[\d+\])?", tok)
    return "v" + m.group(1) if m else None


def parse(l):
    if l.endswith(":"):  # a label (pin it with --head)
        return set(), set(), False
    if "// !" in l:  # a branch to code that writes the first listed register (and returns)
        regs = [reg(t) for t in l.split("// !")[1].split()]
        own = [r for r in (reg(t) for t in re.findall(r"[a-z]+\d+", l.split("//")[0])) if r]
        return set(regs) | set(own) | {"nzcv"}, {regs[0]}, False
    l = l.split("//")[0].strip()
    op, _, rest = l.partition(" ")
    rs = [r for r in (reg(t) for t in re.findall(r"[a-z]+\d+(?:\.\w+)?(?:\[\d+\])?", rest)) if r]
    reads, writes, store = set(), set(), False
    mem = list(re.finditer(r"\[((?:x\d+|sp)[^\]]*)\]", rest))
    post = bool(mem) and ("]!" in rest or "," in rest[mem[-1].end():])
    if op in ("stp", "str", "st1", "stur"):
        reads |= set(rs)
        store = True
        if post:
            writes.add(reg(mem[-1].group(1).split(",")[0]))
    elif op in ("ldp", "ldr", "ldrb", "ldur", "ld1"):
        addr = [r for r in (reg(t) for t in re.findall(r"[a-z]+\d+", mem[-1].group(1))) if r]
        dst = rs[:len(rs) - len(addr)]
        reads |= set(addr)
        writes |= set(dst)
        if op == "ld1":
            reads |= set(dst)
        if post:
            writes.add(addr[0])
    elif op.startswith("b"):
        reads.add("nzcv")
    elif op in ("cmp", "cmn", "tst"):
        reads |= set(rs)
        writes.add("nzcv")
    elif op in ("ccmp", "ccmn"):
        reads |= set(rs) | {"nzcv"}
        writes.add("nzcv")
    else:
        writes.add(rs[0])
        reads |= set(rs[1:])
        if op in ("bfxil", "bfi", "ins", "tbx", "smlal", "smlal2", "movk", "sli", "sri", "fmla", "fmls",
                  "uqxtn2", "sqxtn2", "xtn2") or (op == "mov" and rs[0].startswith("v") and "[" in rest.split(",")[0]):
            reads.add(rs[0])
        if op in ("csel", "cneg", "csinc", "csinv", "csneg", "cset", "csetm", "cinc"):
            reads.add("nzcv")
        if op in ("adds", "subs", "ands"):
            writes.add("nzcv")
    return reads, writes, store


info = [parse(l) for l in lines]


def dep(a, b):  # must a stay before b?
    ra, wa, sa = info[a]
    rb, wb, sb = info[b]
    return bool(wa & rb or wa & wb or ra & wb) or (sa and sb)


CUTS = [int(c) for c in opt["cuts"].split(",")] if "cuts" in opt else []


def cycles(orders, cpu):
    """Cycles of each order, or with --cuts=A,B,... (body line indexes, the label not counted)
    the sum over the blocks cut there (as qemu's translation blocks are timed)."""
    def blocks(o):
        body = [lines[i] for i in o if not lines[i].endswith(":")]
        b = [0] + CUTS + [len(body)]
        return [body[b[k]:b[k + 1]] for k in range(len(b) - 1)]
    parts = [blocks(o) if CUTS else [[lines[i] for i in o]] for o in orders]
    text = "".join(f"# LLVM-MCA-BEGIN r{k}_{j}\n" + "\n".join(l.split("//")[0] for l in blk) + "\n# LLVM-MCA-END\n"
                   for k, p in enumerate(parts) for j, blk in enumerate(p))
    r = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", f"-mcpu={cpu}", f"-iterations={ITER}"], input=text,
                       capture_output=True, text=True)
    c = [int(x) for x in re.findall(r"Total Cycles:\s+(\d+)", r.stdout)]
    n = len(parts[0])
    return [sum(c[k * n:(k + 1) * n]) for k in range(len(orders))]


def score(orders):
    return [a * 100000 + b for a, b in zip(cycles(orders, "cortex-a53"), cycles(orders, "cortex-a57"))]


def window(order, i):
    x, lo, hi = order[i], i, i
    while lo - 1 >= head and not dep(order[lo - 1], x):
        lo -= 1
    while hi + 1 < last and not dep(x, order[hi + 1]):
        hi += 1
    return lo, hi


def moved(order, i, j):
    new = order[:i] + order[i + 1:]
    new.insert(j, order[i])
    return new


def show(s):
    return f"A53 {s // 100000 / ITER:.2f} A57 {s % 100000 / ITER:.2f}"


last = len(lines) - 1  # the loop branch stays last
order = list(range(len(lines)))
cur = best = score([order])[0]
best_order, stall, done = list(order), 0, 0
print("start", show(cur), flush=True)
while done < evals:
    i = random.randrange(head, last)
    lo, hi = window(order, i)
    cands = [moved(order, i, j) for j in range(lo, hi + 1) if j != i]
    if not cands:
        continue
    sc = score(cands)
    done += len(cands)
    m = min(sc)
    stall = stall + 1 if m >= cur else 0
    if stall > 150:
        order = list(best_order)
        for _ in range(int(opt.get("kick", 4))):
            k = random.randrange(head, last)
            lo, hi = window(order, k)
            order = moved(order, k, random.randint(lo, hi))
        cur, stall = score([order])[0], 0
        continue
    if m <= cur:
        order, cur = random.choice([c for c, v in zip(cands, sc) if v == m]), m
        if cur < best:
            best, best_order = cur, list(order)
            print(done, show(best), flush=True)
            open(outp, "w").write("\n".join(lines[k] for k in best_order) + "\n")
open(outp, "w").write("\n".join(lines[k] for k in best_order) + "\n")
print("final", show(best))
