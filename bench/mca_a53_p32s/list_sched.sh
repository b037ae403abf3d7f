#!/bin/bash
# bench/mca_a53_p32s/list_sched.sh IN.s OUT.s: bench/mca_a53_persp/list_sched.py's greedy order of
# a steps_k1v_pass / steps_k2v_pass block (wrapped as a loop for it), then the reloads of st
# (x28 #24, #40: the last run's steps) moved back after the stp that stores them (list_sched.py
# does not order loads after stores), timed with llvm-mca (A53). A start for order_search.py.
d=$(mktemp -d); (echo "1:"; cat $1; echo "b.ne 1b") > $d/w.s
python3 "$(dirname "$0")"/../mca_a53_persp/list_sched.py $d/w.s $d/o.s > /dev/null
sed '1d;$d' $d/o.s > $d/b.s
python3 - $d/b.s $2 <<'PY'
import sys
L=[l.rstrip('\n') for l in open(sys.argv[1])]
mv=[l for l in L if l.startswith('ldr') and ('[x28, #24]' in l or '[x28, #40]' in l)]
L=[l for l in L if l not in mv]
i=[k for k,l in enumerate(L) if l.startswith('stp q30, q1, [x28, #16]')][0]
L[i+1:i+1]=mv
open(sys.argv[2],'w').write('\n'.join(L)+'\n')
PY
echo -n "$2 A53 "; llvm-mca-14 -mtriple=aarch64 -mcpu=cortex-a53 -iterations=100 $2 2>/dev/null | grep "Total Cycles" | awk '{print $3/100}'
