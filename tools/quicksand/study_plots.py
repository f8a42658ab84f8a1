"""The study's plots, in STUDY/output/ (tools/study.py draws them after the runs):

  study_series.png   head above the tailwater, filter velocity (gate flux / A_s) and bed height
                     against time, every variant overlaid and labelled; beside the head, each
                     variant's closed forms for a fixed bed (quicksand/hydraulics.head_decay): the
                     laminar line's exponential (dotted) and the ODE with the line's own wall
                     friction (Churchill's smooth pipe, Blasius' within 3 % when turbulent) and
                     its minor losses (dashed)
  study_figures.png  each figure of study.csv against each parameter: one row per figure, one
                     column per parameter, points joined along that parameter and coloured by
                     the others' values
"""
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import hydraulics  # noqa: E402
from . import figures as study_figures  # noqa: E402
from . import results  # noqa: E402

# the figures worth a panel, with how to label them
PLOTTED = [("onset_time_s", "onset time (s)"), ("onset_gradient", "onset gradient (-)"),
           ("peak_filter_velocity_ms", "peak filter velocity (m/s)"), ("peak_expansion", "peak expansion (-)"),
           ("fluidised_duration_s", "time fluidised (s)"), ("resettled_height_m", "resettled height (m)"),
           ("sand_carried_out_kg", "sand carried out (kg)"), ("head_tau_s", "head decay tau (s)"),
           ("head_exponent", "head decay exponent n (-)")]


def label(variant, keys):
    return ", ".join(f"{study_figure_key(k)} = {format_param(variant['params'][k])}" for k in keys)


def format_param(v):
    return f"{v:.4g}" if isinstance(v, float) else str(v)


def study_figure_key(key):
    return key.split(".")[-1]


def plot_series(study):
    fig, axes = plt.subplots(3, 1, figsize=(10, 11), sharex=True)
    colours = plt.cm.viridis(np.linspace(0, 0.9, max(1, len(study.variants))))
    drawn = 0
    for v, colour in zip(study.variants, colours):
        path = os.path.join(v["out"], "series.csv")
        if not os.path.isfile(path):
            continue
        s = study_figures.read_series(path)
        if not s:
            continue
        case = study_figures.read_case(v["out"])
        column = case["column"]
        tail = column.get("overflow_level", column.get("water_level"))
        t = s["time"]
        name = label(v, study.keys)
        axes[0].plot(t, s["reservoir_head"] - tail, color=colour, label=name)
        closed = hydraulics.head_decay(case, study.base, t)
        if closed is not None:
            _, laminar, turbulent, _ = closed
            axes[0].plot(t, laminar, ":", color=colour, lw=1)
            axes[0].plot(t, turbulent, "--", color=colour, lw=1)
        axes[1].plot(t, s["gate_flux"] / case["grid"]["cross_section_area"] * 1e3, color=colour, label=name)
        axes[2].plot(t, s["bed_height"] * 1e3, color=colour, label=name)
        drawn += 1
    axes[0].set_ylabel("head above the tailwater (m)")
    axes[0].set_title("runs (solid); fixed-bed closed forms: laminar line (dotted), wall friction + minor losses (dashed)",
                      fontsize=9)
    axes[1].set_ylabel("filter velocity Q / A_s (mm/s)")
    axes[2].set_ylabel("bed height (mm)")
    axes[2].set_xlabel("time (s)")
    for ax in axes:
        ax.grid(alpha=0.3)
    if drawn:
        axes[2].legend(fontsize=7, loc="best")
    fig.suptitle(f"study of {os.path.relpath(study.base, study.dir)}: {drawn} of {len(study.variants)} variants")
    return save(fig, study, "study_series.png", 110)


def save(fig, study, name, dpi):
    """Writes the figure to STUDY/output/NAME; returns its path and the figure (closed: its axes
    keep what was drawn)."""
    fig.tight_layout()
    out = os.path.join(study.output, name)
    fig.savefig(out, dpi=dpi)
    plt.close(fig)
    return out, fig


def number(value):
    """A cell as a float, None where it is empty or not a number."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        return None
    return None if math.isnan(x) else x


def plot_figures(study):
    rows = results.read_study(study.output).to_dict("records")
    shown = [(k, name) for k, name in PLOTTED if any(number(r[k]) is not None for r in rows)]
    numeric = [k for k in study.keys if all(number(r[k]) is not None for r in rows)]
    if not shown or not numeric:
        return None
    fig, axes = plt.subplots(len(shown), len(numeric), figsize=(4.2 * len(numeric), 2.4 * len(shown)), squeeze=False)
    for j, key in enumerate(numeric):
        others = [k for k in study.keys if k != key]
        groups = {}
        for r in rows:
            groups.setdefault(tuple(r[k] for k in others), []).append(r)
        colours = plt.cm.plasma(np.linspace(0, 0.85, max(1, len(groups))))
        for (group, members), colour in zip(groups.items(), colours):
            members.sort(key=lambda r: number(r[key]))
            x = [number(r[key]) for r in members]
            name = ", ".join(f"{study_figure_key(k)} = {g}" for k, g in zip(others, group)) or None
            for i, (fkey, _) in enumerate(shown):
                y = [number(r[fkey]) for r in members]
                pts = [(a, b) for a, b in zip(x, y) if b is not None]
                if pts:
                    axes[i][j].plot(*zip(*pts), "o-", color=colour, label=name, ms=4)
        for i, (_, fname) in enumerate(shown):
            axes[i][j].set_ylabel(fname if j == 0 else "")
            axes[i][j].grid(alpha=0.3)
            if i == len(shown) - 1:
                axes[i][j].set_xlabel(key)
            if i == 0 and others:
                axes[i][j].legend(fontsize=6)
        for i, (fkey, fname) in enumerate(shown):
            if j > 0:
                axes[i][j].set_title(fname, fontsize=8)
    fig.suptitle("study.csv: each figure against each parameter")
    return save(fig, study, "study_figures.png", 100)


def plot_study(study):
    """Both plots of a study; returns their paths."""
    return [drawn[0] for drawn in (plot_series(study), plot_figures(study)) if drawn]
