// Closed forms against every reference number of physics.md (sections 1 and 4).
//
// Tolerances are relative errors matching the digits physics.md quotes: a number rounded to
// d significant digits is within 5 * 10^-d of the exact value (relative), so 4 digits -> 5e-4.
#include "physics/ClosedForms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace qs::closed {
namespace {

constexpr double kDigits3 = 5e-3;
constexpr double kDigits4 = 5e-4;
constexpr double kDigits5 = 5e-5;

constexpr double kPi = 3.14159265358979323846;

// Default parameter set P0 of physics.md section 4.
struct P0 {
    static constexpr double g = 9.81;
    static constexpr double rhoS = 2650.0;
    static constexpr double rhoL = 998.2;
    static constexpr double n0 = 0.38;
    static constexpr double E = 1e6;
    static constexpr double nu = 0.3;
    static constexpr double KL = 2.128e7;
    static constexpr double mu = 8.91e-4;
    static constexpr double kappa = 1.49e-10;
    static constexpr double H = 0.186;
    static constexpr double D10 = 2.61e-4;
    static constexpr double ergunA = 150.0;
    static constexpr double ergunB = 1.75;
};

double gammaW() { return P0::rhoL * P0::g; }
double conductivityP0() {
    return hydraulicConductivity(P0::kappa, P0::rhoL, P0::g, P0::mu);
}

#define EXPECT_REL(actual, reference, rel)                                       \
    EXPECT_NEAR((actual) / (reference), 1.0, (rel))                              \
        << "actual " << (actual) << " reference " << (reference)

// ---- section 1: the paper's data -------------------------------------------------------------

TEST(ClosedForms, SpecificGravityAndCylinderArea) {
    EXPECT_REL(P0::rhoS / P0::rhoL, 2.6548, kDigits5);
    EXPECT_REL(kPi * 0.0798 * 0.0798 / 4.0, 5.0014e-3, kDigits5);
}

TEST(ClosedForms, CriticalGradient) {
    EXPECT_REL(criticalGradient(P0::rhoS, P0::rhoL, P0::n0), 1.026, kDigits4);
    // Simulation B's bed at n = 0.452 carries only 0.907: B is a rigid-skeleton seepage case.
    EXPECT_REL(criticalGradient(P0::rhoS, P0::rhoL, 0.452), 0.907, kDigits3);
}

TEST(ClosedForms, HydraulicConductivity) {
    EXPECT_REL(conductivityP0(), 1.6376e-3, kDigits5);
    // physics.md Table 1 quotes 1.638e-3 m/s with the paper's g = 9.806; the formula gives
    // 1.63688e-3, i.e. 1.637e-3. 1.638e-3 is the P0 (g = 9.81) value 1.63755e-3 rounded.
    EXPECT_REL(hydraulicConductivity(P0::kappa, P0::rhoL, 9.806, P0::mu), 1.637e-3, kDigits4);
}

TEST(ClosedForms, KozenyCarmanFromD10IsNotThePapersKappa) {
    EXPECT_REL(kozenyCarman(P0::D10, P0::n0, P0::ergunA), 6.48e-11, kDigits3);
}

TEST(ClosedForms, KozenyCarmanScaledKeepsKappa0AtN0AndFollowsKC) {
    EXPECT_DOUBLE_EQ(kozenyCarmanScaled(P0::kappa, P0::n0, P0::n0), P0::kappa);
    const double ratioKC = kozenyCarman(P0::D10, 0.452, 150.0) / kozenyCarman(P0::D10, 0.38, 150.0);
    EXPECT_REL(kozenyCarmanScaled(P0::kappa, P0::n0, 0.452) / P0::kappa, ratioKC, 1e-12);
}

TEST(ClosedForms, KozenyCarmanCapsPorosityAt095) {
    const double atCap = kozenyCarman(P0::D10, 0.95, 150.0);
    EXPECT_DOUBLE_EQ(kozenyCarman(P0::D10, 0.99, 150.0), atCap);
    EXPECT_DOUBLE_EQ(kozenyCarman(P0::D10, 1.0, 150.0), atCap);
    EXPECT_TRUE(std::isfinite(kozenyCarmanScaled(P0::kappa, P0::n0, 1.0)));
}

TEST(ClosedForms, ErgunFactor) {
    EXPECT_REL(ergunFactor(P0::n0, P0::ergunA, P0::ergunB), 0.6100, kDigits4);
}

TEST(ClosedForms, OedometricModulus) {
    EXPECT_REL(oedometricModulus(P0::E, P0::nu), 1.3462e6, kDigits5);
}

// ---- section 4, problem 1: geostatic column ----------------------------------------------------

TEST(ClosedForms, GeostaticColumnBaseStresses) {
    EXPECT_REL(gammaW() * P0::H, 1821.4, kDigits5);
    const double buoyantUnitWeight = (1.0 - P0::n0) * (P0::rhoS - P0::rhoL) * P0::g;
    EXPECT_REL(buoyantUnitWeight * P0::H, 1868.7, kDigits5);
    // Problem 2: sigma'_v = gamma_w (i_c - i) z is the same column, so it vanishes at i_c.
    EXPECT_REL(gammaW() * criticalGradient(P0::rhoS, P0::rhoL, P0::n0) * P0::H,
               buoyantUnitWeight * P0::H, 1e-12);
}

// ---- problem 3: steady seepage -----------------------------------------------------------------

TEST(ClosedForms, SteadySeepageCaseBWithKozenyCarman) {
    const double n = 0.452;
    const double kappa = kozenyCarman(P0::D10, n, P0::ergunA);
    const double F = ergunFactor(n, P0::ergunA, P0::ergunB);
    EXPECT_REL(darcyForchheimerFlux(1.32, kappa, F, P0::rhoL, P0::g, P0::mu), 2.001e-3, kDigits4);
}

TEST(ClosedForms, SteadySeepageCaseBWithFixedKappa) {
    const double F = ergunFactor(0.452, P0::ergunA, P0::ergunB);
    EXPECT_REL(darcyForchheimerFlux(1.32, P0::kappa, F, P0::rhoL, P0::g, P0::mu), 2.132e-3,
               kDigits4);
}

TEST(ClosedForms, SteadySeepageCoarseGrainsShowForchheimer) {
    const double kappa = kozenyCarman(2e-3, 0.4, P0::ergunA);
    const double F = ergunFactor(0.4, P0::ergunA, P0::ergunB);
    EXPECT_REL(darcyForchheimerFlux(1.0, kappa, F, P0::rhoL, P0::g, P0::mu), 2.496e-2, kDigits4);
    EXPECT_REL(darcyForchheimerFlux(1.0, kappa, 0.0, P0::rhoL, P0::g, P0::mu), 5.21e-2, kDigits3);
}

TEST(ClosedForms, DarcyForchheimerSatisfiesItsLawAndIsOdd) {
    const double F = ergunFactor(0.4, P0::ergunA, P0::ergunB);
    const double kappa = kozenyCarman(2e-3, 0.4, P0::ergunA);
    for (double i : {1e-8, 1e-3, 0.5, 1.0, 10.0}) {
        const double q = darcyForchheimerFlux(i, kappa, F, P0::rhoL, P0::g, P0::mu);
        const double lhs = P0::mu / kappa * q + F * P0::rhoL / std::sqrt(kappa) * q * std::abs(q);
        EXPECT_REL(lhs, i * gammaW(), 1e-12) << "i = " << i;
        EXPECT_DOUBLE_EQ(darcyForchheimerFlux(-i, kappa, F, P0::rhoL, P0::g, P0::mu), -q);
    }
    EXPECT_EQ(darcyForchheimerFlux(0.0, kappa, F, P0::rhoL, P0::g, P0::mu), 0.0);
    // F = 0 is Darcy: q = K i.
    EXPECT_REL(darcyForchheimerFlux(1.0, P0::kappa, 0.0, P0::rhoL, P0::g, P0::mu),
               conductivityP0(), 1e-14);
}

// ---- problem 4: Terzaghi consolidation with compressible water -------------------------------

TEST(ClosedForms, ConsolidationP0) {
    const double Eoed = oedometricModulus(P0::E, P0::nu);
    EXPECT_REL(undrainedPressureRatio(Eoed, P0::n0, P0::KL), 0.9765, kDigits4);
    const double cv = consolidationCoefficient(conductivityP0(), P0::rhoL, P0::g, Eoed, P0::n0,
                                               P0::KL);
    EXPECT_REL(cv, 0.2198, kDigits4);
    // The verification run uses k/10: c_v scales with k.
    EXPECT_REL(consolidationCoefficient(conductivityP0() / 10.0, P0::rhoL, P0::g, Eoed, P0::n0,
                                        P0::KL),
               0.02198, kDigits4);
}

TEST(ClosedForms, TerzaghiSolutionAtT02) {
    EXPECT_REL(terzaghiDegree(0.2), 0.5041, kDigits4);
    EXPECT_REL(terzaghiPressureRatio(0.5, 0.2), 0.553, kDigits3);
}

TEST(ClosedForms, TerzaghiDegreeIsOneMinusMeanPressure) {
    // U = 1 - integral_0^1 u/u0 dZ; Simpson's rule on the series checks the two sums agree.
    const double T = 0.1;
    const int N = 400;
    double integral = 0.0;
    for (int k = 0; k <= N; ++k) {
        const double w = (k == 0 || k == N) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        integral += w * terzaghiPressureRatio(double(k) / N, T);
    }
    integral /= 3.0 * N;
    EXPECT_NEAR(terzaghiDegree(T), 1.0 - integral, 1e-6);
    EXPECT_NEAR(terzaghiPressureRatio(0.0, T), 0.0, 1e-12);  // drained face
}

// ---- problem 5: compression waves ------------------------------------------------------------

TEST(ClosedForms, WaveSpeedsP0) {
    const double Eoed = oedometricModulus(P0::E, P0::nu);
    const WaveSpeeds c = zeroDragWaveSpeeds(Eoed, P0::KL, P0::n0, P0::rhoS, P0::rhoL);
    EXPECT_REL(c.fast, 186.4, kDigits4);
    EXPECT_REL(c.slow, 22.4, kDigits3);
    EXPECT_REL(undrainedWaveSpeed(Eoed, P0::KL, P0::n0, P0::rhoS, P0::rhoL), 168.4, kDigits4);
}

TEST(ClosedForms, WaveSpeedsAreTheEigenvaluesOfMinvK) {
    // det(K - c^2 M) = 0 for both speeds: an independent check of the trace/determinant algebra.
    const double Eoed = oedometricModulus(P0::E, P0::nu);
    const double n = P0::n0;
    const WaveSpeeds c = zeroDragWaveSpeeds(Eoed, P0::KL, n, P0::rhoS, P0::rhoL);
    const double k11 = Eoed + (1 - n) * (1 - n) * P0::KL / n, k12 = (1 - n) * P0::KL,
                 k22 = n * P0::KL, m1 = (1 - n) * P0::rhoS, m2 = n * P0::rhoL;
    for (double speed : {c.fast, c.slow}) {
        const double l = speed * speed;
        const double det = (k11 - l * m1) * (k22 - l * m2) - k12 * k12;
        EXPECT_NEAR(det / (k12 * k12), 0.0, 1e-10) << "speed " << speed;
    }
    EXPECT_GT(c.fast, undrainedWaveSpeed(Eoed, P0::KL, n, P0::rhoS, P0::rhoL));
}

// ---- problem 6: falling head -------------------------------------------------------------------

TEST(ClosedForms, FallingHeadTauP0) {
    const double As = 5.0014e-3;
    EXPECT_REL(fallingHeadTau(As, As, P0::H, conductivityP0(), 0.0), 113.58, kDigits5);
}

TEST(ClosedForms, TubeResistanceAddsToTau) {
    // R_t = 128 mu L /(pi rho g d^4); for d = 4 mm, L = 1 m by hand: 1.4481e4 s/m2.
    const double d = 4e-3, L = 1.0;
    const double Rt = tubeResistance(d, L, P0::rhoL, P0::g, P0::mu);
    EXPECT_REL(Rt, 128.0 * P0::mu * L / (kPi * P0::rhoL * P0::g * std::pow(d, 4)), 1e-14);
    EXPECT_REL(Rt, 1.4481e4, kDigits5);
    const double As = 5.0014e-3, Ar = 1e-2;
    EXPECT_REL(fallingHeadTau(Ar, As, P0::H, conductivityP0(), Rt),
               Ar * (P0::H / (conductivityP0() * As) + Rt), 1e-14);
}

FallingHeadForchheimer fallingHeadP0(double F) {
    FallingHeadForchheimer fh;
    fh.alpha = P0::H / conductivityP0();  // no tube
    fh.beta = P0::H * F / (P0::g * std::sqrt(P0::kappa));
    fh.areaRatio = 1.0;  // A_r = A_s
    return fh;
}

TEST(ClosedForms, FallingHeadForchheimerP0) {
    // P0 column (L = H = 0.186 m, kappa = 1.49e-10, g = 9.81), F = ergunFactor(0.38, 150, 1.75),
    // A_r = A_s, no tube, h0 = 0.15 m.
    const double F = ergunFactor(P0::n0, P0::ergunA, P0::ergunB);
    for (double f : {F, 0.6100}) {  // the rounded F quoted in physics.md gives the same digits
        const FallingHeadForchheimer fh = fallingHeadP0(f);
        const double h0 = 0.15;
        EXPECT_REL(fh.timeToHead(h0, 0.5 * h0), 79.35, kDigits4);
        EXPECT_REL(fh.timeToHead(h0, 0.25 * h0), 158.39, kDigits5);
        EXPECT_REL(fh.timeToHead(h0, 0.1 * h0), 262.66, kDigits5);
    }
}

TEST(ClosedForms, FallingHeadForchheimerMatchesItsOde) {
    // A_r dh/dt = -A_s q(h), integrated with RK4, checks t(q) independently of its derivation.
    FallingHeadForchheimer fh = fallingHeadP0(ergunFactor(P0::n0, P0::ergunA, P0::ergunB));
    fh.areaRatio = 0.5;
    const std::function<double(double)> rate = [&](double h) {
        return -fh.flux(h) / fh.areaRatio;
    };
    const double h0 = 0.15, tEnd = fh.timeToHead(h0, 0.25 * h0);
    const int steps = 20000;
    const double dt = tEnd / steps;
    double h = h0;
    for (int k = 0; k < steps; ++k) {
        const double k1 = rate(h), k2 = rate(h + 0.5 * dt * k1), k3 = rate(h + 0.5 * dt * k2),
                     k4 = rate(h + dt * k3);
        h += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    EXPECT_REL(h, 0.25 * h0, 1e-9);
}

TEST(ClosedForms, FallingHeadForchheimerReducesToDarcy) {
    FallingHeadForchheimer fh = fallingHeadP0(0.0);
    const double tau = fallingHeadTau(1.0, 1.0, P0::H, conductivityP0(), 0.0);
    EXPECT_REL(fh.timeToHead(0.15, 0.15 * std::exp(-1.0)), tau, 1e-12);
    EXPECT_REL(fh.flux(0.15), conductivityP0() * 0.15 / P0::H, 1e-14);
}

// ---- problem 7: bed expansion; problem 9: batch settling (drift-flux / Kynch) -----------------

// Filter velocity of a bed at zero effective stress: the gradient equals i_c at that porosity.
double fluidisedFlux(double n) {
    return darcyForchheimerFlux(criticalGradient(P0::rhoS, P0::rhoL, n),
                                kozenyCarman(P0::D10, n, P0::ergunA),
                                ergunFactor(n, P0::ergunA, P0::ergunB), P0::rhoL, P0::g, P0::mu);
}

TEST(ClosedForms, BedExpansionAfterAFluxStep) {
    const double n1 = P0::n0, n2 = 0.452;
    const double U1 = fluidisedFlux(n1), U2 = fluidisedFlux(n2);
    EXPECT_REL(U1, 7.28e-4, kDigits3);
    EXPECT_REL(U2, 1.380e-3, kDigits4);
    EXPECT_REL((1 - n1) * (U2 - U1) / (n2 - n1), 5.61e-3, kDigits3);  // front (shock) speed
    EXPECT_REL(P0::H * (1 - n1) / (1 - n2), 210.4e-3, kDigits4);     // final height
}

TEST(ClosedForms, BatchSettling) {
    const double n0 = 0.55, np = 0.41, H0 = 0.186;
    // Zero net flux: q = n (v_L - v_S) with n v_L + (1-n) v_S = 0 gives v_S = -q.
    const double topSpeed = fluidisedFlux(n0);
    EXPECT_REL(topSpeed, 2.986e-3, kDigits4);
    // Sediment front: shock between the suspension (solid flux (1-n0) v_S) and the rest bed.
    const double frontSpeed = (1 - n0) * topSpeed / (n0 - np);
    EXPECT_REL(frontSpeed, 9.60e-3, kDigits3);
    const double Hfinal = H0 * (1 - n0) / (1 - np);
    EXPECT_REL(Hfinal, 141.9e-3, kDigits4);
    EXPECT_REL(H0 / (topSpeed + frontSpeed), 14.8, kDigits3);  // they meet
    EXPECT_REL((H0 - Hfinal) / topSpeed, 14.8, kDigits3);      // ... at the final height
}

// ---- problem 8: two layers in series -----------------------------------------------------------

TEST(ClosedForms, SeriesFlux) {
    const double K = conductivityP0();
    // Equal layers are one layer of the summed length.
    EXPECT_REL(seriesFlux(0.1, 0.1, K, 0.086, K), K * 0.1 / 0.186, 1e-14);
    // A filter 50x more permeable adds L2/(50 L1) to the resistance.
    EXPECT_REL(seriesFlux(0.1, 0.186, K, 0.05, 50 * K), K * 0.1 / (0.186 + 0.001), 1e-14);
}

}  // namespace
}  // namespace qs::closed
