#!/usr/bin/env python3
"""One column in 1D, 2D axisymmetric and 3D, side by side (issue 7).

    /usr/bin/python3 tools/dimension_comparison.py                       # the Deltares column, 100 s
    /usr/bin/python3 tools/dimension_comparison.py --end 30 --geometries 1d,axisymmetric
    /usr/bin/python3 tools/dimension_comparison.py --case cases/paperSimulationB --across 2

Runs CASE (a 1D case.toml; default cases/deltaresColumnLumped, the main job with its lumped tube)
as it is, as an axisymmetric cylinder of `--across` cells' radius and as a 3D square column of
`--across` x `--across` cells, each in build/dimension_comparison/<geometry>/. The cylinder's
and the square's cross-sections differ from the 1D one (a radius must be a whole number of
cells), so the reservoir is scaled with the area: its plan area by A / A_1D and the tube's length
by A_1D / A. The tube's share of the loss and the reservoir's time scale then stay those of the 1D
column, and every quantity per unit area (the filter velocity, the bed height, the front) must
agree. Prints, per geometry, the largest differences from the 1D run over the run and the wall
time, writes them to build/dimension_comparison/comparison.csv and plots the three series to
docs/images/dimension_comparison.png (or --plot PATH).

The 1D, 2D and 3D columns are laterally uniform: the 2D and 3D runs must reproduce the 1D run,
and a lateral mode growing in them (fluidisation localising, the free water sloshing) shows as a
difference.
"""
import argparse
import csv
import math
import os
import shutil
import sys
import time
import tomllib

import quicksand as qs

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def read_series(path):
    return {k: list(v) for k, v in qs.arrays(qs.read_series(path)).items()}


def variant(config, geometry, across, end):
    """The overrides (--set) of `geometry`, the reservoir scaled with the cross-section, and the
    cross-section (m2)."""
    h = config["grid"]["cell_size"]
    area1d = config["grid"]["cross_section_area"]
    width = across * h
    overrides = {}
    if geometry == "1d":
        area = area1d
    else:
        axisymmetric = geometry == "axisymmetric"
        area = math.pi * width * width if axisymmetric else width * width
        overrides = {"grid.dimension": 2 if axisymmetric else 3, "grid.width": width, "grid.cross_section_area": area}
        if axisymmetric:
            overrides["grid.geometry"] = "axisymmetric"
    ratio = area / area1d
    res = config.get("reservoir", {})
    if "area" in res:
        overrides["reservoir.area"] = res["area"] * ratio
    if "tube_length" in res:
        overrides["reservoir.tube_length"] = res["tube_length"] / ratio
    if end is not None:
        overrides["time.end"] = end
    return overrides, area


def run(case_dir, geometry, across, end, quicksand, work):
    with open(os.path.join(case_dir, "case.toml"), "rb") as f:
        config = tomllib.load(f)
    overrides, area = variant(config, geometry, across, end)
    out = os.path.join(work, geometry)
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(case_dir, out, ignore=shutil.ignore_patterns("output", "output.previous"))
    t0 = time.time()
    print(f"{geometry}: running {out} ...", flush=True)
    failed = None
    try:
        qs.run(out, overrides, binary=quicksand)
    except qs.QuicksandError as e:  # keep what it wrote: where it stopped is part of the comparison
        failed = str(e).strip().splitlines()[-1] if str(e).strip() else f"exit {e.returncode}"
    wall = time.time() - t0
    s = read_series(os.path.join(out, "output"))
    s["failed"] = failed
    if failed:
        print(f"{geometry}: stopped at t = {s['time'][-1]:.2f} s: {failed}", flush=True)
    s["filter_velocity"] = [q / area for q in s["gate_flux"]]
    return s, wall, area


