#!/usr/bin/env python3
# bench/mca_a53_palette/v7_inline.py: writes a searched ARMv7 loop body (v7scaleS_s.s, the
# last line its branch) into asm/neon_palette.h between "// BEGIN palette_v7_scaleS" and
# "// END ...", with gen_scales.py's fixed registers as the asm statement's operands
# (rN=name arguments replace that mapping: the scale-1 loop binds r0, r8, r9, r10 only).
#   v7_inline.py BLOCK.s HEADER NAME [rN=name ...]
import re, sys

OPS = {"r0": "p", "r9": "s", "r10": "e", "r8": "pal", "r1": "nr", "r2": "ng"}


def main(src, hdr, name, *maps):
    ops = dict(m.split("=", 1) for m in maps) if maps else OPS
    body = [l.split("@")[0].strip() for l in open(src)]
    body = [l for l in body if l and not l.startswith(".") and not l.startswith("bne")]
    pat = re.compile(r"\b(" + "|".join(ops) + r")\b")
    body = [pat.sub(lambda m: "%[" + ops[m.group(1)] + "]", l) for l in body]
    h = open(hdr).read()
    a = h.index(f"// BEGIN {name}\n")
    ind = h[h.rindex("\n", 0, a) + 1:a]
    a = h.index("\n", a) + 1
    b = h.index(f"// END {name}\n", a)
    b = h.rindex("\n", 0, b) + 1
    text = "".join(f'{ind}"{l}\\n\\t"\n' for l in body)
    open(hdr, "w").write(h[:a] + text + h[b:])


if __name__ == "__main__":
    main(*sys.argv[1:])
