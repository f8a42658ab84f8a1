// Phases 1 and 2 of the double-point step: points sorted by cell (the cells' water and free
// surface are FreeSurface.cpp's), then lumped masses, momenta, the effective-stress force, nodal
// porosity and drag coefficients mapped to the grid (physics.md section 2).
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "solver/DoublePointSolver.hpp"
#include "boundary/Overflow.hpp"
#include "grid/ShapeFunctions.hpp"
#include "materials/StressTensor.hpp"
#include "physics/DragLaw.hpp"
#include "solver/Parallel.hpp"
#include "solver/PointStencil.hpp"

namespace qs {


// ---------------------------------------------------------------------------------------------
// 1 sort points by cell
// ---------------------------------------------------------------------------------------------

/// Each point's cell, the points sorted by cell (stable) and each cell's first point (cellStart).
template <int D>
template <class Set>
void DoublePointSolver<D>::sortByCell(Set& set, std::vector<Index>& cellStart, std::vector<Index>& counts) {
    const Index n = static_cast<Index>(set.size());
    set.shape.resize(n);
    auto& cell = set.shape.cell;
    forAll(n, [&](Index p) { cell[p] = grid_.cellOf(&set.x[p * D]); });

    // Sorted (most steps: few points change cells), each cell's first point is where the cells
    // change, found in parallel. Every pass over the points here runs in parallel, each thread
    // over its own share: a serial pass pulls all of them through one core's cache, and the other
    // core's next phase fetches its half back from there (core/ForAll.hpp).
    const Index nc = grid_.numCells();
    const bool sorted = !anyOf(n, [&](Index p) { return p > 0 && cell[p] < cell[p - 1]; });
    if (sorted) {
        forAll(n, [&](Index p) {
            for (Index c = p == 0 ? 0 : cell[p - 1] + 1; c <= cell[p]; ++c) cellStart[c] = p;
        });
        for (Index c = n == 0 ? 0 : cell[n - 1] + 1; c <= nc; ++c) cellStart[c] = n;
    } else {
        // counting sort: stable, so points of a cell keep their relative order
        std::fill(counts.begin(), counts.end(), 0);
        for (Index p = 0; p < n; ++p) ++counts[cell[p] + 1];
        for (Index c = 0; c < nc; ++c) counts[c + 1] += counts[c];
        std::copy(counts.begin(), counts.end(), cellStart.begin());
        auto& order = scratch_.order;
        order.resize(n);
        for (Index p = 0; p < n; ++p) order[counts[cell[p]]++] = p;
        reorderPoints(set, order, scratch_);
        forAll(n, [&](Index p) { cell[p] = grid_.cellOf(&set.x[p * D]); });
    }
}

/// uGIMP's per-axis weights of every point, cached for the step's transfers. Linear shape
/// functions are taken from the positions where they are used (PointStencil.hpp): nothing to do.
template <int D>
template <class Set>
void DoublePointSolver<D>::computeWeights(Set& set) {
    if (!set.shape.weights) return;
    const Index n = static_cast<Index>(set.size());
    const auto kind = config_.grid.shapeFunctions;
    const Real h = grid_.h(), lp = set.halfLength;
    // the region each set fills: the grid, and for the sand only what is above the filter
    constexpr bool sand = std::is_same_v<Set, SolidPoints<D>>;
    Real lo[D] = {}, hi[D];
    for (int d = 0; d < D; ++d) hi[d] = grid_.cells(d) * h;
    if (sand) lo[D - 1] = sandBottomRow_ * h;
    forAll(n, [&](Index p) {
        Index start = 0;
        for (int d = 0; d < D; ++d) {
            const AxisWeights a = axisWeights(set.x[p * D + d], h, grid_.cells(d), kind, lp, lo[d], hi[d]);
            start += a.start * grid_.nodeStride(d);
            for (int k = 0; k < kStencil; ++k) {
                set.shape.w[(p * D + d) * 3 + k] = a.w[k];
                set.shape.dw[(p * D + d) * 3 + k] = a.dw[k];
            }
        }
        set.shape.start[p] = start;
    });
}

template <int D>
void DoublePointSolver<D>::sortPoints() {
    sortByCell(solid_, cells_.solidStart, cells_.counts);
    sortByCell(liquid_, cells_.liquidStart, cells_.counts);
    computeWeights(solid_);
    computeWeights(liquid_);
}

// ---------------------------------------------------------------------------------------------
// 2 points to grid
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::pointsToGrid() {
    for (auto* a : {&nodes_.massS, &nodes_.massL, &sums_.grainVolume, &sums_.darcy, &sums_.forchheimer, &nodes_.slopeMass})
        std::fill(a->begin(), a->end(), 0.0);
    for (auto* a : {&nodes_.momS, &nodes_.momL, &nodes_.forceS, &nodes_.forceL}) std::fill(a->begin(), a->end(), 0.0);

    // Solid: mass, momentum, grain volume, drag sums and the effective-stress force
    // F_int,S = sum grad(N)^T sigma' V (subtracted).
    // The sand rests on the filter and never reaches below it. A uGIMP point next to the filter
    // has its domain cut there (computeWeights), so it leaves nothing on the chamber's nodes; a
    // sliver there (weight ~ (displacement/h)^2) would meet the cell-based interaction force,
    // which does not scale with the solid present, and be driven wildly (found as a 10 % slower,
    // and with one point per cell a stalled, consolidation above the closed base). The points
    // are kept above the filter (gridToPoints); should one be found below it by more than lp (a
    // checkpoint of an older version), its whole domain stays, and the test below drops what it
    // maps there.
    const Index firstSolidNode = sandBottomRow_ * grid_.nodeStride(D - 1);
    const bool axisymmetric = grid_.axisymmetric();
    const bool gimp = config_.grid.shapeFunctions == ShapeFunctionKind::Gimp;
    // What a solid point hands every node it reaches, scaled by N (or grad N): its mass, its
    // grains' volume, the drag sums V / kappa and V F / sqrt(kappa), and its effective stress
    // times its volume (the force is -V sigma' grad N). Axisymmetry: the hoop stress pulls the
    // ring towards the axis, sigma_tt V N_i / r on the radial component (Voigt yy is theta).
    struct SolidShares {
        Real m, grains, dragA, dragB, hoop;
        Real stressV[D][D];  ///< -V sigma'_de, the force per unit of grad N
    };
    auto sharesOf = [&](Index p) {
        SolidShares t;
        const Real V = solid_.volume[p], n = solid_.porosity[p];
        const auto& mat = materials_[solid_.material[p]];
        const DragLaw::Shares drag = DragLaw::pointShares(mat.permeability.kappa(n), mat.permeability.ergunFactor(n), V);
        t.m = solid_.mass[p];
        t.grains = t.m / mat.grainDensity;
        t.dragA = drag.darcy;
        t.dragB = drag.forchheimer;
        const Real* s = &solid_.stress[p * 6];
        for (int d = 0; d < D; ++d)
            for (int e = 0; e < D; ++e) t.stressV[d][e] = -V * s[voigt(axis3<D>(d), axis3<D>(e))];
        t.hoop = axisymmetric ? s[1] * V / solid_.x[p * D] : 0.0;
        return t;
    };
    if (!gimp) {
        // Linear shape functions: the point's cell's 2^D nodes (grid/LinearStencil.hpp). APIC's
        // velocity at node k, v_p + C_p (x_k - x_p) with x_k - x_p = (k_e - xi_e) h, is the
        // velocity at the cell's lowest node plus C_p h for each axis along which k is the upper node.
        const Real h = grid_.h();
        forEachPointColoured(grid_, cells_.solidStart, slabRows(true), [&](Index p) {
            // the node arrays as locals: the compiler keeps them in registers across the nodes
            Real* const mass = nodes_.massS.data();
            Real* const grains = sums_.grainVolume.data();
            Real* const dragA = sums_.darcy.data();
            Real* const dragB = sums_.forchheimer.data();
            Real* const mom = nodes_.momS.data();
            Real* const force = nodes_.forceS.data();
            Real* const slopeMass = nodes_.slopeMass.data();
            const LinearStencil<D> st = linearStencil(grid_, &solid_.x[p * D]);
            const SolidShares t = sharesOf(p);
            const Real* C = &solid_.velocityGradient[p * D * D];
            // the momentum at the cell's lowest node, m (v_p - C_p xi h), and its step per axis, m C_p h
            Real base[D], step[D][D];
            for (int d = 0; d < D; ++d) {
                base[d] = solid_.v[p * D + d];
                for (int e = 0; e < D; ++e) {
                    base[d] -= C[d * D + e] * st.xi[e] * h;
                    step[d][e] = t.m * C[d * D + e] * h;
                }
                base[d] *= t.m;
            }
            // the sand never reaches below the filter (gridToPoints keeps it above); a point
            // found there all the same (a checkpoint of an older version) leaves nothing below it
            Real keep[LinearStencil<D>::kNodes], N[LinearStencil<D>::kNodes];
            for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
                keep[k] = st.node[k] >= firstSolidNode ? 1.0 : 0.0;
                N[k] = keep[k] * st.N[k];
            }
            // three passes over the nodes, each with few values live (one pass spilled registers)
#pragma GCC unroll 8
            for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
                const Index i = st.node[k];
                mass[i] += N[k] * t.m;
                grains[i] += N[k] * t.grains;
                dragA[i] += N[k] * t.dragA;
                dragB[i] += N[k] * t.dragB;
            }
#pragma GCC unroll 8
            for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
                const Index i = st.node[k];
                for (int d = 0; d < D; ++d) {
                    Real mv = base[d];
                    for (int e = 0; e < D; ++e)
                        if (LinearStencil<D>::bit(k, e)) mv += step[d][e];
                    mom[i * D + d] += N[k] * mv;
                }
            }
#pragma GCC unroll 8
            for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
                const Index i = st.node[k];
                Real slope2 = 0;
                for (int d = 0; d < D; ++d) {
                    Real f = 0;
                    for (int e = 0; e < D; ++e) f += t.stressV[d][e] * st.grad[k][e];
                    force[i * D + d] += keep[k] * f;
                    slope2 += st.grad[k][d] * st.grad[k][d];
                }
                slopeMass[i] += keep[k] * t.m * h * h * slope2;
                if (axisymmetric) force[i * D] -= t.hoop * N[k];
            }
        });
    } else {
        // uGIMP: the cached per-axis weights (computeWeights), up to 3 nodes per axis
        forEachPointColoured(grid_, cells_.solidStart, slabRows(false), [&](Index p) {
            const SolidShares t = sharesOf(p);
            Real v[D], C[D * D];
            for (int d = 0; d < D; ++d) v[d] = solid_.v[p * D + d];
            for (int k = 0; k < D * D; ++k) C[k] = solid_.velocityGradient[p * D * D + k];
            const Real* xp = &solid_.x[p * D];
            // APIC: the stencil's first node, where the node offsets count from (one division per point)
            const IVec<D> first = grid_.nodeCoords(solid_.shape.start[p]);
            // The affine term is taken about the mean position of the nodes the point reaches,
            // sum N x_i / sum N: inside its region that is the point itself; a uGIMP domain cut at
            // a wall or at the filter (ShapeFunctions.hpp) is centred on the cut domain's centre
            // instead, and about x_p the term would add momentum
            Real centre[D], sum = 0, moment[D] = {};
            forStencilOffsets<D>(grid_, solid_.shape.start[p], &solid_.shape.w[p * D * 3],
                                 &solid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real*, const int* offset) {
                if (i < firstSolidNode) return;
                sum += N;
                for (int e = 0; e < D; ++e) moment[e] += N * grid_.nodePosition(first[e] + offset[e]);
            });
            for (int e = 0; e < D; ++e) centre[e] = sum > 0 ? moment[e] / sum : xp[e];
            forStencilOffsets<D>(grid_, solid_.shape.start[p], &solid_.shape.w[p * D * 3],
                                 &solid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real* gradN, const int* offset) {
                if (i < firstSolidNode) return;
                nodes_.massS[i] += N * t.m;
                sums_.grainVolume[i] += N * t.grains;
                sums_.darcy[i] += N * t.dragA;
                sums_.forchheimer[i] += N * t.dragB;
                Real dx[D], slope2 = 0;
                for (int e = 0; e < D; ++e) dx[e] = grid_.nodePosition(first[e] + offset[e]) - centre[e];
                for (int e = 0; e < D; ++e) slope2 += gradN[e] * gradN[e];
                nodes_.slopeMass[i] += t.m * grid_.h() * grid_.h() * slope2;
                for (int d = 0; d < D; ++d) {
                    Real vi = v[d];
                    for (int e = 0; e < D; ++e) vi += C[d * D + e] * dx[e];
                    nodes_.momS[i * D + d] += N * t.m * vi;
                    Real f = 0;
                    for (int e = 0; e < D; ++e) f += t.stressV[d][e] * gradN[e];
                    nodes_.forceS[i * D + d] += f;
                }
                if (axisymmetric) nodes_.forceS[i * D] -= t.hoop * N;
            });
        });
    }
    withStencilKind(!gimp, [&](auto linearShapes) {
        constexpr bool linear = decltype(linearShapes)::value;
        forEachPointColoured(grid_, cells_.liquidStart, slabRows(linear), [&](Index p) {
            Real* const mass = nodes_.massL.data();
            Real* const mom = nodes_.momL.data();
            const Real m = liquid_.mass[p];
            Real mv[D];
            for (int d = 0; d < D; ++d) mv[d] = m * liquid_.v[p * D + d];
            forEachNodeOfPoint<linear>(grid_, liquid_, p, [&](Index i, Real N, const Real*) {
                mass[i] += N * m;
                for (int d = 0; d < D; ++d) mom[i * D + d] += N * mv[d];
            });
        });
    });

    // Nodal porosity n_i = 1 - (sum N m_s / rho_s) / V_i with V_i = integral of N_i over the
    // active cells only: over the whole grid the sand surface would look far too porous.
    const Real rhoL = config_.liquid.density;
    const DragLaw drag{config_.liquid.viscosity, rhoL};
    const bool gridLiquid = config_.liquid.gridLiquidMass;
    const Index gateRow = grid_.nodeStride(D - 1);
    const Real starved = starvedShare();
    forAll(grid_.numNodes(), [&](Index i) {
        Real vol = 0, solidSide = 0;
        grid_.forEachCellOfNode(i, [&](Index cell, int corner) {
            const Real share = grid_.cellShare(cell, corner);
            if (filling_.active[cell]) vol += share;
            if (cells_.hasSolid(cell)) solidSide += share;
        });
        const Real por = vol > 0 ? 1 - sums_.grainVolume[i] / vol : 1.0;
        nodes_.porosity[i] = std::clamp(por, Real(1e-3), Real(1));
        // The porosity of the sand itself, over the cells that hold sand only: at the filter and
        // at a sand surface on a node it is the bed's, where n_i blends in the free water beside
        // it. The liquid-state switch and fluidised points read this one.
        nodes_.sandPorosity[i] = solidSide > 0 ? std::clamp(1 - sums_.grainVolume[i] / solidSide, Real(1e-3), Real(1)) : 1.0;
        // Darcy + Ergun drag, lumped: Q_i = n_i^2 mu sum(N V / kappa)
        //                                 + rho_L n_i^3 |w_i| sum(N V F / sqrt(kappa)),
        // |w_i| from the last step (physics/DragLaw.hpp).
        const Real ni = nodes_.porosity[i];
        // The nodal liquid mass is the water the cells around the node hold, rho_L n_i V_w,i
        // (waterVolumeAt), not the sum over liquid points. The points bunch where the chamber
        // water enters the sand (+35 % / -15 %, physics.md's first open problem), which made the
        // liquid's weight there wrong. And at a free surface a mass that follows the points
        // within a cell is a Rayleigh-Taylor interface to the one pressure per cell, which cannot
        // see where in the cell they are: points sinking towards a node make it heavier, the
        // cell's pressure does not hold the extra weight, and the node pulls them further down.
        // In 2D that grew from round-off at about 5 /s into a sloshing of the free water's top
        // cells (v_z alternating by node column, invisible to the cell-centre divergence) and
        // stopped batch settling at 11.3 s. From the cells' fills the mass does not depend on
        // where the points are within a cell. The points' mean velocity is kept. The gate plane
        // keeps the points' mass: the chamber's gap below the lowest points is empty.
        // (Bounding the grid's mass at the surface to within a factor of 2 of the points', so
        // that forces at the nodes of a stray point, where the grid holds f^2 of a share, reach it
        // less amplified, was tried: a point falling back then dragged the water below harder,
        // 1.6 Pa in the sand against 1.0 Pa, test_FreeSurface.cpp.)
        if (gridLiquid && i >= gateRow && nodes_.massL[i] > 0) {
            const Real M = rhoL * ni * waterVolumeAt(i);
            if (M > 0) {
                const Real scale = M / nodes_.massL[i];
                nodes_.massL[i] = M;
                for (int d = 0; d < D; ++d) nodes_.momL[i * D + d] *= scale;
            }
        }
        nodes_.drag[i] = (nodes_.massS[i] > 0 && nodes_.massL[i] > 0)
                       ? drag.nodal(ni, sums_.darcy[i], sums_.forchheimer[i], nodes_.relSpeed[i])
                       : 0.0;
        // how far the node is fed with sand, per component (a held one keeps its weight): the
        // phases after this read a starved node through it (GridToPoints.cpp)
        const Real w = fedWeight(i, starved);
        for (int d = 0; d < D; ++d) nodes_.fedWeight[i * D + d] = masks_.solidFixed[i * D + d] ? Real(1) : w;
    });
}

