"""Plot vertical profiles at one output time: OUTPUT_DIR/fields.h5 -> OUTPUT_DIR/profiles.png.

Usage:
    .venv/bin/python tools/plot_profiles.py OUTPUT_DIR [--step N] [--out FILE.png]
    quicksand.plots.profiles.plot(OUTPUT_DIR, step=None) -> (path, figure)

Three panels against elevation z (the last coordinate; fields.h5 stores positions as XYZ with
the vertical in Z whatever the grid dimension):
  1. pore pressure of the liquid points (liquid/pore_pressure, Pa gauge, compression positive)
  2. vertical effective stress of the solid points, shown compression positive:
     sigma'_v = -solid/effective_stress[:, 2] (zz of the Voigt order xx, yy, zz, yz, xz, xy;
     quicksand's stresses are tension positive)
  3. porosity of the solid points (solid/porosity, -)
By default the last step in the file; --step picks another (0-based, as in step_000000).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display on build machines or CI
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..results import read_fields  # noqa: E402

VERTICAL_STRESS = 2  # index of zz in the Voigt order xx, yy, zz, yz, xz, xy


def read_set(step, name, fields):
    """Returns (z, {field: array}) for point set `name` of an output (Fields.step); a missing set
    or field comes back as None."""
    if name not in step or "positions" not in step[name]:
        return None, {}
    group = step[name]
    positions = np.asarray(group["positions"], dtype=float).reshape(-1, 3)
    values = {field: np.asarray(group[field], dtype=float) if field in group else None for field in fields}
    return positions[:, -1], values


def note_missing(ax, what):
    ax.text(0.5, 0.5, f"no {what}", transform=ax.transAxes, ha="center", va="center", color="0.5")


def plot(output_dir, step=None, out=None):
    """Draws output `step` (default: the last) of OUTPUT_DIR/fields.h5 into `out` (default
    OUTPUT_DIR/profiles.png); returns the path and the figure. Raises OSError or ValueError for a
    file that cannot be read or lacks the step."""
    source = os.path.join(output_dir, "fields.h5")
    target = out or os.path.join(output_dir, "profiles.png")
    fields = read_fields(source)
    if len(fields) == 0:
        raise ValueError(f"{source}: no output step yet")
    if step is not None and not 0 <= step < len(fields):
        raise ValueError(f"{source}: no step_{step:06d} (have step_000000 .. step_{len(fields) - 1:06d})")
    k = len(fields) - 1 if step is None else step
    output = fields.step(k)
    step_name, time = f"step_{k:06d}", output["time"]
    z_liquid, liquid = read_set(output, "liquid", ["pore_pressure"])
    z_solid, solid = read_set(output, "solid", ["effective_stress", "porosity"])

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
    fig.suptitle(f"{os.path.abspath(output_dir)}: {step_name}, t = {time:.6g} s", fontsize="medium")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target, fig


def main(argv=None):
    parser = argparse.ArgumentParser(prog="plot_profiles.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("output_dir", help="a quicksand output directory holding fields.h5")
    parser.add_argument("--step", type=int, help="step index (default: the last one)")
    parser.add_argument("--out", help="PNG to write (default OUTPUT_DIR/profiles.png)")
    args = parser.parse_args(argv)
    try:
        target, _ = plot(args.output_dir, args.step, args.out)
    except (OSError, ValueError, KeyError) as error:
        print(f"plot_profiles: {error}", file=sys.stderr)
        return 1
    print(target)
    return 0


if __name__ == "__main__":
    sys.exit(main())
