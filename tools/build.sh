#!/usr/bin/env bash
# Builds quicksand (Release) after making sure the system packages are there.
#
#   bash tools/build.sh [--openfoam]     arguments go to tools/setup.sh
#
# The build directory is ./build, or $QUICKSAND_BUILD_DIR (relative to the repository root).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash tools/setup.sh "$@"

build_dir="${QUICKSAND_BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j2
