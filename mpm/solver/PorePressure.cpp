// The pore pressure, one state of the water per cell (physics.md section 2, pore pressure): the
// cells' water read from the liquid points at the step's start, its gradient, the pressure's
// forces on the nodes (phase 3), and after the step the water pressed by the mixture's volume
// balance and handed back to the points (phase 6). The pair of operators is the divergence D
// (nodes to cells, updatePressure) and its transpose D^T (cells to nodes, pressureForces); the
// semi-implicit scheme builds its pressure equation from the same two (SemiImplicitIntegrator.cpp).
#include <algorithm>
#include <cmath>

#include "physics/Cavitation.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/PressureForce.hpp"
#include "solver/Parallel.hpp"

namespace qs {

// ---------------------------------------------------------------------------------------------
// 3 the water at the step's start, and its forces
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::cellWaterFromPoints() {
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
}

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
void DoublePointSolver<D>::pressureForces() {
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
        Real fL[D], fS[D];
        nodePressureForce(grid_, water_, nodes_.porosity[i], i, fL, fS);
        for (int a = 0; a < D; ++a) {
            nodes_.forceL[i * D + a] += fL[a];
            nodes_.forceS[i * D + a] += fS[a];
        }
    });
}

// ---------------------------------------------------------------------------------------------
// 6 pore pressure, one value per cell
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::updatePressure() {
    // dp_c = -(K_L / n_c) dt sum_i grad N_i(x_c) . Phi_i,  Phi_i = (1-n_i) v_S,i + n_i v_L,i
    // (compressible liquid, incompressible grains; the cell average avoids volumetric locking).
    // K_L is a numerical stiffness: this is artificial compressibility, taken at a fixed place.
    const Real KL = config_.liquid.bulkModulus, dt = dt_;
    const bool zeroSurface = config_.liquid.freeSurfaceZeroPressure;
    forAllCells(grid_.numCells(), cells_.liquidStart, [&](Index c) {
        if (!cells_.hasLiquid(c)) return;
        Real div = 0;
        grid_.forEachNodeOfCell(c, [&](Index i, int corner) {
            const Real ni = nodes_.porosity[i];
            for (int a = 0; a < D; ++a) {
                const Real gN = grid_.divergenceWeight(c, corner, a);  // with the hoop part in axisymmetry
                div += gN * ((1 - ni) * nodes_.velS[i * D + a] + ni * nodes_.velL[i * D + a]);
            }
        });
        // the water's top cells are open to the air (classifyCells): they take no suction, and
        // what they expand is their surface rising, not a cavity, so none is kept. Kept there,
        // the top row's water at p ~ 0 gathered cavities from every ripple and the gate's flux
        // strayed 1.9 % from the filter's in the side-by-side gravels
        const bool openToAir = filling_.openToAir[c];
        // the cell's water (computeForces) pressed by the mixture's strain, which is the water's
        // over n_c: beyond the limit a cavity opens, which a compression closes before it
        // presses the water (physics/Cavitation.hpp)
        const CavitatingWater water =
            pressWater({water_.pressure[c], water_.cavity[c]}, -KL / water_.porosity[c] * dt * div, KL, cellLimit(c));
        // Each point takes the cell's field where it now is, p_c + grad p_c . (x - x_c): the field
        // the liquid moves through, so that a point entering the next cell brings that cell's
        // pressure instead of kicking its mean by a cell's drop. Points carried their own
        // pressures along the gradient until 2026-12-05: nothing then pulled a point back to its
        // cell's field, and once piping2D's bed fluidised, points from cells at the limit mixed
        // with pressed ones and kept their own values, rms 1 to 44 kPa about the cell's field
        // (docs/piping.md, "The point pressures"). Water within a cell equalises in h / c_L (three
        // steps), so one state per cell is the water's physics at this resolution.
        Real centre[D];
        const IVec<D> cc = grid_.cellCoords(c);
        for (int a = 0; a < D; ++a) centre[a] = grid_.cellCentre(cc[a]);
        const Real* grad = &water_.pressureGradient[c * D];
        // The cavity the points keep decides how the next step reads them back (computeForces):
        // with none, along the gradient; so the gradient goes on exactly where none is kept.
        const Real cavity = openToAir ? 0 : water.cavity;
        for (Index p = cells_.liquidStart[c]; p < cells_.liquidStart[c + 1]; ++p) {
            Real pressure = water.pressure;
            if (cavity == 0)
                for (int a = 0; a < D; ++a) pressure += grad[a] * (liquid_.x[p * D + a] - centre[a]);
            const bool surface = liquid_.state[p] == kFreeSurfaceLiquid;
            liquid_.pressure[p] = zeroSurface && surface && openToAir ? 0 : pressure;  // p = 0 only with no cavity
            liquid_.cavity[p] = cavity;
        }
    });
}

#define QS_INSTANTIATE(D)                                          \
    template void DoublePointSolver<D>::cellWaterFromPoints();     \
    template void DoublePointSolver<D>::computePressureGradient();  \
    template void DoublePointSolver<D>::pressureForces();          \
    template void DoublePointSolver<D>::updatePressure();
QS_INSTANTIATE(1)
QS_INSTANTIATE(2)
QS_INSTANTIATE(3)
#undef QS_INSTANTIATE

}  // namespace qs
