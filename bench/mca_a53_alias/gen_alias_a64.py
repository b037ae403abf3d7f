#!/usr/bin/env python3
# bench/mca_a53_alias/gen_alias_a64.py: writes asm/alias_span_a64.h's loop from the searched
# full body (full_out.s: one iteration drawing group i and preparing group i + 1, found by
# bench/order_search.py from full_in.s). The first group's preparation (its state stepped by
# r pixels, not 8), the prepare-only body (groups whose pixels are all hidden) and the
# draw-only tail (the last group) are the same lines split by the section they came from in
# full_in.s, in the searched order.
#   gen_alias_a64.py > ../../asm/alias_span_a64.h  (run from this directory)
import re, sys

OPS = {"18": "r", "28": "a", "30": "w", "19": "pz", "20": "db", "21": "zb", "22": "rb", "23": "skin", "24": "cm", "25": "cnt", "26": "m", "27": "wb"}


def lines(path):
    return [l.split("//")[0].strip() for l in open(path) if l.split("//")[0].strip()]


def section_of(path):
    sec, out = None, {}
    for raw in open(path):
        if raw.startswith("// B:"):
            sec = "B"
        elif raw.startswith("// A:"):
            sec = "A"
        l = raw.split("//")[0].strip()
        if l:
            out[l] = sec
    return out


def op(l):
    pat = re.compile(r"\b([xw])(" + "|".join(OPS) + r")\b")
    return pat.sub(lambda m: "%" + ("w" if m.group(1) == "w" else "") + "[" + OPS[m.group(2)] + "]", l)


# The lane state (S, T, L, Z in v0..v7: lanes 0..3, 4..7) from the span's fields (x28: its
# address), the steps (v24..v27, one pixel's until group 0 is prepared, then 8 pixels'), the
# skin width in each 16-bit lane (v28, from x30) and r (v30, x18).
SETUP = ["ldp w0, w1, [x28]", "ldp w4, w5, [x28, #16]", "ldp w2, w3, [x28, #8]", "ldp w6, w7, [x28, #24]",
         "dup v0.4s, w0", "dup v24.4s, w4", "dup v2.4s, w1", "dup v25.4s, w5", "dup v4.4s, w2",
         "dup v26.4s, w6", "dup v6.4s, w3", "dup v27.4s, w7", "mla v0.4s, v24.4s, v29.4s",
         "mla v2.4s, v25.4s, v29.4s", "mla v4.4s, v26.4s, v29.4s", "mla v6.4s, v27.4s, v29.4s",
         "shl v16.4s, v24.4s, #2", "shl v17.4s, v25.4s, #2", "shl v18.4s, v26.4s, #2", "shl v19.4s, v27.4s, #2",
         "add v1.4s, v0.4s, v16.4s", "add v3.4s, v2.4s, v17.4s", "add v5.4s, v4.4s, v18.4s",
         "add v7.4s, v6.4s, v19.4s", "dup v28.4h, w30", "dup v30.4s, w18"]


def searched(path, derived):
    try:
        got = lines(path)
    except FileNotFoundError:
        return derived
    if sorted(got) != sorted(derived):
        sys.exit(f"{path}: not an order of the derived lines (regenerate it from {path.replace('out', 'in')})")
    return got


def main():
    body = lines("full_out.s")
    sec = section_of("full_in.s")
    ctl = {"subs x25, x25, #1", "b.ne .+4"}
    a = [l for l in body if l not in ctl and sec[l] == "A"]
    b = [l for l in body if l not in ctl and sec[l] == "B"]
    full = [l for l in body if l != "b.ne .+4"]
    # group 0, prepared in the set-up: its state steps by r (1 .. 8, the pixels to group 1)
    first = []
    for l in a:
        m = re.fullmatch(r"add (v\d+)\.4s, \1\.4s, (v2[4-7])\.4s", l)
        if m:
            first.append(f"mla {m.group(1)}.4s, {m.group(2)}.4s, v30.4s")
        elif l == "str q16, [x21], #16":
            first += ["str q16, [x21]", "add x21, x21, x18, lsl #1"]
        else:
            first.append(l)
    # prepare only: group i has nothing to draw; the read buffer moves on
    aonly = a + ["eor x22, x22, #0x40", "subs x25, x25, #1"]
    bonly = [l for l in b if l != "eor x22, x22, #0x40"]
    setup = SETUP + first + ["shl v24.4s, v24.4s, #3", "shl v25.4s, v25.4s, #3", "shl v26.4s, v26.4s, #3",
                             "shl v27.4s, v27.4s, #3"]
    # the set-up and the draw-only tail as derived here (searched orders: setup_out.s, bonly_out.s)
    open("setup_in.s", "w").write("\n".join(setup) + "\n")
    open("bonly_in.s", "w").write("\n".join(bonly) + "\n")
    setup = searched("setup_out.s", setup)
    bonly = searched("bonly_out.s", bonly)
    asm = setup + ["cbz x25, 4f", "1:", "cbz x26, 3f"] + full + ["b.ne 1b", "b 4f", "3:"] + aonly + [
          "b.ne 1b", "4:", "cbz x26, 5f"] + bonly + ["5:"]
    out = "\n".join(f'      "{op(l)}\\n\\t"' for l in asm)
    sys.stdout.write(open("alias_span_a64.h.in").read().replace("@ASM@", out))


main()
