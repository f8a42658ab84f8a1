#!/usr/bin/env bash
# Installs the system packages quicksand needs to build, test and plot (Debian/Ubuntu, apt-get).
#
#   bash tools/setup.sh              compiler, CMake, Eigen, HDF5, toml++, GoogleTest/Mock,
#                                    Google Benchmark, hypre (its AMG is benchmarked against the
#                                    pressure solvers), Python (numpy, pandas, h5py, matplotlib,
#                                    pytest) and the quicksand Python package in .venv, pybind11
#                                    (the solver's Python binding)
#   bash tools/setup.sh --fuzz       the same plus clang with libFuzzer and OpenMP (tests/fuzz)
#   bash tools/setup.sh --slurm      the same plus Slurm's daemons and client and munge: the
#                                    study tests start a one-node cluster of their own (a user's
#                                    studies need only the cluster's sbatch, squeue and scancel)
#   bash tools/setup.sh --mpi        the same plus Debian's Open MPI (libopenmpi-dev, mpirun): the
#                                    build runs on MPI ranks and the mpi tests run
#   bash tools/setup.sh --openfoam   the same plus Debian's `openfoam` package (OpenFOAM reservoir),
#                                    its tutorials (`openfoam-examples`)
#                                    and its headers: the source package of the installed version,
#                                    fetched once into ~/.cache/quicksand/openfoam-src (or
#                                    $QUICKSAND_CACHE_DIR/openfoam-src) without touching apt's config
#
# Idempotent: packages already installed are skipped (checked with dpkg-query), and apt-get
# update runs only when something is missing, so a second run installs nothing and says so.
# Uses sudo only when not run as root.
set -euo pipefail

usage() { sed -n '2,23p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

packages=(cmake g++ make pkg-config libeigen3-dev libhdf5-dev zlib1g-dev libtomlplusplus-dev liblapack-dev
          libgtest-dev libgmock-dev libbenchmark-dev libhypre-dev
          python3-matplotlib python3-numpy python3-h5py python3-pandas python3-pytest python3-venv python3-setuptools python3-wheel
          python3-dev pybind11-dev)
with_openfoam=false
for arg in "$@"; do
    case "$arg" in
        --openfoam) with_openfoam=true ;;
        --fuzz) packages+=(clang libclang-rt-dev libomp-dev) ;;
        --mpi) packages+=(libopenmpi-dev openmpi-bin) ;;
        --slurm) packages+=(slurmctld slurmd slurm-client munge) ;;
        -h|--help) usage; exit 0 ;;
        *) echo "setup.sh: unknown option '$arg' (known: --openfoam, --mpi, --slurm, --fuzz, --help)" >&2; exit 2 ;;
    esac
done
# the OpenFOAM headers come from the source package, checked with the Debian archive keyring:
# its .orig tarball is .tar.bz2 (tar runs bzip2), the Debian part .tar.xz (xz-utils)
# openfoam-examples: OpenFOAM's own tutorials; a stock pimpleFoam tutorial is coupled as the feed
# line in the tests (tests/openfoam/test_UserCases.cpp) and the docs' walkthrough
if $with_openfoam; then packages+=(openfoam openfoam-examples bzip2 xz-utils debian-archive-keyring); fi

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

