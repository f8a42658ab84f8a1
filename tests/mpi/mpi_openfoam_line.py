#!/usr/bin/env python3
"""The OpenFOAM line on MPI ranks (ctest labels mpi and openfoam; issue 41, part 4).

The column of cases/verification/openfoam_short_tube (1D, stepped whole on every rank) fed by
its OpenFOAM tube (a wedge, 5 x 10 cells), run to 0.05 s:

 1. without system/decomposeParDict on 2 ranks, rank 0 solves the line and says so: series.csv
    is the one-rank run's, byte for byte;
 2. decomposed over 2 and over 3 ranks (decomposePar, method simple along the tube: the gate's
    faces on one rank, the reservoir's on another), each rank its processorN/: the gate's flux and
    pressure and the column's series within the line's solver tolerance of the one-rank run
    (tolerance 1e-6 of each quantity's scale; guard 1e-7, achieved about 1e-8); the same with a
    2D column, cut over the ranks as the line is (implicit coupling's rollback on each rank), under
    both time schemes;
 3. reconstructPar on output/openfoam/ gives the serial run's time folders, with its pressure
    field within 1e-6 m2/s2 (the p solver's tolerance is 1e-6 absolute);
 4. checkpoints across rank counts: 1 then 2 ranks, and 2 then 1, against 1 then 1 (the same
    stop at 0.05 s, so the same coupling windows), at the tolerance of 2;
 5. hostile: numberOfSubdomains 3 on 2 ranks, and a decomposeParDict whose simple split does not
    make numberOfSubdomains parts, are refused once each with exit 1, naming the file, within
    the timeout, the earlier output/ untouched;
 6. hostile: rank 1's processor folder damaged before a resume ends the run (no hang), naming
    the rank, the checkpoint intact.

usage: mpi_openfoam_line.py QUICKSAND "MPIEXEC ..." SOURCE_DIR WORK_DIR
"""
import csv
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

quicksand, mpiexec, source, work = sys.argv[1], shlex.split(sys.argv[2]), sys.argv[3], sys.argv[4]
TOLERANCE, GUARD = 1e-6, 1e-7
COMPARED = ("gate_flux", "gate_pressure", "reservoir_head", "q_mid", "cumulative_inflow", "water_surface")
failures = []


def fail(message):
    failures.append(message)
    print("FAIL: " + message, flush=True)


def decompose_dict(parts, split):
    return ("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
            f"numberOfSubdomains {parts};\nmethod simple;\nsimpleCoeffs {{ n ({split}); delta 0.001; }}\n")


def make_case(name, parts=None, split=None):
    case = os.path.join(work, name)
    shutil.copytree(os.path.join(source, "cases/verification/openfoam_short_tube"), case)
    if parts:
        with open(os.path.join(case, "reservoir/system/decomposeParDict"), "w") as f:
            f.write(decompose_dict(parts, split))
    return case


def run(case, ranks=1, end=0.05, resume=False, expect=0, extra=(), env=None):
    cmd = (([*mpiexec, "-np", str(ranks)] if ranks > 1 else []) + [quicksand, "run", case, "--set", f"time.end={end}"]
           + list(extra))
    if resume:
        cmd.append("--resume")
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300, env=dict(os.environ, **(env or {})))
    if expect is not None and p.returncode != expect:
        fail(f"{' '.join(cmd)}: exit {p.returncode}, expected {expect}:\n{p.stdout[-2000:]}\n{p.stderr[-3000:]}")
    return p


def series(case):
    with open(os.path.join(case, "output/series.csv")) as f:
        return list(csv.DictReader(f))


def compare(what, reference, other):
    """Each compared quantity's worst difference over the rows, relative to its scale."""
    a, b = series(reference), series(other)
    if len(a) != len(b) or [r["time"] for r in a] != [r["time"] for r in b]:
        fail(f"{what}: output times differ: {[r['time'] for r in a]} against {[r['time'] for r in b]}")
        return 0.0
    worst = 0.0
    for key in COMPARED:
        scale = max(abs(float(r[key])) for r in a) or 1.0
        difference = max(abs(float(x[key]) - float(y[key])) for x, y in zip(a, b)) / scale
        worst = max(worst, difference)
        if difference > TOLERANCE:
            fail(f"{what}: {key} differs by {difference:.3g} of its scale (tolerance {TOLERANCE:g})")
        elif difference > GUARD:
            fail(f"{what}: {key} differs by {difference:.3g} of its scale (guard {GUARD:g}, achieved about 1e-8)")
    print(f"{what}: worst difference {worst:.3g} of the scale", flush=True)
    return worst


