"""Plot a quicksand run's time series: OUTPUT_DIR/series.csv -> OUTPUT_DIR/series.png.

Usage:
    .venv/bin/python tools/plot_series.py OUTPUT_DIR [--out FILE.png]
    quicksand.plots.series.plot(OUTPUT_DIR) -> (path, figure)

Panels (each skipped gracefully, with a note, when its columns are missing):
  1. filter velocity q at every monitor (columns q_<monitor>, m/s in the file; shown in mm/s)
  2. gate pressure (gate_pressure, Pa gauge; shown in kPa) and reservoir head (reservoir_head, m)
  3. sand surface elevation (sand_surface, m)
  4. cumulative inflow and outflow volume (cumulative_inflow, cumulative_outflow, m3; shown in L)

"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display on build machines or CI
import matplotlib.pyplot as plt  # noqa: E402  (must follow the backend choice)

from ..results import arrays, read_series as qs_read_series  # noqa: E402


def read_series(path):
    """Returns {column: float array} (quicksand.results: short lines dropped, words as NaN)."""
    return arrays(qs_read_series(path))


def note_missing(ax, what):
    ax.text(0.5, 0.5, f"no {what} in series.csv", transform=ax.transAxes, ha="center", va="center",
            color="0.5")


def plot_filter_velocity(ax, t, s):
    monitors = sorted(name for name in s if name.startswith("q_"))
    for name in monitors:
        ax.plot(t, s[name] * 1e3, label=name[2:])  # m/s -> mm/s
    if monitors:
        ax.axhline(0.0, color="0.7", linewidth=0.8)
        ax.legend(title="monitor", fontsize="small")
    else:
        note_missing(ax, "q_<monitor> columns")
    ax.set_ylabel("filter velocity q (mm/s)")
    ax.set_title("Filter velocity at monitors")


def plot_gate(ax, t, s):
    drawn = []
    if "gate_pressure" in s:
        drawn += ax.plot(t, s["gate_pressure"] / 1e3, color="tab:red", label="gate pressure")  # Pa -> kPa
        ax.set_ylabel("gate pressure (kPa, gauge)", color="tab:red")
    if "reservoir_head" in s:
        # A second axis: a head in m and a pressure in kPa share no scale.
        head_axis = ax.twinx() if "gate_pressure" in s else ax
        drawn += head_axis.plot(t, s["reservoir_head"], color="tab:blue", linestyle="--",
                                label="reservoir head")
        head_axis.set_ylabel("reservoir head above gate (m)", color="tab:blue")
    if drawn:
        ax.legend(drawn, [line.get_label() for line in drawn], fontsize="small")
    else:
        note_missing(ax, "gate_pressure or reservoir_head")
    ax.set_title("Gate pressure and reservoir head")


def plot_sand_surface(ax, t, s):
    if "sand_surface" in s:
        ax.plot(t, s["sand_surface"], color="tab:brown")
    else:
        note_missing(ax, "sand_surface")
    ax.set_ylabel("sand surface elevation (m)")
    ax.set_title("Sand surface")


def plot_cumulative_volume(ax, t, s):
    drawn = False
    for name, label in (("cumulative_inflow", "inflow"), ("cumulative_outflow", "outflow")):
        if name in s:
            ax.plot(t, s[name] * 1e3, label=label)  # m3 -> L
            drawn = True
    if drawn:
        ax.legend(fontsize="small")
    else:
        note_missing(ax, "cumulative_inflow or cumulative_outflow")
    ax.set_ylabel("cumulative volume (L)")
    ax.set_title("Cumulative inflow and outflow")


def plot(output_dir, out=None):
    """Draws OUTPUT_DIR/series.csv into `out` (default OUTPUT_DIR/series.png); returns the path and
    the figure (closed: its axes keep what was drawn). Raises OSError or ValueError for a series
    that cannot be read or has no time column."""
    source = os.path.join(output_dir, "series.csv")
    target = out or os.path.join(output_dir, "series.png")
    s = read_series(source)
    if "time" not in s:
        raise ValueError(f"{source}: no 'time' column")
    t = s["time"]

    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True, constrained_layout=True)
    plot_filter_velocity(axes[0, 0], t, s)
    plot_gate(axes[0, 1], t, s)
    plot_sand_surface(axes[1, 0], t, s)
    plot_cumulative_volume(axes[1, 1], t, s)
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    for ax in axes[1, :]:
        ax.set_xlabel("time (s)")
    fig.suptitle(f"{os.path.abspath(output_dir)}  ({len(t)} output times)", fontsize="medium")
    fig.savefig(target, dpi=120)
    plt.close(fig)
    return target, fig


def main(argv=None):
    parser = argparse.ArgumentParser(prog="plot_series.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("output_dir", help="a quicksand output directory holding series.csv")
    parser.add_argument("--out", help="PNG to write (default OUTPUT_DIR/series.png)")
    args = parser.parse_args(argv)
    try:
        target, _ = plot(args.output_dir, args.out)
    except (OSError, ValueError) as error:
        print(f"plot_series: {error}", file=sys.stderr)
        return 1
    print(target)
    return 0
