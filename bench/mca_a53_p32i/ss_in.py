#!/usr/bin/env python3
# bench/mca_a53_p32i/ss_in.py IN.s OUT.inc: plain lines with ss_out.py's operand registers back
# to an asm statement's quoted lines with the operand names (asm/span_persp_a64pair48.h's
# short_samples48 block between its BEGIN / END lines).
import re, sys

from ss_out import OPS


def main():
    res = []
    for l in open(sys.argv[1]):
        l = l.split("//")[0].strip()
        if not l:
            continue
        l = l.replace("[x29]", "%[zb]")
        for k, r in OPS.items():
            l = re.sub(rf"\bw{r[1:]}\b", f"%w[{k}]", l)
            l = re.sub(rf"\b{r}\b", f"%[{k}]", l)
        res.append(f'        "{l}\\n\\t"')
    res[-1] = res[-1][:-5] + '"'
    open(sys.argv[2], "w").write("\n".join(res) + "\n")


if __name__ == "__main__":
    main()
