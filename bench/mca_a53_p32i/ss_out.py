#!/usr/bin/env python3
# bench/mca_a53_p32i/ss_out.py HEADER OUT.s: short_samples2's asm text (asm/span_persp_a64pair.h)
# as plain lines (bench/order_search.py's syntax), each named operand a register of its own
# (OPS; the memory operand %[zb] as [x29]); ss_in.py turns such lines back into the quoted
# lines of an asm statement with the operand names.
import re, sys

OPS = {"pa": "x19", "pb": "x20", "out": "x21", "kc": "x22", "oa": "x23", "ob": "x24", "it": "x25", "end": "x26",
       "na": "x27", "fl": "x28", "h": "x1", "n0": "x2", "n1": "x3", "s1": "x4", "z0": "x5", "z1": "x16", "ra": "x17",
       "la": "x30"}


def main():
    text = open(sys.argv[1]).read()
    body = text.split("// BEGIN short_samples2\n", 1)[1].split("// END short_samples2", 1)[0]
    out = []
    for l in body.splitlines():
        l = l.strip()
        if not l.startswith('"'):
            continue
        l = re.sub(r'\\n\\t"$|"$', "", l[1:])
        l = l.replace("%[zb]", "[x29]")
        for k, r in OPS.items():
            l = l.replace(f"%w[{k}]", "w" + r[1:]).replace(f"%x[{k}]", r).replace(f"%[{k}]", r)
        assert "%" not in l, l
        out.append(l)
    open(sys.argv[2], "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
