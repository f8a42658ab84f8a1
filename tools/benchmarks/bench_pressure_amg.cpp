// The pressure solve with hypre's algebraic multigrid (Debian's libhypre-dev), against Eigen's
// solvers in bench_pressure.cpp on the same system (SandSystem.hpp): conjugate gradients
// preconditioned by one BoomerAMG V-cycle, to the same relative residual (PressureSystem's
// kTolerance), through the class the step will use over MPI ranks (DistributedPressureSolver).
// Built only where hypre is found; on one rank the step does not use it (docs/performance.md,
// "The pressure solve alone", says why).
//
//   build/tools/benchmarks/quicksand_benchmarks --benchmark_filter=BM_PressureAMG
// BM_PressureAMG2D/<cells per axis>/<setup>, BM_PressureAMG3D/...:
//   setup 1: each iteration copies the values into hypre's matrix, builds the AMG hierarchy and
//            solves, what a step whose matrix changes would do;
//   setup 0: the hierarchy is built once and only the solve is timed (the bound for a
//            preconditioner kept over several steps).
// Counters: cells, iterations. One MPI rank (the benchmarks' main initialises MPI).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "SandSystem.hpp"
#include "core/Error.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedPressureSolver.hpp"

namespace {

/// PressureSystem's matrix as this rank's rows in compressed sparse rows (its columns are its
/// rows: the matrix is symmetric), for DistributedPressureSolver.
struct RowsOf {
    std::vector<qs::Index> start, columns;
    std::vector<double> values;
    void load(qs::PressureSystem& system, qs::Index n) {
        start.assign(1, 0);
        columns.clear();
        values.clear();
        for (qs::Index c = 0; c < n; ++c) {
            for (qs::Index k = 0; k < system.size(c); ++k) {
                columns.push_back(system.rows(c)[k]);
                values.push_back(system.values(c)[k]);
            }
            start.push_back(static_cast<qs::Index>(columns.size()));
        }
    }
};

/// The distributed solve the step takes over ranks (parallel/DistributedPressureSolver.hpp), on
/// one rank: CG with one BoomerAMG V-cycle, to PressureSystem's tolerance.
template <int D>
void BM_PressureAMG(benchmark::State& state) {
    qs::bench::SandSquare<D> square(state.range(0), qs::PressureSolver::ConjugateGradient);
    const qs::Grid<D>& grid = square.grid;
    const qs::Index n = grid.numCells();
    const bool everyStep = state.range(1) == 1;
    RowsOf rows;
    rows.load(square.system, n);
    qs::DistributedPressureSolver solver(qs::Communicator::world(), 0, n, D);
    solver.setMatrix(rows.start, rows.columns, rows.values);
    const std::vector<double> b(square.b.data(), square.b.data() + n);
    std::vector<double> x(static_cast<std::size_t>(n), 0.0);
    int iterations = 0;
    for (auto _ : state) {
        if (everyStep) {  // the values copied in and the hierarchy built again, as a changed matrix needs
            rows.load(square.system, n);
            solver.setMatrix(rows.start, rows.columns, rows.values);
        }
        std::fill(x.begin(), x.end(), 0.0);
        try {
            iterations = solver.solve(b, x, qs::PressureSystem::kTolerance);
        } catch (const qs::Error& e) {
            state.SkipWithError(e.what());
            break;
        }
    }
    state.counters["cells"] = static_cast<double>(n);
    state.counters["iterations"] = iterations;
    state.SetItemsProcessed(state.iterations() * n);
}

}  // namespace

// the sizes of BM_Pressure2D/3D, and 1e6 cells, where Eigen's solvers are out of reach
BENCHMARK_TEMPLATE(BM_PressureAMG, 2)->Name("BM_PressureAMG2D")
    ->ArgsProduct({{32, 100, 316, 1000}, {1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PressureAMG, 3)->Name("BM_PressureAMG3D")
    ->ArgsProduct({{10, 22, 46, 100}, {1, 0}})->Unit(benchmark::kMillisecond);
