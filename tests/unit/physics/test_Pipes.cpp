// The pipe measurement (physics/Pipes.hpp) on constructed cell states whose pipes are known.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/Constants.hpp"
#include "io/PipesTable.hpp"
#include "physics/Pipes.hpp"

using namespace qs;

namespace {

/// A solid bed: `nx` (x `ny` in 3D) columns, rows 1..sandRows of sand above a chamber row 0, no sand
/// above; each column lets 1e-6 m3/s through the filter except where `flux` says otherwise.
SandCells solidBed(int dimension, Index nx, Index ny, Index rows, Index sandRows) {
    SandCells s;
    s.dimension = dimension;
    s.cells[0] = nx;
    s.cells[1] = dimension == 3 ? ny : rows;
    if (dimension == 3) s.cells[2] = rows;
    s.h = 0.01;
    s.baseRow = 1;
    s.filterLevel = 0.01;
    s.state.assign(s.columns() * rows, CellSand::None);
    for (Index r = 1; r <= sandRows; ++r)
        for (Index k = 0; k < s.columns(); ++k) s.state[s.cell(k, r)] = CellSand::Solid;
    s.baseFlux.assign(s.columns(), 1e-6);
    s.surface.assign(s.columns(), s.filterLevel + sandRows * s.h);
    return s;
}

void empty(SandCells& s, Index column, Index fromRow, Index toRow) {
    for (Index r = fromRow; r <= toRow; ++r) s.state[s.cell(column, r)] = CellSand::None;
}

void fluidise(SandCells& s, Index column, Index fromRow, Index toRow) {
    for (Index r = fromRow; r <= toRow; ++r) s.state[s.cell(column, r)] = CellSand::Fluidised;
}

}  // namespace

TEST(Pipes, FindsAnInteriorPipeAndAWallPipeAndNothingElse) {
    // 8 columns, 10 sand rows (filter at z = 0.01 m):
    //   columns 2-3, rows 1-6: an interior pipe two cells wide, 6 cells tall, with more water
    //   column 7, rows 1-3: a wall pipe
    //   column 5, row 1: a patch on the filter one cell tall (not a pipe: it does not rise)
    //   column 0, rows 5-8: a fluidised pocket off the filter (not a pipe)
    //   column 4, row 7: touches the interior pipe only at a corner (not part of it)
    SandCells s = solidBed(2, 8, 1, 12, 10);
    fluidise(s, 2, 1, 6);
    fluidise(s, 3, 1, 5);
    fluidise(s, 7, 1, 3);
    fluidise(s, 5, 1, 1);
    fluidise(s, 0, 5, 8);
    fluidise(s, 4, 7, 7);
    s.baseFlux[2] = s.baseFlux[3] = 3e-6;
    // total: 6 columns at 1e-6 and 2 at 3e-6 = 12e-6 m3/s
    const PipeSurvey survey = findPipes(s);
    ASSERT_EQ(survey.pipes.size(), 2u);
    const Pipe& interior = survey.pipes[0];  // largest flux share first
    EXPECT_EQ(interior.cellCount, 11);
    EXPECT_NEAR(interior.x, (6 * 0.025 + 5 * 0.035) / 11, 1e-12);
    EXPECT_NEAR(interior.width, 11 * 0.01 / 6, 1e-12);  // 11 cells over 6 rows
    EXPECT_NEAR(interior.height, 0.06, 1e-12);          // the top of row 6 (z = 0.07) above the filter
    EXPECT_FALSE(interior.wall);
    EXPECT_NEAR(interior.fluxShare, 6.0 / 12, 1e-12);
    const Pipe& wall = survey.pipes[1];
    EXPECT_EQ(wall.cellCount, 3);
    EXPECT_NEAR(wall.x, 0.075, 1e-12);
    EXPECT_NEAR(wall.width, 0.01, 1e-12);
    EXPECT_NEAR(wall.height, 0.03, 1e-12);
    EXPECT_TRUE(wall.wall);
    EXPECT_NEAR(wall.fluxShare, 1.0 / 12, 1e-12);
    // every fluidised base cell: the two pipes and the patch
    EXPECT_NEAR(survey.fluidisedFluxShare, 8.0 / 12, 1e-12);
}

TEST(Pipes, ABedFluidisedAcrossItsBaseHasNoPipe) {
    SandCells s = solidBed(2, 6, 1, 12, 10);
    for (Index k = 0; k < 6; ++k) fluidise(s, k, 1, k == 3 ? 7 : 4);  // a front, uneven
    const PipeSurvey survey = findPipes(s);
    EXPECT_TRUE(survey.pipes.empty());
    EXPECT_NEAR(survey.fluidisedFluxShare, 1.0, 1e-12);
    // and a solid bed: none, and no fluidised flux
    const PipeSurvey solid = findPipes(solidBed(2, 6, 1, 12, 10));
    EXPECT_TRUE(solid.pipes.empty());
    EXPECT_EQ(solid.fluidisedFluxShare, 0.0);
}

