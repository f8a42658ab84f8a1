#pragma once
// Cavitation: the pore water's pressure under tension (docs/piping.md, "Cavitation").
//
// The water is pressed by its artificial stiffness, dp = -(K_L / n) d eps (eps the mixture's
// volumetric strain as the pressure equation sees it). It takes no tension below the cavitation
// limit p_min: what it expands beyond that opens a cavity (vapour, released air), a volumetric
// strain c >= 0 that the water point remembers. A compression closes the cavity first, at p_min,
// and only then presses the water again. So the pressure is a function of the strain alone,
//   p = max(p_min, p_0 - (K_L / n) eps), with the cavity c = max(0, (p_min - p_0) n / K_L + eps),
// and a closed cycle of strain returns the pressure and the cavity to where they started.
//
// Clamping the pressure without the cavity (as quicksand did until 2026-12-04) made every
// expansion at the limit free and the compression after it stiff at once: a water point gained
// the expansion as volume of water, each cycle. In piping2D the collapsing sand's pressure waves
// drove such cycles until half the column's water sat at the limit and the column surged.
#include <algorithm>

#include "core/Types.hpp"

namespace qs {

struct CavitatingWater {
    Real pressure;  ///< Pa, gauge, compression positive
    Real cavity;    ///< -, the volumetric strain opened at the limit (>= 0)
};

/// The water's state after a pressure increment `dp` = -stiffness d eps (stiffness = K_L / n).
inline CavitatingWater pressWater(CavitatingWater w, Real dp, Real stiffness, Real limit) {
    if (w.cavity > 0 && dp > 0) {  // a compression closes the cavity first, at the limit
        const Real closing = std::min(w.cavity * stiffness, dp);
        w.cavity -= closing / stiffness;
        dp -= closing;
    }
    w.pressure += dp;
    if (w.pressure < limit) {  // beyond the limit the water opens a cavity instead of pulling
        w.cavity += (limit - w.pressure) / stiffness;
        w.pressure = limit;
    }
    return w;
}

}  // namespace qs
