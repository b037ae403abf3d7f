#!/usr/bin/env python3
# bench/gen_v7five.py: generates the ARMv7 asm statement of asm/span_persp_v7five.h's
# five_tail_v7 (between its "Generated" marker and its clobbers line): run 3 of a five-run
# second-order span (65 .. 80 px, persp_five_run_v7) drawn as persp_mid_v7's runs draw theirs
# (16 pixels in eight groups of two, asm/span_persp_v7mid.h's SB_V7_RUN), with the rest of the
# last run's set-up between the groups (after five_head_v7's part): the one-run path's chain
# (bench/gen_v7one.py's span(), the same operations from the deltas on) for samples 4 and 5.
#
#   python3 bench/gen_v7five.py [--mca F.s] [--no-order]
#
# The set-up's ops are list-scheduled (gen_v7one.schedule with the Cortex-A9 model's
# latencies; the loads first: their pointer, %[b], is the pixels' scratch from the first
# group's second pixel on), registers allocated (gen_v7one.allocate; five_head_v7's outputs
# and sample 4 pinned), then each op placed after the pixel group whose end (about 8 cycles
# a group) comes first at or after its scheduled start less HEAD cycles, the first ones
# after the first pixel's first line. The statement's order is then
# bench/mca_a9_five/tail_order.s when that file holds the same lines (--mca writes them in
# llvm-mca form, %[u] .. %[d] as r0 .. r10; bench/order_search.py --arch=armv7 reorders them).
import os, re, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_v7one as g  # noqa: E402


def setup():
    """The last run's set-up after five_head_v7 (asm/span_persp_v7five.h): Z4, Z5 (the depths,
    divides issued there), U5, V5 (urow + ux X5, vrow + vx X5), ZX (zix / 2), UV ([umax, vmax])
    and S4 (sample 4's [u, v]) in fixed registers (PIN); %[b] the row's tail (kFiveRows[m].s).
    Outputs: DD = [ddu, ddv], M = [du, dv] (the one-run path's)."""
    B = "%[b]"
    ops = [
        (f"vld1.64 {{{{{{S}}, {{KK}}, {{TT}}, {{M2}}}}}}, [{B}]!", ["S", "KK", "TT", "M2", B], [B, "M:tab"]),
        (f"vld1.64 {{{{{{BIG}}}}}}, [{B}]", ["BIG"], [B, "M:tab"]),
        # Sample 5: times z5, to 16.16, [u, v], min [umax, vmax]; curve, c2.
        ("vmul.f64 {U5}, {U5}, {Z5}", ["U5"], ["U5", "Z5"]),
        ("vmul.f64 {V5}, {V5}, {Z5}", ["V5"], ["V5", "Z5"]),
        ("vadd.f64 {Z4}, {Z4}, {Z5}", ["Z4"], ["Z4", "Z5"]),
        ("vmul.f64 {ZX}, {ZX}, {Z4}", ["ZX"], ["ZX", "Z4"]),  # curve = (zix * 0.5) (z4 + z5)
        ("vmul.f64 {ZX}, {ZX}, {M2}", ["ZX"], ["ZX", "M2"]),  # c2 = -2 curve (exact)
        ("vcvt.u32.f64 {U5}, {U5}, #16", ["U5"], ["U5"]),
        ("vcvt.u32.f64 {V5}, {V5}, #16", ["V5"], ["V5"]),
        ("vsli.64 {U5}, {V5}, #32", ["U5"], ["U5", "V5"]),
        ("vmin.u32 {U5}, {U5}, {UV}", ["U5"], ["U5", "UV"]),
        ("vsub.i32 {D}, {U5}, {S4}", ["D"], ["U5", "S4"]),  # [du, dv] (exact: both in [0, 2^31))
    ]
    # From the deltas on: the one-run path's operations (its quotients, ddf, the tests), less
    # its row load (KK, TT loaded above) and its stores.
    one = g.span("a")
    k0 = next(i for i, o in enumerate(one) if o[0].startswith("vcvt.f64.s32 {FU}"))
    for text, defs, uses in one[k0:]:
        if text.startswith("vld1.64") or text.startswith("vst1.32"):
            continue
        ops.append((text, defs, uses))
    return [(t, d, u, "a") for t, d, u in ops]


def pixel(t, step=2):
    """One pixel of SB_V7_PX (step 2: all four adds; 1: u and v only; 0: none)."""
    out = [f"smulbt {t}, %[w], %[v]", f"uxtah {t}, {t}, %[u], ror #16"]
    if step >= 1:
        out += ["add %[u], %[u], %[du]", "add %[v], %[v], %[dv]"]
    if step >= 2:
        out += ["add %[du], %[du], %[ddu]", "add %[dv], %[dv], %[ddv]"]
    return out + [f"ldrb {t}, [%[tx], {t}]"]


def groups():
    """The run's eight two-pixel groups (asm/span_persp_v7mid.h's SB_V7_RUN, without F0 .. F7)."""
    gs = []
    for k in range(4):
        gs.append(pixel("%[a]") + pixel("%[b]") + ["orr %[a], %[a], %[b], lsl #8"])
        last = k == 3
        gs.append(pixel("%[b]", 1 if last else 2) + ["orr %[a], %[a], %[b], lsl #16"] +
                  pixel("%[b]", 0 if last else 2) + ["orr %[a], %[a], %[b], lsl #24", f"str %[a], [%[d], #{4 * k}]"])
    return gs


