// Phase 7 of the double-point step: the reservoir advanced with the gate flux, inflow injected at
// the chamber, outflow over the overflow's weir (physics.md section 2).
#include <algorithm>
#include <cmath>
#include <iostream>

#include "solver/DoublePointSolver.hpp"
#include "boundary/Overflow.hpp"
#include "solver/Parallel.hpp"

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
    // Over MPI ranks with the ghost points still there: a slot's lowest water, which the new water
    // follows, may be a neighbour's point that has just crossed the cut. Each rank fills its own
    // slots; the gaps are then every slot's on every rank.
    if (config_.gate.mode != GateMode::Closed) {
        chamber_.inject(grid_, liquid_, cells_.liquidStart, config_.liquid.density, water_.pressureGradient);
        chamber_.shareGaps([&](std::vector<Real>& gaps) { sumOverRanks(gaps); });
    }
    dropGhostPoints();

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
        const Real grains = sumOverRanks(grainsBetween(grid_, solid_, cells_.solidStart[lowCell],
                                                       static_cast<Index>(solid_.size()), lowRow * grid_.h(), zOver,
                                                       config_.points.solidPerCell));
        const Real out = ranks_ ? spillOnRanks(lowCell, grains)
                                : spillOverRim(grid_, overflowRow_, kRimRows, cells_.liquidStart[lowCell], grains,
                                               config_.points.liquidPerCell, config_.liquid.density, liquid_,
                                               dropFlags_, spillOrder_);
        if (out > 0) {
            outflowVolume_ += out;
            // the cell lists are stale now: rebuilt for what reads them between steps (the weights
            // wait for the next step's sort)
            sortByCell(liquid_, cells_.liquidStart, cells_.counts);
        }
    }

    // the step count times the step, not a running sum: outputs stay on the times asked
    // (solver/TimeLattice.hpp), also after 1e8 steps
    ++steps_;
    time_ = Real(steps_) * dt_;
}

/// The overflow's weir over MPI ranks: the decision spillOverRim takes (boundary/Overflow.hpp),
/// over the whole cross-section. What the rows under the rim lack is added over the ranks, and
/// every rank takes the weir's decision over the points above the rim of all ranks, in the same
/// order (rimOrder: by position), then drops its own that spill. Returns the water spilled over
/// all ranks (m3), the same on every rank.
template <int D>
Real DoublePointSolver<D>::spillOnRanks(Index lowCell, Real grains) {
    const Index n = static_cast<Index>(liquid_.size());
    const Real h = grid_.h(), zRim = overflowRow_ * h;
    const Index lowRow = std::max<Index>(overflowRow_ - kRimRows, 0), up = grid_.cellStride(D - 1);
    auto above = [&](Index p) { return liquid_.x[p * D + D - 1] > zRim; };
    const Index first = firstOf(n, above);
    // the points above the rim: z, x, y, V, mass, rank, index
    constexpr int kWidth = 7;
    std::vector<double> mine;
    for (Index p = first; p < n; ++p) {
        if (!above(p)) continue;
        const Real* x = &liquid_.x[p * D];
        mine.insert(mine.end(), {x[D - 1], D > 1 ? x[0] : 0.0, D > 2 ? x[1] : 0.0, liquid_.volume[p], liquid_.mass[p],
                                 double(ranks_->rank()), double(p)});
    }
    const std::vector<double> all = ranks_->comm().allGatherv(mine);
    if (all.empty()) return 0;
    Real room = 0;
    for (Index c = lowRow * up; c < overflowRow_ * up; ++c) room += grid_.cellVolume(c);
    const Index from = std::min(cells_.liquidStart[lowCell], first);
    const Real water = sumOverRanks(waterBetween(grid_, liquid_, from, n, lowRow * h, zRim,
                                                 config_.points.liquidPerCell, zRim));
    const Real hold = room - grains - water - kWeirHoldsFrom * room / static_cast<Real>(overflowRow_ - lowRow);

    const std::size_t count = all.size() / kWidth;
    std::vector<std::size_t> order(count);
    for (std::size_t k = 0; k < count; ++k) order[k] = k;
    auto at = [&](std::size_t k) { return &all[k * kWidth]; };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        // rimOrder wants (x, [y,] z): the record holds z first
        Real pa[3], pb[3];
        for (int d = 0; d < D - 1; ++d) { pa[d] = at(a)[1 + d]; pb[d] = at(b)[1 + d]; }
        pa[D - 1] = at(a)[0];
        pb[D - 1] = at(b)[0];
        if (rimOrder(pa, pb, D)) return true;
        if (rimOrder(pb, pa, D)) return false;
        return a < b;  // the same place: by rank, then index
    });
    dropFlags_.assign(static_cast<std::size_t>(n), 0);
    Real out = 0;
    bool any = false;
    weirDecides(hold, zRim, h, count, [&](std::size_t k) { return at(order[k])[0]; },
                [&](std::size_t k) { return at(order[k])[3]; }, [&](std::size_t k) {
                    const double* r = at(order[k]);
                    out += r[4] / config_.liquid.density;
                    if (int(r[5]) == ranks_->rank()) {
                        dropFlags_[static_cast<std::size_t>(r[6])] = 1;
                        any = true;
                    }
                });
    if (any) compactPoints(liquid_, dropFlags_, static_cast<std::size_t>(first));
    return out;
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
template Real DoublePointSolver<1>::spillOnRanks(Index, Real);
template Real DoublePointSolver<2>::spillOnRanks(Index, Real);
template Real DoublePointSolver<3>::spillOnRanks(Index, Real);
template void DoublePointSolver<1>::carrySandOut(Real);
template void DoublePointSolver<2>::carrySandOut(Real);
template void DoublePointSolver<3>::carrySandOut(Real);

}  // namespace qs
