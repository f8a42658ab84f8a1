// libFuzzer target: any bytes as case.toml. The loader and the checks that `check` and `run` make
// before the first step must either accept the case or throw qs::Error; anything else (a crash,
// a sanitizer report, another exception, a hang) is a defect. Run: tests/fuzz/README.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "solver/RunSize.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const qs::CaseConfig config = qs::parseCase(text, "fuzz/case.toml", "/nonexistent-fuzz-case");
        qs::requireStableTimeStep(config);
        qs::requireFitsMachine(config, qs::estimateRunSize(config), qs::machineMemory());
    } catch (const qs::Error&) {
        // refused with a message: what bad input must get
    }
    return 0;
}
