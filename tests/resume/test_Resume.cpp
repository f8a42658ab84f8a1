// Checkpoint and resume (ctest label `resume`): a run stopped at t1 and resumed from its
// checkpoint reaches the same state at t2 as a run straight to t2, and its series.csv goes on
// from the checkpoint without duplicated or missing rows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "case/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/Interruption.hpp"
#include "solver/Run.hpp"
#include "solver/RunSize.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <limits>
#include <map>

using namespace qs;
namespace fs = std::filesystem;

namespace {

fs::path freshCopy(const std::string& name, const std::string& tag) {
    const fs::path src = fs::path(QUICKSAND_SOURCE_DIR) / "cases/verification" / name;
    const fs::path dst = fs::path(QUICKSAND_BINARY_DIR) / "resume-tests" / (name + "-" + tag);
    fs::remove_all(dst);
    fs::create_directories(dst);
    fs::copy_file(src / "case.toml", dst / "case.toml");
    return dst;
}

std::vector<std::string> lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> out;
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

/// A resumed run's file equals the straight run's, line by line.
void expectSameLines(const fs::path& straight, const fs::path& resumed) {
    const auto la = lines(straight);
    const auto lb = lines(resumed);
    ASSERT_EQ(la.size(), lb.size());
    for (std::size_t k = 0; k < la.size(); ++k) EXPECT_EQ(la[k], lb[k]) << resumed << " line " << k + 1;
}

/// What a fresh 1D solver of the case says when it loads the checkpoint: its error, or "accepted".
std::string loadingMessage(const CaseConfig& c, const CheckpointData& data) {
    const auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> fresh(c, *reservoir);
    try {
        fresh.loadState(data);
    } catch (const Error& e) {
        return e.what();
    }
    return "accepted";
}

/// The checkpoint with its entries renamed (`rename` gives the new name, empty to leave one out).
template <class Rename>
CheckpointData renamed(const CheckpointData& data, Rename rename) {
    CheckpointData older;
    for (const std::string& name : data.names()) {
        const std::string to = rename(name);
        if (to.empty()) continue;
        try { older.put(to, data.doubles(name)); continue; } catch (const Error&) {}
        try { older.put(to, data.integers(name)); continue; } catch (const Error&) {}
        older.putScalar(to, data.scalar(name));
    }
    return older;
}

/// The checkpoint without one entry, as an older version wrote it.
CheckpointData without(const CheckpointData& data, const std::string& entry) {
    return renamed(data, [&](const std::string& name) { return name == entry ? std::string() : name; });
}

/// The entry names of checkpoints written before the field registry (2026-12-07): the point
/// fields numbered in the registry's order, the grid's carried fields at the root.
std::string numberedName(const std::string& name) {
    static const std::map<std::string, std::string> before = {
        {"solid/position", "solid_field0"},         {"solid/velocity", "solid_field1"},
        {"solid/mass", "solid_field2"},             {"solid/volume", "solid_field3"},
        {"solid/porosity", "solid_field4"},         {"solid/effective_stress", "solid_field5"},
        {"solid/state", "solid_field6"},            {"solid/material", "solid_field7"},
        {"solid/state_variables", "solid_field8"},  {"solid/velocity_gradient", "solid_field9"},
        {"liquid/position", "liquid_field0"},       {"liquid/velocity", "liquid_field1"},
        {"liquid/mass", "liquid_field2"},           {"liquid/volume", "liquid_field3"},
        {"liquid/pore_pressure", "liquid_field4"},  {"liquid/state", "liquid_field5"},
        {"liquid/cavity", "liquid_field6"},         {"nodes/rel_speed", "rel_speed"},
        {"cells/pressure_gradient", "pressure_gradient"}};
    const auto it = before.find(name);
    return it == before.end() ? name : it->second;
}

}  // namespace

TEST(Resume, ResumedRunMatchesStraightRun) {
    RunOptions quiet;
    quiet.quiet = true;

    const fs::path straightDir = freshCopy("falling_head_forchheimer", "straight");
    CaseConfig straight = loadCase(straightDir.string());
    straight.time.end = 0.4;
    const RunSummary a = runCase(straight, quiet);

    const fs::path splitDir = freshCopy("falling_head_forchheimer", "split");
    CaseConfig split = loadCase(splitDir.string());
    split.time.end = 0.4;
    RunOptions first = quiet;
    first.endTime = 0.2;
    runCase(split, first);
    ASSERT_TRUE(fs::exists(splitDir / "output/checkpoint.h5"));
    RunOptions resume = quiet;
    resume.resume = true;
    const RunSummary b = runCase(split, resume);

    EXPECT_DOUBLE_EQ(a.final.time, b.final.time);
    EXPECT_DOUBLE_EQ(a.final.reservoirHead, b.final.reservoirHead);
    EXPECT_DOUBLE_EQ(a.final.gateFlux, b.final.gateFlux);
    EXPECT_DOUBLE_EQ(a.final.cumulativeOutflow, b.final.cumulativeOutflow);
    EXPECT_DOUBLE_EQ(a.final.liquidMass, b.final.liquidMass);
    EXPECT_EQ(a.final.liquidPoints, b.final.liquidPoints);

    // the series of the resumed run equals the straight one line by line
    expectSameLines(straightDir / "output/series.csv", splitDir / "output/series.csv");
}

