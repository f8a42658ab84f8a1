#pragma once
// The grid's fields of the double-point step, grouped by what they describe (physics.md
// section 2). Plain structures of arrays: one std::vector per quantity, sized once before the
// time loop (resize) and overwritten in place each step, so that the hot loops stay flat and the
// step allocates nothing. Vectors marked [D] hold D components per entry: [entry * D + axis].
//
// Which phase writes and reads each set (DoublePointSolver.hpp numbers the phases):
//   NodeFields      2 pointsToGrid writes masses, momenta, porosities, drag and forces; 3 adds the
//                   pressure, gravity and boundary forces; 4 the velocities; 4c the diffusion nodes
//   TransferSums    2 pointsToGrid only: what the solid points scatter before the node loop reads it
//   CellIndex       1 sortPoints: each cell's range of solid and liquid points
//   CellFilling     1 classifyCells: how full of water each cell is (the free surface)
//   CellWater       3 computeForces: each cell's pore water; 6 updatePressure reads it
//   CellSandState   2b measureSandPorosity, 4b switchLiquidState: each cell's sand
// Two fields carry state from one step to the next and are checkpointed: NodeFields::relSpeed
// (the Forchheimer drag's |w|) and CellWater::pressureGradient (where a cell's points sit on its
// pressure plane). Each set lists them in forEachStateField(f), f(vector, FieldSpec), the grid's
// part of the field registry (points/PointSet.hpp): the checkpoint saves and loads what it lists.
#include <vector>

#include "core/Types.hpp"
#include "points/PointSet.hpp"

namespace qs {

/// What each node of the grid carries: the two phases' lumped masses, momenta, forces and
/// velocities, the mixture's porosity there and the drag between the phases.
template <int D>
struct NodeFields {
    std::vector<Real> massS, massL;    ///< kg, lumped masses of the solid and the liquid
    std::vector<Real> momS, momL;      ///< [D] kg m/s, momenta mapped from the points
    std::vector<Real> forceS, forceL;  ///< [D] N, stress, pressure, gravity and boundary forces
    std::vector<Real> velS, velL;      ///< [D] m/s, velocities at the end of the step
    std::vector<Real> velLIncrement;   ///< [D] m/s, v_L - v_L(before the step): the FLIP update
    std::vector<Real> porosity;        ///< -, the mixture's n_i over the active cells
    std::vector<Real> sandPorosity;    ///< -, n_i over the cells that hold sand only
    std::vector<Real> drag;            ///< kg/s, the implicit drag coefficient Q_i
    std::vector<Real> relSpeed;        ///< m/s, |v_L - v_S| of the last step (state: checkpointed)
    /// kg, sum of m_p (h |grad N_ip|)^2 over the solid points reaching the node: the yardstick of
    /// a node starved of sand (GridToPoints.cpp)
    std::vector<Real> slopeMass;
    std::vector<Real> fedWeight;       ///< [D] -, how far the node is fed with sand, 1 for a held component
    std::vector<char> diffusionNode;   ///< where the front diffusion acts (FrontDiffusion.cpp)
    bool anyDiffusion = false;         ///< whether any node is one

    /// The fields carried from one step to the next (checkpointed as nodes/NAME).
    template <class F>
    void forEachStateField(F&& f) { f(relSpeed, FieldSpec{"rel_speed", 1}); }
    template <class F>
    void forEachStateField(F&& f) const { f(relSpeed, FieldSpec{"rel_speed", 1}); }

    void resize(Index nodes) {
        for (auto* a : {&massS, &massL, &porosity, &sandPorosity, &drag, &relSpeed, &slopeMass})
            a->assign(nodes, 0.0);
        for (auto* a : {&momS, &momL, &forceS, &forceL, &velS, &velL, &velLIncrement, &fedWeight})
            a->assign(nodes * D, 0.0);
        diffusionNode.assign(nodes, 0);
    }
};

/// What the solid points scatter to the nodes for the node loop of pointsToGrid to turn into
/// porosity and drag: sums of N times a point's grain volume and its drag shares.
struct TransferSums {
    std::vector<Real> grainVolume;  ///< m3, sum N m_p / rho_s
    std::vector<Real> darcy;        ///< m, sum N V / kappa (physics/DragLaw.hpp)
    std::vector<Real> forchheimer;  ///< m2, sum N V F / sqrt(kappa)

