#include "physics/PipeFriction.hpp"

#include <cmath>

#include "core/Constants.hpp"
#include "core/Error.hpp"

namespace qs::friction {

double laminar(double reynolds) {
    QS_CHECK(reynolds > 0, "laminar friction factor: Re must be > 0, got " << reynolds);
    return 64.0 / reynolds;
}

double blasius(double reynolds) {
    QS_CHECK(reynolds > 0, "Blasius friction factor: Re must be > 0, got " << reynolds);
    return 0.316 * std::pow(reynolds, -0.25);
}

double colebrookSmooth(double reynolds) {
    QS_CHECK(reynolds > 0, "Colebrook friction factor: Re must be > 0, got " << reynolds);
    double x = 1.0 / std::sqrt(blasius(reynolds));  // x = 1/sqrt(f)
    for (int k = 0; k < 100; ++k) {
        const double next = -2.0 * std::log10(2.51 * x / reynolds);
        if (std::abs(next - x) <= 1e-15 * x) return 1.0 / (next * next);
        x = next;
    }
    return 1.0 / (x * x);
}

namespace {
/// (A + B)^(-3/2) of Churchill's law, 0 where A + B overflows (deep in the laminar range).
double turbulentTerm(double reynolds, double relativeRoughness) {
    const double a = std::pow(2.457 * std::log(1.0 / (std::pow(7.0 / reynolds, 0.9) + 0.27 * relativeRoughness)), 16);
    const double b = std::pow(37530.0 / reynolds, 16);
    return std::pow(a + b, -1.5);
}
}  // namespace

double churchill(double reynolds, double relativeRoughness) {
    QS_CHECK(reynolds > 0, "Churchill friction factor: Re must be > 0, got " << reynolds);
    return 8.0 * std::pow(std::pow(8.0 / reynolds, 12) + turbulentTerm(reynolds, relativeRoughness), 1.0 / 12.0);
}

double frictionMultiplier(double reynolds) {
    // f Re / 64 = [1 + (Re/8)^12 (A + B)^(-3/2)]^(1/12): no 1/Re to blow up as the flow stops
    if (!(reynolds > 0)) return 1.0;
    return std::pow(1.0 + std::pow(reynolds / 8.0, 12) * turbulentTerm(reynolds, 0.0), 1.0 / 12.0);
}

double laminarHeadPerFlow(double d, double L, double rho, double g, double mu) {
    const double nu = mu / rho, area = 0.25 * kPi * d * d;
    return 32 * nu * L / (g * d * d * area);
}

}  // namespace qs::friction
