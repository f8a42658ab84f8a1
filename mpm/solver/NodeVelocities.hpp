#pragma once
// The nodal update with implicit drag and the boundary conditions (physics.md section 2), the
// step's phase 4 as the explicit scheme takes it and the semi-implicit one predicts with it.
// Per node and axis, with the forces F_S, F_L known, the two phases' velocities solve
//   M_S v_S = M_S v_S* + dt Q (v_L - v_S),   (M_L + dt c) v_L = M_L v_L* - dt Q (v_L - v_S),
// v* = v0 + dt F / M the drag-free predictors, Q the node's drag coefficient (kg/s), c the
// gate's tube loss in 1D; a held component keeps its prescribed value.
#include <cmath>

#include "core/ForAll.hpp"
#include "solver/TimeIntegrator.hpp"

namespace qs {

/// One node component's masses, drag and boundary flags: what its velocities depend on besides
/// the predictors.
struct NodeComponent {
    Real massS = 0, massL = 0;  ///< kg
    Real drag = 0;              ///< kg/s, Q_i
    Real tubeLoss = 0;          ///< kg/s, c = R A_gate A_i at a 1D gate's vertical component, else 0
    bool solidHeld = false, liquidHeld = false;
    Real heldLiquidVelocity = 0;  ///< m/s, the liquid's prescribed value where it is held
};

struct PhaseVelocities { Real solid = 0, liquid = 0; };

/// The component's end-of-step velocities from the drag-free predictors vS1, vL1 (ignored for a
/// phase without mass). Linear in (vS1, vL1, heldLiquidVelocity): the semi-implicit scheme takes
/// its response to a pressure force from it (componentResponse, below).
inline PhaseVelocities solveComponent(const NodeComponent& n, Real dt, Real vS1, Real vL1) {
    const Real mS = n.massS, mL = n.massL, Q = n.drag;
    Real vS = 0, vL = 0;
    if (mS > 0 && mL > 0) {
        if (n.solidHeld && n.liquidHeld) {
            vS = 0; vL = n.heldLiquidVelocity;
        } else if (n.solidHeld) {
            // solid held: solve the liquid alone (solving the pair and overwriting one
            // afterwards loses momentum)
            vS = 0;
            vL = (mL * vL1) / (mL + dt * Q + dt * n.tubeLoss);
        } else if (n.liquidHeld) {
            vL = n.heldLiquidVelocity;
            vS = (mS * vS1 + dt * Q * vL) / (mS + dt * Q);
        } else {
            // drag keeps M_L v_L + M_S v_S and relaxes w = v_L - v_S
            const Real M = mL + mS;
            const Real vm = (mL * vL1 + mS * vS1) / M;
            const Real w = (vL1 - vS1) / (1 + dt * Q * (1 / mL + 1 / mS));
            vL = vm + mS * w / M;
            vS = vm - mL * w / M;
        }
    } else if (mL > 0) {
        vL = n.liquidHeld ? n.heldLiquidVelocity : mL * vL1 / (mL + dt * n.tubeLoss);
    } else if (mS > 0) {
        vS = n.solidHeld ? 0.0 : vS1;
    }
    return {vS, vL};
}

/// The component's velocities per unit impulse on the mixture, shared as (1 - n) on the solid
/// and n on the liquid, nothing prescribed: solveComponent with vS1 = (1 - n) / M_S,
/// vL1 = n / M_L and no held velocity (the semi-implicit step's response to a pressure force).
/// Where both phases move, its closed form in two divisions instead of solveComponent's eight:
/// the relaxed slip w = v_L - v_S with numerator and denominator times M_S M_L. There, as in
/// solveComponent, the tube's loss plays no part: a gate node's solid is held.
inline PhaseVelocities componentResponse(NodeComponent c, Real dt, Real porosity) {
    c.heldLiquidVelocity = 0;
    const Real mS = c.massS, mL = c.massL;
    if (mS > 0 && mL > 0 && !c.solidHeld && !c.liquidHeld) {
        const Real M = mS + mL;
        const Real w = (porosity * mS - (1 - porosity) * mL) / (mS * mL + dt * c.drag * M);
        return {(1 - mL * w) / M, (1 + mS * w) / M};
    }
    return solveComponent(c, dt, mS > 0 ? (1 - porosity) / mS : 0.0, mL > 0 ? porosity / mL : 0.0);
}

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
/// visit(i, a, component) sees each node component as it is solved: the semi-implicit step takes
/// the components' responses to a pressure force in the same pass.
template <int D, class Visit>
Real solveNodes(const StepContext<D>& ctx, const StepInputs& in, Visit&& visit) {
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
            const NodeComponent component = nodeComponent(ctx, in, i, d);
            const PhaseVelocities v = solveComponent(component, dt, vS1, vL1);
            visit(i, d, component);
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

/// The same, for the explicit step.
template <int D>
Real solveNodes(const StepContext<D>& ctx, const StepInputs& in) {
    return solveNodes(ctx, in, [](Index, int, const NodeComponent&) {});
}

}  // namespace qs
