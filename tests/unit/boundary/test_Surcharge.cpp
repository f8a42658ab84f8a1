// The surcharge acts where the sand is in each column of cells (boundary/Surcharge.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "boundary/Surcharge.hpp"
#include "points/PointSet.hpp"

using namespace qs;

namespace {

constexpr double kDepth = 0.5;  ///< m, out of plane: the cross-section 0.15 m2 over the width 0.3 m

/// A 2D grid of 3 x 6 cells of 0.1 m, 0.5 m deep, with one solid point per cell up to each
/// column's own height (a cratered surface); the points sorted by cell.
struct UnevenSand {
    Grid<2> grid{IVec<2>{3, 6}, 0.1, 0.15};
    SolidPoints<2> solid;
    std::vector<Index> cellStart;
    // column tops: the points' centres at the cell centres, each 0.1 m x 0.1 m (one per cell)
    const int rows[3] = {4, 2, 3};

    UnevenSand() {
        std::vector<double> x;
        cellStart.assign(grid.numCells() + 1, 0);
        for (Index c = 0; c < grid.numCells(); ++c) {
            const Index col = c % 3, row = c / 3;
            cellStart[c + 1] = cellStart[c];
            if (row >= rows[col]) continue;
            x.push_back(0.1 * col + 0.05);
            x.push_back(0.1 * row + 0.05);
            ++cellStart[c + 1];
        }
        resizePoints(solid, x.size() / 2);
        solid.x = x;
        for (std::size_t p = 0; p < solid.size(); ++p) solid.volume[p] = 0.1 * 0.1 * kDepth;
    }
};

}  // namespace

TEST(Surcharge, EachColumnOfCellsCarriesItsShareAtItsOwnSurface) {
    UnevenSand s;
    const double q = 1000, h = 0.1;
    std::vector<double> force(s.grid.numNodes() * 2, 0.0);
    addSurcharge(s.grid, s.solid, s.cellStart, 1, q, force);
    // every column's top is on a node row (points fill whole cells): its load on that row alone,
    // half the column's plan area to each of its two corner nodes, nothing anywhere else
    std::vector<double> expected(force.size(), 0.0);
    const double half = 0.5 * h * kDepth;
    for (int col = 0; col < 3; ++col) {
        const Index row = s.rows[col];
        for (Index nx : {Index(col), Index(col + 1)}) expected[(row * 4 + nx) * 2 + 1] -= q * half;
    }
    double total = 0;
    for (std::size_t k = 0; k < force.size(); ++k) {
        EXPECT_NEAR(force[k], expected[k], 1e-9) << "node " << k / 2 << " component " << k % 2;
        total += force[k];
    }
    EXPECT_NEAR(total, -q * s.grid.crossSection(), 1e-9);  // the whole load, q A
}

TEST(Surcharge, ASurfaceInsideACellSplitsLinearlyBetweenItsNodeRows) {
    UnevenSand s;
    for (std::size_t p = 0; p < s.solid.size(); ++p) s.solid.x[p * 2 + 1] -= 0.03;  // every top 0.03 below
    const double q = 1000;
    std::vector<double> force(s.grid.numNodes() * 2, 0.0);
    addSurcharge(s.grid, s.solid, s.cellStart, 1, q, force);
    // column 1's surface at 0.17 m: 30 % on node row 2, 70 % on node row 1
    const Index nx = 1, below = 1 * 4 + nx, above = 2 * 4 + nx;  // node 1 of rows 1 and 2
    const double share0 = 0.5 * 0.1 * kDepth;  // column 1's half of node nx's footprint
    // node nx also carries column 0's share (surface at 0.37 m: rows 3 and 4)
    EXPECT_NEAR(force[below * 2 + 1], -q * share0 * 0.3, 1e-9);
    EXPECT_NEAR(force[above * 2 + 1], -q * share0 * 0.7, 1e-9);
}

