#!/usr/bin/env python3
# bench/mca_a53_p32s/div120.py IN.s OUT.s (tried, not kept: README.md):
# steps16_dd's monotone test 120 |dd| <= |delta| (D01: abs, umin 2^25, mul 120, cmhs) as
# |dd| <= B, B = floor(|delta| / 120) = (|delta| m) >> 38, m = ceil(2^38 / 120) (exact for
# |delta| <= 2^31), computed from |delta| off the dd chain: umull, umull2, uzp2, ushr.
import sys
L = [l.rstrip('\n') for l in open(sys.argv[1]) if l.strip()]
def rep(old, new):
    i = L.index(old); L[i:i+1] = new
rep('ldr q25, [x30, #160]', ['ldp q25, q4, [x30, #160]'])
rep('ldp q2, q4, [x27]', ['ldr q2, [x27]'])
rep('abs v26.4s, v0.4s', ['abs v26.4s, v0.4s', 'umull v8.2d, v26.2s, v4.2s', 'umull2 v10.2d, v26.4s, v4.4s',
                          'uzp2 v8.4s, v8.4s, v10.4s', 'ushr v8.4s, v8.4s, #6'])
rep('umin v3.4s, v3.4s, v4.4s', [])
rep('mul v3.4s, v3.4s, v2.4s', [])
rep('cmhs v3.4s, v26.4s, v3.4s', ['cmhs v3.4s, v8.4s, v3.4s'])
open(sys.argv[2], 'w').write('\n'.join(L) + '\n')
