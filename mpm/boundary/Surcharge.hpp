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

/// The sand's surface in one vertical column of cells: the row of its highest cell holding sand
/// and the top of that cell's highest point (its extent from its volume). Row -1: no sand.
struct ColumnSurface {
    Index row = -1;
    Real top = 0;  ///< m
};

template <int D>
ColumnSurface sandSurfaceOfColumn(const Grid<D>& grid, const SolidPoints<D>& solid,
                                  const std::vector<Index>& cellStart, Index column, int pointsPerCell) {
    const Index up = grid.cellStride(D - 1);
    for (Index row = grid.cells(D - 1) - 1; row >= 0; --row) {
        const Index c = column + row * up;
        if (cellStart[c + 1] == cellStart[c]) continue;
        ColumnSurface s{row, 0};
        for (Index p = cellStart[c]; p < cellStart[c + 1]; ++p)
            s.top = std::max(s.top, solid.x[p * D + D - 1] +
                                        0.5 * solid.volume[p] / grid.pointFootprint(&solid.x[p * D], pointsPerCell));
        return s;
    }
    return {};
}

/// Adds the force of the surcharge q (Pa, downwards) on the sand's top, column by column of
/// cells: F_i = -q N_i(z_col) a_i,col on the vertical component, a_i,col the node's share of the
/// column's plan area (the traction of the weak form on each column's part of the surface).
/// z_col is taken within the column's top sand cell: a top point reaching a little above its cell
/// would put the load on nodes of the row above, which hold no solid there. A column without
/// sand carries nothing (its share has no sand to act on).
template <int D>
void addSurcharge(const Grid<D>& grid, const SolidPoints<D>& solid, const std::vector<Index>& cellStart,
                  int pointsPerCell, Real q, std::vector<Real>& force) {
    const Real h = grid.h();
    const Index up = grid.cellStride(D - 1);
    for (Index column = 0; column < up; ++column) {
        const ColumnSurface s = sandSurfaceOfColumn(grid, solid, cellStart, column, pointsPerCell);
        if (s.row < 0) continue;
        const Real xi = std::clamp(s.top / h - s.row, Real(0), Real(1));
        const Index cell = column + s.row * up;
        // a corner's share of the column's plan area: its share of the cell's volume over h / 2
        grid.forEachNodeOfCell(cell, [&](Index i, int corner) {
            const Real N = ((corner >> (D - 1)) & 1) ? xi : 1 - xi;
            force[i * D + D - 1] -= q * N * 2 * grid.cellShare(cell, corner) / h;
        });
    }
}

}  // namespace qs
