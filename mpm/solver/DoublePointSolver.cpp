#include "solver/DoublePointSolver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "grid/ShapeFunctions.hpp"
#include "materials/StressTensor.hpp"
#include "physics/ClosedForms.hpp"
#include "solver/ColumnBuilder.hpp"
#include "boundary/Overflow.hpp"
#include "solver/Parallel.hpp"

namespace qs {

namespace {
Index roundCells(Real length, Real h) { return static_cast<Index>(std::llround(length / h)); }
}  // namespace

// ---------------------------------------------------------------------------------------------
// Set-up
// ---------------------------------------------------------------------------------------------

template <int D>
DoublePointSolver<D>::DoublePointSolver(const CaseConfig& config, ReservoirModel& reservoir)
    : config_(config), reservoir_(reservoir) {
    const Real h = config.grid.cellSize;
    IVec<D> cells;
    for (int d = 0; d < D - 1; ++d) cells[d] = roundCells(config.grid.width, h);
    cells[D - 1] = roundCells(config.column.top, h);
    grid_ = Grid<D>(cells, h, config.grid.crossSectionArea);

    const Real rhoL = config.liquid.density, KL = config.liquid.bulkModulus;
    waveSpeed_ = std::sqrt(KL / rhoL);  // free water
    for (const auto& m : config.materials) {
        QS_CHECK(m.model == ConstitutiveModel::LinearElastic,
                 "materials." << m.name << ".model: only \"linear_elastic\" is implemented so far");
        SolidMaterial s;
        s.name = m.name;
        s.grainDensity = m.grainDensity;
        s.maxPorosity = m.maxPorosity;
        s.elastic = LinearElastic::fromYoung(m.youngsModulus, m.poissonRatio);
        s.permeability = PermeabilityLaw::from(m);
        materials_.push_back(s);
        const auto c = closed::zeroDragWaveSpeeds(s.elastic.oedometric(), KL, m.porosity,
                                                  m.grainDensity, rhoL);
        waveSpeed_ = std::max(waveSpeed_, c.fast);
    }
    // dt = C h / c_fast: with implicit drag the fastest explicit wave is the zero-drag fast wave.
    dt_ = config.time.courant * h / waveSpeed_;
    if (config.time.dt) {
        const Real stable = 0.5 * h / waveSpeed_;
        QS_CHECK(*config.time.dt <= stable,
                 config.caseDirectory << "/case.toml: key 'time.dt': " << *config.time.dt
                                      << " s exceeds the stable step 0.5 h / c_fast = " << stable
                                      << " s (c_fast = " << waveSpeed_ << " m/s)");
        dt_ = *config.time.dt;
    }

    buildColumn(config, grid_, materials_, solid_, liquid_);
    allocate();
    masks_.build(grid_, config);
    // new points as small as the free-water points, so they do not leave sand cells empty
    chamber_.setup(grid_,
                   grid_.cellVolume() / freeWaterPointsPerCell(config) /
                       std::pow(Real(config.points.liquidPerCell), D - 1),
                   config.points.liquidPerCell);

    for (const auto& m : config.monitors) {
        const Index row = std::clamp<Index>(std::llround(m.elevation / h), 0, grid_.nodes(D - 1) - 1);
        monitorNodes_.push_back(row);
    }
    sandBottomRow_ = roundCells(config.filterLevel(), h);

    initialLiquidMass_ = 0;
    for (Real m : liquid_.mass) initialLiquidMass_ += m;
    gateLaw_ = reservoir_.gateLaw(0.0);
    gatePressure_ = gateLaw_.staticPressure;
    // fill the cell and node fields once so that the state at t = 0 can be reported
    sortPoints();
    classifyCells();
    pointsToGrid();
    computeForces();
}

template <int D>
void DoublePointSolver<D>::allocate() {
    const Index nn = grid_.numNodes(), nc = grid_.numCells();
    for (auto* a : {&massS_, &massL_, &solidVolume_, &nodeVolume_, &porosity_, &dragA_, &dragB_,
                    &drag_, &relSpeed_})
        a->assign(nn, 0.0);
    for (auto* a : {&momS_, &momL_, &forceS_, &forceL_, &velS_, &velL_, &velSOld_, &velLOld_})
        a->assign(nn * D, 0.0);
    solidCellStart_.assign(nc + 1, 0);
    liquidCellStart_.assign(nc + 1, 0);
    counts_.assign(nc + 1, 0);
    cellActive_.assign(nc, 0);
    cellSubmerged_.assign(nc, 0);
    for (auto* a : {&cellLiquidVolume_, &cellPressure_, &cellWeight_, &cellPorosity_,
                    &cellPressureIncrement_})
        a->assign(nc, 0.0);
    cellPorosityGrad_.assign(nc * D, 0.0);

    // Liquid points come and go: reserve for the densest filling the run can reach.
    const std::size_t liquidCapacity =
        4 * static_cast<std::size_t>(nc) * freeWaterPointsPerCell(config_) *
            static_cast<std::size_t>(std::pow(config_.points.liquidPerCell, D - 1)) + liquid_.size();
    reservePoints(liquid_, liquidCapacity, scratch_, 6);
    reservePoints(solid_, solid_.size(), scratch_, 6);
    scratch_.reals.reserve(liquidCapacity * 6);
    scratch_.ints.reserve(liquidCapacity);
    scratch_.order.reserve(liquidCapacity);
    liquid_.shape.reserve(liquidCapacity);
    liquid_.weight.reserve(liquidCapacity);
    liquid_.strainVol.reserve(liquidCapacity);
    solid_.shape.reserve(solid_.size());
    dropFlags_.reserve(liquidCapacity);
}

// ---------------------------------------------------------------------------------------------
// 1 sort points by cell, classify cells
// ---------------------------------------------------------------------------------------------

template <int D>
template <class Set>
void DoublePointSolver<D>::computeShape(Set& set, std::vector<Index>& cellStart,
                                        std::vector<Index>& counts) {
    const Index n = static_cast<Index>(set.size());
    set.shape.resize(n);
    auto& cell = set.shape.cell;
    forAll(n, [&](Index p) { cell[p] = grid_.cellOf(&set.x[p * D]); });

    bool sorted = true;
    for (Index p = 1; p < n && sorted; ++p) sorted = cell[p] >= cell[p - 1];
    std::fill(counts.begin(), counts.end(), 0);
    for (Index p = 0; p < n; ++p) ++counts[cell[p] + 1];
    for (Index c = 0; c < grid_.numCells(); ++c) counts[c + 1] += counts[c];
    std::copy(counts.begin(), counts.end(), cellStart.begin());
    if (!sorted) {
        // counting sort: stable, so points of a cell keep their relative order
        auto& order = scratch_.order;
        order.resize(n);
        for (Index p = 0; p < n; ++p) order[counts[cell[p]]++] = p;
        reorderPoints(set, order, scratch_);
        forAll(n, [&](Index p) { cell[p] = grid_.cellOf(&set.x[p * D]); });
    }

    const auto kind = config_.grid.shapeFunctions;
    const Real h = grid_.h(), lp = set.halfLength;
    forAll(n, [&](Index p) {
        Index start = 0;
        for (int d = 0; d < D; ++d) {
            const AxisWeights a = axisWeights(set.x[p * D + d], h, grid_.cells(d), kind, lp);
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
    computeShape(solid_, solidCellStart_, counts_);
    computeShape(liquid_, liquidCellStart_, counts_);
}

template <int D>
void DoublePointSolver<D>::classifyCells() {
    const Index nc = grid_.numCells();
    forAll(nc, [&](Index c) {
        Real vol = 0;
        for (Index p = liquidCellStart_[c]; p < liquidCellStart_[c + 1]; ++p) vol += liquid_.volume[p];
        cellLiquidVolume_[c] = vol;
        cellActive_[c] = (liquidCellStart_[c + 1] > liquidCellStart_[c]) ||
                         (solidCellStart_[c + 1] > solidCellStart_[c]);
    });
    // A cell is below the free surface when the cell above holds liquid. There the cell's liquid
    // points share the whole cell, V* = V_cell V / sum V, so they fill the pores and a half-empty
    // chamber cell carries no multiple of the gate pressure; above it V* = V (physics.md).
    const Index up = grid_.cellStride(D - 1);
    const Index rows = grid_.cells(D - 1);
    liquid_.weight.resize(liquid_.size());
    forAll(nc, [&](Index c) {
        const Index row = (c / up) % rows;
        const bool above = row + 1 < rows && liquidCellStart_[c + up + 1] > liquidCellStart_[c + up];
        cellSubmerged_[c] = above;
        const Real scale = above && cellLiquidVolume_[c] > 0 ? grid_.cellVolume() / cellLiquidVolume_[c] : 1.0;
        const bool thin = cellLiquidVolume_[c] < config_.liquid.freeSurfaceFilling * grid_.cellVolume();
        for (Index p = liquidCellStart_[c]; p < liquidCellStart_[c + 1]; ++p) {
            liquid_.weight[p] = liquid_.volume[p] * scale;
            liquid_.state[p] = (!above && thin) ? kFreeSurfaceLiquid : kSubmergedLiquid;
        }
    });
}

// ---------------------------------------------------------------------------------------------
// 2 points to grid
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::pointsToGrid() {
    for (auto* a : {&massS_, &massL_, &solidVolume_, &dragA_, &dragB_})
        std::fill(a->begin(), a->end(), 0.0);
    for (auto* a : {&momS_, &momL_, &forceS_, &forceL_}) std::fill(a->begin(), a->end(), 0.0);

    // Solid: mass, momentum, grain volume, drag sums and the effective-stress force
    // F_int,S = sum grad(N)^T sigma' V (subtracted).
    forEachPointColoured(grid_, solidCellStart_, [&](Index p) {
        const Real m = solid_.mass[p], V = solid_.volume[p];
        const auto& mat = materials_[solid_.material[p]];
        const Real grains = m / mat.grainDensity;
        const Real n = solid_.porosity[p];
        const Real kappa = mat.permeability.kappa(n);
        const Real a = V / kappa;
        const Real b = V * mat.permeability.ergunFactor(n) / std::sqrt(kappa);
        const Real* s = &solid_.stress[p * 6];
        const Real* v = &solid_.v[p * D];
        forStencil<D>(grid_, solid_.shape.start[p], &solid_.shape.w[p * D * 3],
                      &solid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real* gradN) {
            massS_[i] += N * m;
            solidVolume_[i] += N * grains;
            dragA_[i] += N * a;
            dragB_[i] += N * b;
            for (int d = 0; d < D; ++d) {
                momS_[i * D + d] += N * m * v[d];
                Real f = 0;
                for (int e = 0; e < D; ++e) f += s[voigt(axis3<D>(d), axis3<D>(e))] * gradN[e];
                forceS_[i * D + d] -= f * V;
            }
        });
    });
    forEachPointColoured(grid_, liquidCellStart_, [&](Index p) {
        const Real m = liquid_.mass[p];
        const Real* v = &liquid_.v[p * D];
        forStencil<D>(grid_, liquid_.shape.start[p], &liquid_.shape.w[p * D * 3],
                      &liquid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real*) {
            massL_[i] += N * m;
            for (int d = 0; d < D; ++d) momL_[i * D + d] += N * m * v[d];
        });
    });

    // Nodal porosity n_i = 1 - (sum N m_s / rho_s) / V_i with V_i = integral of N_i over the
    // active cells only: over the whole grid the sand surface would look far too porous.
    const Real cellShare = grid_.cellVolume() / (1 << D);
    const Real mu = config_.liquid.viscosity, rhoL = config_.liquid.density;
    forAll(grid_.numNodes(), [&](Index i) {
        const IVec<D> n = grid_.nodeCoords(i);
        Real vol = 0;
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> c;
            bool inside = true;
            for (int d = 0; d < D; ++d) {
                c[d] = n[d] - 1 + ((k >> d) & 1);
                if (c[d] < 0 || c[d] >= grid_.cells(d)) inside = false;
            }
            if (inside && cellActive_[grid_.cellIndex(c)]) vol += cellShare;
        }
        nodeVolume_[i] = vol;
        const Real por = vol > 0 ? 1 - solidVolume_[i] / vol : 1.0;
        porosity_[i] = std::clamp(por, Real(1e-3), Real(1));
        // Darcy + Ergun drag, lumped: Q_i = n_i^2 mu sum(N V / kappa)
        //                                 + rho_L n_i^3 |w_i| sum(N V F / sqrt(kappa)),
        // |w_i| from the last step (physics.md, drag).
        const Real ni = porosity_[i];
        drag_[i] = (massS_[i] > 0 && massL_[i] > 0)
                       ? ni * ni * mu * dragA_[i] + rhoL * ni * ni * ni * relSpeed_[i] * dragB_[i]
                       : 0.0;
    });
}

// ---------------------------------------------------------------------------------------------
// 3 forces
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::computeForces() {
    const Real g = config_.gravity, rhoL = config_.liquid.density;
    const Index nc = grid_.numCells();
    const Real h = grid_.h();

    // Cell pore pressure p_c = sum p V* / sum V*, cell porosity and its gradient at the centre.
    forAll(nc, [&](Index c) {
        Real pv = 0, w = 0;
        for (Index p = liquidCellStart_[c]; p < liquidCellStart_[c + 1]; ++p) {
            pv += liquid_.pressure[p] * liquid_.weight[p];
            w += liquid_.weight[p];
        }
        cellWeight_[c] = w;
        cellPressure_[c] = w > 0 ? pv / w : 0.0;
        const IVec<D> cc = grid_.cellCoords(c);
        Real n = 0;
        Real grad[D] = {};
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> nd;
            for (int d = 0; d < D; ++d) nd[d] = cc[d] + ((k >> d) & 1);
            const Real ni = porosity_[grid_.nodeIndex(nd)];
            n += ni / (1 << D);
            for (int a = 0; a < D; ++a) {
                Real gN = (((k >> a) & 1) ? 1.0 : -1.0) / h;
                for (int d = 0; d < D; ++d)
                    if (d != a) gN *= 0.5;
                grad[a] += gN * ni;
            }
        }
        cellPorosity_[c] = n;
        for (int a = 0; a < D; ++a) cellPorosityGrad_[c * D + a] = grad[a];
    });

