// ConstantHead gate law, state round-trip, and the factory's choice of model.
#include "reservoir/ConstantHead.hpp"

#include "core/Error.hpp"
#include "io/CaseConfig.hpp"

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

TEST(ReservoirFactory, OpenFoamWithoutRegistrationIsAClearError) {
    registerOpenFoamReservoir(nullptr);  // whatever another test left: this build has none
    CaseConfig config = constantHeadCase();
    config.reservoir.kind = ReservoirKind::OpenFoam;
    try {
        makeReservoirModel(config);
        FAIL() << "expected qs::Error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "case.toml: key 'reservoir.model': \"openfoam\" needs a quicksand build with "
                  "OpenFOAM; this build has none. Install it with tools/setup.sh --openfoam and "
                  "rebuild, or use \"constant_head\" or \"lumped\".");
    }
}

TEST(ReservoirFactory, OpenFoamUsesTheRegisteredFactory) {
    int calls = 0;
    registerOpenFoamReservoir([&calls](const CaseConfig& c) -> std::unique_ptr<ReservoirModel> {
        ++calls;  // stands in for the OpenFOAM model
        return std::make_unique<ConstantHead>(c.liquid.density, c.gravity, 1.0);
    });
    CaseConfig config = constantHeadCase();
    config.reservoir.kind = ReservoirKind::OpenFoam;
    const auto model = makeReservoirModel(config);
    registerOpenFoamReservoir(nullptr);  // leave no global state behind
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(calls, 1);
    EXPECT_THROW(makeReservoirModel(config), Error);
}

}  // namespace
}  // namespace qs
