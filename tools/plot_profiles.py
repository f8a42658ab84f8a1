#!/usr/bin/python3
"""Plot vertical profiles at one output time: OUTPUT_DIR/fields.h5 -> OUTPUT_DIR/profiles.png.

Usage:
    tools/plot_profiles.py OUTPUT_DIR [--step N] [--out FILE.png]

Three panels against elevation z (the last coordinate; fields.h5 stores positions as XYZ with
the vertical in Z whatever the grid dimension):
  1. pore pressure of the liquid points (liquid/pore_pressure, Pa gauge, compression positive)
  2. vertical effective stress of the solid points, shown compression positive:
     sigma'_v = -solid/effective_stress[:, 2] (zz of the Voigt order xx, yy, zz, yz, xz, xy;
     quicksand's stresses are tension positive)
  3. porosity of the solid points (solid/porosity, -)
By default the last step in the file; --step picks another (0-based, as in step_000000).

The shebang is /usr/bin/python3 on purpose: Debian's python3-matplotlib, numpy and h5py live
there, not in the pyenv python3 that may come first on PATH.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display on build machines or CI
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

VERTICAL_STRESS = 2  # index of zz in the Voigt order xx, yy, zz, yz, xz, xy


def read_set(step, name, fields):
    """Returns (z, {field: array}) for point set `name` of an HDF5 step group; missing set or
    fields come back as None."""
    if name not in step or "positions" not in step[name]:
        return None, {}
    group = step[name]
    positions = np.asarray(group["positions"][...], dtype=float).reshape(-1, 3)
    values = {}
    for field in fields:
        values[field] = np.asarray(group[field][...], dtype=float) if field in group else None
    return positions[:, -1], values


def note_missing(ax, what):
    ax.text(0.5, 0.5, f"no {what}", transform=ax.transAxes, ha="center", va="center", color="0.5")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output_dir", help="a quicksand output directory holding fields.h5")
    parser.add_argument("--step", type=int, help="step index (default: the last one)")
    parser.add_argument("--out", help="PNG to write (default OUTPUT_DIR/profiles.png)")
    args = parser.parse_args(argv)

    source = os.path.join(args.output_dir, "fields.h5")
    target = args.out or os.path.join(args.output_dir, "profiles.png")
    try:
        h5 = h5py.File(source, "r")
    except OSError as error:
        print(f"plot_profiles: {source}: cannot open ({error})", file=sys.stderr)
        return 1
    with h5:
        steps = sorted(name for name in h5 if name.startswith("step_"))
        if not steps:
            print(f"plot_profiles: {source}: no output step yet", file=sys.stderr)
            return 1
        if args.step is None:
            step_name = steps[-1]
        else:
            step_name = f"step_{args.step:06d}"
            if step_name not in h5:
                print(f"plot_profiles: {source}: no {step_name} (have {steps[0]} .. {steps[-1]})",
                      file=sys.stderr)
                return 1
        step = h5[step_name]
        time = float(step.attrs["time"]) if "time" in step.attrs else float("nan")
        z_liquid, liquid = read_set(step, "liquid", ["pore_pressure"])
        z_solid, solid = read_set(step, "solid", ["effective_stress", "porosity"])

    fig, axes = plt.subplots(1, 3, figsize=(13, 6), sharey=True, constrained_layout=True)
    marker = dict(s=8, linewidths=0)

    ax = axes[0]
    if z_liquid is not None and liquid["pore_pressure"] is not None:
        ax.scatter(liquid["pore_pressure"] / 1e3, z_liquid, color="tab:blue", **marker)  # Pa -> kPa
    else:
        note_missing(ax, "liquid/pore_pressure")
    ax.set_xlabel("pore pressure p (kPa, gauge)")
    ax.set_title("Pore pressure (liquid points)")

    ax = axes[1]
    stress = solid.get("effective_stress")
    if z_solid is not None and stress is not None and stress.ndim == 2 and stress.shape[1] == 6:
        ax.scatter(-stress[:, VERTICAL_STRESS] / 1e3, z_solid, color="tab:red", **marker)  # Pa -> kPa
    else:
        note_missing(ax, "solid/effective_stress (6 components)")
    ax.set_xlabel("vertical effective stress σ'_v = −σ'_zz (kPa, compression +)")
    ax.set_title("Vertical effective stress (solid points)")

    ax = axes[2]
    if z_solid is not None and solid.get("porosity") is not None:
        ax.scatter(solid["porosity"], z_solid, color="tab:brown", **marker)
    else:
        note_missing(ax, "solid/porosity")
    ax.set_xlabel("porosity n (-)")
    ax.set_title("Porosity (solid points)")

    axes[0].set_ylabel("elevation z (m)")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    fig.suptitle(f"{os.path.abspath(args.output_dir)}: {step_name}, t = {time:.6g} s", fontsize="medium")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
