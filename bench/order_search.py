#!/usr/bin/env python3
# bench/order_search.py: searches an instruction order of one block (a loop body whose last line
# is its branch, or straight-line code) against llvm-mca. AArch64 (default): Cortex-A53 cycles
# first, Cortex-A57 (the A72 column) to break ties, or A53 + W A57 with --a57=W. --arch=armv7:
# Thumb-2 + NEON against Cortex-A9 (as bench/count.sh times armhf blocks).
#
#   order_search.py IN.s OUT.s [EVALS] [--evals=N] [--head=K] [--seed=S] [--a57=W] [--cuts=A,B,..]
#                              [--iter=N] [--kick=N] [--mem] [--arch=armv7] [--runs]
#
# AArch64: operands are plain registers. Moves keep every register, flag and store order:
# accumulating ops (fmla, mla, bsl/bit/bif, ssra, sqxtn2, lane inserts, ld1 lane loads ...) read
# their destination, every register of a multi-register load (ld2 {a, b}) is written, conditional
# selects and ccmp read the flags. A last line that is a branch stays last; labels and other
# branches are barriers, except a branch annotated `// ! rA rB ..` (to fallback code that
# rewrites rA from the listed registers and returns), which reads those registers and its own
# and writes rA. --head=K pins the first K lines (e.g. stores a loop entry label must follow),
# --tail=K the last K (e.g. the compiler's code after an asm statement, timed with it).
# --cuts=A,B (body line indexes, labels not counted) scores the sum over the blocks cut
# there, as qemu's translation blocks are timed by bench/count.sh. --lcuts=A,B/C,..: several
# layouts of fixed cuts (the same text reached by two code copies cut at other places), scored
# by the sum over all their blocks; no line moves across any layout's cut (the cuts stay). --qcuts=P[,P2..]: cuts as qemu 7.2
# with the hotblocks plugin makes them for each order (bench/qemu_cuts.py: op counts, a page end at
# body index P, 0 for none; several: the sum over those code placements): for straight loop bodies
# longer than qemu translates in one block. --mem keeps loads in order
# with stores too (for blocks that reload what they store: stack state, layout buffers);
# without it only stores keep their order. sp is a register like the others.
# ARMv7 (--arch=armv7; lines starting with `.` are dropped, `@` starts a comment): one
# instruction a line, no IT: a conditional move that an IT block guards is written
# unconditionally with the comment `@flags`, which makes it read the flags. q registers are
# their two d registers, s registers their d register (an s write reads its d: partial write),
# sl/fp/ip/sb are r10/r11/r12/r9. Memory: loads and stores keep their order (two loads may
# swap) unless both carry different tags (`@m=NAME`); ldrb (texel gathers) move freely; --mem
# does not apply. Branches and labels are barriers, a last branch stays last. --runs: IN.s is a
# hot block of the ARMv7 50 .. 64 px spans as bench/count.sh dumps it (SB_MCA_DUMP); only the
# lines of a run's asm statement move, within it (a run: from a smulbt through the pixel groups
# and the VFP / NEON lines among and after them); the compiler's code between runs stays. Score:
# Cortex-A9 cycles (--iter default 100).
# Each step takes one instruction, times every legal position for it in one llvm-mca run,
# keeps the best (ties: any); after 150 steps without a gain it restarts from the best order
# moved a little (--kick moves). EVALS / --evals: orders timed in all (default 20000). Writes
# OUT.s at every gain. AArch64 branches to numeric local labels (`b.ne 1b`) are timed as `.+4`
# (llvm-mca 14 rejects `1b` and drops the branch: such loops were scored without it). A model
# search: check the result with the tests.
import random, re, subprocess, sys

BRANCHES = ("b", "cbz", "cbnz", "tbz", "tbnz")  # and b.cond (not bif, bit, bsl)
V7, REGION, QCUTS = False, None, None  # --arch=armv7, --runs, --qcuts (set by main)
LCUTS, SEGS = [], []  # --lcuts (set by main)
CACHE = {}  # per cpu: cycles of blocks already timed
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
    if op in ("stp", "str", "strb", "strh", "st1", "st2", "st3", "st4", "stur"):
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


