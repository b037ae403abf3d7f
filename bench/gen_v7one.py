#!/usr/bin/env python3
# bench/gen_v7one.py: generates the ARMv7 pair set-up of one-run second-order spans (the asm
# statement in asm/span_persp_v7one.h, between its "generated" markers): spans a and b, each
# from its PerspItem to its u0, v0, steps and second-order steps stored to memory, all in
# VFP / NEON registers. Each span's instruction list (SPAN below) is fixed; the two lists are
# merged by a greedy in-order list scheduler with the Cortex-A9 model's latencies (the
# instruction whose operands are ready first; ties to the span behind), then registers are
# allocated (linear scan over the merged order: vld1 lists in consecutive registers, q
# operands in aligned pairs, s-register operands in d0 .. d15).
#
#   python3 bench/gen_v7one.py            rewrites the block in asm/span_persp_v7one.h
#   python3 bench/gen_v7one.py --mca F.s  also writes the block as llvm-mca input (no IT)
import re, sys

# Per span, {X} a virtual register (d unless noted), {X.s0}/{X.s1} its singles, {X.q} a q
# register (X, X+1), core operands %[name] (the asm statement's). Each op: text, defs, uses.
# `acc` ops read their destination. Lat: result latency (A9 model), fp: FP-pipe slots.
LAT = {"vadd.f64": 4, "vfma.f64": 9, "vfms.f64": 9, "vmul.f64": 6, "vdiv.f64": 25, "vcmpe.f64": 1, "vmrs": 1,
       "vmovle.f64": 1, "vcvt.u32.f64": 4, "vcvt.f64.s32": 4, "vcvt.s32.f64": 4, "vsli.64": 3, "vmin.u32": 4,
       "vsub.i32": 3, "vabs.s32": 4, "vcgt.u32": 4, "vmull.u32": 7, "vmovl.u32": 4, "vqsub.u64": 4,
       "vqmovn.u64": 4, "vtst.32": 4, "vbic": 3, "vand": 3, "vbsl": 3, "vld1.64": 1, "vst1.32": 1, "ldr": 3, "add": 1,
       "sub": 1}
FP_FREE = ("vld1.64", "vst1.32", "ldr", "add", "sub")


