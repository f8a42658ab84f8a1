#pragma once
// InflowChamber<D>: the free-water chamber under the filter, where water enters through the
// gate plane (physics.md section 2, inflow).
//
// The liquid points of the chamber move up as water enters, leaving an empty gap above the gate
// plane. The gate traction is reduced by the weight of that gap (rho_L g gap), and when the gap
// of an injection slot reaches the height of one new point, a new point is injected there. The
// slots are the horizontal lattice of the liquid points (liquid_per_cell per cell and axis), so
// that water rising faster under one part of the column than under another is refilled where it
// left: a slot per column of cells, refilled a row at a time from its lowest point, left voids
// under the faster part and closed the liquid ledger of two gravels side by side only to 1.5e-3.
// New points are short, h / ceil(liquid_per_cell / n_min) high, so that they do not leave sand
// cells empty when they get there (larger ones gave -3.5 % +- 7.8 % flux in the prototype); their
// volume is that height times the slot's footprint (in axisymmetry, 2 pi r_slot wide).
//
// Usage, once per step after the points moved:
//   chamber.inject(grid, liquid, liquidCellStart, density, cellPressureGradient);
//   chamber.gapAtNode(grid, node)  // for the next step's gate traction
#include <vector>

#include "grid/Grid.hpp"
#include "points/LiquidPoints.hpp"

namespace qs {

template <int D>
class InflowChamber {
public:
    /// pointHeight: m, height of one injected point; pointsPerCell: liquid points per cell and
    /// horizontal axis (the horizontal lattice of an injected row).
    void setup(const Grid<D>& grid, Real pointHeight, int pointsPerCell);

    /// Injects new points in every slot whose gap reached one point's height. The cell lists
    /// are those of the step's start (the chamber's lowest two cell rows are scanned).
    /// A new point takes the velocity of the lowest point above it, and its pressure carried
    /// along that point's cell's pressure gradient (Pa/m, [cell][axis]) to where it is put, or
    /// its pressure and cavity as they are if that point holds a cavity (its water at the limit).
    void inject(const Grid<D>& grid, LiquidPoints<D>& liquid, const std::vector<Index>& liquidCellStart,
                Real density, const std::vector<Real>& cellPressureGradient);

    Real gapVolume(const Grid<D>& grid) const;          ///< m3, all slots
    Real injectedVolume() const { return injected_; }    ///< m3 since the start
    /// m, the gap under a gate node: the mean over the slots whose centres lie in the node's
    /// footprint (half a cell either side). Taking one neighbouring column instead shifted the
    /// gap's weight half a cell sideways.
    Real gapAtNode(const Grid<D>& grid, Index node) const;

    std::vector<Real>& gaps() { return gaps_; }         ///< for checkpoints (one per slot)
    /// Over MPI ranks: the slots under the columns this rank owns (ownsColumn(k) for the grid's
    /// column k) are the only ones it injects into; the others' gaps come from their owners
    /// (shareGaps). Without it, every slot.
    template <class Owns>
    void restrictTo(const Grid<D>& grid, Owns&& ownsColumn) {
        owned_.assign(gaps_.size(), 1);
        for (Index slot = 0; slot < static_cast<Index>(gaps_.size()); ++slot) {
            Index rest = slot, column = 0, stride = 1;
            for (int d = 0; d < D - 1; ++d) {
                const Index n = grid.cells(d) * pointsPerCell_;
                column += (rest % n) / pointsPerCell_ * stride;
                rest /= n;
                stride *= grid.cells(d);
            }
            owned_[slot] = ownsColumn(column) ? 1 : 0;
        }
    }
    /// Every slot's gap on every rank: each owner's, added over the ranks (`sum` adds a vector
    /// over the ranks in place), so that a gate node by a cut sees its neighbours' slots.
    template <class Sum>
    void shareGaps(Sum&& sum) {
        if (owned_.empty()) return;
        for (std::size_t slot = 0; slot < gaps_.size(); ++slot)
            if (!owned_[slot]) gaps_[slot] = 0;
        sum(gaps_);
    }
    void setInjectedVolume(Real v) { injected_ = v; }

private:
    struct Scan {
        Real bottom = 1e300;   ///< m, the lowest point's lower edge
        Index ref = -1;        ///< the lowest point
        Index cell = -1;       ///< its cell
    };
    Index slotOf(const Grid<D>& grid, const Real* x) const;
    void slotCentre(const Grid<D>& grid, Index slot, Real* centre) const;  ///< horizontal coordinates
    Real slotFootprint(const Grid<D>& grid, Index slot) const;              ///< m2

    std::vector<Real> gaps_;   ///< m, per injection slot
    std::vector<Scan> scan_;   ///< per slot, scratch of inject() (no allocation per step)
    Real pointHeight_ = 0;
    int pointsPerCell_ = 1;
    Real injected_ = 0;
    std::vector<char> owned_;  ///< the slots this rank injects into (empty: all)
};

}  // namespace qs
