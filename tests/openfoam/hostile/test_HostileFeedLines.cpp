// OpenFOAM cases quicksand cannot run (ctest labels `openfoam` and `hostile`, issue 21): a user's
// case of another kind of solver, a broken or unknown turbulence model, coupled patches whose
// conditions quicksand cannot set. Each, run through the quicksand command, exits 1 with
// "quicksand: error:", names the user's file (not the run's working copy) and what is supported,
// and leaves the earlier output/ as it was. Skips, saying why, where this build has no OpenFOAM.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "../OpenFoamTestSupport.hpp"

using namespace qs::test;
namespace fs = std::filesystem;

namespace {

/// An OpenFOAM dictionary file with the header OpenFOAM expects and `body`.
void writeDictionary(const fs::path& file, const std::string& cls, const std::string& body) {
    std::ofstream(file) << "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class " << cls
                        << ";\n    object " << file.filename().string() << ";\n}\n\n"
                        << body << "\n";
}

struct Hostile {
    const char* tag;
    std::function<void(const fs::path& reservoir)> breakIt;
    std::vector<std::string> expected;  ///< texts the error must contain
};

}  // namespace

TEST(HostileFeedLines, EachGetsAClearErrorAndLeavesTheOutputAlone) {
    QS_REQUIRE_OPENFOAM();
    const std::vector<Hostile> cases = {
        {"compressible",
         [](const fs::path& r) {
             writeDictionary(r / "constant/thermophysicalProperties", "dictionary",
                             "thermoType { type hePsiThermo; mixture pureMixture; }");
         },
         {"constant/thermophysicalProperties", "compressible", "incompressible single-phase"}},
        {"multiphase",
         [](const fs::path& r) { fs::copy_file(r / "0/p", r / "0/alpha.water"); },
         {"0/alpha.water", "multiphase", "incompressible single-phase"}},
        {"buoyant",
         [](const fs::path& r) { fs::copy_file(r / "0/p", r / "0/p_rgh"); },
         {"0/p_rgh", "buoyant"}},
        {"no-turbulenceProperties",
         [](const fs::path& r) { fs::remove(r / "constant/turbulenceProperties"); },
         {"constant/turbulenceProperties", "missing", "simulationType laminar"}},
        {"broken-turbulenceProperties",
         [](const fs::path& r) {
             replaceInFile(r / "constant/turbulenceProperties", "simulationType  laminar;", "simulationType  RAS;");
         },
         {"turbulenceProperties", "RAS"}},
        {"unknown-turbulence-model",
         [](const fs::path& r) {
             replaceInFile(r / "constant/turbulenceProperties", "simulationType  laminar;",
                           "simulationType  RAS;\nRAS { RASModel kOmegaSSTT; turbulence on; printCoeffs off; }");
         },
         {"kOmegaSSTT", "turbulenceProperties", "kOmegaSST", "kEpsilon"}},  // OpenFOAM's list of valid models
        {"piso-only",
         [](const fs::path& r) { replaceInFile(r / "system/fvSolution", "PIMPLE\n{", "PISO\n{"); },
         {"system/fvSolution", "PISO", "PIMPLE"}},
        {"moving-mesh",
         [](const fs::path& r) {
             writeDictionary(r / "constant/dynamicMeshDict", "dictionary",
                             "dynamicFvMesh   dynamicMotionSolverFvMesh;\nmotionSolver solidBody;");
         },
         {"constant/dynamicMeshDict", "dynamicMotionSolverFvMesh", "static mesh"}},
        {"gate-U-not-settable",
         [](const fs::path& r) {
             replaceInFile(r / "0/U", "type            fixedValue;\n        value           uniform (0 0 0);",
                           "type            zeroGradient;");
         },
         {"0/U", "patch gate", "zeroGradient", "fixedValue"}},
        {"reservoir-p-not-settable",
         [](const fs::path& r) {
             replaceInFile(r / "0/p", "type            totalPressure;\n        p0              uniform 0;",
                           "type            zeroGradient;\n        p0x             uniform 0;");
         },
         {"0/p", "patch reservoir", "totalPressure"}},
    };
    for (const auto& h : cases) {
        SCOPED_TRACE(h.tag);
        const fs::path dir = freshCaseCopy("verification/openfoam_short_tube", std::string("hostile-") + h.tag);
        h.breakIt(dir / "reservoir");
        fs::create_directories(dir / "output");  // earlier results, which must survive byte for byte
        std::ofstream(dir / "output/series.csv") << "earlier results\n";
        const fs::path err = dir / "stderr.txt";
        const std::string cmd = std::string("timeout 300 ") + QUICKSAND_EXECUTABLE + " run '" + dir.string() +
                                "' --quiet > /dev/null 2> '" + err.string() + "'";
        const int status = std::system(cmd.c_str());
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        const std::string text = readFile(err);
        EXPECT_EQ(code, 1) << text;  // not 124 (a hang), not a signal
        EXPECT_NE(text.find("quicksand: error:"), std::string::npos) << text;
        for (const auto& e : h.expected) EXPECT_NE(text.find(e), std::string::npos) << "'" << e << "' in: " << text;
        // the user's case is named, never the run's working copy
        EXPECT_EQ(text.find("output/openfoam"), std::string::npos) << text;
        EXPECT_NE(text.find((dir / "reservoir").string()), std::string::npos) << text;
        EXPECT_EQ(readFile(dir / "output/series.csv"), "earlier results\n");
        EXPECT_FALSE(fs::exists(dir / "output/openfoam")) << "a failed start left a working copy";
        std::printf("%s: %s", h.tag, text.c_str());
    }
}
