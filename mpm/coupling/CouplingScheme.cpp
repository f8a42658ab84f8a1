#include "coupling/CouplingScheme.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <ostream>

#include "core/Error.hpp"

namespace qs {

namespace {
using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
}  // namespace

void CouplingScheme::restoreState(const std::vector<double>& s) {
    if (s.size() < 3) return;
    lastFlux_ = s[0];
    lastPressure_ = s[1];
    previousFlux_ = s[2];
    aitken_ = s.size() > 3 ? s[3] : 0;  // checkpoints before the factor was kept restart from none
    started_ = true;
}

void CouplingScheme::advanceWindow(MpmSide& mpm, double end) {
    if (!started_) {
        lastPressure_ = model_.initialGatePressure();
        started_ = true;
    }
    const double t0 = mpm.time();
    // a whole number of MPM steps per window, the last window cut to end at `end` only where a
    // whole window would overshoot it: a run that ends (and checkpoints) on a window boundary then
    // solves exactly the windows of a longer run, and its resume repeats that run bit for bit
    const double steps = std::max(1.0, std::round(config_.window / mpm.dt()));
    double dt = steps * mpm.dt();
    if (t0 + dt > end + 0.5 * mpm.dt()) dt = std::max(mpm.dt(), end - t0);
    solveWindow(mpm, t0, dt);
    ++stats_.windows;
}

double CouplingScheme::solveModel(double t0, double dt, double flux) {
    const auto start = Clock::now();
    const double p = model_.solveWindow(t0, dt, flux);
    stats_.modelSeconds += seconds(start);
    ++stats_.modelSolves;
    QS_CHECK(std::isfinite(p), "the reservoir model " << model_.name() << " returned a non-finite gate pressure at t = "
                                                      << t0 + dt << " s");
    return p;
}

double CouplingScheme::runMpm(MpmSide& mpm, double t0, double dt, double pStart, double pEnd,
                              double flux, double impedance) {
    const auto start = Clock::now();
    gate_.beginWindow(t0, dt, pStart, pEnd, flux, impedance);
    const double tEnd = t0 + dt - 0.5 * mpm.dt();
    while (mpm.time() < tEnd) mpm.step();
    stats_.mpmSeconds += seconds(start);
    return gate_.meanFlux();
}

void ExplicitCoupling::solveWindow(MpmSide& mpm, double t0, double dt) {
    // staggered: the model leads with the last window's flux, the MPM follows
    const double pEnd = solveModel(t0, dt, lastFlux_);
    model_.acceptWindow();
    const double flux = runMpm(mpm, t0, dt, lastPressure_, pEnd);
    stats_.lastResidual = std::abs(flux - lastFlux_) / std::max(std::abs(flux), 1e-300);
    previousFlux_ = lastFlux_;
    lastFlux_ = flux;
    lastPressure_ = pEnd;
}

void ImplicitCoupling::solveWindow(MpmSide& mpm, double t0, double dt) {
    CheckpointData start;
    mpm.save(start);
    // predictor: linear extrapolation of the accepted window fluxes
    double flux = 2 * lastFlux_ - previousFlux_;
    // the first relaxation of a window: the last window's converged Aitken factor (the coupled
    // problem changes slowly), else the configured one
    double omega = aitken_ > 0 ? aitken_ : config_.relaxation;
    double rPrev = 0, pEnd = lastPressure_, mpmFlux = flux;
    double solvedFlux = flux;  // the flux of the last model solve: the pair accepted at the end
    bool converged = false;
    int k = 0;
    for (; k < config_.maxIterations; ++k) {
        solvedFlux = flux;
        pEnd = solveModel(t0, dt, flux);
        if (k > 0) mpm.load(start);
        // the window's end pressure over the whole window (backward Euler): a ramp from the last
        // window's pressure makes the coupled pair trapezoidal, and the tube's stiff inertia then
        // leaves an undamped odd-even oscillation of the window fluxes
        mpmFlux = runMpm(mpm, t0, dt, pEnd, pEnd, flux, impedance_);
        const double r = mpmFlux - flux;
        const double scale = std::max({std::abs(mpmFlux), std::abs(flux), 1e-300});
        stats_.lastResidual = std::abs(r) / scale;
        if (log_)
            *log_ << std::setprecision(9) << "window t = " << t0 << " iteration " << k + 1
                  << " flux " << flux << " gate pressure " << pEnd << " mpm flux " << mpmFlux << " residual "
                  << stats_.lastResidual << " omega " << omega << " impedance " << impedance_ << "\n";
        if (stats_.lastResidual <= config_.tolerance) { converged = true; break; }
        if (k > 0 && r != rPrev) omega = -omega * rPrev / (r - rPrev);  // Aitken (scalar form)
        if (omega > 0 && omega <= 1) aitken_ = omega;
        flux += omega * r;
        rPrev = r;
    }
    stats_.iterations += std::min(k + 1, config_.maxIterations);
    if (!converged) {
        ++stats_.unconverged;
        if (log_)
            *log_ << "window t = " << t0 << ": not converged after " << config_.maxIterations
                  << " iterations (residual " << stats_.lastResidual << "), accepted\n";
    }
    model_.acceptWindow();
    previousFlux_ = lastFlux_;
    lastFlux_ = solvedFlux;
    lastPressure_ = pEnd;
}

std::unique_ptr<CouplingScheme> makeCouplingScheme(const CouplingConfig& config, WindowedModel& model,
                                                   CouplingInterface& gate, std::ostream* log) {
    if (config.scheme == CouplingKind::Explicit)
        return std::make_unique<ExplicitCoupling>(model, gate, config, log);
    return std::make_unique<ImplicitCoupling>(model, gate, config, log);
}

}  // namespace qs
