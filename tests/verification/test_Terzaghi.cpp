// Verification problem 4 (physics.md section 4): Terzaghi consolidation with compressible water
// (Verruijt). Undrained start under q: u0 = q m_v / (m_v + n/K_L), then
// u/u0 = sum 2/M sin(M Z) exp(-M^2 T), T = c_v t / H^2, Z from the drained face.
// Tolerance 0.05 u0 for T >= 0.05 on every sand cell row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;
using namespace qs::test;

namespace {
/// scheme: the binary's own (tests/CMakeLists.txt) unless given
void checkTerzaghi(ShapeFunctionKind shape, int solidPerCell = 2, std::optional<TimeScheme> scheme = std::nullopt,
                   double guard = 0.0075) {
    const CaseRun run = runVerificationCase("terzaghi", [&](CaseConfig& c) {
        c.grid.shapeFunctions = shape;
        c.points.solidPerCell = solidPerCell;
        if (scheme) c.time.scheme = *scheme;
    });
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double Eoed = closed::oedometricModulus(sand.youngsModulus, sand.poissonRatio);
    const double KL = c.liquid.bulkModulus, n = sand.porosity;
    const double q = c.loads.surcharge;
    const double u0 = q * closed::undrainedPressureRatio(Eoed, n, KL);
    ASSERT_NEAR(u0 / q, 0.9765, 5e-4);
    // c_v = k/(gamma_w (m_v + n/K_L)) = (kappa/mu)/(m_v + n/K_L), independent of g
    const double cv = (sand.permeability.value / c.liquid.viscosity) / (1 / Eoed + n / KL);
    ASSERT_NEAR(cv, 0.02198, 1e-5);
    const double H = c.sandTop() - c.filterLevel();

    double worst = 0;
    int compared = 0;
    for (std::size_t k = 0; k < run.series.size(); ++k) {
        const double T = cv * run.series[k].time / (H * H);
        if (T < 0.05) continue;
        for (const auto& r : sandRows(run.profiles[k])) {
            const double Z = (c.sandTop() - r.z) / H;
            const double exact = closed::terzaghiPressureRatio(Z, T);
            const double err = std::abs(r.porePressure / u0 - exact);
            worst = std::max(worst, err);
            EXPECT_LE(err, 0.05) << "T = " << T << ", Z = " << Z;
            ++compared;
        }
    }
    EXPECT_GT(compared, 100);
    EXPECT_GT(cv * run.series.back().time / (H * H), 0.5);
    // guard near what is achieved, 0.0066 (linear) and 0.0063 / 0.0062 (uGIMP, 2 and 1 points per cell):
    // 0.05 alone let a 10 %-slow consolidation pass at 0.048
    EXPECT_LE(worst, guard);
    std::printf("Terzaghi (%s): largest |u/u0 - exact| over T >= 0.05: %.4f, %zu outputs\n",
                run.config.time.scheme == TimeScheme::Explicit ? "explicit" : "semi-implicit", worst, run.series.size());
}
}  // namespace

TEST(Terzaghi, ExcessPorePressureFollowsVerruijtSolution) { checkTerzaghi(ShapeFunctionKind::Linear); }

TEST(Terzaghi, ExcessPorePressureFollowsVerruijtSolutionWithGimp) { checkTerzaghi(ShapeFunctionKind::Gimp); }

TEST(Terzaghi, ExcessPorePressureFollowsVerruijtSolutionWithGimpOnePointPerCell) {
    // the largest uGIMP domain (half a cell): the case that exposed solid support leaking below
    // the filter (the base then stayed at 0.96 u0 instead of 0.36 at T = 0.5)
    checkTerzaghi(ShapeFunctionKind::Gimp, 1);
}

