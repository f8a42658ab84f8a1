#pragma once
// The overflow level at the top of the column (physics.md section 2, outflow): liquid points
// above it leave the domain and count as outflow (the real test weighs it). The overflow holds
// the water's surface at its level: the water's top cells count as full (solver/PointsToGrid.cpp),
// so removing whole points no longer makes the level jump. (physics.md's surface pressure
// rho_L g (z_overflow - z_surface), with z_surface from the liquid mass, did that until
// 2026-12-02; in 2D its point-sampled surface pumped energy into the free water.) The water
// surface from the liquid mass is still measured for series.csv.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/Error.hpp"
#include "grid/Grid.hpp"
#include "points/LiquidPoints.hpp"
#include "points/PointSet.hpp"
#include "points/SolidPoints.hpp"

namespace qs {

/// Removes the liquid points above zOverflow; returns their volume of water (m3).
/// `drop` is the caller's scratch (reserved once, no allocation here).
template <int D>
Real removeLiquidAbove(Real zOverflow, Real density, LiquidPoints<D>& liquid, std::vector<char>& drop) {
    const Index n = static_cast<Index>(liquid.size());
    auto above = [&](Index p) { return liquid.x[p * D + D - 1] > zOverflow; };
    // The first point above, found in parallel (a serial scan would pull every thread's points
    // through one core's cache, core/ForAll.hpp). The points are sorted by cell, so those above
    // lie at the set's end, and only that tail is scanned and compacted, in order.
    const Index first = firstOf(n, above);
    if (first == n) return 0;
    drop.resize(n);
    Real volume = 0;
    for (Index p = first; p < n; ++p) {
        drop[p] = above(p);
        if (drop[p]) volume += liquid.mass[p] / density;
    }
    compactPoints(liquid, drop, static_cast<std::size_t>(first));
    return volume;
}

/// Removes the solid points above zOverflow: sand the water carries out over the column's rim
/// (column.sand_overflow = "carry"); returns their mass of grains (kg). A point leaves whole, once
/// its centre passes the rim, as a liquid point does. The solid points are sorted by cell, so
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

/// m, the free-water surface from the liquid mass above zRef (a plane one cell above the sand);
/// points straddling the plane count by their fraction. 0 when no liquid is above zRef.
template <int D>
Real waterSurfaceFromMass(const Grid<D>& grid, const LiquidPoints<D>& liquid, Real zRef,
                          Real density, int pointsPerCell) {
    Real mass = 0;
    for (std::size_t p = 0; p < liquid.size(); ++p) {
        const Real z = liquid.x[p * D + D - 1];
        const Real half = 0.5 * liquid.mass[p] / density / grid.pointFootprint(&liquid.x[p * D], pointsPerCell);
        if (z + half <= zRef) continue;
        mass += std::min(Real(1), (z + half - zRef) / (2 * half)) * liquid.mass[p];
    }
    if (mass == 0) return 0.0;
    return zRef + mass / (density * grid.crossSection());
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
