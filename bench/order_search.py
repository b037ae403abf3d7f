#!/usr/bin/env python3
# bench/order_search.py: searches an instruction order of one AArch64 block (a loop body whose
# last line is its branch, or straight-line code) against llvm-mca: Cortex-A53 cycles first,
# Cortex-A57 (the A72 column) to break ties, or A53 + W A57 with --a57=W.
#
#   order_search.py IN.s OUT.s [--evals=N] [--head=K] [--seed=S] [--a57=W] [--cuts=A,B,..]
#                              [--iter=N] [--kick=N] [--mem]
#
# Operands are plain registers. Moves keep every register, flag and store order: accumulating
# ops (fmla, mla, bsl/bit/bif, ssra, sqxtn2, lane inserts, ld1 lane loads ...) read their
# destination, every register of a multi-register load (ld2 {a, b}) is written, conditional
# selects and ccmp read the flags. A last line that is a branch stays last; labels and other
# branches are barriers, except a branch annotated `// ! rA rB ..` (to fallback code that
# rewrites rA from the listed registers and returns), which reads those registers and its own
# and writes rA. --head=K pins the first K lines (e.g. stores a loop entry label must follow).
# --cuts=A,B (body line indexes, labels not counted) scores the sum over the blocks cut
# there, as qemu's translation blocks are timed by bench/count.sh. --mem keeps loads in order
# with stores too (for blocks that reload what they store: stack state, layout buffers);
# without it only stores keep their order. sp is a register like the others.
# Each step takes one instruction, times every legal position for it in one llvm-mca run,
# keeps the best (ties: any); after 150 steps without a gain it restarts from the best order
# moved a little (--kick moves). Writes OUT.s at every gain. Branches to numeric local labels
# (`b.ne 1b`) are timed as `.+4` (llvm-mca 14 rejects `1b` and drops the branch: such loops
# were scored without it). A model search: check the result with the tests.
import random, re, subprocess, sys

BRANCHES = ("b", "cbz", "cbnz", "tbz", "tbnz")  # and b.cond (not bif, bit, bsl)
ACCUMULATE = ("bfxil", "bfi", "ins", "tbx", "smlal", "smlal2", "movk", "sli", "sri", "fmla", "fmls", "mls", "mla",
              "bit", "bif", "bsl", "ssra", "usra", "sqxtn2", "uqxtn2", "xtn2")


def reg(tok):
    if tok in ("sp", "wsp"):
        return "sp"
    m = re.fullmatch(r"[xw](\d+)", tok)
    if m:
        return "x" + m.group(1)
    m = re.fullmatch(r"[vqdsbh](\d+)(\.\w+)?(\[\d+\])?", tok)
    return "v" + m.group(1) if m else None


def is_branch(op):
    return op in BRANCHES or op.startswith("b.")


