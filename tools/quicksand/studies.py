"""Runs a study: one base case over a set of parameter values, side by side, and compares the runs.

  .venv/bin/python tools/study.py STUDY.toml             check every variant, run them, write study.csv and plots
  .venv/bin/python tools/study.py STUDY.toml --check     check every variant only
  .venv/bin/python tools/study.py STUDY.toml --collect   only (re)write study.csv and the plots from finished runs

The study file (docs/studies.md has every key):

  base = "../../deltaresColumnLumped"        # the base case directory, relative to the study file
  combine = "product"                        # "product" (every combination) or "zip" (the i-th values together)
  [parameters]                               # each a case key (as for quicksand --set) with its values
  "reservoir.area" = [0.0083, 0.0166, 0.0332]          # a list
  "reservoir.tube_length" = { from = 1.0, to = 4.0, count = 2 }   # a range: count values, ends included
  [set]                                      # overrides every variant shares
  "time.end" = 60

Each variant is the base case run by `quicksand run BASE --set KEY=VALUE ...` exactly as a user would
type it, writing to STUDY/output/<variant>/ (output.directory is set to it). A variant is a hand run:
the same command gives the same series, bit for bit.

Why a tool and not `quicksand study`: a study starts processes, waits for them, reads their tables and
draws plots. That is a script's work (Python's subprocess, csv, tomllib and matplotlib), while the
solver stays one run of one case. Every check of a value is still the solver's: the study runs
`quicksand check` on every variant before the first run, and refuses the study naming each variant
that fails and why.

Concurrency: `parallel` variants at once (default: the machine's cores), each with `threads` OpenMP
threads (default: cores / parallel, at least 1). Progress is one line per running variant and an
overall ETA, every `progress_interval` s.

Resuming: run the same command again. Finished variants (STUDY/output/<variant>/study-status.json)
are kept; a variant that was interrupted (Ctrl-C or SIGTERM write a checkpoint, solver/Interruption)
continues from its checkpoint with --resume; one that never wrote a checkpoint starts again. A
variant that failed stays failed (its error in study.csv) unless --retry-failed.

What it gives back, in STUDY/output/: study.csv (one row per variant: its parameters and figures,
quicksand/figures.py), and the plots of quicksand/study_plots.py.

Needs python3 (tomllib: 3.11), python3-numpy and python3-matplotlib (tools/setup.sh installs them).
"""
import argparse
import difflib
import itertools
import json
import math
import os
import shlex
import signal
import subprocess
import sys
import threading
import time

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11
    sys.exit("study.py: needs Python 3.11 or later (tomllib); Debian bookworm's python3 is 3.11")

from . import running
STUDY_KEYS = ["base", "combine", "parameters", "set", "parallel", "threads", "progress_interval", "quicksand"]


class StudyError(Exception):
    """A problem with the study file or its variants: the message names the file and the key."""


def fail_key(path, key, what):
    raise StudyError(f"{path}: key '{key}': {what}")


toml_value = running.toml_value  # how a value is written after --set KEY= (TOML)