// The step is fitted to the output interval (solver/TimeLattice.hpp), whose default is end / 100:
// a resume asking for a later end (so another default interval) keeps the checkpoint's step and
// ends where a straight run to that end with the first interval does, bit for bit; a resume whose
// stable step differs (another Courant number) is refused, naming it.
TEST(Resume, AResumeToALaterEndKeepsTheCheckpointsStep) {
    RunOptions quiet;
    quiet.quiet = true;
    const fs::path straightDir = freshCopy("falling_head_forchheimer", "straight-later");
    CaseConfig straight = loadCase(straightDir.string());
    straight.time.end = 0.4;
    straight.time.outputInterval = 0.003;  // the first run's default, 0.3 / 100
    const RunSummary a = runCase(straight, quiet);

    const fs::path splitDir = freshCopy("falling_head_forchheimer", "split-later");
    CaseConfig first = loadCase(splitDir.string());
    first.time.end = 0.3;
    first.time.outputInterval = first.time.end / 100;
    const RunSummary f = runCase(first, quiet);
    CaseConfig later = first;
    later.time.end = 0.4;
    later.time.outputInterval = later.time.end / 100;  // as the default would be
    ASSERT_NE(timeStep(later), f.dt) << "the later end must ask another step, or this tests nothing";
    RunOptions resume = quiet;
    resume.resume = true;
    const RunSummary b = runCase(later, resume);
    EXPECT_EQ(b.dt, f.dt);
    EXPECT_EQ(a.dt, f.dt);
    EXPECT_EQ(a.final.time, b.final.time);
    EXPECT_EQ(a.final.reservoirHead, b.final.reservoirHead);
    EXPECT_EQ(a.final.gateFlux, b.final.gateFlux);
    EXPECT_EQ(a.final.liquidMass, b.final.liquidMass);

    CaseConfig stiffer = later;
    stiffer.time.courant *= 0.9;
    try {
        runCase(stiffer, resume);
        ADD_FAILURE() << "a resume with another Courant number was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("stable step"), std::string::npos) << e.what();
    }
}

TEST(Resume, A2DRunWithPipesResumesWithTheSamePipesCsv) {
    // the random bed with sd 0.02, seed 5, pipes from 0.25 s (cases/studies/pipingSeeds): stopped at
    // 0.5 s, with a pipe in pipes.csv at the checkpoint's time, and resumed, pipes.csv goes on as in
    // the straight run
    RunOptions quiet;
    quiet.quiet = true;
    auto bed = [](const fs::path& dir) {
        CaseConfig c = loadCase(dir.string());
        c.initial.porosityField.standardDeviation = 0.02;
        c.initial.porosityField.seed = 5;
        c.time.end = 0.75;
        return c;
    };
    const fs::path straightDir = freshCopy("random_bed", "straight");
    runCase(bed(straightDir), quiet);

    const fs::path splitDir = freshCopy("random_bed", "split");
    CaseConfig split = bed(splitDir);
    split.time.checkpointInterval = 0.5;
    RunOptions first = quiet;
    first.endTime = 0.5;
    runCase(split, first);
    const auto before = lines(splitDir / "output/pipes.csv");
    ASSERT_FALSE(before.empty());
    EXPECT_NEAR(std::stod(before.back().substr(0, before.back().find(','))), 0.5, 1e-4) << before.back();
    EXPECT_EQ(before.back().find(",nan"), std::string::npos) << "a pipe at the checkpoint: " << before.back();
    RunOptions resume = quiet;
    resume.resume = true;
    runCase(split, resume);

    expectSameLines(straightDir / "output/pipes.csv", splitDir / "output/pipes.csv");
}

