#!/usr/bin/env bash
# Builds quicksand and runs its test suite with CTest.
#
#   bash tools/test.sh                  every test
#   bash tools/test.sh -L verification  extra arguments go to ctest (here: one label only)
#
# Without arguments it then runs the Python package's tests (pytest, tools/tests), builds a second
# tree with AddressSanitizer and UBSan (build-sanitize) and runs the fast labels (unit, hostile,
# resume, cli) there too (QUICKSAND_SANITIZE=0 skips it),
# and a third with clang and libFuzzer (build-fuzz) whose three fuzzers run 20 s each
# (tests/fuzz; QUICKSAND_FUZZ=0 skips it, QUICKSAND_FUZZ_SECONDS sets the time).
#
# Ends with CTest's summary line ("100% tests passed, 0 tests failed out of N") and exits with
# CTest's exit code. A selection that matches no test is an error, not a silent pass.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# Each stage's wall time is said at the end (CI's 45 minutes: which stage to cut)
stage_times=()
stage_start=$SECONDS
stage_done() { stage_times+=("$1 $((SECONDS - stage_start)) s"); stage_start=$SECONDS; }

bash tools/build.sh --openfoam --mpi --slurm   # CI runs the OpenFOAM, MPI and Slurm tests too
stage_done "set-up and build:"

build_dir="${QUICKSAND_BUILD_DIR:-build}"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT

# ctest's output is kept (tee) to check that its summary line was printed; PIPESTATUS gives
# ctest's own exit code, not tee's.
set +e
ctest --test-dir "$build_dir" --output-on-failure --no-tests=error -j2 "$@" 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
set -e
stage_done "ctest:"

# The fast labels again under AddressSanitizer and UndefinedBehaviorSanitizer (no OpenFOAM, which
# is not built for them; the slow verification runs stay out to keep CI short). Only when the whole
# suite is asked for: `bash tools/test.sh -L verification` runs that label alone. QUICKSAND_SANITIZE=0
# skips it. Each extra stage reports its own failure and sets the exit code, but never stops the
# script before the suite's summary line.
sanitizer_stage() {
    local dir="${build_dir}-sanitize"
    # line tables only (-g1): ASan's reports keep file and line, and the build takes 449 s instead
    # of 604 s here (2026-12-08), a quarter of the stage
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DQUICKSAND_SANITIZE=ON \
        -DQUICKSAND_WITH_OPENFOAM=OFF -DQUICKSAND_WITH_PYTHON=OFF -DQUICKSAND_BUILD_BENCHMARKS=OFF >/dev/null || return 1
    # only what those labels run: the verification, validation and MPI binaries, the larger
    # part of a build, are not run here (CI's 45 minutes)
    cmake --build "$dir" -j2 --target quicksand quicksand_unit_tests quicksand_resume_tests \
        quicksand_study_StudyResume quicksand_study_HostileStudies >/dev/null || return 1
    # the three longest (166, 81 and 74 s here under the sanitizers, half the stage) stay out: the
    # semi-implicit step, its resume and 2D pipes' resume are still run by shorter tests here
    ctest --test-dir "$dir" --output-on-failure --no-tests=error -j2 -L 'unit|hostile|resume|cli' \
        -E 'Resume.A2DRunWithPipesResumesWithTheSamePipesCsv|Resume.ASemiImplicitRunWithCGResumesBitIdentically|Determinism.OneAndTwoThreadsGiveIdenticalResultsWithTheSemiImplicitStep' 2>&1 \
        | grep -E '^(.*\*\*\*|[0-9]+% tests passed)' | sed 's/^/sanitizers: /'
    return "${PIPESTATUS[0]}"
}

# libFuzzer on the case loader, the checkpoint file and the checkpoint's state (tests/fuzz/README.md)
fuzz_stage() {
    local dir="${build_dir}-fuzz"
    bash tools/setup.sh --fuzz >/dev/null || return 1
    CC=clang CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQUICKSAND_FUZZ=ON \
        -DQUICKSAND_FUZZ_SECONDS="${QUICKSAND_FUZZ_SECONDS:-20}" -DQUICKSAND_BUILD_TESTS=OFF \
        -DQUICKSAND_WITH_OPENFOAM=OFF -DQUICKSAND_WITH_PYTHON=OFF -DQUICKSAND_BUILD_BENCHMARKS=OFF >/dev/null || return 1
    cmake --build "$dir" -j2 --target fuzz_case_loader fuzz_checkpoint fuzz_checkpoint_state quicksand \
        >/dev/null || return 1
    ctest --test-dir "$dir" --output-on-failure --no-tests=error -j2 -L fuzz -V 2>&1 \
        | grep -E '(: stat::|\*\*\*|found a defect|[0-9]+% tests passed)' | sed 's/^[0-9]*: //; s/^/fuzz: /'
    return "${PIPESTATUS[0]}"
}

# The Python package's tests (tools/tests: the readers on outputs this build writes, the runner)
# under pytest, in the virtual environment setup.sh made (tools/setup.sh: .venv), with this
# build's quicksand
python_stage() {
    QUICKSAND="$(realpath "$build_dir/mpm/quicksand")" QUICKSAND_BUILD_DIR="$(realpath "$build_dir")" .venv/bin/python -m pytest -q -p no:cacheprovider tools/tests 2>&1 \
        | tail -n 30 | grep -E '(passed|failed|error|Error|FAILED)' | sed 's/^/pytest: /'
    return "${PIPESTATUS[0]}"
}

if [[ $# -eq 0 ]]; then
    if ! python_stage; then echo "test.sh: the Python package's tests failed" >&2; rc=1; fi
    stage_done "pytest:"
fi
if [[ $# -eq 0 && "${QUICKSAND_SANITIZE:-1}" != 0 ]]; then
    if ! sanitizer_stage; then echo "test.sh: the sanitizer stage failed" >&2; rc=1; fi
    stage_done "sanitizers (build and run):"
fi
if [[ $# -eq 0 && "${QUICKSAND_FUZZ:-1}" != 0 ]]; then
    if ! fuzz_stage; then echo "test.sh: the fuzzing stage failed" >&2; rc=1; fi
    stage_done "fuzzers (set-up, build and run):"
fi

for t in "${stage_times[@]}"; do echo "test.sh: $t"; done
if [[ $# -eq 0 ]]; then
    # ctest's summary line of the whole suite, last, for CI
    grep -E '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -1
fi

if ! grep -Eq '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log"; then
    echo "test.sh: ctest printed no summary line (no tests ran?); ctest exit code $rc" >&2
    [[ $rc -ne 0 ]] || rc=1
fi
exit "$rc"
