// LumpedReservoir: gate law (tube and minor losses), exponential drainage through a linear
// resistance, state round-trip, Reynolds warning, construction by the factory.
#include "reservoir/LumpedReservoir.hpp"

#include "core/Error.hpp"
#include "case/CaseConfig.hpp"
#include "physics/ClosedForms.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace qs {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRho = 998.2;
constexpr double kG = 9.81;
constexpr double kMu = 8.91e-4;
constexpr double kColumnArea = 5.0014e-3;  // m2, the paper's cylinder

LumpedReservoirParameters tubeReservoir() {
    LumpedReservoirParameters p;
    p.liquidDensity = kRho;
    p.gravity = kG;
    p.viscosity = kMu;
    p.area = 2e-3;
    p.initialHead = 0.5;
    p.tubeDiameter = 8e-3;
    p.tubeLength = 2.0;
    return p;
}

TEST(LumpedReservoir, GateLawHasHydrostaticHeadAndHagenPoiseuilleResistance) {
    const LumpedReservoir reservoir(tubeReservoir());
    const double Rt = 128.0 * kMu * 2.0 / (kPi * kRho * kG * std::pow(8e-3, 4));
    EXPECT_NEAR(reservoir.tubeResistance() / Rt, 1.0, 1e-14);
    EXPECT_NEAR(Rt, 1.8102e3, 0.5);  // s/m2, by hand
    const GateLaw law = reservoir.gateLaw(0.0);
    EXPECT_DOUBLE_EQ(law.staticPressure, kRho * kG * 0.5);
    EXPECT_NEAR(law.resistance / (kRho * kG * Rt), 1.0, 1e-14);  // Pa s/m3
    EXPECT_EQ(reservoir.name(), "lumped");
}

TEST(LumpedReservoir, NoTubeMeansNoResistance) {
    LumpedReservoirParameters p = tubeReservoir();
    p.tubeDiameter = 0.0;
    LumpedReservoir reservoir(p);
    reservoir.advance(0.0, 1.0, 1e-5);
    EXPECT_EQ(reservoir.gateLaw(1.0).resistance, 0.0);
    EXPECT_EQ(reservoir.tubeReynolds(), 0.0);
    p.minorLoss = 0.5;  // a minor loss needs the tube area
    EXPECT_THROW(LumpedReservoir{p}, Error);
}

TEST(LumpedReservoir, MinorLossIsLinearisedAboutTheLastFlux) {
    LumpedReservoirParameters p = tubeReservoir();
    p.minorLoss = 1.5;
    LumpedReservoir reservoir(p);
    const double base = reservoir.gateLaw(0.0).resistance;  // no flux yet: tube loss only
    EXPECT_NEAR(base / (kRho * kG * reservoir.tubeResistance()), 1.0, 1e-14);
    const double Q = -2e-5;  // the slope uses |Q|
    reservoir.advance(0.0, 1e-3, Q);
    const double At = kPi * 8e-3 * 8e-3 / 4.0;
    EXPECT_NEAR(reservoir.gateLaw(1e-3).resistance - base,
                1.5 * kRho * std::abs(Q) / (2.0 * At * At), 1e-9 * base);
    // At Q_last the linearised law gives exactly the quadratic loss K rho/2 (Q/A_t)^2.
    const double lossMinor = (reservoir.gateLaw(1e-3).resistance - base) * std::abs(Q);
    EXPECT_NEAR(lossMinor / (0.5 * 1.5 * kRho * (Q / At) * (Q / At)), 1.0, 1e-12);
}

TEST(LumpedReservoir, AdvanceMovesTheLevelByTheStepVolume) {
    LumpedReservoir reservoir(tubeReservoir());
    reservoir.advance(0.0, 0.1, 4e-6);
    EXPECT_NEAR(reservoir.head(), 0.5 - 4e-6 * 0.1 / 2e-3, 1e-15);
    EXPECT_DOUBLE_EQ(reservoir.gateLaw(0.1).staticPressure, kRho * kG * reservoir.head());
}

TEST(LumpedReservoir, DrainsExponentiallyThroughALinearResistance) {
    // The reservoir alone, drained through the P0 column seen as a linear resistance plus its
    // own tube: Q = rho g h / R_total, so h = h0 exp(-t/tau) with
    // tau = A_r R_total/(rho g) = A_r (L/(K A_s) + R_t)  (physics.md section 4, problem 6).
    LumpedReservoirParameters p = tubeReservoir();
    p.area = 1e-3;
    LumpedReservoir reservoir(p);
    const double K = closed::hydraulicConductivity(1.49e-10, kRho, kG, kMu);
    const double L = 0.186;
    const double columnResistance = kRho * kG * L / (K * kColumnArea);  // Pa s/m3
    const double tau = closed::fallingHeadTau(p.area, kColumnArea, L, K, reservoir.tubeResistance());
    const double dt = tau / 20000.0;
    const double h0 = reservoir.head();
    double t = 0.0;
    double worst = 0.0;
    for (int step = 0; step < 60000; ++step) {  // three time constants
        const GateLaw law = reservoir.gateLaw(t);
        const double Q = law.staticPressure / (columnResistance + law.resistance);
        reservoir.advance(t, dt, Q);
        t += dt;
        worst = std::max(worst, std::abs(reservoir.head() - h0 * std::exp(-t / tau)) / h0);
    }
    EXPECT_LT(worst, 1e-3);
    EXPECT_NEAR(reservoir.head() / h0, std::exp(-3.0), 1e-3);
}

