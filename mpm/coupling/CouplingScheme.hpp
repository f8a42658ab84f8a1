#pragma once
// Coupling schemes between the MPM column and a windowed reservoir model (physics.md section 3;
// the structure follows preCICE's coupling schemes: a base running the shared sequence,
// subclasses filling in the window).
//
// Usage:
//   CouplingInterface gate(model);               // the MPM solver's ReservoirModel
//   DoublePointSolver<1> solver(config, gate);
//   MpmAdapter<1> mpm(solver);
//   auto scheme = makeCouplingScheme(config.coupling, model, gate, log);
//   while (solver.time() < end) scheme->advanceWindow(mpm);
//
// Explicit (staggered, subcycled): the model solves the window first with the MPM's mean flux
// of the previous window; the MPM then runs its steps with the gate pressure interpolated from
// the last window's end value to the new one. Cheap, one model solve per window, but the gate
// pressure answers flux acceleration at once (the added mass of the tube's water): it is unstable
// whenever the tube's water is heavier than the column's free water that answers first,
// (L_t/A_t)/(h_chamber/A_s) > 1, whatever the window.
// Implicit (per window, Aitken): the MPM runs the window with the model's end-of-window pressure
// (backward Euler; a linear ramp would make the pair trapezoidal and leave the tube's stiff
// inertia an undamped odd-even mode); the window is repeated, the MPM rolled back each time, until
// the MPM's mean flux equals the flux the model was solved with (relative tolerance), the flux
// updated by Aitken's dynamic relaxation
//   omega_k = -omega_{k-1} r_{k-1} (r_k - r_{k-1}) / |r_k - r_{k-1}|^2,  Q_{k+1} = Q_k + omega_k r_k.
// The implicit scheme also gives the MPM the gate's acoustic impedance rho_L c_L / A about the
// window's flux (see CouplingInterface): the converged solution is the same, but the chamber's
// free water does not ring from window to window. (The model's own dp/dQ would be far stiffer and
// would pin the flux, so the flux residual could no longer see the pressure.) The explicit
// scheme is the plain staggered one.
// Each window starts from the last window's Aitken factor (the coupled problem changes slowly;
// with a heavy tube the factor is ~1e-3 and restarting from 0.5 costs several iterations).
// Stable where explicit fails; costs the iterations' model solves and MPM steps.
#include <iosfwd>
#include <memory>

#include "coupling/CouplingInterface.hpp"
#include "case/CaseConfig.hpp"
#include "io/Checkpoint.hpp"

namespace qs {

/// What a coupling scheme needs of the MPM solver.
class MpmSide {
public:
    virtual ~MpmSide() = default;
    virtual void step() = 0;
    virtual double time() const = 0;
    virtual double dt() const = 0;
    virtual void save(CheckpointData& data) const = 0;
    virtual void load(const CheckpointData& data) = 0;
};

template <class Solver>
class MpmAdapter final : public MpmSide {
public:
    explicit MpmAdapter(Solver& s) : s_(s) {}
    void step() override { s_.step(); }
    double time() const override { return s_.time(); }
    double dt() const override { return s_.dt(); }
    // a window's start, not a checkpoint: over MPI ranks each rank keeps its own (no gather)
    void save(CheckpointData& d) const override { s_.saveWindowStart(d); }
    void load(const CheckpointData& d) override { s_.loadWindowStart(d); }

private:
    Solver& s_;
};

/// Statistics of the run so far.
struct CouplingStats {
    long windows = 0;
    long modelSolves = 0;
    long iterations = 0;          ///< implicit: sum over windows
    long unconverged = 0;         ///< implicit: windows that hit the iteration cap
    double lastResidual = 0;      ///< relative flux residual of the last window
    double modelSeconds = 0;      ///< wall time spent in the model
    double mpmSeconds = 0;        ///< wall time spent in MPM steps
};

class CouplingScheme {
public:
    CouplingScheme(WindowedModel& model, CouplingInterface& gate, const CouplingConfig& config,
                   std::ostream* log)
        : model_(model), gate_(gate), config_(config), log_(log) {}
    virtual ~CouplingScheme() = default;

    /// Advances MPM and model by one window (the last one may be shorter to end at `end`).
    void advanceWindow(MpmSide& mpm, double end);
    const CouplingStats& stats() const { return stats_; }
    /// Pa s/m3, the damping impedance the implicit scheme applies about each window's flux.
    void setGateImpedance(double z) { impedance_ = z; }
    double lastFlux() const { return lastFlux_; }
    /// For checkpoints: the scheme's whole state (last fluxes and pressure, the Aitken factor the
    /// next window starts from), so that a resumed run repeats the straight run bit for bit.
    std::vector<double> saveState() const { return {lastFlux_, lastPressure_, previousFlux_, aitken_}; }
    void restoreState(const std::vector<double>& s);

protected:
    virtual void solveWindow(MpmSide& mpm, double t0, double dt) = 0;
    /// Runs the MPM from its current state to t0 + dt with the gate pressure from pStart to pEnd;
    /// returns the MPM's mean gate flux.
    double runMpm(MpmSide& mpm, double t0, double dt, double pStart, double pEnd, double flux = 0,
                  double impedance = 0);
    double solveModel(double t0, double dt, double flux);

    WindowedModel& model_;
    CouplingInterface& gate_;
    const CouplingConfig config_;  ///< a copy: the run fits the window (solver/TimeLattice.hpp)
    std::ostream* log_;
    CouplingStats stats_;
    double lastFlux_ = 0;       ///< m3/s, accepted mean flux of the last window
    double previousFlux_ = 0;   ///< m3/s, the one before (for the implicit predictor)
    double lastPressure_ = 0;   ///< Pa, gate pressure at the end of the last window
    double aitken_ = 0;         ///< implicit: the last Aitken factor in (0, 1] (0: none yet)
    double impedance_ = 0;      ///< implicit: the gate's damping impedance (Pa s/m3)
    bool started_ = false;
};

class ExplicitCoupling final : public CouplingScheme {
public:
    using CouplingScheme::CouplingScheme;

private:
    void solveWindow(MpmSide& mpm, double t0, double dt) override;
};

class ImplicitCoupling final : public CouplingScheme {
public:
    using CouplingScheme::CouplingScheme;

private:
    void solveWindow(MpmSide& mpm, double t0, double dt) override;
};

std::unique_ptr<CouplingScheme> makeCouplingScheme(const CouplingConfig& config, WindowedModel& model,
                                                   CouplingInterface& gate, std::ostream* log);

}  // namespace qs
