// The stencil walks of solver/Parallel.hpp: the fixed 2-node-per-axis walk for linear hats
// (forStencilOffsets<D, true>) must make the same calls as the general, trimmed walk, in the same
// order, adding only nodes whose N and grad N are exactly zero, so that every transfer's sums are
// the same bit for bit. Points inside cells, on nodes (one, two or all axes), within an ulp of
// every node (where the rounded node positions could give a linear hat a third weight), at the
// grid's ends and just outside it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "grid/ShapeFunctions.hpp"
#include "solver/Parallel.hpp"

using namespace qs;

namespace {

constexpr double h = 0.01;
constexpr Index cells = 9;  // node positions k h that round both ways

struct Call {
    Index node;
    double N, grad[3];
    int offset[3];
};

template <int D, bool Linear>
std::vector<Call> walk(const Grid<D>& grid, const double* x) {
    Index start = 0;
    double w[3 * D], dw[3 * D];
    for (int d = 0; d < D; ++d) {
        const AxisWeights a = axisWeights(x[d], h, cells, ShapeFunctionKind::Linear, 0.0, 0.0, cells * h);
        start += a.start * grid.nodeStride(d);
        for (int k = 0; k < kStencil; ++k) {
            w[d * 3 + k] = a.w[k];
            dw[d * 3 + k] = a.dw[k];
        }
    }
    std::vector<Call> calls;
    forStencilOffsets<D, Linear>(grid, start, w, dw, [&](Index i, double N, const double* g, const int* o) {
        Call c{i, N, {}, {}};
        for (int d = 0; d < D; ++d) {
            c.grad[d] = g[d];
            c.offset[d] = o[d];
        }
        calls.push_back(c);
    });
    return calls;
}

bool isZero(const Call& c, int D) {
    bool zero = c.N == 0;
    for (int d = 0; d < D; ++d) zero = zero && c.grad[d] == 0;
    return zero;
}

/// A transfer's sum over a walk: N and grad N weighting values that differ from node to node.
template <int D>
double transferSum(const std::vector<Call>& calls) {
    double sum = 0;
    for (const Call& c : calls) {
        sum += c.N * (c.node + 1.5);
        for (int d = 0; d < D; ++d) sum += c.grad[d] * (c.node + 0.25 * (d + 1));
    }
    return sum;
}

template <int D>
void checkPoint(const Grid<D>& grid, const double* x) {
    const auto general = walk<D, false>(grid, x), linear = walk<D, true>(grid, x);
    ASSERT_EQ(linear.size(), std::size_t(1) << D) << "2 nodes per axis";
    std::size_t g = 0;
    for (const Call& c : linear) {
        ASSERT_GE(c.node, 0);
        ASSERT_LT(c.node, grid.numNodes());
        if (g < general.size() && general[g].node == c.node) {
            EXPECT_EQ(c.N, general[g].N);
            for (int d = 0; d < D; ++d) {
                EXPECT_EQ(c.grad[d], general[g].grad[d]);
                EXPECT_EQ(c.offset[d], general[g].offset[d]);
            }
            ++g;
        } else {
            EXPECT_TRUE(isZero(c, D)) << "an added node must carry nothing: node " << c.node << ", N = " << c.N;
        }
    }
    EXPECT_EQ(g, general.size()) << "every node of the general walk, in its order";
    EXPECT_EQ(transferSum<D>(linear), transferSum<D>(general)) << "the sums, bit for bit";
    // a linear hat has at most two live nodes per axis, and they are neighbours
    for (int d = 0; d < D; ++d) {
        const AxisWeights a = axisWeights(x[d], h, cells, ShapeFunctionKind::Linear, 0.0, 0.0, cells * h);
        const bool live[3] = {a.w[0] != 0 || a.dw[0] != 0, a.w[1] != 0 || a.dw[1] != 0, a.w[2] != 0 || a.dw[2] != 0};
        EXPECT_FALSE(live[0] && live[2]) << "axis " << d << " at x = " << x[d] << ": a third weight "
                                         << a.w[0] << ", " << a.w[1] << ", " << a.w[2];
    }
}

template <int D>
void checkAll() {
    IVec<D> n;
    n.fill(cells);
    const Grid<D> grid(n, h, 1.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> inside(0.0, cells * h);
    std::uniform_int_distribution<int> node(0, cells);
    std::bernoulli_distribution onNode(0.5);
    for (int trial = 0; trial < 2000; ++trial) {
        double x[D];
        // each axis: inside a cell, or exactly on a node (the grid's ends included)
        for (int d = 0; d < D; ++d) x[d] = onNode(rng) ? node(rng) * h : inside(rng);
        SCOPED_TRACE(testing::Message() << "trial " << trial);
        checkPoint(grid, x);
        if (testing::Test::HasFatalFailure()) return;
    }
    // within an ulp of every node, on every axis at once, and just outside the grid
    for (Index k = 0; k <= cells; ++k)
        for (const double toward : {-1.0, 1.0}) {
            double x[D];
            for (int d = 0; d < D; ++d) x[d] = std::nextafter(k * h, toward);
            SCOPED_TRACE(testing::Message() << "next to node " << k << " towards " << toward);
            checkPoint(grid, x);
            if (testing::Test::HasFatalFailure()) return;
        }
    for (const double outside : {-0.3 * h, cells * h + 0.3 * h}) {
        double x[D];
        for (int d = 0; d < D; ++d) x[d] = outside;
        checkPoint(grid, x);
    }
    double corner[D];
    for (int d = 0; d < D; ++d) corner[d] = cells * h;  // the grid's far corner
    checkPoint(grid, corner);
    for (int d = 0; d < D; ++d) corner[d] = 0;
    checkPoint(grid, corner);
}

}  // namespace

TEST(Stencil, TheLinearWalkMakesTheGeneralWalksCallsIn1D) { checkAll<1>(); }
TEST(Stencil, TheLinearWalkMakesTheGeneralWalksCallsIn2D) { checkAll<2>(); }
TEST(Stencil, TheLinearWalkMakesTheGeneralWalksCallsIn3D) { checkAll<3>(); }
