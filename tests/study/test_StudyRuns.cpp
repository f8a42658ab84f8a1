// The study tool (tools/study.py, docs/studies.md) against what it promises (labels `study` and
// `verification`):
//  - a 2 x 2 study of a cheap 1D case gives four runs whose series equal, bit for bit, the runs a
//    user makes by hand with `quicksand run CASE --set ...` and the same overrides;
//  - study.csv's figures of a case with known values: the bed expansion of problem 7 (physics.md
//    section 4): fluidised as the front passes the first row of cells, at the gradient of U_mf,
//    final height H2 of the drift-flux closed form within problem 7's 2 %;
//  - a variant that fails (the sand reaches the overflow with column.sand_overflow = "stop") is
//    reported in study.csv with its error, and the others finish.
#include <gtest/gtest.h>

#include <cstdlib>

#include "StudyTestSupport.hpp"
#include "case/CaseLoader.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/DriftFlux.hpp"

using namespace qs;
using namespace qs::test;

namespace {

const std::string kFallingHead = std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/falling_head";

}  // namespace

TEST(Study, ATwoByTwoStudyGivesTheRunsMadeByHandBitForBit) {
    const fs::path dir = freshStudyFolder("two-by-two");
    std::ofstream(dir / "study.toml") << "base = \"" << kFallingHead << "\"\n"
                                      << "threads = 1\nparallel = 2\n"
                                      << "[parameters]\n"
                                      << "\"reservoir.area\" = [5.0e-5, 1.0e-4]\n"
                                      << "\"reservoir.tube_length\" = { from = 1.7, to = 3.4, count = 2 }\n"
                                      << "[set]\n\"time.end\" = 1.0\n\"output.fields\" = false\n";
    const Command study = runStudy(dir / "study.toml", "--quiet");  // with the plots
    ASSERT_EQ(study.exitCode, 0) << study.output;
    const auto rows = readStudyCsv(dir / "output" / "study.csv");
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_TRUE(fs::exists(dir / "output" / "study_series.png"));
    EXPECT_TRUE(fs::exists(dir / "output" / "study_figures.png"));
    int compared = 0;
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("status"), "finished") << row.at("variant");
        // the same run by hand, as a user types it
        const fs::path hand = dir / ("hand-" + row.at("variant"));
        const Command run = runCommand(std::string("OMP_NUM_THREADS=1 ") + QUICKSAND_EXECUTABLE + " run " + kFallingHead +
                                       " --quiet --set time.end=1.0 --set output.fields=false --set reservoir.area=" +
                                       row.at("reservoir.area") + " --set reservoir.tube_length=" +
                                       row.at("reservoir.tube_length") + " --set output.directory=" + hand.string());
        ASSERT_EQ(run.exitCode, 0) << run.output;
        const std::string byStudy = readText(dir / "output" / row.at("variant") / "series.csv");
        const std::string byHand = readText(hand / "series.csv");
        ASSERT_GT(byStudy.size(), 1000u);
        EXPECT_EQ(byStudy, byHand) << row.at("variant") << ": the study's series differs from the hand run's";
        // each variant's effective case names its overrides
        const std::string effective = readText(dir / "output" / row.at("variant") / "case.effective.toml");
        EXPECT_NE(effective.find("--set reservoir.area=" + row.at("reservoir.area")), std::string::npos) << effective;
        ++compared;
    }
    EXPECT_EQ(compared, 4);
    // the variants differ: the tube's length and the reservoir's area set the head's time constant
    EXPECT_NE(rows[0].at("head_tau_s"), rows[3].at("head_tau_s"));
}

