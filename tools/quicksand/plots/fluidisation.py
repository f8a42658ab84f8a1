"""Plots how a column fluidises, from a run's output directory (series.csv and fields.h5):

  fluidisation.png, four panels:
    1. bed height against time (bed_height);
    2. filter velocity against time (gate flux / cross-section, and each monitor's q), with the
       analytic lines: --analytic-q (m/s) if given; for a pressure gate, the quasi-steady
       Darcy-Forchheimer filter velocity of the fixed bed for the reservoir's head at each time
       (through the tube, if any), and for a fluidised bed the tube's share of the head,
       q = (h - h_tail - i_c H) / (R_t A_s) (the bed takes i_c H whatever the flux);
    3. a space-time image of the solid points' porosity along the column (cell-row means), with
       the fluidised region outlined (rows where most of the solid mass is fluidised);
    4. the fluidised front (fluidised_front) against time, with its linear fit over the window
       where it moves (--fit-from, --fit-to, s) and the fit's speed and r^2.

  front_fit.csv: the fit (speed m/s, intercept m, r2, window) for scripts and docs.

Usage:
  .venv/bin/python tools/plot_fluidisation.py CASE/output [--analytic-q 1.38e-3] [--fit-from T0] [--fit-to T1]
      [--title TEXT]

Needs Debian's python3-matplotlib, python3-numpy and python3-h5py (tools/setup.sh installs them).
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .. import results as qs  # noqa: E402
from ..hydraulics import analytic_lines  # noqa: E402


def read_series(path):
    s = qs.read_series(path)
    if s.empty:
        sys.exit(f"plot_fluidisation.py: {path} has no rows")
    return qs.arrays(s)


def read_space_time(path, cell):
    """Cell-row means of solid porosity and the fluidised share of each row, per output time."""
    with h5py.File(path, "r") as h:
        steps = sorted(k for k in h.keys() if k.startswith("step_"))
        times, columns = [], []
        zmax = 0.0
        for k in steps:
            g = h[k]
            if "solid" not in g or g["solid"]["positions"].shape[0] == 0:
                continue
            zmax = max(zmax, float(np.max(g["solid"]["positions"][:, 2])))
        rows = int(np.ceil(zmax / cell)) + 1
        for k in steps:
            g = h[k]
            if "solid" not in g or g["solid"]["positions"].shape[0] == 0:
                continue
            z = g["solid"]["positions"][:, 2]
            n = g["solid"]["porosity"][:]
            st = g["solid"]["state"][:]
            r = np.clip((z / cell).astype(int), 0, rows - 1)
            count = np.bincount(r, minlength=rows)
            por = np.bincount(r, weights=n, minlength=rows)
            fl = np.bincount(r, weights=(st > 0).astype(float), minlength=rows)
            with np.errstate(invalid="ignore", divide="ignore"):
                columns.append((np.where(count > 0, por / count, np.nan), np.where(count > 0, fl / count, np.nan)))
            times.append(float(g.attrs["time"]))
    return np.array(times), rows, columns


def linear_fit(t, y):
    b, a = np.polyfit(t, y, 1)
    pred = a + b * t
    ss = float(np.sum((y - np.mean(y)) ** 2))
    r2 = 1 - float(np.sum((y - pred) ** 2)) / ss if ss > 0 else 0.0
    return b, a, r2


def plot(argv=None):
    """Draws as the command does with `argv` (the output directory first); returns the figure."""
    p = argparse.ArgumentParser(prog="plot_fluidisation.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output", help="a run's output directory (series.csv, fields.h5)")
    p.add_argument("--analytic-q", type=float, default=None, help="analytic filter velocity, m/s")
    p.add_argument("--fit-from", type=float, default=None, help="start of the front fit window, s")
    p.add_argument("--fit-to", type=float, default=None, help="end of the front fit window, s")
    p.add_argument("--cell", type=float, default=None, help="cell size, m (default: from case.toml)")
    p.add_argument("--area", type=float, default=None, help="cross-section, m2 (default: from case.toml)")
    p.add_argument("--title", default=None)
    a = p.parse_args(argv)

    series_path = os.path.join(a.output, "series.csv")
    fields_path = os.path.join(a.output, "fields.h5")
    if not os.path.isfile(series_path):
        sys.exit(f"plot_fluidisation.py: no series.csv in {a.output}")
    s = read_series(series_path)
    t = s["time"]

    cell, area, title = a.cell, a.area, a.title
    case = None
    case_toml = os.path.join(os.path.dirname(os.path.abspath(a.output)), "case.toml")
    if os.path.isfile(case_toml):
        try:
            import tomllib  # Python 3.11

            with open(case_toml, "rb") as f:
                case = tomllib.load(f)
            cell = cell or case["grid"]["cell_size"]
            area = area or case["grid"].get("cross_section_area")
            title = title or case.get("title")
        except Exception:  # a plot should not fail on a case it cannot read
            pass
    if cell is None:
        sys.exit("plot_fluidisation.py: give --cell (no readable case.toml beside the output)")

    fig, ax = plt.subplots(2, 2, figsize=(13, 8.5))
    if title:
        fig.suptitle(title)

    # 1 bed height
    ax[0, 0].plot(t, 1000 * s["bed_height"], color="tab:brown")
    ax[0, 0].set_xlabel("time (s)")
    ax[0, 0].set_ylabel("bed height (mm)")
    ax[0, 0].set_title("bed height above the filter")
    ax[0, 0].grid(alpha=0.3)

    # 2 filter velocity
    if area:
        ax[0, 1].plot(t, s["gate_flux"] / area, color="tab:blue", label="gate flux / area")
    for k in s:
        if k.startswith("q_"):
            ax[0, 1].plot(t, s[k], lw=0.8, label=f"q at monitor {k[2:]}")
    if a.analytic_q is not None:
        ax[0, 1].axhline(a.analytic_q, color="k", ls="--", label=f"analytic {a.analytic_q:.4g} m/s")
    elif case is not None and "reservoir_head" in s:
        lines = analytic_lines(case, os.path.dirname(case_toml), t, s["reservoir_head"])
        if lines is not None:
            fixed, fluid = lines
            ax[0, 1].plot(t, fixed, "k--", lw=1, label="Darcy-Forchheimer, fixed bed, for the head")
            if fluid is not None:
                ok = fluid > fixed
                ax[0, 1].plot(t[ok], fluid[ok], "k:", lw=1.2, label="fluidised bed: tube takes (h - i_c H)")
    ax[0, 1].set_xlabel("time (s)")
    ax[0, 1].set_ylabel("filter velocity (m/s)")
    ax[0, 1].set_title("filter velocity")
    ax[0, 1].legend(fontsize=8)
    ax[0, 1].grid(alpha=0.3)

    # 3 space-time porosity
    if os.path.isfile(fields_path):
        times, rows, columns = read_space_time(fields_path, cell)
        if len(times) > 1:
            por = np.array([c[0] for c in columns]).T
            fl = np.array([c[1] for c in columns]).T
            z = (np.arange(rows) + 0.5) * cell
            im = ax[1, 0].pcolormesh(times, 1000 * z, por, shading="nearest", cmap="viridis", vmin=0.35, vmax=0.55)
            fig.colorbar(im, ax=ax[1, 0], label="porosity (row mean of solid points)")
            if np.nanmax(fl) > 0.5:
                ax[1, 0].contour(times, 1000 * z, np.nan_to_num(fl), levels=[0.5], colors="red", linewidths=1.2)
                ax[1, 0].plot([], [], color="red", label="fluidised region (outline)")
                ax[1, 0].legend(fontsize=8, loc="lower right")
            else:
                ax[1, 0].text(0.5, 0.03, "no sand fluidised", ha="center", transform=ax[1, 0].transAxes)
    else:
        ax[1, 0].text(0.5, 0.5, "no fields.h5", ha="center", transform=ax[1, 0].transAxes)
    ax[1, 0].set_xlabel("time (s)")
    ax[1, 0].set_ylabel("elevation (mm)")
    ax[1, 0].set_title("porosity along the column")

    # 4 front with fit
    front = s["fluidised_front"]
    ax[1, 1].plot(t, 1000 * front, color="tab:red", label="fluidised front")
    if np.max(s["fluidised_share"]) == 0:
        ax[1, 1].text(0.5, 0.5, "no sand fluidised: no front", ha="center", transform=ax[1, 1].transAxes)
        a.fit_from = a.fit_to = -1.0
    t0 = a.fit_from if a.fit_from is not None else t[0]
    t1 = a.fit_to if a.fit_to is not None else t[-1]
    if a.fit_from is None and a.fit_to is None and np.max(s["fluidised_share"]) > 0:
        # by default, while the front climbs: from its first rise to its highest point
        moving = np.nonzero(s["fluidised_share"] > 0)[0]
        k0 = moving[0]
        k1 = k0 + int(np.argmax(front[k0:]))
        t0, t1 = t[k0], t[max(k0, k1 - 1)]
    sel = (t >= t0) & (t <= t1)
    fit_row = None
    if np.count_nonzero(sel) >= 3:
        b, c, r2 = linear_fit(t[sel], front[sel])
        ax[1, 1].plot(t[sel], 1000 * (c + b * t[sel]), "k--", label=f"fit: {1000 * b:.3f} mm/s, r$^2$ = {r2:.3f}")
        fit_row = (b, c, r2, t0, t1)
    ax[1, 1].set_xlabel("time (s)")
    ax[1, 1].set_ylabel("elevation (mm)")
    ax[1, 1].set_title("fluidised front")
    ax[1, 1].legend(fontsize=8)
    ax[1, 1].grid(alpha=0.3)

    fig.tight_layout()
    out = os.path.join(a.output, "fluidisation.png")
    fig.savefig(out, dpi=110)
    print(out)
    if fit_row:
        with open(os.path.join(a.output, "front_fit.csv"), "w") as f:
            f.write("speed,intercept,r2,fit_from,fit_to\n")
            f.write(",".join(f"{v:.6g}" for v in fit_row) + "\n")
    plt.close(fig)
    return fig


def main(argv=None):
    plot(argv)
    return 0


if __name__ == "__main__":
    main()
