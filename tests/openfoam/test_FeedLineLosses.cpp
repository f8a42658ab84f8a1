// Localised losses in the OpenFOAM feed line (issue 21, ctest label `openfoam`): a partly open
// valve made by tools/make_tube_case.py --valve-k as a porousBafflePressure baffle (OpenFOAM's
// own pressure-jump condition, docs/openfoam.md "A valve or bends in your own case"). Against
// the same mesh with the baffle's coefficient set to 0, the gate pressure at a fixed flux drops
// by K U^2 / 2 (kinematic), at two flows, within 2 %; and a falling head through a turbulent line
// with such a valve into a rigid column follows its ODE within 3 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "OpenFoamTestSupport.hpp"
#include "coupling/WindowedModel.hpp"
#include "physics/PipeFriction.hpp"
#include "solver/Run.hpp"

using namespace qs;
using namespace qs::test;
namespace fs = std::filesystem;

namespace {

/// A 10 mm pipe from tools/make_tube_case.py with the given extra options, in the build tree.
fs::path makeTube(const std::string& tag, const std::string& options) {
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests" / tag;
    fs::remove_all(dir);
    fs::create_directories(dir.parent_path());
    const std::string cmd = "/usr/bin/python3 " + std::string(QUICKSAND_SOURCE_DIR) + "/tools/make_tube_case.py " +
                            QUICKSAND_SOURCE_DIR + "/cases/verification/openfoam_utube/reservoir '" + dir.string() +
                            "' --diameter 0.01 --length 0.5 --axial 100 --radial 8 " + options + " > /dev/null";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return dir;
}

/// The kinematic gate pressure (m2/s2) of the line at `dir` after `windows` windows at flux Q.
double gatePressure(const fs::path& dir, double Q, int windows) {
    CaseConfig c;
    c.caseDirectory = dir.parent_path().string();
    c.output.directory = "output-" + dir.filename().string();
    c.reservoir.kind = ReservoirKind::OpenFoam;
    c.reservoir.openfoamCase = dir.string();
    c.reservoir.head = 0.5;
    c.reservoir.area = 1e9;  // a level that does not move
    c.gravity = 9.81;
    c.liquid.density = 998.2;
    const auto model = makeOpenFoamModel(c, false);
    double p = 0, t = 0;
    const double dt = 0.02;
    for (int k = 0; k < windows; ++k, t += dt) {
        p = model->solveWindow(t, dt, Q);
        model->acceptWindow();
    }
    return p / c.liquid.density;
}

}  // namespace

TEST(FeedLineLosses, AValveBaffleLosesKTimesTheVelocityHead) {
    QS_REQUIRE_OPENFOAM();
    const double K = 5.0, d = 0.01, A = M_PI * d * d / 4;
    const fs::path valve = makeTube("valve-k5", "--valve-k 5");
    // the same mesh without the loss: the baffle's coefficient I set to 0
    const fs::path open = makeTube("valve-k0", "--valve-k 5");
    {
        std::string p = readFile(open / "0/p");
        const auto at = p.find("I               5;");
        ASSERT_NE(at, std::string::npos) << "the baffle's coefficient in " << (open / "0/p");
        p.replace(at, 18, "I               0;");
        std::ofstream(open / "0/p") << p;
    }
    for (const double U : {0.1, 0.3}) {
        const double Q = U * A;
        const double drop = gatePressure(open, Q, 40) - gatePressure(valve, Q, 40);
        const double expected = K * U * U / 2;
        EXPECT_NEAR(drop, expected, 0.02 * expected) << "U = " << U << " m/s";
        EXPECT_NEAR(drop, expected, 1e-4 * expected) << "U = " << U << " m/s (a guard near the 1e-6 achieved)";
        std::printf("valve K = %g at U = %g m/s: drop %.7g m2/s2, K U^2/2 = %.7g (%+.5f %%)\n", K, U, drop, expected,
                    100 * (drop / expected - 1));
    }
}

