// Run-time conditions a user can cause end in a clear qs::Error, never a crash.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "solver/Run.hpp"

using namespace qs;

TEST(RunErrors, SolidReachingTheOverflowLevelIsNamedWhenAskedToStop) {
    // far above the critical gradient with no tube resistance the bed lifts off the filter
    // (the filter holds the solid, so the column tears at the base) and rises to the overflow;
    // column.sand_overflow = "stop" ends the run there (the default carries the sand out)
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
    c.column.sandOverflow = SandOverflow::Stop;
    c.column.waterLevel = c.sandTop() + c.grid.cellSize;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 4 * c.grid.cellSize;
    c.reservoir.head = c.column.waterLevel + 3.0 * 0.186;
    c.reservoir.headRate = 0;
    c.time.end = 5.0;
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    try {
        runCase(c, o);
        FAIL() << "the run should have stopped";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("overflow"), std::string::npos) << what;
        EXPECT_NE(what.find("solid points"), std::string::npos) << what;
    }
}

TEST(RunErrors, WaterDrainingBelowTheOverflowIsNamed) {
    // the overflow holds the water's surface at its level; a head falling below it drains the
    // column, and the run stops once the top two rows of cells lack a row of water, saying why
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/steady_seepage_coarse");
    c.reservoir.head = *c.column.overflowLevel;
    c.reservoir.headRate = -0.2;  // m/s: the head falls below the overflow at once
    c.time.end = 3.0;
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    try {
        runCase(c, o);
        FAIL() << "the run should have stopped";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("fell below the overflow level column.overflow_level"), std::string::npos) << what;
        EXPECT_NE(what.find("rows of water"), std::string::npos) << what;
    }
}

TEST(RunErrors, TimeStepAboveTheStableOneIsRejected) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
    c.time.dt = 1e-3;
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    try {
        runCase(c, o);
        FAIL() << "dt = 1e-3 s should be rejected";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("time.dt"), std::string::npos) << e.what();
    }
}

TEST(RunErrors, AnUnstableStepIsCaughtWhereItStartsWithWhatWhereAndWhen) {
    // a step six times the stable one (past the loader's courant <= 0.5, on purpose): the run
    // stops at the first point that outruns a cell per step, before anything turns non-finite.
    // (Four times, courant 2, was caught so until the cavitation limit kept its cavities: since,
    // the cavities soak up the unstable expansions and the top rows empty first, at t = 0.009 s,
    // stopped by the overflow's check instead)
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/steady_seepage_B");
    c.time.courant = 3.0;
    c.time.end = 1.0;
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    try {
        runCase(c, o);
        FAIL() << "the unstable run should have stopped";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("numerical failure at t = "), std::string::npos) << what;
        EXPECT_NE(what.find(" point "), std::string::npos) << what;
        EXPECT_NE(what.find("elevation"), std::string::npos) << what;
        EXPECT_NE(what.find("more than a cell per step"), std::string::npos) << what;
        EXPECT_NE(what.find("time.courant"), std::string::npos) << what;
        EXPECT_EQ(what.find("nan"), std::string::npos) << "caught only once non-finite: " << what;
        std::printf("%s\n", what.c_str());
    }
}
