#include "physics/DriftFlux.hpp"

#include <cmath>

#include "physics/ClosedForms.hpp"

namespace qs::closed {

double SuspensionFlux::equilibriumFlux(double n) const {
    const double i = criticalGradient(grainDensity, liquidDensity, n);
    return darcyForchheimerFlux(i, law.kappa(n), law.ergunFactor(n), liquidDensity, gravity, viscosity);
}

double SuspensionFlux::equilibriumPorosity(double q) const {
    double lo = 1e-3, hi = 0.95;  // q(n) increases with n: bisection
    for (int k = 0; k < 200; ++k) {
        const double n = 0.5 * (lo + hi);
        (equilibriumFlux(n) < q ? lo : hi) = n;
    }
    return 0.5 * (lo + hi);
}

BedExpansion bedExpansion(const SuspensionFlux& flux, double n1, double U1, double U2, double H1) {
    BedExpansion e;
    e.expandedPorosity = flux.equilibriumPorosity(U2);
    e.frontSpeed = (1 - n1) * (U2 - U1) / (e.expandedPorosity - n1);
    e.plugSpeed = U2 - U1;
    e.finalHeight = H1 * (1 - n1) / (1 - e.expandedPorosity);
    e.duration = H1 / (e.frontSpeed - e.plugSpeed);
    return e;
}

BatchSettling batchSettling(const SuspensionFlux& flux, double n0, double np, double H0) {
    BatchSettling b;
    b.topSpeed = flux.equilibriumFlux(n0);
    b.frontSpeed = (1 - n0) * b.topSpeed / (n0 - np);
    b.meetingTime = H0 / (b.topSpeed + b.frontSpeed);
    b.finalHeight = H0 * (1 - n0) / (1 - np);
    return b;
}

}  // namespace qs::closed
