#pragma once
// Front diffusion: a numerical diffusion of the solid concentration in sand that carries no
// effective stress (fluidised, or a skeleton at its tension cut-off / Mohr-Coulomb apex), so that
// the fronts of fluidisation stay monotone (docs/fluidisation.md, "Fronts").
//
// Why. Where drag dominates (always, for sand in water: grains relax to the drag equilibrium in
// about a millisecond) and the skeleton carries no stress, the solid concentration phi = 1 - n
// obeys Kynch's kinematic-wave equation, d(phi)/dt + d(phi v_S)/dz = 0, v_S set by the local drag
// balance. Its fronts (the expansion front, the top of a sediment) are weak shocks: the
// characteristics meet them at a few 1e-4 m/s, so whatever error a front makes on the grid is
// absorbed only over tens of seconds. The material points, moving with the grid's velocities,
// leave porosity ripples of +-0.03 behind every front, which do not shrink with the cell
// (problem 7 at 6 and 3 mm). Two-fluid models of fluidisation are regularised by a particle
// pressure (Anderson & Jackson 1968); as a stress it would push at every boundary of the
// stress-free zone (the filter, the packed plug above an expansion front, which is in neutral
// equilibrium at U_mf and runs away under any push). So the diffusion is applied as what it is in
// the drag-dominated limit, a kinematic one: the points move with
//   v_S + w_S,  w_S = -D grad(phi) / phi   (solid: a Fickian flux -D grad phi)
//   v_L + w_L,  w_L = -(1 - n) w_S / n     (liquid: the mixture's volume flux is unchanged)
// added to their displacement, not to their velocity nor to their strain: momentum, the
// pressure equation and both phases' mass are untouched. (Points the diffusion moves take their
// porosity from the grid, which sees the displacement; the liquid points' volume does not.)
//
//   D = alpha h c,  c = phi dq/dn at n = n_max  (the kinematic wave speed of the suspension)
//
// a cell Peclet number of 1/alpha: fronts one to two cells wide, the diffusion vanishing as
// h -> 0 and zero in a uniform bed. alpha = 0.25, the smallest value that removed the ripples in
// a 1D study of the kinematics (docs/fluidisation.md). For the paper's sand c = 1.13e-2 m/s at
// n_max = 0.41; on 6 mm cells D = 1.70e-5 m2/s (tests/unit/physics/test_DragLaw.cpp; the 5.1e-3
// and 7.6e-6 this comment gave until 2026-12-05 were not what the code computes).
#include <algorithm>

#include "core/Types.hpp"
#include "physics/DragLaw.hpp"
#include "physics/Permeability.hpp"

namespace qs {

constexpr Real kFrontDiffusionAlpha = 0.25;

/// m/s, the filter velocity of the equilibrium suspension at porosity n: the drag carries the
/// grains' buoyant weight, (1 - n)(rho_s - rho_L) g, as the pressure gradient of the relative flow.
inline Real equilibriumSuspensionFlux(const DragLaw& drag, const PermeabilityLaw& law, Real grainDensity,
                                      Real gravity, Real n) {
    return drag.flux(law.kappa(n), law.ergunFactor(n), (1 - n) * (grainDensity - drag.liquidDensity) * gravity);
}

/// m2/s, D = alpha h c at n = n_max (capped at 0.9), c = (1 - n) dq/dn the kinematic wave speed of
/// the equilibrium suspension, on cells of h (m); alpha the material's `front_diffusion` (with a
/// particle phase that holds the fronts itself it may be cut, docs/fluidisation.md).
inline Real frontDiffusivity(const DragLaw& drag, const PermeabilityLaw& law, Real grainDensity, Real gravity,
                             Real maxPorosity, Real h, Real alpha = kFrontDiffusionAlpha) {
    const Real n = std::min(maxPorosity, Real(0.9)), dn = 1e-4;
    auto q = [&](Real at) { return equilibriumSuspensionFlux(drag, law, grainDensity, gravity, at); };
    const Real c = (1 - n) * (q(n + dn) - q(n - dn)) / (2 * dn);
    return alpha * h * std::max(c, Real(0));
}

}  // namespace qs