TEST(Surcharge, ATopPointReachingAboveItsCellLoadsItsOwnCellsTopNodes) {
    UnevenSand s;
    // column 2's top point (cell row 2) swells to reach 0.02 m into row 3, which has no sand
    const Index top = s.cellStart[2 * 3 + 2];
    s.solid.volume[top] *= 1.4;  // extent 0.07 m above its centre at 0.25 m: top at 0.32 m
    const double q = 1000;
    std::vector<double> force(s.grid.numNodes() * 2, 0.0);
    addSurcharge(s.grid, s.solid, s.cellStart, 1, q, force);
    const double share = 0.5 * 0.1 * kDepth;  // half of column 2's plan area
    for (Index nx : {Index(2), Index(3)}) {
        EXPECT_NEAR(force[(3 * 4 + nx) * 2 + 1], -q * share, 1e-9) << "node " << nx << " of row 3, the cell's top";
        EXPECT_EQ(force[(4 * 4 + nx) * 2 + 1], 0.0) << "node " << nx << " of row 4, above the sand";
    }
}

TEST(Surcharge, InAxisymmetryEachRingCarriesQTimesItsArea) {
    // a level surface on a cylinder of 3 cells' radius: every node of the surface's row carries q
    // times its footprint (the rings' areas, the axis node's included), q pi R^2 in all
    Grid<2> grid(IVec<2>{3, 4}, 0.1, 0.0, true, 2);
    SolidPoints<2> solid;
    std::vector<Index> cellStart(grid.numCells() + 1, 0);
    std::vector<double> x;
    for (Index c = 0; c < grid.numCells(); ++c) {
        cellStart[c + 1] = cellStart[c];
        if (c / 3 >= 2) continue;  // two rows of sand
        x.push_back(0.1 * (c % 3) + 0.05);
        x.push_back(0.1 * (c / 3) + 0.05);
        ++cellStart[c + 1];
    }
    resizePoints(solid, x.size() / 2);
    solid.x = x;
    for (std::size_t p = 0; p < solid.size(); ++p) solid.volume[p] = 0.1 * grid.pointFootprint(&solid.x[p * 2], 1);
    const double q = 1000;
    std::vector<double> force(grid.numNodes() * 2, 0.0);
    addSurcharge(grid, solid, cellStart, 1, q, force);
    double total = 0;
    for (Index i = 0; i < grid.numNodes(); ++i) {
        const bool surface = i / 4 == 2;
        EXPECT_NEAR(force[i * 2 + 1], surface ? -q * grid.nodeFootprint(i) : 0.0, 1e-9 * q) << "node " << i;
        EXPECT_EQ(force[i * 2], 0.0);
        total += force[i * 2 + 1];
    }
    EXPECT_NEAR(total, -q * std::acos(-1.0) * 0.09, 1e-9 * q);
}

TEST(Surcharge, AColumnWithoutSandCarriesNothing) {
    UnevenSand s;
    // rebuild the point list without column 0
    SolidPoints<2> solid;
    std::vector<Index> start(s.grid.numCells() + 1, 0);
    std::vector<double> x;
    for (Index c = 0; c < s.grid.numCells(); ++c) {
        start[c + 1] = start[c];
        if (c % 3 == 0) continue;
        for (Index p = s.cellStart[c]; p < s.cellStart[c + 1]; ++p) {
            x.push_back(s.solid.x[p * 2]);
            x.push_back(s.solid.x[p * 2 + 1]);
            ++start[c + 1];
        }
    }
    resizePoints(solid, x.size() / 2);
    solid.x = x;
    for (std::size_t p = 0; p < solid.size(); ++p) solid.volume[p] = 0.1 * 0.1 * kDepth;
    std::vector<double> force(s.grid.numNodes() * 2, 0.0);
    addSurcharge(s.grid, solid, start, 1, 1000.0, force);
    double total = 0;
    for (double f : force) total += f;
    // columns 1 and 2 carry their own q times 0.1 m x 0.5 m; column 0 nothing
    EXPECT_NEAR(total, -1000.0 * 2 * 0.1 * kDepth, 1e-9);
    EXPECT_EQ(force[(0 * 4 + 0) * 2 + 1], 0.0);
}