def values_of(path, key, spec):
    """A parameter's values: a list, or a range {from, to, count} / {from, to, step} (spacing
    "linear" or "log")."""
    where = f"parameters.\"{key}\""
    if isinstance(spec, list):
        if not spec:
            fail_key(path, where, "an empty list of values: give at least one")
        return spec
    if isinstance(spec, dict):
        allowed = {"from", "to", "count", "step", "spacing"}
        for k in spec:
            if k not in allowed:
                near = difflib.get_close_matches(k, allowed, 1)
                fail_key(path, f"{where}.{k}", "unknown key" + (f"; did you mean '{near[0]}'?" if near else f"; a range takes {sorted(allowed)}"))
        for k in ("from", "to"):
            if not isinstance(spec.get(k), (int, float)) or isinstance(spec.get(k), bool):
                fail_key(path, f"{where}.{k}", f"a range needs '{k}' as a number, got {spec.get(k)!r}")
        a, b = float(spec["from"]), float(spec["to"])
        spacing = spec.get("spacing", "linear")
        if spacing not in ("linear", "log"):
            fail_key(path, f"{where}.spacing", f"expected \"linear\" or \"log\", got {spacing!r}")
        if ("count" in spec) == ("step" in spec):
            fail_key(path, where, "a range needs exactly one of 'count' (values, ends included) and 'step'")
        if "count" in spec:
            n = spec["count"]
            if not isinstance(n, int) or isinstance(n, bool) or n < 1:
                fail_key(path, f"{where}.count", f"expected a whole number >= 1, got {n!r}")
            if spacing == "log":
                if a <= 0 or b <= 0:
                    fail_key(path, where, "a log range needs from > 0 and to > 0")
                return [a] if n == 1 else [a * (b / a) ** (k / (n - 1)) for k in range(n)]
            return [a] if n == 1 else [a + (b - a) * k / (n - 1) for k in range(n)]
        step = spec["step"]
        if not isinstance(step, (int, float)) or step == 0 or (b - a) / step < 0:
            fail_key(path, f"{where}.step", f"expected a number that leads from {a} to {b}, got {step!r}")
        n = int(math.floor((b - a) / step + 1e-9)) + 1
        # whole numbers stay whole (seeds, counts): the case's integer keys refuse 10.0
        if all(isinstance(spec[k], int) and not isinstance(spec[k], bool) for k in ("from", "to", "step")):
            return [spec["from"] + k * step for k in range(n)]
        return [a + k * step for k in range(n)]
    fail_key(path, where, f"expected a list of values or a range {{ from, to, count }}, got {spec!r}")


def short_name(key, keys):
    """The variant's name for a key: its last name, or the whole key if two keys share it."""
    last = key.split(".")[-1]
    return last if sum(1 for k in keys if k.split(".")[-1] == last) == 1 else key


def format_value(v):
    if isinstance(v, float):
        return f"{v:.6g}"
    if isinstance(v, (list, dict)):
        return "".join(c for c in toml_value(v) if c.isalnum() or c in ".-_")[:24]
    return str(v)


