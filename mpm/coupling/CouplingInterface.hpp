#pragma once
// CouplingInterface: what the MPM solver sees of a windowed model during one window: a
// ReservoirModel whose gate pressure is interpolated in time between the window's start and end
// values, and which integrates the gate flux the MPM reports, for the window's mean flux.
#include "coupling/WindowedModel.hpp"
#include "reservoir/ReservoirModel.hpp"

namespace qs {

class CouplingInterface final : public ReservoirModel {
public:
    explicit CouplingInterface(WindowedModel& model) : model_(model) {
        pStart_ = pEnd_ = model.initialGatePressure();
    }

    /// Starts a window [t0, t0+dt] with the gate pressure going from pStart to pEnd.
    void beginWindow(double t0, double dt, double pStart, double pEnd) {
        t0_ = t0; dt_ = dt; pStart_ = pStart; pEnd_ = pEnd;
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
        return {pStart_ + s * (pEnd_ - pStart_), 0.0};
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
    double fluxIntegral_ = 0, elapsed_ = 0;
};

}  // namespace qs
