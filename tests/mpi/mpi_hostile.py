#!/usr/bin/env python3
"""Runs on MPI ranks that lose a rank or meet an error on one rank only (ctest labels mpi and
hostile; issue 41): each ends every rank within the timeout, says why, and leaves the last
checkpoint whole, so the run resumes from it.

 1. a rank killed (SIGKILL) mid-run: mpirun ends the other rank and exits non-zero; the last
    checkpoint resumes on one rank;
 2. an error on rank 0 alone inside the run: the step files' folder (output/fields/) removed
    under a running 2-rank run, so that rank 0, which alone writes the fields, cannot write the
    next output. Rank 0 says so, naming itself, and MPI_Abort ends the other rank, which would
    otherwise wait for rank 0 in the next step's reduction; the checkpoint resumes;
 3. SIGTERM to one rank: both stop at the same step, the checkpoint written there (no periodic
    one), the interruption said once, mpirun exits 143, the checkpoint resumes;
 4. SIGTERM to mpirun, which forwards it: the same, mpirun exiting non-zero (1: its own status).

The column is the piping tests' random bed, 24 columns wide (cut into 2 blocks of 12).

usage: mpi_hostile.py QUICKSAND "MPIEXEC ..." SOURCE_DIR WORK_DIR
"""
import os
import shlex
import shutil
import signal
import subprocess
import sys
import time

quicksand, mpiexec, source, work = sys.argv[1], shlex.split(sys.argv[2]), sys.argv[3], sys.argv[4]
# Under tools/test.sh's AddressSanitizer stage, LeakSanitizer reports Open MPI's own allocations
# at exit (its dlopen'ed components, frames of no module) and turns an exit status into 1: the
# statuses are what these runs check, so leaks are not looked for here (the serial tests do)
os.environ["ASAN_OPTIONS"] = ":".join(filter(None, [os.environ.get("ASAN_OPTIONS", ""), "detect_leaks=0"]))
TIMEOUT = 120  # s for a run to end once its trouble began
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, flush=True)


def make_case(name):
    case = os.path.join(work, name)
    os.makedirs(case)
    shutil.copy(os.path.join(source, "cases/verification/random_bed/case.toml"), case)
    return case


def start(case, *extra):
    cmd = [*mpiexec, "-np", "2", quicksand, "run", case, "--set", "grid.width=0.1488", "--set", "time.end=30",
           "--set", "time.output_interval=0.01", "--set", "time.checkpoint_interval=0.01", "--quiet", *extra]
    return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)


def wait_for(path, process, seconds=180):
    """Until `path` exists (and a little longer, so that a checkpoint follows it)."""
    end = time.time() + seconds
    while time.time() < end and process.poll() is None:
        if os.path.exists(path):
            return True
        time.sleep(0.2)
    return False


def ranks_of(process):
    """The quicksand processes mpirun started (its children), from /proc (no procps needed)."""
    children = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                stat = f.read()
        except OSError:
            continue
        # pid (comm) state ppid ...: the name may hold spaces, so split after its ')'
        fields = stat[stat.rindex(")") + 2:].split()
        if int(fields[1]) == process.pid and "quicksand" in stat[stat.index("(") + 1:stat.rindex(")")]:
            children.append(int(entry))
    return sorted(children)


def finish(process, what):
    try:
        out, err = process.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        fail(f"{what}: the run did not end within {TIMEOUT} s (a rank waiting for another)")
    return process.returncode, out, err


