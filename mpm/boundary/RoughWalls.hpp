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
// water stays smooth on the wall. The decision is the predictor's: the semi-implicit step's
// pressure increment moves a stuck component as a held one (componentResponse sees it held) and
// a slipping one with its friction fixed. The increment does not change N: its normal force is
// the water's, which the wall takes.
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

    /// Node i's velocities on the wall. grainPush[a] = M_S v_S0 / dt + F_S - F_p,S (N), the grains'
    /// push along each axis; c, vS1, vL1 the components and drag-free predictors as solveNodes has
    /// them. A component that sticks comes back held (c[a].solidHeld), for the semi-implicit
    /// step's response.
    void solve(Index i, Real dt, const Real (&grainPush)[D], NodeComponent (&c)[D], const Real (&vS1)[D],
               const Real (&vL1)[D], PhaseVelocities (&v)[D]) const {
        Real N = 0;
        bool tangential[D] = {};
        for (int a = 0; a < D; ++a) {
            const int s = side[i * D + a];
            if (s != 0) N += std::max(Real(0), s * grainPush[a]);
            tangential[a] = s == 0 && !c[a].solidHeld;
        }
        const Real mS = c[0].massS;
        // the stuck solution, and the reaction it needs
        Real R[D] = {}, R2 = 0;
        PhaseVelocities stuck[D];
        for (int a = 0; a < D; ++a) {
            if (!tangential[a]) continue;
            NodeComponent held = c[a];
            held.solidHeld = true;
            stuck[a] = solveComponent(held, dt, vS1[a], vL1[a]);
            R[a] = -(mS * vS1[a] / dt + c[a].drag * stuck[a].liquid);
            R2 += R[a] * R[a];
        }
        const Real limit = friction * N;
        const bool sticks = mS > 0 && R2 <= limit * limit;
        const Real scale = R2 > 0 ? limit / std::sqrt(R2) : 0.0;
        for (int a = 0; a < D; ++a) {
            if (tangential[a] && sticks) {
                c[a].solidHeld = true;
                v[a] = stuck[a];
            } else if (tangential[a] && mS > 0) {
                v[a] = solveComponent(c[a], dt, vS1[a] + dt * scale * R[a] / mS, vL1[a]);
            } else {
                v[a] = solveComponent(c[a], dt, vS1[a], vL1[a]);
            }
        }
    }
};

}  // namespace qs