def span(x):
    """The ops of span x ('a' or 'b'): %[ix] its item pointer (then the field pointer), %[rx] its
    row pointer, %[ox] its output pointer; KMIN, ONE, HALF, M2, BIG shared constants."""
    I, R, O = f"%[i{x}]", f"%[r{x}]", f"%[o{x}]"
    ops = [
        # n, the row (kOneRows[n]: n - 1, max(n - 1, 1), (max(n - 1, 1) - 1) / 2, [T, T]), the fields.
        (f"ldr {R}, [{I}, #4]", [R], [I]),
        (f"add {I}, {I}, #8", [I], [I]),
        (f"add {R}, %[kr], {R}, lsl #5", [R], [R, "%[kr]"]),
        (f"vld1.64 {{{{{{Z1}}}}}}, [{I}]", ["Z1"], [I, "M:item"]),  # zi0 (sample 1's accumulator)
        (f"vld1.64 {{{{{{Z0}}, {{ZX}}, {{U0}}, {{UX}}}}}}, [{I}]!", ["Z0", "ZX", "U0", "UX", I], [I, "M:item"]),
        (f"vld1.64 {{{{{{V1}}}}}}, [{I}]", ["V1"], [I, "M:item"]),  # vz0
        (f"vld1.64 {{{{{{V0}}, {{VX}}, {{P}}, {{UV}}}}}}, [{I}]", ["V0", "VX", "P", "UV"], [I, "M:item"]),
        (f"sub {I}, {I}, #16", [I], [I]),
        (f"vld1.64 {{{{{{U1}}}}}}, [{I}]", ["U1"], [I, "M:item"]),  # uz0
        (f"vld1.64 {{{{{{F}}, {{S}}}}}}, [{R}]!", ["F", "S", R], [R, "M:tab"]),
        # Positions P, P + (n - 1); depths max(zrow + zix x, kMinZi) (fused; NaN -> kMinZi), 1 / zi.
        ("vadd.f64 {P1}, {P}, {F}", ["P1"], ["P", "F"]),
        ("vfma.f64 {Z0}, {ZX}, {P}", ["Z0"], ["Z0", "ZX", "P"]),
        ("vfma.f64 {Z1}, {ZX}, {P1}", ["Z1"], ["Z1", "ZX", "P1"]),
        ("vcmpe.f64 {Z0}, {KMIN}", ["FLAGS"], ["Z0", "KMIN"]),
        ("vmrs APSR_nzcv, fpscr", ["APSR"], ["FLAGS"]),
        ("vmovle.f64 {Z0}, {KMIN}", ["Z0"], ["Z0", "KMIN", "APSR"]),
        ("vcmpe.f64 {Z1}, {KMIN}", ["FLAGS"], ["Z1", "KMIN"]),
        ("vmrs APSR_nzcv, fpscr", ["APSR"], ["FLAGS"]),
        ("vmovle.f64 {Z1}, {KMIN}", ["Z1"], ["Z1", "KMIN", "APSR"]),
        ("vdiv.f64 {Z0}, {ONE}, {Z0}", ["Z0"], ["ONE", "Z0"]),
        ("vdiv.f64 {Z1}, {ONE}, {Z1}", ["Z1"], ["ONE", "Z1"]),
        # (urow + ux x), (vrow + vx x) (fused), zix / 2.
        ("vfma.f64 {U0}, {UX}, {P}", ["U0"], ["U0", "UX", "P"]),
        ("vfma.f64 {V0}, {VX}, {P}", ["V0"], ["V0", "VX", "P"]),
        ("vfma.f64 {U1}, {UX}, {P1}", ["U1"], ["U1", "UX", "P1"]),
        ("vfma.f64 {V1}, {VX}, {P1}", ["V1"], ["V1", "VX", "P1"]),
        ("vmul.f64 {ZX}, {ZX}, {HALF}", ["ZX"], ["ZX", "HALF"]),
        # Samples: times z, to 16.16 (usat32(trunc)), [u, v] paired, min [umax, vmax].
        ("vmul.f64 {U0}, {U0}, {Z0}", ["U0"], ["U0", "Z0"]),
        ("vmul.f64 {V0}, {V0}, {Z0}", ["V0"], ["V0", "Z0"]),
        ("vmul.f64 {U1}, {U1}, {Z1}", ["U1"], ["U1", "Z1"]),
        ("vmul.f64 {V1}, {V1}, {Z1}", ["V1"], ["V1", "Z1"]),
        ("vadd.f64 {Z0}, {Z0}, {Z1}", ["Z0"], ["Z0", "Z1"]),
        ("vmul.f64 {ZX}, {ZX}, {Z0}", ["ZX"], ["ZX", "Z0"]),  # curve = (zix * 0.5) (z0 + z1)
        ("vmul.f64 {ZX}, {ZX}, {M2}", ["ZX"], ["ZX", "M2"]),  # c2 = -2 curve (exact)
        ("vcvt.u32.f64 {U0}, {U0}, #16", ["U0"], ["U0"]),
        ("vcvt.u32.f64 {V0}, {V0}, #16", ["V0"], ["V0"]),
        ("vcvt.u32.f64 {U1}, {U1}, #16", ["U1"], ["U1"]),
        ("vcvt.u32.f64 {V1}, {V1}, #16", ["V1"], ["V1"]),
        ("vsli.64 {U0}, {V0}, #32", ["U0"], ["U0", "V0"]),
        ("vsli.64 {U1}, {V1}, #32", ["U1"], ["U1", "V1"]),
        ("vmin.u32 {U0}, {U0}, {UV}", ["U0"], ["U0", "UV"]),
        ("vmin.u32 {U1}, {U1}, {UV}", ["U1"], ["U1", "UV"]),
        ("vsub.i32 {D}, {U1}, {U0}", ["D"], ["U1", "U0"]),  # [du, dv] (exact: both in [0, 2^31))
        (f"vst1.32 {{{{{{U0}}}}}}, [{O}]!", ["M:out" + x, O], ["U0", O, "M:out" + x]),  # u0, v0
        # Quotients double(delta) / max(n - 1, 1); ddf = -2 (q curve), to int32 (trunc, saturating).
        ("vcvt.f64.s32 {FU}, {D.s0}", ["FU"], ["D"]),
        ("vcvt.f64.s32 {FV}, {D.s1}", ["FV"], ["D"]),
        ("vdiv.f64 {FU}, {FU}, {S}", ["FU"], ["FU", "S"]),
        ("vdiv.f64 {FV}, {FV}, {S}", ["FV"], ["FV", "S"]),
        (f"vld1.64 {{{{{{KK}}, {{TT}}}}}}, [{R}]", ["KK", "TT"], [R, "M:tab"]),
        ("vabs.s32 {PD}, {D}", ["PD"], ["D"]),
        ("vmovl.u32 {QPD.q}, {PD}", ["QPD"], ["PD"]),
        # ddf = q c2 (-2 (q curve): the same int32 after vcvt, see the header), dd = its trunc
        # (saturating); lin = trunc(q).
        ("vmul.f64 {TU}, {FU}, {ZX}", ["TU"], ["FU", "ZX"]),
        ("vmul.f64 {TV}, {FV}, {ZX}", ["TV"], ["FV", "ZX"]),
        ("vcvt.s32.f64 {L.s0}, {FU}", ["L"], ["FU"]),
        ("vcvt.s32.f64 {L.s1}, {FV}", ["L"], ["FV", "L"]),
        ("vcvt.s32.f64 {DD.s0}, {TU}", ["DD"], ["TU"]),
        ("vcvt.s32.f64 {DD.s1}, {TV}", ["DD"], ["TV", "DD"]),
        # d = trunc(q - dd k) (k = (s - 1) / 2; dd k exact), used where dd is accepted; beside
        # it the test: |dd| < 1e9 and T |dd| <= |delta| (64-bit), the walker's range and
        # acceptance (last_ddi, last_dd); then dd' = accepted ? dd : 0, d = accepted ? d : lin.
        ("vcvt.f64.s32 {GU}, {DD.s0}", ["GU"], ["DD"]),
        ("vcvt.f64.s32 {GV}, {DD.s1}", ["GV"], ["DD"]),
        ("vabs.s32 {A}, {DD}", ["A"], ["DD"]),
        ("vfms.f64 {FU}, {GU}, {KK}", ["FU"], ["FU", "GU", "KK"]),
        ("vfms.f64 {FV}, {GV}, {KK}", ["FV"], ["FV", "GV", "KK"]),
        ("vmull.u32 {QP.q}, {A}, {TT}", ["QP"], ["A", "TT"]),
        ("vcgt.u32 {M}, {BIG}, {A}", ["M"], ["BIG", "A"]),
        ("vqsub.u64 {QP.q}, {QP.q}, {QPD.q}", ["QP"], ["QP", "QPD"]),
        ("vcvt.s32.f64 {R.s0}, {FU}", ["R"], ["FU"]),
        ("vcvt.s32.f64 {R.s1}, {FV}", ["R"], ["FV", "R"]),
        ("vqmovn.u64 {X}, {QP.q}", ["X"], ["QP"]),
        ("vtst.32 {X}, {X}, {X}", ["X"], ["X"]),
        ("vbic {M}, {M}, {X}", ["M"], ["M", "X"]),
        ("vand {DD}, {DD}, {M}", ["DD"], ["DD", "M"]),
        ("vbsl {M}, {R}, {L}", ["M"], ["M", "R", "L"]),
        (f"vst1.32 {{{{{{DD}}}}}}, [{O}]!", ["M:out" + x, O], ["DD", O, "M:out" + x]),  # ddu, ddv
        (f"vst1.32 {{{{{{M}}}}}}, [{O}]", ["M:out" + x], ["M", O, "M:out" + x]),  # du, dv
    ]
    return ops


