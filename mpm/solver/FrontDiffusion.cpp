// Phase 4c of the double-point step: where the kinematic front diffusion of
// physics/FrontDiffusion.hpp acts. A node takes part when every cell around it holds sand that
// carries no effective stress (fluidised, or a skeleton at its tension cut-off / apex); a point
// diffuses when its whole stencil does. Not in the top two sand cells (phi drops to zero at the
// surface, a strong front that needs no help, and whose porosity the grid cannot resolve), nor
// on the filter (the sand's vertical motion held), nor on the grid's bottom and top rows.
// On the smooth side walls it does act: they hold only the horizontal motion, and the diffusion
// flux through them vanishes with the gradient of a field symmetric about them. (Taken out there
// like the filter, it left the wall columns of a 2D bed expanding differently from the inner ones,
// 0.467 against 0.456 behind the front, and the bed lost its lateral uniformity.)
// GridToPoints.cpp moves the points: per point, from the grid's solid fraction at its stencil,
//   w_S = -D grad(phi) / phi   (grad from the shape-function gradients: compact, so that no
//                               grid mode of phi, the odd-even one included, escapes it)
//   w_L = -(1 - n) w_S / n     (the liquid: the mixture's volume flux is unchanged)
// added to the displacement, not to the velocity.
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
bool DoublePointSolver<D>::insideStressFreeSand(Index i) const {
    const Index row = i / grid_.nodeStride(D - 1);
    if (!(nodes_.massS[i] > 0) || masks_.solidFixed[i * D + D - 1] || row == 0 || row == grid_.nodes(D - 1) - 1)
        return false;
    bool inside = true;
    grid_.forEachCellOfNode(i, [&](Index c, int) {
        if (!cells_.hasSolid(c) || !sand_.stressFree[c] || sand_.surface[c]) inside = false;
    });
    return inside;
}

template <int D>
void DoublePointSolver<D>::diffuseFronts() {
    forAll(grid_.numNodes(), [&](Index i) { nodes_.diffusionNode[i] = insideStressFreeSand(i); });
    // most steps of most runs have no stress-free sand: the points then skip the diffusion's sums
    nodes_.anyDiffusion = anyOf(grid_.numNodes(), [&](Index i) { return nodes_.diffusionNode[i] != 0; });
}

template bool DoublePointSolver<1>::insideStressFreeSand(Index) const;
template bool DoublePointSolver<2>::insideStressFreeSand(Index) const;
template bool DoublePointSolver<3>::insideStressFreeSand(Index) const;
template void DoublePointSolver<1>::diffuseFronts();
template void DoublePointSolver<2>::diffuseFronts();
template void DoublePointSolver<3>::diffuseFronts();

}  // namespace qs
