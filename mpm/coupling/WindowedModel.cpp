#include "coupling/WindowedModel.hpp"

#include "core/Error.hpp"

namespace qs {

namespace {
WindowedModelFactory& openFoamFactory() {
    static WindowedModelFactory factory;
    return factory;
}
}  // namespace

void registerOpenFoamModel(WindowedModelFactory factory) { openFoamFactory() = std::move(factory); }

namespace {
OpenFoamCaseCheck& openFoamCaseCheck() {
    static OpenFoamCaseCheck check;
    return check;
}
}  // namespace

void registerOpenFoamCaseCheck(OpenFoamCaseCheck check) { openFoamCaseCheck() = std::move(check); }

std::vector<std::string> checkOpenFoamCase(const CaseConfig& config) {
    if (!openFoamCaseCheck()) return {};
    return openFoamCaseCheck()(config);
}

std::unique_ptr<WindowedModel> makeOpenFoamModel(const CaseConfig& config, bool resume, const Communicator* ranks) {
    if (!openFoamFactory())
        throw Error(
            "case.toml: key 'reservoir.model': \"openfoam\" needs a quicksand build with OpenFOAM; "
            "this build has none. Install it with tools/setup.sh --openfoam and rebuild, or use "
            "\"constant_head\" or \"lumped\".");
    return openFoamFactory()(config, resume, ranks);
}

}  // namespace qs
