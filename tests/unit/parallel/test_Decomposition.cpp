// The grid's cut over MPI ranks (parallel/Decomposition.hpp): every cell in one block, the
// blocks' points balanced, the ghost layers as wide as the shape functions reach, columns kept
// whole where that costs nothing, and a clear refusal where the grid cannot be cut so finely.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "parallel/Decomposition.hpp"
#include "solver/RunSize.hpp"

using namespace qs;

namespace {

CaseConfig shipped(const std::string& name, std::vector<CaseOverride> overrides = {}) {
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/" + name, overrides);
}

/// The blocks tile the grid: their cells and owned nodes add up to the grid's, their points to
/// RunSize's count of the case.
void expectTiles(const Decomposition& d, const CaseConfig& config) {
    const RunSize size = estimateRunSize(config);
    Index cells = 0, nodes = 0;
    double solid = 0, liquid = 0;
    for (const auto& b : d.blocks) {
        cells += b.cells;
        nodes += b.nodes;
        solid += b.solidPoints;
        liquid += b.liquidPoints;
    }
    EXPECT_EQ(cells, size.cells);
    EXPECT_EQ(nodes, size.nodes);
    EXPECT_NEAR(solid, double(size.solidPoints), 1e-9 * double(size.solidPoints));
    EXPECT_NEAR(liquid, double(size.liquidPoints), 1e-6 * double(size.liquidPoints) + 1);
    EXPECT_EQ(static_cast<int>(d.blocks.size()), d.ranks);
}

}  // namespace

TEST(Decomposition, OneRankIsTheWholeGrid) {
    const CaseConfig c = shipped("piping2D");
    const Decomposition d = decompose(c, 1);
    ASSERT_EQ(d.blocks.size(), 1u);
    EXPECT_EQ(d.blocks[0].ghostNodes, 0);
    EXPECT_DOUBLE_EQ(d.imbalance(), 1.0);
    expectTiles(d, c);
}

// A 1D column is not cut for a run (its only column would be cut across the height: refused,
// saying so); priced for the scaling model, its cuts follow the points (sand rows hold more than
// free water, the air none), not the rows.
TEST(Decomposition, AColumnIsCutOnlyInTheModelWhereItsPointsAre) {
    const CaseConfig c = shipped("verification/terzaghi");
    try {
        decompose(c, 2);
        FAIL() << "a 1D column cut over 2 ranks";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("a 1D column (grid.dimension = 1) cannot be cut over 2 ranks"),
                  std::string::npos) << e.what();
    }
    EXPECT_EQ(decompose(c, 1).blocks.size(), 1u);
    for (int ranks : {2, 3}) {
        const Decomposition d = decomposeAs(c, {ranks, 1, 1});
        EXPECT_EQ(d.parts[0], ranks);  // the only axis of a 1D grid
        EXPECT_EQ(d.parts[1] * d.parts[2], 1);
        expectTiles(d, c);
        EXPECT_LT(d.imbalance(), 1.1) << ranks << " ranks";
        for (const auto& b : d.blocks) {
            EXPECT_GE(b.cellEnd[0] - b.cellBegin[0], d.ghostLayers + 1);
            EXPECT_LE(b.ghostNodes, 2 * d.ghostLayers + 1);  // a cell each side, the cut's node above
        }
    }
}

// piping2D (13 x 49 cells): a block owns the nodes at its cells' lower corners and keeps a ghost
// cell beside each cut with its nodes: below a cut that is two node layers (the cut's, owned
// above it, and the ghost cell's far one), above it one. A layer is a node column of 50 in bands
// of whole columns, a node row of 14 in slabs across the height. A run takes the bands.
TEST(Decomposition, APlaneBedIsCutIntoBandsOfWholeColumns) {
    const CaseConfig c = shipped("piping2D");
    const Index rows = static_cast<Index>(std::llround(c.column.top / c.grid.cellSize));
    for (int ranks : {2, 3}) {
        const Decomposition bands = decomposeAs(c, {ranks, 1, 1}), slabs = decomposeAs(c, {1, ranks, 1});
        expectTiles(bands, c);
        expectTiles(slabs, c);
        EXPECT_TRUE(bands.columnsWhole());
        EXPECT_FALSE(slabs.columnsWhole());
        for (int r = 0; r < ranks; ++r) {
            const Index layers = (r > 0 ? 1 : 0) + (r < ranks - 1 ? 2 : 0);
            EXPECT_EQ(bands.blocks[r].ghostNodes, layers * (rows + 1)) << "rank " << r << " of " << ranks;
            EXPECT_EQ(slabs.blocks[r].ghostNodes, layers * 14) << "rank " << r << " of " << ranks;
        }
        EXPECT_LT(bands.imbalance(), 1.0 + 1.0 / 6) << ranks;  // 13 columns: 7 + 6, or 5 + 4 + 4 (4.33 a rank)
        EXPECT_LT(slabs.imbalance(), 1.05) << ranks;            // the rows follow the points
        const Decomposition chosen = decompose(c, ranks);
        EXPECT_EQ(chosen.parts, bands.parts) << ranks;
        EXPECT_EQ(decompositionPrice(chosen), decompositionPrice(bands)) << ranks;
    }
}

