"""quicksand.plots: each plot writes its file and draws the data of the run's own files."""
import os

import numpy as np

import quicksand as qs
from quicksand.plots import fluidisation, pipes, profiles, series


def test_series_draws_series_csv(column_run, tmp_path):
    out = str(tmp_path / "series.png")
    path, fig = series.plot(column_run.output, out)
    assert path == out and os.path.getsize(out) > 10_000
    s = column_run.series()
    gate, surface = fig.axes[1], fig.axes[2]
    np.testing.assert_allclose(gate.lines[0].get_ydata(), s["gate_pressure"] / 1e3)  # kPa
    np.testing.assert_allclose(surface.lines[0].get_xdata(), s["time"])
    np.testing.assert_allclose(surface.lines[0].get_ydata(), s["sand_surface"])


def test_profiles_draw_the_last_output_of_fields_h5(column_run, tmp_path):
    path, fig = profiles.plot(column_run.output, out=str(tmp_path / "profiles.png"))
    assert os.path.getsize(path) > 10_000
    last = column_run.fields().step(-1)
    drawn = fig.axes[2].collections[0].get_offsets()  # porosity against elevation
    np.testing.assert_allclose(drawn[:, 0], last["solid"]["porosity"])
    np.testing.assert_allclose(drawn[:, 1], last["solid"]["positions"][:, 2])
    try:
        profiles.plot(column_run.output, step=99)
        raise AssertionError("step 99 was drawn")
    except ValueError as e:
        assert "step_000099" in str(e)


def test_pipes_draw_pipes_csv(stripe_run):
    written, fig = pipes.plot(stripe_run.output, frames=2, gif=False)
    assert [os.path.basename(p) for p in written] == ["pipes_frames.png", "pipes.png"]
    table = stripe_run.pipes()
    per_time = table.groupby("time")["pipes"].first()
    count = fig.axes[0].lines[0]
    np.testing.assert_allclose(count.get_xdata(), per_time.index)
    np.testing.assert_allclose(count.get_ydata(), per_time.to_numpy())


def test_fluidisation_draws_the_bed_height(column_run):
    fig = fluidisation.plot([column_run.output])
    assert os.path.getsize(os.path.join(column_run.output, "fluidisation.png")) > 10_000
    s = qs.read_series(column_run.output)
    height = fig.axes[0].lines[0]
    np.testing.assert_allclose(height.get_xdata(), s["time"])
    np.testing.assert_allclose(height.get_ydata(), 1000 * s["bed_height"])  # mm
