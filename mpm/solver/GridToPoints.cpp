// Phases 5 and 6 of the double-point step: APIC (solid) and FLIP (liquid) velocities, positions, strains and the
// constitutive update of the points, then the pore-pressure increment of every cell
// (physics.md section 2).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <type_traits>

#include "solver/DoublePointSolver.hpp"
#include "materials/ConstitutiveModel.hpp"
#include "materials/StressTensor.hpp"
#include "physics/Cavitation.hpp"
#include "solver/Parallel.hpp"
#include "solver/PointStencil.hpp"

namespace qs {

// ---------------------------------------------------------------------------------------------
// 5 grid to points: velocities (solid APIC, liquid FLIP), positions, strains, constitutive update
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::gridToPoints() {
    const Real dt = dt_;
    const Real picShare = config_.liquid.picShareFor(dt);
    Real lowest[D] = {}, extent[D];  // points stay inside the grid, axis by axis
    for (int d = 0; d < D; ++d) extent[d] = grid_.cells(d) * grid_.h();
    const bool axisymmetric = grid_.axisymmetric();
    const bool gimp = config_.grid.shapeFunctions == ShapeFunctionKind::Gimp;
    // in axisymmetry off the axis itself, where the hoop terms divide by r (a point reaches the
    // axis only when something pushes it there: v_r vanishes on the axis)
    if (axisymmetric) lowest[0] = 1e-6 * grid_.h();
    // the sand stays above the filter: a uGIMP point on the filter still takes a share of the
    // velocity of the node row above it (uGIMP does not interpolate at nodes), and a settling bed
    // would carry its lowest points up to lp below the filter plane, into the chamber's cells
    Real sandLowest[D];
    for (int d = 0; d < D; ++d) sandLowest[d] = lowest[d];
    sandLowest[D - 1] = sandFloor_;
    // Starved nodes. A node beside a cell without sand (a lone point, a sand surface) that a point
    // has just crossed away from holds only the tail of its hat: a sliver of solid mass, N m_p. The
    // point's stress still pushes on it with the full slope 1/h, so its velocity is that force over
    // the sliver, and the point's strain took that velocity with the full slope too: the explicit
    // update of a vanishing mass. S_i = sum_p m_p (h |grad N_ip|)^2 (nodes_.slopeMass, PointsToGrid.cpp)
    // is the points' mass weighted by their slopes; C = dt c_fast / h is the step's. A node with
    // less solid mass than starvedShare S_i = (C^2 / 2) S_i is starved: its share of the velocity
    // gradient is taken with weight w_i = m_i / (starvedShare S_i), and the rest, 1 - w_i, with
    // the velocity of the nodes that are fed, v_fed = sum N w v / sum N w, as if the node moved
    // with the sand around it. The point's strain then never reads the sliver's velocity, whatever
    // the skeleton's stiffness (a first version completed the share with the point's velocity,
    // sum N_i v_i, which still holds the sliver: stable only for c_sk < 0.96 c_fast at C = 0.4).
    // Continuous in m_i (a hard cut moved the columns of a 2D bed apart); equal at a side wall,
    // where m_i and S_i both halve; a held component (a wall, the filter) is a boundary value, not
    // a sliver, and keeps its weight. A uniform velocity stays strain-free; in 2D and 3D a rigid
    // rotation is not, at a starved point. Inside the sand m_i / S_i is 0.4 to 0.5 (linear hats)
    // and uGIMP's tails keep it above lp / h, far above C^2 / 2 (test_StarvedNodes.cpp). The
    // point's velocity, sum N_i v_i, is the nodes' momentum and stays as it is. (The Deltares
    // column resettling at t = 51.88 s: a lone point 2.4e-8 cells past node row 10 read -563 m/s
    // at the node above, a strain of -1.21 in one step, a porosity of 3.98.)
    // The solid's update, with the front diffusion's sums only on steps that have any: with no
    // diffusion node no point diffuses (its weights sum to 1, so some node with N > 0 is not one)
    // The front diffusion's D at a point of cell c with the solid fraction's gradient there: in
    // full at a front, fading as (h |grad phi| / s)^2 where the porosity changes by less than the
    // material's threshold s over a cell (physics/FrontDiffusion.hpp)
    const Real h2 = grid_.h() * grid_.h();
    auto frontDiffusivity = [&](Index c, const Real* gradPhi) {
        const Real inverse2 = sand_.inverseThreshold2[c];
        if (inverse2 == 0) return sand_.diffusivity[c];
        Real g2 = 0;
        for (int d = 0; d < D; ++d) g2 += gradPhi[d] * gradPhi[d];
        return sand_.diffusivity[c] * std::min(Real(1), h2 * g2 * inverse2);
    };
    auto solidPoint = [&](Index p, auto withDiffusion, auto linearShapes) {
        constexpr bool diffusion = decltype(withDiffusion)::value;
        constexpr bool linear = decltype(linearShapes)::value;
        Real vNew[D] = {}, L[D][D] = {}, gridPorosity = 0, gradPhi[D] = {};
        bool diffuses = diffusion, held[D] = {}, anyStarved = false;
        forEachNodeOfPoint<linear>(grid_, solid_, p, [&](Index i, Real N, const Real* gradN) {
            for (int d = 0; d < D; ++d) {
                const Real v = nodes_.velS[i * D + d];
                vNew[d] += N * v;
                for (int e = 0; e < D; ++e) L[d][e] += v * gradN[e];
                anyStarved = anyStarved || nodes_.fedWeight[i * D + d] < 1;
                if constexpr (diffusion) gradPhi[d] -= gradN[d] * nodes_.sandPorosity[i];
            }
            gridPorosity += N * nodes_.sandPorosity[i];
            if constexpr (diffusion) {
                if (N > 0 && !nodes_.diffusionNode[i]) diffuses = false;
                for (int d = 0; d < D - 1; ++d) held[d] = held[d] || (N > 0 && masks_.solidFixed[i * D + d]);
            }
        });
        if (anyStarved) {
            // a second pass, at the sand's edge only. Per component: sum (1 - w_i) grad N_i v_i,
            // sum (1 - w_i) grad N_i, sum N_i w_i v_i, sum N_i w_i
            Real starvedL[D][D] = {}, starvedSlope[D][D] = {}, fedV[D] = {}, fedN[D] = {};
            forEachNodeOfPoint<linear>(grid_, solid_, p, [&](Index i, Real N, const Real* gradN) {
                for (int d = 0; d < D; ++d) {
                    const Real v = nodes_.velS[i * D + d], w = nodes_.fedWeight[i * D + d];
                    fedV[d] += N * w * v;
                    fedN[d] += N * w;
                    for (int e = 0; e < D; ++e) {
                        starvedSlope[d][e] += (1 - w) * gradN[e];
                        starvedL[d][e] += (1 - w) * v * gradN[e];
                    }
                }
            });
            for (int d = 0; d < D; ++d) {
                // a point whose nodes are all starved (a lone grain in water) keeps its own velocity
                const Real vFed = fedN[d] > 1e-12 ? fedV[d] / fedN[d] : vNew[d];
                for (int e = 0; e < D; ++e) L[d][e] -= starvedL[d][e] - vFed * starvedSlope[d][e];
            }
        }
        const Index cell = solid_.shape.cell[p];
        const Real radius = solid_.x[p * D];  // where the shape functions were taken
        for (int d = 0; d < D; ++d) {
            // APIC: the point takes the grid's velocity and its gradient (next to it, C = L), so
            // that its next transfer hands back the grid's linear field instead of smearing it (PIC)
            // or keeping velocities of its own the grid cannot see (FLIP: in sand without effective
            // stress those grew from round-off at 3 /s into an odd-even lateral mode in 2D and 3D)
            solid_.v[p * D + d] = vNew[d];
            // the front diffusion moves the point; it is not part of its velocity. Next to a
            // wall it does not move it towards or away from the wall: no flux through the wall,
            // whatever the field beside it (the gradient there is one-sided)
            const Real w = diffuses && !held[d] ? -frontDiffusivity(cell, gradPhi) * gradPhi[d] / std::max(Real(1e-3), 1 - gridPorosity) : 0;
            solid_.x[p * D + d] = std::clamp(solid_.x[p * D + d] + dt * (vNew[d] + w), sandLowest[d], extent[d]);
        }
        for (int d = 0; d < D; ++d)
            for (int e = 0; e < D; ++e) solid_.velocityGradient[p * D * D + d * D + e] = L[d][e];  // APIC's C
        Real dEps[6] = {};
        for (int d = 0; d < D; ++d)
            for (int e = d; e < D; ++e)
                dEps[voigt(axis3<D>(d), axis3<D>(e))] = 0.5 * dt * (L[d][e] + L[e][d]);
        // axisymmetry: the hoop strain v_r / r at the point's own radius (Voigt yy is theta)
        if (axisymmetric) dEps[1] = dt * vNew[0] / radius;
        const Real dVol = dEps[0] + dEps[1] + dEps[2];
        const auto& mat = materials_[solid_.material[p]];
        Real* s = &solid_.stress[p * 6];
        Real& n = solid_.porosity[p];
        const bool fluidised = sand_.fluidised[cell];
        const bool resettling = !fluidised && solid_.state[p] == kFluidisedState;
        if (resettling) {
            // a skeleton again, restarting from zero effective stress (no viscous stress left)
            solid_.state[p] = kSolidState;
            for (int k = 0; k < 6; ++k) s[k] = 0;
        }
        // the sand's porosity where the point is, from the grid (at the sand's top, the cell's)
        if (sand_.surface[cell]) gridPorosity = sand_.porosity[cell];
        gridPorosity = std::clamp(gridPorosity, Real(1e-3), Real(0.99));
        // looser than the loosest packing the grains form no skeleton (no effective stress); a
        // skeleton that carries stress loses it only beyond the switch's hysteresis band, so that
        // the grid's sampling noise about n_max does not unload a consolidated sediment
        const Real looseLimit = mat.maxPorosity + (isStressFree(s) ? 0 : stateRule_.hysteresis);
        const bool noSkeleton = !fluidised && gridPorosity > looseLimit;
        if (fluidised || resettling || diffuses || noSkeleton) {
            // fluidised material, material resettling from it, sand without a skeleton and
            // stress-free sand that the front diffusion moves take their porosity from the grid,
            // where the points' spacing shows, and a volume to match: their own mass balance
            // drifts once the skeleton carries no stress (physics/LiquidStateRule.hpp)
            n = gridPorosity;
            solid_.volume[p] = solid_.mass[p] / (mat.grainDensity * (1 - n));
        }
        if (fluidised) {
            // no effective stress, only the suspension's viscous stress
            solid_.state[p] = kFluidisedState;
            mat.suspension.stress(n, dEps, dt, s);
            solid_.stressReturn[p] = -1;
            return;
        }
        n = 1 - (1 - n) / (1 + dVol);  // solid mass balance, grains incompressible
        solid_.volume[p] *= 1 + dVol;
        // no skeleton denser than its densest packing: grains in contact at n_min cannot close up
        // further (the grid's flow can push a skeleton there that no elastic law stiffens against:
        // sand a pipe throws up converges into a column at the wall, docs/piping.md). The volume
        // follows, the mass is the point's own
        if (n < mat.minPorosity) {
            n = mat.minPorosity;
            solid_.volume[p] = solid_.mass[p] / (mat.grainDensity * (1 - n));
        }
        const StressPoint point{dEps, s, solid_.internal.data() + p * solid_.internalCount, dt};
        solid_.stressReturn[p] = static_cast<int>(mat.model->update(point));
        // a resettling bed settles onto its sediment without stress until it reaches n_max,
        // and its skeleton takes stress from there on
        if (noSkeleton)
            for (int k = 0; k < 6; ++k) s[k] = 0;
    };
    // Over MPI ranks a ghost sand point (one another rank owns: its cell at the step's start is
    // not this rank's) is not updated: nothing reads it after this phase before the ghosts are
    // dropped (the pressure is the nodes', the chamber and the weir read the water), and its owner
    // updates it. The ghost water moves, for the chamber's injection.
    const Index solidCount = static_cast<Index>(solid_.size());
    const std::vector<Index>& startCell = solid_.shape.cell;
    withStencilKind(!gimp, [&](auto linearShapes) {
        if (nodes_.anyDiffusion)
            forAll(solidCount, [&](Index p) { if (ownsCell(startCell[p])) solidPoint(p, std::true_type{}, linearShapes); });
        else
            forAll(solidCount, [&](Index p) { if (ownsCell(startCell[p])) solidPoint(p, std::false_type{}, linearShapes); });
    });

    // The liquid's update, with the front diffusion's sums only on steps that have any (most
    // steps of most runs have no stress-free sand)
    auto liquidPoint = [&](Index p, auto withDiffusion, auto linearShapes) {
        constexpr bool diffusion = decltype(withDiffusion)::value;
        constexpr bool linear = decltype(linearShapes)::value;
        Real dv[D] = {}, vNew[D] = {}, div = 0, gradPhi[D] = {}, sand = 0, mixture = 0;
        bool diffuses = diffusion, held[D] = {};
        forEachNodeOfPoint<linear>(grid_, liquid_, p, [&](Index i, Real N, const Real* gradN) {
            for (int d = 0; d < D; ++d) {
                const Real v = nodes_.velL[i * D + d];
                dv[d] += N * nodes_.velLIncrement[i * D + d];
                vNew[d] += N * v;
                div += v * gradN[d];
                if constexpr (diffusion) gradPhi[d] -= gradN[d] * nodes_.sandPorosity[i];
            }
            if constexpr (diffusion) {
                sand += N * nodes_.sandPorosity[i];
                mixture += N * nodes_.porosity[i];
                if (N > 0 && !nodes_.diffusionNode[i]) diffuses = false;
                for (int d = 0; d < D - 1; ++d) held[d] = held[d] || (N > 0 && masks_.liquidFixed[i * D + d]);
            }
        });
        const Real k = diffuses ? frontDiffusivity(liquid_.shape.cell[p], gradPhi) / std::max(Real(1e-3), 1 - sand) : 0;
        if (axisymmetric) div += vNew[0] / liquid_.x[p * D];  // the hoop strain rate v_r / r
        for (int d = 0; d < D; ++d) {
            liquid_.v[p * D + d] += dv[d];  // FLIP
            // with liquid.pic_share a share of the grid's own velocity (PIC): it damps the
            // velocities of points that the grid cannot see, which FLIP keeps and nothing else
            // in the free water dissipates (docs/piping.md, "The free water over a boil")
            liquid_.v[p * D + d] += picShare * (vNew[d] - liquid_.v[p * D + d]);
            // the liquid's share of the front diffusion: the mixture's volume flux stays
            const Real w = diffuses && !held[d] ? (1 - mixture) / mixture * k * gradPhi[d] : 0;
            liquid_.x[p * D + d] = std::clamp(liquid_.x[p * D + d] + dt * (vNew[d] + w), lowest[d], extent[d]);
        }
        liquid_.volume[p] *= 1 + dt * div;  // V follows the liquid's own strain
    };
    const Index liquidCount = static_cast<Index>(liquid_.size());
    withStencilKind(!gimp, [&](auto linearShapes) {
        if (nodes_.anyDiffusion) forAll(liquidCount, [&](Index p) { liquidPoint(p, std::true_type{}, linearShapes); });
        else forAll(liquidCount, [&](Index p) { liquidPoint(p, std::false_type{}, linearShapes); });
    });
}

template void DoublePointSolver<1>::gridToPoints();
template void DoublePointSolver<2>::gridToPoints();
template void DoublePointSolver<3>::gridToPoints();

}  // namespace qs
