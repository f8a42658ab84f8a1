"""quicksand.figures and quicksand.studies: a run's figures from its outputs, and the study tool's
entry point. The studies themselves (local runs, resume, failing variants) are tested by ctest's
`study` label (tests/study), which runs tools/study.py as a user does."""
import os
import subprocess
import sys

import numpy as np
import pytest

import quicksand as qs
from quicksand import figures, studies

TOOLS = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


def test_a_runs_figures_are_read_from_its_series(column_run):
    f = figures.figures(column_run.output)
    series = column_run.series()
    assert f["peak_gate_flux_m3s"] == pytest.approx(series["gate_flux"].max(), rel=1e-12)
    assert f["initial_bed_height_m"] == pytest.approx(series["bed_height"].iloc[0], rel=1e-12)
    assert f["final_bed_height_m"] == pytest.approx(series["bed_height"].iloc[-1], rel=1e-12)
    fluid = series["fluidised_share"] > 0
    if fluid.any():
        assert f["onset_time_s"] == series["time"][fluid].iloc[0]
    else:
        assert f["onset_time_s"] is None and f["fluidised_duration_s"] is None


def test_the_entry_point_says_what_is_missing_without_numpy(tmp_path):
    # a python3 whose numpy is shadowed, as a pyenv python3 without Debian's packages
    (tmp_path / "numpy.py").write_text("raise ImportError('No module named numpy')\n")
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    done = subprocess.run([sys.executable, os.path.join(TOOLS, "study.py"), "any.toml"], capture_output=True,
                          text=True, env=env)
    assert done.returncode != 0
    assert "tools/setup.sh" in done.stderr and ".venv" in done.stderr and "numpy" in done.stderr


def test_a_study_file_that_is_not_there_is_named(tmp_path):
    with pytest.raises(studies.StudyError) as refused:
        studies.Study(str(tmp_path / "missing.toml"))
    assert "missing.toml" in str(refused.value)


@pytest.fixture(scope="module")
def small_study(quicksand_binary, tmp_path_factory):
    """Two reservoirs of the main job's lumped twin, 1 s each, run by the local scheduler."""
    folder = tmp_path_factory.mktemp("study")
    base = os.path.relpath(os.path.join(TOOLS, "..", "cases", "deltaresColumnLumped"), folder)
    (folder / "study.toml").write_text(f'base = "{base}"\nparallel = 2\nthreads = 1\n'
                                       '[parameters]\n"reservoir.area" = [0.0083, 0.0166]\n'
                                       '[set]\n"time.end" = 1.0\n"output.fields" = false\n')
    assert studies.main([str(folder / "study.toml"), "--quiet", "--no-plots"]) == 0
    return studies.Study(str(folder / "study.toml"))


def test_a_studys_table_holds_each_variants_figures(small_study):
    table = qs.read_study(small_study.output)
    assert list(table["reservoir.area"]) == [0.0083, 0.0166]
    assert list(table["status"]) == ["finished", "finished"]
    for v, peak in zip(small_study.variants, table["peak_gate_flux_m3s"]):
        assert peak == pytest.approx(qs.read_series(v["out"])["gate_flux"].max(), rel=1e-9)


def test_the_study_plots_draw_each_variants_series(small_study):
    from quicksand import study_plots

    path, fig = study_plots.plot_series(small_study)
    assert os.path.getsize(path) > 10_000
    head, velocity, bed = fig.axes[:3]
    runs = [line for line in head.lines if line.get_linestyle() == "-"]  # the closed forms are dotted, dashed
    assert len(runs) == 2
    for v, line in zip(small_study.variants, runs):
        s = qs.read_series(v["out"])
        np.testing.assert_allclose(line.get_xdata(), s["time"])
        np.testing.assert_allclose(bed.lines[small_study.variants.index(v)].get_ydata(), 1e3 * s["bed_height"])
    path, fig = study_plots.plot_figures(small_study)
    assert os.path.getsize(path) > 10_000
    table = qs.read_study(small_study.output)
    # a row per figure study.csv has values for, against the one parameter
    peak = next(ax for ax in fig.axes if ax.get_ylabel() == "peak filter velocity (m/s)")
    np.testing.assert_allclose(peak.lines[0].get_xdata(), table["reservoir.area"])
    np.testing.assert_allclose(peak.lines[0].get_ydata(), table["peak_filter_velocity_ms"])
