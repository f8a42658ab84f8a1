#pragma once
// The pressure benchmarks' system (bench_pressure.cpp, bench_pressure_amg.cpp): a square (cube) of
// saturated sand (n = 0.4, real water K_L = 2.2 GPa, the drag locking the phases: beta = 1 / M, M
// the node's mixture mass) at the semi-implicit step of the Deltares sand (dt = 0.4 h / 28.6 m/s),
// assembled with the solver's own divergence weights (Grid::divergenceWeight) into
// PressureSystem's pattern, so its stencil and conditioning are the step's.
#include <cmath>

#include "grid/Grid.hpp"
#include "solver/PressureSystem.hpp"

namespace qs::bench {

template <int D>
void fillSandSystem(const Grid<D>& grid, PressureSystem& system, Eigen::VectorXd& b) {
    const double h = grid.h(), n = 0.4, K = 2.2e9, rho = 2000.0, dt = 0.4 * h / 28.6;
    const double V = std::pow(h, D);
    for (Index c = 0; c < grid.numCells(); ++c) {
        double* value = system.values(c);
        for (Index k = 0; k < system.size(c); ++k) value[k] = 0;
        grid.forEachNodeOfCell(c, [&](Index i, int corner) {
            int cellsOfNode = 0;
            grid.forEachCellOfNode(i, [&](Index, int) { ++cellsOfNode; });
            const double beta = 1 / (rho * V * cellsOfNode / (1 << D));
            for (int a = 0; a < D; ++a) {
                const double Dc = V * grid.divergenceWeight(c, corner, a);
                grid.forEachCellOfNode(i, [&](Index c2, int corner2) {
                    int offset[D];
                    for (int d = 0; d < D; ++d) offset[d] = ((corner >> d) & 1) - ((corner2 >> d) & 1);
                    value[system.slot(c, PressureSystem::offsetCode(offset, D))] +=
                        dt * dt * beta * (Dc * (V * grid.divergenceWeight(c2, corner2, a)));
                });
            }
        });
        const int centre[D] = {};
        value[system.slot(c, PressureSystem::offsetCode(centre, D))] += V * n / K;
        const IVec<D> cc = grid.cellCoords(c);
        b[c] = std::sin(0.37 * static_cast<double>(cc[0])) + 0.5 * std::cos(0.11 * static_cast<double>(cc[D - 1]));
    }
}

/// A square (cube) of n^D cells of 6.2 mm and its system, assembled for `solver`, with b.
template <int D>
struct SandSquare {
    Grid<D> grid;
    PressureSystem system;
    Eigen::VectorXd b;
    SandSquare(Index n, PressureSolver solver) : grid(cellsPerAxis(n), 0.0062, 0.005), b(grid.numCells()) {
        system.build(grid, solver);
        fillSandSystem(grid, system, b);
    }
    static IVec<D> cellsPerAxis(Index n) {
        IVec<D> cells;
        for (int d = 0; d < D; ++d) cells[d] = n;
        return cells;
    }
};

}  // namespace qs::bench
