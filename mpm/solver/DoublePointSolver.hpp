#pragma once
// DoublePointSolver<D>: the explicit double-point MPM step for a saturated sand column
// (physics.md section 2; Anura3D lineage: Bandara & Soga 2015, Martinelli & Rohe).
//
// Usage:
//   ConstantHead reservoir(...);                       // any ReservoirModel
//   DoublePointSolver<1> solver(config, reservoir);    // builds grid and points from the case
//   while (solver.time() < config.time.end) solver.step();
//   ColumnState s = solver.columnState();              // fluxes, pressures, ledger
//
// One step, as named phases over plain arrays (structure of arrays, OpenMP, no allocation):
//   1 sortPoints          points by cell; active cells; liquid weights V*; free surface
//   2 pointsToGrid        lumped masses, momenta, nodal porosity, drag coefficients
//   2b measureSandPorosity  the sand's own porosity per cell (the surface's top cells corrected)
//   3 computeForces       gravity, effective stress, cell pore pressure, gate and surface tractions
//   4 solveVelocities     the time scheme (TimeIntegrator.hpp): predictors, implicit drag, filter /
//                         walls / gate; the semi-implicit scheme's pressure increment
//   4b switchLiquidState  per cell: solid or fluidised (physics/LiquidStateRule.hpp)
//   4c diffuseFronts      kinematic diffusion where the sand carries no stress (FrontDiffusion)
//   5 gridToPoints        velocities (solid APIC, liquid FLIP), positions, strains, stress, porosity, liquid volume
//   6 updatePressure      cell pore-pressure increment from the mixed volumetric strain
//   7 exchangeAtBoundaries  inflow injection, outflow removal, ledger, reservoir
//   8 checkHealth         a non-finite value, a runaway point, a porosity outside (0, 1) stops the run
// Every phase is deterministic: results do not depend on the number of OpenMP threads.
// The phases live in their own files: PointsToGrid.cpp (1, 2), Forces.cpp (3), the time scheme
// behind TimeIntegrator.hpp (4), LiquidStateSwitch.cpp (4b), FrontDiffusion.cpp (4c),
// GridToPoints.cpp (5), BoundaryExchange.cpp (7), HealthCheck.cpp (8). Each physics term has its
// own home: the free surface FreeSurface.cpp (1), the pore pressure PorePressure.cpp (3, 6), the
// gate Gate.cpp (3, 4, 7), the drag physics/DragLaw.hpp (2), the node solve NodeVelocities.hpp
// (4). Set-up and the step itself here in DoublePointSolver.cpp, the measurements in
// ColumnMeasurements.cpp, checkpoints in SolverCheckpoint.cpp.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "boundary/BoundaryMasks.hpp"
#include "boundary/InflowChamber.hpp"
#include "grid/Grid.hpp"
#include "case/CaseConfig.hpp"
#include "materials/ConstitutiveModel.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/RankShare.hpp"
#include "physics/Cavitation.hpp"
#include "physics/LiquidStateRule.hpp"
#include "physics/FrontDiffusion.hpp"
#include "physics/Pipes.hpp"
#include "physics/ClosePacking.hpp"
#include "physics/ParticlePhase.hpp"
#include "physics/Permeability.hpp"
#include "physics/SuspensionViscosity.hpp"
#include "points/LiquidPoints.hpp"
#include "points/SolidPoints.hpp"
#include "solver/GridFields.hpp"
#include "solver/TimeIntegrator.hpp"
#include "reservoir/ReservoirModel.hpp"

