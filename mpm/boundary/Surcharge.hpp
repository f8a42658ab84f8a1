#pragma once
// The surcharge on the sand (loads.surcharge): a uniform vertical pressure on the sand's top,
// acting where the sand is in each vertical column of cells. A single level for the whole column
// (the highest point anywhere) put the load of a lower part of the surface on nodes above it,
// which carry no solid there, and so lost it; per column each part of the surface carries its
// own share, q times its plan area (issue 7: surfaces local in 2D and 3D).
#include <algorithm>
#include <cmath>
#include <vector>

#include "grid/Grid.hpp"
#include "points/SolidPoints.hpp"

namespace qs {

/// m, the top of the highest solid point of one vertical column of cells (its extent from its
/// volume), or `floor` when the column holds no sand. `cellStart` lists the points by cell.
template <int D>
Real sandTopOfColumn(const Grid<D>& grid, const SolidPoints<D>& solid, const std::vector<Index>& cellStart,
                     Index column, int pointsPerCell, Real floor) {
    const Index up = grid.cellStride(D - 1);
    for (Index row = grid.cells(D - 1) - 1; row >= 0; --row) {
        const Index c = column + row * up;
        if (cellStart[c + 1] == cellStart[c]) continue;
        Real top = floor;
        for (Index p = cellStart[c]; p < cellStart[c + 1]; ++p)
            top = std::max(top, solid.x[p * D + D - 1] +
                                    0.5 * solid.volume[p] / grid.pointFootprint(&solid.x[p * D], pointsPerCell));
        return top;
    }
    return floor;
}

/// Adds the force of the surcharge q (Pa, downwards) on the sand's top, column by column of
/// cells: F_i = -q N_i(z_col) a_i,col on the vertical component, a_i,col the node's share of the
/// column's plan area (the traction of the weak form on each column's part of the surface).
template <int D>
void addSurcharge(const Grid<D>& grid, const SolidPoints<D>& solid, const std::vector<Index>& cellStart,
                  int pointsPerCell, Real filterLevel, Real q, std::vector<Real>& force) {
    const Real h = grid.h();
    const Index up = grid.cellStride(D - 1);
    for (Index column = 0; column < up; ++column) {
        const Real z = sandTopOfColumn(grid, solid, cellStart, column, pointsPerCell, filterLevel);
        const Index row = std::clamp<Index>(static_cast<Index>(std::floor(z / h)), 0, grid.cells(D - 1) - 1);
        const Real xi = std::clamp(z / h - row, Real(0), Real(1));
        // a corner's share of the column's plan area: its share of the cell's volume over h / 2
        grid.forEachNodeOfCell(column + row * up, [&](Index i, int corner) {
            const Real N = ((corner >> (D - 1)) & 1) ? xi : 1 - xi;
            force[i * D + D - 1] -= q * N * 2 * grid.cellShare(column + row * up, corner) / h;
        });
    }
}

}  // namespace qs