// The same problem in 2D (4 cells wide) and 3D (2 x 2 cells): rows against the closed form with
// the 1D tolerance, and the pore pressure of every row laterally uniform. The column is
// laterally uniform, so this checks that the 2D and 3D step reproduce the 1D physics (and grows
// no lateral mode); lateral errors proper are the business of test_LateralPhysics.cpp.
namespace {
template <int D>
void checkTerzaghiInDimension(int across, double tolerance, double guard, bool axisymmetric = false,
                              double spreadBound = 1e-12, double level = 1e-7) {
    CaseConfig c = loadVerificationCase("terzaghi");
    inGeometry(c, D == 3 ? Geometry::ThreeD : (axisymmetric ? Geometry::Axisymmetric : Geometry::Plane2D), across);
    const auto& sand = c.material("sand");
    const double Eoed = closed::oedometricModulus(sand.youngsModulus, sand.poissonRatio);
    const double KL = c.liquid.bulkModulus, n = sand.porosity;
    const double u0 = c.loads.surcharge * closed::undrainedPressureRatio(Eoed, n, KL);
    const double cv = (sand.permeability.value / c.liquid.viscosity) / (1 / Eoed + n / KL);
    const double H = c.sandTop() - c.filterLevel();
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<D> solver(c, *reservoir);
    double worst = 0, spread = 0;
    for (const double T : {0.05, 0.1, 0.2}) {
        while (cv * solver.time() / (H * H) < T) solver.step();
        const double Tnow = cv * solver.time() / (H * H);
        for (const auto& r : sandRows(solver.profile())) {
            const double err = std::abs(r.porePressure / u0 - closed::terzaghiPressureRatio((c.sandTop() - r.z) / H, Tnow));
            worst = std::max(worst, err);
            EXPECT_LE(err, tolerance) << D << "D, T = " << Tnow << ", z = " << r.z;
        }
        // lateral uniformity: liquid points at the same height (to 0.1 um), against each other;
        // within a row the pressure varies with height (each point carries the cell's gradient)
        const auto& l = solver.liquid();
        struct Level { double lo = 1e300, hi = -1e300; int points = 0; };
        std::map<long, Level> levels;  // by height, in steps of `level`
        for (std::size_t p = 0; p < l.size(); ++p) {
            const double z = l.x[p * D + D - 1];
            if (z <= c.filterLevel() || z >= c.sandTop()) continue;
            Level& at = levels[std::lround(z / level)];
            at.lo = std::min(at.lo, l.pressure[p]);
            at.hi = std::max(at.hi, l.pressure[p]);
            ++at.points;
        }
        ASSERT_GT(levels.size(), 20u);
        for (const auto& [key, at] : levels) {
            EXPECT_GE(at.points, 2 * across) << "points at one height side by side";
            spread = std::max(spread, (at.hi - at.lo) / u0);
        }
    }
    EXPECT_LE(worst, guard) << D << "D: achieved 0.0046 (the 1D run's 0.0061 over its whole run)";
    EXPECT_LE(spread, spreadBound) << D << "D: a laterally uniform column must stay so";
    std::printf("Terzaghi %dD%s (%s): largest |u/u0 - exact| %.4f, largest lateral spread %.2e u0\n", D,
                axisymmetric ? " axisymmetric" : "",
                c.time.scheme == TimeScheme::Explicit ? "explicit" : "semi-implicit", worst, spread);
}
}  // namespace

TEST(Terzaghi, In2DAnd3DTheRowsFollowVerruijtAndStayLaterallyUniform) {
    // plane and 3D: points side by side agree to round-off (3.5e-16 u0 is achieved)
    checkTerzaghiInDimension<2>(4, 0.05, 0.01);
    checkTerzaghiInDimension<3>(2, 0.05, 0.01);
}

TEST(Terzaghi, AxisymmetricRowsFollowVerruijtAndStayLaterallyUniform) {
    // points side by side agree to round-off too (9.3e-16 u0 is achieved), since the grid
    // integrates over the rings as the points do (grid/Grid.hpp); with the exact integrals the
    // points at the axis settled 10 um differently
    checkTerzaghiInDimension<2>(4, 0.05, 0.01, true);
}

// The semi-implicit scheme (solver/SemiImplicitIntegrator.hpp) on the same problem and the same
// soft water: the same tolerance, its own guard near what it achieves.
TEST(Terzaghi, SemiImplicitSchemeFollowsVerruijtSolution) {
    checkTerzaghi(ShapeFunctionKind::Linear, 2, TimeScheme::SemiImplicit, 0.0075);
}
