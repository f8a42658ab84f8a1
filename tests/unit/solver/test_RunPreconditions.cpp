// validateRun is what `quicksand check` and `run` share: a case run refuses before its first
// step, check refuses too, with the same message, and without printing a report.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "app/CheckReport.hpp"
#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "solver/Run.hpp"
#include "solver/RunPreconditions.hpp"

namespace qs {
namespace {

CaseConfig shippedCase(const std::string& name) {
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/" + name);
}

/// The message `action` throws ("" if it throws nothing).
template <class Action>
std::string messageOf(Action action) {
    try {
        action();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// Expects validateRun, the check report and the run to refuse `c` with one message; returns it.
std::string expectRefusedAlike(const CaseConfig& c) {
    const std::string validated = messageOf([&] { validateRun(c); });
    std::ostringstream report;
    const std::string checked = messageOf([&] { printCheckReport(c, report); });
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    const std::string run = messageOf([&] { runCase(c, o); });
    EXPECT_FALSE(validated.empty());
    EXPECT_EQ(checked, validated);
    EXPECT_EQ(run, validated);
    EXPECT_EQ(report.str(), "") << "check printed a report of a case it refuses";
    return validated;
}

TEST(RunPreconditions, ATimeStepBeyondTheStableOneIsRefusedByCheckAsByRun) {
    CaseConfig c = shippedCase("verification/geostatic");
    c.time.dt = 1e-3;
    const std::string what = expectRefusedAlike(c);
    EXPECT_NE(what.find("case.toml: key 'time.dt': 0.001 s exceeds the stable step"), std::string::npos) << what;
}

TEST(RunPreconditions, AReservoirTheRunCannotMakeIsRefusedByCheckToo) {
    // the loader accepts gravity = 0; a lumped reservoir needs gravity to drive its tube
    CaseConfig c = shippedCase("deltaresColumnLumped");
    c.gravity = 0;
    const std::string what = expectRefusedAlike(c);
    EXPECT_NE(what.find("lumped reservoir"), std::string::npos) << what;
}

TEST(RunPreconditions, ACaseTheRunAcceptsPassesAndIsReported) {
    const CaseConfig c = shippedCase("verification/geostatic");
    EXPECT_NO_THROW(validateRun(c));
    std::ostringstream report;
    printCheckReport(c, report);
    EXPECT_NE(report.str().find("case OK"), std::string::npos) << report.str();
}

}  // namespace
}  // namespace qs
