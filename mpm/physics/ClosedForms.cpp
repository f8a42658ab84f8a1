#include "physics/ClosedForms.hpp"

#include "core/Constants.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cmath>

namespace qs::closed {

namespace {


// Kozeny-Carman blows up as n -> 1; physics.md caps n at 0.95 inside the formula so a fully
// fluidised point keeps a finite (large) permeability instead of an infinite one.
constexpr double kMaxKozenyCarmanPorosity = 0.95;

double kozenyCarmanPorosityFactor(double porosity) {
    const double n = std::min(porosity, kMaxKozenyCarmanPorosity);
    return n * n * n / ((1.0 - n) * (1.0 - n));
}

/// Positive root of b q^2 + a q = r (r >= 0, a > 0, b >= 0), written as 2r / (a + sqrt(a^2 + 4br))
/// rather than (-a + sqrt(...)) / 2b: the textbook form cancels catastrophically when the
/// quadratic term is small (fine sands, small fluxes) and is 0/0 for b = 0 (pure Darcy).
double positiveQuadraticRoot(double a, double b, double r) {
    return 2.0 * r / (a + std::sqrt(a * a + 4.0 * b * r));
}

}  // namespace

double criticalGradient(double grainDensity, double liquidDensity, double porosity) {
    QS_CHECK(liquidDensity > 0.0, "criticalGradient: liquid density must be > 0");
    return (grainDensity / liquidDensity - 1.0) * (1.0 - porosity);
}

double hydraulicConductivity(double permeability, double liquidDensity, double gravity,
                             double viscosity) {
    QS_CHECK(viscosity > 0.0, "hydraulicConductivity: viscosity must be > 0");
    return permeability * liquidDensity * gravity / viscosity;
}

double kozenyCarman(double grainSize, double porosity, double A) {
    QS_CHECK(A > 0.0, "kozenyCarman: constant A must be > 0");
    return grainSize * grainSize * kozenyCarmanPorosityFactor(porosity) / A;
}

double kozenyCarmanScaled(double kappa0, double n0, double porosity) {
    return kappa0 * kozenyCarmanPorosityFactor(porosity) / kozenyCarmanPorosityFactor(n0);
}

double ergunFactor(double porosity, double A, double B) {
    QS_CHECK(A > 0.0 && porosity > 0.0, "ergunFactor: A and porosity must be > 0");
    return B / (std::sqrt(A) * std::pow(porosity, 1.5));
}

double darcyForchheimerFlux(double gradient, double permeability, double ergunF,
                            double liquidDensity, double gravity, double viscosity) {
    QS_CHECK(permeability > 0.0, "darcyForchheimerFlux: permeability must be > 0");
    const double a = viscosity / permeability;                          // Pa s/m2
    const double b = ergunF * liquidDensity / std::sqrt(permeability);  // Pa s2/m3
    const double drive = gradient * liquidDensity * gravity;            // Pa/m
    // q|q| makes the law odd in q: solve for |q| and give it the sign of the gradient.
    const double q = positiveQuadraticRoot(a, b, std::abs(drive));
    return std::copysign(q, drive);
}

double tubeResistance(double diameter, double length, double liquidDensity, double gravity,
                      double viscosity) {
    QS_CHECK(diameter > 0.0, "tubeResistance: diameter must be > 0");
    const double d2 = diameter * diameter;
    return 128.0 * viscosity * length / (kPi * liquidDensity * gravity * d2 * d2);
}

double oedometricModulus(double youngsModulus, double poissonRatio) {
    const double nu = poissonRatio;
    return youngsModulus * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

WaveSpeeds zeroDragWaveSpeeds(double Eoed, double bulkModulusLiquid, double porosity,
                              double grainDensity, double liquidDensity) {
    const double n = porosity;
    const double KL = bulkModulusLiquid;
    const double k11 = Eoed + (1.0 - n) * (1.0 - n) * KL / n;
    const double k22 = n * KL;
    const double m1 = (1.0 - n) * grainDensity;
    const double m2 = n * liquidDensity;
    // Eigenvalues of M^-1 K from its trace and determinant. det K = k11 k22 - k12^2 reduces to
    // E_oed n K_L exactly; it is written that way because the two K_L^2 terms would cancel.
    // For the same reason the small eigenvalue is det/large: det is far below trace^2
    // (K_L >> E_oed), and trace - sqrt(...) would lose most of the slow wave's digits.
    const double trace = k11 / m1 + k22 / m2;
    const double det = Eoed * k22 / (m1 * m2);
    const double large = 0.5 * (trace + std::sqrt(std::max(0.0, trace * trace - 4.0 * det)));
    const double small = det / large;
    return {std::sqrt(large), std::sqrt(small)};
}

double undrainedWaveSpeed(double Eoed, double bulkModulusLiquid, double porosity,
                          double grainDensity, double liquidDensity) {
    const double rhoSat = (1.0 - porosity) * grainDensity + porosity * liquidDensity;
    return std::sqrt((Eoed + bulkModulusLiquid / porosity) / rhoSat);
}

double consolidationCoefficient(double conductivity, double liquidDensity, double gravity,
                                double Eoed, double porosity, double bulkModulusLiquid) {
    const double mv = 1.0 / Eoed;
    return conductivity / (liquidDensity * gravity * (mv + porosity / bulkModulusLiquid));
}

double undrainedPressureRatio(double Eoed, double porosity, double bulkModulusLiquid) {
    const double mv = 1.0 / Eoed;
    return mv / (mv + porosity / bulkModulusLiquid);
}

double terzaghiPressureRatio(double Z, double T, int terms) {
    double sum = 0.0;
    for (int m = 0; m < terms; ++m) {
        const double M = (2 * m + 1) * kPi / 2.0;
        sum += 2.0 / M * std::sin(M * Z) * std::exp(-M * M * T);
    }
    return sum;
}

double terzaghiDegree(double T, int terms) {
    double sum = 0.0;
    for (int m = 0; m < terms; ++m) {
        const double M = (2 * m + 1) * kPi / 2.0;
        sum += 2.0 / (M * M) * std::exp(-M * M * T);
    }
    return 1.0 - sum;
}

double fallingHeadTau(double reservoirArea, double columnArea, double length, double conductivity,
                      double tubeResistance) {
    QS_CHECK(columnArea > 0.0 && conductivity > 0.0,
             "fallingHeadTau: column area and conductivity must be > 0");
    return reservoirArea * (length / (conductivity * columnArea) + tubeResistance);
}

double FallingHeadForchheimer::flux(double head) const {
    QS_CHECK(alpha > 0.0, "FallingHeadForchheimer: alpha must be > 0");
    const double q = positiveQuadraticRoot(alpha, beta, std::abs(head));
    return std::copysign(q, head);
}

double FallingHeadForchheimer::timeToFlux(double q0, double q) const {
    QS_CHECK(q0 > 0.0 && q > 0.0, "FallingHeadForchheimer: fluxes must be > 0 (upward seepage)");
    return areaRatio * (alpha * std::log(q0 / q) + 2.0 * beta * (q0 - q));
}

double seriesFlux(double headDifference, double L1, double K1, double L2, double K2) {
    QS_CHECK(K1 > 0.0 && K2 > 0.0, "seriesFlux: conductivities must be > 0");
    return headDifference / (L1 / K1 + L2 / K2);
}

}  // namespace qs::closed
