// Phase 4 of the double-point step: the uniform gate and the gate's flux (the node solve itself
// is in NodeVelocities.hpp, for the two schemes to share it in one pass).
#include "solver/NodeVelocities.hpp"

#include <cmath>

namespace qs {

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
        if (nodes.massL[i] <= 0 || (ctx.ranks && !ctx.ranks->ownsNode(i))) continue;
        momentum += nodes.massL[i] * nodes.velL[i * D + D - 1];  // the drag-free predictor (no solid here)
        mass += nodes.massL[i];
        wet += nodeFootprint(ctx.grid, i);
    }
    if (ctx.ranks) {  // the whole gate plane's, over the ranks
        momentum = ctx.ranks->comm().sum(momentum);
        mass = ctx.ranks->comm().sum(mass);
        wet = ctx.ranks->comm().sum(wet);
    }
    const Real v = mass > 0 ? momentum / (mass + dt * resistance * wet * wet) : 0.0;
    for (Index i : ctx.masks.gateNodes)
        if (nodes.massL[i] > 0) {
            const Index k = i * D + D - 1;
            nodes.velL[k] = v;
            nodes.velLIncrement[k] = v - nodes.momL[k] / nodes.massL[i];  // from the velocity before the step, as solveNodes
        }
}

template <int D>
Real gateFlux(const StepContext<D>& ctx) {
    Real Qg = 0;
    for (Index i : ctx.masks.gateNodes)
        if (ctx.nodes.massL[i] > 0 && (!ctx.ranks || ctx.ranks->ownsNode(i)))
            Qg += ctx.nodes.velL[i * D + D - 1] * nodeFootprint(ctx.grid, i);
    return ctx.ranks ? ctx.ranks->comm().sum(Qg) : Qg;
}

#define QS_INSTANTIATE(D)                                                          \
    template void uniformGateVelocity<D>(const StepContext<D>&, Real, Real);         \
    template Real gateFlux<D>(const StepContext<D>&);
QS_INSTANTIATE(1)
QS_INSTANTIATE(2)
QS_INSTANTIATE(3)
#undef QS_INSTANTIATE

}  // namespace qs
