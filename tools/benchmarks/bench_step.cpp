// Throughput of the double-point step (material-point updates per second).
//
//   build/tools/benchmarks/quicksand_benchmarks            (tools/benchmark.sh runs it and the
//                                                          longest verification case)
// BM_Step/<cells per metre>: one step of the coarse steady-seepage column (1D, rigid skeleton,
// inflow and outflow active) refined to the given cell size; items = points x steps.
#include <benchmark/benchmark.h>

#include <memory>

#include "io/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

namespace {

qs::CaseConfig benchmarkCase(double cellSize, bool rigid) {
    qs::CaseConfig c = qs::loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
    // keep the geometry a whole number of cells
    const double h = cellSize;
    c.grid.cellSize = h;
    c.column.chamberHeight = 2 * h;
    const int sandCells = static_cast<int>(0.186 / h + 0.5);
    c.layers.front().thickness = sandCells * h;
    c.column.waterLevel = c.column.chamberHeight + (sandCells + 2) * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 4 * h;
    c.reservoir.head = c.column.waterLevel + 0.1;
    c.reservoir.headRate = 0;
    c.initial.rigidSkeleton = rigid;
    return c;
}

void BM_Step(benchmark::State& state) {
    const double h = 1.0 / state.range(0);
    const qs::CaseConfig c = benchmarkCase(h, state.range(1) != 0);
    auto reservoir = qs::makeReservoirModel(c);
    qs::DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 100; ++k) solver.step();  // past the start-up transient
    std::size_t points = 0;
    for (auto _ : state) {
        solver.step();
        points += solver.solid().size() + solver.liquid().size();
    }
    state.SetItemsProcessed(static_cast<int64_t>(points));
    state.counters["points"] = static_cast<double>(solver.solid().size() + solver.liquid().size());
}
BENCHMARK(BM_Step)->ArgsProduct({{108, 1075, 10753}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