def pressure_field(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform List<scalar>\s*\n(\d+)\n\((.*?)\n\)", text, re.S)
    return [float(v) for v in m.group(2).split()]


def time_folders(directory):
    def is_time(name):
        try:
            float(name)
            return True
        except ValueError:
            return False
    return sorted((n for n in os.listdir(directory) if is_time(n)), key=float)


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

# the one-rank run every other is compared with
serial = make_case("serial")
run(serial)

# 1. no decomposeParDict: rank 0 alone
alone = make_case("alone")
p = run(alone, ranks=2)
if "solved on rank 0 of 2" not in p.stdout:
    fail("a line without decomposeParDict on 2 ranks did not say that rank 0 solves it:\n" + p.stdout)
if open(os.path.join(serial, "output/series.csv")).read() != open(os.path.join(alone, "output/series.csv")).read():
    fail("a line solved on rank 0 of 2: series.csv is not the one-rank run's byte for byte")

# 2. decomposed over 2 and 3 ranks (check says how, once)
for ranks, split in ((2, "2 1 1"), (3, "3 1 1")):
    case = make_case(f"decomposed{ranks}", ranks, split)
    c = subprocess.run([*mpiexec, "-np", str(ranks), quicksand, "check", case], capture_output=True, text=True,
                       timeout=120)
    if c.returncode != 0 or c.stdout.count("the column is stepped whole on each") != 1:
        fail(f"check on {ranks} ranks (exit {c.returncode}) did not say once how the run is spread:\n"
             + c.stdout[-2000:] + c.stderr[-2000:])
    p = run(case, ranks=ranks)
    if f"decomposed over {ranks} MPI ranks" not in p.stdout:
        fail(f"the line on {ranks} ranks did not say it is decomposed:\n" + p.stdout)
    for r in range(ranks):
        if not os.path.isdir(os.path.join(case, f"output/openfoam/processor{r}/0.05")):
            fail(f"the line on {ranks} ranks wrote no output/openfoam/processor{r}/0.05")
    compare(f"decomposed over {ranks} ranks against one", serial, case)

# 2b. a 2D column beside the decomposed line, cut over the ranks too (12 columns: a block and its
# window of ghost points do not cover the grid), against one rank: implicit coupling repeats each
# window from every rank's own points (DoublePointSolver::saveWindowStart)
PLANE = ["--set", "grid.dimension=2", "--set", "grid.width=0.1116"]
for scheme in ("explicit", "semi_implicit"):
    extra = PLANE + ["--set", f'time.scheme="{scheme}"']
    plane1, plane2 = make_case(f"plane1_{scheme}"), make_case(f"plane2_{scheme}", 2, "2 1 1")
    run(plane1, extra=extra)
    c = subprocess.run([*mpiexec, "-np", "2", quicksand, "check", plane2, *extra], capture_output=True, text=True,
                       timeout=120)
    if c.returncode != 0 or "decomposition: 2 ranks, 2 x 1 blocks" not in c.stdout or "line is decomposed" not in c.stdout:
        fail(f"{scheme}: check of a 2D column beside a line on 2 ranks did not show the column's blocks and the "
             "line's decomposition:\n" + c.stdout[-2000:] + c.stderr[-2000:])
    p = run(plane2, ranks=2, extra=extra)
    if "blocks of whole columns" not in p.stdout or "stepped whole" in p.stdout:
        fail(f"{scheme}: a 2D column beside a line on 2 ranks was not cut over them:\n" + p.stdout)
    m = re.search(r"coupling: (\d+) windows, (\d+) model solves", p.stdout)
    if not m or int(m.group(2)) <= int(m.group(1)):
        fail(f"{scheme}: the 2D column's implicit coupling repeated no window (as many model solves as windows): "
             "the rollback was not exercised:\n" + p.stdout[-1500:])
    compare(f"a 2D column cut over 2 ranks ({scheme}), the line decomposed over them, against one rank",
            plane1, plane2)

# 3. reconstructPar gives the serial run's folders and fields
decomposed = os.path.join(work, "decomposed2")
env = dict(os.environ, WM_PROJECT_DIR=os.environ.get("WM_PROJECT_DIR", "/usr/share/openfoam"))
r = subprocess.run(["reconstructPar", "-case", os.path.join(decomposed, "output/openfoam")],
                   capture_output=True, text=True, env=env, timeout=300)
if r.returncode != 0:
    fail("reconstructPar of the decomposed line failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
else:
    mine, theirs = (time_folders(os.path.join(c, "output/openfoam")) for c in (serial, decomposed))
    if mine != theirs:
        fail(f"reconstructPar's time folders {theirs} are not the serial run's {mine}")
    else:
        a = pressure_field(os.path.join(serial, "output/openfoam", mine[-1], "p"))
        b = pressure_field(os.path.join(decomposed, "output/openfoam", mine[-1], "p"))
        worst = max(abs(x - y) for x, y in zip(a, b))
        print(f"reconstructed p at {mine[-1]}: worst difference {worst:.3g} m2/s2", flush=True)
        if len(a) != len(b) or worst > 1e-6:
            fail(f"the reconstructed p differs from the serial run's by {worst:.3g} m2/s2 (tolerance 1e-6)")

# 4. checkpoints across rank counts, against the same stop on one rank
chain11, chain12, chain21 = make_case("chain11"), make_case("chain12"), make_case("chain21", 2, "2 1 1")
run(chain11, end=0.05)
run(chain11, end=0.1, resume=True)
run(chain12, end=0.05)
with open(os.path.join(chain12, "reservoir/system/decomposeParDict"), "w") as f:
    f.write(decompose_dict(2, "2 1 1"))  # decomposed from the resume on
run(chain12, ranks=2, end=0.1, resume=True)
run(chain21, ranks=2, end=0.05)
os.remove(os.path.join(chain21, "reservoir/system/decomposeParDict"))  # one rank from the resume on
run(chain21, end=0.1, resume=True)
if any(n.startswith("processor") for n in os.listdir(os.path.join(chain21, "output/openfoam"))):
    fail("a decomposed line resumed on one rank kept its processor folders (reconstructPar should have joined them)")
compare("1 then 2 ranks against 1 then 1", chain11, chain12)
compare("2 then 1 rank against 1 then 1", chain11, chain21)

# 5. hostile decompositions: refused once, exit 1, earlier output untouched
for name, parts, split, said in (
        ("wrong_count", 3, "3 1 1", r"system/decomposeParDict: numberOfSubdomains 3, but quicksand runs on 2 MPI ranks"),
        ("does_not_fit", 2, "3 1 1", r"decomposePar could not decompose the line")):
    case = make_case(name, parts, split)
    os.makedirs(os.path.join(case, "output"))
    with open(os.path.join(case, "output/series.csv"), "w") as f:
        f.write("earlier results\n")
    try:
        p = run(case, ranks=2, expect=1)
    except subprocess.TimeoutExpired:
        fail(f"{name}: the run did not end within 300 s (a rank waiting for another)")
        continue
    count = len(re.findall(said, p.stderr))
    if count != 1:
        fail(f"{name}: the error was said {count} times, expected once:\n{p.stderr[-3000:]}")
    if open(os.path.join(case, "output/series.csv")).read() != "earlier results\n":
        fail(f"{name}: a refused run touched the earlier output/")

# 6. hostile: one rank's processor folder damaged by hand between a run and its resume. That rank
# fails to open its part while the other reads its own, waiting in OpenFOAM's exchanges with it:
# the failing rank says why (naming itself) and ends the run within its wait (QUICKSAND_OPENING_WAIT,
# 4 s here, 20 by default), exit non-zero,
# the checkpoint as it was
damaged = make_case("damaged", 2, "2 1 1")
run(damaged, ranks=2, end=0.05)
with open(os.path.join(damaged, "output/openfoam/processor1/0.05/p"), "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class volScalarField; object p; }\ninternalField garbage (\n")
checkpoint = open(os.path.join(damaged, "output/checkpoint.h5"), "rb").read()
start = time.monotonic()
try:
    p = run(damaged, ranks=2, end=0.1, resume=True, expect=None, env={"QUICKSAND_OPENING_WAIT": "4"})
    took = time.monotonic() - start
    print(f"a damaged processor folder on rank 1: exit {p.returncode} after {took:.1f} s", flush=True)
    if p.returncode == 0:
        fail("a resume with rank 1's processor folder damaged ran on:\n" + p.stdout[-1500:])
    if took > 4 + 30:
        fail(f"a damaged processor folder on rank 1: the run took {took:.1f} s to end, its wait is 4 s")
    if "error: rank 1 of 2" not in p.stderr or "output/openfoam/processor1/0.05/p" not in p.stderr:
        fail("a damaged processor folder on rank 1: the error does not name the rank and the damaged file:\n"
             + p.stderr[-3000:])
    if p.stderr.count("ill defined") != 1:
        fail("a damaged processor folder on rank 1: OpenFOAM's reason not said once:\n" + p.stderr[-3000:])
    if open(os.path.join(damaged, "output/checkpoint.h5"), "rb").read() != checkpoint:
        fail("a damaged processor folder on rank 1: the checkpoint changed")
except subprocess.TimeoutExpired:
    fail("a damaged processor folder on rank 1: the run hung (no end within 300 s)")
# both ranks' folders damaged alike: they fail alike and agree at once, the error said once
with open(os.path.join(damaged, "output/openfoam/processor0/0.05/p"), "w") as f:
    f.write("FoamFile { version 2.0; format ascii; class volScalarField; object p; }\ninternalField garbage (\n")
start = time.monotonic()
p = run(damaged, ranks=2, end=0.1, resume=True, expect=1)
took = time.monotonic() - start
print(f"both processor folders damaged: exit {p.returncode} after {took:.1f} s", flush=True)
if p.stderr.count("ill defined") != 1 or took > 15:
    fail(f"both processor folders damaged: the error said {p.stderr.count('ill defined')} times after {took:.1f} s, "
         "expected once, agreed at once:\n" + p.stderr[-3000:])

if failures:
    sys.exit(f"{len(failures)} failures")
print("the OpenFOAM line on MPI ranks: all checks passed")