// A bed much wider than tall: bands of whole columns cost far fewer ghosts, and are taken.
TEST(Decomposition, AWideBedIsCutIntoBandsOfWholeColumns) {
    const CaseConfig c = shipped("piping2D", {parseOverride("grid.width=0.62")});  // 100 columns
    const Decomposition d = decompose(c, 2);
    EXPECT_TRUE(d.columnsWhole());
    EXPECT_EQ(d.parts[0], 2);
    expectTiles(d, c);
}

// uGIMP's support reaches a cell further: two ghost cells beside each cut (three node layers
// below it, two above), and blocks of at least three cells.
TEST(Decomposition, GimpKeepsTwoGhostLayers) {
    const CaseConfig c = shipped("piping2D", {parseOverride("grid.shape_functions=\"gimp\"")});
    const Decomposition d = decomposeAs(c, {2, 1, 1});
    EXPECT_EQ(d.ghostLayers, 2);
    const Index rows = static_cast<Index>(std::llround(c.column.top / c.grid.cellSize));
    EXPECT_EQ(d.blocks[0].ghostNodes, 3 * (rows + 1));
    EXPECT_EQ(d.blocks[1].ghostNodes, 2 * (rows + 1));
    EXPECT_NO_THROW(decomposeAs(c, {4, 1, 1}));  // 13 columns: 3 + 3 + 3 + 4
    EXPECT_THROW(decomposeAs(c, {5, 1, 1}), Error);
}

// A 3D bed on 4 ranks: every process grid tiles the bed, and the one a run takes is the cheapest
// of whole columns (2 x 2: fewer ghosts than four slices); ranks are numbered axis 0 fastest.
TEST(Decomposition, A3DBedTakesTheCheapestGridOfWholeColumns) {
    const CaseConfig c = shipped("piping3D");
    const Decomposition d = decompose(c, 4);
    expectTiles(d, c);
    EXPECT_TRUE(d.columnsWhole());
    double cheapest = 1e300;
    for (const std::array<int, 3>& parts : {std::array<int, 3>{4, 1, 1}, std::array<int, 3>{1, 4, 1},
                                            std::array<int, 3>{1, 1, 4}, std::array<int, 3>{2, 2, 1},
                                            std::array<int, 3>{2, 1, 2}, std::array<int, 3>{1, 2, 2}}) {
        const Decomposition other = decomposeAs(c, parts);
        expectTiles(other, c);
        if (other.columnsWhole()) cheapest = std::min(cheapest, decompositionPrice(other));
    }
    EXPECT_EQ(decompositionPrice(d), cheapest);
    EXPECT_EQ(d.parts, (std::array<int, 3>{2, 2, 1}));
    const Decomposition quarters = decomposeAs(c, {2, 2, 1});
    EXPECT_EQ(quarters.rankOf({1, 1, 0}), 3);
    EXPECT_EQ(quarters.blocks[3].cellBegin[0], quarters.blocks[1].cellBegin[0]);
    EXPECT_EQ(quarters.blocks[3].cellBegin[1], quarters.blocks[2].cellBegin[1]);
}

// More ranks than the grid can be cut into: refused, naming the file, the grid and the way out.
TEST(Decomposition, MoreRanksThanTheGridHoldsIsRefused) {
    const CaseConfig c = shipped("piping2D");
    try {
        decompose(c, 1000);
        FAIL() << "1000 ranks accepted for 13 x 49 cells";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("piping2D/case.toml"), std::string::npos) << m;
        EXPECT_NE(m.find("13 x 49 cells"), std::string::npos) << m;
        EXPECT_NE(m.find("cannot be cut into 1000 blocks"), std::string::npos) << m;
        EXPECT_NE(m.find("fewer ranks"), std::string::npos) << m;
    }
    EXPECT_THROW(decompose(c, 0), Error);
    EXPECT_THROW(decomposeAs(c, {14, 1, 1}), Error);  // 13 columns
    EXPECT_THROW(decomposeAs(c, {2, 1, 2}), Error);   // a third axis in 2D
}

// The description `quicksand check` prints: the process grid and a line per rank.
TEST(Decomposition, DescribesEachRank) {
    const std::string text = describe(decompose(shipped("piping2D"), 2));
    EXPECT_NE(text.find("decomposition: 2 ranks, "), std::string::npos) << text;
    EXPECT_NE(text.find(" blocks (columns "), std::string::npos) << text;
    EXPECT_NE(text.find("\n     0 "), std::string::npos) << text;
    EXPECT_NE(text.find("\n     1 "), std::string::npos) << text;
}
