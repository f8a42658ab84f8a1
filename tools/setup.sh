#!/usr/bin/env bash
# Installs the system packages quicksand needs to build, test and plot (Debian/Ubuntu, apt-get).
#
#   bash tools/setup.sh              compiler, CMake, Eigen, HDF5, toml++, GoogleTest/Mock,
#                                    Google Benchmark, Python plotting
#   bash tools/setup.sh --openfoam   the same plus Debian's `openfoam` package (OpenFOAM reservoir)
#
# Idempotent: packages already installed are skipped (checked with dpkg-query), and apt-get
# update runs only when something is missing, so a second run installs nothing and says so.
# Uses sudo only when not run as root.
set -euo pipefail

usage() { sed -n '2,10p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

packages=(cmake g++ make pkg-config libeigen3-dev libhdf5-dev libtomlplusplus-dev
          libgtest-dev libgmock-dev libbenchmark-dev
          python3-matplotlib python3-numpy python3-h5py)
with_openfoam=false
for arg in "$@"; do
    case "$arg" in
        --openfoam) with_openfoam=true ;;
        -h|--help) usage; exit 0 ;;
        *) echo "setup.sh: unknown option '$arg' (known: --openfoam, --help)" >&2; exit 2 ;;
    esac
done
if $with_openfoam; then packages+=(openfoam); fi

is_installed() {
    [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

# apt-get needs root; sudo drops the environment, hence `env` for DEBIAN_FRONTEND.
as_root() {
    if [[ "$(id -u)" -eq 0 ]]; then
        env DEBIAN_FRONTEND=noninteractive "$@"
    else
        sudo env DEBIAN_FRONTEND=noninteractive "$@"
    fi
}

# TODO(OpenFOAM reservoir, later issue): Debian's `openfoam` package ships the libraries
# (/usr/lib/libOpenFOAM.so, libfiniteVolume, ...) but no headers. foamCoupling/ will need the
# headers of the same version (Debian source package openfoam 1912.200626-1, fetched with a
# private deb-src list so the machine's apt configuration stays untouched), unpacked into flat
# lnInclude/ folders for src/OpenFOAM, src/finiteVolume, src/meshTools, src/OSspecific/POSIX,
# and their location handed to CMake. See /work/shared/design/openfoam-embedding.md.
setup_openfoam_headers() {
    echo "setup.sh: TODO: OpenFOAM headers for foamCoupling/ are not set up yet;" \
         "the build will not include the OpenFOAM reservoir." >&2
}

missing=()
for p in "${packages[@]}"; do
    is_installed "$p" || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "setup.sh: all ${#packages[@]} required packages are already installed; nothing to install."
else
    echo "setup.sh: installing ${#missing[@]} missing package(s): ${missing[*]}"
    as_root apt-get update
    as_root apt-get install -y --no-install-recommends "${missing[@]}"
    echo "setup.sh: done."
fi

if $with_openfoam; then setup_openfoam_headers; fi
