"""Studies on a Slurm cluster: every variant still to run is a task of one job array.

    .venv/bin/python tools/study.py STUDY.toml --scheduler slurm

The study is checked here first, as locally (quicksand check on every variant). Then one
`sbatch --array=0-(N-1)%parallel` job runs the variants still to run, `parallel` at a time, each
task with the study's `threads` (--cpus-per-task, OMP_NUM_THREADS) and the memory that `quicksand
check` estimates for the largest variant (x 1.5, at least 256 MiB). A task runs one variant
exactly as the local scheduler does (studies.run_variant: quicksand run, its log, its
study-status.json), so study.csv is the same to the last digit through either scheduler.

Progress comes from the scheduler (squeue: pending and running tasks) and from each running
variant's own progress lines (its STUDY/output/<variant>.log). A task that Slurm ended without a
status of its own (cancelled, out of time or memory, a node lost: its state from scontrol, or
from sacct once the controller has forgotten it) is reported as `killed` with Slurm's state in
study.csv's error column; its checkpoint is kept and the next run of the study resumes it. Ctrl-C
(or SIGTERM) here cancels the array (scancel): each task's quicksand writes its checkpoint, and the
same command resumes, as the local one does. The job script and the tasks' own output are in
STUDY/output/slurm/.
"""
import json
import math
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time

from . import studies

TOOLS = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
ENDED_BY_SLURM = {"CANCELLED", "TIMEOUT", "OUT_OF_MEMORY", "NODE_FAIL", "PREEMPTED", "FAILED", "BOOT_FAIL",
                  "DEADLINE", "REVOKED"}
_UNITS = {"B": 1, "KiB": 2**10, "MiB": 2**20, "GiB": 2**30, "TiB": 2**40}


def memory_estimate(report):
    """Bytes: `quicksand check`'s "estimated peak memory X MiB", or None."""
    m = re.search(r"estimated peak memory ([0-9.]+) (B|KiB|MiB|GiB|TiB)", report or "")
    return float(m.group(1)) * _UNITS[m.group(2)] if m else None


def _slurm(command, what):
    """Runs a Slurm command; a missing command or its failure is a StudyError saying which."""
    if not shutil.which(command[0]):
        raise studies.StudyError(f"--scheduler slurm: no '{command[0]}' on PATH: this machine has no Slurm client "
                                 "(Debian's slurm-client), or run the study with --scheduler local")
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        said = (done.stderr.strip() or done.stdout.strip()).splitlines()
        raise studies.StudyError(f"--scheduler slurm: {what} failed ({' '.join(command[:2])} ...): "
                                 + (said[-1] if said else f"exit {done.returncode}"))
    return done.stdout


