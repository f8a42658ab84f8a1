#pragma once
// When sand turns liquid and back: the liquid-state switch of the double-point formulation,
// decided per cell of the background grid (docs/fluidisation.md gives the rule in physics terms).
//
// The paper's two conditions for incipient fluidisation are that the effective stress has vanished
// and that the skeleton has expanded until it loses its structure (n >= n_max). Per point they
// flip the state of neighbouring points back and forth, because a point's own mass-balance
// porosity drifts away from the real spacing of the points around it once the skeleton carries
// no stress. So the state is a property of a cell, from the solid mass the grid holds in it:
//
//   n_c = 1 - (solid volume in the cell) / V_c, the mean of the cell's nodal porosities (the grid's
//         solid mass, mapped with the shape functions, shared among the cells of each node);
//   a solid cell turns fluidised when   all its solid points are stress-free after their return
//                                       and n_c >= n_max and div v_S >= 0 (not compacting);
//   a fluidised cell turns solid when   n_c < n_max - hysteresis and div v_S < 0 (compacting).
//
// The hysteresis keeps a cell at n_max from flipping every step as its porosity fluctuates by a
// round-off or a point's crossing. Every point takes the state of the cell it is in (a point
// entering a cell of the other state changes with it); fluidised points take their porosity from
// the grid (the nodal porosity interpolated at the point), carry no effective stress, only the
// suspension's viscous stress; points turning solid restart from zero effective stress at the
// grid's porosity.
#include "core/Types.hpp"

namespace qs {

struct LiquidStateRule {
    /// -, porosity band below n_max in which a fluidised cell stays fluidised. 0.005 is about a
    /// tenth of the expansion from n0 = 0.38 to n_max = 0.41 seen in the cells' fluctuations, and
    /// costs at most 0.005 / (1 - n_max) = 0.85 % of a resettled bed's height.
    Real hysteresis = 0.005;

    bool turnsFluidised(bool stressFree, Real n, Real nMax, Real solidDivergence) const {
        return stressFree && n >= nMax && solidDivergence >= 0;
    }
    bool turnsSolid(Real n, Real nMax, Real solidDivergence) const {
        return n < nMax - hysteresis && solidDivergence < 0;
    }
};

}  // namespace qs
