// Verification problem 3 (physics.md section 4): steady seepage through a rigid skeleton,
// i gamma_w = (mu/kappa) q + (F rho_L / sqrt(kappa)) q|q|. The paper's case B (i = 1.32,
// n = 0.452) with kappa fixed (2.132e-3 m/s) and Kozeny-Carman (2.001e-3 m/s), and coarse grains
// where Forchheimer shows (2.496e-2 m/s; Darcy alone 5.21e-2). Tolerance 1 %, measured on the
// grid at the monitor section and at the gate, averaged over the last third of the run (each run
// lasts longer than one cell's worth of throughput).
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/Permeability.hpp"

using namespace qs;
using namespace qs::test;

namespace {

double closedFormFlux(const CaseConfig& c, double gradient) {
    const auto& m = c.material(c.layers.front().material);
    const auto law = PermeabilityLaw::from(m);
    return closed::darcyForchheimerFlux(gradient, law.kappa(m.porosity), law.ergunFactor(m.porosity),
                                        c.liquid.density, c.gravity, c.liquid.viscosity);
}

void checkSteadySeepage(const std::string& name, double gradient, double reference,
                        ShapeFunctionKind shape = ShapeFunctionKind::Linear,
                        const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase(name, [&](CaseConfig& c) {
        c.grid.shapeFunctions = shape;
        if (geometry) geometry(c);
    });
    const auto& c = run.config;
    const double expected = closedFormFlux(c, gradient);
    ASSERT_NEAR(expected, reference, 5e-4 * reference) << "closed form vs physics.md";
    const double t0 = c.time.end * 2.0 / 3.0;
    const double qMonitor = meanAfter(run.series, t0, [](const ColumnState& s) { return s.monitorFlux.at(0); });
    const double A = c.grid.crossSectionArea;
    const double qGate = meanAfter(run.series, t0, [A](const ColumnState& s) { return s.gateFlux / A; });
    EXPECT_NEAR(qMonitor, expected, 0.01 * expected);
    EXPECT_NEAR(qGate, expected, 0.01 * expected);
    if (onShippedGrid(c)) {
        // guards: within 0.035 % is achieved (+0.2 to +0.3 % before the overflow held the surface)
        EXPECT_NEAR(qMonitor, expected, 1e-3 * expected);
        EXPECT_NEAR(qGate, expected, 1e-3 * expected);
    }
    std::printf("%s (%dD%s): q monitor %.5g (%+.3f %%), gate %.5g (%+.3f %%), closed form %.5g m/s\n",
                name.c_str(), c.grid.dimension, c.grid.geometry == GridGeometry::Axisymmetric ? " axisymmetric" : "", qMonitor, 100 * (qMonitor / expected - 1), qGate,
                100 * (qGate / expected - 1), expected);
}

}  // namespace

TEST(SteadySeepage, CaseBConstantPermeability) {
    checkSteadySeepage("steady_seepage_B", 1.32, 2.132e-3);
}

TEST(SteadySeepage, CaseBConstantPermeabilityGimp) {
    checkSteadySeepage("steady_seepage_B", 1.32, 2.132e-3, ShapeFunctionKind::Gimp);
}

TEST(SteadySeepage, CaseBKozenyCarman) {
    checkSteadySeepage("steady_seepage_B_kozeny_carman", 1.32, 2.001e-3);
}

TEST(SteadySeepage, CoarseGrainsForchheimer) {
    checkSteadySeepage("steady_seepage_coarse", 1.0, 2.496e-2);
}

TEST(SteadySeepage, CoarseGrainsFailWithoutTheForchheimerTerm) {
    // The same run with the Ergun term off must miss the Forchheimer closed form by far.
    const CaseRun run = runVerificationCase("steady_seepage_coarse", [](CaseConfig& c) {
        c.materials.front().ergun = false;
        c.time.end = 0.3;
    });
    const double q = run.series.back().monitorFlux.at(0);
    EXPECT_GT(std::abs(q / 2.496e-2 - 1), 0.2);
}

