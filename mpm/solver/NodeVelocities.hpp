#pragma once
// The nodal update with implicit drag and the boundary conditions (physics.md section 2), the
// step's phase 4 as the explicit scheme takes it and the semi-implicit one predicts with it.
// Per node and axis, with the forces F_S, F_L known, the two phases' velocities solve
//   M_S v_S = M_S v_S* + dt Q (v_L - v_S),   (M_L + dt c) v_L = M_L v_L* - dt Q (v_L - v_S),
// v* = v0 + dt F / M the drag-free predictors, Q the node's drag coefficient (kg/s), c the
// gate's tube loss in 1D; a held component keeps its prescribed value.
#include <cmath>

#include "core/ForAll.hpp"
#include "solver/NodeComponent.hpp"
#include "solver/PressureForce.hpp"
#include "solver/TimeIntegrator.hpp"

namespace qs {

/// Node i's component a as solveNodes sees it this step.
template <int D>
NodeComponent nodeComponent(const StepContext<D>& ctx, const StepInputs& in, Index i, int a) {
    const Index k = i * D + a;
    const bool vertical = a == D - 1;
    const bool isGate = i < ctx.grid.nodeStride(D - 1);  // the bottom node row
    NodeComponent n;
    n.massS = ctx.nodes.massS[i];
    n.massL = ctx.nodes.massL[i];
    n.drag = ctx.nodes.drag[i];
    // implicit tube loss at the gate: M_L v = M_L v* - dt c v, c = R A_total A_i; a uniform gate
    // takes its tube loss on the whole gate plane (uniformGateVelocity)
    if (isGate && vertical && !in.gate.uniform)
        n.tubeLoss = in.gate.resistance * in.gate.area * nodeFootprint(ctx.grid, i);
    n.solidHeld = ctx.masks.solidFixed[k];
    n.liquidHeld = ctx.masks.liquidFixed[k];
    n.heldLiquidVelocity = (isGate && vertical) ? in.gate.velocity : 0.0;
    return n;
}

/// m3/s through the gate plane: sum of v_L A_i over its wet nodes (free water: q = v_L).
template <int D>
Real gateFlux(const StepContext<D>& ctx);

/// The uniform gate: its wet nodes' water at one vertical velocity (NodeVelocities.cpp says why).
template <int D>
void uniformGateVelocity(const StepContext<D>& ctx, Real dt, Real resistance);

/// Phase 4 of the explicit step: every node's velocities with implicit drag, the masks and the
/// gate; nodes.velS, velL, velLIncrement and relSpeed. Returns the gate flux, m3/s.
/// visit(i, component, vS1, vL1, contact) sees each node as it is solved, its components (a
/// component the wall holds by friction held), drag-free predictors and, at a rough wall, the
/// friction's limit and decision (else nullptr): the semi-implicit step takes the components'
/// responses to a pressure force in the same pass, and checks the walls' decisions against it.
template <int D, class Visit>
Real solveNodes(const StepContext<D>& ctx, const StepInputs& in, Visit&& visit) {
    NodeFields<D>& nodes = ctx.nodes;
    const Real dt = in.dt;
    forAll(ctx.grid.numNodes(), [&](Index i) {
        const Real mS = nodes.massS[i], mL = nodes.massL[i];
        Real vS1[D], vL1[D], vL0[D];
        NodeComponent component[D];
        for (int d = 0; d < D; ++d) {
            const Index k = i * D + d;
            const Real vS0 = mS > 0 ? nodes.momS[k] / mS : 0.0;
            vL0[d] = mL > 0 ? nodes.momL[k] / mL : 0.0;
            Real fS = nodes.forceS[k], fL = nodes.forceL[k];
            if (in.damping) {
                // local damping, gravity stage only: F <- F - alpha |F| sign(v)
                fS -= in.dampingAlpha * std::abs(fS) * (vS0 > 0 ? 1 : (vS0 < 0 ? -1 : 0));
                fL -= in.dampingAlpha * std::abs(fL) * (vL0[d] > 0 ? 1 : (vL0[d] < 0 ? -1 : 0));
            }
            vS1[d] = mS > 0 ? vS0 + dt * fS / mS : 0.0;  // drag-free predictors
            vL1[d] = mL > 0 ? vL0[d] + dt * fL / mL : 0.0;
            component[d] = nodeComponent(ctx, in, i, d);
        }
        PhaseVelocities v[D];
        typename RoughWalls<D>::Contact contact;
        const bool wall = ctx.masks.roughWalls.rough(i) && mS > 0;
        if (wall) {
            // the grains' push on the wall, the pore pressure's share off (boundary/RoughWalls.hpp)
            // from the undamped force: the gravity stage's damping is no force on a wall
            Real pL[D], pS[D], grainPush[D];
            nodePressureForce(ctx.grid, ctx.water, nodes.porosity[i], i, pL, pS);
            for (int d = 0; d < D; ++d) grainPush[d] = nodes.momS[i * D + d] / dt + nodes.forceS[i * D + d] - pS[d];
            contact = ctx.masks.roughWalls.solve(i, dt, grainPush, component, vS1, vL1, v);
        } else {
            for (int d = 0; d < D; ++d) v[d] = solveComponent(component[d], dt, vS1[d], vL1[d]);
        }
        visit(i, component, vS1, vL1, wall ? &contact : nullptr);
        Real w2 = 0;
        for (int d = 0; d < D; ++d) {
            const Index k = i * D + d;
            nodes.velS[k] = v[d].solid;
            nodes.velL[k] = v[d].liquid;
            nodes.velLIncrement[k] = v[d].liquid - vL0[d];  // what the FLIP update hands the liquid points
            w2 += (v[d].liquid - v[d].solid) * (v[d].liquid - v[d].solid);
        }
        nodes.relSpeed[i] = (mS > 0 && mL > 0) ? std::sqrt(w2) : 0.0;
    });
    if (in.gate.uniform) uniformGateVelocity(ctx, dt, in.gate.resistance);
    return gateFlux(ctx);
}

/// The same, for the explicit step.
template <int D>
Real solveNodes(const StepContext<D>& ctx, const StepInputs& in) {
    return solveNodes(ctx, in, [](Index, const NodeComponent(&)[D], const Real(&)[D], const Real(&)[D],
                                  const typename RoughWalls<D>::Contact*) {});
}

}  // namespace qs
