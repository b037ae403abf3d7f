#!/usr/bin/env python3
# bench/count_report.py: the work behind bench/count.sh (which builds everything first).
#
# For each target (x86-64, aarch64, armhf) and each case x variant of starbow_count_kernels:
#   instructions per unit  = (I(2R reps) - I(R reps)) / (R * units)       exact, deterministic
#       x86-64: valgrind cachegrind "I refs"; ARM: qemu-user + the insn plugin ("insns:")
#   estimated cycles/unit  = the kernel's hot translation blocks, found by running the driver
#       under qemu-user with the hotblocks plugin (x86-64 too: qemu-x86_64 -cpu max), each
#       block disassembled from the binary (objdump) and timed by llvm-mca on named cores:
#         cycles/unit = sum over hot blocks in sb::simd code of (llvm-mca cycles per block
#                       iteration x executions) / (R * units)
#       "cover" = share of the kernel's counted instructions that those blocks hold (hotblocks
#       lists the 400 most executed blocks (count.sh's build); code outside the binary, e.g.
#       libc's memcpy, is not timed).
#   Each block is timed on its own as if it looped (llvm-mca's model), so overlap between
#   consecutive blocks on out-of-order cores is not credited: a mild over-estimate there.
# Also the whole frame: x86-64 by callgrind over a flythrough of F and 2F frames, aarch64 and
# armhf by qemu-user's insn plugin over the same flythroughs.
#
# Writes the table to stdout and to bench/counts.md.
# Filter (bench/count.sh --quick passes arguments through): --only=PREFIX[,PREFIX...] keeps
# the cases starting with a prefix (e.g. --only=block_mip or --only=span,persp), --variants=a,b keeps those
# variants; a filtered run replaces only its own rows of the existing bench/counts.md.
import json, math, os, re, subprocess, sys, time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
B = os.path.join(ROOT, "build")
PLUG = os.path.join(B, "qemu-plugins")
MCA = os.environ.get("LLVM_MCA", "llvm-mca-14")

TARGETS = [
    # name, driver, emulator prefix (for qemu), objdump, mca triple, cpus, comment char
    dict(name="x86-64", exe=f"{B}/count/starbow_count_kernels", qemu=["qemu-x86_64", "-cpu", "max"],
         objdump="objdump", triple="x86_64-linux-gnu", cpus=["znver3", "skylake"], cc="#"),
    dict(name="aarch64", exe=f"{B}/count-aarch64/starbow_count_kernels",
         qemu=["qemu-aarch64", "-L", "/usr/aarch64-linux-gnu", "-cpu", "cortex-a53"],
         objdump="aarch64-linux-gnu-objdump", triple="aarch64-linux-gnu", cpus=["cortex-a53", "cortex-a72"], cc="#"),  # llvm-mca 14 sees region markers after "#" only
    dict(name="armhf", exe=f"{B}/count-armhf/starbow_count_kernels",
         qemu=["qemu-arm", "-L", "/usr/arm-linux-gnueabihf", "-cpu", "cortex-a15"],
         objdump="arm-linux-gnueabihf-objdump", triple="thumbv7-linux-gnueabihf", cpus=["cortex-a9"], cc="@"),
]
CPU_NOTE = {"cortex-a72": "cortex-a72 (LLVM 14 times it with its Cortex-A57 model)"}

KERNEL = {"span16": "surface_span (16-px runs)", "span1920": "surface_span (1 call, 1920 px)",
          "lit16": "lit_span (single pass, 16-px runs, mip 0)",
          "lit16m2": "lit_span (single pass, 16-px runs, mip 2, 0.5-1 texel/px, second order)",
          "block_mip0": "surface_block mip 0", "block_mip1": "surface_block mip 1",
          "block_mip2": "surface_block mip 2", "block_mip3": "surface_block mip 3",
          "z1920": "z_span", "palette": "expand_palette (x1)",
          "palette2": "expand_palette (x2)", "palette3": "expand_palette (x3)", "palette4": "expand_palette (x4)",
          "alias32": "alias_span (17-47 px spans, mean 32, visible)", "alias1920h": "alias_span (1920 px, half hidden)",
          "persp1920": "surface_span_persp (1 span, 1920 px)", "persp64": "surface_span_persp (spans of 50-64 px, mean 57)",
          "persp1920lin": "surface_span_persp (1920 px, linear steps)",
          "persp64lin": "surface_span_persp (spans of 50-64 px, linear steps)",
          "persp64single": "surface_span_persp (spans of 50-64 px, one call each)",
          "persp192": "surface_span_persp (spans of 179-205 px, mean 192)",
          "persp192lin": "surface_span_persp (spans of 179-205 px, linear steps)",
          "persp32": "surface_span_persp (spans of 17-48 px, mean 32.5)",
          "persp16": "surface_span_persp (spans of 1-16 px, mean 8.5)",
          "persp72": "surface_span_persp (spans of 65-80 px, mean 72.5)",
          "persp32mix": "surface_span_persp (mixed batch: 17-48 px among linear, 1-16, 49-64, long)"}
