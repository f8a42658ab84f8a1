#pragma once
// Rough lateral walls: Coulomb friction between the sand and the wall (physics.md section 2,
// boundaries), column.wall_friction_angle = delta, mu = tan(delta). A smooth wall holds the
// grains' normal velocity only, so sand against it is held from one side; a real wall holds it by
// friction too, which is what carries part of a column's weight in a silo (Janssen) and what a
// pipe along the wall has to overcome.
//
// At a wall node the grains press on the wall with N, the normal reaction the held normal
// component needs, less the pore pressure's share (the water presses on the wall too, but only
// grain contacts rub: the effective stress). N is read from the node's own solve, as Bardenhagen
// et al. (2000) read contact forces in MPM: N = sum over the node's walls of
//   max(0, s (M_S v_S0 / dt + F_S - F_p,S)),  s = +1 on the wall at an axis' upper end, -1 at its lower,
// F_S the grains' force of the step (stress, gravity, drag's share aside, the pore pressure's
// F_p,S taken off: solver/PressureForce.hpp). The tangential components then
//   - stick (v_S,t = 0) if the reaction that needs, R_t = -(M_S v_S,t* / dt + Q v_L,t), the drag of
//     the water moving past held grains included, is within |R_t| <= mu N;
//   - slip otherwise, with the friction force mu N R_t / |R_t| (against the slip) added to the
//     grains' predictor, the pair then solved with drag as anywhere else.
// The tangential components are taken together (in 3D a wall's two, at a corner the vertical
// with both walls' N), so the friction is isotropic in the wall's plane. Only the grains rub: the
// water stays smooth on the wall. The semi-implicit step decides in its predictor, and takes the
// decision again after each pressure solve with the increment's force in the trial
// (SemiImplicitIntegrator::recheckWalls): a stuck component responds to the increment as a held
// one, a slipping one with its friction fixed, until a decision overturns. The increment does
// not change N: its normal force is the water's, which the wall takes.
// In axisymmetry the outer wall (r = R) is rough and the axis, a line of symmetry, is not.
#include <cmath>
#include <vector>

#include "case/CaseConfig.hpp"
#include "core/Constants.hpp"
#include "grid/Grid.hpp"
#include "solver/NodeComponent.hpp"

namespace qs {

template <int D>
struct RoughWalls {
    Real friction = 0;               ///< -, mu = tan(delta); 0: smooth walls (nothing below runs)
    std::vector<signed char> side;   ///< [node][axis]: +1 a wall at the axis' upper end, -1 at its lower, 0 none
    std::vector<char> atWall;        ///< [node]: on a rough wall

    void build(const Grid<D>& grid, const CaseConfig& config) {
        friction = std::tan(config.column.wallFrictionAngle * kPi / 180);
        side.clear();
        atWall.clear();
        if (!(friction > 0) || D == 1) return;
        const Index nn = grid.numNodes();
        side.assign(nn * D, 0);
        atWall.assign(nn, 0);
        for (Index i = 0; i < nn; ++i) {
            const IVec<D> n = grid.nodeCoords(i);
            for (int d = 0; d < D - 1; ++d) {
                const bool axis = grid.axisymmetric() && d == 0;
                if (n[d] == 0 && !axis) side[i * D + d] = -1;
                if (n[d] == grid.nodes(d) - 1) side[i * D + d] = 1;
                if (side[i * D + d] != 0) atWall[i] = 1;
            }
        }
    }

    bool rough(Index i) const { return !atWall.empty() && atWall[i]; }

    /// The grains' normal push on node i's walls: N = sum over them of max(0, s push_a), from
    /// grainPush[a] = M_S v_S0 / dt + F_S - F_p,S (N) along each axis. Friction holds up to mu N.
    Real limit(Index i, const Real (&grainPush)[D]) const {
        Real N = 0;
        for (int a = 0; a < D; ++a) {
            const int s = side[i * D + a];
            if (s != 0) N += std::max(Real(0), s * grainPush[a]);
        }
        return friction * N;
    }

    /// A component the friction acts on: along the wall, the grains' not held by another boundary.
    bool tangential(Index i, int a, const NodeComponent& c) const { return side[i * D + a] == 0 && !c.solidHeld; }

    /// Whether node i's grains stick under the friction limit mu N (N), and R, the tangential
    /// reaction holding them still would need: R_a = -(M_S v_S1,a / dt + Q v_L,a), v_L,a the water's
    /// velocity with the grains held (its drag on them included). c as nodeComponent gives them
    /// (the grains not yet held by the wall), vS1, vL1 the drag-free predictors.
    bool sticks(Index i, Real dt, Real limit, const NodeComponent (&c)[D], const Real (&vS1)[D],
                const Real (&vL1)[D], Real (&R)[D]) const {
        Real R2 = 0;
        for (int a = 0; a < D; ++a) {
            R[a] = 0;
            if (!tangential(i, a, c[a])) continue;
            NodeComponent held = c[a];
            held.solidHeld = true;
            R[a] = -(c[a].massS * vS1[a] / dt + c[a].drag * solveComponent(held, dt, vS1[a], vL1[a]).liquid);
            R2 += R[a] * R[a];
        }
        return c[0].massS > 0 && R2 <= limit * limit;
    }

    /// Node i's velocities with that decision: a stuck component held (c[a].solidHeld set, so
    /// that the semi-implicit step's response sees it held); a slipping one with the friction
    /// mu N R / |R| on the grains' predictor. The friction opposes the slip: the tangential
    /// components share one mass, drag and water, so the slip comes out along R (an implicit
    /// Coulomb law's radial return) and is never reversed by it, as |R| > mu N.
    void velocities(Index i, Real dt, Real limit, bool stuck, const Real (&R)[D], NodeComponent (&c)[D],
                    const Real (&vS1)[D], const Real (&vL1)[D], PhaseVelocities (&v)[D]) const {
        Real R2 = 0;
        for (int a = 0; a < D; ++a) R2 += R[a] * R[a];
        const Real mS = c[0].massS, scale = R2 > 0 && mS > 0 ? limit / std::sqrt(R2) : 0.0;
        for (int a = 0; a < D; ++a) {
            const bool along = tangential(i, a, c[a]);
            if (along && stuck) c[a].solidHeld = true;
            const Real friction = along && !stuck ? dt * scale * R[a] / mS : 0.0;
            v[a] = solveComponent(c[a], dt, vS1[a] + friction, vL1[a]);
        }
    }

    /// Node i's velocities on the wall (grainPush, c, vS1, vL1 as above). Returns mu N, whether
    /// the grains stick, and the holding reaction R.
    struct Contact { Real limit = 0; bool stuck = false; Real reaction[D] = {}; };
    Contact solve(Index i, Real dt, const Real (&grainPush)[D], NodeComponent (&c)[D], const Real (&vS1)[D],
                  const Real (&vL1)[D], PhaseVelocities (&v)[D]) const {
        Contact contact;
        contact.limit = limit(i, grainPush);
        contact.stuck = sticks(i, dt, contact.limit, c, vS1, vL1, contact.reaction);
        velocities(i, dt, contact.limit, contact.stuck, contact.reaction, c, vS1, vL1, v);
        return contact;
    }
};

}  // namespace qs
