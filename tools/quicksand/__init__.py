"""quicksand from Python: a run's results as pandas tables, runs of the quicksand command.

    import quicksand as qs
    run = qs.run("cases/deltaresColumnLumped", {"time.end": 2.0})   # quicksand run ... --set time.end=2.0
    series = run.series()                    # series.csv as a DataFrame; series.attrs["units"]
    series.plot(x="time", y="gate_flux")

One module per concern: results (the files a run writes, read once each), running (the command:
finding it, check, run), studies (a base case over parameter values: tools/study.py), figures (a
run's figures, study.csv), study_plots. The closed forms of hydraulics stay apart from the solver:
they are its references.
"""
try:
    import numpy  # noqa: F401
    import pandas  # noqa: F401
except ImportError as missing:  # a pyenv or conda python3 without Debian's packages
    raise ImportError(f"the quicksand package needs numpy and pandas ({missing}); run `bash tools/setup.sh` and use "
                      "its virtual environment: `source .venv/bin/activate` (or .venv/bin/python)") from missing

from .results import (Fields, UNITS, arrays, read_fields, read_front_fit, read_function_object, read_pipes,
                      read_postprocessing, read_series, read_study, read_table)
from .running import QuicksandError, Run, check, find_quicksand, run, set_arguments

__version__ = "0.1.0"

__all__ = ["Fields", "UNITS", "arrays", "read_fields", "read_front_fit", "read_function_object", "read_pipes",
           "read_postprocessing", "read_series", "read_study", "read_table", "QuicksandError", "Run", "check",
           "find_quicksand", "run", "set_arguments"]