    void resize(Index nodes) {
        for (auto* a : {&grainVolume, &darcy, &forchheimer}) a->assign(nodes, 0.0);
    }
};

/// Each cell's points, after sortPoints: the solid points of cell c are solidStart[c] to
/// solidStart[c + 1] - 1 (likewise the liquid ones).
struct CellIndex {
    std::vector<Index> solidStart, liquidStart;
    std::vector<Index> counts;  ///< scratch of the counting sort

    bool hasSolid(Index c) const { return solidStart[c + 1] > solidStart[c]; }
    bool hasLiquid(Index c) const { return liquidStart[c + 1] > liquidStart[c]; }
    void resize(Index cells) {
        solidStart.assign(cells + 1, 0);
        liquidStart.assign(cells + 1, 0);
        counts.assign(cells + 1, 0);
    }
};

/// How full of water each cell is: the free surface as the grid sees it (classifyCells in
/// PointsToGrid.cpp).
struct CellFilling {
    std::vector<char> active;        ///< the cell holds water or sand: it counts in the nodal volumes
    std::vector<char> submerged;     ///< the cell above is full enough that this one is under water
    /// the water's surface (no sand in or above the cell, the cell above under a quarter wet) or a
    /// sand-free cell of the overflow's row: its water is under the air
    std::vector<char> openToAir;
    std::vector<Real> fill;          ///< -, the wet share of the cell, min(1, V_water / V_cell)
    std::vector<Real> liquidVolume;  ///< m3, the liquid points' volume in the cell (scratch)

    void resize(Index cells) {
        for (auto* a : {&active, &submerged, &openToAir}) a->assign(cells, 0);
        for (auto* a : {&fill, &liquidVolume}) a->assign(cells, 0.0);
    }
};

/// Each cell's pore water: one pressure per cell with a gradient about its centre (computeForces
/// in PorePressure.cpp).
template <int D>
struct CellWater {
    std::vector<Real> pressure;          ///< Pa, p_c at the cell's centre at the start of the step
    std::vector<Real> weight;            ///< m3, V_c = sum of the points' V*: the water's volume share
    std::vector<Real> cavity;            ///< -, the cell's cavity strain, 0 without one (physics/Cavitation.hpp)
    std::vector<Real> porosity;          ///< -, n_c, the mean of the cell's nodal porosities
    std::vector<Real> pressureGradient;  ///< [D] Pa/m, grad p_c (state: checkpointed)

    /// The fields carried from one step to the next (checkpointed as cells/NAME); a checkpoint
    /// written before 2026-12-04 has no pressure gradient, which then starts at zero.
    template <class F>
    void forEachStateField(F&& f) { f(pressureGradient, FieldSpec{"pressure_gradient", D, false, true, "2026-12-04"}); }
    template <class F>
    void forEachStateField(F&& f) const {
        f(pressureGradient, FieldSpec{"pressure_gradient", D, false, true, "2026-12-04"});
    }

    void resize(Index cells) {
        for (auto* a : {&pressure, &weight, &cavity, &porosity}) a->assign(cells, 0.0);
        pressureGradient.assign(cells * D, 0.0);
    }
};

/// Each cell's sand: its own porosity and its state (measureSandPorosity, switchLiquidState).
struct CellSandState {
    std::vector<Real> porosity;     ///< -, the sand's own porosity (its top cells corrected)
    std::vector<char> surface;      ///< one of the top two sand cells of its column, whose porosity is corrected
    std::vector<char> fluidised;    ///< the liquid state: the sand carries no effective stress
    std::vector<char> stressFree;   ///< the sand carries no stress: fluidised, or all its points stress free
    std::vector<Real> diffusivity;  ///< m2/s, the front diffusion's D in the cell
    /// 1 / s^2 of the front diffusion's threshold s in the cell (0: none, D in full)
    std::vector<Real> inverseThreshold2;
    /// Pa, the particle phase's pressure Pi in the cell, NaN where it does not act (ParticlePhase.cpp)
    std::vector<Real> particlePressure;
    /// Pa, close packing's contact pressure in the cell, 0 at or above n_min (PackingPressure.cpp)
    std::vector<Real> packingPressure;

    void resize(Index cells) {
        for (auto* a : {&porosity, &diffusivity, &inverseThreshold2, &particlePressure, &packingPressure})
            a->assign(cells, 0.0);
        for (auto* a : {&surface, &fluidised, &stressFree}) a->assign(cells, 0);
    }
};

}  // namespace qs
