#pragma once
// The semi-implicit scheme (time.scheme = "semi_implicit"): an incremental pressure projection
// for the double-point step (physics.md section 2; docs/semi-implicit-design.md).
//
//  1 Predictor: the explicit node solve (NodeVelocities.hpp) with the forces of the step's start,
//    the pore pressure p^n among them: v*_S, v*_L and the mixture's flux Phi* = (1-n) v*_S + n v*_L.
//  2 Each node component's response to a pressure force: a force G on the mixture, shared as
//    (1-n) G on the solid and n G on the liquid, moves the velocities by dt r_S G and dt r_L G,
//    (r_S, r_L) from the same node solve (componentResponse, in the predictor's pass), and the
//    flux by dt beta G, beta = (1-n) r_S + n r_L: the drag, the masks and the tube's loss are in it.
//  3 The pressure increment dp of the cells that keeps each cell's water balance with the
//    velocities it makes, S_c dp_c + dt (D Phi)_c = 0, S_c = V_c n_c / K_L:
//      (S + dt^2 D B D^T) dp = -dt D Phi*,
//    D the cells' divergence (the discrete one of updatePressure, V_c times it) and D^T the nodes'
//    pressure force (computeForces), B = diag(beta). Dropping the dt^2 term gives the explicit
//    update back. In 2D and 3D a pressure gate's water moves at one velocity: a rank-one term,
//    solved by Sherman-Morrison (two solves with one factorisation).
//  4 Corrector: v = v* + dt r D^T dp. updatePressure then takes the cell's water from these
//    velocities as in the explicit scheme, which gives p^n + dp where the system held, and keeps
//    cavities and the water's volume consistent everywhere.
// Rough walls (boundary/RoughWalls.hpp) decide stick or slip in the predictor; the increment's
// force along the wall changes what holding the grains takes (its normal share is the water's,
// which the wall takes, so mu N stays). After each solve every wall node's decision is taken
// again with the increment's force in its trial: where one overturns (a stuck node past mu N, a
// slipping one back within it or pulled the other way), the wall nodes' predictors and responses
// are redone, the friction re-aimed, and the pass solved again, as the active set below is.
// The water's lowest pressure (cavitation, no suction under the air) is a bound p >= p_lim: a
// cell at its bound at the step's start is held there, a cell the solve takes below it is held
// at it, and a held cell whose water the velocities would press above its bound is let go; a few
// solves (an active set) settle which cells are held.
//
// What bounds the step: the skeleton's stress, explicit, sqrt(E_oed / ((1 - n) rho_s)); the
// water's compression and the drag are implicit.
//
// Over MPI ranks (a cut column) each rank assembles its own cells' rows as above, from its
// block and the ghost points' window; hypre's CG with BoomerAMG solves the system over the ranks
// (parallel/DistributedPressureSolver.hpp, the cells numbered rank by rank), and the increment,
// the held cells and their known increments come to the window's cells from their owners before
// the corrector reads them. The gate's sums, the active set's "changed" and the checkpointed
// guesses are reduced over the ranks, each cell and gate node counted by its owner.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parallel/DistributedPressureSolver.hpp"
#include "solver/NodeVelocities.hpp"
#include "solver/PressureSystem.hpp"

