#pragma once
// What this build knows about OpenFOAM. registerFoamCoupling() registers the OpenFOAM reservoir
// (FoamReservoir, a WindowedModel) with qs::registerOpenFoamModel; without OpenFOAM it registers
// nothing and a case asking for reservoir.model = "openfoam" gets a clear error.
namespace qs::foam {
bool available();
void registerFoamCoupling();
}  // namespace qs::foam
