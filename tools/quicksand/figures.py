"""The figures a fluidisation engineer reads off one run, and the study's table of them.

  .venv/bin/python tools/study_figures.py CASE/output      print one run's figures

From a run's series.csv and case.effective.toml (docs/case-format.md):

  onset_time_s, onset_gradient   the first output with fluidised sand (fluidised_share > 0), and
                                 the hydraulic gradient there (series' gradient)
  peak_gate_flux_m3s             the largest gate flux; peak_filter_velocity_ms = it / A_s
  initial_bed_height_m, peak_bed_height_m, peak_expansion (peak / initial - 1), final_bed_height_m
  fluidised_duration_s           how long some sand is fluidised (the outputs' intervals)
  resettle_time_s                when the last fluidised sand resettles (empty: still fluidised at
                                 the end); resettled_height_m the bed's height then
  sand_carried_out_kg            grains carried over the overflow (cumulative_solid_outflow)
  head_tau_s, head_tau_r2        the head above the tailwater fitted as u0 exp(-t / tau) (a laminar
                                 line through a fixed bed: exact) over u from 0.95 u0 down to 0.05 u0
  head_exponent, head_exponent_r2  fitted as du/dt = -a u^n (a turbulent line: n = 4/7 with Blasius'
                                 friction alone; 1 for a laminar one), over the same range
and of a 2D or 3D run, from its pipes.csv (docs/piping.md):
  first_pipe_time_s, first_pipe_gradient  the first output with a pipe, and the bed's gradient there
  first_pipe_wall, first_pipe_x_m         whether that pipe touches a wall (1) or not (0), and its x
  pipe_time_share                         the share of the outputs from the first pipe on with a pipe
  wall_pipe_share                         of the outputs with a pipe, the share whose main pipe
                                          (most water) touches a wall
  max_pipes, max_pipe_flux_share          the most pipes at once, and the largest share of the
                                          water one pipe carried
A figure that does not apply (no fluidisation, a constant head; the head fits for a reservoir
with an area_table, whose decay is neither law) is left empty.
"""
import csv
import json
import math
import os
import sys

try:
    import tomllib
except ModuleNotFoundError:
    tomllib = None

import numpy as np

from . import results as qs

FIGURES = ["onset_time_s", "onset_gradient", "peak_gate_flux_m3s", "peak_filter_velocity_ms",
           "initial_bed_height_m", "peak_bed_height_m", "peak_expansion", "final_bed_height_m",
           "fluidised_duration_s", "resettle_time_s", "resettled_height_m", "sand_carried_out_kg",
           "head_tau_s", "head_tau_r2", "head_exponent", "head_exponent_r2",
           "first_pipe_time_s", "first_pipe_gradient", "first_pipe_wall", "first_pipe_x_m", "pipe_time_share",
           "wall_pipe_share", "max_pipes", "max_pipe_flux_share"]


def read_series(path):
    s = qs.read_series(path)
    return {} if s.empty else qs.arrays(s)


def read_case(output_dir):
    with open(os.path.join(output_dir, "case.effective.toml"), "rb") as f:
        return tomllib.load(f)


def fit_line(x, y):
    """slope, intercept, r^2 of a least-squares line"""
    slope, intercept = np.polyfit(x, y, 1)
    ss = float(np.sum((y - np.mean(y)) ** 2))
    r2 = 1 - float(np.sum((y - (intercept + slope * x)) ** 2)) / ss if ss > 0 else 1.0
    return float(slope), float(intercept), r2


def head_fits(t, head, tail):
    """(tau, r2, exponent, r2) of the head's fall above the tailwater; Nones if it does not fall."""
    u = head - tail
    if len(u) < 5 or u[0] <= 0 or np.ptp(head) < 1e-9:
        return None, None, None, None
    u0 = u[0]
    # the window starts where the head first falls below 0.95 u0 and ends where it first falls below 0.05
    below = np.nonzero(u <= 0.95 * u0)[0]
    if len(below) == 0:
        return None, None, None, None
    first = below[0]
    last = np.nonzero(u < 0.05 * u0)[0]
    last = last[0] if len(last) else len(u)
    window = np.zeros(len(u), bool)
    window[first:last] = True
    window &= u > 0
    if window.sum() < 4:
        return None, None, None, None
    slope, _, r2 = fit_line(t[window], np.log(u[window]))
    tau = -1 / slope if slope < 0 else None
    # du/dt by central differences on the window's inner points
    dudt = np.gradient(u, t)
    ok = window & (dudt < 0)
    if ok.sum() < 4:
        return tau, r2, None, None
    n, _, r2n = fit_line(np.log(u[ok]), np.log(-dudt[ok]))
    return tau, r2, n, r2n


