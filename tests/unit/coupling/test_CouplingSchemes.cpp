// Coupling schemes (explicit staggered with subcycling, implicit with Aitken) verified with the
// InertialTubeModel, the lumped form of the OpenFOAM tube (its water has inertia, so the gate
// pressure answers flux acceleration at once). The same claims are checked against the OpenFOAM
// tube itself in tests/openfoam/.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/InertialTubeModel.hpp"
#include "case/CaseLoader.hpp"
#include "solver/Run.hpp"

using namespace qs;

namespace {

CaseConfig fallingHead(double end) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/falling_head");
    c.time.end = end;
    c.time.outputInterval = 0.05;
    return c;
}

InertialTubeParameters tubeOf(const CaseConfig& c, double diameter, double length) {
    InertialTubeParameters p;
    p.liquidDensity = c.liquid.density;
    p.gravity = c.gravity;
    p.viscosity = c.liquid.viscosity;
    p.area = c.reservoir.area;
    p.initialHead = c.reservoir.head;
    p.tubeDiameter = diameter;
    p.tubeLength = length;
    return p;
}

struct Outcome {
    RunSummary summary;
    std::vector<ColumnState> series;
};

Outcome runCoupled(CaseConfig c, CouplingKind scheme, double window, InertialTubeParameters tube) {
    c.coupling.scheme = scheme;
    c.coupling.window = window;
    InertialTubeModel model(tube);
    Outcome o;
    RunOptions options;
    options.quiet = true;
    options.writeFiles = false;
    options.windowedModel = &model;
    options.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) { o.series.push_back(s); };
    o.summary = runCase(c, options);
    return o;
}

}  // namespace

TEST(CouplingSchemes, ImplicitCouplingReproducesTheBuiltInLumpedReservoir) {
    // the built-in lumped reservoir is advanced inside every MPM step with its tube loss
    // implicit; the windowed tube without inertia through implicit coupling must give the same
    // decay (with inertia the tube's water takes (L_t/A_t)/(g (R_t + L/(K A_s))) = 0.29 s to
    // accelerate here, a real difference)
    const CaseConfig c = fallingHead(1.0);
    RunOptions options;
    options.quiet = true;
    options.writeFiles = false;
    const RunSummary builtIn = runCase(c, options);
    auto tube = tubeOf(c, c.reservoir.tubeDiameter, c.reservoir.tubeLength);
    tube.inertialLength = 0;
    const Outcome coupled = runCoupled(c, CouplingKind::Implicit, 1e-3, tube);
    const double tail = *c.column.overflowLevel;
    const double dropBuiltIn = c.reservoir.head - builtIn.final.reservoirHead;
    const double dropCoupled = c.reservoir.head - coupled.summary.final.reservoirHead;
    EXPECT_NEAR(dropCoupled, dropBuiltIn, 0.01 * dropBuiltIn);
    EXPECT_NEAR(coupled.summary.final.gateFlux, builtIn.final.gateFlux, 0.01 * builtIn.final.gateFlux);
    EXPECT_EQ(coupled.summary.coupling.unconverged, 0);
    EXPECT_GT(coupled.summary.final.reservoirHead, tail);
    std::printf("built-in lumped: head drop %.6g m, flux %.6g; implicit coupled: %.6g m, %.6g "
                "(%.2f model solves per window)\n",
                dropBuiltIn, builtIn.final.gateFlux, dropCoupled, coupled.summary.final.gateFlux,
                double(coupled.summary.coupling.modelSolves) / coupled.summary.coupling.windows);
}

TEST(CouplingSchemes, ExplicitAndImplicitAgreeWhereExplicitIsStable) {
    // a connection as wide as the column and 10 mm long: its water is lighter than the chamber's
    // free water, (L_t/A_t)/(h_chamber/A_s) = 0.54 < 1, so explicit coupling is stable
    const CaseConfig c = fallingHead(0.5);
    const auto tube = tubeOf(c, 0.0798, 0.01);
    const Outcome ex = runCoupled(c, CouplingKind::Explicit, 1e-3, tube);
    const Outcome im = runCoupled(c, CouplingKind::Implicit, 1e-3, tube);
    ASSERT_EQ(ex.series.size(), im.series.size());
    for (std::size_t k = 2; k < ex.series.size(); ++k) {
        EXPECT_NEAR(ex.series[k].gateFlux, im.series[k].gateFlux, 0.01 * std::abs(im.series[k].gateFlux))
            << "t = " << ex.series[k].time;
    }
}

TEST(CouplingSchemes, ImplicitStaysStableWhereExplicitFails) {
    // the falling-head tube (d = 4 mm, L = 1.7 m): its water is heavy against the chamber's,
    // added-mass ratio (L_t/A_t)/(h_chamber/A_s) about 36000 > 1
    const CaseConfig c = fallingHead(0.3);
    const auto tube = tubeOf(c, c.reservoir.tubeDiameter, c.reservoir.tubeLength);
    const Outcome im = runCoupled(c, CouplingKind::Implicit, 1e-3, tube);
    double imMax = 0;
    for (const auto& s : im.series) imMax = std::max(imMax, std::abs(s.gateFlux));
    EXPECT_LT(imMax, 2 * im.series.back().gateFlux);  // a smooth start, no oscillation
    EXPECT_EQ(im.summary.coupling.unconverged, 0);

    bool failed = false;
    try {
        const Outcome ex = runCoupled(c, CouplingKind::Explicit, 1e-3, tube);
        double exMax = 0;
        for (const auto& s : ex.series) exMax = std::max(exMax, std::abs(s.gateFlux));
        failed = !std::isfinite(exMax) || exMax > 100 * imMax;
    } catch (const Error& e) {
        failed = true;  // the solution became non-finite: the run stops with a clear error
        std::printf("explicit coupling failed as expected: %s\n", e.what());
    }
    EXPECT_TRUE(failed) << "explicit coupling should be unstable with this tube";
}

TEST(CouplingSchemes, OpenFoamModelInABuildWithoutItNamesTheKey) {
    // the unit tests link no foamCoupling/: nothing registered an OpenFOAM model
    CaseConfig c = fallingHead(0.1);
    c.reservoir.kind = ReservoirKind::OpenFoam;
    try {
        makeOpenFoamModel(c);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("reservoir.model"), std::string::npos) << what;
        EXPECT_NE(what.find("tools/setup.sh --openfoam"), std::string::npos) << what;
    }
}
