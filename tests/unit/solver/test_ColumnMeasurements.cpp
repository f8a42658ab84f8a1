// What series.csv reads of a column with grains in its free water: the water's surface and the
// bed's hydraulic gradient must not follow the highest grain. In piping3D (2026-12-06) a boil's
// plume carried grains to the rim: the water surface, reckoned from the water above the highest
// grain, read 0, and the gradient, fitted up to the highest grain, took in rows of free water
// and read 0.92 while the bed carried its critical gradient.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "case/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;

namespace {

enum class Shape { Plane2D, Axisymmetric, ThreeD };

/// The geostatic column two cells wide (in 3D two by two), in steady upward seepage (the bed
/// carries i = 0.22), under four cells of water
CaseConfig seepingColumn(Shape shape) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
    const double h = c.grid.cellSize;
    c.grid.dimension = shape == Shape::ThreeD ? 3 : 2;
    if (shape == Shape::Axisymmetric) c.grid.geometry = GridGeometry::Axisymmetric;
    c.grid.width = 2 * h;
    c.column.waterLevel = c.sandTop() + 4 * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.sandTop() + 6 * h;
    c.reservoir.head = c.column.waterLevel;
    c.initial.filterVelocity = 3.6e-4;  // m/s
    return c;
}

/// The column's series after one step, with its highest solid point (the last of the highest: by
/// the wall, or at the axis's far side) first moved `lift` (m) up, into the free water (0: left
/// where it is). It stands alone over one column of cells: the column is no longer uniform.
template <int D>
ColumnState afterOneStep(Shape shape, double lift) {
    const CaseConfig c = seepingColumn(shape);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<D> solver(c, *reservoir);
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> x = data.doubles("solid/position");
    std::size_t top = 0;
    for (std::size_t p = 0; p < x.size() / D; ++p)
        if (x[p * D + D - 1] >= x[top * D + D - 1]) top = p;
    x[top * D + D - 1] += lift;
    data.put("solid/position", x);
    solver.loadState(data);
    solver.step();
    return solver.columnState();
}

template <int D>
void checkAGrainInTheFreeWater(Shape shape) {
    const CaseConfig c = seepingColumn(shape);
    const double h = c.grid.cellSize;
    const ColumnState still = afterOneStep<D>(shape, 0.0);
    const ColumnState lifted = afterOneStep<D>(shape, 3 * h);  // a cell under the water's surface
    ASSERT_GT(lifted.sandSurface, c.sandTop() + 2.5 * h) << "the grain was not lifted";
    // the surface: the water's level, whatever the grains do
    EXPECT_NEAR(still.waterSurface, c.column.waterLevel, 1e-4);
    EXPECT_NEAR(lifted.waterSurface, still.waterSurface, 1e-9);
    // the gradient: the bed's (0.22), within a thousandth
    EXPECT_GT(still.gradient, 0.15);
    EXPECT_NEAR(lifted.gradient, still.gradient, 1e-3 * still.gradient);
    std::printf("water surface %.6f m (water level %.6f m), lifted %.6f m; gradient %.5f, lifted %.5f\n",
                still.waterSurface, c.column.waterLevel, lifted.waterSurface, still.gradient, lifted.gradient);
}

}  // namespace

TEST(ColumnMeasurements, AGrainInTheFreeWaterMovesNeitherTheWaterSurfaceNorTheBedsGradient) {
    checkAGrainInTheFreeWater<2>(Shape::Plane2D);
}

TEST(ColumnMeasurements, AGrainInTheFreeWaterMovesNeitherInAxisymmetry) {
    checkAGrainInTheFreeWater<2>(Shape::Axisymmetric);
}

TEST(ColumnMeasurements, AGrainInTheFreeWaterMovesNeitherIn3D) { checkAGrainInTheFreeWater<3>(Shape::ThreeD); }
