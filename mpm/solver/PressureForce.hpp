#pragma once
// The pore pressure's force on one node, both phases (physics.md section 2, pressure forces): the
// transpose of the cells' divergence (PorePressure.cpp says why it is this form),
//   F_p,L,i = + sum_c p_c V_c n_i grad N_i(x_c),  F_p,S,i = + sum_c p_c V_c (1 - n_i) grad N_i(x_c).
// Written once: pressureForces adds it to every node, and a rough wall (boundary/RoughWalls.hpp)
// takes it off the grains' push on the wall, which presses the grains, not the water, on it.
#include "grid/Grid.hpp"
#include "solver/GridFields.hpp"

namespace qs {

template <int D>
void nodePressureForce(const Grid<D>& grid, const CellWater<D>& water, Real porosity, Index i, Real (&fL)[D],
                       Real (&fS)[D]) {
    for (int a = 0; a < D; ++a) fL[a] = fS[a] = 0;
    grid.forEachCellOfNode(i, [&](Index cell, int corner) {
        const Real pV = water.pressure[cell] * water.weight[cell];
        if (pV == 0) return;
        for (int a = 0; a < D; ++a) {
            const Real gN = grid.divergenceWeight(cell, corner, a);
            fL[a] += pV * porosity * gN;
            fS[a] += pV * (1 - porosity) * gN;
        }
    });
}

}  // namespace qs
