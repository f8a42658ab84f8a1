// Phase 3 of the double-point step, in computeForces: the fluidised sand's particle phase,
// Foscolo and Gibilaro's elastic force (physics/ParticlePhase.hpp says why, why as an exchange
// force, and why in this form). With Pi the particle pressure, K grad(phi) = grad(Pi):
//   cells:  Pi_c from the cell's sand porosity, where the sand carries no effective stress;
//   nodes:  F_S,i += sum_c Pi_c V_c w_c,i   (the transpose of the cells' divergence, as the pore
//           pressure's force: solver/PressureForce.hpp),  F_L,i -= the same,
// at nodes whose cells all carry such sand (a node at the zone's edge gets nothing: no push on
// the plug above an expansion front, nor on the filter). The two phases' forces cancel node by
// node: the mixture's momentum is untouched.
// The cells are decided from their points as the step finds them (each point fluidised or
// without effective stress; points and their stresses are checkpointed), so that a resumed run,
// and a repeated coupling window, take the same force as a straight run. (This mask is not quite
// the front diffusion's, which is the liquid-state switch's verdict after the step's solve.)
// What it does not see: Pi_c comes from the cell's mean of its nodes' sand porosity, so in 1D
// the force is K V (n_i+1 - n_i-1) / 2h at a node, the wide difference, as the point-spread form
// it replaced was, and with the nodes' porosity moved by their velocities' wide divergence the
// pair damps a mode by sin^2(kh) / h^2 instead of k^2: blind to the nodes' odd-even mode. The
// front diffusion, applied to the points per cell, is compact and catches such a pattern once it
// passes its threshold (docs/verification.md, problem 12b).
#include <cmath>
#include <limits>

#include "materials/ConstitutiveModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::particlePhaseForces() {
    if (!anyParticlePhase_) return;
    constexpr Real kOutside = std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real>& pressure = sand_.particlePressure;
    forAllCells(grid_.numCells(), cells_.solidStart, [&](Index c) {
        const Index first = cells_.solidStart[c], last = cells_.solidStart[c + 1];
        bool inside = first < last && !sand_.surface[c];
        Real mass = 0, pi = 0;
        const Real phi = 1 - sand_.porosity[c];
        for (Index p = first; p < last && inside; ++p) {
            const SolidMaterial& material = materials_[solid_.material[p]];
            const bool free = solid_.state[p] == kFluidisedState || isStressFree(&solid_.stress[p * 6]);
            inside = material.particlePhase && free;
            mass += solid_.mass[p];
            pi += solid_.mass[p] * material.elasticForce.pressure(phi);
        }
        pressure[c] = inside ? pi / mass : kOutside;
    });
    // most steps of most runs have no stress-free sand: the nodes then have nothing to take
    if (!anyOf(grid_.numCells(), [&](Index c) { return !std::isnan(pressure[c]); })) return;
    const Index rowStride = grid_.nodeStride(D - 1), lastRow = grid_.nodes(D - 1) - 1;
    forAll(grid_.numNodes(), [&](Index i) {
        const Index row = i / rowStride;
        if (!(nodes_.massS[i] > 0) || masks_.solidFixed[i * D + D - 1] || row == 0 || row == lastRow) return;
        Real f[D] = {};
        bool inside = true;
        grid_.forEachCellOfNode(i, [&](Index c, int corner) {
            if (std::isnan(pressure[c])) inside = false;
            const Real piV = pressure[c] * grid_.cellVolume(c);
            for (int a = 0; a < D; ++a) f[a] += piV * grid_.divergenceWeight(c, corner, a);
        });
        if (!inside) return;
        for (int a = 0; a < D; ++a) {
            nodes_.forceS[i * D + a] += f[a];
            nodes_.forceL[i * D + a] -= f[a];
        }
    });
}

template void DoublePointSolver<1>::particlePhaseForces();
template void DoublePointSolver<2>::particlePhaseForces();
template void DoublePointSolver<3>::particlePhaseForces();

}  // namespace qs
