"""Fixtures of the package's tests: the repository, and runs of this build's quicksand made once a
session (a 1D column for 0.2 s, a 2D loose stripe for 0.1 s) into pytest's temporary directory."""
import os
import shutil

import pytest

import quicksand as qs

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def _copy_case(name, tmp_path_factory):
    target = tmp_path_factory.mktemp(name.replace("/", "_")) / "case"
    shutil.copytree(os.path.join(REPOSITORY, "cases", name), target,
                    ignore=shutil.ignore_patterns("output", "output.previous"))
    return str(target)


@pytest.fixture(scope="session")
def quicksand_binary():
    try:
        return qs.find_quicksand()
    except qs.QuicksandError as e:
        pytest.skip(str(e))


@pytest.fixture(scope="session")
def column_run(quicksand_binary, tmp_path_factory):
    """The lumped Deltares column, 0.2 s with outputs every 0.04 s."""
    case = _copy_case("deltaresColumnLumped", tmp_path_factory)
    return qs.run(case, {"time.end": 0.2, "time.output_interval": 0.04}, threads=1)


@pytest.fixture(scope="session")
def stripe_run(quicksand_binary, tmp_path_factory):
    """The 2D loose stripe of the piping problems, 0.1 s (pipes.csv and the cells' point set)."""
    case = _copy_case("verification/loose_stripe", tmp_path_factory)
    return qs.run(case, {"time.end": 0.1, "time.output_interval": 0.05}, threads=1)
