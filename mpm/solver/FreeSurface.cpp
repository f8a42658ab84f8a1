// The free surface as the grid sees it (phase 1 of the double-point step, after the sort): how
// full of water each cell is, which cells are under water and which are open to the air, the
// liquid points' weights V*, the water a node's cells hold, and the check that the overflow's
// rows still hold their water (physics.md section 2, free surface).
#include <algorithm>
#include <sstream>

#include "boundary/Overflow.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

namespace {
/// -, the fill of a cell (its wet share) from which the cell below it counts as below
/// the free surface: more than a stray point or two (the free water holds lpc^(D-1) n_z points a
/// cell, n_z = lpc / n_min: 7 in 1D, 14 in 2D for the shipped cases), less than any cell of a
/// connected water body, whose points bunch by -15 % at most
constexpr Real kSubmergingFill = 0.25;
}  // namespace

template <int D>
void DoublePointSolver<D>::classifyCells() {
    const Index nc = grid_.numCells();
    forAllCells(nc, cells_.liquidStart, [&](Index c) {
        Real vol = 0;
        for (Index p = cells_.liquidStart[c]; p < cells_.liquidStart[c + 1]; ++p) vol += liquid_.volume[p];
        filling_.liquidVolume[c] = vol;
        // the wet share of the cell: a liquid point stands for a mixture volume (its water is
        // n rho_L V), so the points of a saturated cell add up to the cell's volume, sand or not
        filling_.fill[c] = std::min(Real(1), vol / grid_.cellVolume(c));
        filling_.active[c] = cells_.hasLiquid(c) || cells_.hasSolid(c);
    });
    // A cell is below the free surface when the cell above is a quarter wet or more
    // (kSubmergingFill), or when it is a cell of the top row below the overflow
    // level and holds liquid: the overflow holds the water's surface at its level (a node row), so
    // the water's top cells are full however few points they hold at the moment. There the
    // cell's liquid points share the whole cell, V* = V_cell V / sum V, so they fill the pores and
    // a half-empty chamber cell carries no multiple of the gate pressure; above the free surface
    // V* = V (physics.md). A few stray points above (spray, a drop falling back) do not make a
    // half-filled cell full: decided by any liquid above, one point above doubled the cell's
    // pressure weight (test FreeSurface.AStrayPointAboveLeavesThePorePressureBelowAsItWas).
    // Deciding the overflow's top row from its points instead (thin: a free surface) made it a
    // moving, point-sampled surface: in 2D its cells flipped between full and thin as the points
    // passing through came and went, which pumped energy into the free water (lateral velocities
    // of 1 m/s within 2 s in a seepage of 1.5 cm/s, two gravels side by side) and slowed the flux.
    const Index up = grid_.cellStride(D - 1);
    const Index rows = grid_.cells(D - 1);
    liquid_.weight.resize(liquid_.size());
    forAllCells(nc, cells_.liquidStart, [&](Index c) {
        const Index row = (c / up) % rows;
        const bool holdsLiquid = cells_.hasLiquid(c);
        const bool above = (row + 1 < rows && filling_.fill[c + up] >= kSubmergingFill) ||
                           (row + 1 == overflowRow_ && holdsLiquid);
        filling_.submerged[c] = above;
        const Real volume = grid_.cellVolume(c);
        const Real scale = above && filling_.liquidVolume[c] > 0 ? volume / filling_.liquidVolume[c] : 1.0;
        const bool thin = filling_.fill[c] < config_.liquid.freeSurfaceFilling;
        for (Index p = cells_.liquidStart[c]; p < cells_.liquidStart[c + 1]; ++p) {
            liquid_.weight[p] = liquid_.volume[p] * scale;
            liquid_.state[p] = (!above && thin) ? kFreeSurfaceLiquid : kSubmergedLiquid;
        }
    });
    // Which cells' water is under the air: scanned down each column of cells, a cell without
    // sand and without sand anywhere above it (sand's pores are saturated, however few liquid
    // points a loosened cell holds at the moment) whose cell above is under a quarter wet, and
    // the cells of the overflow's row that hold no sand. Spray above an air gap does not close the
    // surface below it (only the cell just above counts for water). They take no suction and keep
    // no cavity (updatePressure). Decided cell by cell (no wet cell just above), a sand-free pocket
    // under a water-starved cell inside piping2D's bed vented, and so did a starved sand cell by
    // the wall: it held p = 0 while its neighbours rose to 70 kPa, and a solid point left at
    // 726 m/s (13.38 s).
    forAll(grid_.columns(), [&](Index column) {
        bool sandAbove = false;
        for (Index row = rows; row-- > 0;) {
            const Index c = grid_.columnCell(column, row);
            const bool holdsSand = cells_.hasSolid(c);
            const bool overflowRow = row + 1 == overflowRow_;
            sandAbove = sandAbove || holdsSand;
            filling_.openToAir[c] = !sandAbove && (overflowRow || !filling_.submerged[c]);
        }
    });
    // The overflow's top cells count as full only while the water stands there: fallen a cell
    // below it (the reservoir drained the column, the water spilled elsewhere), the grid would hold
    // water the column has lost, and the run stops saying so (the head is checked against the
    // overflow before the run, case/CaseRules.cpp).
    // The water is measured over the top two rows, from the points' extents (a point's water spans
    // z +- V / (2 a), a its footprint), and the run stops when they hold less than one row's worth.
    // A liquid point spills whole (the weir, boundary/Overflow.hpp), so the row under the rim loses
    // up to half a point of water at once: half a cell in sand (two points a cell), more where a
    // suspension's points have grown. Counted by centres in the top row alone, the Deltares
    // column through a 10 mm tube stopped with its water at the rim all along: a bed heaving
    // against the rim read 49.7 % each time its top point left (t = 7.75 s), and, fluidised, a
    // point of 0.83 cells leaving left 46.7 % (t = 14.17 s).
    if (overflowRow_ > 0) {
        Real room = 0;
        const Index lowRow = std::max<Index>(overflowRow_ - kRimRows, 0);
        const Index first = lowRow * up, last = overflowRow_ * up;  // cells of the rows measured
        for (Index c = first; c < last; ++c) room += grid_.cellVolume(c);
        // their points, those of the row below and those of the row above, whose extents reach
        // into them (the weir holds crest water there, straddling the rim)
        const Index from = lowRow >= 1 ? (lowRow - 1) * up : first;
        const Index to = std::min(last + up, nc);
        const Real zLow = lowRow * grid_.h(), zRim = overflowRow_ * grid_.h();
        // a bed risen into these rows fills them with grains and the water in its pores: the
        // rows are full (counting water alone stopped a boil reaching the rim, and the 2D
        // Deltares column on 9.3 mm cells, its expanded bed two rows under the rim)
        const int lpc = config_.points.liquidPerCell, spc = config_.points.solidPerCell;
        Real water = 0, grains = 0;
        if (!ranks_) {
            water = waterBetween(grid_, liquid_, cells_.liquidStart[from], cells_.liquidStart[to], zLow, zRim, lpc);
            grains = grainsBetween(grid_, solid_, cells_.solidStart[from], cells_.solidStart[to], zLow, zRim, spc);
        } else {  // the rank's own cells (its ghosts are other ranks'), added over the ranks
            for (Index c = from; c < to; ++c) {
                if (!ownsCell(c)) continue;
                water += waterBetween(grid_, liquid_, cells_.liquidStart[c], cells_.liquidStart[c + 1], zLow, zRim, lpc);
                grains += grainsBetween(grid_, solid_, cells_.solidStart[c], cells_.solidStart[c + 1], zLow, zRim, spc);
            }
            water = sumOverRanks(water);
            grains = sumOverRanks(grains);
        }
        const Real rowsMeasured = static_cast<Real>(overflowRow_ - lowRow);
        const Real missing = std::max(Real(0), room - grains - water) / room * rowsMeasured;  // in rows
        if (!(missing <= 1)) {
            std::ostringstream m;
            m << "the water fell below the overflow level column.overflow_level = " << *config_.column.overflowLevel
              << " m at t = " << time_ << " s: the top " << (overflowRow_ - lowRow) << " rows of cells under it lack "
              << missing << " rows of water. The overflow holds the water's surface at its level, so the reservoir's "
                            "head must keep the column full to it";
            if (ranks_) throw SharedError(m.str());  // every rank has it: the water is summed over them
            throw Error(m.str());
        }
    }
}

