// The OpenFOAM reservoir (issue 3), ctest label `openfoam`. Skips, saying why, only where this
// build has no OpenFOAM.
//  - the tube alone: steady laminar flow gives the Hagen-Poiseuille pressure drop within 2 %;
//  - falling head through a tube carrying half the loss: tau = A_r (L/(K A_s) + R_t) within 2 %;
//  - the coupled steady state equals the lumped reservoir with the same tube within 1 %;
//  - explicit and implicit coupling agree within 1 % where both are stable, and implicit stays
//    stable with the Deltares U-tube, where explicit fails;
//  - the fields are written at the output times; broken cases give a clear error, not an abort.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>

#include "OpenFoamTestSupport.hpp"
#include "physics/ClosedForms.hpp"
#include "solver/Interruption.hpp"
#include "solver/Run.hpp"

using namespace qs;
using namespace qs::test;
namespace fs = std::filesystem;

namespace {

struct Outcome {
    RunSummary summary;
    std::vector<ColumnState> series;
};

Outcome run(const CaseConfig& c) {
    Outcome o;
    RunOptions options;
    options.quiet = true;
    options.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) { o.series.push_back(s); };
    o.summary = runCase(c, options);
    return o;
}

/// Runs the quicksand command on a case; returns its exit code and what it printed to stderr.
std::pair<int, std::string> runCommand(const fs::path& caseDir) {
    const fs::path err = caseDir / "stderr.txt";
    const std::string cmd = std::string("timeout 300 ") + QUICKSAND_EXECUTABLE + " run '" + caseDir.string() +
                            "' --quiet > /dev/null 2> '" + err.string() + "'";
    const int status = std::system(cmd.c_str());
    std::ifstream in(err);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}

}  // namespace

TEST(OpenFoamReservoir, TubeGivesHagenPoiseuillePressureDrop) {
    QS_REQUIRE_OPENFOAM();
    // cases/verification/openfoam_tube is an OpenFOAM case itself (see its README.md)
    const fs::path dir = freshCaseCopy("verification/openfoam_tube", "hagen-poiseuille/tube");
    CaseConfig c;
    c.caseDirectory = dir.parent_path().string();
    c.reservoir.kind = ReservoirKind::OpenFoam;
    c.reservoir.openfoamCase = dir.string();
    c.reservoir.head = 0.5;
    c.reservoir.area = 1e9;  // a level that does not move
    c.gravity = 9.81;
    c.liquid.density = 998.2;
    const auto model = makeOpenFoamModel(c, false);
    WindowedModel& tube = *model;
    const double d = 0.010, L = 2.0, nu = 8.93e-7, U = 0.009;  // the case's pipe (README.md there)
    const double area = M_PI * d * d / 4, Q = U * area;
    // march to steady state (the start-up decays within about 10 s, see the case's README)
    double p = 0, t = 0;
    const double dt = 0.05;
    for (int k = 0; k < 400; ++k, t += dt) {
        p = tube.solveWindow(t, dt, Q);
        tube.acceptWindow();
    }
    const double rho = c.liquid.density;
    const double drop = (rho * c.gravity * c.reservoir.head - p) / rho;  // kinematic, m2/s2
    // the total-pressure inlet also accelerates the water to its mean velocity head (U^2/2)
    const double hagenPoiseuille = 32 * nu * L * U / (d * d);
    const double measured = drop - 0.5 * U * U;
    EXPECT_NEAR(measured, hagenPoiseuille, 0.02 * hagenPoiseuille);
    std::printf("tube: pressure drop %.6g m2/s2 (less U^2/2: %.6g), Hagen-Poiseuille %.6g (%+.2f %%)\n", drop,
                measured, hagenPoiseuille, 100 * (measured / hagenPoiseuille - 1));
}

