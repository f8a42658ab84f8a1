// Phase 4b of the double-point step: the liquid-state switch, decided per cell from the grid's
// solid mass in the cell (physics/LiquidStateRule.hpp; docs/fluidisation.md). Runs after the
// nodal solve, so that the cell's solid velocity divergence (compacting or not) is this step's,
// and before the points are updated, which then take their cell's state.
#include <algorithm>

#include "materials/ConstitutiveModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::switchLiquidState() {
    forAllCells(grid_.numCells(), cells_.solidStart, [&](Index c) {
        const Index first = cells_.solidStart[c], last = cells_.solidStart[c + 1];
        if (first == last) {
            sand_.fluidised[c] = 0;
            sand_.stressFree[c] = 0;
            return;
        }
        // the cell's previous state is that of most of its solid mass; n_max the mass-weighted
        // one of its materials; stress-free if every solid-state point carries no effective stress
        Real mass = 0, fluidMass = 0, nMax = 0, diffusivity = 0, threshold = 0;
        bool stressFree = true;
        for (Index p = first; p < last; ++p) {
            const Real m = solid_.mass[p];
            mass += m;
            nMax += m * materials_[solid_.material[p]].maxPorosity;
            diffusivity += m * materials_[solid_.material[p]].frontDiffusivity;
            threshold += m * materials_[solid_.material[p]].frontThreshold;
            if (solid_.state[p] == kFluidisedState) fluidMass += m;
            else if (!isStressFree(&solid_.stress[p * 6])) stressFree = false;
        }
        nMax /= mass;
        sand_.diffusivity[c] = diffusivity / mass;
        threshold /= mass;
        sand_.inverseThreshold2[c] = threshold > 0 ? 1 / (threshold * threshold) : 0.0;
        // div v_S at the cell centre from this step's nodal velocities (extension positive). A
        // starved node (GridToPoints.cpp) counts with its fed weight w_i and, for the rest, the
        // cell's mass-weighted solid velocity: its own is a force over a sliver of mass
        Real cellMomentum[D] = {}, cellMass = 0;
        grid_.forEachNodeOfCell(c, [&](Index i, int) {
            cellMass += nodes_.massS[i];
            for (int a = 0; a < D; ++a) cellMomentum[a] += nodes_.massS[i] * nodes_.velS[i * D + a];
        });
        Real divergence = 0;
        grid_.forEachNodeOfCell(c, [&](Index i, int corner) {
            for (int a = 0; a < D; ++a) {
                const Real wa = nodes_.fedWeight[i * D + a];
                const Real v = cellMass > 0 ? wa * nodes_.velS[i * D + a] + (1 - wa) * cellMomentum[a] / cellMass : nodes_.velS[i * D + a];
                divergence += grid_.divergenceWeight(c, corner, a) * v;
            }
        });
        // the cell's porosity decides when it turns fluidised; its densest node when it resettles:
        // a sediment grows into the cell from one side, and the rest of the cell, still looser
        // than n_max, then settles onto it without a skeleton (GridToPoints.cpp)
        const Real n = sand_.porosity[c];
        Real densest = 1;
        grid_.forEachNodeOfCell(c, [&](Index i, int) { densest = std::min(densest, nodes_.sandPorosity[i]); });
        if (sand_.surface[c]) densest = n;
        const bool wasFluidised = 2 * fluidMass > mass;
        sand_.fluidised[c] = wasFluidised ? !stateRule_.turnsSolid(densest, nMax, divergence)
                                         : stateRule_.turnsFluidised(stressFree, n, nMax, divergence);
        // the sand here carries no effective stress: fronts diffuse (FrontDiffusion.cpp)
        sand_.stressFree[c] = sand_.fluidised[c] || (stressFree && fluidMass == 0);
    });
}

template void DoublePointSolver<1>::switchLiquidState();
template void DoublePointSolver<2>::switchLiquidState();
template void DoublePointSolver<3>::switchLiquidState();

}  // namespace qs