/// m3, the pore volume a node's water fills (times n_i, the water it carries): each cell around it
/// gives its share of the node's volume as if it were wet from its bottom up to its fill f, the
/// wet share of the cell (f = 1 below the free surface): f^2 of the share to the cell's top
/// nodes, 2f - f^2 to its bottom nodes (the integrals of the linear N over the wet part). The cells at and
/// above the overflow level do not count (no water stands there).
template <int D>
Real DoublePointSolver<D>::waterVolumeAt(Index node) const {
    Real volume = 0;
    grid_.forEachCellOfNode(node, [&](Index cell, int corner) {
        if (!filling_.active[cell]) return;
        if (overflowRow_ >= 0 && grid_.cellCoords(cell)[D - 1] >= overflowRow_) return;
        const bool full = filling_.submerged[cell] && cells_.hasLiquid(cell);
        const Real f = full ? 1 : filling_.fill[cell];  // below the free surface the pores are full
        const bool top = (corner >> (D - 1)) & 1;
        volume += grid_.cellShare(cell, corner) * (top ? f * f : f * (2 - f));
    });
    return volume;
}

template void DoublePointSolver<1>::classifyCells();
template void DoublePointSolver<2>::classifyCells();
template void DoublePointSolver<3>::classifyCells();
template Real DoublePointSolver<1>::waterVolumeAt(Index) const;
template Real DoublePointSolver<2>::waterVolumeAt(Index) const;
template Real DoublePointSolver<3>::waterVolumeAt(Index) const;

}  // namespace qs
