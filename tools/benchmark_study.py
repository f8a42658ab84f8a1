#!/usr/bin/env python3
"""Measures what a study costs beyond its runs (figures go to docs/performance.md):

  python3 tools/benchmark_study.py [--case cases/verification/bed_expansion] [--rounds 3]

- concurrency: a study of one 1D variant, then of two (parallel = 2, one thread each), of the same
  case; the ratio of their wall times (1.0: the second variant is free on the second core; the
  issue asks for at most 1.15 on 2 cores);
- overhead per variant: the study's wall time less the runs' own (each variant's wall_seconds in
  its study-status.json, the time its quicksand process ran): checking the variants, starting the
  runs, collecting study.csv (the plots are left out: --no-plots).
Rounds alternate one and two variants; the best of each is reported, with the spread.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def study(work, case, variants):
    folder = os.path.join(work, f"study{variants}")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    flux = [1.380e-3, 1.381e-3][:variants]
    with open(os.path.join(folder, "study.toml"), "w") as f:
        f.write(f'base = "{os.path.abspath(case)}"\nparallel = {variants}\nthreads = 1\n'
                f'[parameters]\n"gate.flux" = {flux}\n[set]\n"output.fields" = false\n')
    start = time.time()
    subprocess.run([sys.executable, os.path.join(HERE, "study.py"), os.path.join(folder, "study.toml"),
                    "--quiet", "--no-plots"], check=True)
    wall = time.time() - start
    runs = []
    for name in sorted(os.listdir(os.path.join(folder, "output"))):
        status = os.path.join(folder, "output", name, "study-status.json")
        if os.path.isfile(status):
            runs.append(json.load(open(status))["wall_seconds"])
    return wall, runs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", default=os.path.join(HERE, "..", "cases", "verification", "bed_expansion"))
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    work = tempfile.mkdtemp()
    try:
        one, two, overhead = [], [], []
        for r in range(args.rounds):
            w1, runs1 = study(work, args.case, 1)
            w2, runs2 = study(work, args.case, 2)
            one.append(w1)
            two.append(w2)
            overhead += [w1 - runs1[0], (w2 - max(runs2)) / 2]
            print(f"round {r + 1}: one variant {w1:.2f} s (run {runs1[0]:.2f} s), two variants {w2:.2f} s "
                  f"(runs {runs2[0]:.2f} s, {runs2[1]:.2f} s): ratio {w2 / w1:.3f}", flush=True)
        print(f"best: one {min(one):.2f} s, two {min(two):.2f} s, ratio {min(two) / min(one):.3f} "
              f"(rounds' ratios {min(b / a for a, b in zip(one, two)):.3f} to {max(b / a for a, b in zip(one, two)):.3f}); "
              f"overhead per variant {min(overhead):.2f} to {max(overhead):.2f} s")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