/// The semi-implicit step: a 2D run with a pressure gate (the uniform gate's rank-one term), split
/// at 0.5 s and resumed from its checkpoint, goes on as the straight run, line by line.
/// With CG the step carries its starting guesses from one step to the next, which the checkpoint
/// keeps (TimeIntegrator::saveState): without them the resumed run's solves start from zeros and
/// part from the straight run's within CG's tolerance.
void expectSemiImplicitResumeIsBitIdentical(PressureSolver solver, const std::string& tag) {
    RunOptions quiet;
    quiet.quiet = true;
    auto bed = [&](const fs::path& dir) {
        CaseConfig c = loadCase(dir.string());
        c.time.scheme = TimeScheme::SemiImplicit;
        c.time.pressureSolver = solver;
        c.time.end = 1.0;
        return c;
    };
    const fs::path straightDir = freshCopy("random_bed", "semi-straight-" + tag);
    runCase(bed(straightDir), quiet);

    const fs::path splitDir = freshCopy("random_bed", "semi-split-" + tag);
    CaseConfig split = bed(splitDir);
    RunOptions first = quiet;
    first.endTime = 0.5;
    runCase(split, first);
    ASSERT_TRUE(fs::exists(splitDir / "output/checkpoint.h5"));
    RunOptions resume = quiet;
    resume.resume = true;
    runCase(split, resume);

    expectSameLines(straightDir / "output/series.csv", splitDir / "output/series.csv");
    expectSameLines(straightDir / "output/pipes.csv", splitDir / "output/pipes.csv");
}

TEST(Resume, ASemiImplicitRunResumesBitIdentically) {
    expectSemiImplicitResumeIsBitIdentical(PressureSolver::Direct, "direct");
}

TEST(Resume, ASemiImplicitRunWithCGResumesBitIdentically) {
    expectSemiImplicitResumeIsBitIdentical(PressureSolver::ConjugateGradient, "cg");
}

TEST(Resume, ResumeWithoutCheckpointIsAClearError) {
    const fs::path dir = freshCopy("geostatic", "nocheckpoint");
    CaseConfig c = loadCase(dir.string());
    RunOptions o;
    o.quiet = true;
    o.resume = true;
    try {
        runCase(c, o);
        FAIL() << "resume without a checkpoint must fail";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("checkpoint"), std::string::npos) << e.what();
    }
}

TEST(Resume, AnInterruptedRunCheckpointsAndResumesBitIdentically) {
    // SIGINT in the middle of a run: the step ends, a checkpoint is written, Interrupted says how
    // to resume (exit code 130 in the quicksand command); resumed, the run ends exactly where a
    // run never interrupted does
    RunOptions quiet;
    quiet.quiet = true;
    const fs::path straightDir = freshCopy("falling_head_forchheimer", "uninterrupted");
    CaseConfig straight = loadCase(straightDir.string());
    straight.time.end = 0.4;
    const RunSummary a = runCase(straight, quiet);

    const fs::path dir = freshCopy("falling_head_forchheimer", "interrupted");
    CaseConfig c = loadCase(dir.string());
    c.time.end = 0.4;
    RunOptions first = quiet;
    bool sent = false;
    first.onOutput = [&](const ColumnState& s, const std::vector<CellRow>&) {
        if (!sent && s.time > 0.15) { sent = true; std::raise(SIGINT); }
    };
    try {
        runCase(c, first);
        FAIL() << "an interrupted run must stop with Interrupted";
    } catch (const Interrupted& e) {
        EXPECT_EQ(e.signal(), SIGINT);
        EXPECT_EQ(e.exitCode(), 130);
        const std::string what = e.what();
        EXPECT_NE(what.find("interrupted by SIGINT at t = "), std::string::npos) << what;
        EXPECT_NE(what.find("--resume"), std::string::npos) << what;
    }
    ASSERT_TRUE(sent);
    ASSERT_TRUE(fs::exists(dir / "output/checkpoint.h5"));
    RunOptions resume = quiet;
    resume.resume = true;
    const RunSummary b = runCase(c, resume);

    EXPECT_EQ(a.final.time, b.final.time);
    EXPECT_EQ(a.final.reservoirHead, b.final.reservoirHead);
    EXPECT_EQ(a.final.gateFlux, b.final.gateFlux);
    EXPECT_EQ(a.final.liquidMass, b.final.liquidMass);
    EXPECT_EQ(a.final.liquidPoints, b.final.liquidPoints);
    const auto la = lines(straightDir / "output/series.csv");
    const auto lb = lines(dir / "output/series.csv");
    ASSERT_EQ(la.size(), lb.size());
    for (std::size_t k = 0; k < la.size(); ++k) EXPECT_EQ(la[k], lb[k]) << "line " << k + 1;
}

