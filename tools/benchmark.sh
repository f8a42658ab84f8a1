#!/usr/bin/env bash
# Measures the speed of the double-point step (figures go to docs/performance.md).
#
#   bash tools/benchmark.sh            Google Benchmark (tools/benchmarks/bench_step.cpp) with 1 and
#                                      2 threads, then the longest verification case through the
#                                      command line (wall time, steps/s, point updates/s)
# Speed is measured here, never by timed tests.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash tools/build.sh >/dev/null
build_dir="${QUICKSAND_BUILD_DIR:-build}"

echo "== machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for threads in 1 2; do
    echo "== Google Benchmark, OMP_NUM_THREADS=$threads"
    OMP_NUM_THREADS=$threads "$build_dir/tools/benchmarks/quicksand_benchmarks" \
        --benchmark_min_time=2 2>&1 | grep -E '^(BM_|---|Benchmark)'
done

echo "== longest verification run (falling_head, 6 s simulated), OMP_NUM_THREADS=1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp cases/verification/falling_head/case.toml "$work/"
OMP_NUM_THREADS=1 "$build_dir/mpm/quicksand" run "$work" | grep -E "^quicksand"
