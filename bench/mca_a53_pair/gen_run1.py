#!/usr/bin/env python3
# bench/mca_a53_pair/gen_run1.py: one second-order 16-pixel run (run 2 of a four-run span whose
# last run is partial, asm/span_persp_a64mid.h's run16_k3) as a software-pipelined straight
# block with virtual core registers, allocated here (the register freed longest ago first).
#   gen_run1.py OUT.s [word]   (word: 4-byte stores, else 8-byte)
# Inputs: x13 = uv (v 2^32 + u), x9 = duv, x10 = dduv (Run16's packing); w in w18, texels x26,
# dest x28 (stores at dest + 32 .. 47: run 2 of the span). Chains as Run16 / short_pass: c0 =
# uv_k, c1 = uv_{k+1}, stepped by e0 = 2 d + dd, e1 = 2 d + 3 dd, each e by 4 dd a pair.
import sys
out = sys.argv[1]
word4 = len(sys.argv) > 2 and sys.argv[2] == "word"
POOL = [1, 2, 3, 4, 5, 6, 7, 8, 11, 12, 14, 15, 16, 17, 19, 20, 21, 22]
ops = []  # (text with {name} virtual registers, reads, writes)


def op(fmt, writes, reads):
    ops.append((fmt, writes, reads))


# set-up (x13, x9, x10 physical inputs named c0, d, dd)
op("add {c1}, {c0in}, {d}", ["c1"], ["c0in", "d"])
op("add {e0}, {dd}, {d}, lsl #1", ["e0"], ["dd", "d"])
op("add {e1}, {e0}, {dd}, lsl #1", ["e1"], ["e0", "dd"])
op("lsl {dd4}, {dd}, #2", ["dd4"], ["dd"])
stages = {}
for g in range(8):  # pixel pairs
    A = []
    for c in (0, 1):
        k = 2 * g + c
        src = "c0in" if (g == 0 and c == 0) else f"c{c}"
        A.append((f"lsr {{h{k}}}, {{{src}}}, #48", [f"h{k}"], [src]))
        A.append((f"lsr {{l{k}}}:w, {{{src}}}:w, #16", [f"l{k}"], [src]))
    for c in (0, 1):
        if g < 7:
            src = "c0in" if (g == 0 and c == 0) else f"c{c}"
            A.append((f"add {{c{c}}}, {{{src}}}, {{e{c}}}", [f"c{c}"], [src, f"e{c}"]))
    for c in (0, 1):
        if g < 6:
            A.append((f"add {{e{c}}}, {{e{c}}}, {{dd4}}", [f"e{c}"], [f"e{c}", "dd4"]))
    B = [(f"madd {{a{k}}}:w, {{h{k}}}:w, w18, {{l{k}}}:w", [f"a{k}"], [f"h{k}", f"l{k}"]) for k in (2 * g, 2 * g + 1)]
    C = [(f"ldrb {{b{k}}}:w, [x26, {{a{k}}}:w, uxtw]", [f"b{k}"], [f"a{k}"]) for k in (2 * g, 2 * g + 1)]
    D = [(f"orr {{p{g}}}, {{b{2*g}}}, {{b{2*g+1}}}, lsl #8", [f"p{g}"], [f"b{2*g}", f"b{2*g+1}"])]
    if word4:
        if g % 2 == 1:
            D.append((f"orr {{q{g//2}}}:w, {{p{g-1}}}:w, {{p{g}}}:w, lsl #16", [f"q{g//2}"], [f"p{g-1}", f"p{g}"]))
            D.append((f"str {{q{g//2}}}:w, [x28, #{32 + 4 * (g // 2)}]", [], [f"q{g//2}"]))
    else:
        if g % 2 == 1:
            D.append((f"orr {{q{g//2}}}, {{p{g-1}}}, {{p{g}}}, lsl #16", [f"q{g//2}"], [f"p{g-1}", f"p{g}"]))
        if g % 4 == 3:
            j = g // 4
            D.append((f"orr {{r{j}}}, {{q{2*j}}}, {{q{2*j+1}}}, lsl #32", [f"r{j}"], [f"q{2*j}", f"q{2*j+1}"]))
            D.append((f"str {{r{j}}}, [x28, #{32 + 8 * j}]", [], [f"r{j}"]))
    stages[g] = (A, B, C, D)
for s in range(8 + 3):
    for st, g in ((3, s - 3), (2, s - 2), (1, s - 1), (0, s)):
        if 0 <= g < 8:
            for o in stages[g][st]:
                op(*o)
# allocation
phys = {"c0in": 13, "d": 9, "dd": 10}  # read-only: never rewritten (the block timed as a loop
# would otherwise wait on its own last writes of them)
lastuse = {}
for i, (f, w, r) in enumerate(ops):
    for n in r + w:
        lastuse[n] = i
free = list(POOL)
reg = {}
lines = []
for i, (f, w, r) in enumerate(ops):
    for n in r:
        if n not in reg:
            reg[n] = phys[n]
    # free the reads that die here before taking the writes' registers? keep them apart (no
    # reuse within one instruction: the order search sees fewer false dependences)
    for n in w:
        if n not in reg:
            if n in phys:
                reg[n] = phys[n]
            else:
                reg[n] = free.pop(0)
    text = f
    for n in set(r + w):
        text = text.replace("{" + n + "}:w", f"w{reg[n]}").replace("{" + n + "}", f"x{reg[n]}")
    lines.append(text)
    for n in set(r + w):
        if lastuse[n] == i and n not in phys:
            free.append(reg[n])
open(out, "w").write("\n".join(lines) + "\n")
print(len(lines), "lines", file=sys.stderr)
