#!/usr/bin/env python3
# bench/mca_a53_pair/gen_run2l.py: run 2 and the partial last run (1 .. 15 pixels) of a four-run
# span (asm/span_persp_a64mid.h's runs_k3) as one asm block with virtual core registers,
# allocated here (the register freed longest ago first), in five regions: run 2 with the last
# run's chain set-up, then chunks of 8, 4, 2, 1 pixels, each behind a tbz on the length's bit.
#   gen_run2l.py OUT.s [pre] [w4]   (pre: each region computes the next chunk's first two texel
#   offsets; w4: run 2's pixels in four 32-bit stores, not two 64-bit ones)
# Inputs: run 2 x13 = uv (v 2^32 + u), x9 = duv, x10 = dduv; the last run x23, x24, x25 (the
# same packing); w in w18, texels x26, dest x28, the last run's length in w0. Chains as Run16:
# c0 = uv_k, c1 = uv_{k+1}, stepped by e0 = 2 d + dd, e1 = 2 d + 3 dd, each e by 4 dd a pixel
# pair; the last run's chains go on from chunk to chunk (each chunk even but the last one).
import sys
out = sys.argv[1]
PRE = "pre" in sys.argv[2:]  # each region computes the texel offsets of the next chunk's first pair
W4 = "w4" in sys.argv[2:]  # run 2 stored as four words (else two 64-bit stores)
POOL = [1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 14, 15, 16, 17, 19, 20, 21, 22, 9, 10, 13]
regions = []  # lists of (fmt, writes, reads)


def pixels(pfx, npairs, c0in, upd_last, chains, pre=False):
    """stage lists per pair g: A (shifts and chain steps), B (madd), C (ldrb). chains: names
    (c0, c1, e0, e1, dd4). upd_last: step the chains after the last pair too. pre: pair 0's
    texel offsets are na0, na1 (computed by the region before)."""
    c0, c1, e0, e1, dd4 = chains
    st = []
    for g in range(npairs):
        A = []
        cs = [c0, c1] if npairs > 0 else []
        for i, c in enumerate((c0, c1)):
            k = 2 * g + i
            src = c0in if (g == 0 and i == 0 and c0in) else c
            if pre and g == 0:
                continue
            A.append((f"lsr {{{pfx}h{k}}}, {{{src}}}, #48", [f"{pfx}h{k}"], [src]))
            A.append((f"lsr {{{pfx}l{k}}}:w, {{{src}}}:w, #16", [f"{pfx}l{k}"], [src]))
        for i, (c, e) in enumerate(((c0, e0), (c1, e1))):
            if g < npairs - 1 or upd_last:
                src = c0in if (g == 0 and i == 0 and c0in) else c
                A.append((f"add {{{c}}}, {{{src}}}, {{{e}}}", [c], [src, e]))
        for i, e in enumerate((e0, e1)):
            if g < npairs - 2 or upd_last:
                A.append((f"add {{{e}}}, {{{e}}}, {{{dd4}}}", [e], [e, dd4]))
        B = [(f"madd {{{pfx}a{k}}}:w, {{{pfx}h{k}}}:w, w18, {{{pfx}l{k}}}:w", [f"{pfx}a{k}"], [f"{pfx}h{k}", f"{pfx}l{k}"])
             for k in (2 * g, 2 * g + 1)]
        C = [(f"ldrb {{{pfx}b{k}}}:w, [x26, {{{pfx}a{k}}}:w, uxtw]", [f"{pfx}b{k}"], [f"{pfx}a{k}"]) for k in (2 * g, 2 * g + 1)]
        if pre and g == 0:
            B = []
            C = [(f"ldrb {{{pfx}b{k}}}:w, [x26, {{na{k}}}:w, uxtw]", [f"{pfx}b{k}"], [f"na{k}"]) for k in (0, 1)]
        st.append([A, B, C])
    return st


