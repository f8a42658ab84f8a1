// grid/LinearStencil.hpp: a point's 2^D nodes and weights under linear shape functions, taken
// from its position. Checked against the per-axis hats of grid/ShapeFunctions.hpp walked by the
// general stencil (the reference), and for what the transfers rely on: the nodes are those of the
// cell Grid::cellOf sorted the point into (so a scatter slab owns them, solver/Parallel.hpp), the
// weights are a partition of unity, their gradients sum to zero, and sum N_k x_k = x_p (the APIC
// offsets (k - xi) h). Points inside cells, on nodes, within an ulp of every node, at the grid's
// ends and corners.
// On a node (or within rounding of one) a hat's slope jumps, and the stencil takes the slopes of
// the cell cellOf gives (the upper one for a point exactly on a node), so the slopes are compared
// with the reference's only away from nodes. The reference takes the slope +1/h at its own node
// there, with nothing from the others: their sum is then 1/h, not 0, and a uniform velocity had a
// strain at such a point (the solver clamps points onto walls, the filter and the grid's top,
// which are node planes); the stencil's slopes sum to zero everywhere (checked).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "grid/LinearStencil.hpp"
#include "grid/ShapeFunctions.hpp"
#include "solver/Parallel.hpp"

using namespace qs;

namespace {

constexpr double kCellSizes[] = {0.01, 0.0062, 0.0093, 0.02, 0.003};
constexpr Index cells = 9;
/// Positions in cells, x / h, are rounded to an ulp of the cell count, and so are the weights
/// (xi = x (1/h) - c here, 1 - |x - x_i| / h in the reference): a few ulps of `cells`.
constexpr double kRoundOff = 4 * 2.220446049250313e-16 * (cells + 1);

struct Weight {
    double N = 0, grad[3] = {};
};

/// The reference: the per-axis linear hats, walked by the general (uGIMP) stencil.
template <int D>
std::map<Index, Weight> reference(const Grid<D>& grid, const double* x) {
    Index start = 0;
    double w[3 * D], dw[3 * D];
    for (int d = 0; d < D; ++d) {
        const AxisWeights a = axisWeights(x[d], grid.h(), grid.cells(d), ShapeFunctionKind::Linear, 0.0, 0.0,
                                          grid.cells(d) * grid.h());
        start += a.start * grid.nodeStride(d);
        for (int k = 0; k < kStencil; ++k) {
            w[d * 3 + k] = a.w[k];
            dw[d * 3 + k] = a.dw[k];
        }
    }
    std::map<Index, Weight> nodes;
    forStencil<D>(grid, start, w, dw, [&](Index i, double N, const double* g) {
        Weight& c = nodes[i];
        c.N = N;
        for (int d = 0; d < D; ++d) c.grad[d] = g[d];
    });
    return nodes;
}

template <int D>
void checkPoint(const Grid<D>& grid, const double* x) {
    const double h = grid.h();
    const LinearStencil<D> st = linearStencil(grid, x);
    const auto ref = reference(grid, x);
    // the nodes of the cell cellOf gives, corner k as in Grid::forEachNodeOfCell
    std::vector<Index> cellNodes;
    grid.forEachNodeOfCell(grid.cellOf(x), [&](Index i, int) { cellNodes.push_back(i); });
    // along which axes the point is within rounding of a node, where the slopes jump
    bool nearNode[D];
    for (int a = 0; a < D; ++a) nearNode[a] = std::abs(x[a] / h - std::round(x[a] / h)) < 1e-9;
    double sumN = 0, sumGrad[D] = {}, centre[D] = {};
    for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
        ASSERT_EQ(st.node[k], cellNodes[k]) << "corner " << k;
        const auto it = ref.find(st.node[k]);
        const Weight expected = it == ref.end() ? Weight{} : it->second;
        EXPECT_NEAR(st.N[k], expected.N, kRoundOff) << "corner " << k;
        for (int a = 0; a < D; ++a)
            if (!nearNode[a]) {
                EXPECT_NEAR(st.grad[k][a], expected.grad[a], kRoundOff / h) << "corner " << k << ", axis " << a;
            }
        sumN += st.N[k];
        const IVec<D> n = grid.nodeCoords(st.node[k]);
        for (int a = 0; a < D; ++a) {
            sumGrad[a] += st.grad[k][a];
            centre[a] += st.N[k] * grid.nodePosition(n[a]);
            // the APIC offset the transfers use, (k_a - xi_a) h, is x_k - x_p
            EXPECT_NEAR((LinearStencil<D>::bit(k, a) - st.xi[a]) * h, grid.nodePosition(n[a]) - x[a], kRoundOff * h);
        }
    }
    // every node the reference gives a weight is in the stencil
    for (const auto& [node, w] : ref) {
        if (w.N < kRoundOff) continue;
        bool found = false;
        for (int k = 0; k < LinearStencil<D>::kNodes; ++k) found = found || st.node[k] == node;
        EXPECT_TRUE(found) << "node " << node << " (N = " << w.N << ") is not in the stencil";
    }
    EXPECT_NEAR(sumN, 1.0, kRoundOff);
    for (int a = 0; a < D; ++a) {
        EXPECT_NEAR(sumGrad[a], 0.0, kRoundOff / h);
        EXPECT_NEAR(centre[a], x[a], kRoundOff * h) << "sum N x_k = x_p";
        EXPECT_GE(st.xi[a], 0.0);
        EXPECT_LE(st.xi[a], 1.0);
    }
}