TEST(OpenFoamReservoir, FallingHeadThroughTheTube) {
    QS_REQUIRE_OPENFOAM();
    const fs::path dir = freshCaseCopy("verification/openfoam_falling_head", "falling-head");
    const CaseConfig c = loadCase(dir.string());
    const Outcome o = run(c);
    const auto& sand = c.material("sand");
    const double rho = c.liquid.density, g = c.gravity, mu = c.liquid.viscosity;
    const double K = closed::hydraulicConductivity(sand.permeability.value, rho, g, mu);
    const double Rt = closed::tubeResistance(0.002, 1.0, rho, g, mu);  // reservoir/: d = 2 mm, L = 1 m
    const double L = c.sandTop() - c.filterLevel(), As = c.grid.crossSectionArea;
    ASSERT_GT(As * Rt, 0.5 * L / K) << "the tube must carry at least half of the loss";
    const double tau = closed::fallingHeadTau(c.reservoir.area, As, L, K, Rt);
    const double tail = *c.column.overflowLevel, h0 = c.reservoir.head - tail;
    double worst = 0;
    for (const auto& s : o.series) {
        if (s.time < 0.5) continue;
        const double exact = h0 * std::exp(-s.time / tau);
        worst = std::max(worst, std::abs((s.reservoirHead - tail) / exact - 1));
        EXPECT_NEAR(s.reservoirHead - tail, exact, 0.02 * exact) << "t = " << s.time;
    }
    // the decay rate between 2 s and the end, against 1/tau
    const auto& a = o.series[o.series.size() * 1 / 4];
    const auto& b = o.series.back();
    const double tauMeasured = (b.time - a.time) / std::log((a.reservoirHead - tail) / (b.reservoirHead - tail));
    EXPECT_NEAR(tauMeasured, tau, 0.02 * tau);
    EXPECT_EQ(o.summary.coupling.unconverged, 0);
    std::printf("OpenFOAM falling head: tau %.4f s measured, %.4f s closed form (%+.2f %%); worst head error %.2f %%; %s\n",
                tauMeasured, tau, 100 * (tauMeasured / tau - 1), 100 * worst, o.summary.couplingSummary.c_str());
}

TEST(OpenFoamReservoir, CoupledSteadyStateEqualsLumpedReservoir) {
    QS_REQUIRE_OPENFOAM();
    const fs::path dir = freshCaseCopy("verification/openfoam_utube", "steady");
    CaseConfig c = loadCase(dir.string());
    c.initial.rigidSkeleton = true;  // a steady state quickly: no consolidation
    c.reservoir.area = 1e3;          // the level does not move
    c.time.end = 2.0;
    c.time.outputInterval = 0.1;
    c.time.checkpointInterval = 0;
    const Outcome coupled = run(c);

    CaseConfig lumped = c;
    lumped.reservoir.kind = ReservoirKind::Lumped;
    lumped.reservoir.tubeDiameter = 0.010;  // reservoir/: the Deltares U-tube
    lumped.reservoir.tubeLength = 2.0;
    lumped.output.directory = "output-lumped";
    const Outcome reference = run(lumped);
    const double qc = coupled.series.back().gateFlux, ql = reference.series.back().gateFlux;
    // steady: the last two outputs agree
    EXPECT_NEAR(coupled.series[coupled.series.size() - 2].gateFlux, qc, 1e-3 * qc);
    EXPECT_NEAR(qc, ql, 0.01 * ql);
    std::printf("steady gate flux: OpenFOAM tube %.6g m3/s, lumped tube %.6g m3/s (%+.3f %%); %s\n", qc, ql,
                100 * (qc / ql - 1), coupled.summary.couplingSummary.c_str());
}

TEST(OpenFoamReservoir, ExplicitAndImplicitAgreeWhereBothAreStable) {
    QS_REQUIRE_OPENFOAM();
    const fs::path dir = freshCaseCopy("verification/openfoam_short_tube", "short-tube");
    CaseConfig c = loadCase(dir.string());
    const Outcome implicit = run(c);
    c.coupling.scheme = CouplingKind::Explicit;
    c.output.directory = "output-explicit";
    const Outcome explicit_ = run(c);
    ASSERT_EQ(implicit.series.size(), explicit_.series.size());
    double worst = 0;
    for (std::size_t k = 0; k < implicit.series.size(); ++k) {
        if (implicit.series[k].time < 0.05) continue;
        const double a = implicit.series[k].gateFlux, b = explicit_.series[k].gateFlux;
        worst = std::max(worst, std::abs(b / a - 1));
        EXPECT_NEAR(b, a, 0.01 * std::abs(a)) << "t = " << implicit.series[k].time;
    }
    std::printf("short tube: explicit vs implicit gate flux, largest difference %.3f %%\n", 100 * worst);
}

