// PermeabilityLaw: the three modes of physics.md section 1 and the Ergun factor.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/ClosedForms.hpp"
#include "physics/Permeability.hpp"

using namespace qs;

TEST(Permeability, ConstantModeIgnoresPorosity) {
    PermeabilityLaw k;
    k.mode = PermeabilityMode::Constant;
    k.value = 1.49e-10;
    EXPECT_DOUBLE_EQ(k.kappa(0.3), 1.49e-10);
    EXPECT_DOUBLE_EQ(k.kappa(0.6), 1.49e-10);
}

TEST(Permeability, KozenyCarmanFromGrainSize) {
    PermeabilityLaw k;
    k.mode = PermeabilityMode::KozenyCarman;
    k.grainSize = 2.61e-4;
    k.A = 150;
    EXPECT_NEAR(k.kappa(0.38), 6.48e-11, 0.005e-11);  // physics.md: KC(D10) at n0
    EXPECT_DOUBLE_EQ(k.kappa(0.38), closed::kozenyCarman(2.61e-4, 0.38, 150));
}

TEST(Permeability, ScaledKozenyCarmanKeepsKappa0AtN0AndGrowsWithPorosity) {
    PermeabilityLaw k;
    k.mode = PermeabilityMode::KozenyCarmanScaled;
    k.value = 1.49e-10;
    k.n0 = 0.38;
    EXPECT_DOUBLE_EQ(k.kappa(0.38), 1.49e-10);
    const double ratio = (0.452 * 0.452 * 0.452 / (0.548 * 0.548)) / (0.38 * 0.38 * 0.38 / (0.62 * 0.62));
    EXPECT_NEAR(k.kappa(0.452), 1.49e-10 * ratio, 1e-22);
    // capped at n = 0.95
    EXPECT_DOUBLE_EQ(k.kappa(0.99), k.kappa(0.95));
}

TEST(Permeability, ErgunFactor) {
    PermeabilityLaw k;
    k.A = 150;
    k.B = 1.75;
    EXPECT_NEAR(k.ergunFactor(0.38), 0.6100, 1e-4);  // physics.md section 4, problem 6
    k.ergun = false;
    EXPECT_EQ(k.ergunFactor(0.38), 0.0);
}
