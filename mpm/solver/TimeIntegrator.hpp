#pragma once
// TimeIntegrator<D>: the seam between the step's shared phases and its time scheme (phase 4 of
// DoublePointSolver.hpp). Everything else in the step is the same for every scheme: the points
// mapped to the grid, the forces (stress, the pore pressure at the step's start, gravity, the
// gate's and the surcharge's tractions), the liquid-state switch, the front diffusion, the grid
// mapped back to the points, the pore-pressure update from the mixture's volume balance
// (updatePressure), the boundaries' exchange and the checkpoints. A scheme turns the nodes'
// masses, momenta, drag and forces into the velocities at the step's end:
//   - explicit (ExplicitIntegrator.cpp): each node on its own, with implicit drag
//     (NodeVelocities.hpp). The pore pressure then follows from the velocities' divergence: its
//     wave, the water's compression, bounds the step (c_fast, solver/RunSize.hpp);
//   - semi-implicit (SemiImplicitIntegrator.cpp): the same node solve as a predictor, then a
//     pressure increment on the cells that makes the velocities satisfy the mixture's volume
//     balance with the increment's own force (a projection, physics.md section 2). The water's
//     wave leaves the step's bound; the skeleton's stays (c_skeleton).
// The scheme is chosen in case.toml, time.scheme; the step's size follows from it
// (solver/RunSize.hpp, timeStep).
#include <memory>
#include <vector>

#include "boundary/BoundaryMasks.hpp"
#include "grid/Grid.hpp"
#include "case/CaseConfig.hpp"
#include "parallel/RankShare.hpp"
#include "solver/GridFields.hpp"

namespace qs {

/// The gate plane (the bottom node row) as the node solve sees it in one step.
struct GateStep {
    Real velocity = 0;     ///< m/s, the liquid's prescribed vertical velocity (flux mode)
    Real resistance = 0;   ///< Pa s/m3, the tube's loss R taken implicitly (pressure mode; 0 otherwise)
    Real area = 0;         ///< m2, the gate plane
    /// 2D/3D pressure gate: the gate row's water moves in at one vertical velocity
    /// (NodeVelocities.cpp, uniformGateVelocity)
    bool uniform = false;
};

/// What changes from step to step besides the fields.
struct StepInputs {
    Real dt = 0;             ///< s
    bool damping = false;    ///< the gravity stage's local damping, F <- F - alpha |F| sign(v)
    Real dampingAlpha = 0;   ///< -
    GateStep gate;
};

/// The fields a scheme reads and writes, by reference: the solver owns them (and checkpoints and
/// measures them); a scheme writes only the nodes' velocities.
template <int D>
struct StepContext {
    const CaseConfig& config;
    const Grid<D>& grid;
    const BoundaryMasks<D>& masks;
    const CellIndex& cells;
    const CellFilling& filling;
    const CellWater<D>& water;
    NodeFields<D>& nodes;
    /// Over MPI ranks, this rank's share: the gate's sums take the nodes it owns, added over the
    /// ranks (null on one rank)
    const RankShare<D>* ranks = nullptr;
};

/// What a scheme's own work cost over the run (the semi-implicit pressure solve; zero for the
/// explicit scheme, whose node solve is the step's phase 4 and nothing more).
struct IntegratorStats {
    long steps = 0;
    long solves = 0;          ///< linear solves (active-set passes), over all steps
    long cappedSteps = 0;     ///< steps whose active set had not settled after the last pass
    long wallPasses = 0;      ///< passes taken again because the increment overturned a rough wall's stick or slip
    long iterations = 0;      ///< CG iterations over all solves (0 with the direct solver)
    /// s of wall time in the assembly, solve and correction (an estimate from sampled steps:
    /// SemiImplicitIntegrator)
    double seconds = 0;
    const char* solver = "";  ///< the linear solver, for the summary
};

template <int D>
class TimeIntegrator {
public:
    virtual ~TimeIntegrator() = default;
    virtual TimeScheme scheme() const = 0;
    /// Pre: the nodes' masses, momenta, drag, porosities and forces of this step, the cells' water
    /// at the step's start. Post: nodes.velS, velL, velLIncrement and relSpeed at the step's end.
    /// Returns the gate flux, m3/s into the column. Throws qs::Error if the scheme cannot advance
    /// (a pressure solve that fails), naming the time and the cell; the nodes' velocities are then
    /// not the step's, and the run stops.
    virtual Real solveVelocities(const StepInputs& in, Real time) = 0;
    virtual IntegratorStats stats() const { return {}; }
    /// What the scheme carries from one step to the next (the semi-implicit step's starting
    /// guesses for CG), for the checkpoint: a run resumed from it takes the same steps as the run
    /// that wrote it. Empty for a scheme that carries nothing.
    virtual std::vector<double> saveState() const { return {}; }
    /// Throws qs::Error if `state` is not one this scheme wrote for this grid.
    virtual void restoreState(const std::vector<double>& state) { (void)state; }
    /// The same state as this rank holds it, for implicit coupling's repeat of a window over MPI
    /// ranks (DoublePointSolver::saveWindowStart): no reduction, each rank its own copy. On one
    /// rank it is saveState's.
    virtual std::vector<double> saveWindowStart() const { return saveState(); }
    virtual void restoreWindowStart(const std::vector<double>& state) { restoreState(state); }
};

template <int D>
std::unique_ptr<TimeIntegrator<D>> makeTimeIntegrator(const StepContext<D>& context);

}  // namespace qs
