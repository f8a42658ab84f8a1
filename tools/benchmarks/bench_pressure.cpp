// The semi-implicit step's pressure solve on its own (solver/PressureSystem.hpp): factorise (or
// precondition) and solve the cells' system once, as each step does.
//
//   build/tools/benchmarks/quicksand_benchmarks --benchmark_filter=BM_Pressure
// BM_Pressure2D/<cells per axis>/<solver>, BM_Pressure3D/...: a square (cube) of n^D cells of
// 6.2 mm filled with saturated sand (n = 0.4, real water K_L = 2.2 GPa, the drag locking the
// phases: beta = 1 / M, M the node's mixture mass), at the semi-implicit step of the Deltares
// sand (dt = 0.4 h / 28.6 m/s). The matrix is assembled with the solver's own divergence weights
// (Grid::divergenceWeight), so its stencil and conditioning are the step's. solver 1: Eigen's
// SimplicialLDLT; 2: conjugate gradients with IncompleteCholesky. Counters: cells, iterations.
#include <benchmark/benchmark.h>

#include <cmath>

#include "grid/Grid.hpp"
#include "solver/PressureSystem.hpp"

namespace {

template <int D>
void fillSandSystem(const qs::Grid<D>& grid, qs::PressureSystem& system, Eigen::VectorXd& b) {
    const double h = grid.h(), n = 0.4, K = 2.2e9, rho = 2000.0, dt = 0.4 * h / 28.6;
    const double V = std::pow(h, D);
    for (qs::Index c = 0; c < grid.numCells(); ++c) {
        double* value = system.values(c);
        for (qs::Index k = 0; k < system.size(c); ++k) value[k] = 0;
        grid.forEachNodeOfCell(c, [&](qs::Index i, int corner) {
            int cellsOfNode = 0;
            grid.forEachCellOfNode(i, [&](qs::Index, int) { ++cellsOfNode; });
            const double beta = 1 / (rho * V * cellsOfNode / (1 << D));
            for (int a = 0; a < D; ++a) {
                const double Dc = V * grid.divergenceWeight(c, corner, a);
                grid.forEachCellOfNode(i, [&](qs::Index c2, int corner2) {
                    int offset[D];
                    for (int d = 0; d < D; ++d) offset[d] = ((corner >> d) & 1) - ((corner2 >> d) & 1);
                    value[system.slot(c, qs::PressureSystem::offsetCode(offset, D))] +=
                        dt * dt * beta * (Dc * (V * grid.divergenceWeight(c2, corner2, a)));
                });
            }
        });
        const int centre[D] = {};
        value[system.slot(c, qs::PressureSystem::offsetCode(centre, D))] += V * n / K;
        const qs::IVec<D> cc = grid.cellCoords(c);
        b[c] = std::sin(0.37 * static_cast<double>(cc[0])) + 0.5 * std::cos(0.11 * static_cast<double>(cc[D - 1]));
    }
}

template <int D>
void BM_Pressure(benchmark::State& state) {
    qs::IVec<D> cells;
    for (int d = 0; d < D; ++d) cells[d] = state.range(0);
    const qs::Grid<D> grid(cells, 0.0062, 0.005);
    qs::PressureSystem system;
    system.build(grid, state.range(1) == 1 ? qs::PressureSolver::Direct : qs::PressureSolver::ConjugateGradient);
    Eigen::VectorXd b(grid.numCells()), x(grid.numCells());
    fillSandSystem(grid, system, b);
    system.factorize();  // the direct solver's symbolic analysis, once per run
    for (auto _ : state) {
        system.factorize();
        if (!system.solve(b, x)) state.SkipWithError("the solve failed");
    }
    state.counters["cells"] = static_cast<double>(grid.numCells());
    state.counters["iterations"] = system.iterations();
    state.SetItemsProcessed(state.iterations() * grid.numCells());
}

}  // namespace

// 1e3 to 1e5 cells; the 3D direct solver only to 1e4 (its fill makes 1e5 minutes a solve)
BENCHMARK_TEMPLATE(BM_Pressure, 2)->Name("BM_Pressure2D")
    ->ArgsProduct({{32, 100, 316}, {1, 2}})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Pressure, 3)->Name("BM_Pressure3D")
    ->Args({10, 1})->Args({22, 1})->Args({10, 2})->Args({22, 2})->Args({46, 2})->Unit(benchmark::kMillisecond);
