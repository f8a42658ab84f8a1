// The 1D column's tridiagonal pressure solve (solver/TridiagonalCholesky.hpp, LAPACK's dpttrf)
// against Eigen's sparse Cholesky on the step's kind of matrix.
#include "solver/TridiagonalCholesky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/SparseCholesky>

#include "core/Error.hpp"
#include "solver/PressureSystem.hpp"

namespace qs {
namespace {

// The semi-implicit step's matrix S + D B D^T of a 1D column (as SemiImplicitIntegrator
// assembles it): each node's response beta drawn at random over two decades, a storage s per
// cell, and every `heldEvery`-th cell and the last an identity row its neighbours do not see.
Eigen::SparseMatrix<double> columnMatrix(Index cells, double storage, int heldEvery, unsigned seed) {
    const Grid<1> grid(IVec<1>{cells}, 0.0093, 1.0);
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> decades(0.0, 2.0);
    std::vector<double> beta(grid.numNodes());
    for (auto& b : beta) b = std::pow(10.0, decades(random));
    auto held = [&](Index c) { return heldEvery > 0 && (c % heldEvery == 0 || c == cells - 1); };
    for (Index c = 0; c < cells; ++c) {
        double* value = system.values(c);
        for (Index k = 0; k < system.size(c); ++k) value[k] = 0;
        const int centre[1] = {0};
        const int diagonal = system.slot(c, PressureSystem::offsetCode(centre, 1));
        if (held(c)) { value[diagonal] = 1; continue; }
        grid.forEachNodeOfCell(c, [&](Index i, int corner) {
            const double Dc = grid.divergenceWeight(c, corner, 0);
            grid.forEachCellOfNode(i, [&](Index c2, int corner2) {
                if (held(c2)) return;
                const int offset[1] = {(corner & 1) - (corner2 & 1)};
                value[system.slot(c, PressureSystem::offsetCode(offset, 1))] +=
                    beta[i] * Dc * grid.divergenceWeight(c2, corner2, 0);
            });
        });
        value[diagonal] += storage;
    }
    return system.matrix();
}

// The residual |A x - b| / |b| over Eigen's SimplicialLDLT's own, with another matrix of the
// same pattern factorised and solved first (as the step uses it: nothing of it may remain)
double errorAgainstEigen(Index cells, double storage, int heldEvery) {
    const Eigen::SparseMatrix<double> A = columnMatrix(cells, storage, heldEvery, 11);
    const Eigen::SparseMatrix<double> other = columnMatrix(cells, 10 * storage + 1, 0, 12);
    TridiagonalCholesky ldlt;
    ldlt.analyse(A);
    Eigen::VectorXd b(cells), x;
    for (Index c = 0; c < cells; ++c) b[c] = std::sin(0.37 * c) + 0.5;
    EXPECT_TRUE(ldlt.factorize(other));
    ldlt.solve(Eigen::VectorXd::Constant(cells, 3.0), x);
    EXPECT_TRUE(ldlt.factorize(A));
    ldlt.solve(b, x);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> eigen(A);
    EXPECT_EQ(eigen.info(), Eigen::Success);
    const Eigen::VectorXd reference = eigen.solve(b);
    EXPECT_LT((x - reference).norm(), 1e-6 * reference.norm());
    return (A * x - b).norm() / std::max((A * reference - b).norm(), 1e-16 * b.norm());
}

}  // namespace

// Soft water (storage 1e-3 of the coupling) and real water (1e-7), with and without held cells,
// a short column and a long one: the residual within twice Eigen's (achieved: 0 to 1.54)
TEST(TridiagonalCholesky, AgreesWithEigensCholesky) {
    for (Index cells : {2, 27, 400})
        for (double storage : {1e-3, 1e-7})
            for (int heldEvery : {0, 5}) {
                SCOPED_TRACE(testing::Message() << cells << " cells, storage " << storage << ", held every " << heldEvery);
                EXPECT_LT(errorAgainstEigen(cells, storage, heldEvery), 2.0);
            }
}

// b may be x: the solve works in place
TEST(TridiagonalCholesky, SolvesInPlace) {
    const Eigen::SparseMatrix<double> A = columnMatrix(27, 1e-3, 0, 5);
    TridiagonalCholesky ldlt;
    ldlt.analyse(A);
    ASSERT_TRUE(ldlt.factorize(A));
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(27, -1.0, 2.0), x = b;
    ldlt.solve(x, x);
    EXPECT_LT((A * x - b).norm(), 1e-9 * b.norm());
}

// A pivot at or below zero, one that is not a number or an infinite one is refused
TEST(TridiagonalCholesky, AMatrixThatIsNotPositiveDefiniteIsRefused) {
    for (double bad : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
        for (Index where : {0, 13, 26}) {
            SCOPED_TRACE(testing::Message() << bad << " at " << where);
            Eigen::SparseMatrix<double> A = columnMatrix(27, 1e-3, 0, 5);
            TridiagonalCholesky ldlt;
            ldlt.analyse(A);
            A.coeffRef(where, where) = bad;
            EXPECT_FALSE(ldlt.factorize(A));
        }
    // positive diagonal, yet indefinite: the pivot turns negative on the way
    Eigen::SparseMatrix<double> A = columnMatrix(27, 1e-3, 0, 5);
    TridiagonalCholesky ldlt;
    ldlt.analyse(A);
    A.coeffRef(14, 13) = A.coeffRef(13, 14) = -2 * std::sqrt(A.coeff(13, 13) * A.coeff(14, 14));
    EXPECT_FALSE(ldlt.factorize(A));
}

// A right-hand side of another size is an error, not a write past x's end
TEST(TridiagonalCholesky, ARightHandSideOfAnotherSizeIsRefused) {
    const Eigen::SparseMatrix<double> A = columnMatrix(27, 1e-3, 0, 5);
    TridiagonalCholesky ldlt;
    ldlt.analyse(A);
    ASSERT_TRUE(ldlt.factorize(A));
    Eigen::VectorXd x;
    EXPECT_THROW(ldlt.solve(Eigen::VectorXd::Ones(20), x), Error);
}

// A 2D grid's pattern is not tridiagonal: refused when analysed, not solved wrongly
TEST(TridiagonalCholesky, APatternOffTheThreeDiagonalsIsRefused) {
    const Grid<2> grid(IVec<2>{3, 4}, 0.01, 1.0);
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    TridiagonalCholesky ldlt;
    EXPECT_THROW(ldlt.analyse(system.matrix()), Error);
}

}  // namespace qs
