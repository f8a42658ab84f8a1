#pragma once
// The compression waves of the saturated sand, as the solver's time step needs them (physics.md
// section 2, wave speeds). The skeleton's stiffness comes from the constitutive seam
// (ConstitutiveModel::oedometricModulus), so a new material model sizes the step without an edit
// here; the water's from liquid.bulk_modulus.
//
// The solver's own implementation: the tests check it against physics/ClosedForms (the Biot
// eigenvalues from the trace and determinant, tests/unit/physics/test_WaveSpeeds.cpp), so the two
// must stay independent. Here the generalised eigenproblem K u = c^2 M u is solved by Eigen.
#include "core/Types.hpp"

namespace qs {

/// m/s, the compression waves of one sand in its water.
struct MixtureWaves {
    Real fast = 0;      ///< Biot's fast wave without drag: grains and water in phase
    Real slow = 0;      ///< Biot's slow wave without drag: grains and water against each other
    Real skeleton = 0;  ///< the skeleton's own wave, sqrt(E_oed / ((1 - n) rho_s)): drained, no water
};

/// The waves of a sand of porosity n, oedometric modulus E_oed (Pa) and grain density rho_s
/// (kg/m3) in water of bulk modulus K_L (Pa) and density rho_L (kg/m3), without drag and with
/// incompressible grains: K = [[E_oed + (1-n)^2 K_L/n, (1-n) K_L], [(1-n) K_L, n K_L]],
/// M = diag((1-n) rho_s, n rho_L) for the phases' displacements.
MixtureWaves mixtureWaves(Real oedometricModulus, Real liquidBulkModulus, Real porosity, Real grainDensity,
                          Real liquidDensity);

/// m/s, sound in free water, sqrt(K_L / rho_L).
Real freeWaterWave(Real liquidBulkModulus, Real liquidDensity);

}  // namespace qs
