#!/usr/bin/env python3
# bench/mca_a53_few/names.py: an asm statement's text (the lines between "// BEGIN NAME" and
# "// END NAME" of a header, C string literals) to plain lines with registers for its named
# operands (to search or trim it: bench/order_search.py, dce.py), and back.
#   names.py out HEADER NAME OUT.s        the block of HEADER with the operands below
#   names.py in IN.s OUT.inc              quoted lines for an asm statement, operands named again
#   names.py splice IN.s HEADER NAME      those lines between HEADER's "// BEGIN NAME" and "// END
#                                         NAME" (replacing what was there); prints the registers
#                                         the block writes (for its clobber list)
import re, sys

# Operand names of the span blocks and the registers they take here (none of them a block's
# own scratch register): d, tx, w as bench/mca_a53_pair's searches name them (x26, x18, w0).
OPS = {"d": "x26", "tx": "x18", "w": "x0", "kp": "x27", "st": "x28", "y": "x30", "n": "x29"}


def out(header, name, dst):
    text = open(header).read()
    body = text.split(f"// BEGIN {name}\n", 1)[1].split(f"// END {name}", 1)[0]
    lines = []
    for l in body.splitlines():
        l = l.strip()
        if not l.startswith('"'):
            continue
        l = re.sub(r'\\n\\t"$|"$', "", l[1:])
        for k, r in OPS.items():
            l = l.replace(f"%w[{k}]", "w" + r[1:]).replace(f"%[{k}]", r)
        lines.append(l)
    open(dst, "w").write("\n".join(lines) + "\n")


def quoted(src):
    lines = [l.strip() for l in open(src) if l.strip()]
    res = []
    for l in lines:
        for k, r in OPS.items():
            l = re.sub(rf"\bw{r[1:]}\b", f"%w[{k}]", l)
            l = re.sub(rf"\b{r}\b", f"%[{k}]", l)
        res.append(f'      "{l}\\n\\t"')
    res[-1] = res[-1][:-5] + '"'
    return res


def back(src, dst):
    open(dst, "w").write("\n".join(quoted(src)) + "\n")


def splice(src, header, name):
    text = open(header).read()
    head, rest = text.split(f"// BEGIN {name}\n", 1)
    _, tail = rest.split(f"// END {name}", 1)
    open(header, "w").write(head + f"// BEGIN {name}\n" + "\n".join(quoted(src)) + f"\n// END {name}" + tail)
    sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(__file__)), ".."))
    from order_search import parse
    w = set()
    for l in open(src):
        if l.strip():
            w |= parse(l.strip())[1]
    print(" ".join(sorted(w, key=lambda r: (r[0], int(r[1:]) if r[1:].isdigit() else 0))))


if __name__ == "__main__":
    if sys.argv[1] == "out":
        out(*sys.argv[2:5])
    elif sys.argv[1] == "in":
        back(*sys.argv[2:4])
    else:
        splice(*sys.argv[2:5])
