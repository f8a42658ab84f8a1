"""quicksand.running: the command found one way, overrides written as TOML, errors as exceptions
with quicksand's message, nothing of an earlier run lost."""
import os

import pytest

import quicksand as qs
from quicksand import running


def test_values_are_written_as_toml():
    assert qs.set_arguments({"time.end": 2.0, "time.scheme": "semi_implicit", "output.fields": False,
                             "grid.dimension": 2, "monitors.elevations": [0.1, 0.2]}) == [
        "--set", "time.end=2.0", "--set", 'time.scheme="semi_implicit"', "--set", "output.fields=false",
        "--set", "grid.dimension=2", "--set", "monitors.elevations=[0.1, 0.2]"]
    # a study file's KEY=VALUE strings are TOML already
    assert qs.set_arguments(['reservoir.head=0.6']) == ["--set", "reservoir.head=0.6"]
    with pytest.raises(TypeError):
        running.toml_value(object())


def test_the_command_is_found_one_way(quicksand_binary, monkeypatch, tmp_path):
    assert os.access(quicksand_binary, os.X_OK)
    monkeypatch.setenv("QUICKSAND", quicksand_binary)
    assert qs.find_quicksand() == quicksand_binary
    with pytest.raises(qs.QuicksandError, match="not an executable"):
        qs.find_quicksand(str(tmp_path / "nothing"))


def test_check_reports_and_refuses_with_quicksands_message(quicksand_binary, column_run):
    report = qs.check(column_run.case)
    assert "case OK" in report and "fitted to dt" in report
    with pytest.raises(qs.QuicksandError) as refused:
        qs.check(column_run.case, {"time.end": -1.0})
    assert "time.end" in str(refused.value) and refused.value.returncode != 0


def test_a_refused_run_raises_and_keeps_the_earlier_results(column_run):
    before = open(os.path.join(column_run.output, "series.csv")).read()
    with pytest.raises(qs.QuicksandError, match="grid.cell_sise|did you mean"):
        qs.run(column_run.case, {"grid.cell_sise": 0.01})
    assert open(os.path.join(column_run.output, "series.csv")).read() == before


def test_a_run_returns_where_it_wrote(column_run):
    assert column_run.output == os.path.join(column_run.case, "output")
    assert "done" in column_run.log
