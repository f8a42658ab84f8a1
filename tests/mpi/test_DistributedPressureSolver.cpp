// The pressure solve over ranks (parallel/DistributedPressureSolver.hpp, CellNumbering.hpp):
// a cell system like the semi-implicit step's (a Laplacian of variable conductivity between
// neighbouring cells plus a storage term on the diagonal), each rank assembling the rows of its
// own cells, solved to a known solution. On 2 and 3 ranks over piping2D's bands, on 4 over
// piping3D's 2 x 2 blocks; the same system on one rank (Eigen's sparse Cholesky) agrees.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "parallel/CellNumbering.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/DistributedPressureSolver.hpp"

using namespace qs;

namespace {

template <int D>
Index flat(const IVec<D>& k, const IVec<D>& cells) {
    Index c = 0;
    for (int a = D; a-- > 0;) c = c * cells[a] + k[a];
    return c;
}

/// The conductivity between a cell and its neighbour: varies over the grid, so a row's entries
/// differ (a system a wrong column index would not solve).
double conductivity(Index a, Index b) { return 1.0 + 0.5 * std::sin(0.37 * double(a + b)); }
double storage(Index c) { return 1e-3 * (1.0 + 0.3 * std::cos(0.11 * double(c))); }
double solution(Index c) { return std::sin(0.05 * double(c)) + 0.01 * double(c % 7); }

/// Row of global cell k: (neighbour's row, value) pairs, the diagonal first.
template <int D>
std::vector<std::pair<Index, double>> rowOf(const IVec<D>& k, const IVec<D>& cells, const CellNumbering<D>& numbering) {
    const Index c = flat<D>(k, cells);
    std::vector<std::pair<Index, double>> row{{numbering.row(k), storage(c)}};
    for (int a = 0; a < D; ++a)
        for (int side : {-1, 1}) {
            IVec<D> n = k;
            n[a] += side;
            if (n[a] < 0 || n[a] >= cells[a]) continue;
            const double g = conductivity(c, flat<D>(n, cells));
            row[0].second += g;
            row.push_back({numbering.row(n), -g});
        }
    return row;
}

template <int D>
void checkSolve(const char* caseName) {
    const Communicator& world = Communicator::world();
    const CaseConfig config = loadCase(std::string(QUICKSAND_SOURCE_DIR) + caseName);
    const Decomposition d = decompose(config, world.size());
    const CellNumbering<D> numbering(d);
    const DecompositionBlock& mine = d.blocks[static_cast<std::size_t>(world.rank())];
    IVec<D> cells;
    for (int a = 0; a < D; ++a) cells[a] = d.cuts[a].back();

    // this rank's rows, and the global solution's values at them
    std::vector<Index> start{0}, columns;
    std::vector<double> values, exact;
    std::vector<std::pair<Index, double>> all;  // (row, b) over the whole grid, for the one-rank solve
    IVec<D> k;
    for (int a = 0; a < D; ++a) k[a] = mine.cellBegin[a];
    while (true) {
        EXPECT_EQ(numbering.row(k), numbering.firstRow(world.rank()) + Index(start.size()) - 1);
        for (const auto& [column, value] : rowOf<D>(k, cells, numbering)) {
            columns.push_back(column);
            values.push_back(value);
        }
        start.push_back(static_cast<Index>(columns.size()));
        exact.push_back(solution(numbering.row(k)));
        int a = 0;
        while (a < D && ++k[a] >= mine.cellEnd[a]) k[a] = mine.cellBegin[a], ++a;
        if (a == D) break;
    }
    std::vector<double> b(exact.size(), 0.0);
    for (std::size_t i = 0; i + 1 < start.size(); ++i)
        for (Index e = start[i]; e < start[i + 1]; ++e) b[i] += values[e] * solution(columns[e]);

    DistributedPressureSolver solver(world, numbering.firstRow(world.rank()), numbering.firstRow(world.rank() + 1), D);
    solver.setMatrix(start, columns, values);
    std::vector<double> x(b.size(), 0.0);
    const int iterations = solver.solve(b, x, 1e-12);
    EXPECT_GT(iterations, 0);
    EXPECT_LT(iterations, 100);
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - exact[i]));
    EXPECT_LT(world.max(worst), 1e-8) << "the solution's largest error over the ranks";

    // a second right-hand side on the same matrix, from the last solution as a guess
    for (double& v : b) v *= 2;
    const int again = solver.solve(b, x, 1e-12);
    EXPECT_LE(again, iterations + 2);
    worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - 2 * exact[i]));
    EXPECT_LT(world.max(worst), 2e-8);

    // from the solution itself CG has nothing to do, and says so without an error; b = 0 gives 0
    EXPECT_NO_THROW(solver.solve(b, x, 1e-12));
    const std::vector<double> kept = x;
    std::vector<double> none(b.size(), 0.0);
    EXPECT_EQ(solver.solve(none, x, 1e-12), 0);
    for (double v : x) EXPECT_EQ(v, 0.0);
    x = kept;

    // the same system on one rank, by Eigen's sparse Cholesky (rank 0 assembles all of it)
    if (world.rank() == 0) {
        const Index n = numbering.rows();
        std::vector<Eigen::Triplet<double>> triplets;
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
        Index count = 1;
        for (int a = 0; a < D; ++a) count *= cells[a];
        for (Index c = 0; c < count; ++c) {
            IVec<D> g;
            Index rest = c;
            for (int a = 0; a < D; ++a) g[a] = rest % cells[a], rest /= cells[a];
            const Index r = numbering.row(g);
            for (const auto& [column, value] : rowOf<D>(g, cells, numbering)) {
                triplets.emplace_back(r, column, value);
                rhs[r] += value * solution(column);
            }
        }
        Eigen::SparseMatrix<double> A(n, n);
        A.setFromTriplets(triplets.begin(), triplets.end());
        Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky(A);
        const Eigen::VectorXd one = cholesky.solve(rhs);
        for (std::size_t i = 0; i < x.size(); ++i)
            EXPECT_NEAR(0.5 * x[i], one[numbering.firstRow(0) + Index(i)], 1e-8) << "row " << i;
    }
}

}  // namespace

TEST(DistributedPressureSolver, SolvesTheCellSystemOverTheRanks) {
    if (!distributedSolverAvailable()) GTEST_SKIP() << "built without hypre";
    if (Communicator::world().size() >= 4) checkSolve<3>("/cases/piping3D");
    else checkSolve<2>("/cases/piping2D");
}

TEST(DistributedPressureSolver, RefusesRowsThatDoNotFit) {
    if (!distributedSolverAvailable()) GTEST_SKIP() << "built without hypre";
    const Communicator& world = Communicator::world();
    DistributedPressureSolver solver(world, 10 * world.rank(), 10 * world.rank() + 10, 2);
    EXPECT_THROW(solver.setMatrix({0, 1}, {0}, {1.0}), Error);  // 1 row start pair for 10 rows
    std::vector<double> x(3);
    EXPECT_THROW(solver.solve({1, 2, 3}, x, 1e-10), Error);     // before setMatrix
}