def parse(l):
    """(reads, writes, store, barrier) of one line."""
    if l.endswith(":"):
        return set(), set(), False, True
    if "// !" in l:
        regs = [reg(t) for t in l.split("// !")[1].split()]
        own = [r for r in (reg(t) for t in re.findall(r"[a-z]+\d+", l.split("//")[0])) if r]
        return set(regs) | set(own) | {"nzcv"}, {regs[0]}, False, False
    l = l.split("//")[0].strip()
    op, _, rest = l.partition(" ")
    rs = [r for r in (reg(t) for t in re.findall(r"\bw?sp\b|[a-z]+\d+(?:\.\w+)?(?:\[\d+\])?", rest)) if r]
    reads, writes, store = set(), set(), False
    mem = list(re.finditer(r"\[((?:x\d+|sp)[^\]]*)\]", rest))
    post = bool(mem) and ("]!" in rest or "," in rest[mem[-1].end():])
    if is_branch(op):
        return set(rs) | {"nzcv"}, set(), False, True
    if op in ("stp", "str", "strb", "strh", "st1", "stur"):
        reads |= set(rs)
        store = True
        if post:
            writes.add(reg(mem[-1].group(1).split(",")[0]))
    elif op.startswith("ld"):  # ldp, ldr, ldrb, ld1, ld1r, ld2 ...: every listed register written
        addr = [r for r in (reg(t) for t in re.findall(r"\bsp\b|[a-z]+\d+", mem[-1].group(1))) if r]
        dst = rs[:len(rs) - len(addr)]
        reads |= set(addr)
        writes |= set(dst)
        if op == "ld1":
            reads |= set(dst)
        if post:
            writes.add(addr[0])
    elif op in ("cmp", "cmn", "tst"):
        reads |= set(rs)
        writes.add("nzcv")
    elif op in ("ccmp", "ccmn"):
        reads |= set(rs) | {"nzcv"}
        writes.add("nzcv")
    else:
        writes.add(rs[0])
        reads |= set(rs[1:])
        if op in ACCUMULATE or (op == "mov" and rs[0].startswith("v") and "[" in rest.split(",")[0]):
            reads.add(rs[0])
        if op in ("adds", "subs", "ands"):
            writes.add("nzcv")
        if op in ("csel", "csinc", "csinv", "csneg", "cset", "csetm", "cinc", "cneg", "adc", "sbc"):
            reads.add("nzcv")
    return reads, writes, store, False


def dep(a, b):  # must a stay before b?
    ra, wa, sa, xa = info[a]
    rb, wb, sb, xb = info[b]
    mem = (sa and sb) or (MEM and (sa and LOAD[b] or LOAD[a] and sb))
    return xa or xb or bool(wa & rb or wa & wb or ra & wb) or mem


def cycles(orders, cpu):
    def blocks(o):
        body = [lines[i] for i in o if not lines[i].endswith(":")]
        b = [0] + CUTS + [len(body)]
        return [body[b[k]:b[k + 1]] for k in range(len(b) - 1)]
    parts = [blocks(o) if CUTS else [[lines[i] for i in o]] for o in orders]
    def text_of(blk):
        return "\n".join(re.sub(r" \d+[bf]$", " .+4", l.split("//")[0].strip()) for l in blk)
    text = "".join(f"# LLVM-MCA-BEGIN r{k}_{j}\n" + text_of(blk) + "\n# LLVM-MCA-END\n"
                   for k, p in enumerate(parts) for j, blk in enumerate(p))
    r = subprocess.run(["llvm-mca-14", "-mtriple=aarch64", f"-mcpu={cpu}", f"-iterations={ITER}"], input=text,
                       capture_output=True, text=True)
    c = [int(x) for x in re.findall(r"Total Cycles:\s+(\d+)", r.stdout)]
    n = len(parts[0])
    return [sum(c[k * n:(k + 1) * n]) for k in range(len(orders))]


def score(orders):
    return [int((a + W57 * b) * 100000 + b) for a, b in zip(cycles(orders, "cortex-a53"), cycles(orders, "cortex-a57"))]


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
    b = s % 100000
    return f"A53 {(s // 100000 - W57 * b) / ITER:.2f} A57 {b / ITER:.2f}"


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    opt = dict(a[2:].partition("=")[::2] for a in sys.argv[1:] if a.startswith("--"))
    inp, outp = args
    evals, head = int(opt.get("evals", 20000)), int(opt.get("head", 0))
    random.seed(int(opt.get("seed", 1)))
    ITER = int(opt.get("iter", 60))
    W57 = float(opt.get("a57", 0))  # 0: A57 breaks ties only
    CUTS = [int(c) for c in opt["cuts"].split(",")] if "cuts" in opt else []
    lines = [l.strip() for l in open(inp) if l.strip() and not l.strip().startswith("//")]
    info = [parse(l) for l in lines]
    MEM = "mem" in opt
    LOAD = [l.split()[0].startswith("ld") and not l.endswith(":") for l in lines]
    last = len(lines) - 1 if is_branch(lines[-1].split()[0]) else len(lines)
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