// ---------------------------------------------------------------------------------------------
// 2b the sand's own porosity per cell (the liquid-state switch, fluidised points)
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::measureSandPorosity() {
    // the mean of the cell's nodal sand porosities: the grid's solid mass in the cell
    forAll(grid_.numCells(), [&](Index c) {
        Real sand = 0;
        grid_.forEachNodeOfCell(c, [&](Index i, int) { sand += nodes_.sandPorosity[i] / (1 << D); });
        sand_.porosity[c] = sand;
        sand_.surface[c] = 0;
    });
    // At the top of the sand the grid cannot tell a loose cell from a half-filled one: the sand
    // surface lies inside the top sand cell, whose nodes then see too little solid, and so does
    // the top node of the cell below it. Per column of cells, the top two sand cells take the
    // porosity of the last node below them whose cells are all filled (the bottom node row of
    // the second cell), so a packed bed rising as a plug, or the top of a suspension, keeps its
    // porosity up to its surface.
    const Index up = grid_.cellStride(D - 1), rows = grid_.cells(D - 1);
    forAll(grid_.columns(), [&](Index col) {
        for (Index row = rows - 1; row >= 2; --row) {
            const Index top = grid_.columnCell(col, row);
            if (!cells_.hasSolid(top)) continue;
            const Index below = top - up, base = below - up;
            if (!cells_.hasSolid(below) || !cells_.hasSolid(base)) break;
            Real n = 0;  // the bottom node row of `below` = the top node row of `base`
            int count = 0;
            grid_.forEachNodeOfCell(base, [&](Index i, int corner) {
                if ((corner >> (D - 1)) & 1) { n += nodes_.sandPorosity[i]; ++count; }
            });
            n /= count;
            for (Index c : {top, below}) {
                sand_.porosity[c] = n;
                sand_.surface[c] = 1;
            }
            break;
        }
    });
}