// A checkpoint whose entries are not what saveState wrote (another case's, or damaged past the
// seal) is refused before the first step, naming the entry or point; fuzzing found a position of
// -inf reaching undefined behaviour in the first step (tests/fuzz/fuzz_checkpoint_state.cpp).
TEST(Resume, ACheckpointThatNoStepCouldTakeIsRefusedNamingWhy) {
    const CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
    const auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    solver.runGravityStage();
    CheckpointData good;
    solver.saveState(good);
    auto refusal = [&](const std::string& entry, std::size_t index, double value) {
        CheckpointData bad = good;
        std::vector<double> v = bad.doubles(entry);
        v.at(index) = value;
        bad.put(entry, v);
        return loadingMessage(c, bad);
    };
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(refusal("solid/position", 3, -inf).find("'solid/position' value 3 is -inf"), std::string::npos);
    EXPECT_NE(refusal("solid/position", 3, -0.01).find("solid point 3 at x0 = -0.01 m, outside the grid"),
              std::string::npos);
    EXPECT_NE(refusal("liquid/velocity", 0, 1e3).find("liquid point 0"), std::string::npos);  // faster than a cell per step
    EXPECT_NE(refusal("solid/porosity", 2, 1.5).find("solid point 2 has porosity 1.5"), std::string::npos);
    EXPECT_NE(refusal("ledger", 1, std::nan("")).find("'ledger' value 1 is nan"), std::string::npos);
    CheckpointData shortLedger = good;
    shortLedger.put("ledger", std::vector<double>{1.0});
    const auto other = makeReservoirModel(c);
    DoublePointSolver<1> fresh(c, *other);
    EXPECT_THROW(fresh.loadState(shortLedger), Error);
    const auto third = makeReservoirModel(c);
    DoublePointSolver<1> again(c, *third);
    EXPECT_NO_THROW(again.loadState(good));
    // a damaged step: the resumed run keeps the checkpoint's step (solver/TimeLattice.hpp), whose
    // product with the step count is the time
    for (int k = 0; k < 10; ++k) solver.step();
    CheckpointData stepped;
    solver.saveState(stepped);
    EXPECT_EQ(loadingMessage(c, stepped), "accepted");
    CheckpointData tiny = stepped;
    tiny.putScalar("dt", stepped.scalar("dt") * 1e-3);
    EXPECT_NE(loadingMessage(c, tiny).find("entries 'dt'"), std::string::npos) << loadingMessage(c, tiny);
}

TEST(Resume, ACheckpointWrittenBeforeAPICStillLoads) {
    // Checkpoints written before 2026-12-02 have no solid velocity gradient (APIC's C, field 9):
    // their points start with C = 0 and the run goes on; one that has it gets it back. A
    // consolidating column, so that C is not zero.
    const CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/terzaghi");
    const auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 200; ++k) solver.step();
    CheckpointData now;
    solver.saveState(now);
    ASSERT_TRUE(now.has("solid/velocity_gradient"));
    double largest = 0;
    for (double value : solver.solid().velocityGradient) largest = std::max(largest, std::abs(value));
    ASSERT_GT(largest, 0.0) << "the column is not moving: C would be zero whether saved or not";
    // as such a checkpoint was: numbered entries (before the field registry), no solid_field9
    const CheckpointData older = without(renamed(now, numberedName), "solid_field9");
    const auto r1 = makeReservoirModel(c);
    DoublePointSolver<1> fromOlder(c, *r1);
    ASSERT_NO_THROW(fromOlder.loadState(older));
    for (double value : fromOlder.solid().velocityGradient) EXPECT_EQ(value, 0.0);
    EXPECT_EQ(fromOlder.solid().velocityGradient.size(), fromOlder.solid().size() * 1 * 1);  // D x D, D = 1
    EXPECT_NO_THROW(fromOlder.step());
    const auto r2 = makeReservoirModel(c);
    DoublePointSolver<1> fromNow(c, *r2);
    fromNow.loadState(now);
    EXPECT_EQ(fromNow.solid().velocityGradient, solver.solid().velocityGradient);
    // a checkpoint that names its entries was written after C existed: without it, it is damaged
    const auto r3 = makeReservoirModel(c);
    DoublePointSolver<1> fromDamaged(c, *r3);
    EXPECT_THROW(fromDamaged.loadState(without(now, "solid/velocity_gradient")), Error);
}

