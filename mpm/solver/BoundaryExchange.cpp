// Phase 7 of the double-point step: the reservoir advanced with the gate flux, inflow injected at
// the chamber, outflow over the overflow's weir (physics.md section 2).
#include <algorithm>
#include <cmath>
#include <iostream>

#include "solver/DoublePointSolver.hpp"
#include "boundary/Overflow.hpp"

namespace qs {

// ---------------------------------------------------------------------------------------------
// 7 inflow, outflow, ledger, reservoir
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::exchangeAtBoundaries() {
    advanceReservoir();

    // The chamber first, on the step's cell lists: its new water takes the field of the cell that
    // set its reference point's pressure (updatePressure). Injected after the spill, on the lists
    // rebuilt then, it took the gradient of the cell its reference had moved into.
    if (config_.gate.mode != GateMode::Closed)
        chamber_.inject(grid_, liquid_, cells_.liquidStart, config_.liquid.density, water_.pressureGradient);

    if (config_.column.overflowLevel) {
        const Real zOver = *config_.column.overflowLevel;
        if (config_.column.sandOverflow == SandOverflow::Stop)
            checkSolidBelow(zOver, solid_, time_, [&] { return sandSurface(); });
        else
            carrySandOut(zOver);
        // the points that began the step two rows under the measured rows or above: a point
        // moves less than a cell in a step, and its water spans up to a cell about its centre
        const Index up = grid_.cellStride(D - 1);
        const Index lowCell = std::max<Index>(overflowRow_ - kRimRows - 2, 0) * up;
        const Index lowRow = std::max<Index>(overflowRow_ - kRimRows, 0);
        const Real grains = grainsBetween(grid_, solid_, cells_.solidStart[lowCell], static_cast<Index>(solid_.size()),
                                          lowRow * grid_.h(), zOver, config_.points.solidPerCell);
        const Real out = spillOverRim(grid_, overflowRow_, kRimRows, cells_.liquidStart[lowCell], grains,
                                      config_.points.liquidPerCell, config_.liquid.density, liquid_, dropFlags_,
                                      spillOrder_);
        if (out > 0) {
            outflowVolume_ += out;
            // the cell lists are stale now: rebuilt for what reads them between steps (the weights
            // wait for the next step's sort)
            sortByCell(liquid_, cells_.liquidStart, cells_.counts);
        }
    }

    time_ += dt_;
    ++steps_;
}

/// Sand above the overflow level leaves with the water: its grains join the solid ledger
/// (cumulative_solid_outflow), and the first time it happens a warning names the time.
template <int D>
void DoublePointSolver<D>::carrySandOut(Real zOver) {
    const Real mass = removeSolidAbove(zOver, solid_, dropFlags_);
    if (mass <= 0) return;
    if (!warnedSandOut_)
        std::cerr << "warning: at t = " << time_ << " s the bed reached the overflow level (" << zOver
                  << " m): the water carries sand out of the column, counted in series.csv's "
                     "cumulative_solid_outflow (column.sand_overflow = \"stop\" stops the run instead)\n";
    solidOutflowMass_ += mass;
    solid_.stressReturn.resize(solid_.size());  // per-step scratch, not a point field: kept in step
    warnedSandOut_ = true;  // once a run: not part of the state, so a repeated window keeps it
    sortByCell(solid_, cells_.solidStart, cells_.counts);
}

template void DoublePointSolver<1>::exchangeAtBoundaries();
template void DoublePointSolver<2>::exchangeAtBoundaries();
template void DoublePointSolver<3>::exchangeAtBoundaries();
template void DoublePointSolver<1>::carrySandOut(Real);
template void DoublePointSolver<2>::carrySandOut(Real);
template void DoublePointSolver<3>::carrySandOut(Real);

}  // namespace qs
