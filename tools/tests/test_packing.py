"""quicksand.packing: the figures of item 3 of issue 42 on frames whose answers are known."""
import numpy as np
import pytest

from quicksand import packing


def frame(porosity, state):
    return np.asarray(porosity, float)[:, None, :], np.asarray(state, float)[:, None, :]


def test_cells_below_the_densest_packing_are_counted():
    p, s = frame([[0.35, 0.31, 0.40], [np.nan, 0.36, 0.30]], [[1, 1, 1], [0, 1, 1]])
    table = packing.packing_of_frames([(0.0, p, s)], min_porosity=0.32)
    assert table["least_porosity"][0] == pytest.approx(0.30)
    assert table["cells_below_min"][0] == 2
    assert table.attrs["units"]["time"] == "s"


def test_only_sand_that_was_fluidised_and_is_solid_again_counts_as_resettled():
    rng = np.random.default_rng(3)
    base = 0.38 + 0.01 * rng.standard_normal((6, 6))
    fluidised = np.full((6, 6), 2.0)
    solid = np.ones((6, 6))
    solid[:, :2] = 2  # still fluidised on the left
    frames = [(0.0, *frame(base, np.ones((6, 6)))), (1.0, *frame(base + 0.05, fluidised)), (2.0, *frame(base, solid))]
    table = packing.packing_of_frames(frames, min_porosity=0.32)
    assert list(table["resettled_cells"]) == [0, 0, 24]
    assert np.isnan(table["resettled_rms"][0])
    # the rms about the 3 x 3 mean, computed here by hand for the resettled cells
    p = base
    mean = np.zeros_like(p)
    for i in range(6):
        for j in range(6):
            mean[i, j] = p[max(0, i - 1):i + 2, max(0, j - 1):j + 2].mean()
    expected = np.sqrt(np.mean((p - mean)[:, 2:] ** 2))
    assert table["resettled_rms"][2] == pytest.approx(expected, rel=1e-12)


def test_salt_and_pepper_is_rough_and_a_smooth_bed_is_not():
    smooth = np.fromfunction(lambda i, j: 0.38 + 0.001 * i, (8, 8))
    pepper = smooth + 0.1 * (np.indices((8, 8)).sum(axis=0) % 2)
    frames_smooth = [(0.0, *frame(smooth, np.full((8, 8), 2.0))), (1.0, *frame(smooth, np.ones((8, 8))))]
    frames_pepper = [(0.0, *frame(pepper, np.full((8, 8), 2.0))), (1.0, *frame(pepper, np.ones((8, 8))))]
    assert packing.packing_of_frames(frames_smooth, 0.32)["resettled_rms"][1] < 1e-3
    assert packing.packing_of_frames(frames_pepper, 0.32)["resettled_rms"][1] > 0.03
