// The overflow's weir (boundary/Overflow.hpp): a liquid point past the rim spills, as a level
// surface spills over it, except the crest water the two rows under the rim need once they lack
// more than half a row (a level surface lacks that much when its top layer has just spilled).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "boundary/Overflow.hpp"
#include "grid/Grid.hpp"
#include "points/LiquidPoints.hpp"
#include "points/SolidPoints.hpp"

using namespace qs;

namespace {

constexpr double kH = 0.01, kRho = 1000.0;
constexpr int kColumns = 4, kRows = 6, kPerCell = 2;
constexpr Index kRimRow = 4;                   // the rim on the node row z = 0.04 m
constexpr double kRim = kRimRow * kH;

// Free water of 4 x 6 cells, 2 x 2 points a cell, out of plane 1 m: each point holds h^2 / 4 of water.
struct Column {
    Grid<2> grid{IVec<2>{kColumns, kRows}, kH, kColumns * kH, false, kPerCell};
    LiquidPoints<2> liquid;
    std::vector<char> drop;
    std::vector<Index> order;
    double grains = 0;  // m3, the sand's grains in the two rows under the rim

    void add(double x, double z, double size = 1.0) {
        const double V = size * kH * kH / (kPerCell * kPerCell);
        liquid.x.insert(liquid.x.end(), {x, z});
        liquid.v.insert(liquid.v.end(), {0.0, 0.0});
        liquid.mass.push_back(kRho * V);
        liquid.volume.push_back(V);
        liquid.pressure.push_back(0.0);
        liquid.state.push_back(kSubmergedLiquid);
        liquid.cavity.push_back(0.0);
    }
    /// a layer of points (centres at z) over the columns of points [from, to)
    void layer(double z, int from, int to) {
        for (int i = from; i < to; ++i) add((i + 0.5) * kH / kPerCell, z);
    }
    /// water up to the rim, layers at rim - h/4, rim - 3h/4, ..., without the top `trough`
    /// layers over the right half: a trough of trough / 4 rows
    void fillToRim(int trough = 0) {
        const int layers = kRimRow * kPerCell;
        for (int k = 0; k < layers; ++k)
            layer((k + 0.5) * kH / kPerCell, 0, k >= layers - trough ? kColumns * kPerCell / 2 : kColumns * kPerCell);
    }
    double spill() { return spillOverRim(grid, kRimRow, 2, 0, grains, kPerCell, kRho, liquid, drop, order); }
    double pointWater() const { return kH * kH / (kPerCell * kPerCell); }
    int countAbove(double z) const {
        int n = 0;
        for (std::size_t p = 0; p < liquid.size(); ++p) n += liquid.x[2 * p + 1] > z;
        return n;
    }
};

constexpr int kHalf = kColumns * kPerCell / 2;  // the points across half the width

}  // namespace

TEST(OverflowWeir, ALevelSurfaceAtTheRimSpillsNothing) {
    Column c;
    c.fillToRim();
    EXPECT_EQ(c.spill(), 0.0);
    EXPECT_EQ(c.liquid.size(), static_cast<std::size_t>(kColumns * kPerCell * kRimRow * kPerCell));
}

TEST(OverflowWeir, ALevelSurfaceHalfACellAboveTheRimSpillsItsLayer) {
    Column c;
    c.fillToRim();
    c.layer(kRim + kH / 4, 0, 2 * kHalf);  // a full layer over the rim
    const double spilled = c.spill();
    EXPECT_NEAR(spilled, 2 * kHalf * c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim), 0);
}

TEST(OverflowWeir, ACrestOverATroughOfHalfARowSpillsAsALevelSurfaceDoes) {
    Column c;
    c.fillToRim(2);                        // the right half's top row empty: half a row lacking
    c.layer(kRim + kH / 4, 0, kHalf);      // its water as a crest over the left half
    c.layer(kRim + 3 * kH / 4, 0, kHalf);
    EXPECT_NEAR(c.spill(), 2 * kHalf * c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim), 0);
}

TEST(OverflowWeir, ACrestOverADeeperTroughFallsBackIntoItUpToWhatItLacksBeyondHalfARow) {
    Column c;
    c.fillToRim(3);                        // three layers over the right half: 0.75 rows lacking
    c.layer(kRim + kH / 4, 0, kHalf);      // a crest of two layers over the left half
    c.layer(kRim + 3 * kH / 4, 0, kHalf);
    // a quarter row is held, the lower layer; cutting every point past the rim spilled both
    EXPECT_NEAR(c.spill(), kHalf * c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim + kH / 2), 0);
    EXPECT_EQ(c.countAbove(kRim), kHalf);
}