TEST(Study, TheFiguresOfABedExpansionMatchProblem7) {
    const fs::path dir = freshStudyFolder("bed-expansion");
    const std::string base = std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/bed_expansion";
    std::ofstream(dir / "study.toml") << "base = \"" << base << "\"\nthreads = 1\n"
                                      << "[parameters]\n\"gate.flux\" = [1.380e-3]\n"
                                      << "[set]\n\"output.fields\" = false\n";
    const Command study = runStudy(dir / "study.toml");
    ASSERT_EQ(study.exitCode, 0) << study.output;
    const auto rows = readStudyCsv(dir / "output" / "study.csv");
    ASSERT_EQ(rows.size(), 1u);
    const CaseConfig c = loadCase(base);
    const auto flux = closed::SuspensionFlux::of(c, c.material("sand"));
    const double n1 = c.material("sand").porosity, H1 = c.sandTop() - c.filterLevel();
    const auto e = closed::bedExpansion(flux, n1, c.initial.filterVelocity, c.gate.flux, H1);
    const double finalHeight = std::stod(rows[0].at("final_bed_height_m"));
    EXPECT_NEAR(finalHeight, e.finalHeight, 0.02 * e.finalHeight) << "problem 7's tolerance";
    EXPECT_NEAR(finalHeight, e.finalHeight, 0.005 * e.finalHeight) << "guard";
    EXPECT_NEAR(std::stod(rows[0].at("initial_bed_height_m")), H1, 1e-3 * H1);
    EXPECT_NEAR(std::stod(rows[0].at("peak_expansion")), e.finalHeight / H1 - 1, 0.02 * e.finalHeight / H1);
    // U1 = U_mf: the bed carries no effective stress, at i_c(n1); its first row of cells (h)
    // turns fluidised as the front at speed s passes it, between h / 2s and h / s, read at the
    // next output
    const double h = c.grid.cellSize, onset = std::stod(rows[0].at("onset_time_s"));
    EXPECT_GE(onset, 0.5 * h / e.frontSpeed - 1e-9) << "s";
    EXPECT_LE(onset, h / e.frontSpeed + c.time.outputInterval + 1e-9) << "s";
    const double ic = closed::criticalGradient(c.material("sand").grainDensity, c.liquid.density, n1);
    EXPECT_NEAR(std::stod(rows[0].at("onset_gradient")), ic, 0.03 * ic);
    EXPECT_NEAR(std::stod(rows[0].at("peak_filter_velocity_ms")), c.gate.flux, 0.02 * c.gate.flux)
        << "a flux gate: the peak filter velocity is U2";
    EXPECT_EQ(rows[0].at("head_tau_s"), "") << "no reservoir that falls: no fit";
    std::printf("study of problem 7: final height %.4f m vs %.4f m (%+.2f %%), onset %.3g s at i = %s\n", finalHeight,
                e.finalHeight, 100 * (finalHeight / e.finalHeight - 1), std::stod(rows[0].at("onset_time_s")),
                rows[0].at("onset_gradient").c_str());
}

TEST(Study, AFailingVariantIsReportedAndTheOthersFinish) {
    const fs::path dir = freshStudyFolder("failing-variant");
    const std::string base = std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/bed_expansion";
    // the second variant's flux lifts the bed to the overflow, where "stop" ends the run
    std::ofstream(dir / "study.toml") << "base = \"" << base << "\"\nthreads = 1\ncombine = \"zip\"\n"
                                      << "[parameters]\n\"gate.flux\" = [1.380e-3, 2.0e-2]\n"
                                      << "\"column.sand_overflow\" = [\"stop\", \"stop\"]\n"
                                      << "[set]\n\"output.fields\" = false\n\"time.end\" = 6.0\n";
    const Command study = runStudy(dir / "study.toml");
    EXPECT_EQ(study.exitCode, 1) << "a study with a failed variant exits 1\n" << study.output;
    EXPECT_NE(study.output.find("did not finish"), std::string::npos) << study.output;
    const auto rows = readStudyCsv(dir / "output" / "study.csv");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].at("status"), "finished");
    EXPECT_NE(rows[0].at("final_bed_height_m"), "");
    EXPECT_EQ(rows[1].at("status"), "failed");
    EXPECT_NE(rows[1].at("error").find("overflow"), std::string::npos) << rows[1].at("error");
}

TEST(Study, ARangeOfWholeNumbersGivesWholeNumbers) {
    // a seed range: the case's integer keys refuse 2.0, so { from = 1, to = 3, step = 1 } must
    // give 1, 2, 3 (it gave 1.0, 2.0, 3.0, and every variant failed its check)
    const fs::path dir = freshStudyFolder("whole-range");
    std::ofstream(dir / "study.toml") << "base = \"" << QUICKSAND_SOURCE_DIR << "/cases/verification/random_bed\"\n"
                                      << "[parameters]\n\"initial.porosity_field.seed\" = { from = 1, to = 3, step = 1 }\n";
    const Command check = runStudy(dir / "study.toml", "--check");
    EXPECT_EQ(check.exitCode, 0) << check.output;
    EXPECT_NE(check.output.find("all 3 variants pass their check"), std::string::npos) << check.output;
}
