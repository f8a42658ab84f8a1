#pragma once
// The P0 sand of physics.md section 4 as a suspension (Kozeny-Carman from D = 0.261 mm, Ergun
// A = 150, B = 1.75, in water at 8.91e-4 Pa s), for the drift-flux and stability closed forms.
#include "physics/DriftFlux.hpp"

namespace qs::test {

inline closed::SuspensionFlux p0Sand() {
    closed::SuspensionFlux f;
    f.law.mode = PermeabilityMode::KozenyCarman;
    f.law.grainSize = 2.61e-4;
    f.law.A = 150;
    f.law.B = 1.75;
    f.grainDensity = 2650;
    f.liquidDensity = 998.2;
    f.gravity = 9.81;
    f.viscosity = 8.91e-4;
    return f;
}

}  // namespace qs::test
