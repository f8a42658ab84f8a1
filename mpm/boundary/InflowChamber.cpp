#include "boundary/InflowChamber.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace qs {

template <int D>
void InflowChamber<D>::setup(const Grid<D>& grid, Real pointVolume, int pointsPerCell) {
    Index columns = 1;
    for (int d = 0; d < D - 1; ++d) columns *= grid.cells(d);
    gaps_.assign(columns, 0.0);
    pointVolume_ = pointVolume;
    pointsPerCell_ = pointsPerCell;
}

template <int D>
Real InflowChamber<D>::gapVolume(const Grid<D>& grid) const {
    Real v = 0;
    for (Real g : gaps_) v += g;
    return v * grid.footprint();
}

template <int D>
Real InflowChamber<D>::gapAtNode(const Grid<D>& grid, Index node) const {
    if (D == 1) return gaps_[0];
    const IVec<D> n = grid.nodeCoords(node);
    Real sum = 0;
    int count = 0;
    // the columns whose lower corner along each horizontal axis is n[d] - 1 or n[d]
    for (int corner = 0; corner < (1 << (D - 1)); ++corner) {
        Index col = 0, stride = 1;
        bool inside = true;
        for (int d = 0; d < D - 1; ++d) {
            const Index c = n[d] - 1 + ((corner >> d) & 1);
            if (c < 0 || c >= grid.cells(d)) inside = false;
            col += c * stride;
            stride *= grid.cells(d);
        }
        if (!inside) continue;
        sum += gaps_[col];
        ++count;
    }
    return sum / count;
}

template <int D>
void InflowChamber<D>::inject(const Grid<D>& grid, LiquidPoints<D>& liquid,
                              const std::vector<Index>& liquidCellStart, Real density, Real gravity,
                              Real fallbackPressure) {
    const int lpc = pointsPerCell_;
    const Real footprint = grid.footprint() / std::pow(Real(lpc), D - 1);
    const Real height = pointVolume_ / footprint;
    const Real spacing = grid.h() / lpc;
    const int rowPoints = static_cast<int>(std::pow(lpc, D - 1));
    for (Index col = 0; col < static_cast<Index>(gaps_.size()); ++col) {
        // the lowest liquid point of the column, in its two lowest cell rows
        Index ref = -1;
        Real bottom = grid.top();
        for (Index row = 0; row < 2; ++row) {
            const Index c = col + row * grid.cellStride(D - 1);
            for (Index p = liquidCellStart[c]; p < liquidCellStart[c + 1]; ++p) {
                const Real z = liquid.x[p * D + D - 1];
                bottom = std::min(bottom, z - 0.5 * liquid.volume[p] / footprint);
                if (ref < 0 || z < liquid.x[ref * D + D - 1]) ref = p;
            }
        }
        const IVec<D> cc = grid.cellCoords(col);
        QS_CHECK(ref >= 0, "the chamber's column " << col << " has no liquid in its two lowest cell rows: the "
                           "water left the chamber faster than one cell per step (reduce time.courant)");
        while (bottom >= height) {
            for (int k = 0; k < rowPoints; ++k) {
                int rest = k;
                for (int d = 0; d < D - 1; ++d) {
                    liquid.x.push_back(cc[d] * grid.h() + (rest % lpc + 0.5) * spacing);
                    rest /= lpc;
                }
                const Real z = bottom - 0.5 * height;
                liquid.x.push_back(z);
                // the new water moves and is pressed like the water just above it
                for (int d = 0; d < D; ++d) liquid.v.push_back(ref >= 0 ? liquid.v[ref * D + d] : 0.0);
                liquid.mass.push_back(density * pointVolume_);
                liquid.volume.push_back(pointVolume_);
                liquid.pressure.push_back(ref >= 0 ? liquid.pressure[ref] + density * gravity * (liquid.x[ref * D + D - 1] - z)
                                                   : fallbackPressure);
                liquid.state.push_back(kSubmergedLiquid);
                injected_ += pointVolume_;
            }
            bottom -= height;
        }
        gaps_[col] = std::max(Real(0), bottom);
    }
}

template class InflowChamber<1>;
template class InflowChamber<2>;
template class InflowChamber<3>;

}  // namespace qs
