#!/usr/bin/env python3
# bench/mca_a9_alias/inline.py: writes a searched loop body (body_s.s: one instruction a line,
# `@` comments, the last line its branch) into asm/alias_span_v7.h between
# "// BEGIN alias_v7_body" and "// END alias_v7_body", without the branch (the header's
# control code follows the body's last flag-setting `subs`).
#   inline.py BODY.s HEADER
import sys


def main(src, hdr):
    body = [l.split("@")[0].strip() for l in open(src)]
    body = [l for l in body if l and not l.startswith(".")]
    if body and body[-1].startswith("b"):
        body = body[:-1]
    h = open(hdr).read()
    a = h.index("// BEGIN alias_v7_body\n")
    ind = h[h.rindex("\n", 0, a) + 1:a]
    a = h.index("\n", a) + 1
    b = h.index("// END alias_v7_body\n", a)
    b = h.rindex("\n", 0, b) + 1
    open(hdr, "w").write(h[:a] + "".join(f'{ind}"{l}\\n\\t"\n' for l in body) + h[b:])


if __name__ == "__main__":
    main(*sys.argv[1:3])
