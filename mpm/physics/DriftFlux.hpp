#pragma once
// Fluidised beds by drift-flux (Kynch) theory: the closed forms of physics.md section 4,
// problems 7 (bed expansion after a step in flux) and 9 (batch settling), for the case's own
// permeability law (Ergun drag: Darcy with kappa(n) plus the Forchheimer term with F(n)).
//
// A suspension at porosity n is in equilibrium when the drag carries the grains' buoyant
// weight: the gradient of the relative flow is the critical one, i = i_c(n) = (Gs - 1)(1 - n),
// so the filter velocity (relative volume flux) of an equilibrium suspension is
//   q(n): i_c(n) gamma_w = (mu / kappa(n)) q + (F(n) rho_L / sqrt(kappa(n))) q |q|.
// q(n0) is the minimum fluidisation velocity U_mf of a packed bed at n0; q(n) grows with n.
//
// Expansion (packed bed n1 at U1 = U_mf, inflow stepped to U2 > U1): the bed below the front
// expands to n2 with q(n2) = U2; the front is a shock, s = (1-n1)(U2-U1)/(n2-n1), and the packed
// bed above it rises as a plug at U2 - U1 until the front reaches its top; then the height is
// H2 = H1 (1-n1)/(1-n2).
// Batch settling (no inflow, suspension at n0 over a closed base): the top falls at q(n0), the
// sediment at n_p grows from the base at s = (1-n0) q(n0) / (n0 - n_p); they meet at
// H0 / (q(n0) + s); the final height is H0 (1-n0)/(1-n_p).
#include "physics/Permeability.hpp"

namespace qs::closed {

struct SuspensionFlux {
    PermeabilityLaw law;
    double grainDensity = 2650, liquidDensity = 998.2, gravity = 9.81, viscosity = 8.91e-4;

    /// The suspension of a case's material in the case's liquid, under the case's gravity.
    static SuspensionFlux of(const CaseConfig& c, const MaterialConfig& m) {
        return {PermeabilityLaw::from(m), m.grainDensity, c.liquid.density, c.gravity, c.liquid.viscosity};
    }

    /// m/s, q(n): the filter velocity at which the drag carries the buoyant weight.
    double equilibriumFlux(double porosity) const;
    /// The porosity of the equilibrium suspension for filter velocity q (inverse of the above).
    double equilibriumPorosity(double flux) const;
};

struct BedExpansion {
    double expandedPorosity;  ///< n2
    double frontSpeed;        ///< m/s, s
    double plugSpeed;         ///< m/s, U2 - U1
    double finalHeight;       ///< m, H2
    double duration;          ///< s, until the front reaches the top of the plug
};
BedExpansion bedExpansion(const SuspensionFlux& flux, double n1, double U1, double U2, double H1);

struct BatchSettling {
    double topSpeed;     ///< m/s, the top interface falls at q(n0)
    double frontSpeed;   ///< m/s, the sediment's top rises
    double meetingTime;  ///< s
    double finalHeight;  ///< m
};
BatchSettling batchSettling(const SuspensionFlux& flux, double n0, double packedPorosity, double H0);

}  // namespace qs::closed
