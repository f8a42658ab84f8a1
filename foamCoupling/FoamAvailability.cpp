#include "FoamAvailability.hpp"

#ifdef QUICKSAND_WITH_OPENFOAM
#include "FoamReservoir.hpp"
#endif

namespace qs::foam {

#ifdef QUICKSAND_WITH_OPENFOAM
bool available() { return true; }
void registerFoamCoupling() {
    registerOpenFoamModel(
        [](const CaseConfig& c, bool resume) { return std::make_unique<FoamReservoir>(c, resume); });
}
#else
bool available() { return false; }
void registerFoamCoupling() {}  // reservoir.model = "openfoam" then names the missing OpenFOAM
#endif

}  // namespace qs::foam