# ARMv7 (Thumb-2 + NEON): registers as sets of r / d names, the flags `flags`, fpscr.
V7_ALIAS = {"sl": "r10", "fp": "r11", "ip": "r12", "sb": "r9"}
V7_ACC = ("vsra", "vmla", "vmlal", "vbsl", "vsri", "vsli", "mla", "vmov.32", "uxtah", "vbit", "vbif")
V7_COND = r"[a-z]+(eq|ne|le|lt|ge|gt|ls|hi|cs|cc|mi|pl)(\.\w+)?"
V7_NOT_COND = ("vcvt", "vmull", "vabs", "vshl", "vmul", "vtst", "vcgt", "vcge", "vmovl", "vqmovn")


def v7_regs(tok):
    tok = V7_ALIAS.get(tok, tok)
    if re.fullmatch(r"r(\d+)|lr|sp", tok):
        return {tok}
    m = re.fullmatch(r"q(\d+)", tok)
    if m:
        n = int(m.group(1))
        return {f"d{2 * n}", f"d{2 * n + 1}"}
    m = re.fullmatch(r"d(\d+)(\[\d\])?", tok)
    if m:
        return {f"d{m.group(1)}"}
    m = re.fullmatch(r"s(\d+)", tok)
    return {f"d{int(m.group(1)) // 2}"} if m else set()


def v7_is_branch(op):
    return op in ("b", "b.w", "b.n", "bx", "cbz", "cbnz") or re.fullmatch(
        r"b(eq|ne|le|lt|ge|gt|ls|hi|cs|cc|mi|pl|vs|vc|hs|lo)(\.[wn])?", op) is not None


V7_FLAG_SETTERS = ("add", "sub", "rsb", "adc", "sbc", "and", "orr", "eor", "bic", "lsl", "lsr", "asr", "ror",
                   "mov", "mvn", "mul", "orn")


def parse_v7(l):
    """(reads, writes, memory class, barrier) of one ARMv7 line. Memory class: None, "free"
    (ldrb), "ld" / "st", with ":TAG" for a line tagged `@m=TAG`."""
    if l.split("@")[0].strip().endswith(":"):
        return set(), set(), None, True
    flags = "@flags" in l
    tag = re.search(r"@m=(\w+)", l)
    op, _, rest = l.split("@")[0].strip().partition(" ")
    if v7_is_branch(op):
        return {"flags"}, set(), None, True
    rest = re.sub(r"d(\d+)-d(\d+)", lambda m: ",".join(f"d{i}" for i in range(int(m.group(1)), int(m.group(2)) + 1)),
                  rest)  # {d0-d3}
    toks = [t for t in re.findall(r"[a-z]+\d*(?:\[\d\])?", rest) if v7_regs(t)]
    allr = [v7_regs(t) for t in toks]
    memm = re.search(r"\[([^\]]*)\]", rest)
    post = "!" in rest or (memm is not None and "," in rest[memm.end():])  # [rN]! or post-index [rN], #k
    inside = set().union(*[v7_regs(t) for t in re.findall(r"[a-z]+\d*", memm.group(1))]) if memm else set()
    base = op.split(".")[0]
    is_store = base in ("str", "strd", "strb", "vst1", "vst2", "vst3", "vst4", "vstr", "strh")
    is_load = base in ("ldr", "ldrd", "ldrb", "vld1", "vld2", "vld3", "vld4", "vldr", "ldrh")
    reads, writes = set(), set()
    if is_store:
        reads = set().union(*allr)
        if post:
            writes |= inside
    elif is_load:
        outside = re.sub(r"\[[^\]]*\]", "", rest)
        writes = set().union(*[v7_regs(t) for t in re.findall(r"[a-z]+\d*(?:\[\d\])?", outside)])
        reads = set(inside)
        if post:
            writes |= inside
    elif base in ("cmp", "tst", "cmn", "teq"):
        reads, writes = set().union(*allr), {"flags"}
    elif base in ("vcmp", "vcmpe"):
        reads, writes = set().union(*allr), {"fpscr"}
    elif base == "vmrs":
        reads, writes = {"fpscr"}, {"flags"}
    else:
        if allr:
            writes, reads = set(allr[0]), set().union(*allr[1:])
            if base == "vmov" and len(allr) == 3 and toks[0].startswith("r"):  # vmov rA, rB, dC
                writes, reads = allr[0] | allr[1], set(allr[2])
            if any(op.startswith(a) for a in V7_ACC):
                reads |= allr[0]
        if re.fullmatch(V7_COND, op) and base not in V7_NOT_COND:  # conditional: reads the flags and its target
            reads |= {"flags"} | writes
        if toks and toks[0].startswith("s"):  # s-register writes are partial: read the d too
            reads |= allr[0]
        if base.endswith("s") and base[:-1] in V7_FLAG_SETTERS:  # adds, lsrs, movs ...: set the flags
            writes |= {"flags"}
    if flags:
        reads |= {"flags"}
    mem = None
    if is_store or is_load:
        mem = "free" if base == "ldrb" else ("st" if is_store else "ld")
        if tag and mem != "free":
            mem += ":" + tag.group(1)
    return reads, writes, mem, False


