#!/usr/bin/env python3
# bench/qemu_cuts.py: where qemu 7.2 (qemu-aarch64 with bench/count.sh's hotblocks plugin) cuts a
# long straight loop body into translation blocks, which bench/count.sh then times one by one
# (each as a loop of its own). qemu ends a block after the instruction that brings its TCG op
# count to 4000 (tcg_op_buf_full), counted as generated: the instruction's own ops (vis below,
# read from `qemu-aarch64 -d op`), 19 plugin placeholder ops an instruction and 13 a memory
# access (removed again before -d op prints), 21 at the block's start; or at a page end (page:
# the body index where the loop's page ends, 0 for none). Checked against the mip-1 band of
# asm/neon_block_a53m1.h (cuts 137 / 256 (page) / 386, and 153 from its entry at 2:). Knows
# only the instruction forms of asm/neon_block_a53*.h's loops (others raise ValueError).
#   qemu_cuts.py BODY.s [START]   prints the cuts from 0 and from START (no page end)
import re
def vis(l):
    op = l.split()[0]
    if op == 'add':
        if '.4s' in l: return 5, 0
        if 'uxth' in l or 'lsr' in l or 'lsl' in l: return 6, 0
        if '#' in l: return 3, 0
        return 5, 0
    if op == 'adds': return 17, 0
    if op == 'subs': return 17, 0
    if op in ('fmov', 'ror', 'tbl'): return (4 if op == 'tbl' else 2), 0
    if op == 'ld1': return 8, 1
    if op == 'ldr':
        if re.match(r'ldr q', l): return 14, 2
        if re.match(r'ldr b', l): return 9, 1
        if '#' in l: return 8, 1
        return 7, 1
    if op in ('smlal', 'smlal2'): return 14, 0
    if op in ('smull', 'smull2'): return 10, 0
    if op == 'stp': return 12, 2
    if op == 'st4': return 16, 4  # lane-0 st4 of four .s registers (measured cut fits 12..20)
    if op == 'mov': return 3, 0
    if op.startswith('b'): return 11, 0
    raise ValueError(l)
def cost(l):
    v, m = vis(l)
    return v + 19 + 13 * m
def cuts(body, page=0, start=0, limit=4000):
    """body: instruction lines (no labels). Returns cut indexes (block starts after start)."""
    res, k, n = [], start, len(body)
    while k < n:
        tot, j = 21, k
        while j < n:
            tot += cost(body[j]); j += 1
            if tot >= limit or j == page: break  # (page 0: none)
        if j < n: res.append(j)
        k = j
    return res
if __name__ == '__main__':
    import sys
    body = [l.strip() for l in open(sys.argv[1]) if l.strip() and not l.strip().endswith(':') and not l.startswith('//')]
    print(cuts(body), cuts(body, start=int(sys.argv[2]) if len(sys.argv) > 2 else 22))
