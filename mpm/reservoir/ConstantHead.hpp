#pragma once
// ConstantHead: a reservoir so large that the gate flux does not move its level. The level may
// follow a prescribed linear ramp (head + headRate t), which is how the critical-gradient test
// raises i slowly (physics.md section 4, problem 2), or a schedule of (time, head), linear
// between its rows: stepwise increases of the head, the lab's way to find i_c.
#include "core/PiecewiseLinear.hpp"
#include "reservoir/ReservoirModel.hpp"

namespace qs {

class ConstantHead final : public ReservoirModel {
public:
    /// head: m, reservoir surface elevation above the gate plane at t = 0; headRate: m/s.
    ConstantHead(double liquidDensity, double gravity, double head, double headRate = 0.0);
    /// schedule: (t s, head m) rows, t strictly increasing; the head before the first row is the
    /// first row's, after the last the last's
    ConstantHead(double liquidDensity, double gravity, const PiecewiseLinear::Points& schedule);

    std::string name() const override { return "constant_head"; }
    /// p_static = rho_L g (head + headRate t); no resistance (the level ignores the flux).
    GateLaw gateLaw(double t) const override;
    void advance(double t, double dt, double gateFlux) override;
    /// The level at the end of the last advanced step (t = 0 before any).
    double head() const override;
    std::vector<double> saveState() const override;
    void restoreState(const std::vector<double>& state) override;

private:
    double headAt(double t) const { return schedule_.empty() ? head0_ + headRate_ * t : schedule_(t); }

    double rhoG_;      ///< Pa/m, rho_L g
    double head0_;     ///< m
    double headRate_;  ///< m/s
    PiecewiseLinear schedule_;  ///< m by s; replaces the ramp when given
    double time_ = 0.0;  ///< s, end of the last advanced step: the only state
};

}  // namespace qs
