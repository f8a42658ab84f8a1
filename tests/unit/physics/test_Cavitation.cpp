// The pore water under tension (physics/Cavitation.hpp): the pressure is a function of the strain
// alone, p = max(p_min, p_0 - K eps), with the cavity c = max(0, (p_min - p_0) / K + eps), and
// waters mixed keep their volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

#include "physics/Cavitation.hpp"

using namespace qs;

namespace {

const double kStiffness = 5.32e7;  // Pa, a bulk modulus (2.5 times the paper's softened water)
const double kLimit = 0.0;                // Pa, gauge

}  // namespace

TEST(Cavitation, AboveTheLimitTheWaterIsPressedAsBefore) {
    const CavitatingWater w = pressWater({1000.0, 0.0}, -400.0, kStiffness, kLimit);
    EXPECT_DOUBLE_EQ(w.pressure, 600.0);
    EXPECT_EQ(w.cavity, 0.0);
}

TEST(Cavitation, BeyondTheLimitACavityOpensAndACompressionClosesItBeforePressing) {
    // from 1000 Pa, an expansion that would take it to -500 Pa: the limit, and a cavity of 500 Pa's strain
    CavitatingWater w = pressWater({1000.0, 0.0}, -1500.0, kStiffness, kLimit);
    EXPECT_EQ(w.pressure, kLimit);
    EXPECT_NEAR(w.cavity, 500.0 / kStiffness, 1e-18);
    // a compression of 300 Pa's strain closes part of it, at the limit
    w = pressWater(w, 300.0, kStiffness, kLimit);
    EXPECT_EQ(w.pressure, kLimit);
    EXPECT_NEAR(w.cavity, 200.0 / kStiffness, 1e-18);
    // one of 700 Pa's closes the rest and presses the water by 500 Pa
    w = pressWater(w, 700.0, kStiffness, kLimit);
    EXPECT_NEAR(w.pressure, 500.0, 1e-9);
    EXPECT_EQ(w.cavity, 0.0);
    // a clamp without the cavity would be at 700 Pa here, and 1000 + 700 after the cycle back
}

TEST(Cavitation, AlongAnyPathOfStrainThePressureIsThatOfTheStrainAlone) {
    // a random walk of strain increments through the limit and back, many times: after each, the
    // state is the closed form of the strain reached, and the walk closed returns it to its start
    const double p0 = 2000.0, limit = -500.0;
    CavitatingWater w{p0, 0.0};
    double eps = 0, worstP = 0, worstC = 0;
    std::uint32_t state = 7;
    auto next = [&]() { state = state * 1664525u + 1013904223u; return state / 4294967296.0 - 0.5; };
    int atLimit = 0;
    for (int k = 0; k < 20000; ++k) {
        const double step = 2e-6 * next() + (k < 10000 ? 1e-8 : -1e-8);  // drift out, then back
        eps += step;
        w = pressWater(w, -kStiffness * step, kStiffness, limit);
        const double p = std::max(limit, p0 - kStiffness * eps);
        const double c = std::max(0.0, (limit - p0) / kStiffness + eps);
        worstP = std::max(worstP, std::abs(w.pressure - p));
        worstC = std::max(worstC, std::abs(w.cavity - c));
        atLimit += w.pressure == limit;
    }
    EXPECT_GT(atLimit, 1000);             // the walk spent a good part at the limit
    EXPECT_LT(worstP, 1e-6);              // Pa: round-off only
    EXPECT_LT(worstC, 1e-12 * 1e-3);      // strain: round-off only
    // closed: a last step takes the strain back to 0, so the pressure returns to its start and
    // the cavity is shut (a clamp without the cavity would end above p0)
    w = pressWater(w, kStiffness * eps, kStiffness, limit);
    EXPECT_NEAR(w.pressure, p0, 1e-6);
    EXPECT_NEAR(w.cavity, 0.0, 1e-15);
}

TEST(Cavitation, WatersMixedKeepTheirVolume) {
    // A cell's water is the V-weighted mean strain of the points in it (solver/PorePressure.cpp).
    // A point from a cavity at the limit (volume 1) and one pressed to 3000 Pa (volume 2): the
    // pressed water fills the cavity and expands, and the total volume gained, c V - p V / K_L,
    // is what it was.
    const double K = 2.128e7, limit = -500.0;
    const CavitatingWater open{limit, 1e-3}, pressed{3000.0, 0.0};
    const double gained = 1.0 * waterStrain(open, K) + 2.0 * waterStrain(pressed, K);
    const CavitatingWater mixed = waterAtStrain(gained / 3.0, K, limit);
    // the volume gained, by hand: the cavity's and the limit's stretch, and the pressed water's
    // shrinkage; the mix's, from its state (not through waterStrain)
    EXPECT_NEAR(gained, 1.0 * (1e-3 - limit / K) + 2.0 * (-3000.0 / K), 1e-18);
    EXPECT_NEAR(3.0 * (mixed.cavity - mixed.pressure / K), gained, 1e-18);
    // closed form: the cavity outweighs what the pressed water gives when it expands to the
    // limit, 2 (3000 - limit) / K, so a smaller cavity remains, spread over all three volumes
    EXPECT_EQ(mixed.pressure, limit);
    EXPECT_NEAR(mixed.cavity, (1e-3 - 2 * (3000.0 - limit) / K) / 3.0, 1e-15);
    // averaging the pressures instead would have put the cell at (limit + 2 * 3000) / 3 = 1833 Pa,
    // the cavity's volume lost
    // a smaller cavity is closed by the pressed water, which is left pressed
    const CavitatingWater small{limit, 1e-5};
    const CavitatingWater closed = waterAtStrain((waterStrain(small, K) + 2.0 * waterStrain(pressed, K)) / 3.0, K, limit);
    EXPECT_EQ(closed.cavity, 0.0);
    EXPECT_NEAR(closed.pressure, (limit - K * 1e-5 + 2 * 3000.0) / 3.0, 1e-6);
}
