// Verification problem 6 (physics.md section 4): falling head with the lumped reservoir.
// Darcy with a tube carrying about half the loss: h = h0 exp(-t/tau), tau = A_r (L/(K A_s) + R_t).
// Forchheimer: t(q) = (A_r/A_s)[alpha ln(q0/q) + 2 beta (q0 - q)]. Tolerance 2 %.
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/Permeability.hpp"

using namespace qs;
using namespace qs::test;

namespace {

/// Time at which the head above the tailwater first falls to `fraction` of h0 (interpolated).
double timeToHeadFraction(const CaseRun& run, double tail, double fraction) {
    const double h0 = run.series.front().reservoirHead - tail;
    for (std::size_t k = 1; k < run.series.size(); ++k) {
        const double a = run.series[k - 1].reservoirHead - tail, b = run.series[k].reservoirHead - tail;
        if (a > fraction * h0 && b <= fraction * h0) {
            const double w = (a - fraction * h0) / (a - b);
            return run.series[k - 1].time + w * (run.series[k].time - run.series[k - 1].time);
        }
    }
    return -1;
}

void checkDarcyWithTube(const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase("falling_head", geometry);
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double g = c.gravity, rho = c.liquid.density, mu = c.liquid.viscosity;
    const double K = closed::hydraulicConductivity(sand.permeability.value, rho, g, mu);
    const double Rt = closed::tubeResistance(c.reservoir.tubeDiameter, c.reservoir.tubeLength, rho, g, mu);
    const double L = c.sandTop() - c.filterLevel();
    const double As = c.grid.crossSectionArea;
    const double tau = closed::fallingHeadTau(c.reservoir.area, As, L, K, Rt);
    ASSERT_GT(As * Rt, 0.5 * L / K) << "the tube must carry at least half the loss";
    const double tail = *c.column.overflowLevel;
    const double h0 = c.reservoir.head - tail;
    double worst = 0;
    for (const auto& s : run.series) {
        if (s.time < 0.1 || s.time > 2 * tau) continue;
        const double exact = h0 * std::exp(-s.time / tau);
        const double err = (s.reservoirHead - tail) / exact - 1;
        worst = std::max(worst, std::abs(err));
        EXPECT_NEAR(s.reservoirHead - tail, exact, 0.02 * exact) << "t = " << s.time;
    }
    const double tHalf = timeToHeadFraction(run, tail, 0.5);
    EXPECT_NEAR(tHalf, tau * std::log(2.0), 0.02 * tau * std::log(2.0));
    if (onShippedGrid(c)) {
        // guards: 0.11 % and 0.02 % are achieved (0.90 % and 0.09 % before the overflow held the surface)
        EXPECT_LT(worst, 3e-3);
        EXPECT_NEAR(tHalf, tau * std::log(2.0), 1e-3 * tau * std::log(2.0));
    }
    std::printf("falling head (Darcy + tube): tau = %.4f s, t(h0/2) = %.4f s vs %.4f s, worst head error %.2f %%\n",
                tau, tHalf, tau * std::log(2.0), 100 * worst);
}

void checkForchheimer(const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase("falling_head_forchheimer", geometry);
    const auto& c = run.config;
    const auto& m = c.material("gravel");
    const auto law = PermeabilityLaw::from(m);
    const double g = c.gravity, rho = c.liquid.density, mu = c.liquid.viscosity;
    const double kappa = law.kappa(m.porosity), F = law.ergunFactor(m.porosity);
    const double K = closed::hydraulicConductivity(kappa, rho, g, mu);
    const double L = c.sandTop() - c.filterLevel();
    closed::FallingHeadForchheimer fh{L / K, L * F / (g * std::sqrt(kappa)),
                                      c.reservoir.area / c.grid.crossSectionArea};
    const double tail = *c.column.overflowLevel;
    const double h0 = c.reservoir.head - tail;
    const double q0 = fh.flux(h0);
    ASSERT_GT(fh.beta * q0 * q0, 0.4 * h0) << "the Forchheimer term must carry a large part of the loss";
    for (double fraction : {0.5, 0.25}) {
        const double t = timeToHeadFraction(run, tail, fraction);
        const double exact = fh.timeToHead(h0, fraction * h0);
        ASSERT_GT(t, 0) << "the head never fell to " << fraction << " h0";
        EXPECT_NEAR(t, exact, 0.02 * exact) << "h/h0 = " << fraction;
        if (onShippedGrid(c)) {
            EXPECT_NEAR(t, exact, 6e-3 * exact) << "guard: +0.30 % and -0.03 % are achieved";
        }
        std::printf("falling head (Forchheimer): h/h0 = %.2f at %.4f s vs %.4f s (%+.2f %%)\n", fraction, t,
                    exact, 100 * (t / exact - 1));
    }
}

}  // namespace

TEST(FallingHead, DarcyWithTubeDecaysExponentially) { checkDarcyWithTube(); }

TEST(FallingHead, ForchheimerFormMatchesClosedForm) { checkForchheimer(); }

// the same columns in 2D, axisymmetry and 3D (VerificationCase.hpp), with the 1D tolerances
class FallingHeadIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(FallingHeadIn, DarcyWithTubeAndForchheimerMatchTheirClosedForms) {
    // the reservoir scaled with the column's cross-section (an axisymmetric column of two cells'
    // radius is a fifth of the 1D area): A_r / A_s and the tube's share A_s R_t stay, and so does
    // the closed form's time scale
    const auto geometry = [](CaseConfig& c) {
        const double before = c.grid.crossSectionArea;
        inTestGeometry(c, GetParam());
        const double ratio = c.grid.crossSectionArea / before;
        c.reservoir.area *= ratio;
        c.reservoir.tubeLength /= ratio;
    };
    checkDarcyWithTube(geometry);
    checkForchheimer(geometry);
}

INSTANTIATE_TEST_SUITE_P(Geometries, FallingHeadIn, kGeometries, geometryName);
