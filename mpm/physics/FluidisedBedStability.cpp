// The linear stability of a uniformly fluidised bed (FluidisedBedStability.hpp, physics.md
// section 7).
#include "physics/FluidisedBedStability.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "physics/SuspensionViscosity.hpp"

namespace qs::closed {

namespace {
using Complex = std::complex<double>;
const Complex I(0, 1);
}  // namespace

FluidisedBed::Base FluidisedBed::base() const {
    const SuspensionFlux& s = suspension;
    const double n0 = porosity, phi0 = 1 - n0;
    const double drho = s.grainDensity - s.liquidDensity, g = s.gravity;
    // F(n, |w|) = n G(n, n |w|): the drag per unit volume of the mixture (physics/DragLaw.hpp)
    auto drag = [&](double n, double w) {
        const double kappa = s.law.kappa(n), q = n * w;
        return n * (s.viscosity * q / kappa + s.law.ergunFactor(n) * s.liquidDensity * q * std::abs(q) / std::sqrt(kappa));
    };
    Base b{};
    b.filterVelocity = s.equilibriumFlux(n0);
    b.waterVelocity = b.filterVelocity / n0;
    const double V0 = b.waterVelocity;
    const double dw = 1e-6 * V0, dn = 1e-6;
    const double fw = (drag(n0, V0 + dw) - drag(n0, V0 - dw)) / (2 * dw);
    b.dragPorositySlope = (drag(n0 + dn, V0) - drag(n0 - dn, V0)) / (2 * dn);
    b.secantDrag = drag(n0, V0) / V0;
    b.dragCoefficient = fw / (n0 * phi0);
    b.kinematicSpeed = n0 * phi0 * (fw * V0 / n0 - b.dragPorositySlope - (n0 - phi0) * drho * g) / fw;
    b.suspensionViscosity = viscous ? SuspensionViscosity{s.viscosity, maxPacking}.excess(n0) : 0.0;
    const double c = b.kinematicSpeed;
    b.inertialDiffusivity = (s.grainDensity * n0 * c * c + s.liquidDensity * phi0 * (V0 - c) * (V0 - c)) / b.dragCoefficient;
    return b;
}

// rho_s n0 s sigma + rho_L phi0 (s + i k V0)(sigma + i k V0) + B (sigma + i k c)
//   + (4/3)(n0/phi0) mu_s k^2 sigma + K k^2 = 0,  sigma = s + D k^2: a s^2 + b s + e = 0
std::complex<double> FluidisedBed::verticalGrowth(double k) const {
    const Base b = base();
    const double n0 = porosity, phi0 = 1 - n0, rhoS = suspension.grainDensity, rhoL = suspension.liquidDensity;
    const double Dk2 = diffusivity * k * k, V0 = b.waterVelocity;
    const double viscous = 4.0 / 3.0 * n0 / phi0 * b.suspensionViscosity * k * k;
    const Complex ikV = I * k * V0;
    const Complex a2 = rhoS * n0 + rhoL * phi0;
    const Complex a1 = rhoS * n0 * Dk2 + rhoL * phi0 * (Dk2 + 2.0 * ikV) + b.dragCoefficient + viscous;
    const Complex a0 = rhoL * phi0 * ikV * (Dk2 + ikV) + b.dragCoefficient * (Dk2 + I * k * b.kinematicSpeed) +
                       viscous * Dk2 + particleModulus * k * k;
    const Complex root = std::sqrt(a1 * a1 - 4.0 * a2 * a0);
    const Complex s1 = (-a1 + root) / (2.0 * a2), s2 = (-a1 - root) / (2.0 * a2);
    return s1.real() >= s2.real() ? s1 : s2;  // the kinematic mode; the other relaxes the slip
}

// State X = (phi', u_x, u_z, v_x, v_z): s X = A X + b p', the mixture's volume balance C X = 0
// fixes p' = -(C A X) / (C b), so s X = (A - b C A / (C b)) X, on C's kernel.
std::complex<double> FluidisedBed::growth(double kx, double kz) const {
    const Base b = base();
    const double n0 = porosity, phi0 = 1 - n0, rhoS = suspension.grainDensity, rhoL = suspension.liquidDensity;
    const double drho = rhoS - rhoL, g = suspension.gravity, V0 = b.waterVelocity;
    const double k2 = kx * kx + kz * kz, mu = b.suspensionViscosity;
    const double fw = b.dragCoefficient * n0 * phi0, beta = b.secantDrag, fn = b.dragPorositySlope;
    enum { P = 0, UX, UZ, VX, VZ };
    Eigen::Matrix<Complex, 5, 5> A = Eigen::Matrix<Complex, 5, 5>::Zero();
    Eigen::Matrix<Complex, 5, 1> bp, C;
    // grains' volume balance, with the front diffusion
    A(P, P) = -diffusivity * k2;
    A(P, UX) = -I * phi0 * kx;
    A(P, UZ) = -I * phi0 * kz;
    // drag f' = beta (v_x - u_x) x + (f_w (v_z - u_z) - f_n phi') z; viscous -mu (k^2 u + k (k . u) / 3)
    const double ms = rhoS * phi0, ml = rhoL * n0;
    A(UX, UX) = (-beta - mu * (k2 + kx * kx / 3)) / ms;
    A(UX, UZ) = -mu * kx * kz / 3 / ms;
    A(UX, VX) = beta / ms;
    A(UZ, UZ) = (-fw - mu * (k2 + kz * kz / 3)) / ms;
    A(UZ, UX) = -mu * kx * kz / 3 / ms;
    A(UZ, VZ) = fw / ms;
    A(UZ, P) = (-n0 * drho * g - fn) / ms;
    A(VX, VX) = -I * kz * V0 - beta / ml;
    A(VX, UX) = beta / ml;
    A(VZ, VZ) = -I * kz * V0 - fw / ml;
    A(VZ, UZ) = fw / ml;
    A(VZ, P) = (-phi0 * drho * g + fn) / ml;
    // a particle phase's exchange force: -K grad(phi) on the grains, +K grad(phi) on the water
    const double K = particleModulus;
    A(UX, P) += -I * kx * K / ms;
    A(UZ, P) += -I * kz * K / ms;
    A(VX, P) += I * kx * K / ml;
    A(VZ, P) += I * kz * K / ml;
    bp << 0.0, -I * kx / rhoS, -I * kz / rhoS, -I * kx / rhoL, -I * kz / rhoL;
    C << -I * kz * V0, I * phi0 * kx, I * phi0 * kz, I * n0 * kx, I * n0 * kz;
    const Complex Cb = C.transpose() * bp;
    const Eigen::Matrix<Complex, 1, 5> CA = C.transpose() * A;
    const Eigen::Matrix<Complex, 5, 5> reduced = A - bp * CA / Cb;
    // on the constrained states x = Q y (C x = 0, Q a basis of C's kernel): 4 modes, without the
    // spurious s = 0 along C, which at a neutral lateral mode would coincide with it
    const Eigen::Matrix<Complex, 5, Eigen::Dynamic> Q = Eigen::FullPivLU<Eigen::Matrix<Complex, 1, 5>>(C.transpose()).kernel();
    const Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> onKernel =
        (Q.adjoint() * Q).inverse() * Q.adjoint() * reduced * Q;
    Eigen::ComplexEigenSolver<Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic>> solver(onKernel);
    const auto& values = solver.eigenvalues();
    // The kinematic mode: one that moves porosity (the shear modes, phi' = 0, decay only at
    // -mu_s k^2 / rho and would otherwise win against -D k^2), the one nearest its drag-dominated
    // limit -i k_z c - (D + K / B) k^2.
    const Complex limit(-(diffusivity + particleModulus / b.dragCoefficient) * k2, -kz * b.kinematicSpeed);
    Complex best(HUGE_VAL, 0);
    for (int m = 0; m < values.size(); ++m) {
        const Eigen::Matrix<Complex, 5, 1> x = Q * solver.eigenvectors().col(m);
        if (std::abs(x(P)) < 1e-6 * x.norm()) continue;
        if (std::abs(values[m] - limit) < std::abs(best - limit)) best = values[m];
    }
    return best;
}

}  // namespace qs::closed
