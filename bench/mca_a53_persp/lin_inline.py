#!/usr/bin/env python3
# bench/mca_a53_persp/lin_inline.py: writes lin_setup.s (registers as asm/span_persp_a64lin.h
# pins them; `2:` the divide fallback's end) as the string lines of the inline asm between
# "// BEGIN lin_setup" and "// END lin_setup" in asm/span_persp_a64lin.h.
#   lin_inline.py [BLOCK.s [HEADER]]
import os, sys
here = os.path.dirname(os.path.abspath(__file__))
src = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "lin_setup.s")
hdr = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "asm", "span_persp_a64lin.h")
body = [l.split("//")[0].strip() for l in open(src)]
body = [l for l in body if l]
h = open(hdr).read()
a = h.index("// BEGIN lin_setup")
a = h.index("\n", a) + 1
b = h.index("// END lin_setup")
b = h.rindex("\n", 0, b) + 1
ind = " " * 8
text = "\n".join(f'{ind}"{l}\\n\\t"' for l in body[:-1]) + f'\n{ind}"{body[-1]}"\n'
open(hdr, "w").write(h[:a] + text + h[b:])
