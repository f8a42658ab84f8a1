// ConstantHead gate law, state round-trip, and the factory's choice of model.
#include "reservoir/ConstantHead.hpp"

#include "core/Error.hpp"
#include "case/CaseConfig.hpp"

#include <gtest/gtest.h>

#include <string>

namespace qs {
namespace {

constexpr double kRho = 998.2;
constexpr double kG = 9.81;

TEST(ConstantHead, GateLawIsTheHydrostaticHeadWithoutResistance) {
    const ConstantHead reservoir(kRho, kG, 0.5);
    const GateLaw law = reservoir.gateLaw(3.0);
    EXPECT_DOUBLE_EQ(law.staticPressure, kRho * kG * 0.5);  // 4896.171 Pa
    EXPECT_NEAR(law.staticPressure, 4896.171, 1e-9);
    EXPECT_EQ(law.resistance, 0.0);
    EXPECT_DOUBLE_EQ(law.pressure(1e-3), law.staticPressure);  // the flux does not matter
    EXPECT_EQ(reservoir.name(), "constant_head");
}

TEST(ConstantHead, HeadFollowsTheRamp) {
    ConstantHead reservoir(kRho, kG, 0.2, 1e-3);
    EXPECT_DOUBLE_EQ(reservoir.gateLaw(10.0).staticPressure, kRho * kG * (0.2 + 1e-3 * 10.0));
    EXPECT_DOUBLE_EQ(reservoir.head(), 0.2);
    reservoir.advance(0.0, 2.5, 7.0);  // any flux: the level ignores it
    EXPECT_DOUBLE_EQ(reservoir.head(), 0.2 + 1e-3 * 2.5);
}

TEST(ConstantHead, SaveRestoreRoundTrip) {
    ConstantHead reservoir(kRho, kG, 0.2, 1e-3);
    reservoir.advance(0.0, 1.0, 1e-4);
    const std::vector<double> saved = reservoir.saveState();
    const double headBefore = reservoir.head();
    reservoir.advance(1.0, 4.0, 1e-4);
    EXPECT_NE(reservoir.head(), headBefore);
    reservoir.restoreState(saved);
    EXPECT_DOUBLE_EQ(reservoir.head(), headBefore);
    EXPECT_EQ(reservoir.saveState(), saved);
    EXPECT_THROW(reservoir.restoreState({1.0, 2.0}), Error);
}

CaseConfig constantHeadCase() {
    CaseConfig config;
    config.gravity = 9.806;
    config.liquid.density = 1000.0;
    config.reservoir.kind = ReservoirKind::ConstantHead;
    config.reservoir.head = 0.4;
    config.reservoir.headRate = 0.01;
    return config;
}

TEST(ReservoirFactory, BuildsConstantHeadFromTheCase) {
    const auto model = makeReservoirModel(constantHeadCase());
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(model->name(), "constant_head");
    EXPECT_DOUBLE_EQ(model->gateLaw(2.0).staticPressure, 1000.0 * 9.806 * (0.4 + 0.01 * 2.0));
}

TEST(ReservoirFactory, OpenFoamIsNotAPerStepReservoir) {
    CaseConfig config = constantHeadCase();
    config.reservoir.kind = ReservoirKind::OpenFoam;
    try {
        makeReservoirModel(config);
        FAIL() << "expected qs::Error";
    } catch (const Error& e) {
        // the OpenFOAM model is windowed: tests/unit/coupling checks its missing-build error
        EXPECT_NE(std::string(e.what()).find("makeOpenFoamModel"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace qs
