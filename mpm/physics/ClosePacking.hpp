#pragma once
// Close packing: grains that touch at their densest packing n_min cannot close up further
// (issue 42, item 3; docs/piping.md, "Close packing held").
//
// Why. A material point is a parcel of grains, not a volume that tiles space: the grid reads a
// cell's sand porosity from the mass its points bring (PointsToGrid.cpp), and nothing in the step
// stops points from crowding into a cell until that mass exceeds what the cell can hold packed.
// Each point's own porosity is kept at n_min (GridToPoints.cpp), but a fluidised or resettling
// point takes the grid's, and a skeleton at n_min does not stiffen. After a pipe the cells of
// cases/piping2D scattered from 0.001 to 0.65 (docs/piping.md). Particle-in-cell codes for dense
// suspensions (MP-PIC: Snider, J. Comput. Phys. 170, 2001) hold the packing with a particle
// normal stress on the grains that rises steeply as the grid's solid fraction nears close
// packing; quicksand takes the same idea in its simplest form, a contact pressure that is zero
// at and above n_min and rises linearly below it:
//   Pi(n) = M (n_min - n) / (1 - n_min)   for n < n_min,   0 otherwise,
// the volumetric strain past close packing times a packing modulus M.
//
// M. The grains' own stiffness (quartz, some 37 GPa) is far beyond what an explicit step carries.
// As discrete-element codes size their contact springs, M is the stiffest the case's time step
// carries: a packing wave, c^2 = M / ((1 - n_min) rho_s) on the grains, at half the speed the step
// is sized by (solver/RunSize.hpp: the water's fast wave under the explicit scheme, the skeleton's
// under the semi-implicit one), so the step resolves it at half the case's Courant number. A cell
// is then held past n_min by (1 - n_min) Pi / M: on cases/piping2D's explicit step (M = 1.6e7 Pa)
// 4e-5 under a kPa; under the semi-implicit step (M about 3e5 Pa) 0.2 %. M is the step's, not the
// sand's: a case with real water under the explicit step (K_L = 2.2e9 Pa) gets some 1e9 Pa, and a
// soft skeleton under the semi-implicit step one of its own load's order, which holds nothing
// (docs/piping.md, "Close packing held").
//
// As a stress among the grains, it acts on the grains alone (the water is not pushed), and on
// every sand cell whatever its points' state, so that a crowded cell pushes its grains into a
// pocket of water beside it.
#include "core/Types.hpp"

namespace qs {

struct ClosePacking {
    Real minPorosity = 0;  ///< -, n_min: the densest packing
    Real modulus = 0;      ///< Pa, M (0: not held)

    /// M for a packing wave at `waveSpeed` (m/s) on grains of density rho_s at close packing.
    static Real modulusFor(Real waveSpeed, Real grainDensity, Real minPorosity) {
        return (1 - minPorosity) * grainDensity * waveSpeed * waveSpeed;
    }
    /// M of a case whose step is sized by `stepWaveSpeed` (m/s): its packing wave at half that speed
    static Real modulusForStep(Real stepWaveSpeed, Real grainDensity, Real minPorosity) {
        return modulusFor(stepWaveSpeed / 2, grainDensity, minPorosity);
    }
    /// Pa, the contact pressure at porosity n
    Real pressure(Real n) const { return n < minPorosity ? modulus * (minPorosity - n) / (1 - minPorosity) : 0; }
};

}  // namespace qs