TEST(LumpedReservoir, SaveRestoreRoundTrip) {
    LumpedReservoirParameters p = tubeReservoir();
    p.minorLoss = 1.0;
    LumpedReservoir reservoir(p);
    reservoir.advance(0.0, 0.5, 3e-6);
    const std::vector<double> saved = reservoir.saveState();
    const GateLaw lawBefore = reservoir.gateLaw(0.5);
    reservoir.advance(0.5, 0.5, 9e-6);  // a window to be repeated
    EXPECT_NE(reservoir.gateLaw(1.0).staticPressure, lawBefore.staticPressure);
    reservoir.restoreState(saved);
    EXPECT_EQ(reservoir.saveState(), saved);
    EXPECT_DOUBLE_EQ(reservoir.gateLaw(0.5).staticPressure, lawBefore.staticPressure);
    EXPECT_DOUBLE_EQ(reservoir.gateLaw(0.5).resistance, lawBefore.resistance);
    EXPECT_THROW(reservoir.restoreState({1.0}), Error);
}

TEST(LumpedReservoir, WarnsOnceWhenTheTubeFlowIsNoLongerLaminar) {
    LumpedReservoir reservoir(tubeReservoir());
    const double d = 8e-3, dt = 1e-3;
    // Q at Re = 1000 and Re = 3000: Q = Re pi mu d / (4 rho).
    const double laminarQ = 1000.0 * kPi * kMu * d / (4.0 * kRho);
    const double turbulentQ = 3.0 * laminarQ;

    testing::internal::CaptureStderr();
    double t = 0;
    for (; t < 5.0; t += dt) reservoir.advance(t, dt, laminarQ);  // ten averaging times
    EXPECT_NEAR(reservoir.tubeReynolds(), 1000.0, 1e-9);
    EXPECT_NEAR(reservoir.meanTubeReynolds(), 1000.0, 1.0);
    // a spike of a few steps (the valve opening onto a compressible chamber) is not a regime
    for (int k = 0; k < 5; ++k, t += dt) reservoir.advance(t, dt, 10 * turbulentQ);
    EXPECT_NEAR(reservoir.tubeReynolds(), 30000.0, 1e-6);
    EXPECT_FALSE(reservoir.reynoldsWarningIssued());
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");

    // a sustained turbulent flow is, backflow included: the mean relaxes from m0 towards 3000
    // and passes 2000 after 0.5 ln((3000 - m0) / 1000) s
    const double m0 = reservoir.meanTubeReynolds();
    const double expectedWarning = LumpedReservoir::kReynoldsAveraging * std::log((3000.0 - m0) / 1000.0);
    testing::internal::CaptureStderr();
    double warnedAt = -1;
    for (int k = 0; k < 5000; ++k, t += dt) {
        reservoir.advance(t, dt, k < 500 ? -turbulentQ : turbulentQ);
        if (warnedAt < 0 && reservoir.reynoldsWarningIssued()) warnedAt = k * dt;
    }
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NEAR(reservoir.meanTubeReynolds(), 3000.0, 1.0);
    EXPECT_TRUE(reservoir.reynoldsWarningIssued());
    EXPECT_NEAR(warnedAt, expectedWarning, 0.005);
    EXPECT_NE(err.find("Reynolds"), std::string::npos) << err;
    EXPECT_NE(err.find("at t = "), std::string::npos) << err;
    EXPECT_EQ(err.find("Reynolds"), err.rfind("Reynolds")) << "warned more than once: " << err;
}

TEST(ReservoirFactory, BuildsLumpedFromTheCase) {
    CaseConfig config;
    config.gravity = 9.81;
    config.liquid.density = kRho;
    config.liquid.viscosity = kMu;
    config.reservoir.kind = ReservoirKind::Lumped;
    config.reservoir.head = 0.3;
    config.reservoir.area = 4e-3;
    config.reservoir.tubeDiameter = 8e-3;
    config.reservoir.tubeLength = 2.0;
    const auto model = makeReservoirModel(config);
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(model->name(), "lumped");
    EXPECT_DOUBLE_EQ(model->head(), 0.3);
    const double Rt = closed::tubeResistance(8e-3, 2.0, kRho, 9.81, kMu);
    EXPECT_NEAR(model->gateLaw(0.0).resistance / (kRho * 9.81 * Rt), 1.0, 1e-14);
    model->advance(0.0, 2.0, 1e-5);
    EXPECT_NEAR(model->head(), 0.3 - 1e-5 * 2.0 / 4e-3, 1e-15);

    config.reservoir.area = 0.0;  // a lumped reservoir needs an area
    EXPECT_THROW(makeReservoirModel(config), Error);
}

}  // namespace
}  // namespace qs
