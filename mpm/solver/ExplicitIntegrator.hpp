#pragma once
// The explicit scheme (time.scheme = "explicit", the default): each node's velocities with
// implicit drag (NodeVelocities.hpp), nothing coupling the nodes within the step. The pore
// pressure then follows from the velocities' divergence (updatePressure), so the water's
// compression wave bounds the step: dt = courant h / c_fast (solver/RunSize.hpp).
#include "solver/NodeVelocities.hpp"

namespace qs {

template <int D>
class ExplicitIntegrator final : public TimeIntegrator<D> {
public:
    explicit ExplicitIntegrator(const StepContext<D>& context) : ctx_(context) {}
    TimeScheme scheme() const override { return TimeScheme::Explicit; }
    Real solveVelocities(const StepInputs& in, Real) override { return solveNodes(ctx_, in); }

private:
    StepContext<D> ctx_;
};

}  // namespace qs
