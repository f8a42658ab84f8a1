#pragma once
// The particle-phase pressure of fluidised sand: a small isotropic compressive stress of the
// suspension's grains, p_s = K_s phi (phi = 1 - n), carried by fluidised solid points beside the
// suspension viscosity. It is not effective stress (there is no skeleton, no enduring contact);
// it is the particle pressure of two-fluid models of fluidisation, without which their equations
// are not well posed (Anderson & Jackson 1968; Jackson, The Dynamics of Fluidized Particles, 2000).
//
// Why it is here. Where drag dominates (always, for sand in water: the grains relax to the drag
// equilibrium in about a millisecond), the concentration of a fluidised bed obeys Kynch's
// kinematic-wave equation d(phi)/dt + d(phi v_S)/dz = 0 with v_S set by the local drag balance.
// Its fronts (the expansion front, the top of a settling suspension, the top of a sediment) are
// weak shocks: characteristics meet them at a few 1e-4 m/s, so a front's numerical error is
// absorbed only over tens of seconds. The material points, moving with grid-interpolated
// velocities, leave porosity ripples of +-0.03 behind every front that neither decay nor shrink
// with the cell (physics.md problem 7, measured at 6 and 3 mm). A particle pressure adds a
// diffusion D = K_s phi / beta to Kynch's equation (beta = d(drag)/dq per unit volume); with
//   K_s = alpha h beta c / phi   at n = n_max,   c = phi dq/dn the kinematic wave speed,
// D = alpha h c: a grid-scale diffusion (cell Peclet number 1/alpha) that keeps fronts monotone
// and one to two cells wide, vanishes as h -> 0, and leaves a uniform bed (no gradient of phi)
// untouched. alpha = 0.25 (the smallest value that removed the ripples in a 1D study of the
// kinematics, docs/fluidisation.md). For the paper's sand on 6 mm cells K_s is about 130 Pa:
// p_s is about 70 Pa in a bed whose buoyant weight is 1.6 kPa at its base.
#include "core/Types.hpp"

namespace qs {

struct ParticlePressure {
    Real modulus = 0;  ///< Pa, K_s

    /// Pa, p_s at porosity n (compression positive).
    Real pressure(Real porosity) const { return modulus * (1 - porosity); }
};

/// The alpha of K_s = alpha h beta c / phi (see above).
constexpr Real kParticlePressureAlpha = 0.25;

}  // namespace qs
