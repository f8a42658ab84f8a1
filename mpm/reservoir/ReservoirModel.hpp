#pragma once
// ReservoirModel: what feeds the permeable gate at the base of the column.
//
// Usage, once per MPM step (or coupling window) starting at time t:
//   1. law = model.gateLaw(t): the gate pressure as an affine law of the gate flux,
//      p_gate = law.staticPressure - law.resistance * Q. The solver treats the resistance
//      implicitly in the gate node update (lagged, a tube loss is unstable unless
//      dt < 2 m_node / (rho_L g R_t A_s^2); physics.md section 3).
//   2. the solver advances and measures the gate flux Q (m3/s, positive into the column).
//   3. model.advance(t, dt, Q): the model moves its own state (reservoir level, CFD fields).
// saveState/restoreState let a coupling scheme repeat a window and a checkpoint resume a run.
//
// Pressures are gauge pressures in Pa at the gate plane (the chamber bottom, z = 0).
#include <memory>
#include <string>
#include <vector>

namespace qs {

struct CaseConfig;

struct GateLaw {
    double staticPressure = 0.0;  ///< Pa, gate pressure at zero flux
    double resistance = 0.0;      ///< Pa s/m3, -dp_gate/dQ (>= 0)
    double pressure(double flux) const { return staticPressure - resistance * flux; }
};

class ReservoirModel {
public:
    virtual ~ReservoirModel() = default;
    virtual std::string name() const = 0;
    /// The gate law for the step starting at time t (s).
    virtual GateLaw gateLaw(double t) const = 0;
    /// Advance the model over [t, t+dt] given the gate flux Q (m3/s into the column).
    virtual void advance(double t, double dt, double gateFlux) = 0;
    /// m, elevation of the reservoir surface above the gate plane.
    virtual double head() const = 0;
    virtual std::vector<double> saveState() const = 0;
    virtual void restoreState(const std::vector<double>& state) = 0;
    /// Called at each output time; models with fields of their own write them here.
    virtual void writeOutput(double /*t*/) {}
};

/// Builds the built-in model named in [reservoir] (constant head, lumped). The OpenFOAM model is
/// a WindowedModel (coupling/WindowedModel.hpp); asking for it here throws qs::Error.
std::unique_ptr<ReservoirModel> makeReservoirModel(const CaseConfig& config);

}  // namespace qs
