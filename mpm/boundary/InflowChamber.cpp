#include "boundary/InflowChamber.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace qs {

template <int D>
void InflowChamber<D>::setup(const Grid<D>& grid, Real pointHeight, int pointsPerCell) {
    pointsPerCell_ = pointsPerCell;
    Index slots = 1;
    for (int d = 0; d < D - 1; ++d) slots *= grid.cells(d) * pointsPerCell;
    gaps_.assign(slots, 0.0);
    pointHeight_ = pointHeight;
    scan_.assign(slots, Scan{});
}

template <int D>
void InflowChamber<D>::slotCentre(const Grid<D>& grid, Index slot, Real* centre) const {
    const Real spacing = grid.h() / pointsPerCell_;
    for (int d = 0; d < D - 1; ++d) {
        const Index n = grid.cells(d) * pointsPerCell_;
        centre[d] = (slot % n + 0.5) * spacing;
        slot /= n;
    }
}

template <int D>
Real InflowChamber<D>::slotFootprint(const Grid<D>& grid, Index slot) const {
    Real centre[D > 1 ? D - 1 : 1] = {};
    slotCentre(grid, slot, centre);
    return grid.pointFootprint(centre, pointsPerCell_);
}

template <int D>
Real InflowChamber<D>::gapVolume(const Grid<D>& grid) const {
    Real v = 0;
    for (Index slot = 0; slot < static_cast<Index>(gaps_.size()); ++slot) v += gaps_[slot] * slotFootprint(grid, slot);
    return v;
}

template <int D>
Index InflowChamber<D>::slotOf(const Grid<D>& grid, const Real* x) const {
    const Real spacing = grid.h() / pointsPerCell_;
    Index slot = 0, stride = 1;
    for (int d = 0; d < D - 1; ++d) {
        const Index n = grid.cells(d) * pointsPerCell_;
        const Index k = std::clamp<Index>(static_cast<Index>(std::floor(x[d] / spacing)), 0, n - 1);
        slot += k * stride;
        stride *= n;
    }
    return slot;
}

template <int D>
Real InflowChamber<D>::gapAtNode(const Grid<D>& grid, Index node) const {
    if (D == 1) return gaps_[0];
    // the slots whose centres lie in the node's footprint (half a cell either side, inside the
    // grid): the gap the node's water sees
    const IVec<D> n = grid.nodeCoords(node);
    const int lpc = pointsPerCell_;
    Index lo[D], hi[D], count[D];
    for (int d = 0; d < D - 1; ++d) {
        const Index slots = grid.cells(d) * lpc;
        lo[d] = std::max<Index>(0, n[d] * lpc - lpc / 2);
        hi[d] = std::min<Index>(slots, n[d] * lpc + (lpc + 1) / 2);
        count[d] = hi[d] - lo[d];
    }
    Index total = 1;
    for (int d = 0; d < D - 1; ++d) total *= count[d];
    // weighted by the slots' footprints (equal shares but in axisymmetry, where they grow with r)
    Real sum = 0, weight = 0;
    for (Index k = 0; k < total; ++k) {
        Index rest = k, slot = 0, stride = 1;
        for (int d = 0; d < D - 1; ++d) {
            slot += (lo[d] + rest % count[d]) * stride;
            rest /= count[d];
            stride *= grid.cells(d) * lpc;
        }
        const Real w = grid.axisymmetric() ? slotFootprint(grid, slot) : 1.0;
        sum += w * gaps_[slot];
        weight += w;
    }
    return sum / weight;
}

template <int D>
void InflowChamber<D>::inject(const Grid<D>& grid, LiquidPoints<D>& liquid,
                              const std::vector<Index>& liquidCellStart, Real density,
                              const std::vector<Real>& cellPressureGradient) {
    const Real height = pointHeight_;
    const Index slots = static_cast<Index>(gaps_.size());
    // the lowest liquid point of every slot, from the chamber's two lowest cell rows
    for (auto& s : scan_) s = Scan{};
    Index columns = 1;
    for (int d = 0; d < D - 1; ++d) columns *= grid.cells(d);
    for (Index c = 0; c < 2 * columns && c < grid.numCells(); ++c) {
        for (Index p = liquidCellStart[c]; p < liquidCellStart[c + 1]; ++p) {
            const Index slot = slotOf(grid, &liquid.x[p * D]);
            Scan& s = scan_[slot];
            const Real z = liquid.x[p * D + D - 1];
            s.bottom = std::min(s.bottom, z - 0.5 * liquid.volume[p] / slotFootprint(grid, slot));
            if (s.ref < 0 || z < liquid.x[s.ref * D + D - 1]) {
                s.ref = p;
                s.cell = c;
            }
        }
    }
    for (Index slot = 0; slot < slots; ++slot) {
        if (!owned_.empty() && !owned_[slot]) continue;  // another rank's
        const Scan& s = scan_[slot];
        QS_CHECK(s.ref >= 0, "the chamber's injection slot " << slot << " has no liquid in its two lowest cell rows: "
                             "the water left the chamber faster than one cell per step (reduce time.courant)");
        Real centre[D > 1 ? D - 1 : 1] = {};
        slotCentre(grid, slot, centre);
        const Real pointVolume = height * slotFootprint(grid, slot);
        Real bottom = std::min(s.bottom, grid.top());
        const Index ref = s.ref;
        while (bottom >= height) {
            for (int d = 0; d < D - 1; ++d) liquid.x.push_back(centre[d]);
            const Real z = bottom - 0.5 * height;
            liquid.x.push_back(z);
            // the new water moves and is pressed like the water just above it: its pressure is
            // that water's cell's field where it is put (the field the next step reads its cells'
            // water from, PorePressure.cpp), or the limit, with its cavity, if that water is there
            Real pressure = liquid.pressure[ref];
            if (liquid.cavity[ref] == 0) {
                const Index at = liquid.x.size() - D;
                for (int d = 0; d < D; ++d)
                    pressure += cellPressureGradient[s.cell * D + d] * (liquid.x[at + d] - liquid.x[ref * D + d]);
            }
            for (int d = 0; d < D; ++d) liquid.v.push_back(liquid.v[ref * D + d]);
            liquid.mass.push_back(density * pointVolume);
            liquid.volume.push_back(pointVolume);
            liquid.pressure.push_back(pressure);
            liquid.state.push_back(kSubmergedLiquid);
            liquid.cavity.push_back(liquid.cavity[ref]);
            injected_ += pointVolume;
            bottom -= height;
        }
        gaps_[slot] = std::max(Real(0), bottom);
    }
}

template class InflowChamber<1>;
template class InflowChamber<2>;
template class InflowChamber<3>;

}  // namespace qs
