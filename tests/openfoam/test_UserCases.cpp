// OpenFOAM cases written the way an OpenFOAM user writes them, coupled to the column (issue 21,
// ctest label `openfoam`):
//  - a stock pimpleFoam RAS tutorial (pitzDaily, Debian's openfoam-examples) with only its two
//    coupled patches' conditions changed, as docs/openfoam.md tells a user to;
//  - a user-written case (renamed patches, probes and surfaceFieldValue, k-omega SST) runs coupled;
//    its function objects write a row per accepted window, and its outlet average is the gate
//    pressure quicksand reports;
//  - a repeated window restores every registered field: solve, roll back, solve again gives the
//    same fields, turbulence included, digit for digit (a third solve with another flux in
//    between, as implicit coupling does).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "OpenFoamTestSupport.hpp"
#include "coupling/WindowedModel.hpp"
#include "solver/Run.hpp"

using namespace qs;
using namespace qs::test;
namespace fs = std::filesystem;

namespace {

/// Replaces the dictionary of `patch` in an OpenFOAM field file's boundaryField with `body`, as a
/// user edits it (the block from the patch's name to its closing brace).
void setPatch(const fs::path& file, const std::string& patch, const std::string& body) {
    std::string text = readFile(file);
    const std::string key = "\n    " + patch + "\n    {";
    const auto at = text.find(key);
    ASSERT_NE(at, std::string::npos) << "patch " << patch << " in " << file;
    const auto end = text.find("\n    }", at + key.size());
    ASSERT_NE(end, std::string::npos);
    text.replace(at, end + 6 - at, "\n    " + patch + "\n    {\n        " + body + "\n    }");
    std::ofstream(file) << text;
}

/// The column of cases/verification/openfoam_short_tube fed by the OpenFOAM case `foamCase` (a
/// folder beside case.toml) through its patches `gate` and `reservoir`.
void writeColumnCase(const fs::path& dir, const std::string& foamCase, const std::string& gate,
                     const std::string& reservoir, double end) {
    std::string text = readFile(fs::path(QUICKSAND_SOURCE_DIR) / "cases/verification/openfoam_short_tube/case.toml");
    auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("openfoam_case = \"reservoir\"", "openfoam_case = \"" + foamCase + "\"\ngate_patch = \"" + gate +
                                                 "\"\nreservoir_patch = \"" + reservoir + "\"");
    replace("end = 0.5", "end = " + std::to_string(end));
    std::ofstream(dir / "case.toml") << text;
}

/// Every file of the OpenFOAM time directory `dir`, by name.
std::map<std::string, std::string> timeDirectory(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().filename().string()] = readFile(e.path());
    return files;
}

}  // namespace

TEST(UserCases, AStockPimpleFoamTutorialRunsCoupled) {
    QS_REQUIRE_OPENFOAM();
    const fs::path tutorial = fs::path(QUICKSAND_OPENFOAM_TUTORIALS) / "incompressible/pimpleFoam/RAS/pitzDaily";
    if (!fs::exists(tutorial / "system/controlDict"))
        GTEST_SKIP() << "no OpenFOAM tutorials at " << tutorial << " (Debian's openfoam-examples: bash tools/setup.sh --openfoam)";
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests/user-pitzDaily";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(tutorial, dir / "pitzDaily", fs::copy_options::recursive);
    // docs/openfoam.md, "A stock tutorial as the feed line": only the two coupled patches change
    setPatch(dir / "pitzDaily/0/U", "inlet", "type            pressureInletOutletVelocity;\n        value           uniform (0 0 0);");
    setPatch(dir / "pitzDaily/0/U", "outlet", "type            fixedValue;\n        value           uniform (0 0 0);");
    setPatch(dir / "pitzDaily/0/p", "inlet", "type            totalPressure;\n        p0              uniform 0;\n        value           uniform 0;");
    setPatch(dir / "pitzDaily/0/p", "outlet", "type            zeroGradient;");
    writeColumnCase(dir, "pitzDaily", "outlet", "inlet", 0.02);
    const CaseConfig c = loadCase(dir.string());
    RunOptions o;
    o.quiet = true;
    const RunSummary s = runCase(c, o);
    EXPECT_NEAR(s.final.time, 0.02, 1e-4);  // within half an MPM step
    EXPECT_TRUE(std::isfinite(s.final.gateFlux));
    EXPECT_GT(s.final.gateFlux, 0);  // the reservoir's head drives water through the step into the column
    EXPECT_EQ(s.coupling.unconverged, 0);
    // the tutorial's own turbulence model ran (OpenFOAM's run-time selection, its log)
    const std::string log = readFile(dir / "output/openfoam.log");
    EXPECT_NE(log.find("kEpsilon"), std::string::npos);
    std::printf("pitzDaily as the feed line: gate flux %.4g m3/s at t = %.3g s; %s\n", s.final.gateFlux, s.final.time,
                s.couplingSummary.c_str());
}

