// The node solve's pieces (solver/NodeVelocities.hpp): the semi-implicit step's response to a
// pressure force, in its closed form, against the general node solve it stands for.
#include "solver/NodeVelocities.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace qs {
namespace {

// A component of every kind the node solve meets: each phase with or without mass, held or
// not, with a 1D gate's tube loss or not; masses, drag and porosity drawn over decades.
NodeComponent randomComponent(std::mt19937& random, int kind) {
    std::uniform_real_distribution<double> decades(-3.0, 3.0);
    auto spread = [&](double scale) { return scale * std::pow(10.0, decades(random)); };
    NodeComponent c;
    c.massS = (kind & 1) ? 0.0 : spread(1e-2);
    c.massL = (kind & 2) ? 0.0 : spread(1e-2);
    c.solidHeld = kind & 4;
    c.liquidHeld = kind & 8;
    c.tubeLoss = (kind & 16) ? spread(1.0) : 0.0;
    c.drag = spread(10.0);
    c.heldLiquidVelocity = spread(1e-3);
    return c;
}

// componentResponse is the node solve's response to a unit impulse on the mixture, shared as
// (1 - n) on the solid and n on the liquid: the difference of two node solves whose drag-free
// predictors differ by it (solveComponent is linear), held velocities and all.
TEST(NodeVelocities, TheResponseIsTheNodeSolvesOwnToAnImpulseOnTheMixture) {
    std::mt19937 random(24);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0;
    int freeBoth = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const int kind = trial % 32;
        const NodeComponent c = randomComponent(random, kind);
        const double dt = 1e-5 * std::pow(10.0, 2 * unit(random)), n = 0.3 + 0.6 * unit(random);
        const double vS1 = unit(random) - 0.5, vL1 = unit(random) - 0.5;
        const double kS = c.massS > 0 ? (1 - n) / c.massS : 0.0, kL = c.massL > 0 ? n / c.massL : 0.0;
        const PhaseVelocities base = solveComponent(c, dt, vS1, vL1);
        const PhaseVelocities pushed = solveComponent(c, dt, vS1 + kS, vL1 + kL);
        const PhaseVelocities r = componentResponse(c, dt, n);
        // each against the larger of the two solves it is the difference of
        const double scaleS = std::max({std::abs(pushed.solid), std::abs(base.solid), 1e-300});
        const double scaleL = std::max({std::abs(pushed.liquid), std::abs(base.liquid), 1e-300});
        const double errorS = std::abs(r.solid - (pushed.solid - base.solid)) / scaleS;
        const double errorL = std::abs(r.liquid - (pushed.liquid - base.liquid)) / scaleL;
        worst = std::max({worst, errorS, errorL});
        ASSERT_LT(errorS, 1e-12) << "kind " << kind << " trial " << trial;
        ASSERT_LT(errorL, 1e-12) << "kind " << kind << " trial " << trial;
        if (c.massS > 0 && c.massL > 0 && !c.solidHeld && !c.liquidHeld) ++freeBoth;
    }
    EXPECT_GT(freeBoth, 1000);  // the closed form's branch was exercised
    RecordProperty("worst_relative_error", std::to_string(worst));
}

// Where both phases move, the closed form conserves the impulse: M_S r_S + M_L r_L = 1 (drag
// moves momentum between the phases, it does not make any).
TEST(NodeVelocities, TheResponseOfTwoFreePhasesCarriesTheWholeImpulse) {
    std::mt19937 random(6);
    for (int trial = 0; trial < 1000; ++trial) {
        const NodeComponent c = randomComponent(random, 0);
        const PhaseVelocities r = componentResponse(c, 1e-4, 0.4);
        EXPECT_NEAR(c.massS * r.solid + c.massL * r.liquid, 1.0, 1e-13) << "trial " << trial;
    }
}

}  // namespace
}  // namespace qs
