"""quicksand.results: every reader on outputs this build writes, and the units against the docs."""
import math
import os
import re

import numpy as np
import pytest

import quicksand as qs
from quicksand import results

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def docs_table(document, heading):
    """The first column's names and the unit column of the table under `heading` in docs/."""
    with open(os.path.join(REPOSITORY, "docs", document)) as f:
        text = f.read()
    section = text.split(f"## {heading}\n", 1)[1].split("\n## ", 1)[0]
    units = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 3 or not cells[0].startswith("`"):
            continue
        names = re.findall(r"`([^`]+)`", cells[0])
        cell_units = [u.strip() for u in cells[1].split(",")] if len(names) > 1 else [cells[1]]
        for name, unit in zip(names, cell_units * len(names) if len(cell_units) == 1 else cell_units):
            units[name] = unit
    return units


def test_the_units_are_those_of_the_docs():
    series = docs_table("case-format.md", "series.csv")
    monitors = {k: v for k, v in series.items() if k.startswith("q_")}
    assert monitors == {"q_NAME": results.MONITOR_UNIT}
    assert {k: v for k, v in series.items() if not k.startswith("q_")} == results.SERIES_UNITS
    assert docs_table("case-format.md", "pipes.csv") == results.PIPES_UNITS
    for name, unit in docs_table("studies.md", "study.csv").items():
        expected = {"m3/s": "m3/s", "m/s": "m/s", "s": "s", "m": "m", "kg": "kg"}.get(unit, "-")
        assert results._unit_of_study_column(name) == expected, name


def test_a_half_written_line_is_dropped_and_a_word_is_nan(tmp_path):
    path = tmp_path / "series.csv"
    path.write_text("time,gate_flux,q_top\n0,1e-5,2e-3\n0.5,nan,oops\n1,3e-5\n")
    s = qs.read_series(str(tmp_path))
    assert list(s["time"]) == [0.0, 0.5]
    assert math.isnan(s["gate_flux"][1]) and math.isnan(s["q_top"][1])
    assert s.attrs["units"] == {"time": "s", "gate_flux": "m3/s", "q_top": "m/s"}
    with pytest.raises(ValueError, match="empty file"):
        (tmp_path / "empty.csv").write_text("")
        qs.read_table(str(tmp_path / "empty.csv"))


def test_series_of_a_run_on_the_times_asked(column_run):
    s = column_run.series()
    assert len(s) == 6
    # outputs on k x 0.04 s (solver/TimeLattice.hpp), as series.csv prints them
    np.testing.assert_allclose(s["time"], 0.04 * np.arange(6), rtol=0, atol=1e-12)
    assert s.attrs["units"]["gate_pressure"] == "Pa"
    assert all(unit != "?" for unit in s.attrs["units"].values()), s.attrs["units"]
    assert (s["solid_points"] > 0).all()
    # the columns are the ones named: the bed's height is the sand's surface above the filter
    np.testing.assert_allclose(s["sand_surface"] - s["bed_height"], 0.0186, atol=1e-12)


def test_fields_of_a_run(column_run):
    fields = column_run.fields()
    series = column_run.series()
    np.testing.assert_allclose(fields.times, series["time"], atol=1e-12)
    assert fields.dimension == 1
    assert fields.quicksand.startswith("quicksand ")
    last = fields.step(-1)
    assert last["time"] == pytest.approx(0.2, abs=1e-12)
    porosity = last["solid"]["porosity"]
    assert porosity.ndim == 1 and len(porosity) == series["solid_points"].iloc[-1]
    assert ((porosity > 0) & (porosity < 1)).all()
    assert last["solid"]["positions"].shape == (len(porosity), 3)
    assert fields.at(0.11)["time"] == pytest.approx(0.12, abs=1e-12)


def test_pipes_of_a_2d_run(stripe_run):
    pipes = stripe_run.pipes()
    assert list(pipes.columns[:4]) == ["time", "pipes", "fluidised_flux_share", "pipe"]
    assert pipes.attrs["units"]["width"] == "m"
    assert set(np.round(pipes["time"], 12)) == {0.0, 0.05, 0.1}
    cells = stripe_run.fields().step(-1)["cells"]
    assert "porosity" in cells


def test_study_and_front_fit_tables(tmp_path):
    (tmp_path / "study.csv").write_text("variant,reservoir.head,time.scheme,onset_time_s,peak_gate_flux_m3s,status,error\n"
                                        "a,0.5,explicit,1.5,2e-5,finished,\nb,0.6,semi_implicit,,,failed,quicksand: bad\n")
    study = qs.read_study(str(tmp_path))
    assert list(study["time.scheme"]) == ["explicit", "semi_implicit"]  # a text parameter stays text
    assert list(study["reservoir.head"]) == [0.5, 0.6]
    assert list(study["variant"]) == ["a", "b"] and list(study["status"]) == ["finished", "failed"]
    assert math.isnan(study["onset_time_s"][1])
    assert study.attrs["units"]["onset_time_s"] == "s" and study.attrs["units"]["peak_gate_flux_m3s"] == "m3/s"
    # as quicksand.plots.fluidisation writes it
    (tmp_path / "front_fit.csv").write_text("speed,intercept,r2,fit_from,fit_to\n0.001,0.02,0.99,2,8\n")
    fit = qs.read_front_fit(str(tmp_path / "front_fit.csv"))
    assert fit["speed"][0] == 0.001 and fit["fit_to"][0] == 8.0
    assert fit.attrs["units"] == {"speed": "m/s", "intercept": "m", "r2": "-", "fit_from": "s", "fit_to": "s"}


DATA = os.path.join(os.path.dirname(__file__), "data")


def test_an_openfoam_lines_postprocessing_is_read_once_per_file():
    # heads of the files the suite's coupled user case wrote (tests/openfoam/test_UserCases.cpp:
    # probes of p and U, a surfaceFieldValue, yPlus), a second time folder as a resumed run's
    tables = qs.read_postprocessing(os.path.join(DATA, "postProcessing"))
    assert sorted(tables) == ["outletPressure/surfaceFieldValue.dat", "probes/U", "probes/p", "yPlus/yPlus.dat"]
    p = tables["probes/p"]
    assert list(p.columns) == ["time", "probe0", "probe1", "probe2"]
    assert list(p["time"]) == [0.02, 0.04, 0.06, 0.08, 0.12, 0.14, 0.16]  # 0/ then 0.1/
    assert p["probe2"][0] == 3.199134 and p.attrs["probes"][1] == (1.2, 0.002, 0.0)
    u = tables["probes/U"]
    assert list(u.columns[:4]) == ["time", "probe0_x", "probe0_y", "probe0_z"] and len(u.columns) == 10
    assert u["probe0_x"][0] == 0.039085597 and u["probe2_z"][0] == -1.0062827e-14
    outlet = tables["outletPressure/surfaceFieldValue.dat"]
    assert list(outlet.columns) == ["time", "areaAverage(p)"] and outlet["areaAverage(p)"][0] == 3.20175124
    yplus = tables["yPlus/yPlus.dat"]
    assert list(yplus["patch"]) == ["walls"] and yplus["max"][0] == 2.3
    assert p.attrs["units"]["time"] == "s"
    with pytest.raises(FileNotFoundError, match="no postProcessing"):
        qs.read_postprocessing(DATA + "/nothing")