class SlurmScheduler:
    """Runs a study's variants as a Slurm job array and follows them to the end."""

    def __init__(self, study, reports, retry_failed=False, quiet=False, python=None):
        self.study, self.quiet, self.retry_failed = study, quiet, retry_failed
        self.reports = reports
        self.python = python or sys.executable
        self.folder = os.path.join(study.output, "slurm")
        self.stopping = False

    def todo(self):
        out = []
        for v in self.study.variants:
            s = studies.status_of(v)
            if s and (s["state"] == "finished" or (s["state"] == "failed" and not self.retry_failed)):
                continue
            out.append(v)
        return out

    def memory_mib(self, todo):
        estimates = [memory_estimate(self.reports.get(v["name"])) for v in todo]
        largest = max((e for e in estimates if e), default=0.0)
        return max(256, int(math.ceil(1.5 * largest / 2**20)))

    def job_script(self, todo, tasks_file):
        lines = [
            "#!/bin/bash",
            f"#SBATCH --job-name=quicksand-{os.path.basename(self.study.dir)}",
            f"#SBATCH --array=0-{len(todo) - 1}%{self.study.parallel}",
            f"#SBATCH --cpus-per-task={self.study.threads}",
            f"#SBATCH --mem={self.memory_mib(todo)}M",
            f"#SBATCH --output={self.folder}/task_%a.out",
            f"#SBATCH --chdir={self.study.dir}",
            "# written by quicksand/slurm.py: one task per variant of STUDY/output/slurm/tasks.json",
            f"export OMP_NUM_THREADS={self.study.threads}",
            f"export QUICKSAND={shlex.quote(os.path.abspath(self.study.quicksand))}  # the binary the study was checked with",
            f"export PYTHONPATH={shlex.quote(TOOLS)}${{PYTHONPATH:+:$PYTHONPATH}}",
            f"exec {shlex.quote(self.python)} {shlex.quote(os.path.join(TOOLS, 'study.py'))} {shlex.quote(self.study.path)} "
            f"--slurm-task {shlex.quote(tasks_file)}",
        ]
        return "\n".join(lines) + "\n"

    def submit(self, todo):
        os.makedirs(self.folder, exist_ok=True)
        tasks_file = os.path.join(self.folder, "tasks.json")
        with open(tasks_file, "w") as f:
            json.dump([v["name"] for v in todo], f, indent=1)
        script = os.path.join(self.folder, "array.sh")
        with open(script, "w") as f:
            f.write(self.job_script(todo, tasks_file))
        out = _slurm(["sbatch", "--parsable", script], "submitting the job array")
        return out.strip().split(";")[0]

    def queued(self, job):
        """{task index: state} of the array's tasks Slurm still holds (pending, running, ...)."""
        out = _slurm(["squeue", "--noheader", "--array", "--jobs", job, "--format=%K %T"], "squeue")
        states = {}
        for line in out.splitlines():
            parts = line.split()
            if len(parts) == 2 and parts[0].isdigit():
                states[int(parts[0])] = parts[1]
        return states

    def final_state(self, job, index):
        """How Slurm ended task `index`: scontrol's JobState while the controller remembers the task
        (MinJobAge, 300 s by default), else sacct's State (a cluster with accounting)."""
        task = f"{job}_{index}"
        done = subprocess.run(["scontrol", "show", "job", task], capture_output=True, text=True, timeout=60)
        m = re.search(r"JobState=(\S+)", done.stdout)
        if m:
            return m.group(1)
        if shutil.which("sacct"):
            try:
                done = subprocess.run(["sacct", "--noheader", "--parsable2", "-X", "-j", task, "-o", "State"],
                                      capture_output=True, text=True, timeout=60)
            except subprocess.TimeoutExpired:
                return "UNKNOWN"
            words = done.stdout.split()
            if done.returncode == 0 and words:
                return words[0]
        return "UNKNOWN"

    def task_output(self, k):
        """The last line task k wrote to its output file (STUDY/output/slurm/task_K.out)."""
        try:
            with open(os.path.join(self.folder, f"task_{k}.out")) as f:
                lines = [line.strip() for line in f if line.strip()]
        except OSError:
            return ""
        return lines[-1] if lines else ""

    def progress_of(self, v):
        """The running variant's last progress fraction, from its log."""
        try:
            with open(os.path.join(os.path.dirname(v["out"]), v["name"] + ".log")) as f:
                lines = f.readlines()[-20:]
        except OSError:
            return None
        for line in reversed(lines):
            frac = studies.parse_fraction(line.rstrip())
            if frac is not None:
                return frac
        return None

    def run(self):
        todo = self.todo()
        if not self.quiet:
            print(f"study: {len(self.study.variants)} variants of {self.study.base}; "
                  f"{len(self.study.variants) - len(todo)} done before, {len(todo)} to run on Slurm, "
                  f"{self.study.parallel} at a time with {self.study.threads} thread(s) each", flush=True)
        if not todo:
            return True
        job = self.submit(todo)
        if not self.quiet:
            print(f"study: submitted job array {job} ({len(todo)} tasks; {self.folder}/array.sh)", flush=True)

        def stop(signum, frame):
            if not self.stopping:
                self.stopping = True
                subprocess.run(["scancel", job], capture_output=True)

        old_int, old_term = signal.signal(signal.SIGINT, stop), signal.signal(signal.SIGTERM, stop)
        reported, last_print, start = set(), 0.0, time.time()
        try:
            while True:
                queued = self.queued(job)
                for k, v in enumerate(todo):
                    if k in queued or k in reported:
                        continue
                    reported.add(k)
                    self.ended(job, k, v)
                if not queued:
                    break
                if not self.quiet and time.time() - last_print >= self.study.progress_interval:
                    last_print = time.time()
                    self.print_progress(todo, queued, reported, start)
                time.sleep(0.5)
        finally:
            signal.signal(signal.SIGINT, old_int)
            signal.signal(signal.SIGTERM, old_term)
        return not self.stopping

    def ended(self, job, k, v):
        """A task Slurm no longer holds: its variant's status, or Slurm's word on it."""
        status = studies.status_of(v)
        if status:
            state = status["state"]
            if state == "failed":
                state = f"FAILED ({status.get('error', '')[:200]})"
        elif self.stopping:
            state = "interrupted"  # cancelled by us: resumes next time
        else:
            slurm_state = self.final_state(job, k)
            error = (f"Slurm ended task {job}_{k} ({slurm_state}) before the run did; its checkpoint is kept and the "
                     "next run of the study resumes it")
            said = self.task_output(k)
            if slurm_state == "FAILED" and said:  # the task itself failed, before or around its run
                error = f"task {job}_{k} failed ({self.folder}/task_{k}.out): {said}"
            if slurm_state in ENDED_BY_SLURM or slurm_state == "UNKNOWN":
                studies.write_status(v, {"state": "killed", "error": error, "slurm_state": slurm_state})
            state = f"killed ({slurm_state})"
        if not self.quiet:
            print(f"study: {v['name']}: {state}", flush=True)

    def print_progress(self, todo, queued, reported, start):
        running = [k for k, s in queued.items() if s == "RUNNING"]
        for k in running:
            frac = self.progress_of(todo[k])
            print(f"  {todo[k]['name']}: " + (f"{100 * frac:5.1f} %" if frac is not None else "started"), flush=True)
        pending = sum(1 for s in queued.values() if s == "PENDING")
        print(f"study: {len(reported)}/{len(todo)} done, {len(running)} running, {pending} pending on Slurm; "
              f"{studies.format_seconds(time.time() - start)} so far", flush=True)


def run_task(study, tasks_file):
    """Inside a task of the array: runs variant SLURM_ARRAY_TASK_ID of tasks_file. SIGTERM (scancel,
    a time limit) goes on to quicksand, which writes its checkpoint; the task then exits 143."""
    with open(tasks_file) as f:
        names = json.load(f)
    index = int(os.environ.get("SLURM_ARRAY_TASK_ID", "-1"))
    if not 0 <= index < len(names):
        raise studies.StudyError(f"{tasks_file}: no task {index} (SLURM_ARRAY_TASK_ID) among {len(names)}")
    variant = next((v for v in study.variants if v["name"] == names[index]), None)
    if variant is None:
        raise studies.StudyError(f"{tasks_file}: variant {names[index]} is not in {study.path} any more")
    child = {}

    def forward(signum, frame):
        if "p" in child:
            child["p"].send_signal(signum)

    signal.signal(signal.SIGTERM, forward)
    signal.signal(signal.SIGINT, forward)
    code, state, wall = studies.run_variant(study, variant, on_start=lambda p, resume: child.update(p=p))
    print(f"study task {index}: {variant['name']}: {state} after {studies.format_seconds(wall)}", flush=True)
    return 0 if code == 0 else (code if code in (130, 143) else 1)
