#!/usr/bin/env python3
# bench/mca_a53_p32i/trim48.py IN.s OUT.s: short_samples2's lines (ss_out.py) to
# short_samples48's (asm/span_persp_a64pair48.h): span b's S44 and c23 stores out (stp q13,
# q4 -> str q4; str q28 dropped), zs23's trn1 / trn2 with the z_3 + z_4 sums replaced by their
# lane 0 alone (mov v1 / dup v22), then bench/mca_a53_few/dce.py (live out: span a's S01 v5,
# S23 v19, zs01 v9, zs23 v1, c01 v3, zh v31 and the core outputs fl x28, ra x17, la x30), then
# the next pair's test for n 17 .. 48 (#32 for #48).
import os, subprocess, sys

EDITS = {
    "stp q13, q4, [x21, #32]": "str q4, [x21, #48]",
    "str q28, [x21, #96]": None,
    "trn1 v1.2d, v8.2d, v12.2d": "mov v1.16b, v8.16b",
    "trn2 v22.2d, v8.2d, v12.2d": "dup v22.2d, v8.d[1]",
}
TEST = {"sub x3, x3, #48": "sub x3, x3, #32", "sub x2, x2, #48": "sub x2, x2, #32"}


def main():
    src, dst = sys.argv[1], sys.argv[2]
    lines = [l.strip() for l in open(src) if l.strip()]
    for k in EDITS:
        assert k in lines, k
    lines = [EDITS.get(l, l) for l in lines]
    lines = [l for l in lines if l is not None]
    tmp = dst + ".edit"
    open(tmp, "w").write("\n".join(lines) + "\n")
    here = os.path.dirname(os.path.abspath(__file__))
    subprocess.run([sys.executable, os.path.join(here, "..", "mca_a53_few", "dce.py"), tmp, dst, "v5", "v19", "v9", "v1",
                    "v3", "v31", "x28", "x17", "x30"], check=True)
    os.remove(tmp)
    out = [l.strip() for l in open(dst) if l.strip()]
    for k in TEST:
        assert k in out, k
    open(dst, "w").write("\n".join(TEST.get(l, l) for l in out) + "\n")


if __name__ == "__main__":
    main()
