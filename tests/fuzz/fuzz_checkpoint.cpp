// libFuzzer target: any bytes as OUTPUT/checkpoint.h5 of a fixed case (the geostatic column).
// Reading it and loading it into a fresh solver must either succeed or throw qs::Error; a crash,
// a sanitizer report, another exception or a hang is a defect. Run: tests/fuzz/README.md.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

namespace {

const qs::CaseConfig& fuzzCase() {
    static const qs::CaseConfig config = qs::loadCase(QUICKSAND_FUZZ_CASE);
    return config;
}

/// The input goes through a real file: readCheckpoint's contract is a path. One per process,
/// in memory where there is a /dev/shm.
const std::string& scratchPath() {
    static const std::string path =
        (access("/dev/shm", W_OK) == 0 ? std::string("/dev/shm") : std::string("/tmp")) +
        "/quicksand-fuzz-checkpoint-" + std::to_string(getpid()) + ".h5";
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::FILE* file = std::fopen(scratchPath().c_str(), "wb");
    if (!file) return 0;
    std::fwrite(data, 1, size, file);
    std::fclose(file);
    try {
        const qs::CheckpointData checkpoint = qs::readCheckpoint(scratchPath());
        const std::unique_ptr<qs::ReservoirModel> reservoir = qs::makeReservoirModel(fuzzCase());
        qs::DoublePointSolver<1> solver(fuzzCase(), *reservoir);
        solver.loadState(checkpoint);
    } catch (const qs::Error&) {
        // refused with a message: what a foreign or damaged checkpoint must get
    }
    return 0;
}
