// Close packing's contact pressure (physics/ClosePacking.hpp): zero at and above n_min, the
// volumetric strain past close packing times M below it, and M from the step's wave speed.
#include <gtest/gtest.h>

#include "physics/ClosePacking.hpp"

using namespace qs;

TEST(ClosePacking, NoPressureAtOrAboveTheDensestPacking) {
    const ClosePacking p{0.32, 1e7};
    EXPECT_EQ(p.pressure(0.32), 0.0);
    EXPECT_EQ(p.pressure(0.45), 0.0);
    EXPECT_EQ(p.pressure(1.0), 0.0);
    EXPECT_EQ((ClosePacking{0.32, 0}).pressure(0.1), 0.0);  // not held
}

TEST(ClosePacking, BelowItTheStrainPastClosePackingTimesTheModulus) {
    const ClosePacking p{0.32, 1e7};
    // n = 0.31: the grains' volume fraction 0.69 against 0.68, a strain of 0.01 / 0.68
    EXPECT_NEAR(p.pressure(0.31), 1e7 * 0.01 / 0.68, 1e-6);
    EXPECT_NEAR(p.pressure(0.22), 10 * p.pressure(0.31), 1e-6);  // linear
}

TEST(ClosePacking, TheModulusMakesAPackingWaveAtTheGivenSpeed) {
    // c^2 = M / ((1 - n_min) rho_s) on the grains
    const double M = ClosePacking::modulusFor(50.0, 2650, 0.32);
    EXPECT_NEAR(M / ((1 - 0.32) * 2650), 2500.0, 1e-9);
}
