#pragma once
// The overflow level at the top of the column (physics.md section 2, outflow): the water that
// passes it spills over the rim (spillOverRim, a weir that holds back crest water while the rows
// under the rim lack more than half a row) and counts as outflow (the real test weighs it).
// The overflow holds the water's surface at its level: the water's top cells count as full (solver/PointsToGrid.cpp),
// so removing whole points no longer makes the level jump. (physics.md's surface pressure
// rho_L g (z_overflow - z_surface), with z_surface from the liquid mass, did that until
// 2026-12-02; in 2D its point-sampled surface pumped energy into the free water.) The water
// surface from the liquid mass is still measured for series.csv.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/Error.hpp"
#include "grid/Grid.hpp"
#include "points/LiquidPoints.hpp"
#include "points/PointSet.hpp"
#include "points/SolidPoints.hpp"

namespace qs {

/// m3, the volume V of a point at x (its footprint a = grid.pointFootprint) spans between zLow and
/// zHigh: the point spans z +- V / (2 a) upwards, and counts by the part of that span inside.
template <int D>
Real volumeBetween(const Grid<D>& grid, const Real* x, Real V, int pointsPerCell, Real zLow, Real zHigh) {
    const Real z = x[D - 1], area = grid.pointFootprint(x, pointsPerCell), half = 0.5 * V / area;
    const Real inside = std::min(z + half, zHigh) - std::max(z - half, zLow);
    return inside > 0 ? area * inside : 0;
}

/// m3, the water the liquid points [from, to) whose centres lie at or below zCentreMax put between
/// zLow and zHigh (volumeBetween: a point's water spans z +- V / (2 a)).
template <int D>
Real waterBetween(const Grid<D>& grid, const LiquidPoints<D>& liquid, Index from, Index to, Real zLow, Real zHigh,
                  int pointsPerCell, Real zCentreMax = std::numeric_limits<Real>::infinity()) {
    Real water = 0;
    for (Index p = from; p < to; ++p)
        if (liquid.x[p * D + D - 1] <= zCentreMax)
            water += volumeBetween(grid, &liquid.x[p * D], liquid.volume[p], pointsPerCell, zLow, zHigh);
    return water;
}

/// m3, the grains the solid points [from, to) put between zLow and zHigh: a point's mixture spans
/// z +- V / (2 a) (volumeBetween), as a liquid point's water does, and (1 - n) of it is grains.
/// Sand in the rows under the rim takes room that no water can fill: the rows lack water only
/// where neither water nor grains are.
template <int D>
Real grainsBetween(const Grid<D>& grid, const SolidPoints<D>& solid, Index from, Index to, Real zLow, Real zHigh,
                   int pointsPerCell) {
    Real grains = 0;
    for (Index p = from; p < to; ++p)
        grains += (1 - solid.porosity[p]) *
                  volumeBetween(grid, &solid.x[p * D], solid.volume[p], pointsPerCell, zLow, zHigh);
    return grains;
}

/// rows of water the rows under the rim lack before the weir holds crest water back
/// (spillOverRim)
constexpr Real kWeirHoldsFrom = 0.5;

/// The order in which the weir holds the points above the rim: lowest first, and among points
/// at one height by their horizontal coordinates. It depends on where the points are, not on
/// where they are stored, so that a run over MPI ranks takes the same decision.
inline bool rimOrder(const Real* a, const Real* b, int dimension) {
    if (a[dimension - 1] != b[dimension - 1]) return a[dimension - 1] < b[dimension - 1];
    for (int d = 0; d < dimension - 1; ++d)
        if (a[d] != b[d]) return a[d] < b[d];
    return false;
}

/// The weir's decision over the points above the rim, taken in rimOrder (k = 0, 1, ...: their
/// heights z(k) and volumes V(k)): from the lowest up, each is held while it is at most a cell
/// above the rim and fits in what the rows lack beyond half a row (`hold`, m3), at least half of
/// it; from the first that does not on, spill(k) is called for each.
template <class Z, class Volume, class Spill>
void weirDecides(Real hold, Real zRim, Real h, std::size_t count, Z&& z, Volume&& V, Spill&& spill) {
    Real held = 0;
    bool holding = true;
    for (std::size_t k = 0; k < count; ++k) {
        holding = holding && z(k) <= zRim + h && hold - held >= 0.5 * V(k);
        if (holding) {
            held += V(k);  // falls back into the trough
            continue;
        }
        spill(k);
    }
}

/// The overflow's weir. A liquid point whose centre passes the rim spills, except the crest water
/// the rows under the rim need once they lack more than half a row (kWeirHoldsFrom). Then the
/// points above the rim stay, lowest first, as long as each fits in what the rows lack beyond
/// half a row (at least half of it), and the rest spill: a crest a boil throws over the rim
/// falls back into the trough beside it. A point more than a cell above the rim spills whatever
/// the rows lack (spray). What the rows lack is measured without the points above the rim.
/// Cutting every point past the rim skimmed each crest and kept each trough: piping2D's
/// sloshing surface spilled 23 % more than its inflow over 27 to 32 s and fell a row below the
/// rim (docs/piping.md). Holding crest water whenever the rows lacked any (the mean level under
/// the rim) left points standing over a level rim, where no water stands on the grid
/// (waterVolumeAt), and the side-by-side gravels' core flux strayed 0.69 % against 0.37 %.
/// Half a row is a choice: it is past what a level surface lacks when a point has just spilled
/// (free-water points are h / 7 tall in piping2D; a suspension's grow to 0.83 h), so a level
/// surface spills as before and every verification test keeps its figures, and it is half the
/// way to the run's stop at a row (solver/PointsToGrid.cpp).
/// The rows measured are the `rows` rows of cells under the rim: their water from the points
/// from index `from` on, and `grains` (m3, grainsBetween) the sand's share of them. Returns the
/// volume of water spilled (m3); `drop` and `order` are the caller's scratch.
template <int D>
Real spillOverRim(const Grid<D>& grid, Index rimRow, Index rows, Index from, Real grains, int pointsPerCell,
                  Real density, LiquidPoints<D>& liquid, std::vector<char>& drop, std::vector<Index>& order) {
    const Index n = static_cast<Index>(liquid.size());
    const Real h = grid.h(), zRim = rimRow * h;
    auto z = [&](Index p) { return liquid.x[p * D + D - 1]; };
    auto above = [&](Index p) { return z(p) > zRim; };
    // firstOf gives the smallest index above (in parallel, core/ForAll.hpp); the points are sorted
    // by cell at the step's start and move less than a cell in it, so it lies in the set's tail
    const Index first = firstOf(n, above);
    if (first == n) return 0;
    const Index lowRow = std::max<Index>(rimRow - rows, 0);
    const Index up = grid.cellStride(D - 1);
    Real room = 0;
    for (Index c = lowRow * up; c < rimRow * up; ++c) room += grid.cellVolume(c);
    const Real lacking =
        room - grains - waterBetween(grid, liquid, std::min(from, first), n, lowRow * h, zRim, pointsPerCell, zRim);
    const Real hold = lacking - kWeirHoldsFrom * room / static_cast<Real>(rimRow - lowRow);

    order.clear();
    for (Index p = first; p < n; ++p)
        if (above(p)) order.push_back(p);
    std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        return rimOrder(&liquid.x[a * D], &liquid.x[b * D], D) || (!rimOrder(&liquid.x[b * D], &liquid.x[a * D], D) && a < b);
    });
    drop.resize(n);
    std::fill(drop.begin() + first, drop.end(), 0);
    Real water = 0;
    weirDecides(hold, zRim, h, order.size(), [&](std::size_t k) { return z(order[k]); },
                [&](std::size_t k) { return liquid.volume[order[k]]; }, [&](std::size_t k) {
                    drop[order[k]] = 1;
                    water += liquid.mass[order[k]] / density;
                });
    if (water > 0) compactPoints(liquid, drop, static_cast<std::size_t>(first));
    return water;
}

