// Drift-flux closed forms against the reference numbers of physics.md section 4, problems 7
// and 9 (P0 data, Kozeny-Carman from D = 0.261 mm with Ergun A = 150, B = 1.75).
#include <gtest/gtest.h>

#include "P0Sand.hpp"
#include "physics/DriftFlux.hpp"

using namespace qs;

using test::p0Sand;

TEST(DriftFlux, BedExpansionOfProblem7) {
    const auto f = p0Sand();
    const double Umf = f.equilibriumFlux(0.38);
    EXPECT_NEAR(Umf, 7.28e-4, 0.005e-4);
    EXPECT_NEAR(f.equilibriumFlux(0.452), 1.380e-3, 0.002e-3);
    const auto e = closed::bedExpansion(f, 0.38, Umf, 1.380e-3, 0.186);
    EXPECT_NEAR(e.expandedPorosity, 0.452, 5e-4);
    EXPECT_NEAR(e.frontSpeed, 5.61e-3, 0.01e-3);
    EXPECT_NEAR(e.finalHeight, 0.2104, 0.0001);
    EXPECT_NEAR(e.plugSpeed, 1.380e-3 - Umf, 1e-12);
}

TEST(DriftFlux, BatchSettlingOfProblem9) {
    const auto b = closed::batchSettling(p0Sand(), 0.55, 0.41, 0.186);
    EXPECT_NEAR(b.topSpeed, 2.986e-3, 0.002e-3);
    EXPECT_NEAR(b.frontSpeed, 9.60e-3, 0.01e-3);
    EXPECT_NEAR(b.meetingTime, 14.8, 0.05);
    EXPECT_NEAR(b.finalHeight, 0.1419, 0.0001);
}

TEST(DriftFlux, EquilibriumPorosityInvertsTheFlux) {
    const auto f = p0Sand();
    for (double n : {0.35, 0.4, 0.5, 0.6, 0.7}) EXPECT_NEAR(f.equilibriumPorosity(f.equilibriumFlux(n)), n, 1e-9);
}
