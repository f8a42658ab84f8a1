// The semi-implicit step: predictor, the cells' pressure increment, corrector
// (SemiImplicitIntegrator.hpp says why each piece is as it is).
#include "solver/SemiImplicitIntegrator.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/ForAll.hpp"
#include "parallel/CellNumbering.hpp"
#include "parallel/RankShare.hpp"
#include "physics/Cavitation.hpp"

namespace qs {

namespace {
/// Active-set passes a step may take before it keeps what it has: updatePressure presses the
/// water from the last velocities, so the state stays consistent either way.
constexpr int kMaxSolves = 8;
/// The solve's share of the wall time is measured on one step in this many
constexpr long kTimedEvery = 8;
/// Pa: how far past its bound a cell's pressure may come out before the active set changes, at a
/// cell of pressure p: 1e-6 Pa and 1e-9 of p, above the solve's own noise
inline Real boundTolerance(Real p) { return 1e-6 + 1e-9 * std::abs(p); }
}  // namespace

template <int D>
SemiImplicitIntegrator<D>::SemiImplicitIntegrator(const StepContext<D>& context) : ctx_(context) {
    const Index nn = ctx_.grid.numNodes(), nc = ctx_.grid.numCells();
    for (auto* a : {&predS_, &predL_, &incL_, &rS_, &rL_, &force_}) a->assign(nn * D, 0.0);
    held_.assign(nc, 0);
    gateWeight_.assign(ctx_.masks.gateNodes.size(), 0.0);
    for (auto* v : {&rhs_, &dp_, &gateY_, &heldValue_, &gateSolve_, &gateLeft_, &gateRight_}) v->setZero(nc);
    // over ranks the system's arrays hold the assembly only (no factorisation is analysed)
    system_.build(ctx_.grid, ctx_.ranks ? PressureSolver::ConjugateGradient : ctx_.config.time.pressureSolver);
    wallSlot_.assign(nn, -1);
    for (Index i = 0; i < nn; ++i)
        if (ctx_.masks.roughWalls.rough(i)) {
            wallSlot_[i] = static_cast<Index>(wallNodes_.size());
            wallNodes_.emplace_back();
            wallNodes_.back().node = i;
        }
    stats_.solver = system_.solverName();
    if (ctx_.ranks) setUpDistributed();
}

template <int D>
void SemiImplicitIntegrator<D>::setUpDistributed() {
    const RankShare<D>& share = *ctx_.ranks;
    const Grid<D>& grid = ctx_.grid;
    const CellNumbering<D> numbering(share.decomposition());
    const int r = share.rank();
    for (Index c = 0; c < grid.numCells(); ++c)
        if (share.ownsCell(c)) owned_.push_back(c);
    QS_CHECK(static_cast<Index>(owned_.size()) == numbering.firstRow(r + 1) - numbering.firstRow(r),
             "the semi-implicit step over ranks: rank " << r << " owns " << owned_.size() << " cells, its rows "
                                                        << numbering.firstRow(r + 1) - numbering.firstRow(r));
    rowStart_.assign(1, 0);
    for (Index c : owned_) {
        const int* rows = system_.rows(c);
        for (Index k = 0; k < system_.size(c); ++k) rowColumns_.push_back(numbering.row(grid.cellCoords(rows[k])));
        rowStart_.push_back(static_cast<Index>(rowColumns_.size()));
    }
    rowValues_.resize(rowColumns_.size());
    bLocal_.resize(owned_.size());
    xLocal_.resize(owned_.size());
    distributed_ = std::make_unique<DistributedPressureSolver>(share.comm(), numbering.firstRow(r),
                                                               numbering.firstRow(r + 1), D);
    stats_.solver = "CG with BoomerAMG over the ranks (hypre)";
}

template <int D>
int SemiImplicitIntegrator<D>::solveDistributed(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    if (!matrixSent_) {  // the values of this pass's assembly, once for its solves
        for (std::size_t i = 0; i < owned_.size(); ++i) {
            const Real* v = system_.values(owned_[i]);
            std::copy(v, v + (rowStart_[i + 1] - rowStart_[i]), rowValues_.begin() + rowStart_[i]);
        }
        distributed_->setMatrix(rowStart_, rowColumns_, rowValues_);
        matrixSent_ = true;
    }
    for (std::size_t i = 0; i < owned_.size(); ++i) {
        bLocal_[i] = b[owned_[i]];
        xLocal_[i] = x[owned_[i]];
    }
    const int iterations = distributed_->solve(bLocal_, xLocal_, PressureSystem::kTolerance);
    for (std::size_t i = 0; i < owned_.size(); ++i) x[owned_[i]] = xLocal_[i];
    return iterations;
}

// CG's starting guesses, dp and y, one after the other
template <int D>
std::vector<double> SemiImplicitIntegrator<D>::saveState() const {
    std::vector<double> state(dp_.data(), dp_.data() + dp_.size());
    state.insert(state.end(), gateY_.data(), gateY_.data() + gateY_.size());
    if (ctx_.ranks) {  // each cell's from its owner (collective)
        // and a resumed run's first solve builds its AMG hierarchy anew: so does this one's next
        distributed_->rebuildPreconditioner();
        const Index nc = ctx_.grid.numCells();
        for (Index c = 0; c < nc; ++c)
            if (!owns(c)) state[c] = state[nc + c] = 0;
        ctx_.ranks->comm().sumInPlace(state);
    }
    return state;
}

template <int D>
void SemiImplicitIntegrator<D>::restoreState(const std::vector<double>& state) {
    const Index nc = ctx_.grid.numCells();
    QS_CHECK(static_cast<Index>(state.size()) == 2 * nc,
             "entry 'integrator' holds " << state.size() << " values, the semi-implicit step's state on this grid "
                                         << 2 * nc << ": a checkpoint of another case or grid");
    dp_ = Eigen::Map<const Eigen::VectorXd>(state.data(), nc);
    gateY_ = Eigen::Map<const Eigen::VectorXd>(state.data() + nc, nc);
}

// A window's start over MPI ranks: each rank's own dp and y, window cells included (they are
// their owners', RankShare::shareCellValues), and the AMG hierarchy built anew at the window's
// start and at each repeat, so that every pass over the window begins from the same solver.
template <int D>
std::vector<double> SemiImplicitIntegrator<D>::saveWindowStart() const {
    if (!ctx_.ranks) return saveState();
    distributed_->rebuildPreconditioner();
    std::vector<double> state(dp_.data(), dp_.data() + dp_.size());
    state.insert(state.end(), gateY_.data(), gateY_.data() + gateY_.size());
    return state;
}

template <int D>
void SemiImplicitIntegrator<D>::restoreWindowStart(const std::vector<double>& state) {
    restoreState(state);
    if (ctx_.ranks) distributed_->rebuildPreconditioner();
}

template <int D>
Real SemiImplicitIntegrator<D>::limit(Index c) const {
    return waterLimit(ctx_.filling.openToAir[c], ctx_.config.liquid.cavitationPressure);
}

template <int D>
Real SemiImplicitIntegrator<D>::solveVelocities(const StepInputs& in, Real time) {
    NodeFields<D>& nodes = ctx_.nodes;
    // the predictor (the explicit step with the pressure of the step's start), and in the same
    // pass each component's response to a pressure force
    for (WallNode& w : wallNodes_) w.active = false;
    solveNodes(ctx_, in, [&](Index i, const NodeComponent (&component)[D], const Real (&vS1)[D], const Real (&vL1)[D],
                             const typename RoughWalls<D>::Contact* contact) {
        for (int a = 0; a < D; ++a) {
            const PhaseVelocities r = componentResponse(component[a], in.dt, nodes.porosity[i]);
            rS_[i * D + a] = r.solid;
            rL_[i * D + a] = r.liquid;
        }
        if (contact) recordWallNode(i, component, vS1, vL1, *contact);
    });
    // the predictor kept aside; correct() writes every node's velocities anew
    std::swap(predS_, nodes.velS);
    std::swap(predL_, nodes.velL);
    std::swap(incL_, nodes.velLIncrement);
    // the solve's share of the wall time, from one step in kTimedEvery: two clock reads a step
    // were a tenth of the 1D step's solve. Not the first step, whose one-off set-up (CG's
    // ordering) would count kTimedEvery times.
    const bool timed = stats_.steps % kTimedEvery == kTimedEvery - 1;
    const auto start = timed ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point();
    gateResponse(in);

    // the cells held at the step's start: no water (their pressure stays 0), or at their bound
    const CellWater<D>& water = ctx_.water;
    forAll(ctx_.grid.numCells(), [&](Index c) {
        const bool dry = !(water.weight[c] > 0);
        const bool atBound = !dry && water.pressure[c] <= limit(c) + boundTolerance(water.pressure[c]);
        held_[c] = dry || atBound;
        heldValue_[c] = atBound ? limit(c) - water.pressure[c] : 0.0;
    });
    if (ctx_.ranks) ctx_.ranks->shareCellValues(held_, heldValue_);  // the window's from their owners
    solves_ = 0;
    bool changed = true;
    while (changed) {
        assemble(in.dt);
        solve(in.dt, time);
        correct(in.dt);
        ++solves_;
        if (solves_ > kMaxSolves) break;  // the pass after the cap, with the set as it stands
        changed = updateHeldCells(in.dt);
        if (recheckWalls(in.dt)) {
            changed = true;
            stats_.wallPasses += 1;
        }
        // held rows become the identity's (and free ones leave it): a kept AMG hierarchy of the
        // pass before fits the new matrix badly
        if (changed && distributed_) distributed_->rebuildPreconditioner();
    }
    stats_.steps += 1;
    stats_.solves += solves_;
    // At the cap the set still moved: one more pass solved with it, so that no cell pulls its
    // neighbours with a suction its water cannot carry; a release it missed is a compression,
    // which updatePressure presses into the water
    if (solves_ > kMaxSolves) stats_.cappedSteps += 1;
    if (timed)
        stats_.seconds +=
            kTimedEvery * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return gateFlux(ctx_);
}

// A uniform gate moves its wet nodes' water at one vertical velocity, from the row's momentum
// (uniformGateVelocity): an impulse G_j on node j's liquid moves all of them by
// dt sum_j M_L,j r_L,j G_j / (sum M_L + dt R A_wet^2), and their flux by n_i times that. In the
// cells' system this is the rank-one term gamma a_L a_R^T, gamma = dt^2 / (sum M_L + dt R A_wet^2),
//   a_L,c = V_c sum_i n_i w_c,i,z,   a_R,c = V_c sum_j M_L,j r_L,j w_c,j,z
// over the cell's wet gate nodes; the node's own vertical response leaves B.
template <int D>
void SemiImplicitIntegrator<D>::gateResponse(const StepInputs& in) {
    gateGamma_ = 0;
    if (!in.gate.uniform) return;
    const NodeFields<D>& nodes = ctx_.nodes;
    const Grid<D>& grid = ctx_.grid;
    const Index gateRow = grid.nodeStride(D - 1);  // nodes below it are the gate's
    Real mass = 0, wet = 0;
    for (Index i : ctx_.masks.gateNodes)
        if (nodes.massL[i] > 0 && (!ctx_.ranks || ctx_.ranks->ownsNode(i))) {
            mass += nodes.massL[i];
            wet += nodeFootprint(grid, i);
        }
    mass = overRanks(mass);
    wet = overRanks(wet);
    if (!(mass > 0)) return;
    gateDenominator_ = mass + in.dt * in.gate.resistance * wet * wet;
    gateGamma_ = in.dt * in.dt / gateDenominator_;
    gateLeft_.setZero();
    gateRight_.setZero();
    for (Index c = 0; c < grid.cellStride(D - 1); ++c) {  // the bottom row of cells
        const Real V = ctx_.water.weight[c];
        grid.forEachNodeOfCell(c, [&](Index i, int corner) {
            if (i >= gateRow || !(nodes.massL[i] > 0)) return;
            const Real w = grid.divergenceWeight(c, corner, D - 1);
            gateLeft_[c] += V * nodes.porosity[i] * w;
            gateRight_[c] += V * nodes.massL[i] * rL_[i * D + D - 1] * w;
        });
    }
    const auto& gate = ctx_.masks.gateNodes;
    for (std::size_t j = 0; j < gate.size(); ++j) {
        const Index k = gate[j] * D + D - 1;
        gateWeight_[j] = nodes.massL[gate[j]] > 0 ? nodes.massL[gate[j]] * rL_[k] : 0.0;  // M_L,j r_L,j
        if (nodes.massL[gate[j]] > 0) rL_[k] = 0;
    }
}

// Column c of (S + dt^2 D B D^T), and b_c = -dt (D Phi*)_c less what the held cells' known
// increments contribute. Each column is written by its own cell, so the loop runs in parallel
// and the sums do not depend on the threads; the entry (c, c') sums over the shared nodes in
// ascending order in both columns, so the matrix is symmetric to the bit. The entries are summed
// in a local array by the neighbour's offset and written to the matrix once: summing in the
// matrix's own values, then scaling them by dt^2, made loads wait on the stores before them
// (a third of the 1D step's assembly; 642 -> 417 ns a step, docs/performance.md).
template <int D>
void SemiImplicitIntegrator<D>::assemble(Real dt) {
    const Grid<D>& grid = ctx_.grid;
    const CellWater<D>& water = ctx_.water;
    const NodeFields<D>& nodes = ctx_.nodes;
    const Real KL = ctx_.config.liquid.bulkModulus, dt2 = dt * dt;
    // the rank-one gate term's share from held cells, a_R . dp over them
    Real heldGate = 0;
    if (gateGamma_ > 0) {
        for (Index c = 0; c < grid.cellStride(D - 1); ++c)
            if (held_[c] && owns(c)) heldGate += gateRight_[c] * heldValue_[c];
        heldGate = overRanks(heldGate);
    }
    matrixSent_ = false;
    forAll(grid.numCells(), [&](Index c) {
        Real entry[kStencil] = {};  // by the neighbour's offset code
        const int centre[D] = {};
        const int diagonal = PressureSystem::offsetCode(centre, D);
        if (held_[c]) {
            // an identity row with a zero right-hand side, its known increment written after the
            // solve: a row in Pa among rows in m3 would dominate CG's stopping test
            entry[diagonal] = 1;
            rhs_[c] = 0;
            writeColumn(c, entry);
            return;
        }
        const Real V = water.weight[c];
        Real divergence = 0, heldSum = 0;
        grid.forEachNodeOfCell(c, [&](Index i, int corner) {
            const Real n = nodes.porosity[i];
            for (int a = 0; a < D; ++a) {
                const Index k = i * D + a;
                const Real Dc = V * grid.divergenceWeight(c, corner, a);
                divergence += Dc * ((1 - n) * predS_[k] + n * predL_[k]);
                const Real beta = dt2 * ((1 - n) * rS_[k] + n * rL_[k]);
                if (beta == 0) continue;
                grid.forEachCellOfNode(i, [&](Index c2, int corner2) {
                    if (!(water.weight[c2] > 0)) return;  // a dry cell: no pressure, no force
                    const Real coupling = beta * (Dc * (water.weight[c2] * grid.divergenceWeight(c2, corner2, a)));
                    if (held_[c2]) { heldSum += coupling * heldValue_[c2]; return; }
                    entry[neighbourCode(corner, corner2)] += coupling;
                });
            }
        });
        // the water's storage, S_c = V_c n_c / K_L; a cavity first takes up a compression:
        // S_c dp_c + dt (D Phi)_c = -V_c n_c cavity_c (physics/Cavitation.hpp)
        entry[diagonal] += V * water.porosity[c] / KL;
        writeColumn(c, entry);
        rhs_[c] = -dt * divergence - heldSum - V * water.porosity[c] * water.cavity[c] -
                  gateGamma_ * gateLeft_[c] * heldGate;
    });
}

// The offset code (PressureSystem::offsetCode) of the cell whose `corner2` is the node that is
// the `corner` of this one
template <int D>
int SemiImplicitIntegrator<D>::neighbourCode(int corner, int corner2) {
    int code = 0;
    for (int d = D - 1; d >= 0; --d) code = code * 3 + ((corner >> d) & 1) - ((corner2 >> d) & 1) + 1;
    return code;
}

// Column c's values from its entries by offset code; each stored value has one code
template <int D>
void SemiImplicitIntegrator<D>::writeColumn(Index c, const Real* entry) {
    Real* value = system_.values(c);
    for (int code = 0; code < kStencil; ++code) {
        const int slot = system_.slot(c, code);
        if (slot >= 0) value[slot] = entry[code];
    }
}

template <int D>
void SemiImplicitIntegrator<D>::solve(Real dt, Real time) {
    auto message = [&](const std::string& what) {
        std::ostringstream s;
        s << "numerical failure at t = " << time << " s: the semi-implicit step's pressure solve "
          << what << " (" << system_.cells() << " cells, " << stats_.solver
          << ", dt = " << dt << " s); a smaller time.courant, or time.scheme = \"explicit\", may get past it";
        return s.str();
    };
    auto fail = [&](const std::string& what) { throw Error(message(what)); };
    // one rank: the system's own solver; over ranks: hypre's, which throws its own failure
    auto solveSystem = [&](const Eigen::VectorXd& b, Eigen::VectorXd& x) {
        if (distributed_) {
            try {
                stats_.iterations += solveDistributed(b, x);
            } catch (const SharedError& e) {  // every rank's solve failed alike: said once
                throw SharedError(message(std::string("over the ranks failed: ") + e.what()));
            }
            return true;
        }
        const bool ok = system_.solve(b, x);
        stats_.iterations += system_.iterations();
        return ok;
    };
    if (!distributed_ && !system_.factorize()) fail("could not factorise the matrix (not positive definite)");
    // CG starts from the last solution; a held cell's row is the identity with a zero right-hand side
    for (Index c = 0; c < ctx_.grid.numCells(); ++c)
        if (held_[c]) dp_[c] = 0;
    if (!solveSystem(rhs_, dp_)) fail("did not converge");
    if (gateGamma_ > 0) {
        // Sherman-Morrison: (A + gamma a_L a_R^T)^-1 b = x - gamma (a_R . x) / (1 + gamma a_R . y) y, A y = a_L
        Eigen::VectorXd& left = gateSolve_;
        left = gateLeft_;
        for (Index c = 0; c < ctx_.grid.cellStride(D - 1); ++c)
            if (held_[c]) left[c] = 0;
        Eigen::VectorXd& y = gateY_;
        for (Index c = 0; c < ctx_.grid.numCells(); ++c)
            if (held_[c]) y[c] = 0;
        if (!solveSystem(left, y)) fail("did not converge (the gate's term)");
        Real ax = 0, ay = 0;
        for (Index c = 0; c < ctx_.grid.cellStride(D - 1); ++c)
            if (!held_[c] && owns(c)) { ax += gateRight_[c] * dp_[c]; ay += gateRight_[c] * y[c]; }
        ax = overRanks(ax);
        ay = overRanks(ay);
        dp_ -= (gateGamma_ * ax / (1 + gateGamma_ * ay)) * y;
    }
    for (Index c = 0; c < ctx_.grid.numCells(); ++c)
        if (held_[c]) dp_[c] = heldValue_[c];
    // the corrector's nodes read the increment of the window's cells: their owners' (a rank's
    // own y and dp elsewhere in its window are not solved)
    if (ctx_.ranks) ctx_.ranks->shareCellValues(dp_);
    for (Index c = 0; c < ctx_.grid.numCells(); ++c)
        if (owns(c) && !std::isfinite(dp_[c])) {
            std::ostringstream what;
            what << "gave a non-finite pressure in cell " << c << " (centre at elevation "
                 << ctx_.grid.cellCentre(ctx_.grid.cellCoords(c)[D - 1]) << " m)";
            fail(what.str());
        }
}

// v = v* + dt r G, G = D^T dp the increment's force on the mixture at each node (the pressure
// force of computeForces with dp for p).
template <int D>
void SemiImplicitIntegrator<D>::correct(Real dt) {
    const Grid<D>& grid = ctx_.grid;
    const CellWater<D>& water = ctx_.water;
    NodeFields<D>& nodes = ctx_.nodes;
    forAll(grid.numNodes(), [&](Index i) {
        Real G[D] = {};
        grid.forEachCellOfNode(i, [&](Index c, int corner) {
            const Real pV = dp_[c] * water.weight[c];
            if (pV == 0) return;
            for (int a = 0; a < D; ++a) G[a] += pV * grid.divergenceWeight(c, corner, a);
        });
        Real w2 = 0;
        for (int a = 0; a < D; ++a) {
            const Index k = i * D + a;
            force_[k] = G[a];
            nodes.velS[k] = predS_[k] + dt * rS_[k] * G[a];
            const Real dvL = dt * rL_[k] * G[a];
            nodes.velL[k] = predL_[k] + dvL;
            nodes.velLIncrement[k] = incL_[k] + dvL;
            w2 += (nodes.velL[k] - nodes.velS[k]) * (nodes.velL[k] - nodes.velS[k]);
        }
        nodes.relSpeed[i] = (nodes.massS[i] > 0 && nodes.massL[i] > 0) ? std::sqrt(w2) : 0.0;
    });
    if (!(gateGamma_ > 0)) return;
    // the uniform gate: one velocity increment for its wet nodes, from the row's impulse
    const auto& gate = ctx_.masks.gateNodes;
    Real impulse = 0;
    for (std::size_t j = 0; j < gate.size(); ++j)
        if (nodes.massL[gate[j]] > 0 && (!ctx_.ranks || ctx_.ranks->ownsNode(gate[j])))
            impulse += gateWeight_[j] * force_[gate[j] * D + D - 1];
    impulse = overRanks(impulse);
    const Real dv = dt * impulse / gateDenominator_;
    for (Index i : gate)
        if (nodes.massL[i] > 0) {
            const Index k = i * D + D - 1;
            nodes.velL[k] = predL_[k] + dv;
            nodes.velLIncrement[k] = incL_[k] + dv;
        }
}

/// The cell's mean divergence of the mixture's flux, as updatePressure takes it.
template <int D>
Real SemiImplicitIntegrator<D>::cellDivergence(Index c) const {
    const NodeFields<D>& nodes = ctx_.nodes;
    Real div = 0;
    ctx_.grid.forEachNodeOfCell(c, [&](Index i, int corner) {
        const Real n = nodes.porosity[i];
        for (int a = 0; a < D; ++a)
            div += ctx_.grid.divergenceWeight(c, corner, a) * ((1 - n) * nodes.velS[i * D + a] + n * nodes.velL[i * D + a]);
    });
    return div;
}

// The active set: a free cell the solve took below its bound is held at it; a held cell whose
// water the velocities would press above its bound (its cavity closed first) is let go. Returns
// whether the set changed. Serial: a few thousand cells' comparisons, in a fixed order.
template <int D>
bool SemiImplicitIntegrator<D>::updateHeldCells(Real dt) {
    const CellWater<D>& water = ctx_.water;
    const Real KL = ctx_.config.liquid.bulkModulus;
    bool changed = false;
    for (Index c = 0; c < ctx_.grid.numCells(); ++c) {
        if (!(water.weight[c] > 0)) continue;
        const Real bound = limit(c), p = water.pressure[c];
        if (!held_[c]) {
            if (p + dp_[c] < bound - boundTolerance(p)) {
                held_[c] = 1;
                heldValue_[c] = bound - p;
                changed = changed || owns(c);
            }
            continue;
        }
        const CavitatingWater pressed =
            pressWater({p, water.cavity[c]}, -KL / water.porosity[c] * dt * cellDivergence(c), KL, bound);
        if (pressed.pressure > bound + boundTolerance(p)) {
            held_[c] = 0;
            changed = changed || owns(c);
        }
    }
    if (!ctx_.ranks) return changed;
    // over ranks: the window's cells as their owners decided, and another pass if any rank's set moved
    ctx_.ranks->shareCellValues(held_, heldValue_);
    return ctx_.ranks->comm().any(changed);
}

// The predictor's wall node, kept for recheckWalls. Its components come with a stuck one held:
// the wall's hold is taken off again (a boundary's, solidFixed, stays).
template <int D>
void SemiImplicitIntegrator<D>::recordWallNode(Index i, const NodeComponent (&c)[D], const Real (&vS1)[D],
                                               const Real (&vL1)[D], const typename RoughWalls<D>::Contact& contact) {
    WallNode& w = wallNodes_[wallSlot_[i]];
    w.active = true;
    w.stuck = contact.stuck;
    w.limit = contact.limit;
    for (int a = 0; a < D; ++a) {
        w.free[a] = c[a];
        w.free[a].solidHeld = ctx_.masks.solidFixed[i * D + a];
        w.vS1[a] = vS1[a];
        w.vL1[a] = vL1[a];
        w.reaction[a] = contact.reaction[a];
    }
}

// The drag-free predictors of a wall node with the increment's force G on the mixture.
template <int D>
void SemiImplicitIntegrator<D>::trialWithIncrement(const WallNode& w, Real dt, Real (&vS1)[D], Real (&vL1)[D]) const {
    const Index i = w.node;
    const Real n = ctx_.nodes.porosity[i], mS = ctx_.nodes.massS[i], mL = ctx_.nodes.massL[i];
    for (int a = 0; a < D; ++a) {
        const Real G = force_[i * D + a];
        vS1[a] = w.vS1[a] + dt * (1 - n) * G / mS;
        vL1[a] = mL > 0 ? w.vL1[a] + dt * n * G / mL : 0.0;
    }
}

// Each wall node's decision taken again with the increment's force G on the mixture in its trial
// (its solid's share (1 - n) G, its water's n G, as componentResponse shares it). Where one
// overturns on any rank, every wall node's predictor and response are redone with the decision
// and the aim the increment gives, and the pass is solved again. Returns whether it must be.
template <int D>
bool SemiImplicitIntegrator<D>::recheckWalls(Real dt) {
    if (wallNodes_.empty()) return false;
    const RoughWalls<D>& walls = ctx_.masks.roughWalls;
    NodeFields<D>& nodes = ctx_.nodes;
    bool overturned = false;
    for (const WallNode& w : wallNodes_) {
        if (!w.active) continue;
        Real vS1[D], vL1[D], R[D];
        trialWithIncrement(w, dt, vS1, vL1);
        const bool stuck = walls.sticks(w.node, dt, w.limit, w.free, vS1, vL1, R);
        Real along = 0;
        for (int a = 0; a < D; ++a) along += R[a] * w.reaction[a];
        const bool flips = stuck != w.stuck || (!stuck && along < 0);
        if (flips && (!ctx_.ranks || ctx_.ranks->ownsNode(w.node))) overturned = true;
    }
    if (ctx_.ranks) overturned = ctx_.ranks->comm().any(overturned);
    if (!overturned) return false;
    for (WallNode& w : wallNodes_) {
        if (!w.active) continue;
        const Index i = w.node;
        Real vS1[D], vL1[D];
        trialWithIncrement(w, dt, vS1, vL1);
        w.stuck = walls.sticks(i, dt, w.limit, w.free, vS1, vL1, w.reaction);
        // the predictor without the increment (correct() adds it through the response), with the
        // decision and the friction's aim the increment gave
        NodeComponent c[D];
        PhaseVelocities v[D];
        for (int a = 0; a < D; ++a) c[a] = w.free[a];
        walls.velocities(i, dt, w.limit, w.stuck, w.reaction, c, w.vS1, w.vL1, v);
        const Real mL = nodes.massL[i];
        for (int a = 0; a < D; ++a) {
            if (!walls.tangential(i, a, w.free[a])) continue;  // the normal and the gate as the predictor left them
            const Index k = i * D + a;
            predS_[k] = v[a].solid;
            predL_[k] = v[a].liquid;
            incL_[k] = v[a].liquid - (mL > 0 ? nodes.momL[k] / mL : 0.0);
            const PhaseVelocities r = componentResponse(c[a], dt, nodes.porosity[i]);
            rS_[k] = r.solid;
            rL_[k] = r.liquid;
        }
    }
    return true;
}

template class SemiImplicitIntegrator<1>;
template class SemiImplicitIntegrator<2>;
template class SemiImplicitIntegrator<3>;

}  // namespace qs
