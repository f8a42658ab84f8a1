// Phase 4 of the double-point step: the nodal velocities with implicit drag, the boundary
// conditions and the uniform gate (NodeVelocities.hpp).
#include "solver/NodeVelocities.hpp"

#include <cmath>

#include "core/ForAll.hpp"

namespace qs {

namespace {

// The gate plane is where the tube's water enters the chamber, with water on both sides. Held
// only by a uniform pressure, node by node, the chamber's water would sit on the gate like water
// in an upturned glass: a free surface with the heavy fluid on top, Rayleigh-Taylor unstable.
// A lateral mode grew from round-off at 20 /s in a 2D case B at rest and broke it after 2.3 s
// of flow. The gate therefore moves all its nodes' water at one vertical velocity: the total
// momentum of the gate row, with the reservoir's pressure (computeForces) and the tube loss
// R Q A_wet taken implicitly on the whole flux, Q = v A_wet (exact now, where per node it was
// not; a gate node without water, which injection keeps rare, carries neither).
// The chamber redistributes the water sideways, as the real one under its filter does.
template <int D>
void uniformGateVelocity(const StepContext<D>& ctx, Real dt, Real resistance) {
    NodeFields<D>& nodes = ctx.nodes;
    // the wet part of the gate carries the flux, Q = v A_wet, and the tube loss R Q on it
    Real momentum = 0, mass = 0, wet = 0;
    for (Index i : ctx.masks.gateNodes) {
        if (nodes.massL[i] <= 0) continue;
        momentum += nodes.massL[i] * nodes.velL[i * D + D - 1];  // the drag-free predictor (no solid here)
        mass += nodes.massL[i];
        wet += nodeFootprint(ctx.grid, i);
    }
    const Real v = mass > 0 ? momentum / (mass + dt * resistance * wet * wet) : 0.0;
    for (Index i : ctx.masks.gateNodes)
        if (nodes.massL[i] > 0) {
            const Index k = i * D + D - 1;
            nodes.velL[k] = v;
            nodes.velLIncrement[k] = v - nodes.momL[k] / nodes.massL[i];  // from the velocity before the step, as solveNodes
        }
}

}  // namespace

template <int D>
Real solveNodes(const StepContext<D>& ctx, const StepInputs& in) {
    NodeFields<D>& nodes = ctx.nodes;
    const Real dt = in.dt;
    forAll(ctx.grid.numNodes(), [&](Index i) {
        const Real mS = nodes.massS[i], mL = nodes.massL[i];
        Real w2 = 0;
        for (int d = 0; d < D; ++d) {
            const Index k = i * D + d;
            const Real vS0 = mS > 0 ? nodes.momS[k] / mS : 0.0;
            const Real vL0 = mL > 0 ? nodes.momL[k] / mL : 0.0;
            Real fS = nodes.forceS[k], fL = nodes.forceL[k];
            if (in.damping) {
                // local damping, gravity stage only: F <- F - alpha |F| sign(v)
                fS -= in.dampingAlpha * std::abs(fS) * (vS0 > 0 ? 1 : (vS0 < 0 ? -1 : 0));
                fL -= in.dampingAlpha * std::abs(fL) * (vL0 > 0 ? 1 : (vL0 < 0 ? -1 : 0));
            }
            const Real vS1 = mS > 0 ? vS0 + dt * fS / mS : 0.0;  // drag-free predictors
            const Real vL1 = mL > 0 ? vL0 + dt * fL / mL : 0.0;
            const PhaseVelocities v = solveComponent(nodeComponent(ctx, in, i, d), dt, vS1, vL1);
            nodes.velS[k] = v.solid;
            nodes.velL[k] = v.liquid;
            nodes.velLIncrement[k] = v.liquid - vL0;  // what the FLIP update hands the liquid points
            w2 += (v.liquid - v.solid) * (v.liquid - v.solid);
        }
        nodes.relSpeed[i] = (mS > 0 && mL > 0) ? std::sqrt(w2) : 0.0;
    });
    if (in.gate.uniform) uniformGateVelocity(ctx, dt, in.gate.resistance);
    return gateFlux(ctx);
}

template <int D>
Real gateFlux(const StepContext<D>& ctx) {
    Real Qg = 0;
    for (Index i : ctx.masks.gateNodes)
        if (ctx.nodes.massL[i] > 0) Qg += ctx.nodes.velL[i * D + D - 1] * nodeFootprint(ctx.grid, i);
    return Qg;
}

#define QS_INSTANTIATE(D)                                                          \
    template Real solveNodes<D>(const StepContext<D>&, const StepInputs&);         \
    template Real gateFlux<D>(const StepContext<D>&);
QS_INSTANTIATE(1)
QS_INSTANTIATE(2)
QS_INSTANTIATE(3)
#undef QS_INSTANTIATE

}  // namespace qs
