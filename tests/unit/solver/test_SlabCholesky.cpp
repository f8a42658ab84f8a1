// The direct pressure solve split into slabs (solver/SlabCholesky.hpp): against Eigen's own
// sparse Cholesky on the step's kind of matrix, with one, two and three slabs, in 2D and 3D.
#include "solver/SlabCholesky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/LU>

#include "solver/PressureSystem.hpp"

namespace qs {
namespace {

// The semi-implicit step's matrix S + D B D^T on the grid's pattern (as SemiImplicitIntegrator
// assembles it): each node's response beta drawn at random over two decades, a storage s per cell,
// and `held` cells as identity rows, whose neighbours do not see them.
template <int D>
void fillStepMatrix(const Grid<D>& grid, PressureSystem& system, double storage, const std::vector<char>& held,
                    unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> decades(0.0, 2.0);
    std::vector<double> beta(grid.numNodes());
    for (auto& b : beta) b = std::pow(10.0, decades(random));
    for (Index c = 0; c < grid.numCells(); ++c) {
        double* value = system.values(c);
        for (Index k = 0; k < system.size(c); ++k) value[k] = 0;
        const int centre[D] = {};
        const int diagonal = system.slot(c, PressureSystem::offsetCode(centre, D));
        if (held[c]) { value[diagonal] = 1; continue; }
        grid.forEachNodeOfCell(c, [&](Index i, int corner) {
            for (int a = 0; a < D; ++a) {
                const double Dc = grid.divergenceWeight(c, corner, a);
                grid.forEachCellOfNode(i, [&](Index c2, int corner2) {
                    if (held[c2]) return;
                    int offset[D];
                    for (int d = 0; d < D; ++d) offset[d] = ((corner >> d) & 1) - ((corner2 >> d) & 1);
                    value[system.slot(c, PressureSystem::offsetCode(offset, D))] +=
                        beta[i] * Dc * grid.divergenceWeight(c2, corner2, a);
                });
            }
        });
        value[diagonal] += storage;
    }
}

/// How much larger the slabs' residual may be than Eigen's (achieved: 0.96 to 1.27)
constexpr double kResidualRatio = 2;

/// Each cell's layer along the last axis
template <int D>
std::vector<int> layersOf(const Grid<D>& grid) {
    std::vector<int> layer(grid.numCells());
    for (Index c = 0; c < grid.numCells(); ++c) layer[c] = static_cast<int>(grid.cellCoords(c)[D - 1]);
    return layer;
}

// The slabs' solution's residual |A x - b| / |b| over Eigen's SimplicialLDLT's own, for a
// right-hand side with every cell's entry set: every equation counts at b's scale, the held cells'
// identity rows too (the solution's own norm is dominated by the cells of least storage)
template <int D>
double errorAgainstEigen(const Grid<D>& grid, double storage, int slabs, int expectedSlabs, int heldEvery) {
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    std::vector<char> held(grid.numCells(), 0);
    if (heldEvery > 0)
        for (Index c = 0; c < grid.numCells(); c += heldEvery) held[c] = 1;
    fillStepMatrix(grid, system, storage, held, 7);
    const SlabCholesky::Matrix A = system.matrix();
    SlabCholesky split;
    split.analyse(A, layersOf(grid), static_cast<int>(grid.cells(D - 1)), slabs);
    EXPECT_EQ(split.slabs(), expectedSlabs);
    Eigen::VectorXd b(grid.numCells()), x(grid.numCells());
    for (Index c = 0; c < grid.numCells(); ++c) b[c] = std::sin(0.37 * c) + 0.5;
    // as the step uses it: another matrix factorised and solved first (the same pattern, other
    // values), then this one solved twice, the second time for b: nothing of the first
    // factorisation or solve may remain
    SlabCholesky::Matrix other = A;
    for (Index k = 0; k < other.nonZeros(); ++k) other.valuePtr()[k] *= 1 + 0.3 * std::sin(1.7 * k);
    for (Index c = 0; c < grid.numCells(); ++c) other.coeffRef(c, c) += 10 * std::abs(A.coeff(c, c));
    EXPECT_TRUE(split.factorize(other));
    split.solve(Eigen::VectorXd::Constant(grid.numCells(), 3.0), x);
    EXPECT_TRUE(split.factorize(A));
    split.solve(Eigen::VectorXd::Constant(grid.numCells(), -2.0), x);
    split.solve(b, x);
    Eigen::SimplicialLDLT<SlabCholesky::Matrix> eigen(A);
    EXPECT_EQ(eigen.info(), Eigen::Success);
    const Eigen::VectorXd reference = eigen.solve(b);
    return (A * x - b).norm() / std::max((A * reference - b).norm(), 1e-16 * b.norm());
}

// The step's matrices with soft water (storage 1e-3 of the coupling) and with real water (1e-7):
// the Schur complement's sum, T_0 + T_1 - A_ss, loses no digits that matter
TEST(SlabCholesky, AgreesWithEigensCholeskyInOneTwoAndThreeSlabs) {
    const Grid<2> plane(IVec<2>{26, 98}, 0.0031, 1.0);
    const Grid<3> box(IVec<3>{6, 5, 40}, 0.0062, 1.0);
    for (double storage : {1e-3, 1e-7}) {
        SCOPED_TRACE(storage);
        for (int slabs : {1, 2, 3}) {
            SCOPED_TRACE(slabs);
            EXPECT_LT(errorAgainstEigen(plane, storage, slabs, slabs, 0), kResidualRatio);
            EXPECT_LT(errorAgainstEigen(plane, storage, slabs, slabs, 7), kResidualRatio);  // held cells, some in the separators
            EXPECT_LT(errorAgainstEigen(box, storage, slabs, slabs, 0), kResidualRatio);
        }
    }
}

// A slab keeps kMinLayers layers of its own: a short axis gets fewer slabs than asked for
TEST(SlabCholesky, AShortAxisGetsFewerSlabs) {
    // two slabs need 4 + 1 + 4 layers, three 4 + 1 + 4 + 1 + 4
    for (int layers : {8, 9, 13, 14}) {
        SCOPED_TRACE(layers);
        const Grid<2> plane(IVec<2>{40, layers}, 0.01, 1.0);
        EXPECT_LT(errorAgainstEigen(plane, 1e-3, 3, layers < 9 ? 1 : layers < 14 ? 2 : 3, 0), kResidualRatio);
    }
}

// A negative pivot in a slab is refused
TEST(SlabCholesky, AMatrixThatIsNotPositiveDefiniteIsRefused) {
    const Grid<2> grid(IVec<2>{10, 30}, 0.01, 1.0);
    for (int where : {3, 15}) {  // a cell of the first slab; one in the middle, at or next to the separator
        SCOPED_TRACE(where);
        PressureSystem system;
        system.build(grid, PressureSolver::Direct);
        std::vector<char> held(grid.numCells(), 0);
        fillStepMatrix(grid, system, 1e-3, held, 3);
        SlabCholesky::Matrix A = system.matrix();
        A.coeffRef(where * 10 + 4, where * 10 + 4) = -1.0;
        SlabCholesky split;
        split.analyse(A, layersOf(grid), 30, 2);
        ASSERT_EQ(split.slabs(), 2);
        EXPECT_FALSE(split.factorize(A));
    }
}

// A matrix whose slabs are each positive definite, but whose separator's Schur complement is not:
// one separator cell's diagonal lowered by delta, between 1 / (S^-1)_jj (where A stops being
// positive definite) and 1 / (T_k^-1)_jj (where slab k's matrix would), is refused by the dense
// LLT of S alone
TEST(SlabCholesky, ASeparatorWhoseSchurComplementIsNotPositiveIsRefused) {
    const Grid<2> grid(IVec<2>{10, 30}, 0.01, 1.0);
    PressureSystem system;
    system.build(grid, PressureSolver::Direct);
    fillStepMatrix(grid, system, 1e-3, std::vector<char>(grid.numCells(), 0), 5);
    SlabCholesky::Matrix A = system.matrix();
    SlabCholesky split;
    split.analyse(A, layersOf(grid), 30, 2);
    ASSERT_EQ(split.slabs(), 2);
    ASSERT_TRUE(split.factorize(A));
    const Index j = split.separatorCells()[4];
    const Index separatorLayer = grid.cellCoords(j)[1];
    // the Schur complement on cell j alone, 1 / (B^-1)_jj, of A over the given cells
    const Eigen::MatrixXd dense(A);
    auto pivotOfJ = [&](auto inside) {
        std::vector<Index> cells;
        for (Index c = 0; c < grid.numCells(); ++c)
            if (inside(c)) cells.push_back(c);
        Eigen::MatrixXd B(cells.size(), cells.size());
        Index at = -1;
        for (std::size_t a = 0; a < cells.size(); ++a) {
            if (cells[a] == j) at = static_cast<Index>(a);
            for (std::size_t b = 0; b < cells.size(); ++b) B(a, b) = dense(cells[a], cells[b]);
        }
        return 1 / B.inverse()(at, at);
    };
    const double whole = pivotOfJ([](Index) { return true; });
    const double below = pivotOfJ([&](Index c) { return grid.cellCoords(c)[1] <= separatorLayer; });
    const double above = pivotOfJ([&](Index c) { return grid.cellCoords(c)[1] >= separatorLayer; });
    ASSERT_LT(1.01 * whole, 0.99 * std::min(below, above));  // room between the two bounds
    const double delta = 0.5 * (whole + std::min(below, above));
    A.coeffRef(j, j) -= delta;
    EXPECT_FALSE(Eigen::LLT<Eigen::MatrixXd>(Eigen::MatrixXd(A)).info() == Eigen::Success);  // A indefinite
    EXPECT_FALSE(split.factorize(A));
}

}  // namespace
}  // namespace qs
