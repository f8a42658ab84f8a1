#!/usr/bin/env bash
# Runs a case and writes its plots (the quicksand command itself writes no pictures).
#
#   bash tools/run-case.sh CASE [quicksand run options, e.g. --resume]
#
# Writes, beside series.csv and fields.h5 in the case's output directory:
#   series.png        gate flux and pressure, head, sand surface, in/outflow (tools/plot_series.py)
#   profiles.png      pore pressure, effective stress, porosity along the column (plot_profiles.py)
#   fluidisation.png  bed height, filter velocity with the analytic lines, the porosity along the
#                     column against time with the fluidised region, the front with its fit
#                     (plot_fluidisation.py; front_fit.csv holds the fit)
# and for 2D and 3D runs (tools/plot_pipes.py; docs/piping.md):
#   pipes_frames.png  a strip of frames through the run: porosity per cell, fluidised cells
#                     outlined, pipes marked (3D: a vertical section through the main pipe and a
#                     horizontal one at mid height)
#   pipes.gif         the frames at every output time, animated
#   pipes.png         number of pipes, their share of the water, heights, wall or interior
# Expects a built quicksand (bash tools/build.sh); $QUICKSAND_BUILD_DIR as in build.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
case_dir="${1:?usage: bash tools/run-case.sh CASE [quicksand run options]}"
shift
build_dir="${QUICKSAND_BUILD_DIR:-build}"
if [[ ! -f "$case_dir/case.toml" ]]; then
    echo "run-case.sh: no case.toml in '$case_dir'" >&2
    exit 1
fi
if [[ ! -x "$build_dir/mpm/quicksand" ]]; then
    echo "run-case.sh: $build_dir/mpm/quicksand is not built (run bash tools/build.sh)" >&2
    exit 1
fi

"$build_dir/mpm/quicksand" run "$case_dir" "$@"

# the output directory: [output] directory of case.toml, relative to the case ("output")
output_dir="$(/usr/bin/python3 - "$case_dir/case.toml" <<'PY'
import sys, tomllib
with open(sys.argv[1], "rb") as f:
    case = tomllib.load(f)
print(case.get("output", {}).get("directory", "output"))
PY
)"
[[ "$output_dir" = /* ]] || output_dir="$case_dir/$output_dir"

/usr/bin/python3 tools/plot_series.py "$output_dir"
/usr/bin/python3 tools/plot_profiles.py "$output_dir"
if [[ -f "$output_dir/fields.h5" ]]; then
    /usr/bin/python3 tools/plot_fluidisation.py "$output_dir"
fi
if [[ -f "$output_dir/pipes.csv" && -f "$output_dir/fields.h5" ]]; then
    /usr/bin/python3 tools/plot_pipes.py "$output_dir"
fi

echo
echo "Results of $case_dir:"
for f in series.csv pipes.csv fields.h5 fields.xdmf checkpoint.h5 series.png profiles.png fluidisation.png front_fit.csv \
         pipes_frames.png pipes.png pipes.gif; do
    if [[ -e "$output_dir/$f" ]]; then
        echo "  $output_dir/$f"
    fi
done