// Checkpoints written before the field registry numbered the point fields (solid_field0..9,
// liquid_field0..6) and kept the grid's carried fields at the root: one resumes to the same state,
// bit for bit, as the same checkpoint under the registry's names, and goes on to the same step.
// Every field the registry lists is named in the map of old names (a field added to the registry
// without a date would fail here, as an older checkpoint cannot hold it).
TEST(Resume, ACheckpointWrittenBeforeTheFieldRegistryStillLoads) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/terzaghi");
    c.time.scheme = TimeScheme::SemiImplicit;  // the cells' pressure gradient is carried, not zero
    const auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 50; ++k) solver.step();
    CheckpointData now;
    solver.saveState(now);
    int listed = 0;
    auto known = [&](const std::string& set, const FieldSpec& f) {
        EXPECT_NE(numberedName(set + "/" + f.name), set + "/" + f.name) << set << "/" << f.name;
        ++listed;
    };
    solver.solid().forEachField([&](const auto&, const FieldSpec& f) { known("solid", f); });
    solver.liquid().forEachField([&](const auto&, const FieldSpec& f) { known("liquid", f); });
    EXPECT_EQ(listed, 17);
    // the dated fields non-zero, so that reading them as missing (zeros) would show: the cells'
    // pressure gradient from the consolidation, a cavity put in by hand
    const std::vector<double>& gradient = now.doubles("cells/pressure_gradient");
    ASSERT_TRUE(std::any_of(gradient.begin(), gradient.end(), [](double g) { return g != 0; }));
    std::vector<double> cavity = now.doubles("liquid/cavity");
    for (std::size_t p = 0; p < cavity.size(); p += 3) cavity[p] = 1e-6 * double(p + 1);
    now.put("liquid/cavity", cavity);
    const CheckpointData older = renamed(now, numberedName);
    ASSERT_FALSE(older.has("solid/position"));
    ASSERT_TRUE(older.has("solid_field9") && older.has("liquid_field6") && older.has("pressure_gradient"));

    const auto r1 = makeReservoirModel(c), r2 = makeReservoirModel(c);
    DoublePointSolver<1> fromOlder(c, *r1), fromNow(c, *r2);
    fromOlder.loadState(older);
    fromNow.loadState(now);
    for (int k = 0; k < 20; ++k) {
        fromOlder.step();
        fromNow.step();
    }
    CheckpointData a, b;
    fromOlder.saveState(a);
    fromNow.saveState(b);
    ASSERT_EQ(a.names(), b.names());
    for (const std::string& name : a.names()) {
        try {
            EXPECT_EQ(a.doubles(name), b.doubles(name)) << name;
        } catch (const Error&) {
            try { EXPECT_EQ(a.integers(name), b.integers(name)) << name; } catch (const Error&) {
                EXPECT_EQ(a.scalar(name), b.scalar(name)) << name;
            }
        }
    }

    EXPECT_EQ(fromOlder.liquid().cavity, fromNow.liquid().cavity);

    // one field under both names is refused, not read from either: a point field, a grid field
    for (const auto& [named, numbered] : {std::pair<std::string, std::string>{"liquid/velocity", "liquid_field1"},
                                          {"cells/pressure_gradient", "pressure_gradient"}}) {
        CheckpointData both = now;
        both.put(numbered, now.doubles(named));
        const auto r3 = makeReservoirModel(c);
        DoublePointSolver<1> twice(c, *r3);
        try {
            twice.loadState(both);
            ADD_FAILURE() << "a field written twice was accepted: " << named;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("'" + named + "' and '" + numbered + "' are one field written twice"),
                      std::string::npos)
                << e.what();
        }
    }
}

// The semi-implicit step's size does not see K_L, so a change of water between a checkpoint and
// its resume is caught by the water the checkpoint records; one written before the entry
// (2026-12-06, when a semi-implicit case without the key had the soft 2.128e7 Pa) is refused
// where the case now means real water, and loads where the key is given
TEST(Resume, ACheckpointOfAnotherWaterIsRefused) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/terzaghi");
    c.time.scheme = TimeScheme::SemiImplicit;
    const auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 5; ++k) solver.step();
    CheckpointData written;
    solver.saveState(written);
    auto loadWith = [&](const CheckpointData& data, double bulkModulus, bool given) {
        CaseConfig other = c;
        other.liquid.bulkModulus = bulkModulus;
        other.liquid.bulkModulusGiven = given;
        return loadingMessage(other, data);
    };
    EXPECT_EQ(loadWith(written, c.liquid.bulkModulus, true), "accepted");
    EXPECT_NE(loadWith(written, 2.2e9, false).find("written with liquid.bulk_modulus = 2.128e+07 Pa, the case now gives 2.2e+09 Pa"),
              std::string::npos);
    const CheckpointData older = without(written, "bulk_modulus");
    EXPECT_NE(loadWith(older, 2.2e9, false).find("predates liquid.bulk_modulus's default"), std::string::npos);
    EXPECT_EQ(loadWith(older, c.liquid.bulkModulus, true), "accepted");
}
