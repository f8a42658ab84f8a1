#pragma once
// What a user's OpenFOAM case of the feed line must be for quicksand to run it (docs/openfoam.md,
// "What your case must contain"): an incompressible single-phase pimpleFoam case. Checked on the
// files before OpenFOAM is loaded, so that a case quicksand cannot run is refused with the file
// that says so and what is supported, instead of OpenFOAM's message about a missing keyword.
// No OpenFOAM header: the checks read the case's files as text.
#include <string>
#include <vector>

namespace qs::foam {

/// Throws qs::Error naming the case's file and what quicksand supports when the case at
/// `directory` is not an incompressible single-phase case pimpleFoam could run.
void requireSupportedCase(const std::string& directory);

/// Over `ranks` MPI ranks, a case with system/decomposeParDict is decomposed into that many
/// parts: throws qs::Error naming the file and the key when numberOfSubdomains is missing or is
/// not `ranks`. Returns whether the case has a decomposeParDict.
bool requireDecomposition(const std::string& directory, int ranks);

/// What the case's dictionaries select, read as text: lines for `quicksand check` (turbulence,
/// viscosity, fvOptions), with a note where the case's nu is not the column's water
/// (liquidViscosity / liquidDensity, Pa s and kg/m3).
std::vector<std::string> describeCase(const std::string& directory, double liquidViscosity, double liquidDensity);

}  // namespace qs::foam
