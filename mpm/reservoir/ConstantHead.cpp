#include "reservoir/ConstantHead.hpp"

#include "core/Error.hpp"

namespace qs {

ConstantHead::ConstantHead(double liquidDensity, double gravity, double head, double headRate)
    : rhoG_(liquidDensity * gravity), head0_(head), headRate_(headRate) {
    // gravity may be 0 (a weightless column, e.g. consolidation): the gate pressure is then 0
    QS_CHECK(liquidDensity > 0.0 && gravity >= 0.0,
             "constant-head reservoir: liquid density must be > 0 and gravity >= 0, got "
                 << liquidDensity << " kg/m3 and " << gravity << " m/s2");
}

ConstantHead::ConstantHead(double liquidDensity, double gravity, const PiecewiseLinear::Points& schedule)
    : ConstantHead(liquidDensity, gravity, schedule.empty() ? 0.0 : schedule.front().second) {
    schedule_ = PiecewiseLinear(schedule);
}

GateLaw ConstantHead::gateLaw(double t) const {
    GateLaw law;
    law.staticPressure = rhoG_ * headAt(t);
    law.resistance = 0.0;
    return law;
}

void ConstantHead::advance(double t, double dt, double /*gateFlux*/) { time_ = t + dt; }

double ConstantHead::head() const { return headAt(time_); }

std::vector<double> ConstantHead::saveState() const { return {time_}; }

void ConstantHead::restoreState(const std::vector<double>& state) {
    QS_CHECK(state.size() == 1, "constant-head reservoir: saved state has " << state.size()
                                                                            << " values, expected 1");
    time_ = state[0];
}

}  // namespace qs
