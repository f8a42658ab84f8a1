"""The files a quicksand run writes, each read once, into pandas tables with their units.

    series = read_series("CASE/output")      # series.csv
    series.attrs["units"]["gate_flux"]       # 'm3/s'
    pipes = read_pipes("CASE/output")        # pipes.csv (2D and 3D runs)
    fields = read_fields("CASE/output")      # fields.h5: fields.times, fields.step(k)["solid"]["porosity"]

Units are those of docs/case-format.md ("series.csv", "pipes.csv") and docs/studies.md ("study.csv");
tools/tests/test_results.py checks that the tables here and there agree. A file that a running or
crashed simulation is still writing may end in half a line: short lines are dropped, and cells
that are not numbers become NaN (study.csv keeps its text columns).
"""
import csv
import os
import re

import numpy as np
import pandas as pd

# docs/case-format.md, "series.csv" and "pipes.csv"
SERIES_UNITS = {
    "time": "s", "gate_flux": "m3/s", "gate_pressure": "Pa", "reservoir_head": "m", "sand_surface": "m",
    "bed_height": "m", "fluidised_front": "m", "fluidised_share": "-", "water_surface": "m", "gradient": "-",
    "cumulative_inflow": "m3", "cumulative_outflow": "m3", "injected_volume": "m3", "ledger_residual": "m3",
    "solid_mass": "kg", "liquid_mass": "kg", "solid_points": "-", "liquid_points": "-",
    "cumulative_solid_outflow": "kg",
}
MONITOR_UNIT = "m/s"  # q_NAME: the filter velocity at monitor NAME
PIPES_UNITS = {
    "time": "s", "pipes": "-", "fluidised_flux_share": "-", "pipe": "-", "x": "m", "y": "m", "width": "m",
    "height": "m", "wall": "-", "flux_share": "-", "cells": "-",
}
# docs/studies.md, "study.csv": a figure's unit is its name's suffix
STUDY_SUFFIX_UNITS = {"_s": "s", "_m": "m", "_kg": "kg", "_m3s": "m3/s", "_ms": "m/s"}
FRONT_FIT_UNITS = {"speed": "m/s", "intercept": "m", "r2": "-", "fit_from": "s", "fit_to": "s"}
UNITS = {"series.csv": SERIES_UNITS, "pipes.csv": PIPES_UNITS, "front_fit.csv": FRONT_FIT_UNITS}


def _file(path, name):
    """`path` itself, or `name` inside it when it is a directory (a run's output directory)."""
    return os.path.join(path, name) if os.path.isdir(path) else path


def _unit_of_series_column(name):
    if name in SERIES_UNITS:
        return SERIES_UNITS[name]
    return MONITOR_UNIT if name.startswith("q_") else "?"


def _unit_of_study_column(name):
    for suffix, unit in STUDY_SUFFIX_UNITS.items():
        if name.endswith(suffix):
            return unit
    return "-"


def read_table(path, unit_of=lambda name: "?", text_columns=()):
    """A CSV file with a header line as a DataFrame: numbers as floats (NaN where a cell is not
    one), `text_columns` kept as text ("auto": every column with a filled cell that is not a
    number), lines shorter or longer than the header dropped.
    DataFrame.attrs["units"] maps each column to unit_of(column); attrs["path"] is the file."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty file (no header line)")
    header = [name.strip() for name in rows[0]]
    body = [r for r in rows[1:] if len(r) == len(header)]
    frame = pd.DataFrame(body, columns=header)
    for name in header:
        numbers = pd.to_numeric(frame[name], errors="coerce").astype(float)
        if text_columns == "auto":  # a column is text if a filled cell of it is not a number
            if (numbers.isna() & (frame[name].str.strip() != "")).any():
                continue
        elif name in text_columns:
            continue
        frame[name] = numbers
    frame.attrs["units"] = {name: unit_of(name) for name in header}
    frame.attrs["path"] = os.path.abspath(path)
    return frame


def arrays(frame):
    """A table as {column: numpy array}, for code written against plain arrays."""
    return {name: frame[name].to_numpy() for name in frame.columns}


def read_series(path):
    """series.csv of a run (its output directory, or the file): one row per output time."""
    return read_table(_file(path, "series.csv"), _unit_of_series_column)


def read_pipes(path):
    """pipes.csv of a 2D or 3D run: one row per pipe and output time (pipe 0: none then)."""
    return read_table(_file(path, "pipes.csv"), lambda name: PIPES_UNITS.get(name, "?"))


def read_study(path):
    """study.csv of a study (its directory, or the file): one row per variant."""
    # its parameters may be text (time.scheme = "semi_implicit"), and its error column is
    return read_table(_file(path, "study.csv"), _unit_of_study_column, text_columns="auto")


def read_front_fit(path):
    """front_fit.csv (quicksand.plots.fluidisation): the fluidised front's linear fit, the front's
    elevation = intercept + speed t over fit_from <= t <= fit_to."""
    return read_table(_file(path, "front_fit.csv"), lambda name: FRONT_FIT_UNITS.get(name, "?"))


class Fields:
    """fields.h5 of a run: per output, the point sets (solid, liquid, and cells in 2D and 3D), each
    field an array (positions N x 3 as x y z, stresses N x 6 as xx yy zz yz xz xy)."""

    def __init__(self, path):
        import h5py  # only readers of fields need it

        self.path = _file(path, "fields.h5")
        self._h5py = h5py
        with h5py.File(self.path, "r") as h:
            self.dimension = int(h.attrs.get("dimension", 0))
            build = h.attrs.get("quicksand", b"")
            self.quicksand = build.decode() if isinstance(build, bytes) else str(build)
            self._steps = sorted(k for k in h.keys() if re.fullmatch(r"step_\d+", k))
            self.times = np.array([float(h[k].attrs["time"]) for k in self._steps])

    def __len__(self):
        return len(self._steps)

    def step(self, k):
        """Output k (negative counts from the last) as {set: {field: array}}, with "time"."""
        name = self._steps[k]
        out = {}
        with self._h5py.File(self.path, "r") as h:
            g = h[name]
            out["time"] = float(g.attrs["time"])
            for point_set in g.keys():
                out[point_set] = {field: g[point_set][field][()] for field in g[point_set].keys()}
        return out

    def at(self, time):
        """The output nearest `time` (s)."""
        return self.step(int(np.argmin(np.abs(self.times - time))))


def read_fields(path):
    """fields.h5 of a run (its output directory, or the file)."""
    return Fields(path)


def _cells(line):
    """A postProcessing line's cells, a vector "(a b c)" kept as one cell."""
    return re.findall(r"\([^)]*\)|\S+", line)