SHARED = ["KMIN", "ONE", "HALF", "M2", "BIG", "FLAGS", "APSR", "%[kr]", "M:tab"]
LOW = {"D", "DD", "R", "L"}  # s-register operands: d0 .. d15
QREG = {"QP", "QPD"}


def tag(ops, x):
    """Virtual register names made per span (X -> X_a), core and memory names kept."""
    out = []
    for text, defs, uses in ops:
        f = lambda r: r if (r in SHARED or r.startswith("%") or r.startswith("M:")) else f"{r}_{x}"
        t = re.sub(r"\{([A-Z0-9]+)((?:\.s0|\.s1|\.q)?)\}", lambda m: "{" + f(m.group(1)) + m.group(2) + "}", text)
        out.append((t, [f(r) for r in defs], [f(r) for r in uses], x))
    return out


def opname(text):
    return text.split()[0]


def merge(a, b):
    """Greedy in-order merge: each span's ops in order; at each step the op (of the two heads)
    whose operands are ready first issues (FP-pipe ops one a cycle); ties: the span behind."""
    ready = {}  # register -> cycle its value is ready
    fp_free = 0
    out, ia, ib = [], 0, 0
    cyc = 0
    flags_owner = None
    while ia < len(a) or ib < len(b):
        cands = []
        for which, lst, i in (("a", a, ia), ("b", b, ib)):
            if i >= len(lst):
                continue
            text, defs, uses, x = lst[i]
            # the flags are shared: a span's vcmpe .. vmovle group may not interleave with the other's
            if ("FLAGS" in defs or "APSR" in defs or "APSR" in uses) and flags_owner not in (None, x):
                continue
            t = max([ready.get(u, 0) for u in uses] + [cyc])
            if opname(text) not in FP_FREE:
                t = max(t, fp_free)
            cands.append((t, i, which))
        t, i, which = min(cands)
        lst = a if which == "a" else b
        text, defs, uses, x = lst[i]
        if opname(text) == "vcmpe.f64":
            flags_owner = x
        if opname(text) == "vmovle.f64":
            flags_owner = None
        lat = LAT.get(opname(text), 4)
        for d in defs:
            ready[d] = t + lat
        if opname(text) not in FP_FREE:
            fp_free = t + (2 if opname(text) == "vmull.u32" else 1)
        cyc = t
        out.append(lst[i])
        if which == "a":
            ia += 1
        else:
            ib += 1
    return out


