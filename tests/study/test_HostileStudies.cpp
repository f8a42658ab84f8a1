// Study files a user gets wrong (labels `study` and `hostile`): each is refused before any run,
// exit 1, with a message naming the study file, the key or the variant, and what is expected; no
// variant's output is written.
#include <gtest/gtest.h>

#include "StudyTestSupport.hpp"

using namespace qs::test;

namespace {

const std::string kBase = std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/falling_head";

/// Writes the study file and runs the tool on it; the output folder must not appear
Command refused(const std::string& tag, const std::string& text) {
    const fs::path dir = freshStudyFolder("hostile-" + tag);
    std::ofstream(dir / "study.toml") << text;
    const Command r = runStudy(dir / "study.toml", "--quiet");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find((dir / "study.toml").string()), std::string::npos) << "names the study file:\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "output")) << "nothing may run";
    return r;
}

}  // namespace

TEST(HostileStudies, AnEmptyParameterList) {
    const Command r = refused("empty-list", "base = \"" + kBase + "\"\n[parameters]\n\"reservoir.area\" = []\n");
    EXPECT_NE(r.output.find("key 'parameters.\"reservoir.area\"': an empty list of values"), std::string::npos) << r.output;
    const Command none = refused("no-parameters", "base = \"" + kBase + "\"\n");
    EXPECT_NE(none.output.find("key 'parameters': missing or empty"), std::string::npos) << none.output;
}

TEST(HostileStudies, AParameterThatIsNotACaseKey) {
    const Command r = refused("not-a-key", "base = \"" + kBase + "\"\n[parameters]\n\"reservoir.aera\" = [1e-4, 2e-4]\n");
    EXPECT_NE(r.output.find("2 of 2 variants fail their check"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("01_aera=0.0001: "), std::string::npos) << "names each variant:\n" << r.output;
    EXPECT_NE(r.output.find("--set reservoir.aera=0.0001: key 'reservoir.aera': unknown key 'aera'. Did you mean 'area'?"),
              std::string::npos)
        << r.output;
}

TEST(HostileStudies, AnIncompatibleCombination) {
    // zip needs lists of one length
    const Command zip = refused("zip-lengths", "base = \"" + kBase + "\"\ncombine = \"zip\"\n[parameters]\n"
                                               "\"reservoir.area\" = [1e-4, 2e-4]\n\"time.end\" = [1, 2, 3]\n");
    EXPECT_NE(zip.output.find("key 'combine': \"zip\" takes the i-th value"), std::string::npos) << zip.output;
    // a combination the case refuses: a constant head has no area, in the variants that pick it
    const Command model = refused("model-and-area", "base = \"" + kBase + "\"\n[parameters]\n"
                                                    "\"reservoir.model\" = [\"lumped\", \"constant_head\"]\n"
                                                    "\"reservoir.area\" = [1e-4]\n");
    EXPECT_NE(model.output.find("1 of 2 variants fail their check"), std::string::npos) << model.output;
    EXPECT_NE(model.output.find("02_model=constant_head_area=0.0001: "), std::string::npos) << model.output;
    EXPECT_NE(model.output.find("does not apply to model = \"constant_head\""), std::string::npos) << model.output;
}

TEST(HostileStudies, ABaseCaseThatIsMissing) {
    const Command r = refused("missing-base", "base = \"no/such/case\"\n[parameters]\n\"time.end\" = [1]\n");
    EXPECT_NE(r.output.find("key 'base':"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("is not a case directory (no case.toml there)"), std::string::npos) << r.output;
    const Command none = refused("no-base", "[parameters]\n\"time.end\" = [1]\n");
    EXPECT_NE(none.output.find("key 'base': missing"), std::string::npos) << none.output;
}

TEST(HostileStudies, UnknownKeysAndBadRanges) {
    const Command key = refused("unknown-key", "base = \"" + kBase + "\"\nparalel = 2\n[parameters]\n\"time.end\" = [1]\n");
    EXPECT_NE(key.output.find("key 'paralel': unknown key; did you mean 'parallel'?"), std::string::npos) << key.output;
    const Command range = refused("bad-range", "base = \"" + kBase + "\"\n[parameters]\n"
                                                "\"time.end\" = { from = 1, to = 2 }\n");
    EXPECT_NE(range.output.find("exactly one of 'count'"), std::string::npos) << range.output;
    const Command syntax = refused("syntax", "base = \"" + kBase + "\"\n[parameters\n");
    EXPECT_NE(syntax.output.find("TOML syntax error"), std::string::npos) << syntax.output;
}
