// The semi-implicit step's pressure solve on its own (solver/PressureSystem.hpp): factorise (or
// precondition) and solve the cells' system once, as each step does.
//
//   build/tools/benchmarks/quicksand_benchmarks --benchmark_filter=BM_Pressure
// BM_Pressure2D/<cells per axis>/<solver>, BM_Pressure3D/...: a square (cube) of n^D cells of
// 6.2 mm filled with saturated sand (n = 0.4, real water K_L = 2.2 GPa, the drag locking the
// phases: beta = 1 / M, M the node's mixture mass), at the semi-implicit step of the Deltares
// sand (dt = 0.4 h / 28.6 m/s). The matrix is assembled with the solver's own divergence weights
// (Grid::divergenceWeight), so its stencil and conditioning are the step's. solver 1: Eigen's
// SimplicialLDLT (in 2D from 1 024 cells in two slabs side by side, solver/SlabCholesky.hpp);
// 2: conjugate gradients with IncompleteCholesky. Counters: cells, iterations.
//
// BM_SlabCholesky/<cells across>/<cells high>/<slabs>: the direct solve alone on the same sand
// in a column of cells (26 x 98: piping2D on 3.1 mm cells), in one slab or split into two
// factorised side by side, with OpenMP's threads as set (OMP_NUM_THREADS=1 or 2). Counter:
// operations, the larger slab's sum of squared column counts of its factor.
//
// BM_Column1D/<cells>/<solver>: a 1D column's factorisation and one solve (the Deltares column
// has 27 cells on 9.3 mm); solver 0: the step's, LAPACK's tridiagonal dpttrf/dpttrs
// (solver/TridiagonalCholesky.hpp); 1: Eigen's SimplicialLDLT in the matrix's own order (1D used
// it before, through SlabCholesky with an AMD order, which for a tridiagonal matrix is no faster).
#include <benchmark/benchmark.h>

#include <Eigen/SparseCholesky>

#include "SandSystem.hpp"

namespace {

template <int D>
void BM_Pressure(benchmark::State& state) {
    qs::bench::SandSquare<D> square(state.range(0), state.range(1) == 1 ? qs::PressureSolver::Direct
                                                                        : qs::PressureSolver::ConjugateGradient);
    const qs::Grid<D>& grid = square.grid;
    qs::PressureSystem& system = square.system;
    const Eigen::VectorXd& b = square.b;
    Eigen::VectorXd x(grid.numCells());
    system.factorize();  // the direct solver's symbolic analysis, once per run
    for (auto _ : state) {
        system.factorize();
        x.setZero();  // CG from zero: the step's first solve, without a last step's to start from
        if (!system.solve(b, x)) state.SkipWithError("the solve failed");
    }
    state.counters["cells"] = static_cast<double>(grid.numCells());
    state.counters["iterations"] = system.iterations();
    state.SetItemsProcessed(state.iterations() * grid.numCells());
}

void BM_SlabCholesky(benchmark::State& state) {
    const qs::Grid<2> grid(qs::IVec<2>{state.range(0), state.range(1)}, 0.0031, 0.005);
    qs::PressureSystem system;
    system.build(grid, qs::PressureSolver::Direct);
    Eigen::VectorXd b(grid.numCells()), x(grid.numCells());
    qs::bench::fillSandSystem(grid, system, b);
    std::vector<int> layer(grid.numCells());
    for (qs::Index c = 0; c < grid.numCells(); ++c) layer[c] = static_cast<int>(grid.cellCoords(c)[1]);
    qs::SlabCholesky cholesky;
    cholesky.analyse(system.matrix(), layer, static_cast<int>(grid.cells(1)), static_cast<int>(state.range(2)));
    for (auto _ : state) {
        if (!cholesky.factorize(system.matrix())) state.SkipWithError("the factorisation failed");
        cholesky.solve(b, x);
    }
    state.counters["slabs"] = cholesky.slabs();
    state.counters["operations"] = cholesky.largestSlabOperations();
    state.SetItemsProcessed(state.iterations() * grid.numCells());
}

void BM_Column1D(benchmark::State& state) {
    const qs::Grid<1> grid(qs::IVec<1>{state.range(0)}, 0.0093, 1.0);
    qs::PressureSystem system;
    system.build(grid, qs::PressureSolver::Direct);
    Eigen::VectorXd b(grid.numCells()), x(grid.numCells());
    qs::bench::fillSandSystem(grid, system, b);
    if (state.range(1) == 0) {
        for (auto _ : state) {
            if (!system.factorize()) { state.SkipWithError("the factorisation failed"); break; }
            system.solve(b, x);
            benchmark::DoNotOptimize(x.data());
        }
    } else {
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>> eigen;
        eigen.analyzePattern(system.matrix());
        for (auto _ : state) {
            eigen.factorize(system.matrix());
            if (eigen.info() != Eigen::Success) { state.SkipWithError("the factorisation failed"); break; }
            x = eigen.solve(b);
            benchmark::DoNotOptimize(x.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * grid.numCells());
}

}  // namespace

BENCHMARK(BM_Column1D)->ArgsProduct({{27, 270}, {0, 1}})->Unit(benchmark::kNanosecond);
BENCHMARK(BM_SlabCholesky)->ArgsProduct({{26}, {98}, {1, 2}})->Args({100, 100, 1})->Args({100, 100, 2})
    ->Unit(benchmark::kMillisecond);

// 1e3 to 1e5 cells; the 3D direct solver only to 1e4 (its fill makes 1e5 minutes a solve)
BENCHMARK_TEMPLATE(BM_Pressure, 2)->Name("BM_Pressure2D")
    ->ArgsProduct({{32, 100, 316}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Pressure, 3)->Name("BM_Pressure3D")
    ->Args({10, 1})->Args({22, 1})->Args({10, 2})->Args({22, 2})->Args({46, 2})->Unit(benchmark::kMillisecond);