def largest_difference(a, b, key, after=0.0):
    n = min(len(a["time"]), len(b["time"]))
    return max((abs(a[key][k] - b[key][k]) for k in range(n) if a["time"][k] >= after), default=0.0)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--case", default=os.path.join(ROOT, "cases", "deltaresColumnLumped"))
    p.add_argument("--geometries", default="1d,axisymmetric,3d")
    p.add_argument("--across", type=int, default=4, help="cells across the radius / the square (3D: --across-3d)")
    p.add_argument("--across-3d", type=int, default=2)
    p.add_argument("--end", type=float, default=None, help="simulated time (s); default: the case's")
    p.add_argument("--build", default=os.environ.get("QUICKSAND_BUILD_DIR", os.path.join(ROOT, "build")))
    p.add_argument("--plot", default=os.path.join(ROOT, "docs", "images", "dimension_comparison.png"))
    a = p.parse_args()
    quicksand = os.path.join(a.build, "mpm", "quicksand")
    work = os.path.join(a.build, "dimension_comparison")
    os.makedirs(work, exist_ok=True)
    geometries = a.geometries.split(",")
    if geometries[0] != "1d":
        sys.exit("dimension_comparison.py: the first geometry must be 1d (the reference)")
    runs = {}
    for g in geometries:
        runs[g] = run(a.case, g, a.across_3d if g == "3d" else a.across, a.end, quicksand, work)

    ref, wall1d, _ = runs["1d"]
    H = ref["bed_height"][0]
    qmax = max(abs(q) for q in ref["filter_velocity"])
    rows = []
    print(f"\n{'geometry':14s} {'wall (s)':>9s} {'x 1D':>6s} {'filter velocity':>16s} {'bed height':>11s} {'front':>9s}")
    for g, (s, wall, area) in runs.items():
        dq = largest_difference(s, ref, "filter_velocity", after=1.0) / qmax
        dh = largest_difference(s, ref, "bed_height") / H
        df = largest_difference(s, ref, "fluidised_front") / H
        rows.append({"geometry": g, "wall_s": round(wall, 1), "cost_vs_1d": round(wall / wall1d, 2),
                     "cross_section_m2": area, "filter_velocity_diff": dq, "bed_height_diff": dh, "front_diff": df,
                     "end_s": s["time"][-1], "stopped": s["failed"] or ""})
        print(f"{g:14s} {wall:9.1f} {wall / wall1d:6.1f} {dq:16.2e} {dh:11.2e} {df:9.2e}"
              + (f"   (stopped at t = {s['time'][-1]:.2f} s)" if s["failed"] else ""))
    print("(largest differences from the 1D run over the run, as fractions: the filter velocity of its largest "
          "value, the bed height and the front of the bed's initial height)")
    with open(os.path.join(work, "comparison.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    style = {"1d": dict(color="k", lw=2.5), "axisymmetric": dict(color="tab:orange", lw=1.5, ls="--"),
             "3d": dict(color="tab:blue", lw=1.2, ls=":")}
    for g, (s, wall, area) in runs.items():
        label = f"{g} ({wall:.0f} s)" + (f", stopped at {s['time'][-1]:.1f} s" if s["failed"] else "")
        ax[0].plot(s["time"], [1000 * q for q in s["filter_velocity"]], label=label, **style.get(g, {}))
        ax[1].plot(s["time"], [1000 * b for b in s["bed_height"]], label=label, **style.get(g, {}))
        ax[2].plot(s["time"], [1000 * (f - ref["fluidised_front"][0]) for f in s["fluidised_front"]], label=label,
                   **style.get(g, {}))
    ax[0].set_ylabel("filter velocity at the gate (mm/s)")
    ax[1].set_ylabel("bed height (mm)")
    ax[2].set_ylabel("fluidised front above the filter (mm)")
    for x in ax:
        x.set_xlabel("time (s)")
        x.grid(alpha=0.3)
        x.legend()
    fig.suptitle(f"{os.path.basename(os.path.normpath(a.case))} in 1D, axisymmetric and 3D (reservoir scaled with the area)")
    fig.tight_layout()
    os.makedirs(os.path.dirname(a.plot), exist_ok=True)
    fig.savefig(a.plot, dpi=90)
    print(f"plot: {a.plot}")


if __name__ == "__main__":
    main()