/// Removes the solid points above zOverflow: sand the water carries out over the column's rim
/// (column.sand_overflow = "carry"); returns their mass of grains (kg). A point leaves whole, once
/// its centre passes the rim (no sand is held back: a suspension's liquid points may be, by the
/// weir). The solid points are sorted by cell, so
/// those above lie at the set's end. `drop` is the caller's scratch.
template <int D>
Real removeSolidAbove(Real zOverflow, SolidPoints<D>& solid, std::vector<char>& drop) {
    const Index n = static_cast<Index>(solid.size());
    auto above = [&](Index p) { return solid.x[p * D + D - 1] > zOverflow; };
    const Index first = firstOf(n, above);
    if (first == n) return 0;
    drop.resize(n);
    Real mass = 0;
    for (Index p = first; p < n; ++p) {
        drop[p] = above(p);
        if (drop[p]) mass += solid.mass[p];
    }
    compactPoints(solid, drop, static_cast<std::size_t>(first));
    return mass;
}

/// Solid reaching the overflow with column.sand_overflow = "stop": an error naming it.
/// `sandSurface()` gives the surface for the message (taken only then: it is a pass over the points).
template <int D, class Surface>
void checkSolidBelow(Real zOverflow, const SolidPoints<D>& solid, Real time, Surface&& sandSurface) {
    const Index n = static_cast<Index>(solid.size());
    if (!anyOf(n, [&](Index p) { return solid.x[p * D + D - 1] > zOverflow; })) return;
    for (std::size_t p = 0; p < solid.size(); ++p) {
        if (solid.x[p * D + D - 1] <= zOverflow) continue;
        std::ostringstream s;
        s << "solid points reached the overflow level column.overflow_level = " << zOverflow
          << " m at t = " << time << " s (sand surface " << sandSurface()
          << " m): the bed expanded beyond the column (column.sand_overflow = \"stop\"; \"carry\" lets the water "
             "carry it out), or raise the overflow level and the grid top";
        throw Error(s.str());
    }
}

/// m, top of the highest solid point (its extent from its volume), at least the filter level.
template <int D>
Real sandSurfaceOf(const Grid<D>& grid, const SolidPoints<D>& solid, Real filterLevel, int pointsPerCell) {
    Real top = filterLevel;
    for (std::size_t p = 0; p < solid.size(); ++p)
        top = std::max(top, solid.x[p * D + D - 1] + 0.5 * solid.volume[p] / grid.pointFootprint(&solid.x[p * D], pointsPerCell));
    return top;
}

}  // namespace qs
