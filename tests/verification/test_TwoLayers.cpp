// Verification problem 8 (physics.md section 4): two layers in series (sand over a filter layer
// 50 x more permeable), rigid skeleton, Darcy. q = dh / (L1/K1 + L2/K2); the head is piecewise
// linear. Tolerance 1 % on q and on the head profile (relative to dh).
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"

using namespace qs;
using namespace qs::test;

namespace {

void checkTwoLayers(const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase("two_layers", geometry);
    const auto& c = run.config;
    const double g = c.gravity, rho = c.liquid.density, mu = c.liquid.viscosity;
    const auto& filter = c.material("filter");
    const auto& sand = c.material("sand");
    const double K2 = closed::hydraulicConductivity(filter.permeability.value, rho, g, mu);
    const double K1 = closed::hydraulicConductivity(sand.permeability.value, rho, g, mu);
    ASSERT_NEAR(K2 / K1, 50.0, 1e-9);
    const double L2 = c.layers[0].thickness, L1 = c.layers[1].thickness;
    const double tail = *c.column.overflowLevel;
    const double dh = c.reservoir.head - tail;
    const double q = closed::seriesFlux(dh, L1, K1, L2, K2);

    const double t0 = c.time.end * 2.0 / 3.0;
    const double qSand = meanAfter(run.series, t0, [](const ColumnState& s) { return s.monitorFlux.at(0); });
    const double qFilter = meanAfter(run.series, t0, [](const ColumnState& s) { return s.monitorFlux.at(1); });
    EXPECT_NEAR(qSand, q, 0.01 * q);
    EXPECT_NEAR(qFilter, q, 0.01 * q);
    if (onShippedGrid(c)) {
        // guards: -0.03 % is achieved (-0.19 % before the overflow held the surface)
        EXPECT_NEAR(qSand, q, 1e-3 * q);
        EXPECT_NEAR(qFilter, q, 1e-3 * q);
    }

    // excess head h(z) = (p - rho g (tail - z)) / (rho g), piecewise linear: dh at the base of
    // the filter layer, q L1/K1 at the interface, 0 at the sand top
    const double zInterface = c.filterLevel() + L2;
    for (const auto& r : sandRows(run.summary.profile)) {
        const double head = (r.porePressure - rho * g * (tail - r.z)) / (rho * g);
        const double exact = r.z >= zInterface ? q * (c.sandTop() - r.z) / K1
                                               : q * L1 / K1 + q * (zInterface - r.z) / K2;
        EXPECT_NEAR(head, exact, 0.01 * dh) << "z = " << r.z;
    }
    std::printf("two layers: q sand %.5g, filter %.5g, closed form %.5g m/s (%+.3f %%)\n", qSand, qFilter, q,
                100 * (qSand / q - 1));
}

}  // namespace

TEST(TwoLayers, FluxAndHeadProfileMatchLayersInSeries) { checkTwoLayers(); }

// the same column in 2D, axisymmetry and 3D (VerificationCase.hpp), with its 1D tolerances
class TwoLayersIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(TwoLayersIn, FluxAndHeadProfileMatchLayersInSeries) {
    checkTwoLayers([](CaseConfig& c) { inTestGeometry(c, GetParam()); });
}

INSTANTIATE_TEST_SUITE_P(Geometries, TwoLayersIn, kGeometries, geometryName);
