#include "FeedLineCase.hpp"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.hpp"

namespace qs::foam {

namespace fs = std::filesystem;

namespace {

/// The file's text without C and C++ comments (OpenFOAM dictionaries use both).
std::string dictionaryText(const fs::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    return std::regex_replace(ss.str(), comments, " ");
}

bool hasDictionary(const std::string& text, const std::string& name) {
    return std::regex_search(text, std::regex("(^|[\\s;}])" + name + "\\s*\\{"));
}

std::string keywordValue(const std::string& text, const std::string& key) {
    std::smatch m;
    if (std::regex_search(text, m, std::regex("(^|[\\s;{}])" + key + "\\s+([^;\\s]+)\\s*;"))) return m[2];
    return "";
}

}  // namespace

void requireSupportedCase(const std::string& directory) {
    const fs::path dir(directory);
    auto fail = [&](const std::string& file, const std::string& why) {
        throw Error("OpenFOAM case " + directory + ": " + file + ": " + why);
    };
    // a case for another kind of solver: say which, and what runs
    const std::string supported =
        "quicksand's feed line is incompressible single-phase flow solved with pimpleFoam's algorithm "
        "(docs/openfoam.md)";
    if (fs::exists(dir / "constant/thermophysicalProperties"))
        fail("constant/thermophysicalProperties", "a compressible or heat-transfer case; " + supported);
    if (fs::is_directory(dir / "0")) {
        for (const auto& e : fs::directory_iterator(dir / "0")) {
            const std::string name = e.path().filename().string();
            if (name.rfind("alpha.", 0) == 0 || name == "alphas")
                fail("0/" + name, "a multiphase case (a phase fraction); " + supported);
            if (name == "p_rgh")
                fail("0/p_rgh", "a buoyant or multiphase case (p_rgh); " + supported + ", whose pressure is p");
        }
    }
    for (const char* needed : {"system/controlDict", "system/fvSchemes", "system/fvSolution",
                               "constant/transportProperties", "0/U", "0/p"})
        if (!fs::exists(dir / needed)) fail(needed, "missing (a pimpleFoam case has it)");
    if (!fs::exists(dir / "constant/turbulenceProperties"))
        fail("constant/turbulenceProperties",
             "missing; pimpleFoam needs it: 'simulationType laminar;' for laminar flow, or "
             "'simulationType RAS; RAS { RASModel kOmegaSST; turbulence on; }' (docs/openfoam.md)");
    const std::string fvSolution = dictionaryText(dir / "system/fvSolution");
    if (!hasDictionary(fvSolution, "PIMPLE")) {
        const std::string had = hasDictionary(fvSolution, "PISO")   ? "a PISO dictionary (icoFoam, pisoFoam)"
                                : hasDictionary(fvSolution, "SIMPLE") ? "a SIMPLE dictionary (simpleFoam: steady)"
                                                                      : "no algorithm dictionary";
        fail("system/fvSolution", "has " + had + " but no PIMPLE dictionary; quicksand runs pimpleFoam's "
             "algorithm (transient). Add 'PIMPLE { nOuterCorrectors 1; nCorrectors 2; "
             "nNonOrthogonalCorrectors 0; }' (nOuterCorrectors 1 is PISO) and solvers for pFinal and UFinal");
    }
    if (fs::exists(dir / "constant/dynamicMeshDict")) {
        const std::string type = keywordValue(dictionaryText(dir / "constant/dynamicMeshDict"), "dynamicFvMesh");
        if (!type.empty() && type != "staticFvMesh")
            fail("constant/dynamicMeshDict", "dynamicFvMesh " + type +
                 ": a moving or changing mesh; quicksand's feed line runs on a static mesh (staticFvMesh)");
    }
}

bool requireDecomposition(const std::string& directory, int ranks) {
    const fs::path file = fs::path(directory) / "system/decomposeParDict";
    if (!fs::exists(file)) return false;
    const std::string where = "OpenFOAM case " + directory + ": system/decomposeParDict: ";
    const std::string text = dictionaryText(file);
    const std::string n = keywordValue(text, "numberOfSubdomains");
    if (n.empty())
        throw Error(where + "no numberOfSubdomains; the line is decomposed into one part per MPI rank: set "
                    "'numberOfSubdomains " + std::to_string(ranks) + ";'");
    int parts = 0;
    try {
        std::size_t used = 0;
        parts = std::stoi(n, &used);
        if (used != n.size()) parts = 0;
    } catch (const std::exception&) {
        parts = 0;
    }
    if (parts != ranks)
        throw Error(where + "numberOfSubdomains " + n + ", but quicksand runs on " + std::to_string(ranks) +
                    " MPI ranks and solves one part of the line on each: set 'numberOfSubdomains " +
                    std::to_string(ranks) + ";' or run with mpirun -np " + n);
    if (keywordValue(text, "method").empty())
        throw Error(where + "no method; give one, e.g. 'method scotch;' (docs/openfoam.md, \"A line on MPI ranks\")");
    return true;
}

std::vector<std::string> describeCase(const std::string& directory, double liquidViscosity, double liquidDensity) {
    const fs::path dir(directory);
    std::vector<std::string> lines;
    const std::string turbulence = dictionaryText(dir / "constant/turbulenceProperties");
    const std::string type = keywordValue(turbulence, "simulationType");
    std::string model = type;
    if (type == "RAS" || type == "LES") {
        const std::string name = keywordValue(turbulence, type + "Model");
        model += " " + (name.empty() ? std::string("(no ") + type + "Model given)" : name);
    }
    lines.push_back("turbulence (constant/turbulenceProperties): " + (model.empty() ? "not given" : model));
    const std::string transport = dictionaryText(dir / "constant/transportProperties");
    const std::string transportModel = keywordValue(transport, "transportModel");
    // nu as "nu 1e-06;" or with dimensions "nu [0 2 -1 0 0 0 0] 1e-06;"
    std::smatch m;
    double nu = 0;
    if (std::regex_search(transport, m, std::regex(R"((^|[\s;{}])nu\s+(\[[^\]]*\]\s*)?([-+0-9.eE]+)\s*;)")))
        nu = std::stod(m[3]);
    std::ostringstream t;
    t << "transport (constant/transportProperties): " << (transportModel.empty() ? "?" : transportModel);
    if (nu > 0) t << ", nu = " << nu << " m2/s";
    lines.push_back(t.str());
    const double water = liquidViscosity / liquidDensity;
    if (nu > 0 && transportModel == "Newtonian" && std::abs(nu / water - 1) > 0.01) {
        std::ostringstream n;
        n << "note: the OpenFOAM case's nu = " << nu << " m2/s is not the column's water, liquid.viscosity / "
          << "liquid.density = " << water << " m2/s: the line carries another fluid";
        lines.push_back(n.str());
    }
    for (const char* where : {"constant/fvOptions", "system/fvOptions"})
        if (fs::exists(dir / where)) lines.push_back(std::string("fvOptions: ") + where);
    return lines;
}

}  // namespace qs::foam
