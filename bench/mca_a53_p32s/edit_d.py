#!/usr/bin/env python3
# bench/mca_a53_p32s/edit_d.py: two edits of the last run's tail in steps_k1v_pass (its lines as
# bench/mca_a53_few/names.py gives them), each one NEON level off the chain from dd to d:
# - the range test |dd| < L (v16 = cmhi v17, |dd|) folded into the monotone test's |delta|:
#   accept = (|delta| & v16) >= min(|dd|, C) T, not cmhs then and. A rejected lane has |dd| >=
#   1e9 and T >= 1 (T = 0 only for s = 1, where dd = 0 and v16 holds), so min(|dd|, C) T >= 1 >
#   0: rejected as before; lanes 0, 1 (L = 2^32 - 1) always hold v16;
# - d = accept ? lin - sel : lin with sel = cond ? (M + 1) >> 1 : M >> 1 as two candidates
#   lin - (M >> 1), lin - ((M + 1) >> 1) (sub, sub, then bit on cond), so that lin - sel no
#   longer waits for cond's bit (one NEON line more).
#   edit_d.py IN.s OUT.s
import sys
L = [l.rstrip('\n') for l in open(sys.argv[1]) if l.strip()]
def rep(old, new):
    i = L.index(old); L[i:i+1] = new
rep('cmhs v0.4s, v27.4s, v0.4s', ['and v16.16b, v27.16b, v16.16b', 'cmhs v0.4s, v16.4s, v0.4s'])
rep('and v0.16b, v0.16b, v16.16b', [])
rep('bit v22.16b, v4.16b, v25.16b', ['sub v22.4s, v30.4s, v22.4s', 'sub v4.4s, v30.4s, v4.4s', 'bit v22.16b, v4.16b, v25.16b'])
rep('sub v21.4s, v30.4s, v22.4s', [])
rep('bit v30.16b, v21.16b, v0.16b', ['bit v30.16b, v22.16b, v0.16b'])
open(sys.argv[2], 'w').write('\n'.join(L) + '\n')
