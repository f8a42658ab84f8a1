// The quicksand command.
//
//   quicksand check CASE [--ranks N] [--set KEY=VALUE]...  validate CASE/case.toml, print derived
//                                                        quantities (and the decomposition over
//                                                        N ranks, or over mpirun's ranks)
//   quicksand run CASE [--resume] [--set KEY=VALUE]...   run it; results in CASE/output (series.csv,
//                                                        fields.h5/.xdmf, case.effective.toml)
//   quicksand --version                                  the version and the build's options
// --set overrides one key of case.toml for this run (case/CaseOverride.hpp, docs/case-format.md).
// Under `mpirun -np N` every rank runs this; what the ranks print, rank 0 prints once.
//
// Exit codes: 0 success, 1 bad input or run-time error (message on stderr), 2 usage.
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "app/CheckReport.hpp"
#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "FoamAvailability.hpp"
#include "case/CaseLoader.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "solver/Interruption.hpp"
#include "solver/Run.hpp"

namespace {

int usage() {
    if (qs::Communicator::world().rank() != 0) return 2;
    std::cerr << "usage: quicksand check CASE_DIRECTORY [--ranks N] [--set KEY=VALUE]...\n"
                 "       quicksand run CASE_DIRECTORY [--resume] [--quiet] [--set KEY=VALUE]...\n"
                 "       quicksand --version\n"
                 "CASE_DIRECTORY holds case.toml (keys: docs/case-format.md). --set overrides one key\n"
                 "for this run: --set reservoir.area=0.02 --set layers[0].thickness=0.2\n"
                 "--ranks N prints how the grid would be cut over N MPI ranks (under mpirun: its ranks)\n";
    return 2;
}

/// One error, once: each rank says whether it failed, and the lowest rank that did prints its
/// message (a case that does not load fails on every rank alike; it is said once, not N times).
int reportOnce(const std::string& message, bool failed) {
    const qs::Communicator& world = qs::Communicator::world();
    const std::vector<double> failures = world.allGather(failed ? 1.0 : 0.0);
    int first = -1;
    for (std::size_t r = 0; r < failures.size() && first < 0; ++r)
        if (failures[r] != 0) first = static_cast<int>(r);
    if (first < 0) return 0;
    if (world.rank() == first) {
        std::cerr << "quicksand: error: " << (world.parallel() ? "rank " + std::to_string(first) + ": " : "")
                  << message << "\n";
    }
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    qs::MpiSession mpi(argc, argv);
    const qs::Communicator& world = qs::Communicator::world();
    if (argc == 2 && !std::strcmp(argv[1], "--version")) {
        if (world.rank() == 0) std::cout << qs::versionText();
        return 0;
    }
    if (argc < 3) return usage();
    const std::string command = argv[1], caseDir = argv[2];
    if (command != "check" && command != "run") {
        if (world.rank() == 0) std::cerr << "quicksand: unknown command '" << command << "'\n";
        return usage();
    }
    qs::RunOptions options;
    std::vector<std::string> sets;
    int ranks = world.size();
    for (int k = 3; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--resume")) options.resume = true;
        else if (!std::strcmp(argv[k], "--quiet")) options.quiet = true;
        else if (!std::strcmp(argv[k], "--set") && k + 1 < argc) sets.push_back(argv[++k]);
        else if (!std::strncmp(argv[k], "--set=", 6)) sets.push_back(argv[k] + 6);
        else if (command == "check" && !std::strcmp(argv[k], "--ranks") && k + 1 < argc) {
            char* end = nullptr;
            const long n = std::strtol(argv[++k], &end, 10);
            if (*end != '\0' || n < 1 || n > 1000000) {
                if (world.rank() == 0) std::cerr << "quicksand: --ranks takes a whole number of ranks >= 1, not '" << argv[k] << "'\n";
                return 2;
            }
            ranks = static_cast<int>(n);
        } else {
            if (world.rank() == 0) std::cerr << "quicksand: unknown option '" << argv[k] << "'\n";
            return usage();
        }
    }
    qs::foam::registerFoamCoupling();

    // The case, on every rank: loading is collective in effect (every rank reads the same file),
    // so a bad case fails everywhere and is said once.
    qs::CaseConfig config;
    std::string failure;
    try {
        std::vector<qs::CaseOverride> overrides;
        for (const std::string& set : sets) overrides.push_back(qs::parseOverride(set));
        config = qs::loadCase(caseDir, overrides);
    } catch (const qs::Error& e) {
        failure = e.what();
    } catch (const std::exception& e) {
        failure = std::string("internal error: ") + e.what();
    }
    if (reportOnce(failure, !failure.empty())) return 1;

    if (command == "check") {
        // deterministic on every rank: each fails or passes alike, and rank 0 prints
        std::ostringstream report;
        try {
            qs::printCheckReport(config, report);
            const bool line = config.reservoir.kind == qs::ReservoirKind::OpenFoam;
            if (ranks > 1 && line && !qs::cutBesideALine(config, ranks)) {
                // 1D, or too few columns: each rank steps the column whole beside its part of the line
                report << "decomposition: " << ranks << " ranks: the column is stepped whole on each ("
                       << (config.grid.dimension == 1       ? "a 1D column is not cut"
                           : qs::decomposable(config, ranks) ? "its semi-implicit step needs hypre to be cut"
                                                               : "too few columns to cut")
                       << "); the OpenFOAM line is decomposed by its system/decomposeParDict (numberOfSubdomains "
                       << ranks << "), or solved on rank 0 without one (docs/openfoam.md, \"A line on MPI ranks\")\n";
            } else {
                const qs::Decomposition d = qs::decompose(config, ranks);
                if (ranks > 1) report << qs::describe(d);
                if (ranks > 1 && line)
                    report << "decomposition: the OpenFOAM line is decomposed by its system/decomposeParDict "
                           << "(numberOfSubdomains " << ranks << "), or solved on rank 0 without one\n";
            }
        } catch (const qs::Error& e) {
            failure = e.what();
        } catch (const std::exception& e) {
            failure = std::string("internal error: ") + e.what();
        }
        if (reportOnce(failure, !failure.empty())) return 1;
        if (world.rank() == 0) std::cout << report.str();
        return 0;
    }

    if (world.parallel()) options.ranks = &world;
    try {
        qs::runCase(config, options);
        return 0;
    } catch (const qs::SharedError& e) {
        // every rank has it (the run's opening agreed on it): said once, and no rank waits
        if (world.rank() == 0) std::cerr << "quicksand: error: " << e.what() << "\n";
        return 1;
    } catch (const qs::Interrupted& e) {
        if (world.rank() == 0) std::cerr << "quicksand: " << e.what() << "\n";
        return e.exitCode();
    } catch (const qs::Error& e) {
        failure = e.what();
    } catch (const std::exception& e) {
        failure = std::string("internal error: ") + e.what();
    }
    // a run's error may be one rank's alone, whose partners would wait for it in their next
    // reduction: it ends every rank, said by the rank that met it
    if (world.parallel()) {
        std::cerr << "quicksand: error: rank " << world.rank() << ": " << failure << "\n";
        world.abort(1);
    }
    std::cerr << "quicksand: error: " << failure << "\n";
    return 1;
}