def allocate(ops, fixed):
    """Physical d registers for the virtual ones (fixed: the shared constants' registers)."""
    last_use = {}
    for k, (text, defs, uses, x) in enumerate(ops):
        for u in uses:
            last_use[u] = k
    # a value defined and never read (none here) is freed at once
    phys = dict(fixed)
    busy = {p: "const" for p in fixed.values()}
    for p in list(fixed.values()):
        pass

    def vregs_of(text):
        return re.findall(r"\{([A-Za-z0-9_]+)((?:\.s0|\.s1|\.q)?)\}", text)

    for k, (text, defs, uses, x) in enumerate(ops):
        # free the registers whose values were last read before this op
        here = [r for r, _ in vregs_of(text)]
        for p, v in list(busy.items()):
            if v == "const" or v in here:
                continue
            if last_use.get(v, -1) < k:
                del busy[p]
        names = [r for r, _ in vregs_of(text)]
        new = [v for v in names if v not in phys and v in defs]
        if not new:
            continue
        base = lambda v: v.rsplit("_", 1)[0]
        if len(new) > 1:  # a vld1 list: consecutive registers, in order
            n = len(new)
            for s in range(0, 33 - n):
                if all(s + j not in busy for j in range(n)):
                    break
            else:
                raise SystemExit(f"no {n} consecutive registers at op {k}: {text}")
            for j, v in enumerate(new):
                phys[v] = s + j
                busy[s + j] = v
            continue
        v = new[0]
        if base(v) in QREG:
            for s in range(16, 31, 2):
                if s not in busy and s + 1 not in busy:
                    break
            else:
                for s in range(0, 15, 2):
                    if s not in busy and s + 1 not in busy:
                        break
                else:
                    raise SystemExit(f"no q register at op {k}: {text}")
            phys[v] = s
            busy[s] = v
            busy[s + 1] = v
            continue
        rng = range(0, 16) if base(v) in LOW else list(range(16, 32)) + list(range(0, 16))
        for s in rng:
            if s not in busy:
                break
        else:
            raise SystemExit(f"no register for {v} at op {k}: {text}")
        phys[v] = s
        busy[s] = v
    # release of q registers: busy entries for the pair's second half were keyed by v too
    return phys


