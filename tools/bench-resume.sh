#!/usr/bin/env bash
# Back-to-back timing of two quicksand builds on the same stretch of a run: each resumes the same
# checkpoint for the same simulated time, in interleaved rounds (docs/performance.md).
#
#   bash tools/bench-resume.sh OLD_BINARY NEW_BINARY RUN_DIR END_TIME [ROUNDS] [THREADS]
#
# RUN_DIR is a finished or stopped run (its case.toml and output/checkpoint.h5); it is not
# touched: each round copies it to a scratch directory. Prints the wall time of each run.
set -euo pipefail
if [ $# -lt 4 ]; then
    echo "usage: $0 OLD_BINARY NEW_BINARY RUN_DIR END_TIME [ROUNDS] [THREADS]" >&2
    exit 2
fi
old=$1 new=$2 run=$3 end=$4 rounds=${5:-2} threads=${6:-1}
for f in "$old" "$new"; do [ -x "$f" ] || { echo "$0: $f is not an executable" >&2; exit 2; }; done
[ -f "$run/case.toml" ] || { echo "$0: $run/case.toml not found" >&2; exit 2; }
[ -f "$run/output/checkpoint.h5" ] || { echo "$0: $run/output/checkpoint.h5 not found" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for round in $(seq "$rounds"); do
    for bin in "$old" "$new"; do
        rm -rf "$scratch/run" && mkdir -p "$scratch/run/output"
        cp "$run/case.toml" "$scratch/run/" && cp "$run/output/checkpoint.h5" "$scratch/run/output/"
        start=$(date +%s.%N)
        OMP_NUM_THREADS=$threads "$bin" run "$scratch/run" --resume --set "time.end=$end" > "$scratch/log" 2>&1
        stop=$(date +%s.%N)
        printf 'round %s  %-50s %8.2f s  %s\n' "$round" "$bin" "$(echo "$stop - $start" | bc)" "$(tail -1 "$scratch/log" | cut -c1-40)"
    done
done
