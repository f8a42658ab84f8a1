#include "solver/TimeLattice.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "solver/RunSize.hpp"

namespace qs {

long partsOfAtMost(double span, double bound) {
    QS_CHECK(span > 0 && bound > 0, "partsOfAtMost: span " << span << " s and bound " << bound << " s must be positive");
    // a span that is a whole number of bounds to round-off takes that number, not one more
    const double parts = span / bound;
    const double whole = std::round(parts);
    const double count = std::max(1.0, std::abs(parts - whole) <= 1e-9 * whole ? whole : std::ceil(parts));
    // a step of 1e-38 s (a bulk modulus typed as 1e70 Pa, found by fuzzing) would overflow the
    // count: it saturates, and the run is refused for its step count (solver/RunSize.hpp)
    return count < double(kMostParts) ? static_cast<long>(count) : kMostParts;
}

TimeLattice timeLattice(const CaseConfig& config, bool windowed) {
    TimeLattice l;
    l.stableDt = stableTimeStep(config);
    const double output = config.time.outputInterval;
    if (partsOfAtMost(output, l.stableDt) == kMostParts) {
        l.dt = l.stableDt;  // no run takes 1e15 steps an output: nothing to fit
        l.window = windowed ? config.coupling.window : 0;
        l.stepsPerWindow = windowed ? kMostParts : 0;
        l.stepsPerOutput = kMostParts;
    } else if (windowed) {
        l.window = output / double(partsOfAtMost(output, config.coupling.window));
        l.stepsPerWindow = partsOfAtMost(l.window, l.stableDt);
        l.dt = l.window / double(l.stepsPerWindow);
        l.stepsPerOutput = l.stepsPerWindow * std::lround(output / l.window);
    } else {
        l.stepsPerOutput = partsOfAtMost(output, l.stableDt);
        l.dt = output / double(l.stepsPerOutput);
    }
    return l;
}

TimeLattice timeLattice(const CaseConfig& config) {
    return timeLattice(config, config.reservoir.kind == ReservoirKind::OpenFoam);
}

}  // namespace qs
