#pragma once
// Closed-form results of soil hydraulics used by `quicksand check` (derived quantities shown
// before a run) and by the verification tests (physics.md sections 1, 3 and 4). SI units.
// Every function is a textbook formula; the comment names it.

namespace qs::closed {

/// Terzaghi's critical gradient i_c = (Gs - 1)(1 - n), Gs = rho_s / rho_L.
double criticalGradient(double grainDensity, double liquidDensity, double porosity);

/// Hydraulic conductivity K = kappa rho_L g / mu (m/s) from the intrinsic permeability (m2).
double hydraulicConductivity(double permeability, double liquidDensity, double gravity,
                             double viscosity);

/// Kozeny-Carman kappa = D^2 n^3 / (A (1-n)^2), n capped at 0.95.
double kozenyCarman(double grainSize, double porosity, double A);

/// Kozeny-Carman scaled to kappa0 at n0: kappa0 [n^3/(1-n)^2] / [n0^3/(1-n0)^2], n capped at 0.95.
double kozenyCarmanScaled(double kappa0, double n0, double porosity);

/// Ergun factor F = B / (sqrt(A) n^1.5).
double ergunFactor(double porosity, double A, double B);

/// Steady Darcy-Forchheimer filter velocity q (m/s) for the hydraulic gradient i:
/// i gamma_w = (mu/kappa) q + (F rho_L / sqrt(kappa)) q |q|  (F = 0: Darcy).
double darcyForchheimerFlux(double gradient, double permeability, double ergunF,
                            double liquidDensity, double gravity, double viscosity);

/// Hagen-Poiseuille tube resistance R_t = 128 mu L / (pi rho g d^4) (s/m2, head per flow rate).
double tubeResistance(double diameter, double length, double liquidDensity, double gravity,
                      double viscosity);

/// Oedometric modulus E_oed = E (1-nu) / ((1+nu)(1-2nu)).
double oedometricModulus(double youngsModulus, double poissonRatio);

/// Compression wave speeds of the saturated two-phase medium without drag (Biot fast and slow
/// waves, grains incompressible): eigenvalues of M^-1 K with
/// K = [[E_oed + (1-n)^2 K_L/n, (1-n) K_L], [(1-n) K_L, n K_L]], M = diag((1-n) rho_s, n rho_L).
struct WaveSpeeds { double fast; double slow; };
WaveSpeeds zeroDragWaveSpeeds(double Eoed, double bulkModulusLiquid, double porosity,
                              double grainDensity, double liquidDensity);

/// Undrained wave speed c_u = sqrt((E_oed + K_L/n) / rho_sat).
double undrainedWaveSpeed(double Eoed, double bulkModulusLiquid, double porosity,
                          double grainDensity, double liquidDensity);

/// Terzaghi consolidation with compressible water (Verruijt): c_v = k / (gamma_w (m_v + n/K_L)),
/// k the hydraulic conductivity (m/s), m_v = 1/E_oed.
double consolidationCoefficient(double conductivity, double liquidDensity, double gravity,
                                double Eoed, double porosity, double bulkModulusLiquid);
/// Initial excess pore pressure ratio u0/q = m_v / (m_v + n/K_L).
double undrainedPressureRatio(double Eoed, double porosity, double bulkModulusLiquid);
/// u/u0 = sum 2/M sin(M Z) exp(-M^2 T), M = (2m+1) pi/2; Z = distance from the drained face / H.
double terzaghiPressureRatio(double Z, double T, int terms = 200);
/// Degree of consolidation U(T) = 1 - sum 2/M^2 exp(-M^2 T).
double terzaghiDegree(double T, int terms = 200);

/// Falling head through a column (rigid, incompressible, inertia-free) fed by a reservoir of
/// area Ar through a tube of resistance Rt: Darcy: h = h0 exp(-t/tau), tau = Ar (L/(K As) + Rt).
double fallingHeadTau(double reservoirArea, double columnArea, double length, double conductivity,
                      double tubeResistance);
/// With Forchheimer: h = alpha q + beta q^2, alpha = L/K + As Rt, beta = L F /(g sqrt(kappa));
/// the time at which the filter velocity has fallen from q0 to q:
/// t(q) = (Ar/As) [alpha ln(q0/q) + 2 beta (q0 - q)].
struct FallingHeadForchheimer {
    double alpha;  ///< s (head per filter velocity)
    double beta;   ///< s2/m
    double areaRatio;  ///< Ar / As
    double flux(double head) const;            ///< q(h) from h = alpha q + beta q^2
    double timeToFlux(double q0, double q) const;
    double timeToHead(double h0, double h) const { return timeToFlux(flux(h0), flux(h)); }
};

/// Two layers in series: q = dh / (L1/K1 + L2/K2).
double seriesFlux(double headDifference, double L1, double K1, double L2, double K2);

}  // namespace qs::closed