TEST(OpenFoamReservoir, ImplicitStaysStableWhereExplicitFails) {
    QS_REQUIRE_OPENFOAM();
    // the Deltares U-tube (10 mm, 2 m): added-mass ratio (L_t/A_t)/(h_chamber/A_s) about 6800
    const fs::path dir = freshCaseCopy("verification/openfoam_utube", "unstable");
    CaseConfig c = loadCase(dir.string());
    c.time.end = 0.1;
    c.time.outputInterval = 0.01;
    c.time.checkpointInterval = 0;
    c.coupling.window = 1e-3;
    const Outcome implicit = run(c);
    double implicitMax = 0;
    for (const auto& s : implicit.series) implicitMax = std::max(implicitMax, std::abs(s.gateFlux));
    EXPECT_TRUE(std::isfinite(implicitMax));
    EXPECT_EQ(implicit.summary.coupling.unconverged, 0);

    c.coupling.scheme = CouplingKind::Explicit;
    c.output.directory = "output-explicit";
    bool failed = false;
    try {
        const Outcome ex = run(c);
        double exMax = 0;
        for (const auto& s : ex.series) exMax = std::max(exMax, std::abs(s.gateFlux));
        failed = !std::isfinite(exMax) || exMax > 100 * implicitMax;
    } catch (const Error& e) {
        failed = true;
        std::printf("explicit coupling with the Deltares U-tube failed as expected: %s\n", e.what());
    }
    EXPECT_TRUE(failed);
}

TEST(OpenFoamReservoir, FieldsAreWrittenAtOutputTimes) {
    QS_REQUIRE_OPENFOAM();
    const fs::path dir = freshCaseCopy("verification/openfoam_short_tube", "fields");
    CaseConfig c = loadCase(dir.string());
    c.time.end = 0.05;
    c.time.outputInterval = 0.025;
    run(c);
    const fs::path work = dir / "output/openfoam";
    int timeDirs = 0;
    for (const auto& e : fs::directory_iterator(work))
        if (e.is_directory() && fs::exists(e.path() / "U") && e.path().filename() != "0") ++timeDirs;
    EXPECT_GE(timeDirs, 2);
    EXPECT_TRUE(fs::exists(dir / "output/openfoam.log"));
    EXPECT_TRUE(fs::exists(dir / "output/coupling.log"));
}

TEST(OpenFoamReservoir, BrokenCasesGiveClearErrors) {
    QS_REQUIRE_OPENFOAM();
    struct Breakage {
        const char* tag;
        std::function<void(const fs::path&)> breakIt;
        const char* expected;
    };
    const std::vector<Breakage> cases = {
        {"missing-directory", [](const fs::path& d) { fs::remove_all(d / "reservoir"); }, "does not exist"},
        {"missing-patch",
         [](const fs::path& d) { replaceInFile(d / "case.toml", "openfoam_case = \"reservoir\"",
                                               "openfoam_case = \"reservoir\"\ngate_patch = \"outlet\""); },
         "no patch named outlet"},
        {"bad-dictionary",
         [](const fs::path& d) { replaceInFile(d / "reservoir/system/fvSolution", "PIMPLE", "PIMPLE {"); },
         "fvSolution"},
        {"bad-blockMeshDict",
         [](const fs::path& d) { replaceInFile(d / "reservoir/system/blockMeshDict", "blocks", "blocks ("); },
         "blockMesh could not mesh"},
    };
    for (const auto& b : cases) {
        const fs::path dir = freshCaseCopy("verification/openfoam_short_tube", std::string("broken-") + b.tag);
        b.breakIt(dir);
        fs::create_directories(dir / "output");  // earlier results, which must survive
        std::ofstream(dir / "output/series.csv") << "earlier results\n";
        const auto [code, err] = runCommand(dir);
        EXPECT_EQ(code, 1) << b.tag << ": " << err;  // not 124 (hang), not a signal
        std::ifstream kept(dir / "output/series.csv");
        std::string line;
        std::getline(kept, line);
        EXPECT_EQ(line, "earlier results") << b.tag << ": the failed run touched the earlier output";
        EXPECT_NE(err.find("quicksand: error:"), std::string::npos) << b.tag << ": " << err;
        EXPECT_NE(err.find(b.expected), std::string::npos) << b.tag << ": " << err;
    }
}

/// The series rows of a run's output from time t on (the straight and the resumed run's rows,
/// compared as text: every digit).
std::vector<std::string> seriesFrom(const fs::path& caseDir, double t) {
    std::ifstream in(caseDir / "output/series.csv");
    std::vector<std::string> rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line))
        if (std::stod(line.substr(0, line.find(','))) >= t) rows.push_back(line);
    return rows;
}

