// Verification problem 7 (physics.md section 4): bed expansion after a step in flux.
// A packed bed at n1 = 0.38 and U1 = U_mf (zero effective stress) gets U2 = 1.380e-3 m/s. Drift
// flux (Kynch): the bed below a shock expands to n2 = 0.452, the front rises at
// s = (1-n1)(U2-U1)/(n2-n1) = 5.614e-3 m/s, the packed bed above rises as a plug at U2 - U1, and
// the bed ends H2 = H1 (1-n1)/(1-n2) = 210.4 mm high.
// Tolerances of physics.md: H2 2 %, plug speed 5 %, front speed 15 %; the expanded zone's
// porosity: cell means within 0.01 of n2, single points within 0.03 (the fluidisation issue).
// Tighter guards sit near what the method achieves (docs/verification.md has the numbers at three
// grid sizes), so that a regression shows long before a tolerance is reached.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "VerificationCase.hpp"
#include "physics/DriftFlux.hpp"

using namespace qs;
using namespace qs::test;

namespace {

const char* geometryText(const CaseConfig& c) {
    if (c.grid.dimension == 1) return "1D";
    if (c.grid.dimension == 3) return "3D";
    return c.grid.geometry == GridGeometry::Axisymmetric ? "axisymmetric" : "2D plane";
}

closed::SuspensionFlux fluxOf(const CaseConfig& c) { return closed::SuspensionFlux::of(c, c.material("sand")); }

struct Errors {
    double height, plug, front, r2;
    double cellPorosity, pointPorosity;  ///< the fully expanded bed at the end
    double wakeCell, wakePoint;          ///< behind the front at three quarters of the expansion
};

/// Problem 7 on cells of cellSize; `edit` may then change the column (its geometry, its end).
Errors runExpansion(double cellSize, const std::function<void(CaseConfig&)>& edit = {}) {
    const CaseRun run = runVerificationCase("bed_expansion", [&](CaseConfig& c) {
        c.grid.cellSize = cellSize;
        if (edit) edit(c);
    });
    const auto& c = run.config;
    const auto flux = fluxOf(c);
    const double n1 = c.material("sand").porosity, U1 = c.initial.filterVelocity, U2 = c.gate.flux;
    const double H1 = c.sandTop() - c.filterLevel();
    EXPECT_NEAR(U1, flux.equilibriumFlux(n1), 1e-4 * U1) << "the case starts at U_mf";
    const auto e = closed::bedExpansion(flux, n1, U1, U2, H1);

    Errors err{};
    // plug: the bed's top rises at U2 - U1 until the front nears it (t < 0.8 of its arrival)
    const LineFit plug = fitOverTime(run.series, 2.0, 0.8 * e.duration, [](const ColumnState& s) { return s.bedHeight; });
    err.plug = plug.slope / e.plugSpeed - 1;
    // front: from its first cells to where it nears the plug's top
    const LineFit front = fitOverTime(run.series, 3.0, 0.85 * e.duration, [](const ColumnState& s) { return s.fluidisedFront; });
    err.front = front.slope / e.frontSpeed - 1;
    err.r2 = front.r2;
    err.height = run.series.back().bedHeight / e.finalHeight - 1;
    // the expanded zone: behind the front at three quarters of the expansion (rows a cell above
    // the filter to three cells below the front), and at the end (to four cells below the
    // surface, where the front arrived last)
    auto zone = [&](std::size_t k, double zMax, double& cell, double& point) {
        for (const auto& r : run.profiles[k]) {
            if (r.solidCount == 0 || r.z < c.filterLevel() + 1.5 * cellSize || r.z > zMax) continue;
            EXPECT_EQ(r.fluidisedShare, 1.0) << "t = " << run.series[k].time << ", z = " << r.z;
            cell = std::max(cell, std::abs(r.porosity - e.expandedPorosity));
            point = std::max({point, std::abs(r.minPorosity - e.expandedPorosity),
                              std::abs(r.maxPorosity - e.expandedPorosity)});
        }
    };
    std::size_t k = 0;
    while (k + 1 < run.series.size() && run.series[k].time < 0.75 * e.duration) ++k;
    zone(k, run.series[k].fluidisedFront - 3 * cellSize, err.wakeCell, err.wakePoint);
    zone(run.series.size() - 1, run.series.back().sandSurface - 4 * cellSize, err.cellPorosity, err.pointPorosity);
    std::printf("bed expansion (%s), h = %.4g m: H2 %+.2f %%, plug speed %+.2f %%, front speed %+.2f %% (r2 %.4f), "
                "expanded bed n: cells within %.4f, points within %.4f of %.4f (behind the front: %.4f, %.4f)\n",
                geometryText(c), cellSize, 100 * err.height, 100 * err.plug, 100 * err.front, err.r2, err.cellPorosity,
                err.pointPorosity, e.expandedPorosity, err.wakeCell, err.wakePoint);
    return err;
}

void expectWithinTolerances(const Errors& e) {
    EXPECT_LT(std::abs(e.height), 0.02);
    EXPECT_LT(std::abs(e.plug), 0.05);
    EXPECT_LT(std::abs(e.front), 0.15);
    EXPECT_GE(e.r2, 0.98);
    EXPECT_LT(e.cellPorosity, 0.01);
    EXPECT_LT(e.pointPorosity, 0.03);
    EXPECT_LT(e.wakeCell, 0.01);
    EXPECT_LT(e.wakePoint, 0.03);
}

}  // namespace