UNIT = {"palette": "src px", "palette2": "out px", "palette3": "out px", "palette4": "out px"}


def sh(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def reps_for(units):
    return max(2, math.ceil(200000 / units))


# ---------------------------------------------------------------- instruction counts

def count_x86(exe, args):
    r = sh(["valgrind", "--tool=cachegrind", "--cache-sim=no", "--cachegrind-out-file=/dev/null", exe] + args)
    m = re.search(r"I\s+refs:\s+([\d,]+)", r.stderr)
    if not m:
        raise RuntimeError("valgrind: no I refs\n" + r.stderr[-2000:])
    return int(m.group(1).replace(",", ""))


def count_qemu(t, args, log):
    r = sh(t["qemu"] + ["-plugin", f"{PLUG}/libinsn.so", "-d", "plugin", "-D", log, t["exe"]] + args)
    txt = open(log).read()
    m = re.search(r"insns:\s*(\d+)", txt)
    if r.returncode or not m:
        raise RuntimeError(f"qemu insn count failed: {r.stderr[-500:]} {txt[-500:]}")
    return int(m.group(1))


# ---------------------------------------------------------------- hot blocks -> llvm-mca

class Disasm:
    """Address -> (instruction text) for one binary, plus the function symbol of each address."""

    def __init__(self, t):
        self.t = t
        out = sh([t["objdump"], "-d", "-C", "--no-show-raw-insn", t["exe"]]).stdout
        self.insns, self.addrs, self.func_of = {}, [], {}
        func = None
        for line in out.splitlines():
            m = re.match(r"^([0-9a-f]+) <(.*)>:$", line)
            if m:
                func = m.group(2)
                continue
            m = re.match(r"^\s+([0-9a-f]+):\s+(.*)$", line)
            if m and func:
                a = int(m.group(1), 16)
                self.insns[a] = m.group(2).strip()
                self.func_of[a] = func
                self.addrs.append(a)
        self.index = {a: i for i, a in enumerate(self.addrs)}

    def block(self, pc, n):
        i = self.index.get(pc)
        if i is None:
            return None, None
        code = [self.clean(self.insns[a]) for a in self.addrs[i:i + n]]
        if self.t["name"] == "armhf":
            code = self.split_lists(self.drop_it(code))
        return code, self.func_of[pc]

    # llvm-mca 14 cannot time Thumb-2's IT instruction: drop it and make the 1-4 instructions
    # it predicates unconditional (their timing is the same; the IT itself is not counted).
    INV = dict(eq="ne", ne="eq", cs="cc", cc="cs", hs="lo", lo="hs", mi="pl", pl="mi", vs="vc", vc="vs",
               hi="ls", ls="hi", ge="lt", lt="ge", gt="le", le="gt")

    # llvm-mca 14 has no Cortex-A9 timing for register-list pushes and pops (nor ldm/stm): time
    # them as one store or load per register (the same memory traffic), plus the writeback.
    def split_lists(self, code):
        out = []
        for c in code:
            c2 = re.sub(r"^(v?)(?:stmdb|stmfd) sp!, ", r"\1push ", c)
            c2 = re.sub(r"^(v?)(?:ldmia|ldmfd|ldm) sp!, ", r"\1pop ", c2)
            m = re.match(r"^(ldm|stm)(?:ia)? (r\d+|ip|lr), \{([^}]*)\}$", c2)  # ldm/stm rN, {...}: one each
            if m:
                regs = []
                for part in m.group(3).split(","):
                    r = re.match(r"^r(\d+)-r(\d+)$", part.strip())
                    regs += [f"r{i}" for i in range(int(r.group(1)), int(r.group(2)) + 1)] if r else [part.strip()]
                op = "ldr" if m.group(1) == "ldm" else "str"
                out += [f"{op} {r}, [{m.group(2)}, #{4 * i}]" for i, r in enumerate(regs)]
                continue
            m = re.match(r"^(v?)(push|pop) \{(.*)\}$", c2)
            g = re.match(r"^(v?)(ldm|stm)(ia|db)?(?:\.\d+)? (\w+)(!?), \{(.*)\}$", c2)
            if g and not m:  # ldm/stm (vldm/vstm, ia or db) on another base: one load/store per register
                regs = []
                for part in g.group(6).split(","):
                    part = part.strip()
                    r = re.match(r"^([rd])(\d+)-[rd](\d+)$", part)
                    regs += [f"{r.group(1)}{i}" for i in range(int(r.group(2)), int(r.group(3)) + 1)] if r else [part]
                size = 8 if g.group(1) else 4
                op = ("vldr" if g.group(2) == "ldm" else "vstr") if g.group(1) else ("ldr" if g.group(2) == "ldm" else "str")
                base = -size * len(regs) if g.group(3) == "db" else 0  # db: the registers below the base
                out += [f"{op} {r}, [{g.group(4)}, #{base + size * i}]" for i, r in enumerate(regs)]
                if g.group(5):
                    out.append(f"{'sub' if base else 'add'} {g.group(4)}, {g.group(4)}, #{size * len(regs)}")
                continue
            if not m:
                out.append(c)
                continue
            regs = []
            for part in m.group(3).split(","):
                part = part.strip()
                r = re.match(r"^([rdq])(\d+)-[rdq](\d+)$", part)
                regs += [f"{r.group(1)}{i}" for i in range(int(r.group(2)), int(r.group(3)) + 1)] if r else [part]
            op = ("vstr" if m.group(2) == "push" else "vldr") if m.group(1) else ("str" if m.group(2) == "push" else "ldr")
            out += [f"{op} {r}, [sp, #{8 * i if m.group(1) else 4 * i}]" for i, r in enumerate(regs)]
        return out

    def drop_it(self, code):
        out, pending = [], []
        for c in code:
            m = re.match(r"^it([te]*) (\w+)$", c)
            if m:
                pending = [m.group(2)] + [m.group(2) if x == "t" else self.INV.get(m.group(2), "") for x in m.group(1)]
                continue
            if not pending:  # an IT block cut by a translation-block start: drop the condition
                m2 = re.match(r"^(v?(?:mov|add|sub|ldr|str|orr|and|eor|rsb|mvn|cmp|cmn|vmov|vneg|vabs)\w*?)"
                              r"(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)((?:\.\w+)*) (.*)$", c)
                if m2 and not m2.group(1).endswith(("s", "b", "h")) or m2 and m2.group(1) in ("cmp", "cmn"):
                    c = f"{m2.group(1)}{m2.group(3)} {m2.group(4)}"
            if pending:
                cond = pending.pop(0)
                mn, _, rest = c.partition(" ")
                base, dot, suffix = mn.partition(".")  # vmovle.f64: the condition precedes the type
                if cond and base.endswith(cond):
                    mn = base[: -len(cond)] + dot + suffix
                c = (mn + " " + rest).strip()
            out.append(c)
        return out

    def clean(self, s):
        name = self.t["name"]
        if name == "x86-64":
            # a call target's symbol may hold '#' (C++ lambdas: "{lambda(...)#1}"): label it first
            s = re.sub(r"\b(0x)?[0-9a-f]+ <.*>", ".Ltgt", s)
            s = s.split("#")[0]
        elif name == "aarch64":
            s = s.split("//")[0]
        else:
            # "vmov.f64 d8, #96 @ 0x3f000000  0.5": the assembler wants the value, not the encoding.
            m = re.match(r"^(vmov\S*\s+[ds]\d+), #\d+\s+@ 0x[0-9a-f]+\s+(\S+)", s)
            if m:
                s = f"{m.group(1)}, #{m.group(2)}"
            s = re.split(r"\s[;@]\s", s + " ")[0]
        s = s.strip()
        # Branch / literal targets "401130 <f+0x10>" -> a label (llvm-mca ignores targets).
        s = re.sub(r"\b(0x)?[0-9a-f]+ <.*>$", ".Ltgt", s)
        if name == "armhf":  # no width suffixes (LLVM picks the encoding), assembler alignment syntax
            s = re.sub(r"^(\w+)\.[wn]\b", r"\1", s)
            s = re.sub(r"\.[wn](\s)", r"\1", s, count=1)
            s = re.sub(r"\[(\w+) :(\d+)\]", r"[\1:\2]", s)
        s = re.sub(r"\s+", " ", s).strip()
        if name == "x86-64" and s.startswith(("cs ", "ds ", "data16 ")):
            s = s.split(" ", 1)[1]
        # llvm-mca does not model calls: it gives each one a latency of 100 cycles (its own
        # warning), which an in-order model waits out. A call is timed as the branch it is
        # (the callee's blocks are timed as their own regions, its return as a branch).
        if name == "x86-64":
            s = re.sub(r"^callq? ", "jmp ", s)
        elif name == "aarch64":
            s = re.sub(r"^bl ", "b ", s)
            s = re.sub(r"^blr ", "br ", s)
        else:
            s = re.sub(r"^blx (r\d+|lr|ip)$", r"bx \1", s)
            s = re.sub(r"^blx? ", "b ", s)
        return s


def hot_blocks(t, args, log):
    r = sh(t["qemu"] + ["-plugin", f"{PLUG}/libhotblocks.so", "-d", "plugin", "-D", log, t["exe"]] + args)
    blocks = []
    for line in open(log):
        m = re.match(r"0x([0-9a-f]+), (\d+), (\d+), (\d+)", line)
        if m:
            blocks.append((int(m.group(1), 16), int(m.group(3)), int(m.group(4))))
    return blocks


def mca_regions(t, cpu, regions):
    """regions: list of instruction lists -> list of cycles per iteration (None on failure)."""
    cc = t["cc"]
    head = ".syntax unified\n.thumb\n" if t["name"] == "armhf" else ""
    text = head + "".join(f"{cc} LLVM-MCA-BEGIN r{i}\n" + "\n".join(r) + f"\n{cc} LLVM-MCA-END\n"
                          for i, r in enumerate(regions))
    attr = ["-mattr=+neon,+vfp4"] if t["name"] == "armhf" else []
    res = sh([MCA, f"-mtriple={t['triple']}", f"-mcpu={cpu}", "-iterations=200"] + attr, input=text)
    if res.returncode:
        return None, res.stderr[-800:]
    cyc = [float(c) for c in re.findall(r"Total Cycles:\s+(\d+)", res.stdout)]
    its = [float(c) for c in re.findall(r"Iterations:\s+(\d+)", res.stdout)]
    if len(cyc) != len(regions):
        return None, "region count mismatch"
    return [c / i for c, i in zip(cyc, its)], None


def estimate(t, dis, case, variant, units, reps, kernel_instr):
    blocks = hot_blocks(t, [case, variant, str(reps)], f"/tmp/sb_count_hb_{os.getpid()}.log")
    regions, weights, insns = [], [], 0
    for pc, icount, ecount in blocks:
        code, func = dis.block(pc, icount)
        if not code or "sb::simd::" not in func.split("(")[0]:
            continue
        regions.append(code)
        weights.append(ecount)
        insns += icount * ecount
    cover = insns / kernel_instr if kernel_instr else 0.0
    if os.environ.get("SB_MCA_DUMP"):  # debugging aid: the hot blocks and their weights
        import json
        json.dump({"regions": regions, "weights": weights, "reps": reps, "units": units},
                  open(os.environ["SB_MCA_DUMP"] + f".{case}.{variant}.{t['name']}.json", "w"))
    out = {}
    gather = any(re.search(r"gather", " ".join(r)) for r in regions)
    for cpu in t["cpus"]:
        cyc, err = mca_regions(t, cpu, regions) if regions else (None, "no hot blocks")
        if cyc is None:
            out[cpu] = None
            print(f"  llvm-mca {cpu} {case} {variant}: {err}", file=sys.stderr)
            continue
        out[cpu] = sum(c * w for c, w in zip(cyc, weights)) / (reps * units)
    return out, cover, gather


# ---------------------------------------------------------------- whole frames (x86-64)

def callgrind_total(cmd, env, outfile):
    r = sh(["valgrind", "--tool=callgrind", f"--callgrind-out-file={outfile}"] + cmd, env=env, cwd=ROOT)
    m = re.search(r"Collected\s*:\s*(\d+)", r.stderr)
    if not m:
        raise RuntimeError("callgrind failed: " + r.stderr[-1500:])
    return int(m.group(1))


def self_cost(outfile, pattern):
    """Self instructions of the callgrind_annotate lines (source file and function) matching pattern."""
    r = sh(["callgrind_annotate", "--threshold=100", outfile])
    total = 0
    for line in r.stdout.splitlines():
        m = re.match(r"\s*([\d,]+)\s+\([^)]*\)\s+\S*:(.*)$", line) or re.match(r"\s*([\d,]+)\s+\S*:(.*)$", line)
        if m and re.search(pattern, line):
            total += int(m.group(1).replace(",", ""))
    return total


def frame_args(exe, quake_dir, res):
    """The flythrough's command line (without the frame count) and the map's label."""
    if os.path.isdir(os.path.join(quake_dir, "lq1")):
        return [exe, "-basedir", quake_dir, "-game", "lq1", "-res", res, "+viewmap", "lq_e0m1"], "lq_e0m1"
    return [exe, "-res", res, "+viewmap", "sample"], "sample (no LibreQuake data)"


def frames(quake_dir, f1, f2, res):
    w, h = map(int, res.split("x"))
    base, label = frame_args(f"{B}/count/starbow", quake_dir, res)
    rows = []
    for mode, env_extra in (("tuned", {}), ("scalar", {"STARBOW_SCALAR": "1"})):
        env = dict(os.environ, **env_extra)
        tot, span = [], []
        for f in (f1, f2):
            of = f"/tmp/sb_count_cg_{os.getpid()}_{f}.out"
            tot.append(callgrind_total(base + ["+flythrough", str(f), "+quit"], env, of))
            # The span drawer: surface_span* and everything compiled from asm/span_persp*.cpp and
            # its headers (its helpers are static functions, some with inlined intrinsics' lines).
            span.append(self_cost(of, r"surface_span|asm/span_(persp\w*\.(cpp|h)|walk\.h):|simd::\(anonymous namespace\)::(persp_|draw_run|run_steps|lin_|div_steps|last_)"))
            os.unlink(of)
        px = (f2 - f1) * w * h
        rows.append((mode, (tot[1] - tot[0]) / px, (span[1] - span[0]) / px, (tot[1] - tot[0]) / (f2 - f1)))
    return label, rows


def frames_qemu(t, quake_dir, f1, f2, res):
    """aarch64 / armhf: the same flythroughs under qemu-user, counted by the insn plugin (the
    whole process: no per-function split). Rows: (mode, instr/pixel/frame, instr/frame)."""
    w, h = map(int, res.split("x"))
    exe = os.path.join(os.path.dirname(t["exe"]), "starbow")
    base, label = frame_args(exe, quake_dir, res)
    rows = []
    for mode, env_extra in (("tuned", {}), ("scalar", {"STARBOW_SCALAR": "1"})):
        tot = []
        for f in (f1, f2):
            log = f"/tmp/sb_count_frame_{os.getpid()}.log"
            r = sh(t["qemu"] + ["-plugin", f"{PLUG}/libinsn.so", "-d", "plugin", "-D", log] + base
                   + ["+flythrough", str(f), "+quit"], env=dict(os.environ, **env_extra), cwd=ROOT)
            m = re.search(r"insns:\s*(\d+)", open(log).read())
            if r.returncode or not m:
                raise RuntimeError(f"{t['name']} flythrough failed: {r.stderr[-800:]}")
            tot.append(int(m.group(1)))
        rows.append((mode, (tot[1] - tot[0]) / ((f2 - f1) * w * h), (tot[1] - tot[0]) / (f2 - f1)))
    return label, rows


# ---------------------------------------------------------------- main

def fmt(x, d=2):
    return "—" if x is None else f"{x:.{d}f}"


def opt(name):
    for a in sys.argv[1:]:
        if a.startswith(f"--{name}="):
            return tuple(x for x in a.split("=", 1)[1].split(",") if x)
    return ()


ONLY, VARIANTS = opt("only"), opt("variants")


def merge_rows(path, rows):
    """Replaces the table rows (same kernel, target, variant) of an existing counts.md."""
    lines = open(path).read().split("\n")
    key = lambda l: tuple(c.strip() for c in l.split("|")[1:4])
    for r in rows:
        hits = [i for i, l in enumerate(lines) if l.startswith("| ") and key(l) == key(r)]
        if hits:
            lines[hits[0]] = r
        else:  # after the last row of the same kernel, else of the kernels before it, else at the end
            same = [i for i, l in enumerate(lines) if l.startswith("| ") and key(l)[0] == key(r)[0]]
            order = list(KERNEL.values())
            before = order[:order.index(key(r)[0])] if key(r)[0] in order else []
            prev = [i for i, l in enumerate(lines) if l.startswith("| ") and key(l)[0] in before]
            last = [i for i, l in enumerate(lines) if l.startswith("| ")]
            lines.insert((same or prev or last)[-1] + 1, r)
    open(path, "w").write("\n".join(lines))


def main():
    quick = "--quick" in sys.argv or bool(ONLY or VARIANTS)
    t0 = time.time()
    results = []  # (target, case, variant, ipu, {cpu: cyc}, cover, gather)
    for t in TARGETS:
        if not os.path.exists(t["exe"]):
            print(f"{t['name']}: {t['exe']} missing, skipped", file=sys.stderr)
            continue
        runner = t["qemu"] if t["name"] != "x86-64" else []
        cases = [l.split() for l in sh(runner + [t["exe"], "list"]).stdout.splitlines()]
        cases = [c for c in cases if (not ONLY or c[0].startswith(ONLY)) and (not VARIANTS or c[1] in VARIANTS)]
        dis = Disasm(t)
        for case, variant, units in cases:
            units = int(units)
            r = reps_for(units)
            args = lambda n: [case, variant, str(n)]
            if t["name"] == "x86-64":
                i1, i2 = count_x86(t["exe"], args(r)), count_x86(t["exe"], args(2 * r))
            else:
                log = f"/tmp/sb_count_insn_{os.getpid()}.log"
                i1, i2 = count_qemu(t, args(r), log), count_qemu(t, args(2 * r), log)
            ipu = (i2 - i1) / (r * units)
            cyc, cover, gather = estimate(t, dis, case, variant, units, r, i2 - i1)
            results.append((t, case, variant, ipu, cyc, cover, gather))
            print(f"  {t['name']:8s} {case:11s} {variant:7s} {ipu:8.2f} instr/unit  "
                  + " ".join(f"{c}={fmt(v)}" for c, v in cyc.items()) + f"  cover {cover:.0%}", file=sys.stderr)

    # Per frame (x86-64 only: valgrind).
    frame = None
    if not quick and os.path.exists(f"{B}/count/starbow"):
        qd = os.environ.get("STARBOW_QUAKE_DIR", os.path.join(ROOT, "..", "shared", "quake"))
        try:
            frame = frames(qd, 50, 100, "320x240")
        except RuntimeError as e:
            print(f"frames: {e}", file=sys.stderr)
    arm_frames = []
    if not quick:
        qd = os.environ.get("STARBOW_QUAKE_DIR", os.path.join(ROOT, "..", "shared", "quake"))
        for t in TARGETS[1:]:
            if os.path.exists(os.path.join(os.path.dirname(t["exe"]), "starbow")):
                try:
                    arm_frames.append((t["name"],) + frames_qemu(t, qd, 50, 100, "320x240"))
                except RuntimeError as e:
                    print(f"frames: {e}", file=sys.stderr)

    md = ["# Instruction counts and estimated cycles (bench/count.sh)", "",
          "Generated by `bench/count.sh`; deterministic instruction counts, model-estimated cycles. Not a test.", "",
          "- **instr/unit**: instructions per pixel (per texel for surface_block, per source pixel for "
          "expand_palette), from two runs of `starbow_count_kernels` (R and 2R repetitions) differenced: "
          "x86-64 under valgrind (cachegrind), aarch64 / armhf under qemu-user with the `insn` plugin.",
          "- **cycles/unit**: llvm-mca (LLVM 14) on the kernel's hot blocks (qemu `hotblocks` plugin), weighted by "
          "how often each ran; *cover* is the share of counted instructions those blocks hold. "
          "cortex-a72 is timed with LLVM 14's Cortex-A57 model (no A72 model). armhf is Thumb-2 + NEON "
          "(-mfpu=neon-vfpv4), timed on cortex-a9 (LLVM has no Cortex-A7 model).",
          "- **x scalar**: scalar instr/unit ÷ variant instr/unit (above 1 = fewer instructions); the cycle "
          "ratio is in brackets.",
          "- **gathers (avx2g, avx2 expand_palette and lit_span)**: llvm-mca's Zen 3 gather model is about 5x too optimistic "
          "against measurement: treat their znver3 figures (marked †) as a lower bound.",
          "- Quake on a Pentium: span drawer 7.5 cycles/pixel, surface builder 2.25 cycles/texel; the last "
          "column divides that by this row's highest estimate (above 1 = beats the Pentium on every modelled core).",
          "- armhf blocks are timed as Thumb-2 with IT instructions dropped (llvm-mca cannot time them) and "
          "register-list push/pop as single loads/stores.",
          "- **surface_span neon, surface_span_persp sse2/neon**: the portable tuned C++ those tables hold "
          "(surface_span_fast, surface_span_persp_fast / surface_spans_persp_fast), not vector code; "
          "surface_span_persp scalar is the reference run walker.",
          "- **lit_span rows**: the single-pass kernel's own variants (asm/lit_span.h): *fast* is tuned scalar C++ "
          "(the tuned choice on armv7 and on x86-64 without AVX2), *neon* NEON lanes with core loads (the tuned "
          "choice on aarch64), *avx2* gathers, *avx2s* AVX2 lanes with scalar loads (the tuned choice with "
          "AVX2). No Pentium figure: Quake had no single-pass lit span drawer.",
          "- **surface_span_persp rows**: drawn as the engine draws a surface's spans, one surface_spans_persp "
          "call (a batch) per repetition: 1 item of 1920 px, 10 of 179-205 px (mean 192), 30 of 50-64 px (mean 57) 32 of 17-48 px (mean 32.5), 32 of 1-16 px (mean 8.5) or 16 of 65-80 px (mean 72.5), mixed lengths so the spans end in different last runs as the engine's do; *one call each* is 30 "
          "surface_span_persp calls per repetition (the per-span entry). Which rows matter for whole frames: bench/span_hist.md (starbow_span_hist). At 320x240 in the LibreQuake flythroughs second-order spans of more than 80 px draw 16-41% of the pixels, linear ones of more than 64 px 18-29%, second-order spans of 17-48 px in pairs 11-21% (persp32), and 880-960 second-order spans of 1-16 px a frame (mean 7 px) 7-9% (persp16); at 640x480 and up the long rows take over. *mixed batch* (persp32mix): 24 items, 818 px, as a surface's batch: linear 40, 56, second-order 100, then second-order 17-48 px spans among 1-16, 49-64 px ones and a linear one (bench/count_kernels.cpp kMixLens), so 17-48 px spans come both after one-run spans and after linear, 49-64 and long ones. llvm-mca gives a call 100 cycles; calls are timed as branches here (since 2026-11-28).", ""]
    header = "| kernel | target | variant | instr/unit | " + " | ".join(
        ["cyc znver3", "cyc skylake", "cyc cortex-a53", "cyc cortex-a72*", "cyc cortex-a9"]) + " | cover | x scalar (cyc) | Pentium Quake ÷ this (worst core) |"
    md += [header, "|" + "---|" * (header.count("|") - 1)]
    allcpus = ["znver3", "skylake", "cortex-a53", "cortex-a72", "cortex-a9"]
    scal = {(t["name"], c): (ipu, cyc) for t, c, v, ipu, cyc, *_ in results if v == "scalar"}
    for t, case, variant, ipu, cyc, cover, gather in sorted(
            results, key=lambda x: (list(KERNEL).index(x[1]), TARGETS.index(x[0]), x[2] != "scalar")):
        s_ipu, s_cyc = scal.get((t["name"], case), (None, {}))
        cells = []
        for c in allcpus:
            if c not in cyc:
                cells.append("")
            else:
                mark = "†" if gather and c == "znver3" and variant in ("avx2g",) or (
                    gather and c == "znver3" and case in ("palette", "palette2", "lit16", "lit16m2") and variant == "avx2") else ""
                cells.append(fmt(cyc[c]) + mark)
        ratio = fmt(s_ipu / ipu) if s_ipu and ipu else "—"
        cr = [s_cyc[c] / cyc[c] for c in cyc if cyc.get(c) and s_cyc.get(c)]
        ratio += f" ({min(cr):.2f}–{max(cr):.2f})" if len(cr) > 1 else (f" ({cr[0]:.2f})" if cr else "")
        quake = 7.5 if case.startswith(("span", "persp")) else 2.25 if case.startswith("block") else None
        worst = max([v for v in cyc.values() if v is not None], default=None)
        vsq = "" if quake is None or worst is None else f"{quake / worst:.2f}"
        md.append(f"| {KERNEL[case]} | {t['name']} | {variant} | {ipu:.2f} | " + " | ".join(cells)
                  + f" | {cover:.0%} | {ratio} | {vsq} |")
    if frame:
        label, rows = frame
        md += ["", f"## Whole frames, x86-64 (callgrind; {label}, 320x240, flythrough 100 minus 50 frames)", "",
               "Both runs fly the same camera path (100 frames sample it twice as densely), so the difference is the "
               "mean cost of a frame along the path. Starbow's headless program presents nothing (no palette "
               "expansion or blit); Chocolate Quake's figure includes 18.7% presentation. "
               "Span kernel: surface_span* and every function compiled from asm/span_persp*.cpp, with the engine's "
               "default second-order steps (Chocolate Quake's span drawer steps linearly).", "",
               "| kernels | instr/pixel/frame | span kernel instr/pixel | instr/frame | Chocolate Quake (320x240) |",
               "|---|---|---|---|---|"]
        for mode, ppf, span, pf in rows:
            md.append(f"| {mode} | {ppf:.1f} | {span:.1f} | {pf / 1e6:.2f} M | 59.1 per pixel, span drawer 19.8 |")
    if arm_frames:
        md += ["", f"## Whole frames, aarch64 and armhf (qemu-user, `insn` plugin; {arm_frames[0][1]}, 320x240, "
               "flythrough 100 minus 50 frames)", "",
               "The same flythroughs as above, cross-built (`starbow`, headless) and run under qemu-user; the plugin "
               "counts the whole process, so there is no span-kernel column. Instruction counts, not cycles, and the "
               "instruction sets differ (x86-64 has memory operands, aarch64 paired loads and shifted operands, "
               "armhf's scalar 64-bit divides are library calls): compare rows of one target.", "",
               "| target | kernels | instr/pixel/frame | instr/frame | tuned ÷ scalar |", "|---|---|---|---|---|"]
        for name, label, rows in arm_frames:
            scalar = dict((m, pf) for m, _, pf in rows).get("scalar")
            for mode, ppf, pf in rows:
                md.append(f"| {name} | {mode} | {ppf:.1f} | {pf / 1e6:.2f} M | "
                          + (f"{pf / scalar:.2f}" if scalar else "—") + " |")
    md += ["", f"Run time: {time.time() - t0:.0f} s."]
    text = "\n".join(md) + "\n"
    if ONLY or VARIANTS:
        merge_rows(os.path.join(ROOT, "bench", "counts.md"), [l for l in md if l.startswith("| ") and "---" not in l
                                                              and not l.startswith("| kernel |")])
    else:
        open(os.path.join(ROOT, "bench", "counts.md"), "w").write(text)
    print(text)


if __name__ == "__main__":
    main()