TEST(UserCases, ARepeatedWindowRestoresEveryFieldDigitForDigit) {
    QS_REQUIRE_OPENFOAM();
    const fs::path tutorial = fs::path(QUICKSAND_OPENFOAM_TUTORIALS) / "incompressible/pimpleFoam/RAS/pitzDaily";
    if (!fs::exists(tutorial / "system/controlDict"))
        GTEST_SKIP() << "no OpenFOAM tutorials at " << tutorial << " (Debian's openfoam-examples: bash tools/setup.sh --openfoam)";
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests/user-rollback";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(tutorial, dir / "line", fs::copy_options::recursive);
    setPatch(dir / "line/0/U", "inlet", "type            pressureInletOutletVelocity;\n        value           uniform (0 0 0);");
    setPatch(dir / "line/0/U", "outlet", "type            fixedValue;\n        value           uniform (0 0 0);");
    setPatch(dir / "line/0/p", "inlet", "type            totalPressure;\n        p0              uniform 0;\n        value           uniform 0;");
    setPatch(dir / "line/0/p", "outlet", "type            zeroGradient;");
    writeColumnCase(dir, "line", "outlet", "inlet", 0.1);
    CaseConfig c = loadCase(dir.string());
    c.reservoir.area = 1e3;  // the level hardly moves
    const auto model = makeOpenFoamModel(c, false);  // the OpenFOAM reservoir, through its seam
    WindowedModel& line = *model;
    const fs::path work = fs::path(c.caseDirectory) / c.output.directory / "openfoam";
    const double dt = 1e-3, Q = 5e-6;
    double t = 0;
    for (int k = 0; k < 20; ++k, t += dt) {  // a developing flow: k and epsilon far from uniform
        line.solveWindow(t, dt, Q);
        line.acceptWindow();
    }
    auto fieldsNow = [&] {
        line.writeOutput(t + dt);
        fs::path latest;
        double newest = -1;
        for (const auto& e : fs::directory_iterator(work)) {
            if (!e.is_directory()) continue;
            try {
                const double v = std::stod(e.path().filename().string());
                if (v > newest) { newest = v; latest = e.path(); }
            } catch (...) {
            }
        }
        return timeDirectory(latest);
    };
    const double p1 = line.solveWindow(t, dt, Q);
    const auto first = fieldsNow();
    const double p2 = line.solveWindow(t, dt, 3 * Q);  // an iteration with another flux
    const auto other = fieldsNow();
    const double p3 = line.solveWindow(t, dt, Q);       // and the first flux again
    const auto again = fieldsNow();
    ASSERT_NE(p2, p1) << "the second iteration must differ, or the test could not fail";
    EXPECT_NE(other.at("k"), first.at("k")) << "k must depend on the flux, or the test could not fail";
    EXPECT_EQ(p3, p1);
    for (const char* name : {"U", "p", "phi", "k", "epsilon", "nut"}) ASSERT_TRUE(first.count(name)) << name << " not written";
    ASSERT_EQ(again.size(), first.size());
    for (const auto& [name, text] : first)
        EXPECT_EQ(again.at(name), text) << name << " differs after the window was repeated";
    std::printf("rollback: %zu fields written, all equal after a repeat with another flux in between\n", first.size());
}

