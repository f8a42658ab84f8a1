// Phase 3 of the double-point step: the nodal forces (gravity, cell pore pressure on both
// phases, gate and surface tractions; physics.md section 2). Phase 4, the velocities, is the time
// scheme's (solver/TimeIntegrator.hpp).
#include <algorithm>
#include <cmath>

#include "solver/DoublePointSolver.hpp"
#include "boundary/Overflow.hpp"
#include "boundary/Surcharge.hpp"
#include "physics/Cavitation.hpp"
#include "solver/Parallel.hpp"

namespace qs {

// ---------------------------------------------------------------------------------------------
// 3 forces
// ---------------------------------------------------------------------------------------------

/// Each liquid cell's pressure gradient: central between its liquid neighbours, one-sided where it
/// has one only (the free surface, the chamber's bottom, a wall).
template <int D>
void DoublePointSolver<D>::computePressureGradient() {
    forAll(grid_.numCells(), [&](Index c) {
        const IVec<D> cc = grid_.cellCoords(c);
        for (int a = 0; a < D; ++a) {
            Real slope = 0;
            if (water_.weight[c] > 0) {
                const Index stride = grid_.cellStride(a);
                const bool lo = cc[a] > 0 && water_.weight[c - stride] > 0;
                const bool hi = cc[a] + 1 < grid_.cells(a) && water_.weight[c + stride] > 0;
                if (lo && hi) slope = (water_.pressure[c + stride] - water_.pressure[c - stride]) / (2 * grid_.h());
                else if (hi) slope = (water_.pressure[c + stride] - water_.pressure[c]) / grid_.h();
                else if (lo) slope = (water_.pressure[c] - water_.pressure[c - stride]) / grid_.h();
            }
            water_.pressureGradient[c * D + a] = slope;
        }
    });
}

template <int D>
void DoublePointSolver<D>::computeForces() {
    const Real g = config_.gravity, rhoL = config_.liquid.density;
    const Index nc = grid_.numCells();

    // Cell pore pressure at the cell's centre x_c, and the cell's porosity (its nodes' mean).
    // A cell holds one state of its water: the pressure p_c with the cell's gradient about it,
    // p = p_c + grad p_c . (x - x_c), or a cavity at the limit (updatePressure sets its points so).
    // Points that crossed in from other cells bring their old cells' field at where they are now;
    // each is taken along this cell's gradient to the centre, and the cell's water is where the
    // mean of their strains, weighted by their water, puts it (physics/Cavitation.hpp),
    //   e_c = sum e(p - grad p_c . (x - x_c), c) m_L / sum m_L,  (p_c, c_c) = the water at e_c,
    // which conserves the water's volume as they mix (weighted by V*, a point in sand counted
    // 1/n times its water). The limit is the cell's: zero suction where it is open to the air.
    // Without cavities p_c is the points' mean taken to the centre: it does not depend on where in
    // the cell the points happen to be. The
    // plain mean did: at an overflow, a point leaving the top cell (the one with the lowest
    // pressure) raised the cell's pressure by a few Pa, a kick that showed as a 3 % dip of case
    // B's filter velocity; in 2D the points' strands sample the cells unevenly. The gradient is the
    // last step's (part of the state, checkpointed), the one updatePressure set the points with:
    // taken from this step's plain means instead, the correction extrapolated at the drained top
    // of Terzaghi's column and blew up.
    const Real KL = config_.liquid.bulkModulus;
    forAllCells(nc, cells_.liquidStart, [&](Index c) {
        Real strain = 0, water = 0, w = 0, centre[D];
        const IVec<D> cc = grid_.cellCoords(c);
        for (int a = 0; a < D; ++a) centre[a] = grid_.cellCentre(cc[a]);
        const Real* grad = &water_.pressureGradient[c * D];
        for (Index p = cells_.liquidStart[c]; p < cells_.liquidStart[c + 1]; ++p) {
            Real atCentre = liquid_.pressure[p];
            if (liquid_.cavity[p] == 0)  // a cavity's water is at the limit throughout its cell
                for (int a = 0; a < D; ++a) atCentre -= grad[a] * (liquid_.x[p * D + a] - centre[a]);
            strain += waterStrain({atCentre, liquid_.cavity[p]}, KL) * liquid_.mass[p];
            water += liquid_.mass[p];
            w += liquid_.weight[p];
        }
        const CavitatingWater state = waterAtStrain(water > 0 ? strain / water : 0.0, KL, cellLimit(c));
        water_.weight[c] = w;
        water_.pressure[c] = w > 0 ? state.pressure : 0.0;
        water_.cavity[c] = w > 0 ? state.cavity : 0.0;
        Real n = 0;
        grid_.forEachNodeOfCell(c, [&](Index i, int) { n += nodes_.porosity[i] / (1 << D); });
        water_.porosity[c] = n;
    });
    computePressureGradient();

    // Pressure forces gathered per node from its cells, the transpose of the discrete storage
    // equation (updatePressure): there a cell's pressure changes with
    //   div_c = sum_i grad N_i(x_c) . ((1 - n_i) v_S,i + n_i v_L,i),
    // so the pressure's power sum_c p_c V_c div_c is exactly what the nodal forces
    //   F_p,L,i = + sum_c p_c V_c n_i grad N_i(x_c),  F_p,S,i = + sum_c p_c V_c (1 - n_i) grad N_i(x_c)
    // do on the nodal velocities: the pressure stores and returns energy without making any.
    // In a uniform porosity they are -n grad p and -(1-n) grad p (physics.md, pressure forces).
    // The centre-rule form n_c grad N_i + N_i grad n_c, used before, is the same in 1D; in 2D and
    // 3D it is not the transpose where the porosity varies sideways, and two gravels side by side
    // then carried fluxes 3 % (fine) and 1 % (coarse) off their own Darcy-Forchheimer values.
    // (grid/Grid.hpp, divergenceWeight: in axisymmetry the divergence has the hoop part Phi_r / r,
    // and so its transpose a radial force; a uniform pressure then pushes no node sideways)
    forAll(grid_.numNodes(), [&](Index i) {
        Real fL[D] = {}, fS[D] = {};
        const Real ni = nodes_.porosity[i];
        grid_.forEachCellOfNode(i, [&](Index cell, int corner) {
            const Real pV = water_.pressure[cell] * water_.weight[cell];
            if (pV == 0) return;
            for (int a = 0; a < D; ++a) {
                const Real gN = grid_.divergenceWeight(cell, corner, a);
                fL[a] += pV * ni * gN;
                fS[a] += pV * (1 - ni) * gN;
            }
        });
        for (int a = 0; a < D; ++a) {
            nodes_.forceL[i * D + a] += fL[a];
            nodes_.forceS[i * D + a] += fS[a];
        }
        nodes_.forceS[i * D + D - 1] -= nodes_.massS[i] * g;
        nodes_.forceL[i * D + D - 1] -= nodes_.massL[i] * g;
    });

    // Gate: the reservoir's pressure acts on the chamber's liquid at the gate plane, less the
    // weight of the empty gap below the lowest liquid point (physics.md, gate).
    if (config_.gate.mode == GateMode::Pressure) {
        for (Index i : masks_.gateNodes) {
            const Real p = gateLaw_.staticPressure - rhoL * g * chamber_.gapAtNode(grid_, i);
            nodes_.forceL[i * D + D - 1] += p * nodeFootprint(grid_, i);
        }
    }

    // Surcharge on the sand top (solid phase), as a traction where the sand's surface is in each
    // column of cells (boundary/Surcharge.hpp). The water's surface needs none: with an overflow
    // it is held at the overflow level, where the top cells count as full (classifyCells), and
    // the natural zero-traction condition holds at a free surface.
    const Real q = surchargeNow();
    if (q != 0)
        addSurcharge(grid_, solid_, cells_.solidStart, config_.points.solidPerCell, q, nodes_.forceS);
}

template void DoublePointSolver<1>::computeForces();
template void DoublePointSolver<1>::computePressureGradient();
template void DoublePointSolver<2>::computeForces();
template void DoublePointSolver<2>::computePressureGradient();
template void DoublePointSolver<3>::computeForces();
template void DoublePointSolver<3>::computePressureGradient();

}  // namespace qs