namespace qs {

class CheckpointData;

/// The material constants a solid point needs, resolved once from MaterialConfig.
struct SolidMaterial {
    std::string name;
    Real grainDensity = 0;
    Real maxPorosity = 0;
    Real minPorosity = 0;                            ///< the densest packing: no skeleton is denser
    std::shared_ptr<const ConstitutiveModel> model;  ///< the skeleton's stress-strain law
    SuspensionViscosity suspension;                  ///< viscosity once fluidised
    Real frontDiffusivity = 0;                       ///< m2/s, D (physics/FrontDiffusion.hpp)
    Real frontThreshold = 0;                         ///< -, s: D fades below a change of s over a cell
    bool particlePhase = false;                      ///< with Foscolo and Gibilaro's force once fluidised
    FoscoloGibilaro elasticForce;                    ///< its modulus (physics/ParticlePhase.hpp)
    ClosePacking packing;                            ///< the contact pressure below n_min (modulus 0: none)
    PermeabilityLaw permeability;
};

/// What the column looks like now: the quantities written to series.csv.
struct ColumnState {
    Real time = 0;
    Real gateFlux = 0;            ///< m3/s into the column through the gate plane
    Real gatePressure = 0;        ///< Pa at the gate plane
    Real reservoirHead = 0;       ///< m above the gate plane
    Real sandSurface = 0;         ///< m, top of the highest solid point
    Real bedHeight = 0;           ///< m, sand surface above the filter
    Real fluidisedFront = 0;      ///< m, where the state first changes above the filter: the top
                                  ///<    of a fluidised zone grown from the filter (expansion), or
                                  ///<    of the resettled bed under a suspension (settling); the
                                  ///<    filter level when no sand is fluidised
    Real fluidisedShare = 0;      ///< -, fluidised share of the solid mass
    Real waterSurface = 0;        ///< m, free surface: the water and grains' volume over the cross-section
    Real gradient = 0;            ///< -, hydraulic gradient fitted over the interior sand cells
    std::vector<Real> monitorFlux;  ///< m/s, filter velocity q = n (v_L - v_S) per monitor
    Real cumulativeInflow = 0;    ///< m3 through the gate (grid flux integrated in time)
    Real cumulativeOutflow = 0;   ///< m3 removed above the overflow level
    Real cumulativeSolidOutflow = 0;  ///< kg of grains carried out above the overflow level
    Real injectedVolume = 0;      ///< m3 of liquid points injected at the chamber bottom
    Real ledgerResidual = 0;      ///< m3, inflow - outflow - stored (should stay ~0)
    Real solidMass = 0;           ///< kg
    Real liquidMass = 0;          ///< kg
    std::size_t solidPoints = 0, liquidPoints = 0;
};

/// Cell-row means along the vertical (the profile a user compares with a closed form).
struct CellRow {
    Real z = 0;                   ///< m, row centre
    Real porePressure = 0;        ///< Pa, cell pressure
    Real verticalStress = 0;      ///< Pa, mean sigma'_zz of the row's solid points (tension +)
    Real horizontalStress = 0;    ///< Pa, mean sigma'_xx
    Real porosity = 0;            ///< -, mean of the row's solid points
    Real minPorosity = 0, maxPorosity = 0;  ///< -, the row's solid points' extremes
    Real fluidisedShare = 0;      ///< -, share of the row's solid points that are fluidised
    Real filterVelocity = 0;      ///< m/s, q at the row's lower node
    int solidCount = 0, liquidCount = 0;
};

template <int D>
class DoublePointSolver {
public:
    /// With `ranks` of more than one process (mpirun), the column is decomposed over them
    /// (parallel/RankShare.hpp): each solver holds its block's points and steps with the others.
    DoublePointSolver(const CaseConfig& config, ReservoirModel& reservoir, const Communicator* ranks = nullptr);
    // the time scheme holds references to the solver's fields: it stays where it was built
    DoublePointSolver(const DoublePointSolver&) = delete;
    DoublePointSolver& operator=(const DoublePointSolver&) = delete;

    /// Advances by dt(). Throws qs::Error if the state becomes invalid (solid reaching the
    /// overflow, a non-finite value), naming time and place.
    void step();
    /// Runs the quasi-static gravity stage (local damping) of initial.gravity_stage_duration.
    void runGravityStage();