TEST(BedExpansion, CoarseGrid) {
    const Errors e = runExpansion(0.0124);
    expectWithinTolerances(e);
    // guards near what is achieved (docs/verification.md)
    EXPECT_LT(std::abs(e.height), 0.01);
    EXPECT_LT(std::abs(e.plug), 0.01);
    EXPECT_LT(std::abs(e.front), 0.03);
}

namespace {
/// The shipped grid's guards near what it achieves (docs/verification.md)
void expectShippedGridGuards(const Errors& e) {
    expectWithinTolerances(e);
    EXPECT_LT(std::abs(e.height), 0.006);
    EXPECT_LT(std::abs(e.plug), 0.005);
    EXPECT_LT(std::abs(e.front), 0.01);
    EXPECT_LT(e.cellPorosity, 0.005);
    EXPECT_LT(e.pointPorosity, 0.008);
}
}  // namespace

TEST(BedExpansion, ShippedGrid) {
    expectShippedGridGuards(runExpansion(0.0062));
    // The expanded bed's spread at the end depends on round-off: the coloured scatter's order of
    // summation (slabs of 1 to 8 rows, all valid orders in 1D, where the scatter is serial) gave
    // cells within 0.0022 and points within 0.0025-0.0029 for six orders (2 rows, the one used:
    // 0.0022, 0.0029), and 0.0041-0.0042 and 0.0068-0.0070 for two (1 and 7 rows). H2 moved between
    // -0.09 % and -0.21 %; plug and front speeds within 0.01 % of each other, the wake the same.
    // The guards sit above both outcomes (docs/verification.md).
}

TEST(BedExpansion, AnExpandedBedAtUniformPorosityStaysUniform) {
    // the bed of the closed form's end state, started there: a suspension at n2 = 0.452 carried by
    // its equilibrium flux q(n2) = 1.380e-3 m/s. Nothing may move: every point's porosity within
    // 0.003 of n2 after 20 s, the bed's height within 0.5 mm, the filter velocity within 0.5 % (a
    // drag, weight or pressure out of balance would expand or compact it).
    const auto flux = fluxOf(loadVerificationCase("bed_expansion"));
    const double n2 = 0.452, q2 = flux.equilibriumFlux(n2);
    const CaseRun run = runVerificationCase("bed_expansion", [&](CaseConfig& c) {
        c.materials.front().porosity = n2;
        c.initial.state = InitialState::Fluidised;
        c.initial.stress = InitialStress::Zero;
        c.initial.filterVelocity = q2;
        c.gate.flux = q2;
        c.layers.front().thickness = 0.1488;  // 24 cells of 6.2 mm
        c.time.end = 20.0;
        c.time.outputInterval = 0.5;
    });
    const auto& c = run.config;
    double cell = 0, point = 0;
    for (const auto& r : run.profiles.back()) {
        if (r.solidCount == 0 || r.z > run.series.back().sandSurface - 2 * c.grid.cellSize) continue;
        EXPECT_EQ(r.fluidisedShare, 1.0) << "z = " << r.z;
        cell = std::max(cell, std::abs(r.porosity - n2));
        point = std::max({point, std::abs(r.minPorosity - n2), std::abs(r.maxPorosity - n2)});
    }
    EXPECT_LT(cell, 0.002);
    EXPECT_LT(point, 0.003);
    EXPECT_LT(point, 1e-3);  // guard: below 1e-4 is achieved
    const double H = c.sandTop() - c.filterLevel();
    EXPECT_NEAR(run.series.back().bedHeight, H, 5e-4);
    EXPECT_NEAR(run.series.back().bedHeight, H, 1e-4);  // guard: 1 um is achieved
    for (const auto& s : run.series)
        if (s.time > 1.0) {
            EXPECT_NEAR(s.monitorFlux.at(0), q2, 0.005 * q2) << "t = " << s.time;
        }
    std::printf("uniform suspension at n = %.3f over 20 s: cells within %.4f, points within %.4f; bed height %+.3f mm\n",
                n2, cell, point, 1000 * (run.series.back().bedHeight - H));
}

// The same bed in 2D plane strain and in a cylinder, 2 cells across, over the whole expansion,
// with the 1D tolerances and the coarse grid's guards. The profiles' point extremes and the
// fluidised share are taken over whole rows, so a row that loses its lateral uniformity fails
// them (with FLIP solid points the 2D bed's rows spread by 0.04 in porosity from 12 s on). 3D
// (2 x 2 cells, about 50 times the 1D run) runs the first 10 s in the next test.
class BedExpansionIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(BedExpansionIn, MatchesDriftFluxOverTheWholeExpansion) {
    QS_SEMI_IMPLICIT_ONLY();  // explicit: BedExpansion2D
    const Errors e = runExpansion(0.0124, [](CaseConfig& c) { inGeometry(c, GetParam()); });
    expectWithinTolerances(e);
    EXPECT_LT(std::abs(e.height), 0.01);
    EXPECT_LT(std::abs(e.plug), 0.01);
    EXPECT_LT(std::abs(e.front), 0.03);
}