template <int D>
void checkAll() {
    for (const double h : kCellSizes) {
        SCOPED_TRACE(testing::Message() << "h = " << h);
        IVec<D> n;
        n.fill(cells);
        const Grid<D> grid(n, h, 1.0);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> inside(0.0, cells * h);
        std::uniform_int_distribution<int> node(0, cells);
        std::bernoulli_distribution onNode(0.5);
        for (int trial = 0; trial < 500; ++trial) {
            double x[D];
            // each axis: inside a cell, or exactly on a node (the grid's ends included)
            for (int d = 0; d < D; ++d) x[d] = onNode(rng) ? node(rng) * h : inside(rng);
            SCOPED_TRACE(testing::Message() << "trial " << trial);
            checkPoint(grid, x);
            if (testing::Test::HasFatalFailure()) return;
        }
        // within an ulp of every node, on every axis at once
        for (Index k = 0; k <= cells; ++k)
            for (const double toward : {-1.0, 1.0}) {
                double x[D];
                for (int d = 0; d < D; ++d) x[d] = std::clamp(std::nextafter(k * h, toward), 0.0, cells * h);
                SCOPED_TRACE(testing::Message() << "next to node " << k << " towards " << toward);
                checkPoint(grid, x);
                if (testing::Test::HasFatalFailure()) return;
            }
        double corner[D];
        for (int d = 0; d < D; ++d) corner[d] = cells * h;  // the grid's far corner: the last cell, xi = 1
        checkPoint(grid, corner);
        for (int d = 0; d < D; ++d) corner[d] = 0;
        checkPoint(grid, corner);
    }
}

}  // namespace

TEST(LinearStencil, MatchesThePerAxisHatsIn1D) { checkAll<1>(); }
TEST(LinearStencil, MatchesThePerAxisHatsIn2D) { checkAll<2>(); }
TEST(LinearStencil, MatchesThePerAxisHatsIn3D) { checkAll<3>(); }

// The solver holds the sand on the filter at Grid::firstInCell: in the cell above the plane, with
// the stencil of that cell, for every row and the cell sizes of the shipped cases (fl(r h) (1/h)
// rounds below r for most rows of some of them). And on the far boundary of a long axis, where
// fl(x (1/h)) can exceed the cell count, the weights stay in [0, 1].
TEST(LinearStencil, APointHeldOnANodePlaneIsInTheCellAbove) {
    for (const double h : {0.0062, 0.0124, 0.0093, 0.003, 0.01, 0.02, 0.007}) {
        const Index rows = 400;
        const Grid<2> grid({2, rows}, h, 1.0);
        for (Index r = 0; r < rows; ++r) {
            const double x[2] = {0.5 * h, grid.firstInCell(1, r)};
            ASSERT_GE(x[1], r * h);
            ASSERT_LE(x[1], r * h * (1 + 8e-16) + 1e-300);
            ASSERT_EQ(grid.cellOf(x), r * grid.cellStride(1)) << "h = " << h << ", row " << r;
            const LinearStencil<2> st = linearStencil(grid, x);
            EXPECT_EQ(st.node[0], r * grid.nodeStride(1)) << "h = " << h << ", row " << r;
            EXPECT_NEAR(st.N[0] + st.N[1], 1.0, 1e-13) << "the weight on the plane's own nodes";
        }
        // the far end: the last cell, xi = 1 at most, no negative weight
        const double top[2] = {2 * h, rows * h};
        const LinearStencil<2> st = linearStencil(grid, top);
        for (int k = 0; k < 4; ++k) EXPECT_GE(st.N[k], 0.0) << "h = " << h << ", corner " << k;
        EXPECT_LE(st.xi[1], 1.0);
        EXPECT_EQ(st.node[3], grid.numNodes() - 1);
    }
}