TEST(OverflowWeir, SprayMoreThanACellAboveTheRimSpillsWhateverTheRowsLack) {
    Column c;
    c.fillToRim(3);
    c.add(0.5 * kH, kRim + 1.5 * kH);     // a drop thrown a cell and a half over the rim
    c.add(0.5 * kH, kRim + 0.5 * kH);     // and one within a cell of it
    EXPECT_NEAR(c.spill(), c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim + kH), 0);
    EXPECT_EQ(c.countAbove(kRim), 1);
}

TEST(OverflowWeir, ACrestStraddlingTheRimCountsWhollyAsCrest) {
    Column c;
    c.fillToRim(3);                        // 0.75 rows lacking: a quarter row, four points, to hold
    c.layer(kRim + kH / 8, 0, kHalf);      // four points whose water reaches an eighth of a cell under the rim
    EXPECT_EQ(c.spill(), 0.0);             // counted as present below the rim, one would have spilled
    EXPECT_EQ(c.countAbove(kRim), kHalf);
}

TEST(OverflowWeir, HoldingStopsAtTheFirstPointThatDoesNotFit) {
    Column c;
    c.fillToRim(3);                        // room to hold four points' water
    c.add(0.5 * kH, kRim + 0.1 * kH, 10);  // a suspension's point of ten: does not fit
    c.add(1.5 * kH, kRim + 0.3 * kH);      // a small one above it would, but holding has stopped
    EXPECT_NEAR(c.spill(), 11 * c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim), 0);
}

TEST(OverflowWeir, WaterBelowTheRimAfterTheSpilledPointsStaysInOrder) {
    Column c;
    c.fillToRim();
    c.layer(kRim + kH / 4, 0, 2 * kHalf);  // a level layer over the rim: spills
    c.add(0.5 * kH, 0.001);                // then, as the chamber appends it, new water at the bottom
    c.add(1.5 * kH, 0.002);
    const std::size_t before = c.liquid.size();
    EXPECT_NEAR(c.spill(), 2 * kHalf * c.pointWater(), 1e-15);
    ASSERT_EQ(c.liquid.size(), before - 2 * kHalf);
    EXPECT_EQ(c.liquid.x[2 * (c.liquid.size() - 2) + 1], 0.001);
    EXPECT_EQ(c.liquid.x[2 * (c.liquid.size() - 1) + 1], 0.002);
}

// A bed risen to the rim (a boil's sand, an expanded bed): its grains fill the rows the water does
// not, so the rows lack nothing and a crest over them spills as over a level surface. Counted as
// lacking water, the rows under a sand of n = 0.625 read 0.75 rows short and the weir held a layer
// of crest water above the rim, where no water stands on the grid.
TEST(OverflowWeir, SandRisenToTheRimLeavesNoRoomForCrestWater) {
    const double n = 0.625;
    Column c;
    SolidPoints<2> sand;
    for (int k = 0; k < kRimRow * kPerCell; ++k) {
        const bool inSand = k >= (kRimRow - 2) * kPerCell;  // the two rows under the rim
        for (int i = 0; i < kColumns * kPerCell; ++i) {
            const double x = (i + 0.5) * kH / kPerCell, z = (k + 0.5) * kH / kPerCell;
            c.add(x, z, inSand ? n : 1.0);  // the water in the sand's pores
            if (!inSand) continue;
            sand.x.insert(sand.x.end(), {x, z});
            sand.volume.push_back(kH * kH / (kPerCell * kPerCell));
            sand.porosity.push_back(n);
        }
    }
    c.grains = grainsBetween(c.grid, sand, 0, static_cast<Index>(sand.porosity.size()), kRim - 2 * kH, kRim, kPerCell);
    EXPECT_NEAR(c.grains, 2 * (1 - n) * kColumns * kH * kH, 1e-15);  // 0.75 rows of grains
    c.layer(kRim + kH / 4, 0, kHalf);  // a crest of two layers over the left half
    c.layer(kRim + 3 * kH / 4, 0, kHalf);
    EXPECT_NEAR(c.spill(), 2 * kHalf * c.pointWater(), 1e-15);
    EXPECT_EQ(c.countAbove(kRim), 0);
}
