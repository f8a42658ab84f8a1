// Free-surface detection, and the 2D/3D solvers running the same column as the verified 1D one.
#include <gtest/gtest.h>

#include <cmath>

#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;

namespace {
CaseConfig geostatic() {
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
}
}  // namespace

TEST(FreeSurface, OnlyPointsOfTheTopPartlyFilledCellAreFlagged) {
    CaseConfig c = geostatic();
    c.column.waterLevel = c.sandTop() + 0.5 * c.grid.cellSize;  // half a cell of water on the sand
    c.reservoir.head = c.column.waterLevel;
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    solver.step();
    const auto& l = solver.liquid();
    const double h = c.grid.cellSize;
    const long topCell = static_cast<long>(std::floor(c.sandTop() / h));  // the half-filled cell
    int flagged = 0;
    for (std::size_t p = 0; p < l.size(); ++p) {
        const long cell = static_cast<long>(std::floor(l.x[p] / h));
        if (cell == topCell) {
            EXPECT_EQ(l.state[p], kFreeSurfaceLiquid) << "z = " << l.x[p];
            ++flagged;
        } else {
            EXPECT_EQ(l.state[p], kSubmergedLiquid) << "z = " << l.x[p];
        }
    }
    EXPECT_GT(flagged, 0);
}

template <int D>
void checkGeostaticInDimension(double width) {
    CaseConfig c = geostatic();
    c.grid.dimension = D;
    c.grid.width = width;
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<D> solver(c, *reservoir);
    for (int k = 0; k < 2000; ++k) solver.step();
    // smooth walls and the same column: still hydrostatic and at rest
    const auto rows = solver.profile();
    const double g = c.gravity, rho = c.liquid.density;
    const double sBase = (1 - 0.38) * (2650 - rho) * g * 0.186;
    for (const auto& r : rows) {
        if (r.solidCount == 0) continue;
        EXPECT_NEAR(r.porePressure, rho * g * (c.column.waterLevel - r.z), 0.02 * rho * g * 0.186);
        EXPECT_NEAR(-r.verticalStress, sBase * (c.sandTop() - r.z) / 0.186, 0.02 * sBase);
    }
    for (double v : solver.liquid().v) EXPECT_LT(std::abs(v), 1e-6);
}

TEST(Dimensions, TwoDimensionalColumnStaysGeostatic) { checkGeostaticInDimension<2>(2 * 0.0093); }

TEST(Dimensions, ThreeDimensionalColumnStaysGeostatic) { checkGeostaticInDimension<3>(2 * 0.0093); }

// [initial.porosity_field]: the sand's points start at n0 + sigma g(x), clipped to
// [n_min, n_max - 0.001]; the same seed, the same bed; the liquid points carry n rho_L V.
TEST(PorosityField, A2DBedStartsAtTheFieldsPorosityReproduciblyFromTheSeed) {
    auto build = [](std::uint64_t seed, double sigma) {
        CaseConfig c = geostatic();
        c.grid.dimension = 2;
        c.grid.width = 0.0744;
        c.initial.porosityField = {true, sigma, 0.02, seed};
        auto reservoir = makeReservoirModel(c);
        DoublePointSolver<2> solver(c, *reservoir);
        return std::make_pair(solver.solid().porosity, solver.liquid().mass);
    };
    const auto [n7, m7] = build(7, 0.01);
    const auto [again, mAgain] = build(7, 0.01);
    const auto [n8, m8] = build(8, 0.01);
    EXPECT_EQ(n7, again);  // bit for bit
    EXPECT_EQ(m7, mAgain);
    EXPECT_NE(n7, n8);
    double mean = 0, var = 0, lo = 1, hi = 0;
    for (double n : n7) { mean += n; lo = std::min(lo, n); hi = std::max(hi, n); }
    mean /= n7.size();
    for (double n : n7) var += (n - mean) * (n - mean);
    const double sd = std::sqrt(var / n7.size());
    // 8 x 20 cells of 9.3 mm with l = 20 mm: only a few correlation lengths across, so the sample's
    // statistics scatter more than the field's (measured for seed 7, 640 points: mean 0.37994,
    // sd 0.00656, range 0.3603 .. 0.3944)
    EXPECT_NEAR(mean, 0.38, 0.002);
    EXPECT_GT(sd, 0.0045);  // sigma halved or doubled would fail
    EXPECT_LT(sd, 0.0095);
    EXPECT_GE(lo, 0.32);          // n_min of the geostatic sand
    EXPECT_LE(hi, 0.41 - 0.001);  // below n_max
    // a field of sigma 0 is the uniform bed
    const auto [uniform, mUniform] = build(7, 0.0);
    for (double n : uniform) EXPECT_EQ(n, 0.38);
}