TEST(OpenFoamReservoir, CoupledRunResumesFromItsCheckpointBitForBit) {
    QS_REQUIRE_OPENFOAM();
    // the checkpoint holds the column, the reservoir level and the coupling's whole state (fluxes,
    // pressure, Aitken factor); the line's fields are written beside it with every digit
    // (output/openfoam/<t>/) and the OpenFOAM case is reopened there. A run stopped where the
    // straight run checkpoints (a window boundary) and resumed repeats the straight run exactly.
    // the Deltares U-tube: its heavy water takes several coupling iterations a window, so the
    // resumed run must start from the Aitken factor the straight run had (fails without it)
    auto prepare = [](const std::string& tag) {
        const fs::path dir = freshCaseCopy("verification/openfoam_utube", tag);
        CaseConfig c = loadCase(dir.string());
        c.time.end = 0.2;
        c.time.outputInterval = 0.02;
        c.time.checkpointInterval = 0.1;
        return c;
    };
    const CaseConfig straight = prepare("resume-straight");
    const Outcome a = run(straight);
    // the window boundary where the straight run checkpointed (and wrote its output of t = 0.1)
    double tc = 0;
    for (const auto& s : a.series)
        if (s.time > 0.09) { tc = s.time; break; }
    ASSERT_GT(tc, 0.09);
    const CaseConfig split = prepare("resume-split");
    RunOptions first;
    first.quiet = true;
    first.endTime = tc;
    runCase(split, first);
    RunOptions again;
    again.quiet = true;
    again.resume = true;
    const RunSummary b = runCase(split, again);
    EXPECT_EQ(b.final.time, a.summary.final.time);
    EXPECT_EQ(b.final.gateFlux, a.summary.final.gateFlux);
    EXPECT_EQ(b.final.reservoirHead, a.summary.final.reservoirHead);
    EXPECT_EQ(b.final.gatePressure, a.summary.final.gatePressure);
    const auto ra = seriesFrom(fs::path(straight.caseDirectory), tc), rb = seriesFrom(fs::path(split.caseDirectory), tc);
    ASSERT_EQ(ra.size(), rb.size());
    ASSERT_GE(ra.size(), 5u);
    for (std::size_t k = 0; k < ra.size(); ++k) EXPECT_EQ(ra[k], rb[k]) << "series row " << k;
}

TEST(OpenFoamReservoir, AnInterruptedCoupledRunCheckpointsAndResumesBitForBit) {
    QS_REQUIRE_OPENFOAM();
    // SIGINT during a coupled run: the coupling window in progress ends, the checkpoint (column,
    // reservoir level, coupling state, the line's fields) is written, Interrupted says how to
    // resume; resumed, the run repeats the run never interrupted, every digit of its series
    auto prepare = [](const std::string& tag) {
        const fs::path dir = freshCaseCopy("verification/openfoam_utube", tag);
        CaseConfig c = loadCase(dir.string());
        c.time.end = 0.2;
        c.time.outputInterval = 0.02;
        c.time.checkpointInterval = 0;
        return c;
    };
    const CaseConfig straight = prepare("interrupt-straight");
    const Outcome a = run(straight);
    const CaseConfig split = prepare("interrupt-split");
    RunOptions first;
    first.quiet = true;
    bool sent = false;
    first.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) {
        if (!sent && s.time > 0.09) { sent = true; std::raise(SIGINT); }
    };
    try {
        runCase(split, first);
        FAIL() << "the interrupted coupled run must stop with Interrupted";
    } catch (const Interrupted& e) {
        EXPECT_EQ(e.exitCode(), 130);
        EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
    }
    RunOptions again;
    again.quiet = true;
    again.resume = true;
    const RunSummary b = runCase(split, again);
    EXPECT_EQ(b.final.time, a.summary.final.time);
    EXPECT_EQ(b.final.gateFlux, a.summary.final.gateFlux);
    EXPECT_EQ(b.final.reservoirHead, a.summary.final.reservoirHead);
    EXPECT_EQ(b.final.gatePressure, a.summary.final.gatePressure);
    const auto ra = seriesFrom(fs::path(straight.caseDirectory), 0.11), rb = seriesFrom(fs::path(split.caseDirectory), 0.11);
    ASSERT_EQ(ra.size(), rb.size());
    for (std::size_t k = 0; k < ra.size(); ++k) EXPECT_EQ(ra[k], rb[k]) << "series row " << k;
}