def figures(output_dir):
    """One run's figures (a dict of FIGURES; missing ones are None)."""
    s = read_series(os.path.join(output_dir, "series.csv"))
    f = dict.fromkeys(FIGURES)
    if not s or len(s["time"]) == 0:
        return f
    case = read_case(output_dir)
    t = s["time"]
    area = case["grid"]["cross_section_area"]
    share = s.get("fluidised_share", np.zeros_like(t))
    fluid = share > 0
    if fluid.any():
        k = int(np.argmax(fluid))
        f["onset_time_s"] = float(t[k])
        f["onset_gradient"] = float(s["gradient"][k])
        dt = np.diff(t, append=t[-1])
        f["fluidised_duration_s"] = float(np.sum(dt[fluid]))
        lastFluid = int(np.nonzero(fluid)[0][-1])
        if lastFluid + 1 < len(t):
            f["resettle_time_s"] = float(t[lastFluid + 1])
            f["resettled_height_m"] = float(s["bed_height"][lastFluid + 1])
    f["peak_gate_flux_m3s"] = float(np.max(s["gate_flux"]))
    f["peak_filter_velocity_ms"] = f["peak_gate_flux_m3s"] / area
    f["initial_bed_height_m"] = float(s["bed_height"][0])
    f["peak_bed_height_m"] = float(np.max(s["bed_height"]))
    f["peak_expansion"] = f["peak_bed_height_m"] / f["initial_bed_height_m"] - 1
    f["final_bed_height_m"] = float(s["bed_height"][-1])
    if "cumulative_solid_outflow" in s:
        f["sand_carried_out_kg"] = float(s["cumulative_solid_outflow"][-1])
    res = case.get("reservoir", {})
    # the fits assume one plan area: with area_table u(t) is neither law, and they are left empty
    if res.get("model") in ("lumped", "openfoam") and "area_table" not in res:
        column = case["column"]
        tail = column.get("overflow_level", column.get("water_level"))
        tau, r2, n, r2n = head_fits(t, s["reservoir_head"], tail)
        f.update(head_tau_s=tau, head_tau_r2=r2, head_exponent=n, head_exponent_r2=r2n)
    f.update(pipe_figures(output_dir, s))
    return f


def pipe_figures(output_dir, s):
    """The pipes' figures from pipes.csv (2D, 3D); {} without one."""
    path = os.path.join(output_dir, "pipes.csv")
    if not os.path.isfile(path):
        return {}
    rows = qs.read_pipes(path).to_dict("records")
    main = {}  # time -> the line of its main pipe (pipe 1), or of no pipe
    for r in rows:
        if r["pipe"] <= 1:
            main.setdefault(r["time"], r)
    times = sorted(main)
    piped = [t for t in times if main[t]["pipes"] > 0]
    out = {"max_pipes": max((main[t]["pipes"] for t in times), default=0.0)}
    if not piped:
        return out
    first = main[piped[0]]
    k = int(np.argmin(np.abs(s["time"] - first["time"])))
    out.update(first_pipe_time_s=first["time"], first_pipe_gradient=float(s["gradient"][k]),
               first_pipe_wall=first["wall"], first_pipe_x_m=first["x"],
               pipe_time_share=len(piped) / len([t for t in times if t >= piped[0]]),
               wall_pipe_share=sum(main[t]["wall"] for t in piped) / len(piped),
               max_pipe_flux_share=max(r["flux_share"] for r in rows if r["pipe"] > 0))
    return out


def cell(v):
    if v is None:
        return ""
    if isinstance(v, float):
        return "" if math.isnan(v) else repr(v)
    return str(v)


def write_study_csv(study):
    """STUDY/output/study.csv: one row per variant, its parameters, its figures, its status."""
    os.makedirs(study.output, exist_ok=True)
    path = os.path.join(study.output, "study.csv")
    with open(path, "w", newline="") as out:
        w = csv.writer(out)
        w.writerow(["variant"] + study.keys + FIGURES + ["status", "error"])
        for v in study.variants:
            try:
                with open(os.path.join(v["out"], "study-status.json")) as f:
                    status = json.load(f)
            except (OSError, ValueError):
                status = {"state": "not run"}
            figs = dict.fromkeys(FIGURES)
            if os.path.isfile(os.path.join(v["out"], "series.csv")):
                try:
                    figs = figures(v["out"])
                except (OSError, KeyError, ValueError) as e:
                    status.setdefault("error", f"figures: {e}")
            w.writerow([v["name"]] + [cell(v["params"][k]) if not isinstance(v["params"][k], (list, dict))
                                      else json.dumps(v["params"][k]) for k in study.keys]
                       + [cell(figs[k]) for k in FIGURES] + [status["state"], status.get("error", "")])
    return path


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: .venv/bin/python tools/study_figures.py CASE/output")
    for k, v in figures(sys.argv[1]).items():
        print(f"{k:26s} {cell(v)}")


if __name__ == "__main__":
    main()
