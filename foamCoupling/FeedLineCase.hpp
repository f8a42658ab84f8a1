#pragma once
// What a user's OpenFOAM case of the feed line must be for quicksand to run it (docs/openfoam.md,
// "What your case must contain"): an incompressible single-phase pimpleFoam case. Checked on the
// files before OpenFOAM is loaded, so that a case quicksand cannot run is refused with the file
// that says so and what is supported, instead of OpenFOAM's message about a missing keyword.
// No OpenFOAM header: the checks read the case's files as text.
#include <string>

namespace qs::foam {

/// Throws qs::Error naming the case's file and what quicksand supports when the case at
/// `directory` is not an incompressible single-phase case pimpleFoam could run.
void requireSupportedCase(const std::string& directory);

}  // namespace qs::foam
