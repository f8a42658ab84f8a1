// The semi-implicit step's linear system on the cells (solver/PressureSystem.hpp): its fixed
// pattern, and Eigen's two solvers on a system whose solution is known.
#include "solver/PressureSystem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace qs {
namespace {

// Each column holds exactly the cell and its in-grid neighbours, and slot() finds each of them
TEST(PressureSystem, ThePatternHoldsEachCellsNeighboursAndSlotFindsThem) {
    const Grid<2> grid(IVec<2>{4, 3}, 0.01, 1.0);
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    for (Index c = 0; c < grid.numCells(); ++c) {
        const IVec<2> cc = grid.cellCoords(c);
        int expected = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const IVec<2> n{cc[0] + dx, cc[1] + dy};
                const int offset[2] = {dx, dy};
                const int slot = system.slot(c, PressureSystem::offsetCode(offset, 2));
                if (n[0] < 0 || n[0] >= 4 || n[1] < 0 || n[1] >= 3) {
                    EXPECT_EQ(slot, -1);
                    continue;
                }
                ++expected;
                ASSERT_GE(slot, 0);
                EXPECT_EQ(system.rows(c)[slot], grid.cellIndex(n));
            }
        EXPECT_EQ(system.size(c), expected);
    }
}

// A 2D Poisson problem with storage, (s I + L) x = b, L the 5-point Laplacian (Dirichlet outside):
// both solvers reproduce a chosen x to the solver's tolerance, with the same matrix values
// written again for a second factorisation (the pattern analysed once)
TEST(PressureSystem, BothSolversSolveAKnownSystem) {
    const Grid<2> grid(IVec<2>{30, 20}, 0.01, 1.0);
    const Index nc = grid.numCells();
    Eigen::VectorXd x(nc), b(nc), y(nc);
    for (Index c = 0; c < nc; ++c) {
        const IVec<2> cc = grid.cellCoords(c);
        x[c] = std::sin(0.3 * cc[0]) * std::cos(0.2 * cc[1]) + 0.1 * cc[1];
    }
    for (auto solver : {PressureSolver::Direct, PressureSolver::ConjugateGradient}) {
        PressureSystem system;
        system.build(grid, solver);
        EXPECT_EQ(system.direct(), solver == PressureSolver::Direct);
        for (int round = 0; round < 2; ++round) {
            const double s = round == 0 ? 1e-3 : 0.5;
            for (Index c = 0; c < nc; ++c) {
                double* v = system.values(c);
                for (Index k = 0; k < system.size(c); ++k) v[k] = 0;
                const IVec<2> cc = grid.cellCoords(c);
                const int centre[2] = {0, 0};
                v[system.slot(c, PressureSystem::offsetCode(centre, 2))] = s + 4;
                double Ax = (s + 4) * x[c];
                for (int a = 0; a < 2; ++a)
                    for (int side : {-1, 1}) {
                        int offset[2] = {0, 0};
                        offset[a] = side;
                        IVec<2> n = cc;
                        n[a] += side;
                        if (n[a] < 0 || n[a] >= grid.cells(a)) continue;
                        v[system.slot(c, PressureSystem::offsetCode(offset, 2))] = -1;
                        Ax -= x[grid.cellIndex(n)];
                    }
                b[c] = Ax;
            }
            ASSERT_TRUE(system.factorize());
            y.setZero();  // CG's guess
            ASSERT_TRUE(system.solve(b, y));
            EXPECT_LT((y - x).norm() / x.norm(), 1e-8) << (solver == PressureSolver::Direct ? "direct" : "CG")
                                                        << ", storage " << s;
            if (solver == PressureSolver::ConjugateGradient) {
                EXPECT_GT(system.iterations(), 0);
                EXPECT_LE(system.error(), PressureSystem::kTolerance);
            }
        }
    }
}

