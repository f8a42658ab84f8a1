// TimeLattice: the step and the coupling window fitted to the output interval, so that outputs,
// checkpoints and an OpenFOAM line's time directories fall on the times the case asks for (0.5,
// 1, 1.5 s, ...), as pimpleFoam's adjustTimeStep lands on its write times.
//
// The stable step (courant h / c, or time.dt) is an upper bound; the run takes the largest step
// below it that a whole number of times fills the coupling window, and the largest window below
// coupling.window that a whole number of times fills time.output_interval. A run without a
// windowed model (no OpenFOAM line) fits its step to the output interval directly. The step is
// never lengthened: stability holds, and the verification tolerances with it.
//
// Time is then the step count times the step (DoublePointSolver), not a running sum: after 5e7
// steps a sum would be off by some 1e-8 s and print 999.999995 for 1000.
#pragma once

#include "case/CaseConfig.hpp"

namespace qs {

struct TimeLattice {
    double stableDt = 0;        ///< s, courant h / c (or time.dt): the bound
    double dt = 0;              ///< s, the step the run takes
    double window = 0;          ///< s, the coupling window a windowed model advances by (0: none)
    long stepsPerWindow = 0;    ///< a whole number (windowed runs)
    long stepsPerOutput = 0;    ///< a whole number
};

/// The lattice of a case. A windowed model is an OpenFOAM line; `windowed` says so for a model
/// given by the caller (the coupling tests' built-in one).
TimeLattice timeLattice(const CaseConfig& config, bool windowed);
TimeLattice timeLattice(const CaseConfig& config);

/// The least whole number of parts of `span` each at most `bound` long (1 if bound >= span),
/// at most kMostParts.
long partsOfAtMost(double span, double bound);
constexpr long kMostParts = 1000000000000000L;  // 1e15, exact in a double

}  // namespace qs
