// Run-time conditions a user can cause end in a clear qs::Error, never a crash.
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "io/CaseLoader.hpp"
#include "solver/Run.hpp"

using namespace qs;

TEST(RunErrors, SolidReachingTheOverflowLevelIsNamed) {
    // far above the critical gradient with no tube resistance the bed lifts off the filter
    // (the filter holds the solid, so the column tears at the base) and rises to the overflow
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
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
