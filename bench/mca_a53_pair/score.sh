#!/bin/sh
# score.sh FILE.s: llvm-mca cycles (200 iterations, per iteration) of the block's two qemu
# blocks: up to the fallback branch, and from the label on (the fallback's divides not timed).
f=$1
for cpu in cortex-a53 cortex-a57; do
  r1=$(sed -n '1,/b.ne 2f/p' "$f" | grep -v '^//' | sed 's/b.ne 2f/b.ne .+4/' | llvm-mca-14 -mtriple=aarch64 -mcpu=$cpu -iterations=200 | awk '/Total Cycles/{print $3/200}')
  r2=$(sed -n '/^2:/,$p' "$f" | grep -v '^2:' | llvm-mca-14 -mtriple=aarch64 -mcpu=$cpu -iterations=200 | awk '/Total Cycles/{print $3/200}')
  echo "$cpu $r1 + $r2"
done
