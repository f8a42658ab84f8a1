#pragma once
// The linear stability of a uniformly fluidised bed (physics.md section 7): the growth rate and
// phase velocity of a small porosity perturbation exp(i k . x + s t) of quicksand's own continuum
// equations for sand without effective stress (drag, the suspension's viscosity, the kinematic
// front diffusion D, a particle phase's exchange force, the pressure forces -phi grad p and
// -n grad p, incompressible water). A
// closed form for the verification tests and `quicksand check`; the step never calls it.
//   - vertical modes (k along z): the quadratic of physics.md section 7, solved exactly;
//   - any direction: the 5 x 5 eigenproblem of the linearised equations for (phi', u', v') with
//     the pressure eliminated by the mixture's volume balance, on its kernel; the kinematic mode is the
//     constrained eigenvalue that moves porosity nearest its drag-dominated limit
//     -i k_z c - (D + K / B) k^2 (the others are the drag's relaxation of the slip, at about -B / rho, and
//     shear modes without porosity, which decay at -mu_s k^2 / rho only).
#include <complex>

#include "physics/DriftFlux.hpp"

namespace qs::closed {

struct FluidisedBed {
    SuspensionFlux suspension;   ///< the drag law, densities, gravity, the water's viscosity
    double porosity = 0.45;      ///< n0 of the uniform bed (its filter velocity is q(n0))
    double maxPacking = 0.68;    ///< phi_m = 1 - n_min, of the suspension's viscosity
    double diffusivity = 0;      ///< m2/s, D of the front diffusion (0: the continuum without it)
    bool viscous = true;         ///< with the suspension's viscosity mu (mu_r - 1)
    /// Pa, K of a particle phase's exchange force -K grad(phi) on the grains, +K grad(phi) on the
    /// water (physics/ParticlePhase.hpp; 0: none)
    double particleModulus = 0;

    /// The base state and the coefficients of the vertical quadratic.
    struct Base {
        double filterVelocity;   ///< m/s, U = q(n0)
        double waterVelocity;    ///< m/s, V0 = U / n0
        double kinematicSpeed;   ///< m/s, c = phi0 dq/dn (Kynch)
        double dragCoefficient;  ///< kg/m3/s, B = f_w / (n0 phi0)
        double secantDrag;       ///< kg/m3/s, beta = f / |w|
        double dragPorositySlope;///< N/m3, f_n = dF/dn at fixed |w|
        double suspensionViscosity;  ///< Pa s, mu_s = mu (mu_r - 1) (0 when not viscous)
        double inertialDiffusivity;  ///< m2/s, D_i = (rho_s n0 c^2 + rho_L phi0 (V0 - c)^2) / B
    };
    Base base() const;

    /// 1/s, s of the kinematic mode for wavevector (k_x, k_z) (rad/m); growth Re s, phase
    /// velocity along k -Im s / |k|.
    std::complex<double> growth(double kx, double kz) const;
    /// The same for a vertical mode from the quadratic (the eigenproblem's check).
    std::complex<double> verticalGrowth(double k) const;
};

}  // namespace qs::closed
