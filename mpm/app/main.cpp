// The quicksand command.
//
//   quicksand check CASE [--set KEY=VALUE]...            validate CASE/case.toml, print derived quantities
//   quicksand run CASE [--resume] [--set KEY=VALUE]...   run it; results in CASE/output (series.csv,
//                                                        fields.h5/.xdmf, case.effective.toml)
// --set overrides one key of case.toml for this run (io/CaseOverride.hpp, docs/case-format.md).
//
// Exit codes: 0 success, 1 bad input or run-time error (message on stderr), 2 usage.
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "app/CheckReport.hpp"
#include "core/Error.hpp"
#include "FoamAvailability.hpp"
#include "io/CaseLoader.hpp"
#include "solver/Interruption.hpp"
#include "solver/Run.hpp"

namespace {

int usage() {
    std::cerr << "usage: quicksand check CASE_DIRECTORY [--set KEY=VALUE]...\n"
                 "       quicksand run CASE_DIRECTORY [--resume] [--quiet] [--set KEY=VALUE]...\n"
                 "CASE_DIRECTORY holds case.toml (keys: docs/case-format.md). --set overrides one key\n"
                 "for this run: --set reservoir.area=0.02 --set layers[0].thickness=0.2\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) return usage();
    const std::string command = argv[1], caseDir = argv[2];
    if (command != "check" && command != "run") {
        std::cerr << "quicksand: unknown command '" << command << "'\n";
        return usage();
    }
    qs::RunOptions options;
    std::vector<std::string> sets;
    for (int k = 3; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--resume")) options.resume = true;
        else if (!std::strcmp(argv[k], "--quiet")) options.quiet = true;
        else if (!std::strcmp(argv[k], "--set") && k + 1 < argc) sets.push_back(argv[++k]);
        else if (!std::strncmp(argv[k], "--set=", 6)) sets.push_back(argv[k] + 6);
        else {
            std::cerr << "quicksand: unknown option '" << argv[k] << "'\n";
            return usage();
        }
    }
    qs::foam::registerFoamCoupling();
    try {
        std::vector<qs::CaseOverride> overrides;
        for (const std::string& set : sets) overrides.push_back(qs::parseOverride(set));
        const qs::CaseConfig config = qs::loadCase(caseDir, overrides);
        if (command == "check") {
            qs::printCheckReport(config, std::cout);
            return 0;
        }
        if (command == "run") {
            qs::runCase(config, options);
            return 0;
        }
        return usage();
    } catch (const qs::Interrupted& e) {
        std::cerr << "quicksand: " << e.what() << "\n";
        return e.exitCode();
    } catch (const qs::Error& e) {
        std::cerr << "quicksand: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "quicksand: internal error: " << e.what() << "\n";
        return 1;
    }
}
