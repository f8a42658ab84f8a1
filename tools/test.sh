#!/usr/bin/env bash
# Builds quicksand and runs its test suite with CTest.
#
#   bash tools/test.sh                  every test
#   bash tools/test.sh -L verification  extra arguments go to ctest (here: one label only)
#
# Ends with CTest's summary line ("100% tests passed, 0 tests failed out of N") and exits with
# CTest's exit code. A selection that matches no test is an error, not a silent pass.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash tools/build.sh --openfoam   # CI runs the OpenFOAM tests too

build_dir="${QUICKSAND_BUILD_DIR:-build}"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT

# ctest's output is kept (tee) to check that its summary line was printed; PIPESTATUS gives
# ctest's own exit code, not tee's.
set +e
ctest --test-dir "$build_dir" --output-on-failure --no-tests=error -j2 "$@" 2>&1 | tee "$log"
rc=${PIPESTATUS[0]}
set -e

if ! grep -Eq '[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log"; then
    echo "test.sh: ctest printed no summary line (no tests ran?); ctest exit code $rc" >&2
    [[ $rc -ne 0 ]] || rc=1
fi
exit "$rc"
