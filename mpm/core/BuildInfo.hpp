#pragma once
// What this build of quicksand is: its version, the commit it was built from, and its options
// (OpenFOAM, MPI, OpenMP, HDF5). `quicksand --version` prints it; a bug report quotes it.
#include <string>

namespace qs {

/// "0.1.0"
std::string version();
/// The commit the build was made from ("401c27d", "+" when the tree had changes), or "unknown".
std::string buildCommit();
/// The OpenFOAM this build couples to ("OpenFOAM v1912 (Debian 1912.200626-2)"), or "none".
std::string openFoamBuildVersion();
/// Several lines: the version and commit, then each option with its version.
std::string versionText();
/// The same in one line, for the head of a run's output and fields.h5's attribute `quicksand`:
/// "quicksand 0.1.0 (commit 401c27d07a80, Release; OpenFOAM v1912, Open MPI v4.1.4, OpenMP
/// 201511, HDF5 1.10.8)".
std::string buildLine();

}  // namespace qs
