#!/usr/bin/env bash
# bench/run_bench.sh: build starbow_bench (default preset), run the flythrough
# benchmark (start, lq_e0m1, lq_e1m1 x 320x200..1920x1080, cached and single-pass paths,
# light styles animated and static), print a markdown table (and single/cached ratios)
# and write it to bench/results.md. Extra arguments go to Google Benchmark, e.g.
#   bench/run_bench.sh --benchmark_filter=lq_e1m1
#   bench/run_bench.sh --styles=animated,static,dynamic   (paths: cached,single; styles:
#   animated,static,dynamic; bench/results_singlepass.md has the issue-4 comparison)
# Times are for comparing runs on one machine, never pass/fail.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default --target starbow_bench starbow_kernel_ratio
build/default/starbow_bench --markdown=bench/results.md "$@"
# Whole frames with the tuned asm/ kernels against the scalar references, paired per frame:
# the "tuned ÷ scalar ms" column per map and resolution (bench/kernel_ratio_bench.cpp).
build/default/starbow_kernel_ratio --markdown=build/default/kernel_ratio.md
{ echo; cat build/default/kernel_ratio.md; } >>bench/results.md
echo
echo "written: bench/results.md"
