#!/usr/bin/env python3
"""The statistics of piping ensembles: one random bed over many seeds, grouped by the porosity
field's standard deviation and correlation length and by the reservoir's head (docs/piping.md,
"Ensembles").

  python3 tools/piping_ensemble.py STUDY/output [STUDY2/output ...] [--out DIR]

Reads each study's study.csv (tools/study.py; the pipe figures of tools/study_figures.py) and
each variant's case.effective.toml (for the field's statistics, whether varied or not), and writes
to --out (default: the first study's output directory):

  piping_ensemble.csv   per (standard deviation, correlation length, reservoir head): runs, runs that piped, the
                        gradient at the first pipe (mean, standard deviation, least, largest), its
                        time (mean), the share of first pipes at a wall, the share of piped outputs
                        whose main pipe is at a wall, and the largest flux share of one pipe (mean)
  piping_ensemble.png   the first-pipe gradient of every run by group (wall pipes red, interior
                        blue), the share at a wall, and the first pipe's time

Needs Debian's python3-matplotlib and python3-numpy.
"""
import argparse
import csv
import os
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import quicksand as qs  # noqa: E402


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def read_runs(output_dir):
    path = os.path.join(output_dir, "study.csv")
    if not os.path.isfile(path):
        sys.exit(f"piping_ensemble.py: no {path} (run tools/study.py on the study first)")
    runs = []
    for row in qs.read_study(path).to_dict("records"):
        if row.get("status") != "finished":
            continue
        case_file = os.path.join(output_dir, row["variant"], "case.effective.toml")
        with open(case_file, "rb") as c:
            case = tomllib.load(c)
        field = case.get("initial", {}).get("porosity_field", {})
        runs.append({"sigma": float(field.get("standard_deviation", 0.0)),
                     "length": float(field.get("correlation_length", 0.0)),
                     "seed": int(field.get("seed", 1)),
                     "head": float(case.get("reservoir", {}).get("head", float("nan"))),
                     "gradient": number(row.get("first_pipe_gradient")),
                     "time": number(row.get("first_pipe_time_s")),
                     "wall": number(row.get("first_pipe_wall")),
                     "wall_share": number(row.get("wall_pipe_share")),
                     "flux_share": number(row.get("max_pipe_flux_share"))})
    return runs


def summarise(runs):
    groups = {}
    for r in runs:
        groups.setdefault((r["sigma"], r["length"], r["head"]), []).append(r)
    rows = []
    for (sigma, length, head), rs in sorted(groups.items()):
        piped = [r for r in rs if np.isfinite(r["gradient"])]
        g = np.array([r["gradient"] for r in piped])
        rows.append({"standard_deviation": sigma, "correlation_length_m": length, "reservoir_head_m": head,
                     "runs": len(rs),
                     "piped": len(piped),
                     "first_pipe_gradient_mean": g.mean() if len(g) else np.nan,
                     "first_pipe_gradient_std": g.std(ddof=1) if len(g) > 1 else np.nan,
                     "first_pipe_gradient_min": g.min() if len(g) else np.nan,
                     "first_pipe_gradient_max": g.max() if len(g) else np.nan,
                     "first_pipe_time_mean_s": np.mean([r["time"] for r in piped]) if piped else np.nan,
                     "first_pipe_at_wall_share": np.mean([r["wall"] for r in piped]) if piped else np.nan,
                     "main_pipe_at_wall_share": np.nanmean([r["wall_share"] for r in piped]) if piped else np.nan,
                     "largest_pipe_flux_share_mean": np.nanmean([r["flux_share"] for r in piped]) if piped else np.nan,
                     "_runs": rs})
    return rows


def write_csv(path, rows):
    keys = [k for k in rows[0] if not k.startswith("_")]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([f"{r[k]:.6g}" if isinstance(r[k], float) else r[k] for k in keys])


def plot(path, rows):
    heads = {r["reservoir_head_m"] for r in rows}
    labels = [f"sd {r['standard_deviation']:g}\nl {r['correlation_length_m'] * 1e3:g} mm"
              + (f"\nhead {r['reservoir_head_m']:.4g} m" if len(heads) > 1 else "") for r in rows]
    x = np.arange(len(rows))
    fig, ax = plt.subplots(3, 1, figsize=(max(6, 1.3 * len(rows) + 2), 9), sharex=True)
    for k, r in enumerate(rows):
        for run in r["_runs"]:
            if not np.isfinite(run["gradient"]):
                continue
            jitter = (run["seed"] % 7 - 3) * 0.04
            ax[0].plot(k + jitter, run["gradient"], "o", ms=4, color="tab:red" if run["wall"] == 1 else "tab:blue")
        if r["piped"]:
            ax[0].errorbar(k + 0.3, r["first_pipe_gradient_mean"], yerr=np.nan_to_num(r["first_pipe_gradient_std"]),
                           fmt="s", color="black", ms=5, capsize=3)
        ax[2].plot(k, r["first_pipe_time_mean_s"], "s", color="black")
    ax[0].set_ylabel("bed gradient at the first pipe")
    ax[0].plot([], [], "o", color="tab:red", label="first pipe at a wall")
    ax[0].plot([], [], "o", color="tab:blue", label="first pipe in the interior")
    ax[0].plot([], [], "s", color="black", label="mean +- 1 sd")
    ax[0].legend(fontsize=8)
    ax[1].bar(x - 0.2, [r["first_pipe_at_wall_share"] for r in rows], 0.4, label="first pipe at a wall")
    ax[1].bar(x + 0.2, [r["main_pipe_at_wall_share"] for r in rows], 0.4, label="main pipe at a wall, all outputs")
    ax[1].set_ylim(0, 1.05)
    ax[1].set_ylabel("share")
    ax[1].legend(fontsize=8)
    ax[2].set_ylabel("first pipe, mean time (s)")
    ax[2].set_xticks(x)
    ax[2].set_xticklabels(labels, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outputs", nargs="+", help="the studies' output directories")
    ap.add_argument("--out", help="where to write (default: the first output directory)")
    args = ap.parse_args()
    runs = [r for d in args.outputs for r in read_runs(d)]
    if not runs:
        sys.exit("piping_ensemble.py: no finished runs")
    rows = summarise(runs)
    out = args.out or args.outputs[0]
    write_csv(os.path.join(out, "piping_ensemble.csv"), rows)
    plot(os.path.join(out, "piping_ensemble.png"), rows)
    for r in rows:
        print(f"sd {r['standard_deviation']:g}, l {r['correlation_length_m'] * 1e3:g} mm, head {r['reservoir_head_m']:.5g} m: "
              f"{r['piped']}/{r['runs']} piped, "
              f"first-pipe gradient {r['first_pipe_gradient_mean']:.4f} +- {r['first_pipe_gradient_std']:.4f} "
              f"[{r['first_pipe_gradient_min']:.4f}, {r['first_pipe_gradient_max']:.4f}] at "
              f"{r['first_pipe_time_mean_s']:.2f} s; at a wall: first {r['first_pipe_at_wall_share']:.2f}, "
              f"main {r['main_pipe_at_wall_share']:.2f}")
    print(f"piping_ensemble.py: wrote {os.path.join(out, 'piping_ensemble.csv')} and piping_ensemble.png")


if __name__ == "__main__":
    main()