    // Pressure forces gathered per node from its cells:
    //   F_p,L = + p_c V_c [ n_c grad N_i(x_c) + N_i(x_c) grad n_c ]
    //   F_p,S = + p_c V_c [ (1 - n_c) grad N_i(x_c) - N_i(x_c) grad n_c ]
    // so the liquid feels -n grad p and the solid -(1-n) grad p (physics.md, pressure forces).
    const Real Nc = 1.0 / (1 << D);
    forAll(grid_.numNodes(), [&](Index i) {
        const IVec<D> n = grid_.nodeCoords(i);
        Real fL[D] = {}, fS[D] = {};
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> c;
            bool inside = true;
            for (int d = 0; d < D; ++d) {
                c[d] = n[d] - 1 + ((k >> d) & 1);
                if (c[d] < 0 || c[d] >= grid_.cells(d)) inside = false;
            }
            if (!inside) continue;
            const Index cell = grid_.cellIndex(c);
            const Real pV = cellPressure_[cell] * cellWeight_[cell];
            if (pV == 0) continue;
            const Real nc_ = cellPorosity_[cell];
            for (int a = 0; a < D; ++a) {
                // node i is the upper node of this cell along a when the cell index is n - 1
                Real gN = (((k >> a) & 1) ? -1.0 : 1.0) / h;
                for (int d = 0; d < D; ++d)
                    if (d != a) gN *= 0.5;
                const Real gn = cellPorosityGrad_[cell * D + a];
                fL[a] += pV * (nc_ * gN + Nc * gn);
                fS[a] += pV * ((1 - nc_) * gN - Nc * gn);
            }
        }
        for (int a = 0; a < D; ++a) {
            forceL_[i * D + a] += fL[a];
            forceS_[i * D + a] += fS[a];
        }
        forceS_[i * D + D - 1] -= massS_[i] * g;
        forceL_[i * D + D - 1] -= massL_[i] * g;
    });

    // Gate: the reservoir's pressure acts on the chamber's liquid at the gate plane, less the
    // weight of the empty gap below the lowest liquid point (physics.md, gate).
    if (config_.gate.mode == GateMode::Pressure) {
        for (Index i : masks_.gateNodes) {
            const Real p = gateLaw_.staticPressure - rhoL * g * chamber_.gap(chamber_.columnOfNode(grid_, i));
            forceL_[i * D + D - 1] += p * nodeFootprint(grid_, i);
        }
    }

    // Surcharge on the sand top (solid phase) and the overflow level's missing water on the
    // free surface, both as tractions at the surface elevation.
    const Real q = surchargeNow();
    if (q != 0) addSurfaceTraction(grid_, forceS_, sandSurface(), q);
    surfacePressure_ = 0;
    if (config_.column.overflowLevel) {
        const Real zs = waterSurface();
        if (zs > 0) {
            surfacePressure_ = rhoL * g * (*config_.column.overflowLevel - zs);
            addSurfaceTraction(grid_, forceL_, zs, surfacePressure_);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 4 nodal update with implicit drag and boundary conditions
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::solveNodes() {
    const Real dt = dt_;
    const Real vGate = gateVelocityNow();
    Real area = 0;
    for (Index i : masks_.gateNodes) area += nodeFootprint(grid_, i);
    const Real gateResistance = config_.gate.mode == GateMode::Pressure ? gateLaw_.resistance : 0.0;
    const Index rowStride = grid_.nodeStride(D - 1);

    forAll(grid_.numNodes(), [&](Index i) {
        const Real mS = massS_[i], mL = massL_[i], Q = drag_[i];
        const bool isGate = i < rowStride;  // bottom node row
        // implicit tube loss at the gate: M_L v = M_L v* - dt c v, c = R A_total A_i
        const Real c = isGate ? gateResistance * area * nodeFootprint(grid_, i) : 0.0;
        Real w2 = 0;
        for (int d = 0; d < D; ++d) {
            const Index k = i * D + d;
            Real vS0 = mS > 0 ? momS_[k] / mS : 0.0;
            Real vL0 = mL > 0 ? momL_[k] / mL : 0.0;
            Real fS = forceS_[k], fL = forceL_[k];
            if (damping_) {
                // local damping, gravity stage only: F <- F - alpha |F| sign(v)
                fS -= dampingAlpha_ * std::abs(fS) * (vS0 > 0 ? 1 : (vS0 < 0 ? -1 : 0));
                fL -= dampingAlpha_ * std::abs(fL) * (vL0 > 0 ? 1 : (vL0 < 0 ? -1 : 0));
            }
            const Real vS1 = mS > 0 ? vS0 + dt * fS / mS : 0.0;  // drag-free predictors
            const Real vL1 = mL > 0 ? vL0 + dt * fL / mL : 0.0;
            const bool vertical = d == D - 1;
            const Real cd = vertical ? c : 0.0;
            const Real vLfix = (isGate && vertical) ? vGate : 0.0;
            Real vS = 0, vL = 0;
            if (mS > 0 && mL > 0) {
                if (masks_.solidFixed[k] && masks_.liquidFixed[k]) {
                    vS = 0; vL = vLfix;
                } else if (masks_.solidFixed[k]) {
                    // solid held: solve the liquid alone (solving the pair and overwriting one
                    // afterwards loses momentum)
                    vS = 0;
                    vL = (mL * vL1) / (mL + dt * Q + dt * cd);
                } else if (masks_.liquidFixed[k]) {
                    vL = vLfix;
                    vS = (mS * vS1 + dt * Q * vL) / (mS + dt * Q);
                } else {
                    // drag keeps M_L v_L + M_S v_S and relaxes w = v_L - v_S
                    const Real M = mL + mS;
                    const Real vm = (mL * vL1 + mS * vS1) / M;
                    const Real w = (vL1 - vS1) / (1 + dt * Q * (1 / mL + 1 / mS));
                    vL = vm + mS * w / M;
                    vS = vm - mL * w / M;
                }
            } else if (mL > 0) {
                vL = masks_.liquidFixed[k] ? vLfix : mL * vL1 / (mL + dt * cd);
            } else if (mS > 0) {
                vS = masks_.solidFixed[k] ? 0.0 : vS1;
            }
            velSOld_[k] = vS0;
            velLOld_[k] = vL0;
            velS_[k] = vS;
            velL_[k] = vL;
            w2 += (vL - vS) * (vL - vS);
        }
        relSpeed_[i] = (mS > 0 && mL > 0) ? std::sqrt(w2) : 0.0;
    });

    // Gate flux through the gate plane (free water: q = v_L).
    Real Qg = 0;
    for (Index i : masks_.gateNodes)
        if (massL_[i] > 0) Qg += velL_[i * D + D - 1] * nodeFootprint(grid_, i);
    gateFlux_ = Qg;
}

// ---------------------------------------------------------------------------------------------
// 5 grid to points: FLIP velocities, positions, strains, constitutive update
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::gridToPoints() {
    const Real dt = dt_;
    Real extent[D];  // points stay inside the grid, axis by axis
    for (int d = 0; d < D; ++d) extent[d] = grid_.cells(d) * grid_.h();
    forAll(static_cast<Index>(solid_.size()), [&](Index p) {
        Real dv[D] = {}, vNew[D] = {}, L[D][D] = {};
        forStencil<D>(grid_, solid_.shape.start[p], &solid_.shape.w[p * D * 3],
                      &solid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real* gradN) {
            for (int d = 0; d < D; ++d) {
                const Real v = velS_[i * D + d];
                dv[d] += N * (v - velSOld_[i * D + d]);
                vNew[d] += N * v;
                for (int e = 0; e < D; ++e) L[d][e] += v * gradN[e];
            }
        });
        for (int d = 0; d < D; ++d) {
            solid_.v[p * D + d] += dv[d];  // FLIP: PIC would smear the jumps at porosity interfaces
            solid_.x[p * D + d] = std::clamp(solid_.x[p * D + d] + dt * vNew[d], Real(0), extent[d]);
        }
        Real dEps[6] = {};
        for (int d = 0; d < D; ++d)
            for (int e = d; e < D; ++e)
                dEps[voigt(axis3<D>(d), axis3<D>(e))] = 0.5 * dt * (L[d][e] + L[e][d]);
        const Real dVol = dEps[0] + dEps[1] + dEps[2];
        const auto& mat = materials_[solid_.material[p]];
        Real* s = &solid_.stress[p * 6];
        Real& n = solid_.porosity[p];
        n = 1 - (1 - n) / (1 + dVol);  // solid mass balance, grains incompressible
        solid_.volume[p] *= 1 + dVol;
        if (solid_.state[p] == kFluidisedState) {
            // fluidised material carries no effective stress; it turns back to solid when it
            // compacts below n_max, restarting from zero effective stress
            if (n < mat.maxPorosity && dVol < 0) solid_.state[p] = kSolidState;
            return;
        }
        mat.elastic.update(s, dEps);
        tensionCutoff(s);
        const bool zeroStress = s[0] == 0 && s[1] == 0 && s[2] == 0;
        if (zeroStress && n >= mat.maxPorosity && dVol >= 0) {
            solid_.state[p] = kFluidisedState;
            for (int k = 0; k < 6; ++k) s[k] = 0;
        }
    });

    liquid_.strainVol.resize(liquid_.size());
    forAll(static_cast<Index>(liquid_.size()), [&](Index p) {
        Real dv[D] = {}, vNew[D] = {}, div = 0;
        forStencil<D>(grid_, liquid_.shape.start[p], &liquid_.shape.w[p * D * 3],
                      &liquid_.shape.dw[p * D * 3], [&](Index i, Real N, const Real* gradN) {
            for (int d = 0; d < D; ++d) {
                const Real v = velL_[i * D + d];
                dv[d] += N * (v - velLOld_[i * D + d]);
                vNew[d] += N * v;
                div += v * gradN[d];
            }
        });
        for (int d = 0; d < D; ++d) {
            liquid_.v[p * D + d] += dv[d];
            liquid_.x[p * D + d] = std::clamp(liquid_.x[p * D + d] + dt * vNew[d], Real(0), extent[d]);
        }
        liquid_.strainVol[p] = dt * div;
        liquid_.volume[p] *= 1 + dt * div;  // V follows the liquid's own strain
    });
}

// ---------------------------------------------------------------------------------------------
// 6 pore pressure, one value per cell
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::updatePressure() {
    // dp_c = -(K_L / n_c) dt sum_i grad N_i(x_c) . Phi_i,  Phi_i = (1-n_i) v_S,i + n_i v_L,i
    // (compressible liquid, incompressible grains; the cell average avoids volumetric locking).
    const Real KL = config_.liquid.bulkModulus, dt = dt_, h = grid_.h();
    const Real pMin = config_.liquid.cavitationPressure;
    const bool zeroSurface = config_.liquid.freeSurfaceZeroPressure;
    forAll(grid_.numCells(), [&](Index c) {
        if (liquidCellStart_[c + 1] == liquidCellStart_[c]) return;
        const IVec<D> cc = grid_.cellCoords(c);
        Real div = 0;
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> nd;
            for (int d = 0; d < D; ++d) nd[d] = cc[d] + ((k >> d) & 1);
            const Index i = grid_.nodeIndex(nd);
            const Real ni = porosity_[i];
            for (int a = 0; a < D; ++a) {
                Real gN = (((k >> a) & 1) ? 1.0 : -1.0) / h;
                for (int d = 0; d < D; ++d)
                    if (d != a) gN *= 0.5;
                div += gN * ((1 - ni) * velS_[i * D + a] + ni * velL_[i * D + a]);
            }
        }
        const Real dp = -(KL / cellPorosity_[c]) * dt * div;
        cellPressureIncrement_[c] = dp;
        for (Index p = liquidCellStart_[c]; p < liquidCellStart_[c + 1]; ++p) {
            Real& pp = liquid_.pressure[p];
            pp = std::max(pp + dp, pMin);  // the liquid takes no tension below the cavitation limit
            if (zeroSurface && liquid_.state[p] == kFreeSurfaceLiquid) pp = 0;
        }
    });
}

