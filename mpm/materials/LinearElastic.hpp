#pragma once
// Linear-elastic skeleton (Hooke's law on the effective stress, incremental form):
//   d sigma' = lambda tr(d eps) I + 2 G d eps, tension positive, strains extension positive.
#include "core/Types.hpp"

namespace qs {

struct LinearElastic {
    Real lambda = 0;  ///< Pa, first Lame constant
    Real shear = 0;   ///< Pa, G

    static LinearElastic fromYoung(Real E, Real nu) {
        LinearElastic m;
        m.shear = E / (2 * (1 + nu));
        m.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
        return m;
    }
    Real oedometric() const { return lambda + 2 * shear; }

    /// stress += D : dEps, both in Voigt order (engineering shear NOT used: dEps holds tensor
    /// components eps_ij).
    void update(Real* stress, const Real* dEps) const {
        const Real tr = dEps[0] + dEps[1] + dEps[2];
        for (int i = 0; i < 3; ++i) stress[i] += lambda * tr + 2 * shear * dEps[i];
        for (int i = 3; i < 6; ++i) stress[i] += 2 * shear * dEps[i];
    }
};

}  // namespace qs
