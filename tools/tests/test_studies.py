"""quicksand.figures and quicksand.studies: a run's figures from its outputs, and the study tool's
entry point. The studies themselves (local runs, resume, failing variants) are tested by ctest's
`study` label (tests/study), which runs tools/study.py as a user does."""
import os
import subprocess
import sys

import pytest

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
