// Verification problem 9 (physics.md section 4): batch settling.
// A suspension at n0 = 0.55 (initially fluidised) settles in a closed column. Kynch: the top falls
// at q(n0) = 2.986e-3 m/s, a sediment at n_p = n_max grows from the filter at
// s = (1-n0) q(n0)/(n0 - n_p) = 9.60e-3 m/s, they meet at 14.8 s, and the bed ends
// H0 (1-n0)/(1-n_p) = 141.9 mm high. Tolerances: final height 2 %, top speed 5 %, sediment
// front 15 %, meeting time 15 %; tighter guards near what the method achieves
// (docs/verification.md: three grid sizes; the sediment forms about 0.007 denser than n_max).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "VerificationCase.hpp"
#include "physics/DriftFlux.hpp"

using namespace qs;
using namespace qs::test;

namespace {

struct Errors { double height, top, front, meeting; };

/// Problem 9 on cells of cellSize; `edit` may then change the column (its geometry).
Errors runSettling(double cellSize, const std::function<void(CaseConfig&)>& edit = {}) {
    const CaseRun run = runVerificationCase("batch_settling", [&](CaseConfig& c) {
        c.grid.cellSize = cellSize;
        if (edit) edit(c);
    });
    const auto& c = run.config;
    const auto& m = c.material("sand");
    const auto flux = closed::SuspensionFlux::of(c, m);
    const double H0 = c.sandTop() - c.filterLevel();
    const auto b = closed::batchSettling(flux, m.porosity, m.maxPorosity, H0);

    Errors err{};
    // the top falls and the sediment grows over most of the time before they meet
    const LineFit top = fitOverTime(run.series, 1.0, 0.8 * b.meetingTime, [](const ColumnState& s) { return s.bedHeight; });
    err.top = -top.slope / b.topSpeed - 1;
    const double filter = c.filterLevel();
    const LineFit front = fitOverTime(run.series, 2.0, 0.8 * b.meetingTime,
                                      [&](const ColumnState& s) { return s.fluidisedFront - filter; });
    err.front = front.slope / b.frontSpeed - 1;
    // they meet when (all but a percent of) the sand has resettled
    double meeting = -1;
    for (const auto& s : run.series)
        if (meeting < 0 && s.time > 1.0 && s.fluidisedShare < 0.01) meeting = s.time;
    EXPECT_GT(meeting, 0) << "the suspension never settled completely";
    err.meeting = meeting / b.meetingTime - 1;
    err.height = run.series.back().bedHeight / b.finalHeight - 1;
    // the sediment carries its buoyant weight: sigma'_v grows with depth at the buoyant unit
    // weight (1 - n_max)(rho_s - rho_L) g (a line through the rows: single points' stresses
    // differ by when each joined the sediment)
    const auto rows = sandRows(run.profiles.back());
    const auto line = fitLine(rows, [](const CellRow& r) { return -r.verticalStress; });
    const double unitWeight = (1 - m.maxPorosity) * (m.grainDensity - c.liquid.density) * c.gravity;
    EXPECT_NEAR(-line.second, unitWeight, 0.05 * unitWeight);
    std::printf("batch settling (%dD%s), h = %.4g m: final height %+.2f %%, top speed %+.2f %%, sediment front %+.2f %%, "
                "meeting time %+.2f %%\n",
                c.grid.dimension, c.grid.geometry == GridGeometry::Axisymmetric ? " axisymmetric" : "", cellSize,
                100 * err.height, 100 * err.top, 100 * err.front, 100 * err.meeting);
    return err;
}

void expectWithinTolerances(const Errors& e) {
    EXPECT_LT(std::abs(e.height), 0.02);
    EXPECT_LT(std::abs(e.top), 0.05);
    EXPECT_LT(std::abs(e.front), 0.15);
    EXPECT_LT(std::abs(e.meeting), 0.15);
}

}  // namespace

TEST(BatchSettling, ShippedGrid) {
    const Errors e = runSettling(0.0062);
    expectWithinTolerances(e);
    // guards near what is achieved
    EXPECT_LT(std::abs(e.height), 0.015);
    EXPECT_LT(std::abs(e.top), 0.005);
    EXPECT_LT(std::abs(e.front), 0.10);
}

// The same settling in 2D plane strain and in a cylinder, 2 cells across, on the shipped grid (on
// 12.4 mm cells the 1D run itself misses the front's tolerance: -15.5 %, meeting +20 %), with the
// 1D tolerances and guards. The water's surface is free, as in 1D (no overflow): until the nodal
// liquid mass at the surface came from the cells' fills rather than the points, a sloshing mode of
// the top cells grew there and the 2D run stopped at 11.3 s (test_FreeSurface.cpp).
class BatchSettlingIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(BatchSettlingIn, MatchesKynchAsIn1D) {
    QS_SEMI_IMPLICIT_ONLY();  // explicit: 1D above, fluidisation in 2D, axisymmetry and 3D elsewhere
    const Errors e = runSettling(0.0062, [](CaseConfig& c) {
        inGeometry(c, GetParam());
        EXPECT_FALSE(c.column.overflowLevel) << "the free surface is what this tests";
    });
    expectWithinTolerances(e);
    EXPECT_LT(std::abs(e.height), 0.015);
    EXPECT_LT(std::abs(e.top), 0.005);
    EXPECT_LT(std::abs(e.front), 0.10);
}

INSTANTIATE_TEST_SUITE_P(Geometries, BatchSettlingIn, ::testing::Values(Geometry::Plane2D, Geometry::Axisymmetric),
                         geometryName);
