// Localised losses in the OpenFOAM feed line (issue 21, ctest label `openfoam`): a partly open
// valve made by tools/make_tube_case.py --valve-k as a porousBafflePressure baffle (OpenFOAM's
// own pressure-jump condition, docs/openfoam.md "A valve or bends in your own case"). Against
// the same mesh with the baffle's coefficient set to 0, the gate pressure at a fixed flux drops
// by K U^2 / 2 (kinematic), at two flows, within 2 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "OpenFoamTestSupport.hpp"
#include "coupling/WindowedModel.hpp"

using namespace qs;
using namespace qs::test;
namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

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