class Study:
    def __init__(self, path, cores=None):
        self.path = os.path.abspath(path)
        self.dir = os.path.dirname(self.path)
        if not os.path.isfile(self.path):
            raise StudyError(f"{path}: cannot read the study file (no such file)")
        try:
            with open(self.path, "rb") as f:
                spec = tomllib.load(f)
        except tomllib.TOMLDecodeError as e:
            raise StudyError(f"{path}: TOML syntax error: {e}")
        for k in spec:
            if k not in STUDY_KEYS:
                near = difflib.get_close_matches(k, STUDY_KEYS, 1)
                fail_key(path, k, "unknown key" + (f"; did you mean '{near[0]}'?" if near else f"; a study file takes {STUDY_KEYS}"))
        if "base" not in spec:
            fail_key(path, "base", "missing: the base case directory, relative to the study file")
        self.base = os.path.normpath(os.path.join(self.dir, spec["base"]))
        if not os.path.isfile(os.path.join(self.base, "case.toml")):
            fail_key(path, "base", f"{self.base} is not a case directory (no case.toml there)")
        self.combine = spec.get("combine", "product")
        if self.combine not in ("product", "zip"):
            fail_key(path, "combine", f"expected \"product\" or \"zip\", got {self.combine!r}")
        params = spec.get("parameters")
        if not isinstance(params, dict) or not params:
            fail_key(path, "parameters", "missing or empty: give at least one case key with its values")
        self.keys = list(params)
        self.values = {k: values_of(path, k, params[k]) for k in self.keys}
        if self.combine == "zip":
            lengths = {k: len(v) for k, v in self.values.items()}
            if len(set(lengths.values())) > 1:
                fail_key(path, "combine", "\"zip\" takes the i-th value of every parameter together, so every "
                         f"parameter needs as many values; got {lengths}")
        self.fixed = spec.get("set", {})
        if not isinstance(self.fixed, dict):
            fail_key(path, "set", "expected a table of case keys and values")
        for k in self.fixed:
            if k in params:
                fail_key(path, f"set.\"{k}\"", "also a parameter: give it in one place")
            if k == "output.directory":
                fail_key(path, f"set.\"{k}\"", "the study chooses each variant's output directory (STUDY/output/<variant>)")
        if "output.directory" in params:
            fail_key(path, "parameters.\"output.directory\"", "the study chooses each variant's output directory")
        cores = cores or os.cpu_count() or 1
        self.parallel = spec.get("parallel", cores)
        if not isinstance(self.parallel, int) or self.parallel < 1:
            fail_key(path, "parallel", f"expected a whole number >= 1 (variants at once), got {self.parallel!r}")
        self.threads = spec.get("threads", max(1, cores // self.parallel))
        if not isinstance(self.threads, int) or self.threads < 1:
            fail_key(path, "threads", f"expected a whole number >= 1 (OpenMP threads per variant), got {self.threads!r}")
        self.progress_interval = float(spec.get("progress_interval", 10.0))
        self.quicksand = spec.get("quicksand") or find_quicksand()
        self.output = os.path.join(self.dir, "output")
        self.variants = self.make_variants()

    def make_variants(self):
        combos = (itertools.product(*(self.values[k] for k in self.keys)) if self.combine == "product"
                  else zip(*(self.values[k] for k in self.keys)))
        variants = []
        for i, combo in enumerate(combos):
            params = dict(zip(self.keys, combo))
            name = f"{i + 1:02d}_" + "_".join(f"{short_name(k, self.keys)}={format_value(v)}" for k, v in params.items())
            out = os.path.join(self.output, name)
            sets = [f"{k}={toml_value(v)}" for k, v in self.fixed.items()]
            sets += [f"{k}={toml_value(v)}" for k, v in params.items()]
            sets.append(f"output.directory={toml_value(out)}")
            variants.append({"name": name, "params": params, "sets": sets, "out": out})
        return variants

    def command(self, verb, variant, resume=False):
        cmd = [self.quicksand, verb, self.base]
        for s in variant["sets"]:
            cmd += ["--set", s]
        if resume:
            cmd.append("--resume")
        return cmd


def find_quicksand():
    try:
        return running.find_quicksand()
    except running.QuicksandError as e:
        raise StudyError(str(e))


def check_all(study):
    """quicksand check on every variant; the study is refused if any fails, naming each. Returns
    each variant's report (what a scheduler reads the memory estimate from)."""
    failures, reports = [], {}
    for v in study.variants:
        r = subprocess.run(study.command("check", v), capture_output=True, text=True)
        if r.returncode != 0:
            message = (r.stderr.strip() or r.stdout.strip()).replace("quicksand: error: ", "")
            failures.append(f"  {v['name']}: {message}")
        reports[v["name"]] = r.stdout
    if failures:
        raise StudyError(f"{study.path}: {len(failures)} of {len(study.variants)} variants fail their check; "
                         "the study did not start:\n" + "\n".join(failures))
    return reports


def status_of(variant):
    try:
        with open(os.path.join(variant["out"], "study-status.json")) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def write_status(variant, status):
    os.makedirs(variant["out"], exist_ok=True)
    tmp = os.path.join(variant["out"], "study-status.json.tmp")
    with open(tmp, "w") as f:
        json.dump(status, f, indent=1)
    os.replace(tmp, os.path.join(variant["out"], "study-status.json"))


def resumable(variant):
    """Whether a variant's next run continues from its checkpoint: it has one, and it did not fail
    (a failed run starts again; an interrupted or scheduler-killed one resumes)."""
    status = status_of(variant)
    return os.path.isfile(os.path.join(variant["out"], "checkpoint.h5")) and not (status and status["state"] == "failed")


def run_variant(study, v, on_start=None, on_line=None, stopping=lambda: False):
    """Runs one variant as `quicksand run` (resuming when resumable), its output appended to
    STUDY/output/<variant>.log, and records how it ended in its study-status.json: 'finished', or
    'failed' with quicksand's error. Interrupted (exit 130 or 143, or `stopping()`) it records
    nothing: the next call resumes it. Returns (exit code, state text, wall seconds). The local
    scheduler calls it in a thread per variant, a Slurm job array in each task."""
    os.makedirs(os.path.dirname(v["out"]), exist_ok=True)
    resume = resumable(v)
    if status_of(v):
        os.remove(os.path.join(v["out"], "study-status.json"))
    env = dict(os.environ, OMP_NUM_THREADS=str(study.threads))
    cmd = study.command("run", v, resume)
    start = time.time()
    log_path = os.path.join(os.path.dirname(v["out"]), v["name"] + ".log")
    with open(log_path, "a") as log:
        log.write("$ " + " ".join(shlex.quote(c) for c in cmd) + "\n")
        log.flush()
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
                             start_new_session=True)
        if on_start:
            on_start(p, resume)
        last_error = ""
        for line in p.stdout:
            log.write(line)
            log.flush()
            line = line.rstrip()
            if "error" in line or "Error" in line:
                last_error = line
            if on_line:
                on_line(line, parse_fraction(line))
        code = p.wait()
    wall = time.time() - start
    if code == 0:
        write_status(v, {"state": "finished", "wall_seconds": wall, "resumed": resume})
        state = "finished"
    elif code in (130, 143) or stopping():
        state = "interrupted"  # no status: the next call resumes it
    else:
        error = last_error.replace("quicksand: error: ", "")
        write_status(v, {"state": "failed", "exit_code": code, "error": error})
        state = f"FAILED ({error[:200]})"
    return code, state, wall


class Runner:
    """Runs the variants `parallel` at a time and prints their progress."""

    def __init__(self, study, retry_failed=False, quiet=False):
        self.study, self.quiet = study, quiet
        self.retry_failed = retry_failed
        self.lock = threading.Lock()
        self.progress = {}  # name -> (fraction done, wall s, last line); wall live from started
        self.started = {}  # name -> wall clock at its start
        self.procs = {}
        self.stopping = False

    def todo(self):
        out = []
        for v in self.study.variants:
            s = status_of(v)
            if s and (s["state"] == "finished" or (s["state"] == "failed" and not self.retry_failed)):
                continue
            out.append(v)
        return out

    def run_one(self, v):
        start = time.time()

        def started(p, resume):
            with self.lock:
                self.procs[v["name"]] = p
                self.started[v["name"]] = start
                self.progress[v["name"]] = (0.0, 0.0, "starting" + (" (resuming)" if resume else ""))

        def line_read(line, frac):
            with self.lock:
                f0 = self.progress[v["name"]][0]
                self.progress[v["name"]] = (frac if frac is not None else f0, time.time() - start, line.strip())

        code, state, wall = run_variant(self.study, v, started, line_read, lambda: self.stopping)
        with self.lock:
            del self.procs[v["name"]]
            self.progress[v["name"]] = (1.0 if code == 0 else self.progress[v["name"]][0], wall, state)
        if not self.quiet:
            print(f"study: {v['name']}: {state} after {format_seconds(wall)}", flush=True)

    def run(self):
        todo = self.todo()
        done_before = len(self.study.variants) - len(todo)
        if not self.quiet:
            print(f"study: {len(self.study.variants)} variants of {self.study.base}; {done_before} done before, "
                  f"{len(todo)} to run, {self.study.parallel} at a time with {self.study.threads} thread(s) each",
                  flush=True)
        queue = list(todo)
        threads = []
        start = time.time()
        last_print = start

        def stop(signum, frame):
            self.stopping = True
            queue.clear()
            with self.lock:
                for p in self.procs.values():
                    try:
                        p.send_signal(signal.SIGINT)  # each run writes its checkpoint and stops
                    except ProcessLookupError:
                        pass

        old_int, old_term = signal.signal(signal.SIGINT, stop), signal.signal(signal.SIGTERM, stop)
        try:
            while queue or any(t.is_alive() for t in threads):
                threads = [t for t in threads if t.is_alive()]
                while queue and len(threads) < self.study.parallel and not self.stopping:
                    t = threading.Thread(target=self.run_one, args=(queue.pop(0),))
                    t.start()
                    threads.append(t)
                time.sleep(0.05)
                if not self.quiet and time.time() - last_print >= self.study.progress_interval:
                    last_print = time.time()
                    self.print_progress(todo, start)
        finally:
            signal.signal(signal.SIGINT, old_int)
            signal.signal(signal.SIGTERM, old_term)
        return not self.stopping

    def print_progress(self, todo, start):
        with self.lock:
            now = time.time()
            running = {n: (p[0], now - self.started[n], p[2]) for n, p in self.progress.items() if n in self.procs}
            finished = [p for n, p in self.progress.items() if n not in self.procs]
        for name, (frac, wall, line) in running.items():
            eta = wall * (1 - frac) / frac if frac > 0.005 else float("nan")
            print(f"  {name}: {100 * frac:5.1f} %  {format_seconds(wall)} so far, ETA {format_seconds(eta)}"
                  + ("" if frac > 0.005 else "  (no progress line from the run yet)"), flush=True)
        # overall: each running variant's remaining time, plus the queued ones at the mean run's length
        walls = [w / f for f, w, _ in list(running.values()) + finished if f > 0.005]
        mean = sum(walls) / len(walls) if walls else float("nan")
        remaining = sum(w * (1 - f) / f if f > 0.005 else mean for f, w, _ in running.values())
        queued = len(todo) - len(running) - len(finished)
        eta = (remaining + queued * mean) / self.study.parallel
        print(f"study: {len(finished)}/{len(todo)} done, {len(running)} running, {queued} queued; "
              f"{format_seconds(time.time() - start)} so far, ETA {format_seconds(eta)}", flush=True)


def parse_fraction(line):
    """The run's progress from its '  t = 12.5 s (20.8 %) ...' line, as a fraction."""
    if line.lstrip().startswith("t = ") and "(" in line and "%)" in line:
        try:
            return float(line[line.index("(") + 1:line.index("%)")]) / 100
        except ValueError:
            return None
    return None


def format_seconds(s):
    if s != s or s == float("inf"):
        return "?"
    s = int(round(s))
    return f"{s // 3600}h{s % 3600 // 60:02d}m" if s >= 3600 else f"{s // 60}m{s % 60:02d}s" if s >= 60 else f"{s}s"


def main(argv=None):
    ap = argparse.ArgumentParser(prog="study.py", description=__doc__.split("\n")[0])
    ap.add_argument("study", help="the study file (STUDY.toml)")
    ap.add_argument("--check", action="store_true", help="check every variant, run none")
    ap.add_argument("--collect", action="store_true", help="only write study.csv and the plots from finished runs")
    ap.add_argument("--retry-failed", action="store_true", help="run failed variants again")
    ap.add_argument("--no-plots", action="store_true", help="write study.csv without plots")
    ap.add_argument("--quiet", action="store_true", help="no progress lines")
    ap.add_argument("--scheduler", choices=["local", "slurm"], default="local",
                    help="run the variants here (local, the default) or as a Slurm job array (quicksand/slurm.py)")
    ap.add_argument("--slurm-task", metavar="TASKS.json", help=argparse.SUPPRESS)  # inside a job array's task
    args = ap.parse_args(argv)
    try:
        study = Study(args.study)
        if args.slurm_task:
            from . import slurm
            return slurm.run_task(study, args.slurm_task)
        if not args.collect:
            reports = check_all(study)
            if not args.quiet:
                print(f"study: all {len(study.variants)} variants pass their check", flush=True)
            if args.check:
                return 0
            if args.scheduler == "slurm":
                from . import slurm
                scheduler = slurm.SlurmScheduler(study, reports, args.retry_failed, args.quiet)
            else:
                scheduler = Runner(study, args.retry_failed, args.quiet)
            if not scheduler.run():
                again = f".venv/bin/python tools/study.py {shlex.quote(args.study)}"
                if args.scheduler != "local":
                    again += f" --scheduler {args.scheduler}"
                print(f"study: interrupted; the finished variants are kept, the others resume from their "
                      f"checkpoints: {again}", file=sys.stderr)
                return 130
        from . import figures
        table = figures.write_study_csv(study)
        if not args.quiet:
            print(f"study: {table}", flush=True)
        if not args.no_plots:
            from . import study_plots
            for path in study_plots.plot_study(study):
                if not args.quiet:
                    print(f"study: {path}", flush=True)
        failed = [v["name"] for v in study.variants if (status_of(v) or {}).get("state") != "finished"]
        if failed:
            print(f"study: {len(failed)} variant(s) did not finish (see study.csv's error column): {', '.join(failed)}",
                  file=sys.stderr)
            return 1
        return 0
    except StudyError as e:
        print(f"study.py: error: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
