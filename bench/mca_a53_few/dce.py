#!/usr/bin/env python3
# bench/mca_a53_few/dce.py: drops the lines of an asm block (one instruction a line, plain
# registers, bench/order_search.py's syntax) whose results nothing later reads: a line stays
# if it stores, branches, or writes a register that a kept later line reads or that is listed
# live out.
#   dce.py IN.s OUT.s [LIVE_OUT_REG ..]
# Branches: forward ones to numeric labels (tbz w0, #3, 1f: runs_k3's chunks), the registers
# live at the label joined to those of the fall-through.
# Used on steps_k3v_pass and runs_k3 (asm/span_persp_a64mid.h) less some of their stores, for
# steps_k1v_pass, steps_k2v_pass and last_chunks (asm/span_persp_a64few.h; README.md here).
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from order_search import parse, reg  # noqa: E402

args = [a for a in sys.argv[1:] if not a.startswith("--")]
src, dst = args[0], args[1]
live = {reg(r) or r for r in args[2:]}
lines = [l.rstrip() for l in open(src) if l.strip()]
keep = [False] * len(lines)
at_label = {}  # label -> registers live where it stands (forward branches only: seen first)
for i in range(len(lines) - 1, -1, -1):
    l = lines[i].split("//")[0].strip()
    if l.endswith(":"):
        at_label[l[:-1]] = set(live)
        keep[i] = True
        continue
    reads, writes, store, barrier = parse(lines[i])
    if barrier:  # a forward branch to a numeric label: live there too
        keep[i] = True
        tgt = l.split(",")[-1].strip().split()[-1]
        live |= at_label.get(tgt.rstrip("f"), set()) | reads
        continue
    if store or (writes & live):
        keep[i] = True
        # a partial write (accumulating ops) reads its destination: parse lists it in reads
        live -= {w for w in writes if w not in reads}
        live |= reads
open(dst, "w").write("".join(l + "\n" for l, k in zip(lines, keep) if k))
print(f"{sum(keep)} of {len(lines)} lines kept", file=sys.stderr)
