// Phase 3 of the double-point step, in computeForces: close packing's contact pressure
// (physics/ClosePacking.hpp says why and how stiff). Taken as the pore pressure's force is (the
// transpose of the cells' divergence, solver/PressureForce.hpp), on the grains alone:
//   cells:  Pi_c from the cell's sand porosity, mass-weighted over its points' materials, in every
//           cell that holds sand but the top two of its column (0 in one without: a pocket of
//           water takes no push back);
//   nodes:  F_S,i += sum_c Pi_c V_c w_c,i.
// Most steps of most runs have no cell past its densest packing: then nothing is added.
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::packingForces() {
    if (!anyClosePacking_) return;
    std::vector<Real>& pressure = sand_.packingPressure;
    forAllCells(grid_.numCells(), cells_.solidStart, [&](Index c) {
        Index first = cells_.solidStart[c];
        const Index last = cells_.solidStart[c + 1];
        Real mass = 0, pi = 0;
        // not the top two sand cells of a column: their porosity is the cell below's, taken where
        // the grid cannot tell a loose cell from a half-filled one (measureSandPorosity), and a
        // push there lands on the surface's top node, which holds a few points' mass (a soft
        // skeleton's surface flew off the grid under it); the third cell's push holds them up
        if (sand_.surface[c]) first = last;
        for (Index p = first; p < last; ++p) {
            mass += solid_.mass[p];
            pi += solid_.mass[p] * materials_[solid_.material[p]].packing.pressure(sand_.porosity[c]);
        }
        pressure[c] = mass > 0 ? pi / mass : 0;
    });
    if (!anyOf(grid_.numCells(), [&](Index c) { return pressure[c] > 0; })) return;
    forAll(grid_.numNodes(), [&](Index i) {
        if (!(nodes_.massS[i] > 0)) return;
        grid_.forEachCellOfNode(i, [&](Index c, int corner) {
            if (pressure[c] == 0) return;
            const Real piV = pressure[c] * grid_.cellVolume(c);
            for (int a = 0; a < D; ++a) nodes_.forceS[i * D + a] += piV * grid_.divergenceWeight(c, corner, a);
        });
    });
}

template void DoublePointSolver<1>::packingForces();
template void DoublePointSolver<2>::packingForces();
template void DoublePointSolver<3>::packingForces();

}  // namespace qs