// ---------------------------------------------------------------------------------------------
// 7 inflow, outflow, ledger, reservoir
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::exchangeAtBoundaries() {
    cumulativeInflow_ += gateFlux_ * dt_;
    gatePressure_ = gateLaw_.pressure(gateFlux_);
    reservoir_.advance(time_, dt_, gateFlux_);

    if (config_.column.overflowLevel) {
        const Real zOver = *config_.column.overflowLevel;
        checkSolidBelow(zOver, solid_, time_, sandSurface());
        const Real out = removeLiquidAbove(zOver, config_.liquid.density, liquid_, dropFlags_);
        if (out > 0) {
            outflowVolume_ += out;
            // the cell lists are stale now: rebuild them for the chamber's scan below
            computeShape(liquid_, liquidCellStart_, counts_);
        }
    }
    if (config_.gate.mode != GateMode::Closed)
        chamber_.inject(grid_, liquid_, liquidCellStart_, config_.liquid.density, gatePressure_);

    time_ += dt_;
    ++steps_;
}

// ---------------------------------------------------------------------------------------------
// the step
// ---------------------------------------------------------------------------------------------

template <int D>
void DoublePointSolver<D>::step() {
    // the gate law for this step, asked afresh: a coupling scheme may have started a new window
    // (or rolled the window back) since the last step
    gateLaw_ = reservoir_.gateLaw(time_);
    sortPoints();
    classifyCells();
    pointsToGrid();
    computeForces();
    solveNodes();
    gridToPoints();
    updatePressure();
    exchangeAtBoundaries();
    if (!std::isfinite(gateFlux_)) {
        std::ostringstream s;
        s << "the solution became non-finite at t = " << time_ << " s (step " << steps_
          << "); reduce time.courant (now " << config_.time.courant
          << "), or with a coupled reservoir use coupling.scheme = \"implicit\"";
        throw Error(s.str());
    }
}

