"""quicksand's solver inside Python (the pybind11 binding, mpm/python/SolverModule.cpp): a run
driven step by step, its fields as numpy arrays.

    from quicksand.solver import Simulation
    sim = Simulation("cases/verification/terzaghi", {"time.end": 0.5}, write_files=False)
    sim.advance_to(0.1)                         # s
    rows = sim.profile()                        # the cell rows: z, pore_pressure, porosity, ...
    sand = sim.points("solid")                  # the registry's fields: position (n x D), porosity, ...
    sim.state()["gate_flux"]                    # series.csv's quantities now

A case or key quicksand refuses raises QuicksandError with its message; Ctrl-C inside advance_to
ends the step, writes the checkpoint (when the run writes files) and raises KeyboardInterrupt.
The binding is built with quicksand (build/python/, when Debian's pybind11-dev is installed); it
runs the column with the built-in reservoirs (an OpenFOAM line runs through `quicksand run`,
quicksand.running.run).
"""
import importlib
import os
import sys

from .running import QuicksandError, toml_value

_REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def binding():
    """The compiled module: from $QUICKSAND_BUILD_DIR/python, else build/python of this repository."""
    build = os.environ.get("QUICKSAND_BUILD_DIR", os.path.join(_REPOSITORY, "build"))
    folder = os.path.join(os.path.abspath(build), "python")
    if folder not in sys.path:
        sys.path.insert(0, folder)
    try:
        return importlib.import_module("quicksand_solver")
    except ImportError as e:
        raise ImportError(f"the solver's Python binding is not in {folder} ({e}): install Debian's pybind11-dev and "
                          "python3-dev (bash tools/setup.sh) and build (bash tools/build.sh)") from e


class Simulation:
    """One run of a case, opened as `quicksand run CASE --set ...` opens it."""

    def __init__(self, case, overrides=None, write_files=True, quiet=True, resume=False):
        module = binding()
        self._error = module.SolverError
        sets = [f"{k}={toml_value(v)}" for k, v in (overrides or {}).items()]
        try:
            self._run = module.Simulation(os.fspath(case), sets, write_files, quiet, resume)
        except module.SolverError as e:
            raise QuicksandError(str(e)) from None

    def _call(self, method, *args):
        try:
            return getattr(self._run, method)(*args)
        except self._error as e:
            raise QuicksandError(str(e)) from None

    @property
    def time(self):
        """s"""
        return self._run.time

    @property
    def dt(self):
        """s, the step (solver/TimeLattice.hpp)"""
        return self._run.dt

    @property
    def steps(self):
        return self._run.steps

    @property
    def dimension(self):
        return self._run.dimension

    def advance_to(self, end):
        """Steps to time `end` (s), writing the outputs and checkpoints that fall due."""
        self._call("advance_to", float(end))

    def state(self):
        """series.csv's quantities now, by its column names (SI)."""
        return self._call("state")

    def profile(self):
        """The cell rows' means along the vertical: z (m), pore_pressure (Pa), vertical_stress (Pa,
        tension +), porosity, fluidised_share, filter_velocity (m/s), ..."""
        return self._call("profile")

    def points(self, kind="solid"):
        """The registry's fields of the solid or liquid points (points/PointSet.hpp) as arrays."""
        if kind not in ("solid", "liquid"):
            raise ValueError(f"points: kind {kind!r}: expected 'solid' or 'liquid'")
        return self._call("points", kind == "solid")

    def cells(self):
        """The grid's cells (2D, 3D) as the pipe survey reads them: porosity and state (0 no sand,
        1 solid, 2 fluidised) indexed [row][column] (3D: [row][y][x]), base_flux per column
        (m3/s), h and filter_level (m). A 1D column raises QuicksandError: use profile()."""
        return self._call("cells")

    def write_output(self):
        self._call("write_output")

    def write_checkpoint(self):
        self._call("write_checkpoint")

    def finish(self):
        """The last checkpoint; the run's summary (final state, steps, wall seconds, dt)."""
        return self._call("finish")
