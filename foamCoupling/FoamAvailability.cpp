#include "FoamAvailability.hpp"

#ifdef QUICKSAND_WITH_OPENFOAM
#include "FeedLineCase.hpp"
#include "FoamReservoir.hpp"
#endif

namespace qs::foam {

#ifdef QUICKSAND_WITH_OPENFOAM
bool available() { return true; }
void registerFoamCoupling() {
    registerOpenFoamModel(
        [](const CaseConfig& c, bool resume, const Communicator* ranks) {
            return std::make_unique<FoamReservoir>(c, resume, ranks);
        });
    registerOpenFoamCaseCheck([](const CaseConfig& c) {
        requireSupportedCase(c.reservoir.openfoamCase);
        return describeCase(c.reservoir.openfoamCase, c.liquid.viscosity, c.liquid.density);
    });
}
#else
bool available() { return false; }
void registerFoamCoupling() {}  // reservoir.model = "openfoam" then names the missing OpenFOAM
#endif

}  // namespace qs::foam
