#pragma once
// MohrCoulomb: linear elasticity with the Mohr-Coulomb yield surface, non-associated flow
// (dilatancy angle psi), cohesion c and a tension cut-off; perfectly plastic.
//
// Principal stresses sigma_1 >= sigma_2 >= sigma_3 (tension positive):
//   yield      f = (1 + sin phi) sigma_1 - (1 - sin phi) sigma_3 - 2 c cos phi      <= 0
//   potential  g = (1 + sin psi) sigma_1 - (1 - sin psi) sigma_3
//   apex       sigma_1 = sigma_2 = sigma_3 = c cot phi
//   tension    sigma_1 <= sigma_t (tensile strength, 0 <= sigma_t <= c cot phi)
//
// The return map works in principal stress space on the elastic trial stress (Clausen, Damkilde
// & Andersen, Computers & Structures 84, 2006, and Int. J. Numer. Meth. Engng 2007: "efficient
// return algorithms for ... multiple yield planes"): with the principal elastic matrix
// D = lambda 1 1^T + 2 G I, the trial stress sigma_B is returned
//   - to the plane:  sigma = sigma_B - dlambda D b, dlambda = f(sigma_B) / (a^T D b), valid while
//                    the result keeps the order sigma_1 >= sigma_2 >= sigma_3;
//   - to an edge, where two planes meet (sigma_1 = sigma_2, triaxial compression, or
//                    sigma_2 = sigma_3, triaxial extension), when the plane return breaks the
//                    order: both planes active, a 2 x 2 system for the two multipliers;
//   - to the apex, when the edge return passes beyond the apex along its line.
// Each region's return is exact (the surfaces are planes, so no iteration), and f = 0 after it.
// The axes of the trial stress are kept (an isotropic return does not rotate them).
//
// The tension cut-off (only active with cohesion: with c = 0 the apex is at zero stress and the
// Mohr-Coulomb cone admits no tension) is a Rankine return of the principal stresses above
// sigma_t, applied after the Mohr-Coulomb return, alternated until both hold (the corner between
// the two surfaces is reached by this alternation, not by a corner return of its own).
//
// State variables: 0 equivalent plastic strain sqrt(2/3 de:de) of the plastic deviator, summed;
// 1 plastic volumetric strain, summed: zero for psi = 0 on the plane and the edges; at the apex
// and the tension cut-off it is the grains losing contact (the main return while a bed lifts).
#include "materials/ConstitutiveModel.hpp"
#include "materials/LinearElastic.hpp"

namespace qs {

class MohrCoulomb final : public ConstitutiveModel {
public:
    /// E, cohesion and tensileStrength in Pa; angles in degrees.
    MohrCoulomb(Real youngsModulus, Real poissonRatio, Real frictionAngle, Real dilatancyAngle,
                Real cohesion = 0, Real tensileStrength = 0);

    std::string name() const override { return "mohr_coulomb"; }
    int stateCount() const override { return 2; }
    std::string stateName(int k) const override;
    StressReturn update(const StressPoint& point) const override;
    Real oedometricModulus() const override { return elastic_.oedometric(); }

    /// f of principal stresses sorted largest first (Pa; > 0 outside the surface).
    Real yield(const Real* principal) const;
    Real apexStress() const { return apex_; }
    /// The principal-space return of a trial stress (sorted, largest first) in place, without
    /// the tension cut-off. `plastic` receives the plastic strain increment's principal values.
    StressReturn returnToSurface(Real* sigma, Real* plastic) const;

private:
    StressReturn tensionReturn(Real* sigma, Real* plastic) const;

    LinearElastic elastic_;
    Real sinPhi_, sinPsi_, cosPhi_;
    Real cohesion_, tensile_, apex_;
};

}  // namespace qs
