#pragma once
// RunPreconditions: what `quicksand run` refuses before its first step, checked without writing a
// file. runCase calls validateRun before it touches an earlier output directory, and
// `quicksand check` calls it too, so whatever run would refuse, check refuses first, with the
// same message:
//  - time.dt beyond the stable step 0.5 h / c_fast (requireStableTimeStep, solver/RunSize.hpp);
//  - a run whose estimated memory exceeds the machine's (requireFitsMachine);
//  - a built-in reservoir that cannot be made (makeReservoirModel);
//  - a solver that cannot be built on the case: its grid, initial points and state are made once
//    and dropped, with the built-in reservoir, or for an OpenFOAM reservoir with a constant head
//    standing in (the OpenFOAM case itself is loaded only by run, which copies and meshes it in
//    the output directory).
//
//   const CaseConfig config = loadCase(dir);
//   validateRun(config);   // throws qs::Error naming the file and key, as run would
#include "case/CaseConfig.hpp"

namespace qs {

/// Throws qs::Error at the first precondition of a run that `config` breaks.
void validateRun(const CaseConfig& config);

}  // namespace qs
