// Verification problem 1 (physics.md section 4): geostatic column, water at the sand top.
// p(base) = rho_L g H = 1821.4 Pa, sigma'_v(base) = (1-n)(rho_s-rho_L) g H = 1868.7 Pa,
// sigma'_h = K0 sigma'_v, within 2 %; spurious filter velocity below 1e-3 K throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"

using namespace qs;
using namespace qs::test;

namespace {
void checkGeostatic(ShapeFunctionKind shape, double gravityStage = 0.0,
                    const std::function<void(CaseConfig&)>& geometry = {}) {
    const CaseRun run = runVerificationCase("geostatic", [&](CaseConfig& c) {
        c.grid.shapeFunctions = shape;
        c.initial.gravityStageDuration = gravityStage;
        c.initial.gravityStageDamping = 0.1;
        if (geometry) geometry(c);
    });
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double g = c.gravity, rhoL = c.liquid.density;
    const double H = c.sandTop() - c.filterLevel();
    const double pBase = rhoL * g * H;
    const double sBase = (1 - sand.porosity) * (sand.grainDensity - rhoL) * g * H;
    ASSERT_NEAR(pBase, 1821.4, 0.1);   // physics.md's numbers, from the case's data
    ASSERT_NEAR(sBase, 1868.7, 0.1);

    const auto rows = sandRows(run.summary.profile);
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(std::llround(H / c.grid.cellSize)));
    for (const auto& r : rows) {
        const double depth = c.sandTop() - r.z;
        EXPECT_NEAR(r.porePressure, rhoL * g * (c.column.waterLevel - r.z), 0.02 * pBase) << "z = " << r.z;
        EXPECT_NEAR(-r.verticalStress, sBase * depth / H, 0.02 * sBase) << "z = " << r.z;
        EXPECT_NEAR(-r.horizontalStress, sand.k0 * sBase * depth / H, 0.02 * sand.k0 * sBase) << "z = " << r.z;
    }
    // the base values, from straight lines through the cell means
    const auto p = fitLine(rows, [](const CellRow& r) { return r.porePressure; });
    const auto s = fitLine(rows, [](const CellRow& r) { return -r.verticalStress; });
    const double zBase = c.filterLevel();
    EXPECT_NEAR(p.first + p.second * zBase, pBase, 0.02 * pBase);
    EXPECT_NEAR(s.first + s.second * zBase, sBase, 0.02 * sBase);

    // no spurious flow
    const double K = closed::hydraulicConductivity(sand.permeability.value, rhoL, g, c.liquid.viscosity);
    for (const auto& st : run.series) {
        EXPECT_LT(std::abs(st.monitorFlux.at(0)), 1e-3 * K) << "t = " << st.time;
        EXPECT_LT(std::abs(st.gateFlux / c.grid.crossSectionArea), 1e-3 * K) << "t = " << st.time;
    }
    EXPECT_GE(run.series.back().time, c.time.end - 0.5 * c.time.outputInterval);
}
}  // namespace

TEST(Geostatic, PorePressureAndEffectiveStressMatchClosedForm) { checkGeostatic(ShapeFunctionKind::Linear); }

TEST(Geostatic, PorePressureAndEffectiveStressMatchClosedFormWithGimp) {
    // (uGIMP once leaked the bottom solid points' support onto the chamber node below the
    // filter, where the interaction force drove that sliver of solid: the column settled for
    // 0.05 s with q up to 6e-3 K. The solid now stops at the filter; see PointsToGrid.cpp.)
    checkGeostatic(ShapeFunctionKind::Gimp);
}

TEST(Geostatic, GravityStageWithLocalDampingReachesTheSameState) {
    // Start from zero effective stress and let a damped gravity stage find equilibrium: the
    // vertical stress must match the closed form; the horizontal one follows elasticity,
    // nu/(1-nu) sigma'_v, not K0 (physics.md section 1).
    const CaseRun run = runVerificationCase("geostatic", [](CaseConfig& c) {
        c.initial.stress = InitialStress::Zero;
        c.initial.gravityStageDuration = 1.0;
        c.initial.gravityStageDamping = 0.1;
        c.time.end = 0.05;
    });
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double H = c.sandTop() - c.filterLevel();
    const double sBase = (1 - sand.porosity) * (sand.grainDensity - c.liquid.density) * c.gravity * H;
    const double lateral = sand.poissonRatio / (1 - sand.poissonRatio);
    for (const auto& r : sandRows(run.summary.profile)) {
        const double depth = c.sandTop() - r.z;
        EXPECT_NEAR(-r.verticalStress, sBase * depth / H, 0.02 * sBase) << "z = " << r.z;
        EXPECT_NEAR(-r.horizontalStress, lateral * sBase * depth / H, 0.02 * sBase) << "z = " << r.z;
    }
}

// the same column in 2D, axisymmetry and 3D (VerificationCase.hpp), with its 1D tolerances
class GeostaticIn : public ::testing::TestWithParam<Geometry> {};

TEST_P(GeostaticIn, PorePressureAndEffectiveStressMatchClosedForm) {
    checkGeostatic(ShapeFunctionKind::Linear, 0.0, [](CaseConfig& c) { inTestGeometry(c, GetParam()); });
}

INSTANTIATE_TEST_SUITE_P(Geometries, GeostaticIn, kGeometries, geometryName);