def gather(pfx, npairs, store, words=False):
    """the orr tree of npairs pairs (1, 2, 4, 8 pairs: 64-bit words of 8, or of 4 if words)
    and its stores."""
    D = {g: [] for g in range(npairs)}
    for g in range(npairs):
        D[g].append((f"orr {{{pfx}p{g}}}, {{{pfx}b{2*g}}}, {{{pfx}b{2*g+1}}}, lsl #8", [f"{pfx}p{g}"], [f"{pfx}b{2*g}", f"{pfx}b{2*g+1}"]))
        if npairs >= 2 and g % 2 == 1:
            D[g].append((f"orr {{{pfx}q{g//2}}}, {{{pfx}p{g-1}}}, {{{pfx}p{g}}}, lsl #16", [f"{pfx}q{g//2}"], [f"{pfx}p{g-1}", f"{pfx}p{g}"]))
        if npairs >= 4 and g % 4 == 3 and not words:
            j = g // 4
            D[g].append((f"orr {{{pfx}r{j}}}, {{{pfx}q{2*j}}}, {{{pfx}q{2*j+1}}}, lsl #32", [f"{pfx}r{j}"], [f"{pfx}q{2*j}", f"{pfx}q{2*j+1}"]))
        D[g] += store(g)
    return D


def pipeline(st, D, npairs):
    ops = []
    for s in range(npairs + 3):
        for stage, g in ((3, s - 3), (2, s - 2), (1, s - 1), (0, s)):
            if 0 <= g < npairs:
                ops += D[g] if stage == 3 else st[g][stage]
    return ops


def nxt(pfx, both):
    """the texel offsets na0, na1 of the last run's next pixel pair (na1 only if both)."""
    o = []
    for i, c in enumerate(("Lx", "L1")[: 2 if both else 1]):
        o += [(f"lsr {{{pfx}h{i}}}, {{{c}}}, #48", [f"{pfx}h{i}"], [c]),
              (f"lsr {{{pfx}l{i}}}:w, {{{c}}}:w, #16", [f"{pfx}l{i}"], [c]),
              (f"madd {{na{i}}}:w, {{{pfx}h{i}}}:w, w18, {{{pfx}l{i}}}:w", [f"na{i}"], [f"{pfx}h{i}", f"{pfx}l{i}"])]
    return o


# region 0: run 2 (8 pairs) and the last run's set-up
r0 = [("add {c1}, {c0in}, {d}", ["c1"], ["c0in", "d"]),
      ("add {e0}, {dd}, {d}, lsl #1", ["e0"], ["dd", "d"]),
      ("add {e1}, {e0}, {dd}, lsl #1", ["e1"], ["e0", "dd"]),
      ("lsl {dd4}, {dd}, #2", ["dd4"], ["dd"])]
st = pixels("", 8, "c0in", False, ("c0", "c1", "e0", "e1", "dd4"))
if W4:  # four 32-bit stores (two orr fewer, two stores more)
    D = gather("", 8, lambda g: [(f"str {{q{g//2}}}:w, [x28, #{32 + 4 * (g // 2)}]", [], [f"q{g//2}"])] if g % 2 == 1 else [], True)
else:
    D = gather("", 8, lambda g: [(f"str {{r{g//4}}}, [x28, #{32 + 8 * (g // 4)}]", [], [f"r{g//4}"])] if g % 4 == 3 else [])
body = pipeline(st, D, 8)
setup = [("add {L1}, {Lx}, {Ld}", ["L1"], ["Lx", "Ld"]),
         ("add {Le0}, {Ldd}, {Ld}, lsl #1", ["Le0"], ["Ldd", "Ld"]),
         ("add {Le1}, {Le0}, {Ldd}, lsl #1", ["Le1"], ["Le0", "Ldd"]),
         ("lsl {Ldd4}, {Ldd}, #2", ["Ldd4"], ["Ldd"]),
         ("add {dp}, x28, #48", ["dp"], [])]
