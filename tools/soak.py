#!/usr/bin/env python3
"""Soak run (issue 8): a fluidising 1D column for a million steps, checked for conservation and
for memory that stays flat. Not part of the test suite (it takes a minute or two); run it after
a change to the step or the boundaries, and record its figures in docs/reliability.md.

    /usr/bin/python3 tools/soak.py [--build build] [--steps 1000000] [--work /tmp/quicksand-soak]

Runs cases/verification/bed_expansion (problem 7: the bed fluidises from the filter up and
expands) with the built quicksand: the first tenth of the steps, then --resume for the rest,
sampling the process's resident memory from /proc. From the two checkpoints (full precision;
series.csv has 9 digits) and series.csv it checks:
  - solid mass exactly constant, and the liquid's changing only by what was injected at the
    chamber and removed at the overflow, to 1e-12 relative;
  - the liquid ledger (inflow - outflow - stored) closed to 1e-6 of the inflow at every output;
  - resident memory at the end within 10 % (and 2 MiB) of the resident memory after a tenth of
    the resumed run.
Exits non-zero, saying which, if any check fails.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

import quicksand as qs

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rss_kib(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--steps", type=int, default=1_000_000)
    ap.add_argument("--work", default="/tmp/quicksand-soak")
    a = ap.parse_args()
    try:
        quicksand = qs.find_quicksand(os.path.join(a.build, "mpm", "quicksand"))
    except qs.QuicksandError as e:
        sys.exit(f"soak.py: {e} (bash tools/build.sh)")

    shutil.rmtree(a.work, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "cases", "verification", "bed_expansion"), a.work)
    check = qs.check(a.work, binary=quicksand)
    dt = float(re.search(r"fitted to dt = ([0-9.e+-]+) s", check).group(1))
    end = a.steps * dt

    def run(extra, end_time):
        start = time.time()
        overrides = {"time.end": end_time, "time.output_interval": end / 200}
        proc = subprocess.Popen([quicksand, "run", a.work, "--quiet", *qs.set_arguments(overrides)] + extra,
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        samples = []
        while proc.poll() is None:
            r = rss_kib(proc.pid)
            if r is not None:
                samples.append((time.time() - start, r))
            time.sleep(0.2)
        if proc.returncode != 0:
            sys.exit(f"soak.py: the run failed ({proc.returncode}):\n{proc.stderr.read().decode()}")
        return time.time() - start, samples

    def totals():
        import h5py
        with h5py.File(os.path.join(a.work, "output", "checkpoint.h5"), "r") as f:
            ledger = f["ledger"][:]  # inflow, injected, outflow, initial liquid mass, ...
            return {"solid": float(f["solid/mass"][:].sum()), "liquid": float(f["liquid/mass"][:].sum()),
                    "injected": float(ledger[1]), "outflow": float(ledger[2]), "steps": int(f["steps"][()])}

    wall1, _ = run([], 0.1 * end)
    first = totals()
    wall2, samples = run(["--resume"], end)
    second = totals()
    wall = wall1 + wall2
    rho = 998.2
    solid_drift = abs(second["solid"] / first["solid"] - 1)
    liquid_expected = first["liquid"] + rho * ((second["injected"] - first["injected"]) -
                                               (second["outflow"] - first["outflow"]))
    liquid_drift = abs(second["liquid"] / liquid_expected - 1)

    rows = qs.read_series(os.path.join(a.work, "output")).to_dict("records")
    f = lambda r, k: float(r[k])
    first_row, last = rows[0], rows[-1]
    inflow = max(abs(f(last, "cumulative_inflow")), 1e-30)
    ledger = max(abs(f(r, "ledger_residual")) for r in rows) / inflow
    tenth = [s for s in samples if s[0] >= 0.1 * wall] or samples
    rss_start, rss_end = tenth[0][1], samples[-1][1]
    fluid = max(f(r, "fluidised_share") for r in rows)

    print(f"soak: {second['steps']} steps ({end:.2f} s simulated) of cases/verification/bed_expansion in {wall:.0f} s "
          f"(the first {first['steps']}, then resumed)")
    print(f"  largest fluidised share {fluid:.2f}; bed height {f(first_row, 'bed_height') * 1e3:.1f} -> {f(last, 'bed_height') * 1e3:.1f} mm")
    print(f"  solid mass drift {solid_drift:.1e} (limit 1e-12), liquid mass drift {liquid_drift:.1e} (limit 1e-12)")
    print(f"  largest ledger residual {ledger:.1e} of the inflow (limit 1e-6)")
    print(f"  resident memory {rss_start / 1024:.1f} MiB after 10 % of the resumed run, {rss_end / 1024:.1f} MiB at the end")
    failures = []
    if solid_drift > 1e-12: failures.append("solid mass")
    if liquid_drift > 1e-12: failures.append("liquid mass")
    if ledger > 1e-6: failures.append("ledger")
    if rss_end > max(1.1 * rss_start, rss_start + 2048): failures.append("memory grows")
    if failures:
        sys.exit("soak: FAILED: " + ", ".join(failures))
    print("soak: passed")


if __name__ == "__main__":
    main()
