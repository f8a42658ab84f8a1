#!/usr/bin/env bash
# Sets up and builds quicksand, runs the main case and writes its plots (tools/run-case.sh).
#
#   bash tools/run-main.sh                 the main case
#   MAIN_CASE=cases/... bash tools/run-main.sh   another case directory
#
# Prints where the results are: series.csv, fields.h5 + fields.xdmf, series.png, profiles.png and
# fluidisation.png in the case's output directory.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The main job: the Deltares column fluidising at i0 = 1.5 (the paper's simulation A), fed through
# an OpenFOAM tube (cases/deltaresColumn); MAIN_CASE=cases/deltaresColumnLumped runs the
# standalone twin with the lumped tube.
main_case="${MAIN_CASE:-cases/deltaresColumn}"

if [[ ! -f "$main_case/case.toml" ]]; then
    echo "run-main.sh: no case.toml in '$main_case' (set MAIN_CASE to a case directory)" >&2
    exit 1
fi

bash tools/build.sh --openfoam
bash tools/run-case.sh "$main_case"