TEST(Pipes, APipeWhoseFootIsAPocketOfWaterIsStillAPipeAndAPocketAloneIsNot) {
    // 8 columns, 10 sand rows:
    //   column 0, rows 1-2 without sand (its base emptied), rows 3-7 fluidised: a wall pipe whose
    //     foot is a pocket of water, 7 cells tall
    //   column 4, rows 1-2 without sand under solid sand: a cavity, not a pipe
    //   column 6, its sand washed out above row 3 (surface at row 3's top): rows 4 and up hold
    //     free water, not a pocket; row 1-3 solid: nothing
    SandCells s = solidBed(2, 8, 1, 14, 10);
    empty(s, 0, 1, 2);
    fluidise(s, 0, 3, 7);
    empty(s, 4, 1, 2);
    empty(s, 6, 4, 10);
    s.surface[6] = s.filterLevel + 3 * s.h;
    s.baseFlux[0] = 4e-6;  // total 11e-6
    const PipeSurvey survey = findPipes(s);
    ASSERT_EQ(survey.pipes.size(), 1u);
    const Pipe& p = survey.pipes[0];
    EXPECT_EQ(p.cellCount, 7);
    EXPECT_NEAR(p.x, 0.005, 1e-12);
    EXPECT_NEAR(p.height, 0.07, 1e-12);
    EXPECT_TRUE(p.wall);
    EXPECT_NEAR(p.fluxShare, 4.0 / 11, 1e-12);
    // the open base cells joined to fluidised sand: the pipe's pocket, not the cavity
    EXPECT_NEAR(survey.fluidisedFluxShare, 4.0 / 11, 1e-12);
    // without the columns' surfaces nothing is a pocket: the fluidised part no longer touches
    // the filter, and no pipe is found
    s.surface.clear();
    EXPECT_TRUE(findPipes(s).pipes.empty());
}

TEST(Pipes, APlugLiftedOffTheFilterIsNeitherAPipeNorFluidised) {
    // the whole base row without sand under a solid bed: a cavity, no fluidised sand anywhere
    SandCells s = solidBed(2, 6, 1, 12, 8);
    for (Index k = 0; k < 6; ++k) empty(s, k, 1, 1);
    const PipeSurvey survey = findPipes(s);
    EXPECT_TRUE(survey.pipes.empty());
    EXPECT_EQ(survey.fluidisedFluxShare, 0.0);
    // one column of it fluidised above the cavity: the whole base is then open and joined to it
    fluidise(s, 2, 2, 8);
    EXPECT_NEAR(findPipes(s).fluidisedFluxShare, 1.0, 1e-12);
}

TEST(Pipes, FreeWaterAboveTheBedOrUnderSandAfloatIsNoPocket) {
    // a fluidised channel through the whole bed (rows 1-6) to its surface, free water above, and
    // sand thrown up afloat across the column at row 10 (its surface read from the highest solid
    // point, row 10's top): the free water under it is not a pocket, so the pipe ends at the bed's
    // top (6 cells, 0.06 m) instead of taking the free water (30 cells, 0.09 m)
    for (int D : {2, 3}) {
        const Index nx = D == 3 ? 4 : 8, ny = D == 3 ? 4 : 1;
        SandCells s = solidBed(D, nx, ny, 14, 6);
        const Index channel = D == 3 ? 1 * nx + 1 : 3;
        fluidise(s, channel, 1, 6);
        const PipeSurvey bare = findPipes(s);  // no raft: the free water above is not a pocket
        ASSERT_EQ(bare.pipes.size(), 1u) << D << "D";
        EXPECT_EQ(bare.pipes[0].cellCount, 6) << D << "D";
        for (Index k = 0; k < s.columns(); ++k) {
            s.state[s.cell(k, 10)] = CellSand::Solid;
            s.surface[k] = s.filterLevel + 10 * s.h;
        }
        const PipeSurvey afloat = findPipes(s);
        ASSERT_EQ(afloat.pipes.size(), 1u) << D << "D";
        EXPECT_EQ(afloat.pipes[0].cellCount, 6) << D << "D";
        EXPECT_NEAR(afloat.pipes[0].height, 0.06, 1e-12) << D << "D";
        EXPECT_NEAR(afloat.fluidisedFluxShare, 1.0 / static_cast<double>(s.columns()), 1e-12) << D << "D";
        // the raft landed on the bed (rows 7-9 sand): now it is the bed's, and a pocket under it
        // beside the channel (row 7 of the channel's neighbour emptied) joins the pipe
        for (Index k = 0; k < s.columns(); ++k)
            for (Index r = 7; r <= 9; ++r) s.state[s.cell(k, r)] = CellSand::Solid;
        fluidise(s, channel, 7, 9);
        empty(s, channel + 1, 7, 7);
        const PipeSurvey landed = findPipes(s);
        ASSERT_EQ(landed.pipes.size(), 1u) << D << "D";
        EXPECT_EQ(landed.pipes[0].cellCount, 10) << D << "D";
        EXPECT_NEAR(landed.pipes[0].height, 0.09, 1e-12) << D << "D";
    }
}

