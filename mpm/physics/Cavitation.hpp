#pragma once
// Cavitation: the pore water's pressure under tension (docs/piping.md, "Cavitation").
//
// The water is pressed by its artificial stiffness, dp = -K_L d eps_w, eps_w the pore water's own
// volumetric strain (the mixture's strain over the porosity, as the pressure equation sees it).
// It takes no tension below the cavitation limit p_min: what it expands beyond that opens a cavity
// (vapour, released air), a strain c >= 0 of the water that the water remembers. A compression
// closes the cavity first, at p_min, and only then presses the water again. So the water's state is
// a function of its strain e = c - p / K_L alone,
//   p = max(p_min, -K_L e),  c = max(0, e + p_min / K_L),
// and a closed cycle of strain returns the pressure and the cavity to where they started.
//
// The cavity is a strain of the water, not of the mixture: its volume c V_L moves with the water
// and does not change when the water passes from sand (n = 0.4) into free water (n = 1). Stored as
// a mixture strain (K_L / n as its stiffness, as until 2026-12-05) it shrank by 60 % there.
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

/// Pa, the lowest pressure a cell's water takes: the cavitation limit p_min, and no suction where
/// the water is open to the air (its surface rises instead).
inline Real waterLimit(bool openToAir, Real cavitationPressure) {
    return openToAir ? std::max(cavitationPressure, Real(0)) : cavitationPressure;
}

/// The water's strain relative to p = 0, e = c - p / K_L: what its volume has gained.
inline Real waterStrain(CavitatingWater w, Real bulkModulus) { return w.cavity - w.pressure / bulkModulus; }

/// The water's state at strain `e` (waterStrain): pressed above the limit, a cavity beyond it.
inline CavitatingWater waterAtStrain(Real e, Real bulkModulus, Real limit) {
    return {std::max(limit, -bulkModulus * e), std::max(Real(0), e + limit / bulkModulus)};
}

/// The water's state after a pressure increment `dp` = -K_L d eps_w: a compression closes its
/// cavity before it presses the water.
inline CavitatingWater pressWater(CavitatingWater w, Real dp, Real bulkModulus, Real limit) {
    if (w.cavity > 0 && dp > 0) {  // a compression closes the cavity first, at the limit
        const Real closing = std::min(w.cavity * bulkModulus, dp);
        w.cavity -= closing / bulkModulus;
        dp -= closing;
    }
    w.pressure += dp;
    if (w.pressure < limit) {  // beyond the limit the water opens a cavity instead of pulling
        w.cavity += (limit - w.pressure) / bulkModulus;
        w.pressure = limit;
    }
    return w;
}

}  // namespace qs
