#!/usr/bin/env python3
# bench/mca_a53_persp/tail1_inline.py: writes tail1_steps.s (one instruction a line, `//`
# comments dropped) into asm/span_persp_a64longspan.h between its "// BEGIN tail1_steps" and
# "// END tail1_steps" lines, the placeholder registers as the asm's operands (see the .s file's
# head); x3 - x5, x9 - x17, x19 and d16 - d23 stay (the asm's clobbers). Run from this directory:
#   python3 tail1_inline.py tail1_steps.s ../../asm/span_persp_a64longspan.h
import re, sys

XW = {"0": "du", "1": "dv", "2": "st", "6": "lu", "7": "lv", "8": "ddu", "18": "ddv"}
D = {"1": "y", "2": "sf", "3": "z1", "4": "z2", "5": "zh"}


def sub(l):
    l = re.sub(r"\b([xw])(\d+)\b",
               lambda g: "%" + ("w" if g.group(1) == "w" else "") + "[" + XW[g.group(2)] + "]" if g.group(2) in XW
               else g.group(0), l)
    return re.sub(r"\bd(\d+)\b", lambda g: "%d[" + D[g.group(1)] + "]" if g.group(1) in D else g.group(0), l)


def main(src, hdr):
    body = [sub(l.split("//")[0].strip()) for l in open(src)]
    body = [l for l in body if l]
    text = "".join(f'      "{l}\\n\\t"\n' for l in body[:-1]) + f'      "{body[-1]}"\n'
    h = open(hdr).read()
    a = h.index("      // BEGIN tail1_steps\n") + len("      // BEGIN tail1_steps\n")
    b = h.index("      // END tail1_steps\n")
    open(hdr, "w").write(h[:a] + text + h[b:])


if __name__ == "__main__":
    main(*sys.argv[1:3])
