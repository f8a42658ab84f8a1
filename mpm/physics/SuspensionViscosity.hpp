#pragma once
// The viscosity of fluidised sand: a suspension of grains in water, Newtonian, its viscosity
// rising with the solid concentration phi = 1 - n as Krieger & Dougherty (Trans. Soc. Rheol. 3,
// 1959) give it:
//
//   mu_mixture = mu (1 - phi / phi_m)^(-[eta] phi_m),   [eta] = 2.5 (Einstein), phi_m = 1 - n_min
//
// phi_m is the densest packing of the sand (its minimum porosity). The pore water of the
// double-point formulation carries no viscous stress of its own (its viscosity acts through the
// drag), so the solid points of fluidised material carry the suspension's excess over water,
// mu_s = mu (mu_r - 1), as the deviatoric stress sigma' = 2 mu_s dev(d eps / dt). It is small
// in 1D (a few hundredths of a Pa s against strain rates of 1e-3 1/s), and it is what resists
// shear of a fluidised bed in 2D and 3D. The concentration is capped at 0.95 phi_m inside the law,
// where mu_r = 163 (31 at n_max = 0.41 for the paper's sand): a fluidised point is never much
// denser than n_max, so the cap only guards against a stray grid value.
#include <algorithm>
#include <cmath>

#include "core/Types.hpp"

namespace qs {

struct SuspensionViscosity {
    Real waterViscosity = 8.91e-4;  ///< Pa s, mu
    Real maxPacking = 0.68;         ///< -, phi_m = 1 - n_min
    Real intrinsic = 2.5;           ///< -, [eta]

    /// Pa s, the viscosity the solid carries at porosity n: mu (mu_r - 1).
    Real excess(Real porosity) const {
        const Real ratio = std::min((1 - porosity) / maxPacking, Real(0.95));
        if (ratio <= 0) return 0;
        return waterViscosity * (std::pow(1 - ratio, -intrinsic * maxPacking) - 1);
    }

    /// sigma' = 2 mu_s dev(dEps / dt), Voigt order, tensor shear components.
    void stress(Real porosity, const Real* dEps, Real dt, Real* sigma) const {
        const Real two = 2 * excess(porosity) / dt;
        const Real mean = (dEps[0] + dEps[1] + dEps[2]) / 3;
        for (int k = 0; k < 3; ++k) sigma[k] = two * (dEps[k] - mean);
        for (int k = 3; k < 6; ++k) sigma[k] = two * dEps[k];
    }
};

}  // namespace qs
