#include "solver/DoublePointSolver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "grid/ShapeFunctions.hpp"
#include "materials/StressTensor.hpp"
#include "solver/ColumnBuilder.hpp"
#include "boundary/Overflow.hpp"
#include "solver/Parallel.hpp"
#include "solver/RunSize.hpp"
#include "materials/ConstitutiveModels.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/DistributedPressureSolver.hpp"

namespace qs {

namespace {
Index roundCells(Real length, Real h) { return static_cast<Index>(std::llround(length / h)); }

}  // namespace

// ---------------------------------------------------------------------------------------------
// Set-up
// ---------------------------------------------------------------------------------------------

template <int D>
DoublePointSolver<D>::DoublePointSolver(const CaseConfig& config, ReservoirModel& reservoir, const Communicator* ranks)
    : config_(config), reservoir_(reservoir) {
    const Real h = config.grid.cellSize;
    IVec<D> cells;
    for (int d = 0; d < D - 1; ++d) cells[d] = roundCells(config.grid.width, h);
    cells[D - 1] = roundCells(config.column.top, h);
    grid_ = Grid<D>(cells, h, config.grid.crossSectionArea, config.grid.geometry == GridGeometry::Axisymmetric,
                    config.points.solidPerCell);

    waveSpeed_ = schemeWaveSpeed(config);
    for (const auto& m : config.materials) {
        SolidMaterial s;
        s.name = m.name;
        s.grainDensity = m.grainDensity;
        s.maxPorosity = m.maxPorosity;
        s.minPorosity = m.minPorosity;
        s.model = makeConstitutiveModel(m);
        s.suspension.waterViscosity = config.liquid.viscosity;
        s.suspension.maxPacking = 1 - m.minPorosity;
        s.permeability = PermeabilityLaw::from(m);
        s.frontDiffusivity = frontDiffusivity(DragLaw{config.liquid.viscosity, config.liquid.density},
                                              s.permeability, m.grainDensity, config.gravity, m.maxPorosity, h,
                                              m.frontDiffusion);
        s.frontThreshold = m.frontThreshold;
        s.particlePhase = m.particlePhase == ParticlePhaseModel::FoscoloGibilaro;
        s.elasticForce = {m.particleGrainSize, m.grainDensity, config.liquid.density, config.gravity};
        anyParticlePhase_ = anyParticlePhase_ || s.particlePhase;
        s.packing.minPorosity = m.minPorosity;
        if (m.closePacking) s.packing.modulus = ClosePacking::modulusForStep(waveSpeed_, m.grainDensity, m.minPorosity);
        anyClosePacking_ = anyClosePacking_ || m.closePacking;
        materials_.push_back(s);
    }
    // dt = C h / c: with implicit drag the fastest explicit wave is the zero-drag fast wave, and
    // with the pressure implicit too the skeleton's (solver/RunSize.hpp, the same step `quicksand
    // check` reports)
    requireStableTimeStep(config);
    dt_ = timeStep(config);

    for (const auto& m : materials_) solid_.internalCount = std::max(solid_.internalCount, m.model->stateCount());
    if (ranks && ranks->parallel()) {
        // each rank makes its block's points of the column, as one rank makes them
        QS_CHECK(config.time.scheme == TimeScheme::Explicit || distributedSolverAvailable(),
                 config.caseDirectory << "/case.toml: time.scheme = \"semi_implicit\" on MPI ranks needs the pressure "
                                      "solve over the ranks (hypre, Debian's libhypre-dev: bash tools/setup.sh --mpi), "
                                      "which this build lacks; run it on one rank, or with time.scheme = \"explicit\"");
        ranks_ = std::make_unique<RankShare<D>>(*ranks, decompose(config, ranks->size()), grid_, ghostPointLayers(config));
        buildColumn(config, grid_, materials_, solid_, liquid_,
                    [&](const Real* x) { return ranks_->ownsCell(grid_.cellOf(x)); });
    } else {
        buildColumn(config, grid_, materials_, solid_, liquid_);
    }
    allocate();
    masks_.build(grid_, config);
    for (Index i : masks_.gateNodes) gateArea_ += nodeFootprint(grid_, i);
    integrator_ = makeTimeIntegrator(StepContext<D>{config_, grid_, masks_, cells_, filling_, water_, nodes_, ranks_.get()});
    // new points as short as the free-water points, so they do not leave sand cells empty
    chamber_.setup(grid_, h / freeWaterPointsPerCell(config), config.points.liquidPerCell);
    if (ranks_) chamber_.restrictTo(grid_, [&](Index column) { return ranks_->ownsColumn(column); });

    for (const auto& m : config.monitors) {
        const Index row = std::clamp<Index>(std::llround(m.elevation / h), 0, grid_.nodes(D - 1) - 1);
        monitorNodes_.push_back(row);
    }
    sandBottomRow_ = roundCells(config.filterLevel(), h);
    sandFloor_ = grid_.firstInCell(D - 1, sandBottomRow_);
    if (config.column.overflowLevel) overflowRow_ = roundCells(*config.column.overflowLevel, h);

    initialLiquidMass_ = 0;
    for (Real m : liquid_.mass) initialLiquidMass_ += m;
    initialLiquidMass_ = sumOverRanks(initialLiquidMass_);
    gateLaw_ = reservoir_.gateLaw(0.0);
    gatePressure_ = gateLaw_.staticPressure;
    // fill the cell and node fields once so that the state at t = 0 can be reported
    exchangePoints();
    sortPoints();
    classifyCells();
    pointsToGrid();
    measureSandPorosity();
    computeForces();
    dropGhostPoints();
}

template <int D>
void DoublePointSolver<D>::exchangePoints() {
    if (!ranks_) return;
    ranks_->exchange(solid_);
    ranks_->exchange(liquid_);
    ranks_->shareCarried(water_, nodes_);
    solid_.stressReturn.resize(solid_.size());  // per-step scratch beside the registry
}

template <int D>
void DoublePointSolver<D>::dropGhostPoints() {
    if (!ranks_) return;
    ranks_->dropGhosts(solid_, cells_.solidStart, solid_.stressReturn);
    ranks_->dropGhosts(liquid_, cells_.liquidStart, liquid_.weight);
}

template <int D>
void DoublePointSolver<D>::allocate() {
    const Index nn = grid_.numNodes(), nc = grid_.numCells();
    nodes_.resize(nn);
    sums_.resize(nn);
    cells_.resize(nc);
    filling_.resize(nc);
    water_.resize(nc);
    sand_.resize(nc);

    // Liquid points come and go: reserve for the densest filling the run can reach (over MPI
    // ranks, in the rank's block and its window of ghost cells).
    const Index reach = ranks_ ? ranks_->windowCells() : nc;
    const std::size_t liquidCapacity = static_cast<std::size_t>(
        qs::liquidCapacity(config_, reach, static_cast<std::int64_t>(liquid_.size())));
    reservePoints(liquid_, liquidCapacity, scratch_, 6);
    // The sand's points stay, but over MPI ranks the ghosts join them each step: room for the
    // window's share of them (its cells over the block's, a tenth more), so that the first
    // exchange does not grow every field. The reorder's scratch holds the widest field: the
    // stress (6), C (D x D) or the internal state.
    const double window = ranks_ ? 1.1 * double(ranks_->windowCells()) / double(std::max<Index>(1, ranks_->ownedCells())) : 1.0;
    const std::size_t solidCapacity = static_cast<std::size_t>(window * double(solid_.size()));
    reservePoints(solid_, solidCapacity, scratch_, std::max({6, D * D, solid_.internalCount}));
    scratch_.reals.reserve(liquidCapacity * 6);
    scratch_.ints.reserve(liquidCapacity);
    scratch_.order.reserve(liquidCapacity);
    const bool gimp = config_.grid.shapeFunctions == ShapeFunctionKind::Gimp;
    liquid_.shape.weights = solid_.shape.weights = gimp;  // linear weights come from the positions
    liquid_.shape.reserve(liquidCapacity);
    liquid_.weight.reserve(liquidCapacity);
    solid_.shape.reserve(solidCapacity);
    solid_.stressReturn.reserve(solidCapacity);
    solid_.stressReturn.assign(solid_.size(), 0);
    dropFlags_.reserve(liquidCapacity);
    spillOrder_.reserve(liquidCapacity);
}

// ---------------------------------------------------------------------------------------------
// the step
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::step() {
    // the gate law for this step, asked afresh: a coupling scheme may have started a new window
    // (or rolled the window back) since the last step
    gateLaw_ = reservoir_.gateLaw(time_);
    exchangePoints();
    sortPoints();
    classifyCells();
    pointsToGrid();
    measureSandPorosity();
    computeForces();
    gateFlux_ = integrator_->solveVelocities(stepInputs(), time_);
    switchLiquidState();
    diffuseFronts();
    gridToPoints();
    updatePressure();
    exchangeAtBoundaries();
    checkHealth();
}

template <int D>
void DoublePointSolver<D>::runGravityStage() {
    const Real duration = config_.initial.gravityStageDuration;
    if (duration <= 0) return;
    damping_ = true;
    dampingAlpha_ = config_.initial.gravityStageDamping;
    const Real t0 = time_;
    const auto saved = reservoir_.saveState();
    const Real ramp = config_.initial.gravityStageRamp;
    while (time_ - t0 < duration) {
        weightShare_ = ramp > 0 ? std::min(Real(1), (time_ - t0) / ramp) : Real(1);
        step();
    }
    weightShare_ = 1;
    reservoir_.restoreState(saved);
    damping_ = false;
    // the dynamic stage starts at rest at t = 0
    time_ = 0;
    steps_ = 0;
    std::fill(solid_.v.begin(), solid_.v.end(), 0.0);
    std::fill(solid_.velocityGradient.begin(), solid_.velocityGradient.end(), 0.0);  // APIC's C: at rest too
    std::fill(liquid_.v.begin(), liquid_.v.end(), 0.0);
    std::fill(nodes_.relSpeed.begin(), nodes_.relSpeed.end(), 0.0);
    cumulativeInflow_ = outflowVolume_ = solidOutflowMass_ = 0;
    chamber_.setInjectedVolume(0);
    initialLiquidMass_ = 0;
    for (Real m : liquid_.mass) initialLiquidMass_ += m;
    initialLiquidMass_ = sumOverRanks(initialLiquidMass_);
    initialGapVolume_ = chamber_.gapVolume(grid_);
    gateLaw_ = reservoir_.gateLaw(0.0);
}

// ---------------------------------------------------------------------------------------------
// loads and measurements
// ---------------------------------------------------------------------------------------------

template <int D>
Real DoublePointSolver<D>::surchargeNow() const {
    const Real q = config_.loads.surcharge, ramp = config_.loads.surchargeRampTime;
    if (damping_) return config_.initial.undrainedSurcharge ? q : 0.0;
    return (ramp > 0 && time_ < ramp) ? q * time_ / ramp : q;
}

template <int D>
Real DoublePointSolver<D>::sandSurface() const {
    return sandSurfaceOf(grid_, solid_, config_.filterLevel(), config_.points.solidPerCell);
}

// The free surface as the column's contents fill it from the gate plane (z = 0): the water (its
// mass over its density, and the cavities it opened: a void under the surface lifts it as much),
// the chamber's gap above the gate (water that came in, not yet a point), and the grains (their
// mass over their density), over the column's cross-section. The water's compression is left
// out: the points' masses are the initial state's, pressed already (0.02 mm in the soft water's
// column). The bed starts submerged and its pores stay full, so this holds wherever the grains
// are. Reckoned from the water above the highest grain instead, a boil's plume or a grain at the
// rim left no water "above the sand" and the surface read 0 (piping3D, 2026-12-06).
template <int D>
Real DoublePointSolver<D>::waterSurface() const {
    // over MPI ranks the points' volumes are each rank's own, added over the ranks; the chamber's
    // gaps are every slot's on every rank (InflowChamber::shareGaps)
    Real volume = ranks_ ? 0.0 : chamber_.gapVolume(grid_);
    for (std::size_t p = 0; p < liquid_.size(); ++p)
        volume += liquid_.mass[p] / config_.liquid.density * (1 + liquid_.cavity[p]);
    for (std::size_t p = 0; p < solid_.size(); ++p)
        volume += solid_.mass[p] / materials_[solid_.material[p]].grainDensity;
    if (ranks_) volume = chamber_.gapVolume(grid_) + sumOverRanks(volume);
    return volume / grid_.crossSection();
}

template class DoublePointSolver<1>;
template class DoublePointSolver<2>;
template class DoublePointSolver<3>;

}  // namespace qs