def mem_dep_v7(ma, mb):
    if not ma or not mb or "free" in (ma, mb) or not (ma.startswith("st") or mb.startswith("st")):
        return False
    ta, tb = ma.partition(":")[2], mb.partition(":")[2]
    return not ta or not tb or ta == tb


V7_PIX = ("smulbt", "uxtah", "add", "ldrb", "orr", "str")


def run_regions(lines):
    """--runs: per line the index of its run statement, or -1 (fixed)."""
    n, reg, r, i = len(lines), [-1] * len(lines), -1, 0
    while i < n:
        if lines[i].startswith("smulbt") and (r < 0 or reg[i - 1] != r):
            r += 1
            j = last = i
            while j < n:
                op = lines[j].split()[0].split(".")[0]
                if op in V7_PIX or lines[j].startswith("v"):
                    if op == "str" or lines[j].startswith("v"):
                        last = j
                    j += 1
                else:
                    break
            for k in range(i, last + 1):
                reg[k] = r
            i = last + 1
        else:
            i += 1
    return reg


def dep(a, b):  # must a stay before b?
    ra, wa, sa, xa = info[a]
    rb, wb, sb, xb = info[b]
    if V7:
        return xa or xb or bool(wa & rb or wa & wb or ra & wb) or mem_dep_v7(sa, sb)
    mem = (sa and sb) or (MEM and (sa and LOAD[b] or LOAD[a] and sb))
    return xa or xb or bool(wa & rb or wa & wb or ra & wb) or mem


def cycles(orders, cpu):
    def blocks(o):
        body = [lines[i] for i in o if not lines[i].endswith(":")]
        b = [0] + CUTS + [len(body)]
        return [body[b[k]:b[k + 1]] for k in range(len(b) - 1)]
    if LCUTS:
        def blocks(o):  # --lcuts: every layout's fixed cuts, the sum
            body = [lines[i] for i in o if not lines[i].endswith(":")]
            res = []
            for cl in LCUTS:
                b = [0] + cl + [len(body)]
                res += [body[b[k]:b[k + 1]] for k in range(len(b) - 1)]
            return res
    if QCUTS is not None:
        def blocks(o):
            body = [lines[i] for i in o if not lines[i].endswith(":")]
            res = []
            for page in QCUTS:  # (several: the sum over those placements)
                b = [0] + qemu_cuts.cuts(body, page=page) + [len(body)]
                res += [body[b[k]:b[k + 1]] for k in range(len(b) - 1)]
            return res
    parts = [blocks(o) if CUTS or LCUTS or QCUTS is not None else [[lines[i] for i in o]] for o in orders]
    cmt, strip = ("@", "@") if V7 else ("#", "//")

    def text_of(blk):
        body = [l.split(strip)[0].strip() for l in blk]
        return "\n".join(body if V7 else [re.sub(r" \d+[bf]$", " .+4", l) for l in body])
    texts = [[text_of(blk) for blk in p] for p in parts]
    cache = CACHE.setdefault(cpu, {})  # block text -> cycles: a move changes one or two cut blocks
    if len(cache) > 50000:
        cache.clear()
    todo = sorted({t for ts in texts for t in ts if t not in cache})
    if todo:
        text = "".join(f"{cmt} LLVM-MCA-BEGIN r{k}\n" + t + f"\n{cmt} LLVM-MCA-END\n" for k, t in enumerate(todo))
        if V7:
            text = ".syntax unified\n.thumb\n" + text
            target = ["-mtriple=thumbv7-linux-gnueabihf", f"-mcpu={cpu}", "-mattr=+neon,+vfp4"]
        else:
            target = ["-mtriple=aarch64", f"-mcpu={cpu}"]
        r = subprocess.run(["llvm-mca-14", *target, f"-iterations={ITER}"], input=text, capture_output=True, text=True)
        c = [int(x) for x in re.findall(r"Total Cycles:\s+(\d+)", r.stdout)]
        if len(c) != len(todo):
            sys.exit(r.stderr[:400])
        cache.update(zip(todo, c))
    return [sum(cache[t] for t in ts) for ts in texts]


