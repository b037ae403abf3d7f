#!/usr/bin/env python3
# bench/mca_a53_persp/tail_inline.py: writes a tail steps block (tail1_steps.s or tail2_steps.s:
# one instruction a line, `//` comments dropped) into asm/span_persp_a64longspan.h between its
# "// BEGIN NAME" and "// END NAME" lines, the placeholder registers as the asm's operands (see
# each .s file's head); other registers stay (the asm's clobbers: tail1_steps x3 - x5, x9 - x17,
# x19, d16 - d23; tail2_steps x9 - x17, d16 - d25). Run from this directory:
#   python3 tail_inline.py tail1_steps tail1_steps.s ../../asm/span_persp_a64longspan.h
#   python3 tail_inline.py tail2_steps tail2_steps.s ../../asm/span_persp_a64longspan.h
import re, sys

# Per block: x / w placeholder number -> operand, d placeholder number -> operand, v placeholder
# number -> (vector) operand.
OPERANDS = {
    "tail1_steps": ({"0": "du", "1": "dv", "2": "st", "6": "lu", "7": "lv", "8": "ddu", "18": "ddv"},
                    {"1": "y", "2": "sf", "3": "z1", "4": "z2", "5": "zc"}, {}),
    "tail2_steps": ({"0": "du", "1": "dv", "2": "d1u", "3": "d1v", "4": "bd", "5": "bdd", "6": "lu", "7": "lv",
                     "8": "ddu", "18": "ddv"},
                    {"0": "cc", "1": "y", "2": "sf", "5": "zc"}, {"3": "z23"}),
}


def sub(l, xw, d, v):
    l = re.sub(r"\bv(\d+)\b", lambda g: "%[" + v[g.group(1)] + "]" if g.group(1) in v else g.group(0), l)
    l = re.sub(r"\b([xw])(\d+)\b",
               lambda g: "%" + ("w" if g.group(1) == "w" else "") + "[" + xw[g.group(2)] + "]" if g.group(2) in xw
               else g.group(0), l)
    return re.sub(r"\bd(\d+)\b", lambda g: "%d[" + d[g.group(1)] + "]" if g.group(1) in d else g.group(0), l)


def main(name, src, hdr):
    xw, d, v = OPERANDS[name]
    body = [sub(l.split("//")[0].strip(), xw, d, v) for l in open(src)]
    body = [l for l in body if l]
    text = "".join(f'      "{l}\\n\\t"\n' for l in body[:-1]) + f'      "{body[-1]}"\n'
    h = open(hdr).read()
    a = h.index(f"      // BEGIN {name}\n") + len(f"      // BEGIN {name}\n")
    b = h.index(f"      // END {name}\n")
    open(hdr, "w").write(h[:a] + text + h[b:])


if __name__ == "__main__":
    main(*sys.argv[1:4])