TEST(Geostatic, ASkeletonCompactedPastItsDensestPackingStaysAtIt) {
    // a soft, permeable skeleton (E = 2 kPa, E_oed = 2.7 kPa, kappa = 1e-8 m2: it drains in about a
    // second) under a surcharge of 400 Pa asks for a volumetric strain of 15 % or more, which takes
    // n = 0.38 past n_min = 0.32; the grains stop there. Without the rule the points reached
    // n = 0.066 (and a pipe's sand column at the wall of cases/piping2D reached n < 0 at 6.58 s and
    // stopped the run). Under 2 kPa (70 % strain) the run still fails, on the water squeezed out:
    // a skeleton at n_min does not stiffen (docs/piping.md, "What quicksand does not carry")
    const CaseRun run = runVerificationCase("geostatic", [](CaseConfig& c) {
        auto& sand = c.materials.at(0);
        sand.youngsModulus = 2.0e3;
        sand.permeability.value = 1.0e-8;
        c.loads.surcharge = 400.0;
        c.loads.surchargeRampTime = 0.5;
        c.time.end = 3.0;
        c.time.outputInterval = 0.05;
        // The semi-implicit step follows this skeleton's wave, 1.3 m/s (dt = 2.9 ms): a skeleton
        // locked at n_min is stiffer than its E says, and at courant 0.4 the water squeezed past
        // the locked grains outran a cell per step at 1.45 s. At 0.2 it holds (docs/case-format.md,
        // choosing the time scheme).
        if (c.time.scheme == TimeScheme::SemiImplicit) c.time.courant = 0.2;
    });
    const double nMin = run.config.material("sand").minPorosity;
    double least = 1;
    for (const auto& rows : run.profiles)
        for (const auto& r : rows)
            if (r.solidCount > 0) least = std::min(least, r.minPorosity);
    EXPECT_GE(least, nMin - 1e-12);
    EXPECT_LT(least, nMin + 1e-3);  // it is reached: the test loads the skeleton that far
    std::printf("soft skeleton under 400 Pa: least porosity %.4f (n_min %.4f)\n", least, nMin);
}

// Close packing held (issue 42, item 3; physics/ClosePacking.hpp): a skeleton of E = 10 kPa
// (E_oed = 13.5 kPa) under 2 kPa, in plane strain 2 cells wide: its own stress at the strain that
// takes n = 0.38 to n_min = 0.32 (8.8 %) is 1.2 kPa, less than the load and its weight, so the
// grid's cells go on crowding past n_min (the points' own porosity is kept at n_min by
// GridToPoints.cpp, so the rows' point porosity cannot show it: the cells' sand porosity, the
// grid's measure, does). Without close packing the bed ends more than 3 % below the height its
// grains take packed, H0 (1 - n0) / (1 - n_min), and its cells below n_min; with it the bed is
// within 1 % of that height and the cells below the top two (whose porosity is copied from the
// cell below, and which are not pushed) at n_min within 1e-3 (2026-12-08: see the printed figures
// and docs/piping.md, "Close packing held"). Explicit only: M is the stiffest the step carries,
// and the semi-implicit step, sized by this skeleton's own wave (2.9 m/s), carries M = 3.7 kPa,
// of the load's order; it holds a sand whose stiffness is far above its stresses (cases/piping2D:
// E_oed 1.35 MPa, M 3e5 Pa, a few kPa). A softer skeleton (E = 6 kPa) still fails with it.
TEST(Geostatic, ASkeletonCrushedOntoItsDensestPackingStopsThere) {
    if (testScheme() != "explicit")
        GTEST_SKIP() << "the semi-implicit step carries a packing modulus of this load's order (see the comment)";
    auto run = [](bool packing) {
        return runVerificationCase("geostatic", [packing](CaseConfig& c) {
            auto& sand = c.materials.at(0);
            sand.youngsModulus = 1.0e4;
            sand.permeability.value = 1.0e-8;
            sand.closePacking = packing;
            c.loads.surcharge = 2000.0;
            c.loads.surchargeRampTime = 0.5;
            c.time.end = 3.0;
            c.time.outputInterval = 0.1;
            inGeometry(c, Geometry::Plane2D);
        });
    };
    // the least sand porosity of the cells below the top two of each column, at the end
    auto leastCell = [](const CaseRun& r) {
        const SandCells& s = r.cells.back();
        double least = 1;
        for (Index col = 0; col < s.columns(); ++col) {
            Index top = -1;
            for (Index row = 0; row < s.rows(); ++row)
                if (s.state[s.cell(col, row)] != CellSand::None) top = row;
            for (Index row = 0; row + 2 <= top; ++row)
                if (s.state[s.cell(col, row)] != CellSand::None) least = std::min(least, s.porosity[s.cell(col, row)]);
        }
        return least;
    };
    const CaseRun held = run(true), crowded = run(false);
    const auto& sand = held.config.material("sand");
    const double nMin = sand.minPorosity, H0 = held.config.layers.front().thickness;
    const double packed = H0 * (1 - sand.porosity) / (1 - nMin);
    const double height = held.series.back().bedHeight, without = crowded.series.back().bedHeight;
    const double least = leastCell(held), leastWithout = leastCell(crowded);
    EXPECT_GE(least, nMin - 1e-3);
    EXPECT_GE(least, nMin - 2e-4);           // a guard near what is reached (9e-5)
    EXPECT_NEAR(height, packed, 0.01 * packed);
    EXPECT_LT(without, 0.97 * packed);       // the test loads the bed that far
    EXPECT_LT(leastWithout, nMin - 0.01);    // and its cells past n_min without close packing
    std::printf("skeleton of 10 kPa under 2 kPa: with close packing the least cell below the top two %.5f (n_min "
                "%.4f), bed height %.5f m against the packed %.5f m (%+.2f %%); without it %.5f and %.5f m (%+.2f %%)\n",
                least, nMin, height, packed, 100 * (height / packed - 1), leastWithout, without,
                100 * (without / packed - 1));
}
