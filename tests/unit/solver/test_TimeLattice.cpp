// TimeLattice: the step and the coupling window fitted so that outputs fall on the times asked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "case/CaseLoader.hpp"
#include "solver/Run.hpp"
#include "solver/RunSize.hpp"
#include "solver/TimeLattice.hpp"

using namespace qs;

namespace {
CaseConfig lumpedColumn() { return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/deltaresColumnLumped"); }

/// The outputs' times of a run of `c` (in memory).
std::vector<double> outputTimes(const CaseConfig& c) {
    std::vector<double> times;
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    o.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) { times.push_back(s.time); };
    runCase(c, o);
    return times;
}
}  // namespace

TEST(TimeLattice, PartsOfAtMostTakeTheLeastWholeNumber) {
    EXPECT_EQ(partsOfAtMost(1.0, 0.3), 4);
    EXPECT_EQ(partsOfAtMost(1.0, 0.25), 4);     // exactly four
    EXPECT_EQ(partsOfAtMost(0.5, 0.01), 50);    // 0.5 / 0.01 is 50 to round-off, not 51
    EXPECT_EQ(partsOfAtMost(0.3, 0.1), 3);      // 2.9999999999999996
    EXPECT_EQ(partsOfAtMost(0.5, 1.0), 1);      // a bound beyond the span: one part
    EXPECT_THROW(partsOfAtMost(0.0, 1.0), Error);
    EXPECT_EQ(partsOfAtMost(1.0, 1e-38), kMostParts);  // saturates (a fuzzed 1e70 Pa water)
}

TEST(TimeLattice, TheStepIsTheLargestBelowTheStableOneThatFillsTheOutputInterval) {
    CaseConfig c = lumpedColumn();
    c.time.outputInterval = 0.07;  // no multiple of the stable step
    const TimeLattice l = timeLattice(c);
    EXPECT_EQ(l.window, 0.0) << "no windowed model";
    EXPECT_LE(l.dt, l.stableDt);
    EXPECT_NEAR(double(l.stepsPerOutput) * l.dt, 0.07, 1e-15);
    // the largest such step: one step fewer would exceed the stable one
    EXPECT_GT(0.07 / double(l.stepsPerOutput - 1), l.stableDt);
    EXPECT_EQ(timeStep(c), l.dt) << "the solver's step is the lattice's";
    // a given time.dt is a bound as courant h / c is
    c.time.dt = 3e-5;
    const TimeLattice g = timeLattice(c);
    EXPECT_EQ(g.stableDt, 3e-5);
    EXPECT_EQ(g.stepsPerOutput, 2334);
    EXPECT_NEAR(g.dt, 0.07 / 2334, 1e-18);
}

TEST(TimeLattice, AWindowedModelsWindowFillsTheOutputIntervalAndTheStepsTheWindow) {
    CaseConfig c = lumpedColumn();
    c.time.outputInterval = 0.07;
    c.coupling.window = 0.003;  // 23.3 windows an output
    const TimeLattice l = timeLattice(c, true);
    EXPECT_NEAR(l.window, 0.07 / 24, 1e-18);
    EXPECT_LE(l.window, c.coupling.window);
    EXPECT_NEAR(double(l.stepsPerWindow) * l.dt, l.window, 1e-18);
    EXPECT_EQ(l.stepsPerOutput, 24 * l.stepsPerWindow);
    EXPECT_LE(l.dt, l.stableDt);
    EXPECT_GT(l.window / double(l.stepsPerWindow - 1), l.stableDt);
    // a window longer than the output interval is cut to it
    c.coupling.window = 0.2;
    EXPECT_DOUBLE_EQ(timeLattice(c, true).window, 0.07);
    // the case's own windowed model is an OpenFOAM line
    c.reservoir.kind = ReservoirKind::OpenFoam;
    EXPECT_DOUBLE_EQ(timeLattice(c).window, 0.07);
}

// A standalone run's outputs fall on k x 0.07 s, to round-off of the step count times the step,
// also the last, some 17 500 steps in; before the fit each came at the first step past its time,
// up to a step (2e-5 s) late.
TEST(TimeLattice, AStandaloneRunsOutputsFallOnTheTimesAsked) {
    CaseConfig c = lumpedColumn();
    c.time.outputInterval = 0.07;
    c.time.end = 0.35;
    const std::vector<double> times = outputTimes(c);
    ASSERT_EQ(times.size(), 6u);
    for (std::size_t k = 0; k < times.size(); ++k) {
        EXPECT_NEAR(times[k], 0.07 * double(k), 1e-14) << k;
        char printed[32];
        std::snprintf(printed, sizeof printed, "%.9g", times[k]);  // as series.csv prints it
        char asked[32];
        std::snprintf(asked, sizeof asked, "%.9g", 0.07 * double(k));
        EXPECT_STREQ(printed, asked);
    }
}
