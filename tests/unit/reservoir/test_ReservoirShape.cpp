// Tests of reservoir/ReservoirShape (a reservoir's plan area by level) and core/PiecewiseLinear
// (the tables of case.toml), and of the head schedule of a constant-head reservoir.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "core/PiecewiseLinear.hpp"
#include "reservoir/ConstantHead.hpp"
#include "reservoir/LumpedReservoir.hpp"
#include "reservoir/ReservoirShape.hpp"

using namespace qs;

TEST(PiecewiseLinear, InterpolatesBetweenRowsAndHoldsBeyondThem) {
    const PiecewiseLinear f({{0, 0.30}, {60, 0.30}, {61, 0.32}});
    EXPECT_DOUBLE_EQ(f(-1), 0.30);
    EXPECT_DOUBLE_EQ(f(30), 0.30);
    EXPECT_DOUBLE_EQ(f(60.5), 0.31);
    EXPECT_DOUBLE_EQ(f(61), 0.32);
    EXPECT_DOUBLE_EQ(f(1e6), 0.32);
    EXPECT_THROW(PiecewiseLinear({{0, 1}, {0, 2}}), Error) << "x must increase strictly";
}

TEST(ReservoirShape, AVolumeTakenOutAndPutBackGivesTheLevelBackAcrossRows) {
    const ReservoirShape cone = ReservoirShape::table({{0.2, 1e-4}, {0.3, 4e-4}, {0.5, 9e-4}});
    // the volume between rows: trapezoids
    EXPECT_NEAR(cone.volumeBelow(0.3), 0.5 * (1e-4 + 4e-4) * 0.1, 1e-18);
    EXPECT_NEAR(cone.volumeBelow(0.5), 2.5e-5 + 0.5 * (4e-4 + 9e-4) * 0.2, 1e-18);
    for (double h : {0.1, 0.2, 0.25, 0.3, 0.41, 0.5, 0.7})
        EXPECT_NEAR(cone.levelOf(cone.volumeBelow(h)), h, 1e-14) << "h = " << h;
    // from 0.45 m out 1e-4 m3: through the row at 0.3 m into the segment below
    const double h = cone.levelAfter(0.45, 1.0e-4);
    EXPECT_NEAR(cone.volumeBelow(0.45) - cone.volumeBelow(h), 1.0e-4, 1e-17);
    EXPECT_LT(h, 0.3);
    // the area between rows is linear
    EXPECT_DOUBLE_EQ(cone.area(0.25), 2.5e-4);
    EXPECT_DOUBLE_EQ(cone.area(0.1), 1e-4) << "prismatic below the first row";
}

TEST(ReservoirShape, APrismaticReservoirFallsByVolumeOverArea) {
    const ReservoirShape tank = ReservoirShape::prismatic(0.0166);
    EXPECT_EQ(tank.levelAfter(0.52, 1e-4), 0.52 - 1e-4 / 0.0166) << "bit for bit as before";
    EXPECT_THROW(ReservoirShape::prismatic(0), Error);
    EXPECT_THROW(ReservoirShape::table({{0.2, 1e-4}}), Error) << "at least two rows";
    EXPECT_THROW(ReservoirShape::table({{0.2, 1e-4}, {0.3, -1e-4}}), Error);
}

TEST(ReservoirShape, TheLumpedReservoirLosesExactlyTheGateVolume) {
    LumpedReservoirParameters p;
    p.areaTable = {{0.2, 1e-4}, {0.3, 4e-4}, {0.5, 9e-4}};
    p.initialHead = 0.45;
    LumpedReservoir r(p);
    const ReservoirShape shape = ReservoirShape::table(p.areaTable);
    double out = 0;
    for (int k = 0; k < 1000; ++k) {
        r.advance(k * 1e-3, 1e-3, 1e-4);  // m3/s: 1e-4 m3 in all, of the 1.13e-4 it holds
        out += 1e-4 * 1e-3;
    }
    EXPECT_GT(r.head(), 0.2) << "still inside the table";
    EXPECT_LT(r.head(), 0.3) << "through the row at 0.3 m";
    EXPECT_NEAR(shape.volumeBelow(0.45) - shape.volumeBelow(r.head()), out, 1e-15);
    // drawn further, it runs empty below its lowest row: an error, not negative water
    auto drain = [&] {
        for (int k = 0; k < 1000; ++k) r.advance(1 + k * 1e-3, 1e-3, 1e-4);
    };
    EXPECT_THROW(drain(), Error);
}

TEST(ConstantHeadSchedule, TheHeadFollowsItsRows) {
    ConstantHead r(998.2, 9.81, PiecewiseLinear::Points{{0, 0.30}, {1, 0.30}, {1.5, 0.40}});
    EXPECT_DOUBLE_EQ(r.head(), 0.30);
    r.advance(1.0, 0.25, 0);
    EXPECT_DOUBLE_EQ(r.head(), 0.35);
    EXPECT_DOUBLE_EQ(r.gateLaw(2.0).staticPressure, 998.2 * 9.81 * 0.40);
    // the state is the time alone: restored, the head follows
    ConstantHead again(998.2, 9.81, PiecewiseLinear::Points{{0, 0.30}, {1, 0.30}, {1.5, 0.40}});
    again.restoreState(r.saveState());
    EXPECT_DOUBLE_EQ(again.head(), 0.35);
}
