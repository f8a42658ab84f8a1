// Phase 4c of the double-point step: the kinematic front diffusion of physics/FrontDiffusion.hpp.
// Per node whose cells with sand all carry no effective stress (fluidised, or a skeleton at its
// tension cut-off / apex): a diffusion velocity of the solid, w_S = -D grad(phi)/phi, and the
// liquid's w_L = -(1-n) w_S / n that keeps the mixture's volume flux, for the points' displacement
// and strain only (GridToPoints.cpp). Elsewhere, and in held components (filter, walls, a rigid
// skeleton), zero.
#include <algorithm>
#include <cmath>

#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::diffuseFronts() {
    forAll(grid_.numNodes(), [&](Index i) {
        Real* wS = &diffusionS_[i * D];
        Real* wL = &diffusionL_[i * D];
        for (int a = 0; a < D; ++a) wS[a] = wL[a] = 0;
        if (massS_[i] <= 0) return;
        // Only inside the sand: every cell around the node holds sand carrying no effective
        // stress (at the sand's surface phi drops to zero, and that edge is not to be spread).
        // grad(phi) from the cells' own sand porosities (measureSandPorosity: the surface's top
        // cells corrected), D their mean diffusivity.
        Real up[D] = {}, down[D] = {}, diffusivity = 0;
        int cells = 0;
        bool inside = true;
        grid_.forEachCellOfNode(i, [&](Index c, int corner) {
            if (solidCellStart_[c + 1] == solidCellStart_[c] || !cellStressFree_[c]) inside = false;
            ++cells;
            diffusivity += cellDiffusivity_[c];
            // corner bit a set: the node is the cell's upper node along a, so the cell lies below
            for (int a = 0; a < D; ++a) ((corner >> a) & 1 ? down : up)[a] += 1 - cellSandPorosity_[c];
        });
        if (!inside || cells < (1 << D)) return;
        Real grad[D];
        for (int a = 0; a < D; ++a) grad[a] = (up[a] - down[a]) / ((1 << (D - 1)) * grid_.h());
        const Real phi = std::max(Real(1e-3), 1 - sandPorosity_[i]);
        const Real n = porosity_[i];
        const Real k = diffusivity / (cells * phi);  // D / phi
        for (int a = 0; a < D; ++a) {
            if (masks_.solidFixed[i * D + a]) continue;
            wS[a] = -k * grad[a];
            if (massL_[i] > 0 && !masks_.liquidFixed[i * D + a] && n < 1) wL[a] = -(1 - n) * wS[a] / n;
        }
    });
}

template void DoublePointSolver<1>::diffuseFronts();
template void DoublePointSolver<2>::diffuseFronts();
template void DoublePointSolver<3>::diffuseFronts();

}  // namespace qs
