// Free-surface detection, and the 2D/3D solvers running the same column as the verified 1D one.
#include <gtest/gtest.h>

#include <cmath>

#include "io/CaseLoader.hpp"
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