    Real time() const { return time_; }
    Real dt() const { return dt_; }
    long stepCount() const { return steps_; }
    const Grid<D>& grid() const { return grid_; }
    const SolidPoints<D>& solid() const { return solid_; }
    const LiquidPoints<D>& liquid() const { return liquid_; }
    ColumnState columnState() const;
    std::vector<CellRow> profile() const;
    /// The sand's state and porosity per cell and the water crossing the filter plane per column
    /// of cells, as the pipe measurement reads them (physics/Pipes.hpp). 2D and 3D.
    SandCells sandCells() const;
    /// The wave speed the time step follows (m/s): c_fast (explicit) or c_skeleton (semi-implicit).
    Real waveSpeed() const { return waveSpeed_; }
    TimeScheme scheme() const { return integrator_->scheme(); }
    IntegratorStats integratorStats() const { return integrator_->stats(); }
    /// The share of its slope mass below which a node is starved: C^2 / 2, C = dt c / h
    /// (GridToPoints.cpp)
    Real starvedShare() const { const Real c = dt_ * waveSpeed_ / grid_.h(); return 0.5 * c * c; }
    /// Each node's solid mass over its slope mass, m_i / S_i, from the last step's transfer; -1
    /// at nodes no solid point reaches. For diagnostics and tests: a node is starved below
    /// starvedShare(); inside the sand the ratio is 0.4 to 0.5 with linear hats.
    std::vector<Real> sandFeeding() const;

    /// This rank's share of a decomposed run (null on one rank).
    const RankShare<D>* rankShare() const { return ranks_.get(); }

    void saveState(CheckpointData& data) const;
    void loadState(const CheckpointData& data);
    /// The state a coupling window starts from, for implicit coupling's repeats of the window
    /// (MpmAdapter): over MPI ranks each rank's own points, grid and sums as it holds them, with no
    /// gather and no reduction, restored bit for bit on the rank that saved them; on one rank the
    /// checkpoint's state.
    void saveWindowStart(CheckpointData& data) const;
    void loadWindowStart(const CheckpointData& data);

private:
    // phases of one step
    void sortPoints();
    void classifyCells();
    void pointsToGrid();
    void measureSandPorosity();
    void computeForces();             // Forces.cpp: the order of the forces below
    void cellWaterFromPoints();       // PorePressure.cpp
    void computePressureGradient();   // PorePressure.cpp
    void pressureForces();            // PorePressure.cpp
    void gravityForces();             // Forces.cpp
    void particlePhaseForces();       // ParticlePhase.cpp
    void packingForces();             // PackingPressure.cpp
    /// Whether node i lies inside sand that carries no effective stress, where the front
    /// diffusion and the particle phase act (FrontDiffusion.cpp)
    bool insideStressFreeSand(Index i) const;
    void gateTraction();              // Gate.cpp
    void switchLiquidState();
    void diffuseFronts();
    void gridToPoints();
    void updatePressure();
    void exchangeAtBoundaries();
    void advanceReservoir();          // Gate.cpp
    void carrySandOut(Real zOverflow);
    void checkHealth() const;
    void checkWater(const CheckpointData& data, bool semi) const;  // SolverCheckpoint.cpp

    // over MPI ranks (parallel/RankShare.hpp); on one rank each is the plain serial operation
    void exchangePoints();            // the step's start: migrants and ghost copies
    void dropGhostPoints();           // after the step's gather: the copies go
    Real spillOnRanks(Index lowCell, Real grains);
    bool ownsCell(Index c) const { return !ranks_ || ranks_->ownsCell(c); }
    bool ownsNode(Index i) const { return !ranks_ || ranks_->ownsNode(i); }
    bool ownsColumn(Index k) const { return !ranks_ || ranks_->ownsColumn(k); }
    Real sumOverRanks(Real local) const { return ranks_ ? ranks_->comm().sum(local) : local; }
    void sumOverRanks(std::vector<Real>& local) const { if (ranks_) ranks_->comm().sumInPlace(local); }
    Real maxOverRanks(Real local) const { return ranks_ ? ranks_->comm().max(local) : local; }

