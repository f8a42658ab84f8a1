#pragma once
// InflowChamber<D>: the free-water chamber under the filter, where water enters through the
// gate plane (physics.md section 2, inflow).
//
// The liquid points of the chamber move up as water enters, leaving an empty gap above the gate
// plane. The gate traction is reduced by the weight of that gap (rho_L g gap), and when the gap
// of a column of cells reaches the height of one new point, a row of new points is injected
// there. New points are small, V = V_cell / ceil(liquid_per_cell / n_min) per point along the
// vertical, so that they do not leave sand cells empty when they get there (larger ones gave
// -3.5 % +- 7.8 % flux in the prototype).
//
// Usage, once per step after the points moved:
//   chamber.inject(grid, liquid, liquidCellStart, density, gravity, fallbackPressure);
//   chamber.gap(column)  // for the next step's gate traction
#include <vector>

#include "grid/Grid.hpp"
#include "points/LiquidPoints.hpp"

namespace qs {

template <int D>
class InflowChamber {
public:
    /// pointVolume: m3 of one injected point; pointsPerCell: liquid points per cell and
    /// horizontal axis (the horizontal lattice of an injected row).
    void setup(const Grid<D>& grid, Real pointVolume, int pointsPerCell);

    /// Injects rows of new points wherever the gap reached one point's height. The cell lists
    /// are those of the step's start (the chamber's lowest two cell rows are scanned).
    /// A new point takes the velocity of the lowest point above it and its pressure plus the
    /// free water's hydrostatic difference between them.
    void inject(const Grid<D>& grid, LiquidPoints<D>& liquid, const std::vector<Index>& liquidCellStart,
                Real density, Real gravity, Real fallbackPressure);

    Real gap(Index column) const { return gaps_[column]; }
    Real gapVolume(const Grid<D>& grid) const;          ///< m3, all columns
    Real injectedVolume() const { return injected_; }    ///< m3 since the start
    Real pointVolume() const { return pointVolume_; }
    /// m, the gap under a gate node: the mean over the columns of cells that share the node (a
    /// node on a wall has half as many). Taking one neighbouring column instead shifts the
    /// gap's weight half a cell sideways, and that one-sided coupling made a lateral pressure
    /// mode in the chamber grow from round-off (x 700 per half second in a 2D case B).
    Real gapAtNode(const Grid<D>& grid, Index node) const;

    std::vector<Real>& gaps() { return gaps_; }         ///< for checkpoints
    void setInjectedVolume(Real v) { injected_ = v; }

private:
    std::vector<Real> gaps_;   ///< m, per column of cells
    Real pointVolume_ = 0;
    int pointsPerCell_ = 1;
    Real injected_ = 0;
};

}  // namespace qs
