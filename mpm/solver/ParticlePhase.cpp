// Phase 3 of the double-point step, in computeForces: the fluidised sand's particle phase,
// Foscolo and Gibilaro's elastic force (physics/ParticlePhase.hpp says why, and why as an
// exchange force). Per solid point of a material that has it, inside sand without effective
// stress (every node its stencil reaches is one: insideStressFreeSand, as the front diffusion),
//   f = -K(n) grad(phi) V_p     on the grains,  +f's opposite on the water,
// scattered with the point's weights N_i: the nodes' F_S -= N_i f, F_L += N_i f. grad(phi) is taken
// at the point from its own stencil's nodal sand porosity, as the front diffusion takes it
// (GridToPoints.cpp): compact, so that no grid mode of phi, the odd-even one included, escapes
// it. The two phases' forces cancel node by node: the mixture's momentum is untouched.
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"
#include "solver/PointStencil.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::particlePhaseForces() {
    if (!anyParticlePhase_) return;
    forAll(grid_.numNodes(), [&](Index i) { nodes_.particlePhaseNode[i] = insideStressFreeSand(i); });
    // most steps of most runs have no stress-free sand
    if (!anyOf(grid_.numNodes(), [&](Index i) { return nodes_.particlePhaseNode[i] != 0; })) return;
    const bool linear = config_.grid.shapeFunctions != ShapeFunctionKind::Gimp;
    withStencilKind(linear, [&](auto linearShapes) {
        constexpr bool kLinear = decltype(linearShapes)::value;
        forEachPointColoured(grid_, cells_.solidStart, slabRows(kLinear), [&](Index p) {
            const SolidMaterial& material = materials_[solid_.material[p]];
            if (!material.particlePhase) return;
            Real gradPhi[D] = {}, n = 0;
            bool inside = true;
            forEachNodeOfPoint<kLinear>(grid_, solid_, p, [&](Index i, Real N, const Real* gradN) {
                for (int d = 0; d < D; ++d) gradPhi[d] -= gradN[d] * nodes_.sandPorosity[i];
                n += N * nodes_.sandPorosity[i];
                if (N > 0 && !nodes_.particlePhaseNode[i]) inside = false;
            });
            if (!inside) return;
            const Real KV = material.elasticForce.modulus(n) * solid_.volume[p];
            forEachNodeOfPoint<kLinear>(grid_, solid_, p, [&](Index i, Real N, const Real*) {
                for (int d = 0; d < D; ++d) {
                    const Real f = N * KV * gradPhi[d];
                    nodes_.forceS[i * D + d] -= f;
                    nodes_.forceL[i * D + d] += f;
                }
            });
        });
    });
}

template void DoublePointSolver<1>::particlePhaseForces();
template void DoublePointSolver<2>::particlePhaseForces();
template void DoublePointSolver<3>::particlePhaseForces();

}  // namespace qs
