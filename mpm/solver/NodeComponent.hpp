#pragma once
// One node component's velocity solve with implicit drag (physics.md section 2): the piece of the
// node solve (solver/NodeVelocities.hpp) that boundaries with a law of their own, a rough wall
// (boundary/RoughWalls.hpp), solve with. Per node and axis, with the forces F_S, F_L known,
//   M_S v_S = M_S v_S* + dt Q (v_L - v_S),   (M_L + dt c) v_L = M_L v_L* - dt Q (v_L - v_S),
// v* = v0 + dt F / M the drag-free predictors, Q the node's drag coefficient (kg/s), c the
// gate's tube loss in 1D; a held component keeps its prescribed value.
#include "core/Types.hpp"

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

}  // namespace qs