    // helpers
    void allocate();
    template <class Set>
    void sortByCell(Set& set, std::vector<Index>& cellStart, std::vector<Index>& counts);
    template <class Set>
    void computeWeights(Set& set);
    Real waterSurface() const;
    Real sandSurface() const;  ///< this rank's points' (all of them on one rank)
    Real bedTop(Real sandSurface) const;
    Real surchargeNow() const;
    void measureStates(ColumnState& s) const;
    void gatherSandCells(SandCells& s) const;
    /// The share of a node's footprint inside horizontal ranges (1 without them).
    Real footprintShare(Index node, const std::optional<HorizontalRange>& x,
                        const std::optional<HorizontalRange>& y) const;
    Real waterVolumeAt(Index node) const;
    Real gateVelocityNow() const;
    StepInputs stepInputs() const;

    const CaseConfig& config_;
    ReservoirModel& reservoir_;
    Grid<D> grid_;
    std::unique_ptr<RankShare<D>> ranks_;  ///< this rank's block, over MPI ranks (null on one)
    std::vector<SolidMaterial> materials_;
    SolidPoints<D> solid_;
    LiquidPoints<D> liquid_;
    ReorderScratch scratch_;

    // the grid's fields, grouped by what they describe (solver/GridFields.hpp)
    NodeFields<D> nodes_;
    TransferSums sums_;
    CellIndex cells_;
    CellFilling filling_;
    CellWater<D> water_;
    CellSandState sand_;
    /// Pa, the lowest pressure a cell's water takes: no suction where it is open to the air
    Real cellLimit(Index c) const { return waterLimit(filling_.openToAir[c], config_.liquid.cavitationPressure); }
    /// How far a node is fed with sand: m_i / (share S_i) for a starved node, else 1 (GridToPoints.cpp)
    Real fedWeight(Index i, Real share) const {
        const Real need = share * nodes_.slopeMass[i];
        return nodes_.massS[i] < need ? nodes_.massS[i] / need : Real(1);
    }
    BoundaryMasks<D> masks_;
    std::unique_ptr<TimeIntegrator<D>> integrator_;  ///< phase 4: the velocities, by time.scheme
    Real gateArea_ = 0;                              ///< m2, the gate plane's
    InflowChamber<D> chamber_;
    std::vector<char> dropFlags_;    ///< scratch of the outflow removal
    std::vector<Index> spillOrder_;  ///< scratch of the overflow's weir: the points above the rim, lowest first

    LiquidStateRule stateRule_;
    GateLaw gateLaw_;
    Real dt_ = 0, time_ = 0, waveSpeed_ = 0;
    long steps_ = 0;
    bool damping_ = false;
    Real dampingAlpha_ = 0;
    bool anyParticlePhase_ = false;  ///< some material has a particle phase (particlePhaseForces)
    bool anyClosePacking_ = false;   ///< some material holds its close packing (packingForces)
    Real weightShare_ = 1;           ///< the share of the grains' buoyant weight loaded (the gravity stage's ramp)
    Real gateFlux_ = 0, gatePressure_ = 0;
    Real cumulativeInflow_ = 0, outflowVolume_ = 0;
    Real solidOutflowMass_ = 0;      ///< kg of grains carried out over the overflow
    bool warnedSandOut_ = false;     ///< the warning that sand leaves was given
    Real initialLiquidMass_ = 0, initialGapVolume_ = 0;
    std::vector<Index> monitorNodes_;
    Index sandBottomRow_ = 0;
    Real sandFloor_ = 0;  ///< m, where the sand is held on the filter: in the cell above it (Grid::firstInCell)
    Index overflowRow_ = -1;  ///< cell rows below the overflow level (-1: no overflow)
    /// the rows of cells under the rim over which the water's level there is measured: the overflow's
    /// weir holds crest water back while they lack more than half a row, and the run stops when they
    /// lack a row
    static constexpr Index kRimRows = 2;
};

}  // namespace qs
