"""Runs of the quicksand command from Python: one way to find it, check and run with overrides.

    report = check("cases/deltaresColumnLumped", {"reservoir.head": 0.6})
    result = run("cases/deltaresColumnLumped", {"time.end": 2.0}, threads=2)
    result.series()

Overrides are the command's `--set KEY=VALUE` (docs/case-format.md): a dict of dotted keys to
Python values, written as TOML (strings quoted, booleans lower case, lists as arrays). An error of
quicksand (a bad key, a refused resume, a failed run) raises QuicksandError with quicksand's own
message; the command's exit code is kept in `.returncode` (130/143: interrupted, resumable).
"""
import json
import os
import shutil
import subprocess
import sys

from . import results

_HERE = os.path.dirname(os.path.abspath(__file__))
_REPOSITORY = os.path.abspath(os.path.join(_HERE, "..", ".."))


class QuicksandError(RuntimeError):
    """quicksand exited non-zero; the message is what it said on stderr."""

    def __init__(self, message, returncode=1, command=None):
        super().__init__(message)
        self.returncode = returncode
        self.command = command


def find_quicksand(explicit=None):
    """The quicksand command: `explicit`, else $QUICKSAND, else this repository's build
    (build/mpm/quicksand), else `quicksand` on PATH."""
    def executable(path):
        return os.path.isfile(path) and os.access(path, os.X_OK)

    for given, what in ((explicit, "the quicksand command given"), (os.environ.get("QUICKSAND"), "$QUICKSAND")):
        if given:
            if not executable(given):
                raise QuicksandError(f"{given} ({what}): not an executable quicksand command")
            return os.path.abspath(given)
    built = os.path.join(_REPOSITORY, "build", "mpm", "quicksand")
    if executable(built):
        return built
    found = shutil.which("quicksand")
    if not found:
        raise QuicksandError("cannot find the quicksand command: build it (bash tools/build.sh) or set "
                             "QUICKSAND=/path/to/quicksand")
    return found


def toml_value(value):
    """A Python value as TOML, as --set KEY= takes it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: JSON's escapes are TOML's
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"cannot write {value!r} ({type(value).__name__}) as a TOML value")


def set_arguments(overrides):
    """{"time.end": 2.0, "time.scheme": "semi_implicit"} -> ["--set", "time.end=2.0", "--set", ...].
    Strings that are already TOML (a "KEY=VALUE" list, as study files write them) pass through."""
    if not overrides:
        return []
    items = overrides.items() if isinstance(overrides, dict) else (s.split("=", 1) for s in overrides)
    args = []
    for key, value in items:
        written = value if not isinstance(overrides, dict) else toml_value(value)
        args += ["--set", f"{key}={written}"]
    return args


def _command(verb, case, overrides, binary, extra=()):
    return [find_quicksand(binary), verb, os.fspath(case), *set_arguments(overrides), *extra]


def _error_of(completed_or_text, returncode, command):
    text = completed_or_text.strip()
    message = text.replace("quicksand: error: ", "") if text else f"quicksand exited with {returncode}"
    return QuicksandError(message, returncode, command)


def check(case, overrides=None, binary=None, ranks=None):
    """`quicksand check CASE`: its report (text). Raises QuicksandError if the case is refused."""
    extra = ["--ranks", str(ranks)] if ranks else []
    command = _command("check", case, overrides, binary, extra)
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise _error_of(done.stderr or done.stdout, done.returncode, command)
    return done.stdout


class Run:
    """A run's case and output directories, and its results read on demand."""

    def __init__(self, case, output, log=""):
        self.case = os.path.abspath(case)
        self.output = os.path.abspath(output)
        self.log = log  # what the command printed (stdout), progress lines included

    def series(self):
        return results.read_series(self.output)

    def pipes(self):
        return results.read_pipes(self.output)

    def fields(self):
        return results.read_fields(self.output)

    def __repr__(self):
        return f"Run(case={self.case!r}, output={self.output!r})"


def output_directory(case, overrides=None):
    """Where a run of `case` writes: output.directory of its case.toml (or the override), under
    the case directory."""
    directory = "output"
    if overrides and isinstance(overrides, dict) and "output.directory" in overrides:
        directory = overrides["output.directory"]
    else:
        try:
            import tomllib

            with open(os.path.join(case, "case.toml"), "rb") as f:
                directory = tomllib.load(f).get("output", {}).get("directory", directory)
        except (OSError, ImportError, ValueError):
            pass
    return directory if os.path.isabs(directory) else os.path.join(case, directory)


def run(case, overrides=None, threads=None, resume=False, binary=None, progress=None, env=None):
    """`quicksand run CASE` with `overrides` (--set), `threads` (OMP_NUM_THREADS) and `resume`.
    Progress lines go to `progress` (a callable taking a line; default: none shown). Returns a
    Run; raises QuicksandError with quicksand's message if the run fails or is interrupted
    (.returncode 130 or 143: a checkpoint was written, resume=True continues)."""
    command = _command("run", case, overrides, binary, ["--resume"] if resume else [])
    environment = dict(os.environ if env is None else env)
    if threads:
        environment["OMP_NUM_THREADS"] = str(threads)
    lines = []
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          env=environment) as process:
        for line in process.stdout:
            lines.append(line)
            if progress:
                progress(line.rstrip("\n"))
        stderr = process.stderr.read()
    if process.returncode != 0:
        raise _error_of(stderr, process.returncode, command)
    return Run(case, output_directory(os.fspath(case), overrides), "".join(lines))


def main(argv=None):
    """`python3 -m quicksand.running CASE [KEY=VALUE ...]`: runs a case, progress on stdout."""
    argv = sys.argv[1:] if argv is None else argv
    if not argv:
        print("usage: python3 -m quicksand.running CASE [KEY=VALUE ...]", file=sys.stderr)
        return 2
    try:
        result = run(argv[0], argv[1:], progress=print)
    except QuicksandError as e:
        print(f"quicksand: {e}", file=sys.stderr)
        return e.returncode
    print(f"results in {result.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
