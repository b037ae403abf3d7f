#!/bin/sh
# assemble.sh R1.s R2.s OUT.s: the whole block from its two searched parts (the fallback's
# divides between them, as gen_pair.py writes them: `one` in v3... see below).
r1=$1; r2=$2; out=$3
sed 's/b.ne .+4/b.ne 2f/' "$r1" > "$out"
grep -A6 '^b.ne 2f' pair_ls.s | tail -n 6 >> "$out"
echo "2:" >> "$out"
cat "$r2" >> "$out"
