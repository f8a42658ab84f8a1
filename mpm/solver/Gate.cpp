// The gate plane, where the reservoir's water enters the chamber (physics.md section 2, gate):
// its traction on the chamber's water (phase 3), what the node solve takes of it (the prescribed
// velocity of the flux mode, the tube's implicit loss, the uniform gate; StepInputs for the time
// scheme, NodeVelocities.cpp), and the reservoir advanced with the step's flux (phase 7).
#include "solver/DoublePointSolver.hpp"

namespace qs {

template <int D>
void DoublePointSolver<D>::gateTraction() {
    const Real g = config_.gravity, rhoL = config_.liquid.density;
    // Gate: the reservoir's pressure acts on the chamber's liquid at the gate plane, less the
    // weight of the empty gap below the lowest liquid point (physics.md, gate).
    if (config_.gate.mode == GateMode::Pressure) {
        for (Index i : masks_.gateNodes) {
            const Real p = gateLaw_.staticPressure - rhoL * g * chamber_.gapAtNode(grid_, i);
            nodes_.forceL[i * D + D - 1] += p * nodeFootprint(grid_, i);
        }
    }
}

template <int D>
Real DoublePointSolver<D>::gateVelocityNow() const {
    if (config_.gate.mode != GateMode::Flux) return 0.0;
    // from the initial seepage (at rest by default) to the gate's flux, linearly over the ramp
    const Real v0 = config_.initial.filterVelocity, v = config_.gate.flux, ramp = config_.gate.fluxRampTime;
    return (ramp > 0 && time_ < ramp) ? v0 + (v - v0) * time_ / ramp : v;
}

template <int D>
StepInputs DoublePointSolver<D>::stepInputs() const {
    StepInputs in;
    in.dt = dt_;
    in.damping = damping_;
    in.dampingAlpha = dampingAlpha_;
    in.gate.velocity = gateVelocityNow();
    in.gate.area = gateArea_;
    in.gate.resistance = config_.gate.mode == GateMode::Pressure ? gateLaw_.resistance : 0.0;
    // in 2D and 3D a pressure gate moves its water in at one velocity across the gate plane
    // (NodeVelocities.cpp); in 1D the gate is one node and the two are the same
    in.gate.uniform = D > 1 && config_.gate.mode == GateMode::Pressure;
    return in;
}

/// The step's flux through the gate into the ledger and the reservoir, and the gate's pressure
/// at that flux.
template <int D>
void DoublePointSolver<D>::advanceReservoir() {
    cumulativeInflow_ += gateFlux_ * dt_;
    gatePressure_ = gateLaw_.pressure(gateFlux_);
    reservoir_.advance(time_, dt_, gateFlux_);
}

#define QS_INSTANTIATE(D)                                             \
    template void DoublePointSolver<D>::gateTraction();               \
    template Real DoublePointSolver<D>::gateVelocityNow() const;      \
    template StepInputs DoublePointSolver<D>::stepInputs() const;     \
    template void DoublePointSolver<D>::advanceReservoir();
QS_INSTANTIATE(1)
QS_INSTANTIATE(2)
QS_INSTANTIATE(3)
#undef QS_INSTANTIATE

}  // namespace qs
