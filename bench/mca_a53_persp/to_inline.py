#!/usr/bin/env python3
# bench/mca_a53_persp/to_inline.py: writes a .s block (this directory's format: vector
# registers fixed, x8 .. x11 the pointer operands kb, kc, y, k1e9) as the string lines of
# the inline asm between the "// BEGIN NAME" and "// END NAME" lines of a header.
#   to_inline.py BLOCK.s HEADER NAME
import re, sys
src, hdr, name = sys.argv[1:]
ops = {"x8": "%[kb]", "x9": "%[kc]", "x10": "%[y]", "x11": "%[k1e9]"}
lines = [l.strip() for l in open(src) if l.strip() and not l.strip().startswith("//")]
body = [re.sub(r"\bx(8|9|10|11)\b", lambda m: ops["x" + m.group(1)], l) for l in lines]
h = open(hdr).read()
a = h.index(f"// BEGIN {name}")
a = h.index("\n", a) + 1
b = h.index(f"// END {name}")
b = h.rindex("\n", 0, b) + 1
ind = " " * (len(h[a:]) - len(h[a:].lstrip(" ")))  # the indent of the block's first line
text = "\n".join(f'{ind}"{l}\\n\\t"' for l in body[:-1]) + f'\n{ind}"{body[-1]}"\n'

open(hdr, "w").write(h[:a] + text + h[b:])