# the set-up spread through run 2's second half (the order search moves it anyway)
r0 += body[:60] + setup + body[60:]
if PRE:  # at the end, where run 2's registers are free again
    r0 += nxt("n0_", True)
r0.append(("tbz w0, #3, 1f", [], []))
regions.append(r0)
LC = ("Lx", "L1", "Le0", "Le1", "Ldd4")
for size, bit, lab in ((8, 2, 1), (4, 1, 2), (2, 0, 3)):
    npairs = size // 2
    pfx = f"k{size}_"
    st = pixels(pfx, npairs, None, True, LC, PRE)
    if size == 8:
        store = lambda g: [(f"str {{k8_r0}}, [{{dp}}], #8", ["dp"], ["k8_r0", "dp"])] if g == 3 else []
    elif size == 4:
        store = lambda g: [(f"str {{k4_q0}}:w, [{{dp}}], #4", ["dp"], ["k4_q0", "dp"])] if g == 1 else []
    else:
        store = lambda g: [(f"strh {{k2_p0}}:w, [{{dp}}], #2", ["dp"], ["k2_p0", "dp"])]
    D = gather(pfx, npairs, store)
    ops = pipeline(st, D, npairs)
    if size == 2:  # only c0 is read after this chunk (chunk 1): no other chain steps
        ops = [o for o in ops if not (o[0].startswith("add {L1}") or o[0].startswith("add {Le"))]
    if PRE:
        ops += nxt(pfx + "n", size > 2)
    regions.append(ops + [(f"{lab}:", [], []), (f"tbz w0, #{bit}, {lab + 1}f", [], [])])
if PRE:
    regions.append([("ldrb {k1b}:w, [x26, {na0}:w, uxtw]", ["k1b"], ["na0"]),
                    ("strb {k1b}:w, [{dp}]", [], ["k1b", "dp"]), ("4:", [], [])])
else:
    regions.append([("lsr {k1h}, {Lx}, #48", ["k1h"], ["Lx"]), ("lsr {k1l}:w, {Lx}:w, #16", ["k1l"], ["Lx"]),
                    ("madd {k1a}:w, {k1h}:w, w18, {k1l}:w", ["k1a"], ["k1h", "k1l"]),
                    ("ldrb {k1b}:w, [x26, {k1a}:w, uxtw]", ["k1b"], ["k1a"]),
                    ("strb {k1b}:w, [{dp}]", [], ["k1b", "dp"]), ("4:", [], [])])
# Layout: region 0 ends in `tbz w0, #3, 1f`; chunk C's code, then its label and the next bit's
# tbz; chunk 1 ends at `4:`.
# allocation over the whole sequence (the last run's state lives across the regions)
ops = [o for r in regions for o in r]
phys = {"c0in": 13, "d": 9, "dd": 10, "Lx": 23, "Ld": 24, "Ldd": 25}
ro = {"c0in", "d", "dd"}  # run 2's inputs: read only (x13, x9, x10 keep their values)
lastuse = {}
for i, (f, w, r) in enumerate(ops):
    for n in r + w:
        lastuse[n] = i
free = [p for p in POOL if p not in phys.values()]
reg = {}
lines = []
for i, (f, w, r) in enumerate(ops):
    for n in r + w:
        if n not in reg:
            reg[n] = phys[n] if n in phys else free.pop(0)
    text = f
    for n in dict.fromkeys(r + w):  # (a fixed order: the allocation is reproducible)
        text = text.replace("{" + n + "}:w", f"w{reg[n]}").replace("{" + n + "}", f"x{reg[n]}")
    lines.append(text)
    for n in dict.fromkeys(r + w):  # (a fixed order: the allocation is reproducible)
        if lastuse[n] == i and n not in ro:
            free.append(reg[n])
open(out, "w").write("\n".join(lines) + "\n")
print(len(lines), "lines; registers", sorted(set(reg.values())), file=sys.stderr)
