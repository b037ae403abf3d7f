#!/usr/bin/env python3
# bench/to_inline.py: writes a .s block (one instruction a line; whole-line and trailing `//`
# comments dropped) as the string lines of the inline asm between the "// BEGIN NAME" and
# "// END NAME" lines of a header, in the indent of the block's present first line.
#
#   to_inline.py BLOCK.s HEADER NAME [N=operand ...]
#
# N=operand: register xN becomes %[operand] and wN becomes %w[operand] (e.g. 8=kb 10=y);
# every other register is written as it stands (pinned in the header). The lines between
# BEGIN and END are replaced; everything else in the header is left byte for byte. The
# command line for each block is recorded in its directory's README (bench/mca_a53_persp,
# bench/mca_a53_p64).
import re, sys


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[3:]):
        sys.exit(__doc__ or "usage: to_inline.py BLOCK.s HEADER NAME [N=operand ...]")
    src, hdr, name = argv[:3]
    ops = dict(a.split("=", 1) for a in argv[3:])
    body = [l.split("//")[0].strip() for l in open(src)]
    body = [l for l in body if l]
    if ops:
        pat = re.compile(r"\b([xw])(" + "|".join(sorted(ops, key=len, reverse=True)) + r")\b")
        body = [pat.sub(lambda m: "%" + ("w" if m.group(1) == "w" else "") + "[" + ops[m.group(2)] + "]", l)
                for l in body]
    h = open(hdr).read()
    a = h.index(f"// BEGIN {name}\n")
    a = h.index("\n", a) + 1
    b = h.index(f"// END {name}\n", a)
    b = h.rindex("\n", 0, b) + 1
    ind = h[a:b][:len(h[a:b]) - len(h[a:b].lstrip(" "))]  # the indent of the block's first line
    text = "\n".join(f'{ind}"{l}\\n\\t"' for l in body[:-1]) + f'\n{ind}"{body[-1]}"\n'
    open(hdr, "w").write(h[:a] + text + h[b:])


if __name__ == "__main__":
    main(sys.argv[1:])