def render(ops, phys):
    lines = []
    for text, defs, uses, x in ops:
        def sub(m):
            v, suf = m.group(1), m.group(2)
            p = phys[v]
            if suf == ".s0":
                return f"s{2 * p}"
            if suf == ".s1":
                return f"s{2 * p + 1}"
            if suf == ".q":
                assert p % 2 == 0
                return f"q{p // 2}"
            return f"d{p}"
        t = re.sub(r"\{([A-Za-z0-9_]+)((?:\.s0|\.s1|\.q)?)\}", sub, text)
        t = t.replace("{{", "{").replace("}}", "}")
        lines.append(t)
    return lines


def main():
    a, b = tag(span("a"), "a"), tag(span("b"), "b")
    head = [("vld1.64 {{{KMIN}, {ONE}, {HALF}, {M2}}}, [%[kc]]!", [], ["%[kc]"], "-"),
            ("vld1.64 {{{BIG}}}, [%[kc]]", [], ["%[kc]"], "-")]
    ops = head + merge(a, b)
    fixed = {"KMIN": 0, "ONE": 1, "HALF": 2, "M2": 3, "BIG": 4}
    phys = allocate(ops, fixed)
    lines = render(ops, phys)
    used = sorted(set(int(m) for l in lines for m in re.findall(r"\bd(\d+)\b", l)) |
                  set(int(m) // 2 for l in lines for m in re.findall(r"\bs(\d+)\b", l)) |
                  set(2 * int(m) + j for l in lines for m in re.findall(r"\bq(\d+)\b", l) for j in (0, 1)))
    if "--mca" in sys.argv:
        f = sys.argv[sys.argv.index("--mca") + 1]
        core = {"%[ia]": "r0", "%[ib]": "r1", "%[ra]": "r2", "%[rb]": "r3", "%[oa]": "r4", "%[ob]": "r5",
                "%[kc]": "r6", "%[kr]": "r7"}
        with open(f, "w") as fh:
            for l in lines:
                for k, v in core.items():
                    l = l.replace(k, v)
                if l.startswith("vmovle"):
                    l = l.replace("vmovle", "vmov") + " @flags"
                fh.write(l + "\n")
    body = []
    for l in lines:
        if l.startswith("vmovle"):
            body.append('"it le\\n\\t"')
        body.append(f'"{l}\\n\\t"')
    body[-1] = body[-1].replace("\\n\\t", "")
    clob = ", ".join(f'"d{r}"' for r in used)
    text = ("    // Generated by bench/gen_v7one.py (do not edit by hand).\n"
            + "".join(f"    {l}\n" for l in body)
            + f"    // clobbers: {clob}\n")
    path = "asm/span_persp_v7one.h"
    src = open(path).read()
    s0 = src.index("    // Generated by bench/gen_v7one.py")
    s1 = src.index("    // clobbers:", s0)
    s1 = src.index("\n", s1) + 1
    src = src[:s0] + text + src[s1:]
    src = re.sub(r"#define SB_V7_ONE_CLOBBERS .*", f"#define SB_V7_ONE_CLOBBERS {clob}", src)
    open(path, "w").write(src)
    print(f"{len(lines)} instructions, d registers used: {used}", file=sys.stderr)


if __name__ == "__main__":
    main()