def read_function_object(path):
    """One file an OpenFOAM function object wrote (postProcessing/NAME/TIME/FILE): probes (a
    column per probe, `probe0`, ..., a vector one as probe0_x, _y, _z), surfaceFieldValue,
    yPlus and the like (the columns of its last header line). Times in s; the other values as
    OpenFOAM writes them (an incompressible case's p is kinematic, m2/s2)."""
    with open(path) as f:
        lines = f.read().splitlines()
    header = [line[1:].strip() for line in lines if line.startswith("#")]
    body = [_cells(line) for line in lines if line.strip() and not line.startswith("#")]
    probes = [h for h in header if h.startswith("Probe ") and "(" in h]
    if probes:
        names = [f"probe{k}" for k in range(len(probes))]
    else:
        names = header[-1].split()[1:] if header and header[-1].split()[:1] == ["Time"] else []
    columns, rows = ["time"], [[] for _ in body]
    for j, name in enumerate(names):
        sample = next((r[j + 1] for r in body if len(r) > j + 1), "")
        if sample.startswith("("):
            parts = len(sample.strip("()").split())
            columns += [f"{name}_{axis}" for axis in "xyz"[:parts]]
            for r, row in zip(body, rows):
                row += r[j + 1].strip("()").split() if len(r) > j + 1 else [""] * parts
        else:
            columns.append(name)
            for r, row in zip(body, rows):
                row.append(r[j + 1] if len(r) > j + 1 else "")
    for r, row in zip(body, rows):
        row.insert(0, r[0])
    frame = pd.DataFrame(rows, columns=columns)
    for name in columns:
        numbers = pd.to_numeric(frame[name], errors="coerce").astype(float)
        if not (numbers.isna() & (frame[name] != "")).any():
            frame[name] = numbers
    frame.attrs["units"] = {name: "s" if name == "time" else "OpenFOAM's" for name in columns}
    frame.attrs["path"] = os.path.abspath(path)
    if probes:
        frame.attrs["probes"] = [tuple(float(x) for x in h[h.index("(") + 1:h.index(")")].split()) for h in probes]
    return frame


def read_postprocessing(path):
    """An OpenFOAM line's postProcessing (a run's output directory, its openfoam/ folder, or the
    postProcessing folder itself): {"NAME/FILE": table}, each function object's file read once,
    the time folders of a resumed run (postProcessing/NAME/0, NAME/12.5, ...) joined in time order."""
    folder = path
    for candidate in (os.path.join(path, "openfoam", "postProcessing"), os.path.join(path, "postProcessing")):
        if os.path.isdir(candidate):
            folder = candidate
            break
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"{path}: no postProcessing folder (an OpenFOAM line's output/openfoam/postProcessing)")
    tables = {}
    for name in sorted(os.listdir(folder)):
        times = []
        for t in os.listdir(os.path.join(folder, name)):
            try:
                times.append((float(t), t))
            except ValueError:
                continue
        files = {}
        for _, t in sorted(times):
            for file in sorted(os.listdir(os.path.join(folder, name, t))):
                files.setdefault(file, []).append(read_function_object(os.path.join(folder, name, t, file)))
        for file, parts in files.items():
            joined = pd.concat(parts, ignore_index=True) if len(parts) > 1 else parts[0]
            joined.attrs = dict(parts[0].attrs)
            tables[f"{name}/{file}"] = joined
    return tables
