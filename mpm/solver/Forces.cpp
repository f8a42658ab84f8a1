// Phase 3 of the double-point step: the nodal forces (physics.md section 2). The effective
// stress came with the points (PointsToGrid.cpp); here, in this order, which fixes each force
// entry's sums to the bit: the pore pressure at the step's start (PorePressure.cpp), gravity, the
// fluidised sand's particle phase (ParticlePhase.cpp), close packing's contact pressure
// (PackingPressure.cpp), the gate's traction (Gate.cpp) and the
// surcharge. Phase 4, the velocities, is the time scheme's
// (solver/TimeIntegrator.hpp).
#include "solver/DoublePointSolver.hpp"
#include "boundary/Surcharge.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::computeForces() {
    cellWaterFromPoints();
    computePressureGradient();
    pressureForces();
    gravityForces();
    particlePhaseForces();
    packingForces();
    gateTraction();
    // Surcharge on the sand top (solid phase), as a traction where the sand's surface is in each
    // column of cells (boundary/Surcharge.hpp). The water's surface needs none: with an overflow
    // it is held at the overflow level, where the top cells count as full (classifyCells), and
    // the natural zero-traction condition holds at a free surface.
    const Real q = surchargeNow();
    if (q != 0)
        addSurcharge(grid_, solid_, cells_.solidStart, config_.points.solidPerCell, q, nodes_.forceS);
}

template <int D>
void DoublePointSolver<D>::gravityForces() {
    const Real g = config_.gravity;
    if (weightShare_ < 1) {
        // the gravity stage's ramp: the grains weigh what the water they displace weighs, plus the
        // loaded share f of their buoyant weight, f M_S g + (1 - f) rho_L V_grains g (a density
        // rising from the water's to their own); the water weighs all its weight, and stays at rest
        const Real f = weightShare_, rhoL = config_.liquid.density;
        forAll(grid_.numNodes(), [&](Index i) {
            nodes_.forceS[i * D + D - 1] -= (f * nodes_.massS[i] + (1 - f) * rhoL * sums_.grainVolume[i]) * g;
            nodes_.forceL[i * D + D - 1] -= nodes_.massL[i] * g;
        });
        return;
    }
    forAll(grid_.numNodes(), [&](Index i) {
        nodes_.forceS[i * D + D - 1] -= nodes_.massS[i] * g;
        nodes_.forceL[i * D + D - 1] -= nodes_.massL[i] * g;
    });
}

template void DoublePointSolver<1>::computeForces();
template void DoublePointSolver<2>::computeForces();
template void DoublePointSolver<3>::computeForces();

}  // namespace qs
