#pragma once
// ConstitutiveModel: the seam between the solver and the skeleton's stress-strain law.
//
// Usage (the solver, once per solid point and step, after the kinematics):
//   StressPoint sp{dEps, stress, state, dt};
//   const StressReturn r = model.update(sp);      // stress and state updated in place
//   if (isStressFree(stress)) ...                 // the liquid-state switch reads this
//
// The call has the shape of the field's standard user-material convention (Abaqus UMAT: strain
// increment and state variables in, stress and state variables out, per point and increment),
// so that a UMAT can later be wrapped behind this interface by one adapter file: `stress` is
// STRESS, `state` is STATEV (stateCount() = NSTATV), `strainIncrement` is DSTRAN with tensor
// (not engineering) shear components, `dt` is DTIME. Material constants are the model's own
// members (PROPS), set once when the model is made from the case (materials/ConstitutiveModels).
// The model never sees the grid or the point's neighbours, so one implementation serves 1D, 2D
// and 3D: strains and stresses are always full 3D tensors (materials/StressTensor.hpp).
//
// Conventions (physics.md section 2): Voigt order xx, yy, zz, yz, xz, xy; strain extension
// positive; effective stress tension positive; Pa, s.
#include <memory>
#include <string>

#include "core/Types.hpp"

namespace qs {

/// What a stress return did. The solver counts them and writes them to fields.h5.
enum class StressReturn : int {
    Elastic = 0,        ///< the trial stress was admissible
    TensionCutoff = 1,  ///< principal stresses returned to the tension limit
    Plane = 2,          ///< return to one yield plane (Mohr-Coulomb)
    Edge = 3,           ///< return to the intersection line of two yield planes
    Apex = 4,           ///< return to the apex of the yield surface
};

/// One point's arguments for one increment (the UMAT argument block).
struct StressPoint {
    const Real* strainIncrement;  ///< [6] d eps, tensor components, extension positive
    Real* stress;                 ///< [6] sigma', tension positive; in: start of step, out: end
    Real* state;                  ///< [stateCount()] state variables, in/out
    Real dt;                      ///< s, the increment's duration
};

class ConstitutiveModel {
public:
    virtual ~ConstitutiveModel() = default;
    /// The case-file name of the model ("linear_elastic", "mohr_coulomb").
    virtual std::string name() const = 0;
    /// Number of state variables per point (0 for a model without any).
    virtual int stateCount() const { return 0; }
    /// Name of state variable k (as written to fields.h5).
    virtual std::string stateName(int k) const { return "state" + std::to_string(k); }
    /// Updates stress and state for the strain increment; returns what the return did.
    virtual StressReturn update(const StressPoint& point) const = 0;
    /// Pa, the elastic oedometric modulus (wave speeds and the time step).
    virtual Real oedometricModulus() const = 0;
};

/// True when the effective stress has vanished (every component within 1e-9 Pa of zero): the
/// first condition of the liquid-state switch (physics.md, tension cut-off).
inline bool isStressFree(const Real* stress) {
    for (int k = 0; k < 6; ++k)
        if (stress[k] > 1e-9 || stress[k] < -1e-9) return false;
    return true;
}

}  // namespace qs
