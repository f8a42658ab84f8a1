#pragma once
// CouplingInterface: what the MPM solver sees of a windowed model during one window: a
// ReservoirModel whose gate pressure is interpolated in time between the window's start and end
// values, and which integrates the gate flux the MPM reports, for the window's mean flux.
//
// Within a window the model's pressure is only known for the window's mean flux Q_w. With an
// impedance Z (Pa s/m3; the implicit scheme uses the liquid's acoustic impedance rho_L c_L / A)
// the gate law is p(t) = p_interp(t) + Z (Q_w - Q(t)): on average the same pressure once the
// MPM's mean flux equals Q_w, so the coupled solution does not change, but the chamber's free
// water no longer rings (a pure pressure ramp re-excites its acoustic mode, period 4 h / c, every
// window and nothing damps it). The solver treats Z implicitly at the gate node.
#include "coupling/WindowedModel.hpp"
#include "reservoir/ReservoirModel.hpp"

namespace qs {

class CouplingInterface final : public ReservoirModel {
public:
    explicit CouplingInterface(WindowedModel& model) : model_(model) {
        pStart_ = pEnd_ = model.initialGatePressure();
    }

    /// Starts a window [t0, t0+dt] with the gate pressure going from pStart to pEnd for the
    /// window flux `flux`, and the impedance (Pa s/m3, >= 0) about it.
    void beginWindow(double t0, double dt, double pStart, double pEnd, double flux = 0, double impedance = 0) {
        t0_ = t0; dt_ = dt; pStart_ = pStart; pEnd_ = pEnd;
        flux_ = flux; impedance_ = impedance;
        fluxIntegral_ = 0; elapsed_ = 0;
    }
    /// m3/s, mean gate flux over the MPM steps since beginWindow.
    double meanFlux() const { return elapsed_ > 0 ? fluxIntegral_ / elapsed_ : 0.0; }
    double windowEnd() const { return t0_ + dt_; }
    double pressureAtEnd() const { return pEnd_; }

    std::string name() const override { return model_.name(); }
    GateLaw gateLaw(double t) const override {
        double s = dt_ > 0 ? (t - t0_) / dt_ : 1.0;
        s = s < 0 ? 0 : (s > 1 ? 1 : s);
        return {pStart_ + s * (pEnd_ - pStart_) + impedance_ * flux_, impedance_};
    }
    void advance(double /*t*/, double dt, double gateFlux) override {
        fluxIntegral_ += gateFlux * dt;
        elapsed_ += dt;
    }
    double head() const override { return model_.head(); }
    std::vector<double> saveState() const override { return {pEnd_}; }
    void restoreState(const std::vector<double>& s) override {
        if (!s.empty()) pStart_ = pEnd_ = s[0];
    }
    void writeOutput(double t) override { model_.writeOutput(t); }

private:
    WindowedModel& model_;
    double t0_ = 0, dt_ = 0, pStart_ = 0, pEnd_ = 0;
    double flux_ = 0, impedance_ = 0;
    double fluxIntegral_ = 0, elapsed_ = 0;
};

}  // namespace qs
