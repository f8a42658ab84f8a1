// Phase 4c of the double-point step: where the kinematic front diffusion of
// physics/FrontDiffusion.hpp acts. A node takes part when every cell around it holds sand that
// carries no effective stress (fluidised, or a skeleton at its tension cut-off / apex); a point
// diffuses when its whole stencil does. Not in the top two sand cells (phi drops to zero at the
// surface, a strong front that needs no help, and whose porosity the grid cannot resolve), nor
// next to the filter or a wall (held components).
// GridToPoints.cpp moves the points: per point, from the grid's solid fraction at its stencil,
//   w_S = -D grad(phi) / phi   (grad from the shape-function gradients: compact, so that no
//                               grid mode of phi, the odd-even one included, escapes it)
//   w_L = -(1 - n) w_S / n     (the liquid: the mixture's volume flux is unchanged)
// added to the displacement, not to the (FLIP) velocity.
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::diffuseFronts() {
    forAll(grid_.numNodes(), [&](Index i) {
        bool inside = massS_[i] > 0;
        int cells = 0;
        grid_.forEachCellOfNode(i, [&](Index c, int) {
            if (solidCellStart_[c + 1] == solidCellStart_[c] || !cellStressFree_[c] || cellSandSurface_[c])
                inside = false;
            ++cells;
        });
        for (int a = 0; a < D; ++a)
            if (masks_.solidFixed[i * D + a]) inside = false;
        diffusionNode_[i] = inside && cells == (1 << D);
    });
    // most steps of most runs have no stress-free sand: the points then skip the diffusion's sums
    anyDiffusion_ = anyOf(grid_.numNodes(), [&](Index i) { return diffusionNode_[i] != 0; });
}

template void DoublePointSolver<1>::diffuseFronts();
template void DoublePointSolver<2>::diffuseFronts();
template void DoublePointSolver<3>::diffuseFronts();

}  // namespace qs
