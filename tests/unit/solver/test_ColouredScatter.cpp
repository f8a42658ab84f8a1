// The coloured scatter of solver/Parallel.hpp: slabs of whole cell rows, two colours. Two slabs
// of one colour run at the same time, so they must never write the same node: checked here for
// the nodes the solver's own stencil walks write (forEachNodeOfPoint: the linear stencil's 2^D
// nodes, zero weights included, and uGIMP's trimmed walk), with points inside cells, on nodes and
// cell faces, within an ulp of them (where the cell of x / h and of x (1/h) can differ), and at
// the grid's ends, for several cell sizes.
// And every point is visited once, the colours in turn, a slab's points in their sorted order.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "grid/ShapeFunctions.hpp"
#include "solver/Parallel.hpp"
#include "solver/PointStencil.hpp"

using namespace qs;

namespace {

/// cell sizes of the shipped and verification cases, and others whose multiples round both ways
constexpr double kCellSizes[] = {0.01, 0.0062, 0.0093, 0.00465, 0.0124, 0.02, 0.003, 0.007};

/// A point set as the solver's (x and its shape cache), sorted by cell.
template <int D>
struct Points {
    std::vector<double> x;  // D per point, sorted by cell
    struct {
        std::vector<Index> cell, start;
        std::vector<double> w, dw;  // 3 per axis and point
    } shape;
    std::vector<Index> cellStart;
};

/// n random points in the grid, a third of their coordinates on a node and a third within an ulp
/// of one, sorted by cell, with the shape functions of `kind` (uGIMP with lp = h/4, its domain
/// cut at the grid's ends).
template <int D>
Points<D> makePoints(const Grid<D>& grid, Index n, ShapeFunctionKind kind, unsigned seed) {
    const double h = grid.h();
    std::mt19937 rng(seed);
    std::vector<std::vector<double>> xs(n, std::vector<double>(D));
    for (auto& x : xs)
        for (int d = 0; d < D; ++d) {
            const double top = grid.cells(d) * h;
            std::uniform_real_distribution<double> inside(0.0, top);
            std::uniform_int_distribution<Index> node(0, grid.cells(d));
            const double onNode = node(rng) * h;
            switch (rng() % 3) {
                case 0: x[d] = onNode; break;
                case 1: x[d] = std::clamp(std::nextafter(onNode, rng() % 2 ? HUGE_VAL : -HUGE_VAL), 0.0, top); break;
                default: x[d] = inside(rng);
            }
        }
    auto cellOf = [&](const std::vector<double>& x) { return grid.cellOf(x.data()); };
    std::stable_sort(xs.begin(), xs.end(), [&](const auto& a, const auto& b) { return cellOf(a) < cellOf(b); });
    Points<D> p;
    p.cellStart.assign(grid.numCells() + 1, 0);
    for (const auto& x : xs) {
        const Index c = cellOf(x);
        p.x.insert(p.x.end(), x.begin(), x.end());
        p.shape.cell.push_back(c);
        ++p.cellStart[c + 1];
        Index start = 0;
        for (int d = 0; d < D; ++d) {
            const AxisWeights a = axisWeights(x[d], h, grid.cells(d), kind, 0.25 * h, 0.0, grid.cells(d) * h);
            start += a.start * grid.nodeStride(d);
            for (int k = 0; k < kStencil; ++k) {
                p.shape.w.push_back(a.w[k]);
                p.shape.dw.push_back(a.dw[k]);
            }
        }
        p.shape.start.push_back(start);
    }
    for (Index c = 0; c < grid.numCells(); ++c) p.cellStart[c + 1] += p.cellStart[c];
    return p;
}

/// The slab a point's cell row belongs to.
template <int D>
Index slabOf(const Grid<D>& grid, Index cell, Index rowsPerSlab) {
    return cell / grid.cellStride(D - 1) / rowsPerSlab;
}

template <int D, bool Linear>
void checkNoSharedNodes(const IVec<D>& cells, ShapeFunctionKind kind, double h) {
    SCOPED_TRACE(testing::Message() << "h = " << h << (Linear ? ", linear" : ", uGIMP"));
    const Grid<D> grid(cells, h, 1.0);
    const Points<D> pts = makePoints(grid, 4000, kind, 11);
    const Index rowsPerSlab = slabRows(Linear);
    // the slab that wrote each node, per colour
    std::map<std::pair<Index, int>, Index> writer;
    std::vector<Index> order;
    const int before = omp_get_max_threads();
    omp_set_num_threads(1);  // the visiting order, as a sequence
    forEachPointColoured(grid, pts.cellStart, rowsPerSlab, [&](Index p) {
        order.push_back(p);
        const Index slab = slabOf(grid, pts.shape.cell[p], rowsPerSlab);
        const int colour = slab % 2;
        forEachNodeOfPoint<Linear>(grid, pts, p, [&](Index i, double, const double*) {
            ASSERT_GE(i, 0);
            ASSERT_LT(i, grid.numNodes());
            const auto key = std::make_pair(i, colour);
            const auto it = writer.find(key);
            if (it == writer.end()) writer[key] = slab;
            else EXPECT_EQ(it->second, slab) << "node " << i << " is written by slabs " << it->second
                                            << " and " << slab << " of colour " << colour;
        });
    });
    omp_set_num_threads(before);
    ASSERT_EQ(order.size(), pts.shape.cell.size()) << "every point once";
    for (std::size_t k = 1; k < order.size(); ++k) {
        const Index a = slabOf(grid, pts.shape.cell[order[k - 1]], rowsPerSlab);
        const Index b = slabOf(grid, pts.shape.cell[order[k]], rowsPerSlab);
        const bool sameSlab = a == b;
        EXPECT_TRUE(sameSlab ? order[k] == order[k - 1] + 1 : (a % 2 < b % 2 || (a % 2 == b % 2 && a < b)))
            << "visit " << k << ": point " << order[k] << " (slab " << b << ") after point " << order[k - 1]
            << " (slab " << a << ")";
    }
}

}  // namespace

