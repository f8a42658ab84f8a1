// What the column looks like now: the quantities of series.csv (fluxes, pressures, surfaces,
// ledger, hydraulic gradient) and the cell-row profiles a user compares with a closed form.
// Measured on the grid, as physics.md asks: the filter velocity q = n (v_L - v_S) at a section's
// nodes (averages over liquid points run about 1 % low under FLIP), the gradient from a linear
// fit of the interior sand cells' pressures (the bottom and top sand cells excluded).
#include <algorithm>
#include <cmath>

#include "boundary/Overflow.hpp"
#include "boundary/Surcharge.hpp"
#include "solver/DoublePointSolver.hpp"

namespace qs {

template <int D>
Real DoublePointSolver<D>::footprintShare(Index node, const std::optional<HorizontalRange>& x,
                                          const std::optional<HorizontalRange>& y) const {
    Real share = 1;
    const IVec<D> n = grid_.nodeCoords(node);
    const Real h = grid_.h();
    for (int d = 0; d < D - 1; ++d) {
        const auto& range = d == 0 ? x : y;
        if (!range) continue;
        const Real centre = n[d] * h, extent = grid_.cells(d) * h;
        const Real lo = std::max(Real(0), centre - h / 2), hi = std::min(extent, centre + h / 2);
        const Real a = std::max(lo, Real(range->from)), b = std::min(hi, Real(range->to));
        if (b <= a) return 0.0;
        // in axisymmetry by ring area (the integral of r dr), elsewhere by length
        share *= grid_.axisymmetric() ? (b * b - a * a) / (hi * hi - lo * lo) : (b - a) / (hi - lo);
    }
    return share;
}

template <int D>
std::vector<Real> DoublePointSolver<D>::sandFeeding() const {
    std::vector<Real> ratio(nodes_.massS.size(), -1.0);
    for (std::size_t i = 0; i < ratio.size(); ++i)
        if (nodes_.slopeMass[i] > 0) ratio[i] = nodes_.massS[i] / nodes_.slopeMass[i];
    return ratio;
}

template <int D>
ColumnState DoublePointSolver<D>::columnState() const {
    ColumnState s;
    s.time = time_;
    s.gateFlux = gateFlux_;
    s.gatePressure = gatePressure_;
    s.reservoirHead = reservoir_.head();
    s.sandSurface = maxOverRanks(sandSurface());
    s.bedHeight = s.sandSurface - config_.filterLevel();
    s.waterSurface = waterSurface();
    measureStates(s);
    for (std::size_t m = 0; m < monitorNodes_.size(); ++m) {
        const Index row = monitorNodes_[m];
        const MonitorConfig& monitor = config_.monitors[m];
        // q = n (v_L - v_S) on the grid, averaged over the section's nodes by footprint (the
        // part of each node's footprint inside the monitor's x and y ranges, if it has them); a
        // starved node's solid velocity counts with its fed weight (GridToPoints.cpp): at the sand's
        // surface it is a force over a sliver of mass, and above it the flux is the water's, so the
        // rest counts as sand at rest there (not the fed neighbours' velocity, as the strain takes
        // it: q is the water's flux through a section, where the sliver holds next to no grains).
        // A dilute suspension (points more than a cell apart) starves nodes inside it too; q there
        // reads the water's flux less the sliver's share of the grains' motion
        Real q = 0, a = 0;
        for (Index i = 0; i < grid_.numNodes(); ++i) {
            if (grid_.nodeCoords(i)[D - 1] != row || nodes_.massL[i] <= 0 || !ownsNode(i)) continue;
            const Real w = nodeFootprint(grid_, i) * footprintShare(i, monitor.x, monitor.y);
            if (w <= 0) continue;
            q += w * nodes_.porosity[i] * (nodes_.velL[i * D + D - 1] - nodes_.fedWeight[i * D + D - 1] * nodes_.velS[i * D + D - 1]);
            a += w;
        }
        q = sumOverRanks(q);
        a = sumOverRanks(a);
        s.monitorFlux.push_back(a > 0 ? q / a : 0.0);
    }
    s.cumulativeInflow = cumulativeInflow_;
    s.cumulativeOutflow = outflowVolume_;
    s.cumulativeSolidOutflow = sumOverRanks(solidOutflowMass_);  // each rank's own sand out
    s.injectedVolume = sumOverRanks(chamber_.injectedVolume());  // each rank's own slots'
    for (Real m : solid_.mass) s.solidMass += m;
    for (Real m : liquid_.mass) s.liquidMass += m;
    s.solidMass = sumOverRanks(s.solidMass);
    s.liquidMass = sumOverRanks(s.liquidMass);
    const Real stored = (s.liquidMass - initialLiquidMass_) / config_.liquid.density +
                        chamber_.gapVolume(grid_) - initialGapVolume_;
    s.ledgerResidual = cumulativeInflow_ - outflowVolume_ - stored;
    s.solidPoints = static_cast<std::size_t>(sumOverRanks(static_cast<Real>(solid_.size())));
    s.liquidPoints = static_cast<std::size_t>(sumOverRanks(static_cast<Real>(liquid_.size())));

    // hydraulic gradient: linear fit of the cell pressures over the interior sand cells (the
    // bottom and top sand cells excluded), i = -(dp/dz)/(rho_L g) - 1
    const auto rows = profile();
    const Real zTop = bedTop(s.sandSurface);
    double sz = 0, sp = 0, szz = 0, szp = 0;
    int count = 0;
    for (const auto& r : rows) {
        if (r.z < config_.filterLevel() + grid_.h() || r.z > zTop - grid_.h()) continue;
        sz += r.z; sp += r.porePressure; szz += r.z * r.z; szp += r.z * r.porePressure;
        ++count;
    }
    if (count >= 2 && config_.gravity > 0) {
        const double slope = (count * szp - sz * sp) / (count * szz - sz * sz);
        s.gradient = -slope / (config_.liquid.density * config_.gravity) - 1;
    }
    return s;
}

// The top of the bed for the gradient's fit: the sand's surface (its highest grain), unless the
// rows under it hold grains for less than a fifth of their volume. Those rows are a boil's plume,
// or grains thrown up to the rim, in free water: fitted with the bed, their level pressure took
// the gradient down (piping3D read i = 0.92 with a grain at the rim while its bed carried i_c).
// Found from the surface down, so that a gap under a bed lifted off the filter does not cut it.
// A layer of points fills a row to (1 - n) / solid_per_cell, 0.22 even at n = 0.55 with two; a
// flat surface's own row is never cut. A mound a quarter of the width wide (a heaving stripe's)
// is cut: the fit then ends at the level bed beside it.
template <int D>
Real DoublePointSolver<D>::bedTop(Real sandSurface) const {
    constexpr Real kSparse = 0.2;  // -, grains' share of a row's volume below which it is not bed
    const Index rows = grid_.cells(D - 1);
    const Index surfaceRow = std::min<Index>(static_cast<Index>(sandSurface / grid_.h()), rows - 1);
    if (sandBottomRow_ >= surfaceRow) return sandSurface;
    std::vector<Real> grains(rows, 0.0);
    for (std::size_t p = 0; p < solid_.size(); ++p) {
        const Index r = std::clamp<Index>(static_cast<Index>(solid_.x[p * D + D - 1] / grid_.h()), 0, rows - 1);
        grains[r] += solid_.mass[p] / materials_[solid_.material[p]].grainDensity;
    }
    sumOverRanks(grains);
    const Real rowVolume = grid_.crossSection() * grid_.h();
    if (grains[surfaceRow - 1] >= kSparse * rowVolume) return sandSurface;
    Index r = surfaceRow - 1;
    while (r > sandBottomRow_ && grains[r] < kSparse * rowVolume) --r;
    return (r + 1) * grid_.h();
}

template <int D>
void DoublePointSolver<D>::measureStates(ColumnState& s) const {
    // per cell row: solid mass, and how much of it is fluidised
    const Index rows = grid_.cells(D - 1);
    std::vector<Real> mass(rows, 0.0), fluid(rows, 0.0);
    Real total = 0, totalFluid = 0;
    for (std::size_t p = 0; p < solid_.size(); ++p) {
        const Index r = std::clamp<Index>(static_cast<Index>(solid_.x[p * D + D - 1] / grid_.h()), 0, rows - 1);
        mass[r] += solid_.mass[p];
        total += solid_.mass[p];
        if (solid_.state[p] == kFluidisedState) {
            fluid[r] += solid_.mass[p];
            totalFluid += solid_.mass[p];
        }
    }
    if (ranks_) {
        sumOverRanks(mass);
        sumOverRanks(fluid);
        total = sumOverRanks(total);
        totalFluid = sumOverRanks(totalFluid);
    }
    s.fluidisedShare = total > 0 ? totalFluid / total : 0.0;
    // the front: the run of rows above the filter in the state of the lowest sand row, its top
    // refined by the share of the next row still in that state (a row's state: most of its mass)
    s.fluidisedFront = config_.filterLevel();
    Index r = sandBottomRow_;
    if (r >= rows || mass[r] <= 0) return;
    const bool bottomFluid = 2 * fluid[r] > mass[r];
    if (!bottomFluid && totalFluid == 0) return;  // nothing fluidised: no front, at the filter
    auto share = [&](Index k) {
        if (mass[k] <= 0) return Real(0);
        return bottomFluid ? fluid[k] / mass[k] : 1 - fluid[k] / mass[k];
    };
    while (r < rows && mass[r] > 0 && 2 * share(r) >= 1) ++r;
    s.fluidisedFront = grid_.h() * (r + ((r < rows) ? share(r) : Real(0)));
}

template <int D>
std::vector<CellRow> DoublePointSolver<D>::profile() const {
    const Index rows = grid_.cells(D - 1);
    const Index perRow = grid_.numCells() / rows;
    std::vector<CellRow> out(rows);
    for (Index r = 0; r < rows; ++r) {
        CellRow& row = out[r];
        row.z = grid_.cellCentre(r);
        Real pw = 0, w = 0;
        for (Index k = 0; k < perRow; ++k) {
            const Index c = r * perRow + k;
            // every point a rank holds is its own; a cell's water is its owner's
            row.liquidCount += static_cast<int>(cells_.liquidStart[c + 1] - cells_.liquidStart[c]);
            if (!ownsCell(c)) continue;
            pw += water_.pressure[c] * water_.weight[c];
            w += water_.weight[c];
        }
        row.porePressure = pw;  // the weighted sum until the ranks' are added (below)
        row.filterVelocity = w;
    }
    if (ranks_) {
        std::vector<Real> sums(static_cast<std::size_t>(3 * rows));
        for (Index r = 0; r < rows; ++r) {
            sums[3 * r] = out[r].porePressure;
            sums[3 * r + 1] = out[r].filterVelocity;
            sums[3 * r + 2] = out[r].liquidCount;
        }
        sumOverRanks(sums);
        for (Index r = 0; r < rows; ++r) {
            out[r].porePressure = sums[3 * r];
            out[r].filterVelocity = sums[3 * r + 1];
            out[r].liquidCount = static_cast<int>(sums[3 * r + 2]);
        }
    }
    for (auto& row : out) {
        row.porePressure = row.filterVelocity > 0 ? row.porePressure / row.filterVelocity : 0.0;
        row.filterVelocity = 0;
    }
    // row means over the solid points, each weighted by the ring it stands for in axisymmetry (its
    // radius), equally elsewhere
    std::vector<Real> weight(rows, 0.0);
    const bool axisymmetric = grid_.axisymmetric();
    for (std::size_t p = 0; p < solid_.size(); ++p) {
        const Index r = std::clamp<Index>(static_cast<Index>(solid_.x[p * D + D - 1] / grid_.h()), 0, rows - 1);
        const Real w = axisymmetric ? solid_.x[p * D] : 1.0;
        out[r].verticalStress += w * solid_.stress[p * 6 + 2];
        out[r].horizontalStress += w * solid_.stress[p * 6 + 0];
        const Real n = solid_.porosity[p];
        out[r].minPorosity = out[r].solidCount ? std::min(out[r].minPorosity, n) : n;
        out[r].maxPorosity = out[r].solidCount ? std::max(out[r].maxPorosity, n) : n;
        out[r].porosity += w * n;
        if (solid_.state[p] == kFluidisedState) out[r].fluidisedShare += w;
        ++out[r].solidCount;
        weight[r] += w;
    }
    if (ranks_) {  // the rows' sums over the ranks, and their extremes
        constexpr int kSums = 6;
        std::vector<Real> sums(static_cast<std::size_t>(kSums * rows)), low(rows), high(rows);
        for (Index r = 0; r < rows; ++r) {
            const CellRow& row = out[r];
            const Real v[kSums] = {row.verticalStress, row.horizontalStress, row.porosity, row.fluidisedShare,
                                   Real(row.solidCount), weight[r]};
            for (int k = 0; k < kSums; ++k) sums[kSums * r + k] = v[k];
            low[r] = row.solidCount ? row.minPorosity : HUGE_VAL;
            high[r] = row.solidCount ? row.maxPorosity : -HUGE_VAL;
        }
        sumOverRanks(sums);
        ranks_->comm().minInPlace(low);
        ranks_->comm().maxInPlace(high);
        for (Index r = 0; r < rows; ++r) {
            CellRow& row = out[r];
            row.verticalStress = sums[kSums * r];
            row.horizontalStress = sums[kSums * r + 1];
            row.porosity = sums[kSums * r + 2];
            row.fluidisedShare = sums[kSums * r + 3];
            row.solidCount = static_cast<int>(sums[kSums * r + 4]);
            weight[r] = sums[kSums * r + 5];
            row.minPorosity = row.solidCount ? low[r] : 0.0;
            row.maxPorosity = row.solidCount ? high[r] : 0.0;
        }
    }
    for (Index r = 0; r < rows; ++r) {
        auto& row = out[r];
        if (row.solidCount > 0) {
            row.verticalStress /= weight[r];
            row.horizontalStress /= weight[r];
            row.porosity /= weight[r];
            row.fluidisedShare /= weight[r];
        }
        Real q = 0, a = 0;
        for (Index i = r * grid_.nodeStride(D - 1); i < (r + 1) * grid_.nodeStride(D - 1); ++i) {
            if (!ownsNode(i)) continue;
            const Real wgt = nodeFootprint(grid_, i);
            q += wgt * nodes_.porosity[i] * (nodes_.velL[i * D + D - 1] - nodes_.fedWeight[i * D + D - 1] * nodes_.velS[i * D + D - 1]);
            a += wgt;
        }
        q = sumOverRanks(q);  // one reduction per row: a profile is taken at outputs only
        a = sumOverRanks(a);
        row.filterVelocity = a > 0 ? q / a : 0.0;
    }
    return out;
}

namespace {
/// m3/s through a column's base cell c: q = n (v_L - w v_S) at its lower nodes, each weighted by
/// its share of the cell's lower face, times the face's area (sandCells says why)
template <int D>
Real baseFlux(const Grid<D>& grid, const NodeFields<D>& nodes, Index c) {
    Real q = 0, weight = 0;
    grid.forEachNodeOfCell(c, [&](Index i, int corner) {
        if ((corner >> (D - 1)) & 1) return;  // an upper node
        const Real w = grid.cellShare(c, corner);
        q += w * nodes.porosity[i] * (nodes.velL[i * D + D - 1] - nodes.fedWeight[i * D + D - 1] * nodes.velS[i * D + D - 1]);
        weight += w;
    });
    return q / weight * grid.cellVolume(c) / grid.h();
}
}  // namespace

template <int D>
SandCells DoublePointSolver<D>::sandCells() const {
    SandCells s;
    s.dimension = D;
    for (int d = 0; d < D; ++d) s.cells[d] = grid_.cells(d);
    s.h = grid_.h();
    s.filterLevel = sandFloor_;
    s.baseRow = sandBottomRow_;
    s.axisymmetric = grid_.axisymmetric();
    const Index cells = grid_.numCells();
    s.state.assign(cells, CellSand::None);
    s.porosity.assign(cells, std::nan(""));
    if (ranks_) {
        gatherSandCells(s);
        return s;
    }
    for (Index c = 0; c < cells; ++c) {
        if (cells_.solidStart[c] == cells_.solidStart[c + 1]) continue;
        s.state[c] = sand_.fluidised[c] ? CellSand::Fluidised : CellSand::Solid;
        s.porosity[c] = sand_.porosity[c];
    }
    // the water crossing the filter plane per column: q = n (v_L - w v_S) at the base row's lower
    // nodes (as the monitors read it), each node weighted by its share of the cell's lower face
    // (its share of the cell's volume: equal on plane grids, the outer node's larger in
    // axisymmetry), times the face's area. The columns then add up to the section's flux.
    // Sampled at nodes, a step in q between two zones is blended over the node on their edge
    const Index columns = s.columns();
    s.baseFlux.assign(columns, 0.0);
    for (Index k = 0; k < columns; ++k) {
        s.baseFlux[k] = baseFlux(grid_, nodes_, grid_.columnCell(k, sandBottomRow_));
    }
    // the sand's top per column: where a stripe heaves against its neighbours, or a boil rises
    s.surface.assign(columns, std::nan(""));
    for (Index k = 0; k < columns; ++k) {
        const ColumnSurface top = sandSurfaceOfColumn(grid_, solid_, cells_.solidStart, k, config_.points.solidPerCell);
        if (top.row >= 0) s.surface[k] = top.top;
    }
    return s;
}

/// sandCells over MPI ranks, the same on every rank. A cell holds sand where any rank's points
/// are filed in it (after the weir re-files the points by where they are, a point may sit in a
/// cell its rank does not own); its state and porosity are its owner's, computed in the step. A
/// column's surface is the top of its highest sand cell's points, over the ranks; the water
/// through the filter its owner's nodes'.
template <int D>
void DoublePointSolver<D>::gatherSandCells(SandCells& s) const {
    const Index cells = grid_.numCells(), columns = s.columns();
    std::vector<Real> all(static_cast<std::size_t>(3 * cells + columns), 0.0);
    for (Index c = 0; c < cells; ++c) {
        all[c] = static_cast<Real>(cells_.solidStart[c + 1] - cells_.solidStart[c]);
        if (!ownsCell(c)) continue;
        all[cells + c] = sand_.fluidised[c] ? 2 : 1;
        all[2 * cells + c] = sand_.porosity[c];
    }
    s.baseFlux.assign(columns, 0.0);
    for (Index k = 0; k < columns; ++k) {
        if (!ownsColumn(k)) continue;
        all[3 * cells + k] = baseFlux(grid_, nodes_, grid_.columnCell(k, sandBottomRow_));
    }
    sumOverRanks(all);
    for (Index c = 0; c < cells; ++c) {
        const bool sand = all[c] > 0;
        s.state[c] = sand ? static_cast<CellSand>(static_cast<int>(all[cells + c])) : CellSand::None;
        s.porosity[c] = sand ? all[2 * cells + c] : std::nan("");
    }
    for (Index k = 0; k < columns; ++k) s.baseFlux[k] = all[3 * cells + k];
    // the surfaces: the highest row with sand over the ranks, then the top of its points
    std::vector<Real> row(columns), top(columns);
    for (Index k = 0; k < columns; ++k)
        row[k] = static_cast<Real>(sandSurfaceOfColumn(grid_, solid_, cells_.solidStart, k, config_.points.solidPerCell).row);
    std::vector<Real> highest = row;
    ranks_->comm().maxInPlace(highest);
    for (Index k = 0; k < columns; ++k) {
        const ColumnSurface mine = sandSurfaceOfColumn(grid_, solid_, cells_.solidStart, k, config_.points.solidPerCell);
        top[k] = (mine.row >= 0 && mine.row == static_cast<Index>(highest[k])) ? mine.top : -HUGE_VAL;
    }
    ranks_->comm().maxInPlace(top);
    s.surface.assign(columns, std::nan(""));
    for (Index k = 0; k < columns; ++k)
        if (highest[k] >= 0) s.surface[k] = top[k];
}

template ColumnState DoublePointSolver<1>::columnState() const;
template ColumnState DoublePointSolver<2>::columnState() const;
template ColumnState DoublePointSolver<3>::columnState() const;
template std::vector<CellRow> DoublePointSolver<1>::profile() const;
template std::vector<CellRow> DoublePointSolver<2>::profile() const;
template std::vector<CellRow> DoublePointSolver<3>::profile() const;
template SandCells DoublePointSolver<2>::sandCells() const;
template void DoublePointSolver<2>::gatherSandCells(SandCells&) const;
template void DoublePointSolver<3>::gatherSandCells(SandCells&) const;
template SandCells DoublePointSolver<3>::sandCells() const;
template std::vector<Real> DoublePointSolver<1>::sandFeeding() const;
template std::vector<Real> DoublePointSolver<2>::sandFeeding() const;
template std::vector<Real> DoublePointSolver<3>::sandFeeding() const;

}  // namespace qs
