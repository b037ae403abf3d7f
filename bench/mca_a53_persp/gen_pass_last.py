#!/usr/bin/env python3
# bench/mca_a53_persp/gen_pass_last.py: the left > 32 tail's runs r, r + 1 and its partial last
# run (1 .. 15 pixels) as one asm block, pass_last (asm/span_persp_a64longlast.h).
#   gen_pass_last.py start OUT.s        region 0 to search: short_pass's searched order
#       (../mca_a53_p64/short_pass2.s: x26 d, x18 tx, w0 w) with the last run's loads, set-up
#       and first texel offsets appended (virtual registers allocated here: each value in the
#       register whose last read in short_pass is earliest, so it can move up that far), and
#       `tbz w27, #3, .+4` (w27 the length); memory operands [sp, #0] the last run's packed
#       start, [sp, #8] / [sp, #12] its u / v steps, [sp, #16] / [sp, #20] its second steps.
#   gen_pass_last.py inline R0.s HEADER  region 0 (as searched) and runs_k3's chunk regions
#       (asm/span_persp_a64mid.h, its lines from `tbz %w[n], #3`: the chunks of 8, 4, 2, 1
#       pixels) with their registers renamed so that its last-run state (x23 uv, x21 uv + d,
#       x22 / x5 the two chains' steps, x8 4 dd, x12 the store pointer, w20 / w17 the next
#       pair's texel offsets) is where region 0 leaves it, written between the header's
#       "// BEGIN pass_last" and "// END pass_last" lines.
# Run from this directory.
import re, sys

sys.path.insert(0, "../")
import order_search as osr  # noqa: E402  (parse: a line's reads and writes)

SP2 = "../mca_a53_p64/short_pass2.s"
MID = "../../asm/span_persp_a64mid.h"
PHYS = [f"x{i}" for i in range(1, 26) if i != 18]  # x18: the tx placeholder


def lines(path):
    return [l.split("//")[0].strip() for l in open(path) if l.split("//")[0].strip()]


# The last run's values after the pass: Lx its packed start (v 2^32 + u), Ld / Ldd its packed
# steps (pack_steps), L1 = Lx + Ld, Le0 = Ldd + 2 Ld, Le1 = Le0 + 2 Ldd, Ldd4 = 4 Ldd, dp = d + 32,
# na0 / na1 the texel offsets of its pixels 0 / 1 (runs_k3's chains and `pre` offsets).
NEW = [("ldr {Lx}, [sp, #0]", ["Lx"], []),
       ("ldrsw {a}, [sp, #8]", ["a"], []), ("ldr {b}:w, [sp, #12]", ["b"], []),
       ("ldrsw {c}, [sp, #16]", ["c"], []), ("ldr {e}:w, [sp, #20]", ["e"], []),
       ("add {Ld}, {a}, {b}, lsl #32", ["Ld"], ["a", "b"]),
       ("add {Ldd}, {c}, {e}, lsl #32", ["Ldd"], ["c", "e"]),
       ("add {L1}, {Lx}, {Ld}", ["L1"], ["Lx", "Ld"]),
       ("add {Le0}, {Ldd}, {Ld}, lsl #1", ["Le0"], ["Ldd", "Ld"]),
       ("add {Le1}, {Le0}, {Ldd}, lsl #1", ["Le1"], ["Le0", "Ldd"]),
       ("lsl {Ldd4}, {Ldd}, #2", ["Ldd4"], ["Ldd"]),
       ("add {dp}, x26, #32", ["dp"], []),
       ("lsr {h0}, {Lx}, #48", ["h0"], ["Lx"]), ("lsr {l0}:w, {Lx}:w, #16", ["l0"], ["Lx"]),
       ("madd {na0}:w, {h0}:w, w0, {l0}:w", ["na0"], ["h0", "l0"]),
       ("lsr {h1}, {L1}, #48", ["h1"], ["L1"]), ("lsr {l1}:w, {L1}:w, #16", ["l1"], ["L1"]),
       ("madd {na1}:w, {h1}:w, w0, {l1}:w", ["na1"], ["h1", "l1"])]
STATE = {"Lx": "x23", "L1": "x21", "Le0": "x22", "Le1": "x5", "Ldd4": "x8", "dp": "x12", "na0": "x20", "na1": "x17"}


def alloc():
    """region 0's text (short_pass's lines, then NEW's) and the virtual -> physical map."""
    sp = lines(SP2)
    last = {r: -1 for r in PHYS}
    for i, l in enumerate(sp):
        rd, wr, _, _ = osr.parse(l)
        for r in rd | wr:
            if r in last:
                last[r] = i
    free = sorted(PHYS, key=lambda r: (last[r], int(r[1:])))  # freed longest ago first
    reg = {}
    body = []
    for f, w, r in NEW:
        for n in w:
            reg[n] = free.pop(0)
        t = f
        for n in reg:
            t = t.replace("{" + n + "}:w", "w" + reg[n][1:]).replace("{" + n + "}", reg[n])
        body.append(t)
    return sp + body, reg


def start(out):
    text, reg = alloc()
    open(out, "w").write("\n".join(text + ["tbz w27, #3, .+4"]) + "\n")
    print("state", {k: reg[k] for k in STATE}, file=sys.stderr)


def chunks():
    h = open(MID).read()
    a = h.index("// BEGIN runs_k3\n")
    b = h.index("// END runs_k3\n")
    body = [re.sub(r'^\s*"|\\n\\t"$|"$', "", l.strip()) for l in h[a:b].splitlines()[1:]]
    k = next(i for i, l in enumerate(body) if l.startswith("tbz %w[n], #3"))
    return body[k + 1:]


def inline(r0, hdr):
    reg = lines(r0)
    assert reg[-1].startswith("tbz w27, #3"), reg[-1]
    reg = reg[:-1]
    phys = alloc()[1]  # the same allocation as start (the search keeps registers)
    # runs_k3's register -> ours: the state first, then the rest in order
    perm = {STATE[n]: phys[n] for n in STATE}
    rest_src = [r for r in PHYS if r not in perm]
    rest_dst = [r for r in PHYS if r not in perm.values()]
    perm.update(zip(rest_src, rest_dst))
    ch = [re.sub(r"\b([xw])(\d+)\b", lambda g: g.group(1) + perm["x" + g.group(2)][1:], l) for l in chunks()]
    mem = {"[sp, #0]": "%[luv]", "[sp, #8]": "%[lu]", "[sp, #12]": "%[lv]", "[sp, #16]": "%[ddu]",
           "[sp, #20]": "%[ddv]"}

    def op(l):
        for k, v in mem.items():
            l = l.replace(k, v)
        l = re.sub(r"\bx26\b", "%[d]", l)
        l = re.sub(r"\bx18\b", "%[tx]", l)
        return re.sub(r"\bw0\b", "%w[w]", l)

    body = [op(l) for l in reg] + ["tbz %w[n], #3, 1f"] + ch
    text = "".join(f'      "{l}\\n\\t"\n' if not l.endswith(":") else f'      "{l}\\n\\t"\n' for l in body[:-1])
    text += f'      "{body[-1]}"\n'
    h = open(hdr).read()
    a = h.index("      // BEGIN pass_last\n") + len("      // BEGIN pass_last\n")
    b = h.index("      // END pass_last\n")
    open(hdr, "w").write(h[:a] + text + h[b:])
    print("state", phys, file=sys.stderr)


if __name__ == "__main__":
    if sys.argv[1] == "start":
        start(sys.argv[2])
    else:
        inline(sys.argv[2], sys.argv[3])