def score(orders):
    if V7:
        return cycles(orders, "cortex-a9")
    # (A53 + W A57, A57): compared as tuples, A57 breaking ties
    return [(a + W57 * b, b) for a, b in zip(cycles(orders, "cortex-a53"), cycles(orders, "cortex-a57"))]


def window(order, i):
    x, lo, hi = order[i], i, i
    lo_min, hi_max = head, last - 1
    if REGION:  # --runs: within the run's statement (its lines keep their positions as a set)
        lo_min, hi_max = max(lo_min, RSPAN[REGION[x]][0]), min(hi_max, RSPAN[REGION[x]][1])
    if LCUTS:  # within the segment between the layouts' cuts (no line crosses a cut)
        lo_min = max([lo_min] + [c for c in SEGS if c <= i])
        hi_max = min([hi_max] + [c - 1 for c in SEGS if c > i])
    while lo - 1 >= lo_min and not dep(order[lo - 1], x):
        lo -= 1
    while hi + 1 <= hi_max and not dep(x, order[hi + 1]):
        hi += 1
    return lo, hi


def moved(order, i, j):
    new = order[:i] + order[i + 1:]
    new.insert(j, order[i])
    return new


def show(s):
    if V7:
        return f"A9 {s / ITER:.2f}"
    return f"A53 {(s[0] - W57 * s[1]) / ITER:.2f} A57 {s[1] / ITER:.2f}"


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    opt = dict(a[2:].partition("=")[::2] for a in sys.argv[1:] if a.startswith("--"))
    inp, outp = args[:2]
    evals = int(opt.get("evals", args[2] if len(args) > 2 else 20000))
    head = int(opt.get("head", 0))
    random.seed(int(opt.get("seed", 1)))
    V7 = opt.get("arch", "aarch64") == "armv7"
    if opt.get("arch", "armv7") not in ("armv7", "aarch64") or ("runs" in opt and not V7):
        sys.exit("--arch=aarch64 (default) or armv7; --runs needs --arch=armv7")
    ITER = int(opt.get("iter", 100 if V7 else 60))
    W57 = float(opt.get("a57", 0))  # 0: A57 breaks ties only
    CUTS = [int(c) for c in opt["cuts"].split(",")] if "cuts" in opt else []
    QCUTS = [int(c) for c in opt["qcuts"].split(",")] if "qcuts" in opt else None
    LCUTS = [[int(c) for c in g.split(",") if c] for g in opt["lcuts"].split("/")] if "lcuts" in opt else []
    SEGS = sorted({c for cl in LCUTS for c in cl})
    if QCUTS is not None:
        import os
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import qemu_cuts
    lines = [l.strip() for l in open(inp) if l.strip() and not l.strip().startswith("//")]
    if V7:
        lines = [l for l in lines if not l.startswith((".", "@"))]
    info = [parse_v7(l) if V7 else parse(l) for l in lines]
    MEM = "mem" in opt
    LOAD = [l.split()[0].startswith("ld") and not l.endswith(":") for l in lines]
    last = len(lines) - 1 if (v7_is_branch if V7 else is_branch)(lines[-1].split()[0]) else len(lines)
    last = min(last, len(lines) - int(opt.get("tail", 0)))  # --tail=K: the last K lines stay
    REGION = run_regions(lines) if "runs" in opt else None
    RSPAN = {}
    for k, rg in enumerate(REGION or []):
        if rg >= 0:
            RSPAN[rg] = (RSPAN.get(rg, (k, k))[0], k)
    movable = [k for k in range(head, last) if not REGION or REGION[k] >= 0]
    order = list(range(len(lines)))
    cur = best = score([order])[0]
    best_order, stall, done = list(order), 0, 0
    print("start", show(cur), flush=True)
    while done < evals:
        i = random.choice(movable) if REGION else random.randrange(head, last)
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
                k = random.choice(movable) if REGION else random.randrange(head, last)
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