template <int D>
void DoublePointSolver<D>::runGravityStage() {
    const Real duration = config_.initial.gravityStageDuration;
    if (duration <= 0) return;
    damping_ = true;
    dampingAlpha_ = config_.initial.gravityStageDamping;
    const Real t0 = time_;
    const auto saved = reservoir_.saveState();
    while (time_ - t0 < duration) step();
    reservoir_.restoreState(saved);
    damping_ = false;
    // the dynamic stage starts at rest at t = 0
    time_ = 0;
    steps_ = 0;
    std::fill(solid_.v.begin(), solid_.v.end(), 0.0);
    std::fill(liquid_.v.begin(), liquid_.v.end(), 0.0);
    std::fill(relSpeed_.begin(), relSpeed_.end(), 0.0);
    cumulativeInflow_ = outflowVolume_ = 0;
    chamber_.setInjectedVolume(0);
    initialLiquidMass_ = 0;
    for (Real m : liquid_.mass) initialLiquidMass_ += m;
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
Real DoublePointSolver<D>::gateVelocityNow() const {
    if (config_.gate.mode != GateMode::Flux) return 0.0;
    const Real v = config_.gate.flux, ramp = config_.gate.fluxRampTime;
    return (ramp > 0 && time_ < ramp) ? v * time_ / ramp : v;
}

template <int D>
Real DoublePointSolver<D>::sandSurface() const {
    return sandSurfaceOf(grid_, solid_, config_.filterLevel(), config_.points.solidPerCell);
}

template <int D>
Real DoublePointSolver<D>::waterSurface() const {
    return waterSurfaceFromMass(grid_, liquid_, sandSurface() + grid_.h(), config_.liquid.density,
                                config_.points.liquidPerCell);
}

template class DoublePointSolver<1>;
template class DoublePointSolver<2>;
template class DoublePointSolver<3>;

}  // namespace qs
