#pragma once
// What this build knows about OpenFOAM. The OpenFOAM reservoir model (issue 3) registers itself
// with qs::registerOpenFoamReservoir from registerFoamCoupling(); without OpenFOAM the stub
// registers nothing and a case asking for reservoir.model = "openfoam" gets a clear error.
namespace qs::foam {
bool available();
void registerFoamCoupling();
}  // namespace qs::foam
