#!/usr/bin/env python3
# bench/mca_a53_p64/to_inline.py: writes a .s block of this directory (x26, x27, x28, x0 the
# operands kp, y, s, st; x13, x9, x10, x23, x24, x25 the outputs a_uv, a_d, a_dd, b_uv, b_d, b_dd;
# every other register fixed) as the string lines of the inline asm
# between the "// BEGIN NAME" and "// END NAME" lines of a header.
# With a fourth argument "pass" (the steps block and the first pass in one, steps_pass.s): x26,
# x27, x0, x28, x18, x30 the operands kp, y, st, d, tx, w; every other register fixed (x13, x9,
# x10, x23, x24, x25 the second pass's arguments, bound by register variables).
#   to_inline.py BLOCK.s HEADER NAME [pass]
import re, sys
src, hdr, name = sys.argv[1:4]
ops = {"26": "kp", "27": "y", "28": "s", "0": "st", "13": "a_uv", "9": "a_d", "10": "a_dd", "23": "b_uv", "24": "b_d",
       "25": "b_dd"}
if sys.argv[4:] == ["pass"]:
    ops = {"26": "kp", "27": "y", "0": "st", "28": "d", "18": "tx", "30": "w"}
pat = r"\b([xw])(" + "|".join(ops) + r")\b"
lines = [l.split("//")[0].strip() for l in open(src)]
lines = [l for l in lines if l]
body = [re.sub(pat, lambda m: "%" + ("w" if m.group(1) == "w" else "") + "[" + ops[m.group(2)] + "]",
               l) for l in lines]
h = open(hdr).read()
a = h.index(f"// BEGIN {name}")
a = h.index("\n", a) + 1
b = h.index(f"// END {name}")
b = h.rindex("\n", 0, b) + 1
ind = " " * 6
text = "\n".join(f'{ind}"{l}\\n\\t"' for l in body[:-1]) + f'\n{ind}"{body[-1]}"\n'
open(hdr, "w").write(h[:a] + text + h[b:])
