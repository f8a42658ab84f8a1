// The quicksand command.
//
//   quicksand check CASE            validate CASE/case.toml and print derived quantities
//   quicksand run CASE [--resume]   run it; results in CASE/output (series.csv, fields.h5/.xdmf)
//
// Exit codes: 0 success, 1 bad input or run-time error (message on stderr), 2 usage.
#include <cstring>
#include <iostream>
#include <string>

#include "app/CheckReport.hpp"
#include "core/Error.hpp"
#include "FoamAvailability.hpp"
#include "io/CaseLoader.hpp"
#include "solver/Interruption.hpp"
#include "solver/Run.hpp"

namespace {

int usage() {
    std::cerr << "usage: quicksand check CASE_DIRECTORY\n"
                 "       quicksand run CASE_DIRECTORY [--resume] [--quiet]\n"
                 "CASE_DIRECTORY holds case.toml (keys: docs/case-format.md).\n";
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
    for (int k = 3; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--resume")) options.resume = true;
        else if (!std::strcmp(argv[k], "--quiet")) options.quiet = true;
        else return usage();
    }
    qs::foam::registerFoamCoupling();
    try {
        const qs::CaseConfig config = qs::loadCase(caseDir);
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