// A matrix that is not positive definite is refused, not solved into nonsense; a right-hand
// side with a NaN is reported
TEST(PressureSystem, AFailedFactorisationOrANonFiniteSolutionIsReported) {
    const Grid<1> grid(IVec<1>{10}, 0.01, 1.0);
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    for (Index c = 0; c < grid.numCells(); ++c) {
        double* v = system.values(c);
        for (Index k = 0; k < system.size(c); ++k) v[k] = 0;
        const int centre[1] = {0};
        v[system.slot(c, PressureSystem::offsetCode(centre, 1))] = c == 4 ? -1.0 : 1.0;  // a negative pivot
    }
    EXPECT_FALSE(system.factorize());
    for (Index c = 0; c < grid.numCells(); ++c) {
        const int centre[1] = {0};
        system.values(c)[system.slot(c, PressureSystem::offsetCode(centre, 1))] = 1.0;
    }
    ASSERT_TRUE(system.factorize());
    Eigen::VectorXd b = Eigen::VectorXd::Ones(grid.numCells()), x = Eigen::VectorXd::Zero(grid.numCells());
    EXPECT_TRUE(system.solve(b, x));
    b[3] = std::nan("");
    EXPECT_FALSE(system.solve(b, x));
}

// The direct solve is split in slabs in 2D from kMinParallelItems cells, not in 1D, 3D or CG
TEST(PressureSystem, TheDirectSolveIsSplitInSlabsIn2DFromAThousandCells) {
    auto slabsOf = [](const auto& grid, PressureSolver solver) {
        PressureSystem system;
        system.build(grid, solver);
        return system.slabs();
    };
    EXPECT_EQ(slabsOf(Grid<2>(IVec<2>{26, 98}, 0.0031, 1.0), PressureSolver::Direct), PressureSystem::kSlabs);
    EXPECT_EQ(slabsOf(Grid<2>(IVec<2>{26, 39}, 0.0031, 1.0), PressureSolver::Direct), 1);  // 1 014 cells
    EXPECT_EQ(slabsOf(Grid<2>(IVec<2>{26, 98}, 0.0031, 1.0), PressureSolver::ConjugateGradient), 1);
    EXPECT_EQ(slabsOf(Grid<1>(IVec<1>{2000}, 0.0031, 1.0), PressureSolver::Direct), 1);
    EXPECT_EQ(slabsOf(Grid<3>(IVec<3>{10, 10, 19}, 0.0062, 1.0), PressureSolver::Direct), 1);
}

}  // namespace
// The 1D direct solve is LAPACK's tridiagonal one (TridiagonalCholesky); 2D and 3D keep Eigen's
TEST(PressureSystem, The1DDirectSolveIsTridiagonal) {
    auto nameOf = [](const auto& grid, PressureSolver solver) {
        PressureSystem system;
        system.build(grid, solver);
        return std::string(system.solverName());
    };
    EXPECT_NE(nameOf(Grid<1>(IVec<1>{27}, 0.0093, 1.0), PressureSolver::Direct).find("tridiagonal"), std::string::npos);
    EXPECT_NE(nameOf(Grid<1>(IVec<1>{27}, 0.0093, 1.0), PressureSolver::Automatic).find("tridiagonal"), std::string::npos);
    EXPECT_EQ(nameOf(Grid<1>(IVec<1>{27}, 0.0093, 1.0), PressureSolver::ConjugateGradient).find("tridiagonal"),
              std::string::npos);
    EXPECT_EQ(nameOf(Grid<2>(IVec<2>{9, 27}, 0.0093, 1.0), PressureSolver::Direct).find("tridiagonal"), std::string::npos);
    // and it is what solves: the same bits as TridiagonalCholesky called on the matrix itself
    const Grid<1> column(IVec<1>{27}, 0.0093, 1.0);
    PressureSystem system;
    system.build(column, PressureSolver::Direct);
    for (Index c = 0; c < column.numCells(); ++c) {
        double* v = system.values(c);
        for (Index k = 0; k < system.size(c); ++k) v[k] = (system.rows(c)[k] == c ? 2.5 + 0.1 * c : -1.0);
    }
    ASSERT_TRUE(system.factorize());
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(27, -1.0, 3.0), x(27), y(27);
    ASSERT_TRUE(system.solve(b, x));
    TridiagonalCholesky ldlt;
    ldlt.analyse(system.matrix());
    ASSERT_TRUE(ldlt.factorize(system.matrix()));
    ldlt.solve(b, y);
    for (Index c = 0; c < 27; ++c) EXPECT_EQ(x[c], y[c]) << "cell " << c;
}

}  // namespace qs
