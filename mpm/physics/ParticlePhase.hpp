#pragma once
// The fluidised sand's particle phase: Foscolo and Gibilaro's elastic force (physics.md
// section 7; docs/fluidisation.md, "The particle phase").
//
// Why. Without it a fluidised cell's grains carry no stress, and what keeps a uniformly fluidised
// bed uniform in quicksand is the kinematic front diffusion D = alpha h c, a numerical term that
// vanishes with the cell: whether a porosity perturbation grows into voidage waves or a channel
// was the grid's to decide (physics.md section 7: the continuum is unstable at every wavelength
// without it). Liquid-fluidised beds of fine sand are in fact stable near minimum fluidisation,
// and Foscolo and Gibilaro's particle-bed model (Chem. Eng. Sci. 39, 1984; 42, 1987) says which
// are and which are not from the grains alone: a bed is particulate (uniform) where the particle
// phase's elastic wave speed u_e = sqrt(3.2 g d phi (rho_s - rho_L) / rho_s) exceeds Kynch's
// kinematic wave speed c, and aggregative (bubbles, voidage waves) where it does not. Their
// elastic force grows from the dependence of the fluid's force on the grains on the voidage
// around them: a grain in a denser neighbourhood is pushed towards the looser one.
//
// How it is cast. As FG cast it, a part of the water's force on the grains, not a stress among
// the grains: -K grad(phi) on the grains and +K grad(phi) on the water, per unit volume. The
// mixture's momentum is untouched, so it cannot lift the packed plug above an expansion front as
// a whole (the grain-stress particle pressure tried before did: +13 % plug speed), and it pushes
// at no boundary. In quicksand's own equations such an exchange force enters the vertical
// quadratic of section 7 as + K k^2, and the bed is stable where
//   rho_s n0 c^2 + rho_L phi0 (V0 - c)^2 < K.
// K is chosen so that this criterion, without the water's inertia (FG's own limit), is FG's,
// c < u_e:  K = n rho_s u_e^2 = 3.2 g d n phi (rho_s - rho_L).
// Its effect on the kinematic waves is a diffusion K / B (B the drag's slip coefficient,
// section 7), which unlike the front diffusion does not depend on the cell.
//
// Where. Much where the front diffusion acts (solver/ParticlePhase.cpp): at nodes whose cells all
// hold sand whose points are fluidised or carry no effective stress, away from the filter, the
// surface's top two cells and the grid's bottom and top rows (the front diffusion takes the
// liquid-state switch's verdict of the step instead). A skeleton that carries stress is held by
// its own stiffness.
//
// How it is discretised. K grad(phi) = grad(Pi), Pi(phi) the particle pressure with dPi/dphi = K:
// each cell's Pi from its sand's porosity, and at the nodes the transpose of the cells'
// divergence, as the pore pressure's force is taken (solver/PressureForce.hpp): a mask fresh from
// the points each step, no push at the edge of the zone it acts in. It is still the wide
// difference on the nodes' porosity (solver/ParticlePhase.cpp says what it cannot see).
#include <cmath>

#include "core/Types.hpp"

namespace qs {

/// Foscolo and Gibilaro's elastic force of a fluidised sand's grains, as the modulus K of the
/// exchange force -K grad(phi) on the grains (+K grad(phi) on the water).
struct FoscoloGibilaro {
    Real grainSize = 0;                 ///< m, d
    Real grainDensity = 0, liquidDensity = 0;  ///< kg/m3
    Real gravity = 0;                   ///< m/s2

    /// Pa, K = 3.2 g d n (1 - n)(rho_s - rho_L) at porosity n
    Real modulus(Real n) const { return 3.2 * gravity * grainSize * n * (1 - n) * (grainDensity - liquidDensity); }
    /// Pa, the particle pressure Pi(phi) whose gradient the force is: dPi/dphi = K,
    /// Pi = 3.2 g d (rho_s - rho_L) (phi^2 / 2 - phi^3 / 3)
    Real pressure(Real phi) const {
        return 3.2 * gravity * grainSize * (grainDensity - liquidDensity) * phi * phi * (0.5 - phi / 3);
    }
    /// m/s, FG's elastic wave speed u_e = sqrt(3.2 g d (1 - n)(rho_s - rho_L) / rho_s)
    Real elasticWaveSpeed(Real n) const {
        return std::sqrt(3.2 * gravity * grainSize * (1 - n) * (grainDensity - liquidDensity) / grainDensity);
    }
};

}  // namespace qs