namespace qs {

template <int D>
class SemiImplicitIntegrator final : public TimeIntegrator<D> {
public:
    explicit SemiImplicitIntegrator(const StepContext<D>& context);
    TimeScheme scheme() const override { return TimeScheme::SemiImplicit; }
    Real solveVelocities(const StepInputs& in, Real time) override;
    IntegratorStats stats() const override { return stats_; }
    std::vector<double> saveState() const override;
    void restoreState(const std::vector<double>& state) override;
    std::vector<double> saveWindowStart() const override;
    void restoreWindowStart(const std::vector<double>& state) override;
    /// Pa per cell, the last step's pressure increment dp (a held cell's: its known one)
    const Eigen::VectorXd& pressureIncrement() const { return dp_; }

private:
    void gateResponse(const StepInputs& in);
    void assemble(Real dt);
    static constexpr int kStencil = D == 1 ? 3 : D == 2 ? 9 : 27;  ///< a cell's neighbours and itself
    static int neighbourCode(int corner, int corner2);
    void writeColumn(Index c, const Real* entry);
    void solve(Real dt, Real time);
    void correct(Real dt);
    bool updateHeldCells(Real dt);
    void recordWallNode(Index i, const NodeComponent (&c)[D], const Real (&vS1)[D], const Real (&vL1)[D],
                        const typename RoughWalls<D>::Contact& contact);
    bool recheckWalls(Real dt);
    struct WallNode;
    void trialWithIncrement(const WallNode& w, Real dt, Real (&vS1)[D], Real (&vL1)[D]) const;
    Real cellDivergence(Index c) const;
    Real limit(Index c) const;
    /// Whether this rank counts cell c (its owner; every cell on one rank).
    bool owns(Index c) const { return !ctx_.ranks || ctx_.ranks->ownsCell(c); }
    /// A sum of this rank's terms over the ranks (the term itself on one rank).
    Real overRanks(Real local) const { return ctx_.ranks ? ctx_.ranks->comm().sum(local) : local; }
    /// Over ranks: the pattern of this rank's rows in the global numbering, and the solver.
    void setUpDistributed();
    /// A = system_ (this rank's rows) solved over the ranks for b into x (the guess as it comes
    /// in); the window's cells of x from their owners. Returns CG's iterations.
    int solveDistributed(const Eigen::VectorXd& b, Eigen::VectorXd& x);

    StepContext<D> ctx_;
    PressureSystem system_;
    std::vector<Real> predS_, predL_;  ///< [D] m/s, the predictor's velocities
    std::vector<Real> incL_;           ///< [D] m/s, the predictor's FLIP increment
    /// [D] s/kg, each component's response to a unit impulse on the mixture, shared as (1 - n)
    /// on the solid and n on the liquid: the node solve with those as its drag-free predictors
    /// and nothing prescribed (solveComponent is linear in them)
    std::vector<Real> rS_, rL_;
    std::vector<Real> force_;          ///< [D] N, D^T dp: the increment's force on the mixture
    std::vector<Real> gateWeight_;     ///< per gate node, M_L r_L: its share of the uniform gate's impulse
    std::vector<char> held_;           ///< per cell: its increment is known (no water, or at its bound)
    /// A rough wall's node as the predictor solved it: what its decision is taken again from
    struct WallNode {
        Index node = 0;
        bool active = false;              ///< it has grains this step
        bool stuck = false;
        Real limit = 0;                   ///< N, mu N
        Real reaction[D] = {};            ///< N, the stuck trial's R the friction is aimed along
        NodeComponent free[D];            ///< the components as nodeComponent gives them
        Real vS1[D] = {}, vL1[D] = {};    ///< m/s, the drag-free predictors
    };
    std::vector<WallNode> wallNodes_;  ///< one per rough wall node, allocated once
    std::vector<Index> wallSlot_;      ///< per node: its entry in wallNodes_, -1 off the walls
    Eigen::VectorXd rhs_, gateSolve_, gateLeft_, gateRight_;
    /// Pa, the increment; and y = A^-1 a_L, the gate's term (Sherman-Morrison). Kept over steps:
    /// CG starts from the last step's (pass's) solution, which the next differs from little.
    Eigen::VectorXd dp_, gateY_;
    Eigen::VectorXd heldValue_;        ///< Pa, the known increment of each held cell
    Real gateGamma_ = 0;               ///< dt^2 / (sum M_L + dt R A_wet^2), 0 without a uniform gate
    Real gateDenominator_ = 0;
    int solves_ = 0;                   ///< this step's
    IntegratorStats stats_;
    // over ranks
    std::unique_ptr<DistributedPressureSolver> distributed_;
    std::vector<Index> owned_;                    ///< this rank's cells, ascending (its rows in order)
    std::vector<Index> rowStart_, rowColumns_;    ///< its rows' pattern, global columns (CSR)
    std::vector<double> rowValues_, bLocal_, xLocal_;
    bool matrixSent_ = false;                     ///< the assembled values are the solver's
};

}  // namespace qs