TEST(ColouredScatter, SlabsOfOneColourShareNoNodeIn1D) {
    for (const double h : kCellSizes) {
        checkNoSharedNodes<1, true>({125}, ShapeFunctionKind::Linear, h);
        checkNoSharedNodes<1, false>({125}, ShapeFunctionKind::Gimp, h);
    }
}

TEST(ColouredScatter, SlabsOfOneColourShareNoNodeIn2D) {
    for (const double h : kCellSizes) {
        checkNoSharedNodes<2, true>({3, 125}, ShapeFunctionKind::Linear, h);
        checkNoSharedNodes<2, false>({3, 125}, ShapeFunctionKind::Gimp, h);
    }
}

TEST(ColouredScatter, SlabsOfOneColourShareNoNodeIn3D) {
    for (const double h : kCellSizes) {
        checkNoSharedNodes<3, true>({2, 3, 125}, ShapeFunctionKind::Linear, h);
        checkNoSharedNodes<3, false>({2, 3, 125}, ShapeFunctionKind::Gimp, h);
    }
}

/// In parallel (more points than kMinParallelItems, enough slabs per colour), with 2 threads:
/// every point is visited exactly once.
TEST(ColouredScatter, TwoThreadsVisitEveryPointOnce) {
    const Grid<3> grid({4, 4, 40}, kCellSizes[0], 1.0);
    ASSERT_GE(grid.cells(2) / slabRows(false), 2 * kMinParallelSlabs);
    for (const bool linear : {true, false}) {
        const Points<3> pts = makePoints(grid, 3 * kMinParallelItems, linear ? ShapeFunctionKind::Linear : ShapeFunctionKind::Gimp, 5);
        std::vector<int> visits(pts.shape.cell.size(), 0);
        const int before = omp_get_max_threads();
        omp_set_num_threads(2);
        forEachPointColoured(grid, pts.cellStart, slabRows(linear), [&](Index p) { ++visits[p]; });
        omp_set_num_threads(before);
        EXPECT_EQ(std::count(visits.begin(), visits.end(), 1), static_cast<long>(visits.size()));
    }
}
