// The step is deterministic: OpenMP with 1 and 2 threads gives bit-identical results
// (coloured scatter in sorted point order, gathers elsewhere; see solver/Parallel.hpp).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

using namespace qs;

namespace {

struct Snapshot {
    std::vector<double> solidX, solidStress, liquidX, liquidV, liquidP;
    double flux;
};

Snapshot runWithThreads(int threads, ShapeFunctionKind shape) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
    c.grid.shapeFunctions = shape;
    // fine enough that every loop runs in parallel: more nodes, cells and points of each set
    // than kMinParallelItems, more slabs per colour than kMinParallelSlabs
    const double h = 0.186 / 4200;
    c.grid.cellSize = h;
    c.column.chamberHeight = 12 * h;
    c.layers.front().thickness = 4200 * h;
    c.column.waterLevel = c.column.chamberHeight + 4212 * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 24 * h;
    c.reservoir.head = c.column.waterLevel;
    c.reservoir.headRate = 200.0;  // flow right away: inflow, drag and heave all active
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    EXPECT_GT(solver.grid().numNodes(), kMinParallelItems);
    EXPECT_GT(static_cast<Index>(solver.solid().size()), kMinParallelItems);
    EXPECT_GT(static_cast<Index>(solver.liquid().size()), kMinParallelItems);
    for (int k = 0; k < 300; ++k) solver.step();
    omp_set_num_threads(before);
    return {solver.solid().x, solver.solid().stress, solver.liquid().x, solver.liquid().v,
            solver.liquid().pressure, solver.columnState().gateFlux};
}

/// The flow is on, and both runs end in the same state, bit for bit.
void expectIdentical(const Snapshot& a, const Snapshot& b) {
    EXPECT_NE(a.flux, 0.0);
    EXPECT_EQ(a.solidX, b.solidX);
    EXPECT_EQ(a.solidStress, b.solidStress);
    EXPECT_EQ(a.liquidX, b.liquidX);
    EXPECT_EQ(a.liquidV, b.liquidV);
    EXPECT_EQ(a.liquidP, b.liquidP);
    EXPECT_EQ(a.flux, b.flux);
}

}  // namespace

TEST(Determinism, OneAndTwoThreadsGiveIdenticalResults) {
    for (auto shape : {ShapeFunctionKind::Linear, ShapeFunctionKind::Gimp}) {
        SCOPED_TRACE(shape == ShapeFunctionKind::Gimp ? "gimp" : "linear");
        expectIdentical(runWithThreads(1, shape), runWithThreads(2, shape));
    }
}

namespace {

/// The critical-gradient column in 2D or 3D with a random porosity field (so that the flow is
/// not laterally uniform), the head rising: every coloured scatter and every loop over nodes,
/// cells and points large enough to run in parallel.
template <int D>
Snapshot lateralRunWithThreads(int threads, double h, int across, int steps,
                               TimeScheme scheme = TimeScheme::Explicit,
                               PressureSolver pressureSolver = PressureSolver::Automatic) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
    c.time.scheme = scheme;
    c.time.pressureSolver = pressureSolver;
    const int sandCells = static_cast<int>(std::lround(0.186 / h));
    c.grid.dimension = D;
    c.grid.cellSize = h;
    c.grid.width = across * h;
    if (D == 3) c.grid.crossSectionArea = c.grid.width * c.grid.width;
    c.column.chamberHeight = 2 * h;
    c.layers.front().thickness = sandCells * h;
    c.column.waterLevel = c.column.chamberHeight + (sandCells + 2) * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 2 * h;
    c.reservoir.head = c.column.waterLevel;
    c.reservoir.headRate = 200.0;
    c.initial.porosityField = {true, 0.01, 4 * h, 3};
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<D> solver(c, *reservoir);
    // the uGIMP scatter's slabs, the thicker ones, two colours
    EXPECT_GE(solver.grid().cells(D - 1) / slabRows(false), 2 * kMinParallelSlabs);
    EXPECT_GT(solver.grid().numCells(), kMinParallelItems);
    EXPECT_GT(static_cast<Index>(solver.solid().size()), kMinParallelItems);
    for (int k = 0; k < steps; ++k) solver.step();
    omp_set_num_threads(before);
    return {solver.solid().x, solver.solid().stress, solver.liquid().x, solver.liquid().v,
            solver.liquid().pressure, solver.columnState().gateFlux};
}

}  // namespace

TEST(Determinism, OneAndTwoThreadsGiveIdenticalResultsIn2DAnd3D) {
    {
        SCOPED_TRACE("2D, 96 x 46 cells");
        expectIdentical(lateralRunWithThreads<2>(1, 0.00465, 96, 100), lateralRunWithThreads<2>(2, 0.00465, 96, 100));
    }
    {
        SCOPED_TRACE("3D, 13 x 13 x 26 cells");
        expectIdentical(lateralRunWithThreads<3>(1, 0.0093, 13, 40), lateralRunWithThreads<3>(2, 0.0093, 13, 40));
    }
}

// The semi-implicit step: its assembly per cell, its correction per node and both solvers keep
// the results independent of the threads: CG is serial (a column-major matrix's products are not
// threaded), and the direct solve's two slabs (96 x 46 cells: split along x) do the same
// arithmetic whichever thread takes them.
TEST(Determinism, OneAndTwoThreadsGiveIdenticalResultsWithTheSemiImplicitStep) {
    for (auto solver : {PressureSolver::Direct, PressureSolver::ConjugateGradient}) {
        SCOPED_TRACE(solver == PressureSolver::Direct ? "direct" : "conjugate gradients");
        const auto semi = TimeScheme::SemiImplicit;
        {
            SCOPED_TRACE("2D, 96 x 46 cells");
            expectIdentical(lateralRunWithThreads<2>(1, 0.00465, 96, 60, semi, solver),
                            lateralRunWithThreads<2>(2, 0.00465, 96, 60, semi, solver));
        }
        {
            SCOPED_TRACE("3D, 13 x 13 x 26 cells");
            expectIdentical(lateralRunWithThreads<3>(1, 0.0093, 13, 20, semi, solver),
                            lateralRunWithThreads<3>(2, 0.0093, 13, 20, semi, solver));
        }
    }
}