// Falling head through a turbulent OpenFOAM line with a valve into a rigid column
// (cases/verification/openfoam_falling_head_turbulent): the reservoir's head against the ODE
//     A_r dh/dt = -Q,  (L/(g A_t)) dQ/dt = h - (L_s/(K A_s)) Q - (f(Re) L/d + sum K) U^2/(2 g)
// integrated here (RK4) with Colebrook's smooth-pipe f (64/Re below Re 2000), sum K = 5 (the
// valve baffle) + 1 (the kinetic energy leaving the line), and the line water's inertia, which the
// OpenFOAM line has (without it the closed form leads by 2 % at 2 s: the water takes about
// 0.5 s to start). Tolerance 3 %.
TEST(FeedLineLosses, FallingHeadThroughATurbulentLineAndAValve) {
    QS_REQUIRE_OPENFOAM();
    const fs::path dir = freshCaseCopy("verification/openfoam_falling_head_turbulent", "falling-head-turbulent");
    const CaseConfig c = loadCase(dir.string());
    std::vector<ColumnState> series;
    RunOptions o;
    o.quiet = true;
    o.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) { series.push_back(s); };
    const RunSummary summary = runCase(c, o);
    EXPECT_EQ(summary.coupling.unconverged, 0);
    const auto& sand = c.material("sand");
    const double g = c.gravity, rho = c.liquid.density, mu = c.liquid.viscosity;
    const double Ks = sand.permeability.value * rho * g / mu;  // hydraulic conductivity, m/s
    const double Ls = c.sandTop() - c.filterLevel(), As = c.grid.crossSectionArea;
    const double d = 0.010, L = 2.0, sumK = 5.0 + 1.0, At = M_PI * d * d / 4, Ar = c.reservoir.area;
    auto lineLoss = [&](double Q) {
        const double U = Q / At, re = std::max(rho * std::abs(U) * d / mu, 1.0);
        const double f = re < 2000 ? friction::laminar(re) : friction::colebrookSmooth(re);
        return (f * L / d + sumK) * U * std::abs(U) / (2 * g);
    };
    auto dQdt = [&](double h, double Q) { return (h - Ls / (Ks * As) * Q - lineLoss(Q)) * g * At / L; };
    const double tail = *c.column.overflowLevel;
    double h = c.reservoir.head - tail, Q = 0, t = 0, worst = 0;
    const double dt = 1e-4;
    for (const auto& s : series) {
        while (t < s.time - 0.5 * dt) {
            const double st = std::min(dt, s.time - t);
            const double h1 = -Q / Ar, q1 = dQdt(h, Q);
            const double h2 = -(Q + 0.5 * st * q1) / Ar, q2 = dQdt(h + 0.5 * st * h1, Q + 0.5 * st * q1);
            const double h3 = -(Q + 0.5 * st * q2) / Ar, q3 = dQdt(h + 0.5 * st * h2, Q + 0.5 * st * q2);
            const double h4 = -(Q + st * q3) / Ar, q4 = dQdt(h + st * h3, Q + st * q3);
            h += st * (h1 + 2 * h2 + 2 * h3 + h4) / 6;
            Q += st * (q1 + 2 * q2 + 2 * q3 + q4) / 6;
            t += st;
        }
        if (s.time < 0.1) continue;
        worst = std::max(worst, std::abs((s.reservoirHead - tail) / h - 1));
        EXPECT_NEAR(s.reservoirHead - tail, h, 0.03 * h) << "t = " << s.time;
    }
    EXPECT_GT(series.size(), 100u);
    EXPECT_LT(worst, 0.022);  // achieved 1.67 %: a guard near it
    std::printf("falling head through a turbulent OpenFOAM line and a valve: worst head error %.2f %% (Re %.0f at the "
                "end); %s\n",
                100 * worst, rho * (Q / At) * d / mu, summary.couplingSummary.c_str());
}