INSTANTIATE_TEST_SUITE_P(Geometries, BedExpansionIn, ::testing::Values(Geometry::Plane2D, Geometry::Axisymmetric),
                         geometryName);

TEST(BedExpansionIn3D, PlugAndFrontMatchDriftFluxOverTheFirst10Seconds) {
    // Semi-implicit only since 2026-12-08 (CI's time: 115 s explicit, 28 s semi-implicit; both gave
    // +0.01 %, -1.63 %): the explicit step's expansion is checked in 1D and in 2D
    // (BedExpansion2D), its 3D step by the 3D critical gradient and falling head.
    QS_SEMI_IMPLICIT_ONLY();
    // 2 x 2 cells of 12.4 mm; the front is fitted from 3 s, the plug from 2 s to 10 s
    double plug = 0, front = 0, spread = 0;
    const CaseRun run = runVerificationCase("bed_expansion", [](CaseConfig& c) {
        c.grid.cellSize = 0.0124;
        inGeometry(c, Geometry::ThreeD);
        c.time.end = 10.0;
    });
    const auto& c = run.config;
    const auto flux = fluxOf(c);
    const double n1 = c.material("sand").porosity, U1 = c.initial.filterVelocity, U2 = c.gate.flux;
    const auto e = closed::bedExpansion(flux, n1, U1, U2, c.sandTop() - c.filterLevel());
    plug = fitOverTime(run.series, 2.0, 10.0, [](const ColumnState& s) { return s.bedHeight; }).slope / e.plugSpeed - 1;
    front = fitOverTime(run.series, 3.0, 10.0, [](const ColumnState& s) { return s.fluidisedFront; }).slope / e.frontSpeed - 1;
    const double h = c.grid.cellSize, top = run.series.back().fluidisedFront - 3 * h;
    for (const auto& r : run.profiles.back())
        if (r.solidCount > 0 && r.z > c.filterLevel() + 1.5 * h && r.z < top) {
            EXPECT_EQ(r.fluidisedShare, 1.0) << "z = " << r.z;
            spread = std::max(spread, r.maxPorosity - r.minPorosity);
        }
    EXPECT_LT(std::abs(plug), 0.05);
    EXPECT_LT(std::abs(front), 0.15);
    EXPECT_LT(std::abs(plug), 0.005);  // guards near what is achieved: +0.01 %, -1.6 %, 0
    EXPECT_LT(std::abs(front), 0.03);
    EXPECT_LT(spread, 0.03);           // the rows' point extremes behind the front (1D: 0.03 about n2)
    EXPECT_LT(spread, 0.006);
    std::printf("bed expansion (3D, 2 x 2 cells of 12.4 mm, 10 s): plug speed %+.2f %%, front speed %+.2f %%, "
                "largest spread of a row's points behind the front %.4f\n", 100 * plug, 100 * front, spread);
}

// With the particle phase (issue 42, item 2) and the front diffusion cut to the fronts
// (front_threshold = 0.01: it fades where the porosity changes by less than 0.01 over a cell),
// problem 7 keeps the shipped grid's guards (2026-12-07: H2 -0.08 %, plug -0.01 %, front +0.06 %,
// the expanded bed's cells within 0.0028 and points within 0.0054, behind the front 0.0090 and
// 0.0107). The particle phase alone cannot hold the fronts on such cells (front_diffusion = 0:
// the front speed's fit fails, the bed's cells 0.035 off): its diffusion, K / B = 6.3e-7 m2/s,
// makes a front about 4 K / (B c) = 0.4 mm wide, far below the cell, so the grid's diffusion stays at the
// fronts, and the threshold keeps it off the small perturbations whose growth the closure decides
// (test_FluidisedBedStability.cpp). Without the particle phase the threshold leaves the wake at
// 0.0103, past its 0.01.
TEST(BedExpansion, WithTheParticlePhaseAndTheFrontDiffusionAtFrontsOnly) {
    // the explicit step gave the same digits (2026-12-07: H2 -0.08 %, plug -0.02 %, front +0.06 %,
    // cells 0.0028, points 0.0054, wake 0.0090 and 0.0107) in 50 s against 9: CI's time
    QS_SEMI_IMPLICIT_ONLY();
    const Errors e = runExpansion(0.0062, [](CaseConfig& c) {
        auto& m = c.materials.front();
        m.particlePhase = ParticlePhaseModel::FoscoloGibilaro;
        m.particleGrainSize = m.permeability.grainSize;
        m.frontThreshold = 0.01;
    });
    expectShippedGridGuards(e);
}