template void DoublePointSolver<1>::sortPoints();
template void DoublePointSolver<1>::pointsToGrid();
template void DoublePointSolver<1>::measureSandPorosity();
template void DoublePointSolver<1>::sortByCell(SolidPoints<1>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<1>::sortByCell(LiquidPoints<1>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<1>::computeWeights(SolidPoints<1>&);
template void DoublePointSolver<1>::computeWeights(LiquidPoints<1>&);
template void DoublePointSolver<2>::sortPoints();
template void DoublePointSolver<2>::pointsToGrid();
template void DoublePointSolver<2>::measureSandPorosity();
template void DoublePointSolver<2>::sortByCell(SolidPoints<2>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<2>::sortByCell(LiquidPoints<2>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<2>::computeWeights(SolidPoints<2>&);
template void DoublePointSolver<2>::computeWeights(LiquidPoints<2>&);
template void DoublePointSolver<3>::sortPoints();
template void DoublePointSolver<3>::pointsToGrid();
template void DoublePointSolver<3>::measureSandPorosity();
template void DoublePointSolver<3>::sortByCell(SolidPoints<3>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<3>::sortByCell(LiquidPoints<3>&, std::vector<Index>&, std::vector<Index>&);
template void DoublePointSolver<3>::computeWeights(SolidPoints<3>&);
template void DoublePointSolver<3>::computeWeights(LiquidPoints<3>&);

}  // namespace qs
