#!/usr/bin/env bash
# bench/run_bench.sh: build starbow_bench (default preset), run the flythrough
# benchmark (start, lq_e0m1, lq_e1m1 x 320x200..1920x1080), print a markdown table
# and write it to bench/results.md. Extra arguments go to Google Benchmark, e.g.
#   bench/run_bench.sh --benchmark_filter=lq_e1m1
# Times are for comparing runs on one machine, never pass/fail.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default --target starbow_bench
build/default/starbow_bench --markdown=bench/results.md "$@"
echo
echo "written: bench/results.md"
