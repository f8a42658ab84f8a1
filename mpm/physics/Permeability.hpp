#pragma once
// Intrinsic permeability kappa(n) (m2) in the three modes of physics.md section 1, and the
// Ergun factor F(n) of the Forchheimer term. Porosity is capped at 0.95 inside the formulas.
#include <algorithm>
#include <cmath>

#include "core/Types.hpp"
#include "case/CaseConfig.hpp"

namespace qs {

struct PermeabilityLaw {
    PermeabilityMode mode = PermeabilityMode::Constant;
    Real value = 0;       ///< m2 (Constant: kappa; Scaled: kappa0 at n0)
    Real grainSize = 0;   ///< m (KozenyCarman)
    Real A = 150, B = 1.75;
    Real n0 = 0.38;
    bool ergun = true;

    static PermeabilityLaw from(const MaterialConfig& m) {
        PermeabilityLaw k;
        k.mode = m.permeability.mode;
        k.value = m.permeability.value;
        k.grainSize = m.permeability.grainSize;
        k.A = m.ergunA;
        k.B = m.ergunB;
        k.n0 = m.porosity;
        k.ergun = m.ergun;
        return k;
    }

    static Real carmanShape(Real n) {
        n = std::min(n, Real(0.95));
        return n * n * n / ((1 - n) * (1 - n));
    }

    Real kappa(Real n) const {
        switch (mode) {
            case PermeabilityMode::Constant: return value;
            case PermeabilityMode::KozenyCarman: return grainSize * grainSize * carmanShape(n) / A;
            case PermeabilityMode::KozenyCarmanScaled: return value * carmanShape(n) / carmanShape(n0);
        }
        return value;
    }

    /// F = B / (sqrt(A) n^1.5), zero with the Forchheimer term off.
    Real ergunFactor(Real n) const {
        if (!ergun) return 0;
        n = std::min(n, Real(0.95));
        return B / (std::sqrt(A) * n * std::sqrt(n));  // n^1.5 without pow: this runs per point and step
    }
};

}  // namespace qs
