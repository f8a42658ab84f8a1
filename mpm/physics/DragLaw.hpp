#pragma once
// DragLaw: the drag between the pore water and the grains, Darcy's law with the Forchheimer
// (Ergun) term, in its one home (physics.md section 2, drag). Per unit volume of the mixture,
// the pressure gradient that drives a filter velocity q = n (v_L - v_S) through a sand of
// intrinsic permeability kappa (m2) and Ergun factor F (-) is
//   i gamma_w = mu q / kappa + rho_L F q |q| / sqrt(kappa).
// The solver carries it as an implicit nodal coefficient Q_i (kg/s), the drag on the node's
// liquid being Q_i (v_S - v_L): the solid points hand the nodes their shares V / kappa and
// V F / sqrt(kappa) (PointsToGrid.cpp), and the node takes
//   Q_i = n_i^2 mu sum(N V / kappa) + rho_L n_i^3 |w_i| sum(N V F / sqrt(kappa)),
// |w_i| = |v_L - v_S| from the last step. The initial seepage (ColumnBuilder), the check's
// expected flux (CheckReport) and the front diffusion's equilibrium suspension
// (physics/FrontDiffusion.hpp) take the law from here too. The closed forms the tests check
// against (physics/ClosedForms.hpp, darcyForchheimerFlux) are a separate implementation of the
// same law; tests/unit/physics/test_DragLaw.cpp holds the two together.
#include <cmath>

#include "core/Types.hpp"

namespace qs {

struct DragLaw {
    Real viscosity = 0;      ///< Pa s, mu
    Real liquidDensity = 0;  ///< kg/m3, rho_L

    /// Pa/m, the pressure gradient that drives filter velocity q (m/s) through the sand.
    Real gradient(Real kappa, Real F, Real q) const {
        return viscosity * q / kappa + F * liquidDensity * q * std::abs(q) / std::sqrt(kappa);
    }

    /// m/s, the filter velocity a pressure gradient (Pa/m) drives: the positive root of the
    /// quadratic, with the gradient's sign. In the form 2 r / (a + sqrt(a^2 + 4 b r)), which
    /// neither cancels when the Forchheimer term is small nor divides by it when it is zero.
    Real flux(Real kappa, Real F, Real pressureGradient) const {
        const Real a = viscosity / kappa, b = F * liquidDensity / std::sqrt(kappa);
        const Real r = std::abs(pressureGradient);
        return std::copysign(2 * r / (a + std::sqrt(a * a + 4 * b * r)), pressureGradient);
    }

    /// A solid point's shares of its nodes' drag sums, before the shape functions: V / kappa (m)
    /// and V F / sqrt(kappa) (m2), V the point's volume (m3).
    struct Shares { Real darcy, forchheimer; };
    static Shares pointShares(Real kappa, Real F, Real volume) {
        return {volume / kappa, volume * F / std::sqrt(kappa)};
    }

    /// kg/s, the node's implicit drag coefficient Q_i from its porosity, its drag sums and the
    /// last step's relative speed |w_i| (m/s).
    Real nodal(Real n, Real darcySum, Real forchheimerSum, Real relativeSpeed) const {
        return n * n * viscosity * darcySum + liquidDensity * n * n * n * relativeSpeed * forchheimerSum;
    }
};

}  // namespace qs
