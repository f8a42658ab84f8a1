// RunSize: what `quicksand check` says a run will take, against what the solver really builds.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "reservoir/ConstantHead.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/RunSize.hpp"

using namespace qs;

namespace {
CaseConfig shipped(const std::string& name) {
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/" + name);
}

template <int D>
void expectCountsOfTheSolver(const CaseConfig& c) {
    const RunSize r = estimateRunSize(c);
    ConstantHead reservoir(c.liquid.density, c.gravity, c.reservoir.head);
    DoublePointSolver<D> solver(c, reservoir);
    EXPECT_EQ(r.cells, solver.grid().numCells());
    EXPECT_EQ(r.nodes, solver.grid().numNodes());
    EXPECT_EQ(r.solidPoints, static_cast<std::int64_t>(solver.solid().size()));
    EXPECT_EQ(r.liquidPoints, static_cast<std::int64_t>(solver.liquid().size()));
    EXPECT_DOUBLE_EQ(r.dt, solver.dt());
}
}  // namespace

TEST(RunSize, PointCountsAndStepAreThoseOfTheSolver1D) {
    expectCountsOfTheSolver<1>(shipped("verification/geostatic"));
    expectCountsOfTheSolver<1>(shipped("deltaresColumnLumped"));
}

TEST(RunSize, PointCountsAndStepAreThoseOfTheSolver2DAnd3D) {
    CaseConfig c = shipped("verification/geostatic");
    c.grid.width = 4 * c.grid.cellSize;
    c.grid.dimension = 2;
    expectCountsOfTheSolver<2>(c);
    c.grid.dimension = 3;
    expectCountsOfTheSolver<3>(c);
}

TEST(RunSize, StepsAndMemoryScaleWithTheGrid) {
    CaseConfig c = shipped("verification/geostatic");
    const RunSize coarse = estimateRunSize(c);
    c.grid.cellSize /= 2;
    const RunSize fine = estimateRunSize(c);
    // 1D: twice the points, half the step
    EXPECT_NEAR(double(fine.solidPoints) / coarse.solidPoints, 2.0, 1e-12);
    EXPECT_NEAR(double(fine.steps) / coarse.steps, 2.0, 0.01);
    EXPECT_NEAR(fine.peakBytes / coarse.peakBytes, 2.0, 0.05);
    EXPECT_NEAR(fine.wallSeconds / coarse.wallSeconds, 4.0, 0.05);
}

TEST(RunSize, ACaseBeyondTheMachinesMemoryIsRefusedWithTheNumbers) {
    CaseConfig c = shipped("verification/geostatic");
    c.grid.cellSize = 1e-7;
    const RunSize r = estimateRunSize(c);
    MachineMemory small;
    small.total = 1e9;
    try {
        requireFitsMachine(c, r, small);
        FAIL() << "a run of " << r.peakBytes << " bytes fitted 1 GB";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("grid.cell_size"), std::string::npos) << what;
        EXPECT_NE(what.find(std::to_string(r.cells) + " cells"), std::string::npos) << what;
        EXPECT_NE(what.find("does not fit"), std::string::npos) << what;
    }
    MachineMemory big;
    big.total = 2 * r.peakBytes;
    EXPECT_NO_THROW(requireFitsMachine(c, r, big));
}

// Found by fuzzing the case loader: a bulk modulus typed as 1e70 Pa gives a step of 1e-38 s,
// and the step count (1e37) overflowed the integer it was converted to (undefined behaviour).
// Counts beyond int64 now saturate; the estimate still says the run would never end.
TEST(RunSize, AnAbsurdStepCountSaturatesInsteadOfOverflowing) {
    CaseConfig c = shipped("verification/geostatic");
    c.liquid.bulkModulus = 1e70;
    const RunSize r = estimateRunSize(c);
    EXPECT_EQ(r.steps, std::int64_t(9.0e18));
    EXPECT_GT(r.wallSeconds, 1e13);  // from the saturated count: still millions of years
}