namespace {

/// Case B held for `duration` s: the chamber's water flushes the first sand cell about once a
/// second, so liquid points bunching at the filter (physics.md's first open problem) or anything
/// else that drifts shows. The filter velocity at the monitor, sampled every 0.5 s, stays within
/// 1 % the whole time; the gate flux averages within 1 % (single steps spike when a liquid point
/// crosses a cell); the ledger closes to 1e-6 of the inflow; the liquid points stay as many as
/// the column holds (between 0.8 and 1.3 times the start: the chamber's smaller points replace
/// the initial lattice as the water flushes the bed, 20 s for case B's 90 mm).
void checkCaseBHolds(double duration, const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase("steady_seepage_B", [&](CaseConfig& c) {
        c.time.end = duration;
        c.time.outputInterval = 0.5;
        if (geometry) geometry(c);
    });
    const auto& c = run.config;
    const double expected = closedFormFlux(c, 1.32);
    double worst = 0;
    const std::size_t start = run.series.front().liquidPoints;
    std::size_t fewest = start, most = start;
    for (const auto& s : run.series) {
        fewest = std::min(fewest, s.liquidPoints);
        most = std::max(most, s.liquidPoints);
        if (s.time < 1.0) continue;
        worst = std::max(worst, std::abs(s.monitorFlux.at(0) / expected - 1));
        EXPECT_NEAR(s.monitorFlux.at(0), expected, 0.01 * expected) << "t = " << s.time;
    }
    const double A = c.grid.crossSectionArea;
    const double qGate = meanAfter(run.series, 10.0, [A](const ColumnState& s) { return s.gateFlux / A; });
    EXPECT_NEAR(qGate, expected, 0.01 * expected);
    const auto& last = run.series.back();
    EXPECT_LT(std::abs(last.ledgerResidual), 1e-6 * last.cumulativeInflow);
    if (onShippedGrid(c)) {
        // guards: 0.075 %, -0.02 % and 1.8e-8 are achieved in 1D
        EXPECT_LT(worst, 2.5e-3);
        EXPECT_NEAR(qGate, expected, 1e-3 * expected);
        EXPECT_LT(std::abs(last.ledgerResidual), 1e-7 * last.cumulativeInflow);
    }
    EXPECT_LE(most, 1.3 * start);
    EXPECT_GE(fewest, 0.8 * start);
    if (c.grid.dimension == 1) {  // in 1D, near what is achieved (47..60 over 60 s from 48)
        EXPECT_LE(most, start + 15);
        EXPECT_GE(fewest + 5, start);
    }
    std::printf("steady_seepage_B over %.0f s (%dD%s): monitor worst %.3f %%, gate mean %+.3f %%, ledger %.2e of the "
                "inflow, liquid points %zu..%zu\n",
                duration, c.grid.dimension, c.grid.geometry == GridGeometry::Axisymmetric ? " axisymmetric" : "",
                100 * worst, 100 * (qGate / expected - 1), std::abs(last.ledgerResidual) / last.cumulativeInflow,
                fewest, most);
}

}  // namespace

TEST(SteadySeepage, CaseBHoldsItsFilterVelocityForAMinute) { checkCaseBHolds(60.0); }

// the same columns in 2D, axisymmetry and 3D (VerificationCase.hpp), with the 1D tolerances; case
// B held for 15 s
class SteadySeepageIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(SteadySeepageIn, CaseBMatchesDarcyForchheimer) {
    checkSteadySeepage("steady_seepage_B", 1.32, 2.132e-3, ShapeFunctionKind::Linear,
                       [](CaseConfig& c) { inTestGeometry(c, GetParam()); });
}

TEST_P(SteadySeepageIn, CoarseGrainsMatchDarcyForchheimer) {
    checkSteadySeepage("steady_seepage_coarse", 1.0, 2.496e-2, ShapeFunctionKind::Linear,
                       [](CaseConfig& c) { inTestGeometry(c, GetParam()); });
}

TEST_P(SteadySeepageIn, CaseBHoldsItsFilterVelocityFor15Seconds) {
    if (GetParam() == Geometry::ThreeD) { QS_SEMI_IMPLICIT_ONLY(); }  // explicit: 2D and axisymmetric here
    checkCaseBHolds(15.0, [](CaseConfig& c) { inTestGeometry(c, GetParam()); });
}

INSTANTIATE_TEST_SUITE_P(Geometries, SteadySeepageIn, kGeometries, geometryName);
