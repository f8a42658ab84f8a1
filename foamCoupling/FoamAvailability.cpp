#include "FoamAvailability.hpp"

namespace qs::foam {
bool available() { return false; }
void registerFoamCoupling() {}
}  // namespace qs::foam
