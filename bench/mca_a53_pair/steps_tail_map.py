# steps_tail_map.py IN.s OUT.s HEADER BLOCK FIRST HEAD TAIL: writes order_search.py's order OUT.s of
# IN.s (a qemu block as bench/count.sh dumps it: HEAD compiler lines, then asm lines FIRST .. of the
# asm statement between `// BEGIN BLOCK` and `// END BLOCK` in HEADER, then TAIL compiler lines,
# which the search kept in place) back onto HEADER's asm lines, matched by their dumped text.
# E.g. steps_tail_in.s: HEADER asm/span_persp_a64mid.h, BLOCK steps_k3v_pass, FIRST 133, 0, 1.
import re
import sys

inp = [l.strip() for l in open(sys.argv[1]) if l.strip()]
out = [l.strip() for l in open(sys.argv[2]) if l.strip()]
hdr, block, first, head, tail = sys.argv[3], sys.argv[4], int(sys.argv[5]), int(sys.argv[6]), int(sys.argv[7])
H = open(hdr).read().split("\n")
b = next(i for i, l in enumerate(H) if f"BEGIN {block}" in l)
e = next(i for i, l in enumerate(H) if f"END {block}" in l)
asm = [i for i in range(b + 1, e) if H[i].strip().startswith('"')]
assert out[:head] == inp[:head] and (tail == 0 or out[-tail:] == inp[-tail:]), "compiler lines moved"
body_in, body_out = inp[head:len(inp) - tail], out[head:len(out) - tail]
n = len(body_in)
idx = asm[first:first + n]
used, perm = [False] * n, []
for l in body_out:
    k = next(k for k in range(n) if not used[k] and body_in[k] == l)
    used[k] = True
    perm.append(k)


def core(t):  # the instruction of a source line "....\n\t" (or the statement's last, "....")
    return t.strip().rstrip(",").strip('"').replace("\\n\\t", "")


texts = [H[i] for i in idx]
ends = ["\\n\\t\"" if H[i].strip().endswith("\\n\\t\"") else "\"" for i in idx]  # kept by position
ind = re.match(r"\s*", H[idx[0]]).group(0)
for pos, k in enumerate(perm):
    H[idx[pos]] = ind + '"' + core(texts[k]) + ends[pos]
open(hdr, "w").write("\n".join(H))
print("moved", sum(1 for a, k in enumerate(perm) if a != k))