def resumes(case, what):
    # to two outputs past the last one written (checkpoints fall on the outputs here)
    with open(os.path.join(case, "output/series.csv")) as f:
        last = float(f.read().strip().splitlines()[-1].split(",")[0])
    p = subprocess.run([quicksand, "run", case, "--set", "grid.width=0.1488", "--resume", "--set",
                        f"time.end={last + 0.02:.6f}", "--quiet"], capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        fail(f"{what}: the last checkpoint does not resume on one rank (exit {p.returncode}):\n{p.stderr[-2000:]}")
    else:
        print(f"{what}: the checkpoint resumed on one rank", flush=True)


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# 1. a rank killed
case = make_case("killed")
run = start(case, "--set", "output.fields=false")
if not wait_for(os.path.join(case, "output/checkpoint.h5"), run):
    fail("killed: no checkpoint written before the run ended: " + (run.communicate()[1] or "")[-2000:])
else:
    time.sleep(1.0)  # the run goes on past its first checkpoint
    ranks = ranks_of(run)
    if len(ranks) != 2:
        fail(f"killed: mpirun's children are {ranks}, expected two ranks")
    else:
        os.kill(ranks[1], signal.SIGKILL)
        rc, out, err = finish(run, "killed")
        print(f"killed: a rank killed, mpirun exited {rc}", flush=True)
        if rc == 0:
            fail("killed: mpirun exited 0 after a rank was killed")
        resumes(case, "killed")

# 2. an error on rank 0 alone
case = make_case("rank0_error")
run = start(case)
steps = os.path.join(case, "output/fields")
if not wait_for(os.path.join(case, "output/checkpoint.h5"), run):
    fail("rank0_error: no checkpoint written before the run ended: " + (run.communicate()[1] or "")[-2000:])
elif not os.path.isdir(steps):
    fail(f"rank0_error: no {steps} to remove (the field writer's layout changed?)")
else:
    time.sleep(0.5)
    os.rename(steps, steps + ".gone")  # at once: rank 0 may be writing a step file into it
    rc, out, err = finish(run, "rank0_error")
    print(f"rank0_error: output/fields/ moved away under the run, mpirun exited {rc}", flush=True)
    said = err.count("quicksand: error: rank 0:")
    if rc == 0:
        fail("rank0_error: the run went on without its step files' folder and exited 0")
    elif said != 1:
        fail(f"rank0_error: rank 0's error was said {said} times, expected once:\n{err[-3000:]}")
    resumes(case, "rank0_error")

# 3 and 4. SIGTERM to one rank, and to mpirun (which forwards it to the ranks): every rank stops at
# the same step, the checkpoint is written there (the periodic ones are off), the message
# is said once, and the run resumes. mpirun exits 143 when a rank alone was signalled (the ranks'
# status), and non-zero when it was signalled itself (Open MPI 4.1: 1, its own status then).
def interrupted(name, signal_mpirun):
    case = make_case(name)
    run = start(case, "--set", "output.fields=false", "--set", "time.checkpoint_interval=1000")
    series = os.path.join(case, "output/series.csv")
    if not wait_for(series, run):
        fail(f"{name}: no output before the run ended: " + (run.communicate()[1] or "")[-2000:])
        return
    time.sleep(1.0)
    ranks = ranks_of(run)
    if len(ranks) != 2:
        fail(f"{name}: mpirun's children are {ranks}, expected two ranks")
        os.killpg(run.pid, signal.SIGKILL)
        return
    os.kill(run.pid if signal_mpirun else ranks[1], signal.SIGTERM)
    rc, out, err = finish(run, name)
    said = err.count("interrupted by SIGTERM")
    print(f"{name}: mpirun exited {rc}, the interruption said {said} times", flush=True)
    if rc == 0 or (not signal_mpirun and rc != 143):
        fail(f"{name}: mpirun exited {rc}, expected {'non-zero' if signal_mpirun else 143}:\n{err[-2000:]}")
    if said != 1:
        fail(f"{name}: the interruption was said {said} times, expected once:\n{err[-3000:]}")
    if not os.path.exists(os.path.join(case, "output/checkpoint.h5")):
        fail(f"{name}: no checkpoint written at the interruption (the interval was 1000 s)")
        return
    resumes(case, name)


interrupted("sigterm_rank", False)
interrupted("sigterm_mpirun", True)

if failures:
    sys.exit(f"{len(failures)} failures")
print("ranks that fail: all checks passed")