def starts(ops):
    """Start cycles of ops in their scheduled order (in-order issue, two a cycle, one FP op a cycle)."""
    ready, fp_free, cyc, out, issued = {}, 0, 0, [], 0
    for text, defs, uses, x in ops:
        t = max([ready.get(u, 0) for u in uses] + [cyc])
        fp = g.opname(text) not in g.FP_FREE
        if fp:
            t = max(t, fp_free)
        if t == cyc:
            issued += 1
            if issued > 2:
                t, issued = t + 1, 1
        else:
            issued = 1
        for d in defs:
            ready[d] = t + g.LAT.get(g.opname(text), 4)
        if fp:
            fp_free = t + (2 if g.opname(text) == "vmull.u32" else 1)
        cyc = t
        out.append(t)
    return out


PIN = {"S4": 4, "V5": 8, "Z5": 10, "UV": 11, "Z4": 12, "ZX": 13, "U5": 14}  # five_head_v7's outputs, s4
GROUP = 8  # cycles a two-pixel group takes (about 16 instructions, two a cycle)
HEAD = 16  # the ops started in the first HEAD cycles go before group 0


def main():
    arg = lambda k: sys.argv[sys.argv.index(k) + 1] if k in sys.argv else None
    g.SLACK = 1000  # the loads first (their pointer is the pixels scratch after group 0)
    ops = g.schedule(setup())
    st = starts(ops)
    phys = g.allocate(ops, PIN)
    lines = g.render(ops, phys)
    slots = [[] for _ in range(9)]  # 0: before group 0; k: after group k - 1
    for l, t in zip(lines, st):
        k = 0 if l.startswith(("vld1", "vldr")) else min(8, max(0, (t + GROUP - 1 - HEAD) // GROUP))
        slots[k].append(l)
    gs = groups()
    # The first pixel's first line writes %[a] (unused before); its second group's, %[b] (the
    # loads' pointer): the set-up's first lines between.
    body = gs[0][:1] + slots[0] + gs[0][1:] + slots[1]
    for k in range(1, 8):
        body += gs[k] + slots[k + 1]
    # The last run's values to core registers (the run's own are dead by then).
    body += [f"vmov %[a], %[b], d{phys['DD']}", f"vmov %[du], %[dv], d{phys['M']}", "vmov %[u], %[v], d4"]
    order = os.path.join(os.path.dirname(os.path.abspath(__file__)), "mca_a9_five", "tail_order.s")
    if "--no-order" not in sys.argv and os.path.exists(order):
        body = reorder(body, order)
    used = sorted(set(int(m) for l in body for m in re.findall(r"\bd(\d+)\b", l)) |
                  set(int(m) // 2 for l in body for m in re.findall(r"\bs(\d+)\b", l)) |
                  set(2 * int(m) + j for l in body for m in re.findall(r"\bq(\d+)\b", l) for j in (0, 1)))
    used = [r for r in used if r not in PIN.values()]
    if arg("--mca"):
        with open(arg("--mca"), "w") as fh:
            for l in body:
                fh.write(to_mca(l) + "\n")
    text = []
    for l in body:
        if l.startswith("vmovle"):
            text.append('"it le\\n\\t"')
        text.append(f'"{l}\\n\\t"')
    text[-1] = text[-1].replace("\\n\\t", "")
    clob = ", ".join(f'"d{r}"' for r in used)
    marker = "// Generated by bench/gen_v7five.py"
    block = f"    {marker} (do not edit by hand).\n" + "".join(f"    {l}\n" for l in text) + f"    // clobbers: {clob}\n"
    path = "asm/span_persp_v7five.h"
    src = open(path).read()
    s0 = src.index(f"    {marker}")
    s1 = src.index("\n", src.index("    // clobbers:", s0)) + 1
    src = src[:s0] + block + src[s1:]
    src = re.sub(r"#define SB_V7_FIVE_CLOBBERS .*", f"#define SB_V7_FIVE_CLOBBERS {clob}", src)
    open(path, "w").write(src)
    print(f"{len(body)} lines, d registers: {used}", file=sys.stderr)


CORE = {"%[u]": "r0", "%[v]": "r1", "%[du]": "r2", "%[dv]": "r3", "%[a]": "r4", "%[b]": "r5", "%[ddu]": "r6",
        "%[ddv]": "r7", "%[w]": "r8", "%[tx]": "r9", "%[d]": "r10"}


def to_mca(l):
    for k, v in CORE.items():
        l = l.replace(k, v)
    if l.startswith("vmovle"):
        l = l.replace("vmovle", "vmov") + " @flags"
    return l


def reorder(body, path):
    """body in the order of `path` (an llvm-mca-form file as --mca writes it, reordered)."""
    back = {v: k for k, v in CORE.items()}
    out = []
    for l in open(path):
        flags = "@flags" in l
        l = l.split("@")[0].strip()
        if not l or l.startswith("."):
            continue
        l = re.sub(r"\br(\d+)\b", lambda m: back.get(m.group(0), m.group(0)), l)
        if flags:
            l = l.replace("vmov.f64", "vmovle.f64", 1)
        out.append(l)
    if sorted(out) != sorted(body):
        raise SystemExit(f"{path}: not the generated statement's lines (regenerate it with --no-order)")
    return out


if __name__ == "__main__":
    main()
