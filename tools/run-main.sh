#!/usr/bin/env bash
# Builds quicksand, runs the main case and plots its time series.
#
#   bash tools/run-main.sh                 the main case
#   MAIN_CASE=cases/... bash tools/run-main.sh   another case directory
#
# Prints where the results are: series.csv, fields.h5 + fields.xdmf and series.png in the case's
# output directory.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The main job: the Deltares column coupled to the OpenFOAM U-tube (cases/deltaresColumn);
# MAIN_CASE=cases/deltaresColumnLumped runs the standalone version with a lumped reservoir.
main_case="${MAIN_CASE:-cases/deltaresColumn}"
build_dir="${QUICKSAND_BUILD_DIR:-build}"

if [[ ! -f "$main_case/case.toml" ]]; then
    echo "run-main.sh: no case.toml in '$main_case' (set MAIN_CASE to a case directory)" >&2
    exit 1
fi

bash tools/build.sh --openfoam

"$build_dir/mpm/quicksand" run "$main_case"

# The output directory is [output] directory in case.toml, relative to the case ("output" by
# default, see mpm/io/CaseConfig.hpp).
output_dir="$(/usr/bin/python3 - "$main_case/case.toml" <<'PY'
import sys, tomllib
with open(sys.argv[1], "rb") as f:
    case = tomllib.load(f)
print(case.get("output", {}).get("directory", "output"))
PY
)"
[[ "$output_dir" = /* ]] || output_dir="$main_case/$output_dir"

/usr/bin/python3 tools/plot_series.py "$output_dir"
/usr/bin/python3 tools/plot_profiles.py "$output_dir"

echo
echo "Results of $main_case:"
for f in series.csv fields.h5 fields.xdmf series.png profiles.png; do
    if [[ -e "$output_dir/$f" ]]; then
        echo "  $output_dir/$f"
    else
        echo "  $output_dir/$f (not written)"
    fi
done