TEST(UserCases, AUserCaseWithRenamedPatchesProbesAndRASRunsCoupled) {
    QS_REQUIRE_OPENFOAM();
    // cases/verification/openfoam_turbulent_pipe: k-omega SST, patches `inlet` and `outlet`, a
    // probes and a surfaceFieldValue function object, as its user wrote it; fed from a reservoir
    // into the rigid column of openfoam_short_tube for 1 s of 20 ms windows (the case's step)
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests/user-pipe";
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(fs::path(QUICKSAND_SOURCE_DIR) / "cases/verification/openfoam_turbulent_pipe", dir / "pipe",
             fs::copy_options::recursive);
    writeColumnCase(dir, "pipe", "outlet", "inlet", 1.0);
    CaseConfig c = loadCase(dir.string());
    c.coupling.window = 0.02;
    c.time.outputInterval = 0.1;
    std::vector<ColumnState> series;
    RunOptions o;
    o.quiet = true;
    o.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) { series.push_back(s); };
    const RunSummary s = runCase(c, o);
    EXPECT_NEAR(s.final.time, 1.0, 1e-4);
    EXPECT_EQ(s.coupling.unconverged, 0);
    EXPECT_GT(s.final.gateFlux, 0);
    // the function objects wrote under quicksand as under pimpleFoam: one row per accepted window
    const fs::path post = dir / "output/openfoam/postProcessing";
    const std::string probes = readFile(post / "probes/0/p"), outlet = readFile(post / "outletPressure/0/surfaceFieldValue.dat");
    ASSERT_FALSE(probes.empty());
    ASSERT_FALSE(outlet.empty());
    int rows = 0;
    std::istringstream lines(outlet);
    std::string line, last;
    for (; std::getline(lines, line);)
        if (!line.empty() && line[0] != '#') { ++rows; last = line; }
    EXPECT_EQ(rows, static_cast<int>(s.coupling.windows)) << "one row per accepted window, none for trial solves";
    // its outlet's area-averaged p is the gate pressure quicksand reports (times rho)
    std::istringstream row(last);
    double time = 0, p = 0;
    row >> time >> p;
    EXPECT_NEAR(time, s.final.time, 1e-4);  // the line's time sums the windows; the column's its steps
    // to the .dat's 7 digits and the coupling's tolerance: the column's gate pressure carries the
    // impedance term Z (Q - Q_window) of a converged window, |Q - Q_window| <= tolerance |Q|, with
    // Z = rho c / A (solver/Simulation.cpp). Until 2026-12-07 this was 1e-5 of the pressure, which
    // held at 1.19e-5 once the step was fitted to the window (the Aitken iterations stop elsewhere
    // inside the tolerance): the bound is the coupling's, not a digit count
    const double impedance = c.liquid.density * std::sqrt(c.liquid.bulkModulus / c.liquid.density) /
                             c.grid.crossSectionArea;
    const double bound = impedance * c.coupling.tolerance * std::abs(s.final.gateFlux) +
                         5e-7 * std::abs(s.final.gatePressure);
    EXPECT_NEAR(c.liquid.density * p, s.final.gatePressure, bound);
    std::printf("outlet pressure against the gate's: %.3g Pa apart, bound %.3g Pa\n",
                std::abs(c.liquid.density * p - s.final.gatePressure), bound);
    // the user's turbulence model ran
    EXPECT_NE(readFile(dir / "output/openfoam.log").find("kOmegaSST"), std::string::npos);
    std::printf("user's pipe case coupled: gate flux %.4g m3/s, gate pressure %.6g Pa = rho x %.8g from its "
                "surfaceFieldValue; %d rows for %ld windows (%ld solves); %s\n",
                s.final.gateFlux, s.final.gatePressure, p, rows, s.coupling.windows, s.coupling.modelSolves,
                s.couplingSummary.c_str());
}

TEST(UserCases, AFastLaminarLineKeepsItsGateStable) {
    QS_REQUIRE_OPENFOAM();
    // Issue 21's failure: the main job with a 10 mm x 2 m laminar line (no valve) stopped at
    // t = 2.53 s, the first coupling iteration returning an MPM flux 4.6 times the line's. At
    // 0.54 m/s (Re 6100) the entry length, 0.05 Re d ~ 3 m, exceeds the 2 m line: the flow
    // arriving at the gate is no parabola, and the parabola the gate imposed kept the water
    // flowing back along the axis (-0.5 m/s over its last 4 cells) and radially in the wedge's
    // axis cell, where OpenFOAM's explicit swirl term grows round-off swirl once
    // dt U_r / r_c > 2: 1e-13 m/s at the start, 0.15 at 2.47 s, then x -2 ... -729 a window,
    // until the axis face's pressure read -3796 m2/s2. The gate now takes the profile of the flow
    // arriving there (GateProfile.H); forced back to the parabola, this run fails at 2.17 s.
    const fs::path dir = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests/user-fast-laminar";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string make = "/usr/bin/python3 " + std::string(QUICKSAND_SOURCE_DIR) + "/tools/make_tube_case.py " +
                             QUICKSAND_SOURCE_DIR + "/cases/verification/openfoam_utube/reservoir '" +
                             (dir / "line").string() + "' --diameter 0.010 --length 2.0 --axial 112 --radial 8 > /dev/null";
    ASSERT_EQ(std::system(make.c_str()), 0) << make;
    std::string text = readFile(fs::path(QUICKSAND_SOURCE_DIR) / "cases/deltaresColumn/case.toml");
    auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
    };
    replace("openfoam_case = \"reservoir\"", "openfoam_case = \"line\"");
    std::ofstream(dir / "case.toml") << text;
    CaseConfig c = loadCase(dir.string());
    c.time.end = 4.0;
    c.time.checkpointInterval = 0;
    RunOptions o;
    o.quiet = true;
    const RunSummary s = runCase(c, o);  // threw "numerical failure" at 2.17-2.53 s before
    EXPECT_NEAR(s.final.time, 4.0, 1e-3);
    EXPECT_EQ(s.coupling.unconverged, 0);
    EXPECT_GT(s.final.gateFlux, 3e-5);  // the fast line: about 4.3e-5 m3/s by then
    std::printf("fast laminar line (10 mm x 2 m, no valve): t = %.3g s, gate flux %.4g m3/s; %s\n", s.final.time,
                s.final.gateFlux, s.couplingSummary.c_str());
}