# OpenFOAM headers for foamCoupling/. Debian's `openfoam` package ships the libraries
# (/usr/lib/libOpenFOAM.so, libfiniteVolume, ...) but no headers, so they come from Debian's
# source package of exactly the installed version, fetched with apt-get through a private
# deb-src list, private index and cache directories (the machine's apt configuration and state
# in /etc/apt, /var/lib/apt and /var/cache/apt stay untouched), and unpacked (src/, META-INFO/,
# the icoFoam and pimpleFoam solvers and the cavity tutorial only) into
#     ${QUICKSAND_CACHE_DIR:-$HOME/.cache/quicksand}/openfoam-src/openfoam-<source version>/
# where cmake/FindOpenFOAM.cmake looks for it (CMake cache variable OPENFOAM_SOURCE_DIR). Once
# that tree is complete for the installed version nothing is downloaded again. Needs no root.
# QUICKSAND_DEBIAN_MIRROR overrides the archive (default http://deb.debian.org/debian).
# See /work/shared/design/openfoam-embedding.md.
setup_openfoam_headers() {
    local cache="${QUICKSAND_CACHE_DIR:-$HOME/.cache/quicksand}/openfoam-src"
    local srcver
    srcver="$(dpkg-query -W -f='${source:Version}' openfoam 2>/dev/null || true)"
    if [[ -z "$srcver" ]]; then
        echo "setup.sh: the openfoam package is not installed; cannot fetch its headers." >&2
        return 1
    fi
    local upstream="${srcver#*:}"            # drop an epoch, if any
    local tree="$cache/openfoam-$upstream"
    # What is unpacked: the library sources (headers and templates), the version files, the two
    # incompressible solvers foamCoupling/ follows and the cavity tutorial (a small test case).
    local parts=(src META-INFO applications/solvers/incompressible/icoFoam
                 applications/solvers/incompressible/pimpleFoam
                 tutorials/incompressible/icoFoam/cavity)
    local stamp="$srcver ${parts[*]}"
    if [[ -f "$tree/.quicksand-complete" && "$(cat "$tree/.quicksand-complete")" == "$stamp" ]]; then
        echo "setup.sh: OpenFOAM $srcver sources already in $tree; nothing to download."
        return 0
    fi

    # Private apt: sources, indexes, cache and lock all below $cache/apt.
    local codename mirror
    codename="$(. /etc/os-release 2>/dev/null && [[ "${ID:-}" == debian ]] && echo "${VERSION_CODENAME:-}" || true)"
    codename="${codename:-bookworm}"
    mirror="${QUICKSAND_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
    local aptdir="$cache/apt"
    mkdir -p "$aptdir/sources.list.d" "$aptdir/lists/partial" "$aptdir/cache/archives/partial" \
             "$aptdir/download"
    cat > "$aptdir/sources.list.d/quicksand-openfoam-src.list" <<EOF_SOURCES
# Written by quicksand's tools/setup.sh; used only through apt-get -o Dir::Etc::SourceParts.
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror $codename main
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $mirror $codename-updates main
EOF_SOURCES
    # The hooks the machine's apt.conf.d runs after an update (AppStream, PackageKit) concern the
    # machine's own indexes, not this private one: cleared through a private config file.
    cat > "$aptdir/apt.conf" <<'EOF_CONF'
// Written by quicksand's tools/setup.sh; read through apt-get -c for the private source fetch.
#clear APT::Update::Pre-Invoke;
#clear APT::Update::Post-Invoke;
#clear APT::Update::Post-Invoke-Success;
EOF_CONF
    local apt_opts=(-q -c "$aptdir/apt.conf"
        -o Dir::Etc::SourceList=/dev/null
        -o Dir::Etc::SourceParts="$aptdir/sources.list.d"
        -o Dir::State::Lists="$aptdir/lists"
        -o Dir::Cache="$aptdir/cache"
        -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=
        -o APT::Sandbox::User="$(id -un)")

    echo "setup.sh: fetching Debian's source package openfoam=$srcver (headers for foamCoupling/)"
    echo "setup.sh:   private apt state in $aptdir (deb-src $mirror $codename and $codename-updates, main)"
    apt-get "${apt_opts[@]}" update
    rm -f "$aptdir/download/"*
    (cd "$aptdir/download" && apt-get "${apt_opts[@]}" source --download-only "openfoam=$srcver")

    local orig debtar
    orig="$(ls "$aptdir/download/"*.orig.tar.* 2>/dev/null | head -n 1 || true)"
    debtar="$(ls "$aptdir/download/"*.debian.tar.* 2>/dev/null | head -n 1 || true)"
    if [[ -z "$orig" ]]; then
        echo "setup.sh: apt-get source gave no .orig tarball for openfoam=$srcver" >&2
        return 1
    fi
    local tmp="$tree.partial"
    rm -rf "$tmp" "$tree"
    mkdir -p "$tmp"
    # Debian's patches for this version; if any touches src/ the whole package is unpacked with
    # dpkg-source (patches applied), otherwise src/ straight from the orig tarball is the same.
    local patches_touch_src=false
    if [[ -n "$debtar" ]] && tar -xf "$debtar" -C "$tmp" debian/patches 2>/dev/null; then
        if grep -qsE '^\+\+\+ [^/]+/src/' "$tmp"/debian/patches/*; then patches_touch_src=true; fi
    fi
    rm -rf "$tmp/debian"
    if $patches_touch_src; then
        echo "setup.sh:   Debian's patches touch src/: unpacking with dpkg-source -x"
        is_installed dpkg-dev || as_root apt-get install -y --no-install-recommends dpkg-dev
        local full="$aptdir/download/full"   # beside the .dsc, so nothing is copied
        dpkg-source --no-check -x "$aptdir/download/"*.dsc "$full" >/dev/null
        for part in "${parts[@]}"; do
            if [[ -e "$full/$part" ]]; then
                mkdir -p "$tmp/$(dirname "$part")"
                mv "$full/$part" "$tmp/$part"
            fi
        done
        rm -rf "$full"
    else
        echo "setup.sh:   unpacking ${parts[*]} from $(basename "$orig")"
        local top
        top="$(tar -tf "$orig" | head -n 1 | cut -d/ -f1 || true)"
        local members=()
        for part in "${parts[@]}"; do members+=("$top/$part"); done
        tar -xf "$orig" -C "$tmp" --strip-components=1 --no-same-owner "${members[@]}"
    fi
    if [[ ! -f "$tmp/src/OpenFOAM/db/Time/Time.H" ]]; then
        echo "setup.sh: unpacking openfoam=$srcver did not give src/OpenFOAM; see $tmp" >&2
        return 1
    fi
    echo "$stamp" > "$tmp/.quicksand-complete"
    mv "$tmp" "$tree"
    # The tree is the cache: the downloads and indexes are not needed any more.
    rm -rf "$aptdir/download" "$aptdir/lists" "$aptdir/cache"
    echo "setup.sh: OpenFOAM $srcver sources in $tree ($(du -sh "$tree" | cut -f1))"
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

# The Python package (tools/quicksand: results, runs, studies) for whatever python3 the user
# runs: a virtual environment .venv at the repository's root, made from Debian's python3 and
# seeing its packages (numpy, pandas, h5py, matplotlib, pytest), with the package installed
# editable from tools/. Nothing is downloaded (--no-index, --no-deps, no build isolation).
# `source .venv/bin/activate`, or .venv/bin/python, then `import quicksand`.
setup_python_package() {
    local root venv
    root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
    venv="$root/.venv"
    if [[ ! -x "$venv/bin/python" ]]; then
        /usr/bin/python3 -m venv --system-site-packages "$venv"
    fi
    # again when tools/pyproject.toml changed (its entry points), else once
    local stamp="$venv/.quicksand-pyproject"
    if ! cmp -s "$root/tools/pyproject.toml" "$stamp" || ! "$venv/bin/python" -c 'import quicksand' 2>/dev/null; then
        "$venv/bin/python" -m pip install --quiet --no-deps --no-build-isolation --no-index --editable "$root/tools"
        cp "$root/tools/pyproject.toml" "$stamp"
        echo "setup.sh: the quicksand Python package installed in $venv (source $venv/bin/activate)"
    fi
}
setup_python_package
