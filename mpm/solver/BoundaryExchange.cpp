// Phase 7 of the double-point step: the reservoir advanced with the gate flux, outflow above the
// overflow level, inflow injected at the chamber (physics.md section 2).
#include <algorithm>
#include <cmath>

#include "solver/DoublePointSolver.hpp"
#include "boundary/Overflow.hpp"

namespace qs {

// ---------------------------------------------------------------------------------------------
// 7 inflow, outflow, ledger, reservoir
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::exchangeAtBoundaries() {
    cumulativeInflow_ += gateFlux_ * dt_;
    gatePressure_ = gateLaw_.pressure(gateFlux_);
    reservoir_.advance(time_, dt_, gateFlux_);

    if (config_.column.overflowLevel) {
        const Real zOver = *config_.column.overflowLevel;
        checkSolidBelow(zOver, solid_, time_, [&] { return sandSurface(); });
        const Real out = removeLiquidAbove(zOver, config_.liquid.density, liquid_, dropFlags_);
        if (out > 0) {
            outflowVolume_ += out;
            // the cell lists are stale now: rebuild them for the chamber's scan below (the
            // weights wait for the next step's sort)
            sortByCell(liquid_, liquidCellStart_, counts_);
        }
    }
    if (config_.gate.mode != GateMode::Closed)
        chamber_.inject(grid_, liquid_, liquidCellStart_, config_.liquid.density, config_.gravity, gatePressure_);

    time_ += dt_;
    ++steps_;
}

template void DoublePointSolver<1>::exchangeAtBoundaries();
template void DoublePointSolver<2>::exchangeAtBoundaries();
template void DoublePointSolver<3>::exchangeAtBoundaries();

}  // namespace qs