TEST(Pipes, InThreeDimensionsWidthIsTheDiameterOfTheMeanSectionAndEveryWallCounts) {
    // 6 x 5 columns: a 2 x 2 pipe in the middle over rows 1-4, a 1 x 1 pipe against the wall y = 0
    // over rows 1-2, and an L-shaped one whose cells touch x = max
    SandCells s = solidBed(3, 6, 5, 10, 8);
    auto column = [&](Index i, Index j) { return j * 6 + i; };
    for (Index i : {2, 3})
        for (Index j : {1, 2}) fluidise(s, column(i, j), 1, 4);
    fluidise(s, column(1, 0), 1, 2);
    fluidise(s, column(4, 4), 1, 3);
    fluidise(s, column(5, 4), 3, 3);
    const PipeSurvey survey = findPipes(s);
    ASSERT_EQ(survey.pipes.size(), 3u);
    // equal flux per column: the biggest base first
    const Pipe& middle = survey.pipes[0];
    EXPECT_EQ(middle.cellCount, 16);
    EXPECT_NEAR(middle.x, 0.03, 1e-12);
    EXPECT_NEAR(middle.y, 0.02, 1e-12);
    EXPECT_NEAR(middle.width, std::sqrt(4 * 4 * 1e-4 / kPi), 1e-12);  // a 2 x 2 section
    EXPECT_NEAR(middle.height, 0.04, 1e-12);
    EXPECT_FALSE(middle.wall);
    EXPECT_NEAR(middle.fluxShare, 4.0 / 30, 1e-12);
    int walls = 0;
    for (const Pipe& p : survey.pipes) walls += p.wall;
    EXPECT_EQ(walls, 2);
}

TEST(Pipes, TheAxisOfAnAxisymmetricGridIsNotAWall) {
    SandCells s = solidBed(2, 6, 1, 12, 10);
    s.axisymmetric = true;
    fluidise(s, 0, 1, 5);  // a pipe on the axis
    fluidise(s, 5, 1, 2);  // one at the outer wall
    const PipeSurvey survey = findPipes(s);
    ASSERT_EQ(survey.pipes.size(), 2u);
    for (const Pipe& p : survey.pipes) EXPECT_EQ(p.wall, p.x > 0.03) << "pipe at x = " << p.x;
}

TEST(Pipes, PipesCsvHasOneLinePerPipeAndOneEmptyLineWithout) {
    SandCells s = solidBed(2, 8, 1, 12, 10);
    fluidise(s, 2, 1, 6);
    fluidise(s, 7, 1, 3);
    const auto columns = pipesColumns(2);
    const auto rows = pipesRows(1.5, 2, findPipes(s));
    ASSERT_EQ(rows.size(), 2u);
    auto at = [&](std::size_t row, const std::string& name) {
        for (std::size_t k = 0; k < columns.size(); ++k)
            if (columns[k] == name) return rows[row].at(k);
        ADD_FAILURE() << "no column " << name;
        return 0.0;
    };
    EXPECT_EQ(at(0, "time"), 1.5);
    EXPECT_EQ(at(0, "pipes"), 2);
    EXPECT_EQ(at(1, "pipe"), 2);
    EXPECT_NEAR(at(0, "x"), 0.025, 1e-12);
    EXPECT_NEAR(at(0, "height"), 0.06, 1e-12);
    EXPECT_EQ(at(0, "wall"), 0);
    EXPECT_EQ(at(1, "wall"), 1);
    EXPECT_NEAR(at(0, "flux_share"), 1.0 / 8, 1e-12);
    EXPECT_NEAR(at(1, "fluidised_flux_share"), 2.0 / 8, 1e-12);
    // no pipes: one line, pipe 0, the pipe's columns nan; 3D adds y
    const auto none = pipesRows(2.0, 3, PipeSurvey{});
    ASSERT_EQ(none.size(), 1u);
    ASSERT_EQ(none[0].size(), pipesColumns(3).size());
    EXPECT_EQ(none[0][1], 0);
    EXPECT_EQ(none[0][3], 0);
    EXPECT_TRUE(std::isnan(none[0][4]));
}
