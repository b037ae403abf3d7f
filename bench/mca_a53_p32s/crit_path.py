#!/usr/bin/env python3
# bench/mca_a53_p32s/crit_path.py: the longest register dependence chain of a block (latencies
# from llvm-mca -instruction-info), ending at its last result or at the first line starting
# with PREFIX, printed line by line with each line's finish cycle.
#   crit_path.py IN.s [CPU] [PREFIX]
import sys, subprocess, re, os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from order_search import parse
f = sys.argv[1]; cpu = sys.argv[2] if len(sys.argv) > 2 else 'cortex-a53'
lines = [l.split('//')[0].strip() for l in open(f) if l.strip()]
out = subprocess.run(['llvm-mca-14', '-mtriple=aarch64', f'-mcpu={cpu}', '-iterations=1', '-instruction-info'], input='\n'.join(lines), capture_output=True, text=True).stdout
lat = []
for l in out.split('Instruction Info:')[1].splitlines():
    m = re.match(r'\s*\d+\s+(\d+)\s+', l)
    if m and '[' not in l[:5]: lat.append(int(m.group(1)))
lat = lat[:len(lines)]
ready = {}; fin = []; via = []
for i, l in enumerate(lines):
    r, w, st, b = parse(l)
    t0 = 0; src = None
    for x in r:
        if x in ready and ready[x][0] > t0: t0, src = ready[x]
    fin.append(t0 + lat[i]); via.append(src)
    for x in w: ready[x] = (t0 + lat[i], i)
end = max(range(len(lines)), key=lambda i: fin[i]) if len(sys.argv) < 4 else [i for i,l in enumerate(lines) if l.startswith(sys.argv[3])][0]
print('critical path', fin[end])
chain = []; i = end
while i is not None: chain.append(i); i = via[i]
for i in reversed(chain): print(f'{fin[i]:4d} {lat[i]} {lines[i]}')
