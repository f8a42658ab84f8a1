"""How well a 2D or 3D run holds its sand's packing (issue 42, item 3), from its fields.h5:

  - the least porosity of any sand cell at each output, and how many cells lie below the sand's
    densest packing n_min (a sand cannot pack below it);
  - in sand that has resettled (solid now, fluidised at an earlier output), the rms of the cells'
    porosity about their 3 x 3 (x 3 in 3D) cell mean: the salt and pepper of single loose or dense
    cells among resettled sand. A resettled bed of a field with standard deviation 0.01 is not
    rougher than twice that.

Usage:
  .venv/bin/python tools/packing.py CASE/output --min-porosity 0.32 [--csv packing.csv]
  quicksand.packing.packing(CASE/output, min_porosity=0.32) -> pandas.DataFrame
"""
import argparse
import os
import sys

import numpy as np
import pandas as pd

from .plots.pipes import read_cells

UNITS = {"time": "s", "least_porosity": "-", "cells_below_min": "-", "resettled_cells": "-", "resettled_rms": "-"}


def local_mean(porosity):
    """Each cell's mean over its 3 x 3 (x 3) neighbourhood's sand cells (NaN where no sand)."""
    padded = np.pad(porosity, 1, constant_values=np.nan)
    shifts = []
    nz, ny, nx = porosity.shape
    for dz in (-1, 0, 1):
        for dy in ((-1, 0, 1) if ny > 1 else (0,)):
            for dx in (-1, 0, 1):
                shifts.append(padded[1 + dz:1 + dz + nz, 1 + dy:1 + dy + ny, 1 + dx:1 + dx + nx])
    stack = np.stack(shifts)
    count = np.sum(~np.isnan(stack), axis=0)
    total = np.nansum(stack, axis=0)
    return np.where(count > 0, total / np.maximum(count, 1), np.nan)


def packing_of_frames(frames, min_porosity):
    """The figures per frame (time, porosity[z][y][x], state[z][y][x]); state 0 no sand, 1 solid,
    2 fluidised. A cell has resettled once it is solid after having been fluidised."""
    rows = []
    was_fluidised = None
    for time, porosity, state in frames:
        sand = state > 0
        fluid = state == 2
        was_fluidised = fluid.copy() if was_fluidised is None else (was_fluidised | fluid)
        resettled = (state == 1) & was_fluidised & ~np.isnan(porosity)
        n = porosity[sand & ~np.isnan(porosity)]
        deviation = (porosity - local_mean(porosity))[resettled]
        rows.append({
            "time": time,
            "least_porosity": float(n.min()) if n.size else np.nan,
            "cells_below_min": int(np.sum(n < min_porosity - 1e-12)),
            "resettled_cells": int(resettled.sum()),
            "resettled_rms": float(np.sqrt(np.mean(deviation ** 2))) if deviation.size else np.nan,
        })
    table = pd.DataFrame(rows)
    table.attrs["units"] = dict(UNITS)
    return table


def packing(output, min_porosity):
    """The figures of a run's output directory (or its fields.h5), one row per output."""
    path = output if output.endswith(".h5") else os.path.join(output, "fields.h5")
    _, frames = read_cells(path)
    return packing_of_frames([(t, p, s) for t, p, s, _ in frames], min_porosity)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output", help="the run's output directory")
    ap.add_argument("--min-porosity", type=float, required=True, help="the sand's n_min (its materials' min_porosity)")
    ap.add_argument("--csv", help="write the table here too")
    args = ap.parse_args(argv)
    table = packing(args.output, args.min_porosity)
    if args.csv:
        table.to_csv(args.csv, index=False)
    with pd.option_context("display.max_rows", None, "display.width", 120):
        print(table.to_string(index=False, float_format=lambda v: f"{v:.4f}"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
