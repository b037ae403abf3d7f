#!/usr/bin/env bash
# sched3.sh IN.s OUT.s: list-schedules lit16_block's three regions (up to the cbz, the
# cells-B part, from 1:) one by one with ../mca_a53_persp/list_sched.py and joins them.
set -euo pipefail
in=$1 out=$2 t=$(mktemp -d)
n1=$(grep -n "^cbz" "$in" | cut -d: -f1)
n2=$(grep -n "^1:$" "$in" | cut -d: -f1)
br=$(sed -n "${n1}p" "$in")
{ echo "1:"; sed -n "1,$((n1 - 1))p" "$in"; echo "${br%,*}, .+4"; } > "$t/r1.s"
{ echo "1:"; sed -n "$((n1 + 1)),$((n2 - 1))p" "$in"; echo "b .+4"; } > "$t/r2.s"
{ echo "1:"; sed -n "$((n2 + 1)),\$p" "$in"; echo "b .+4"; } > "$t/r3.s"
for r in r1 r2 r3; do
  python3 "$(dirname "$0")/../mca_a53_persp/list_sched.py" "$t/$r.s" "$t/${r}o.s" >/dev/null
done
{ sed '1d;$d' "$t/r1o.s"; echo "$br"; sed '1d;$d' "$t/r2o.s"; echo "1:"; sed '1d;$d' "$t/r3o.s"; } > "$out"
for r in r1 r2 r3; do
  printf "%s " "$r"; sed '1d' "$t/${r}o.s" | llvm-mca-14 -mtriple=aarch64 -mcpu=cortex-a53 -iterations=200 | grep "Total Cycles"
done
rm -rf "$t"
