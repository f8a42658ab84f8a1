#include "physics/Pipes.hpp"

#include <algorithm>
#include <cmath>

#include "core/Constants.hpp"

namespace qs {

namespace {

/// Whether a cell is open to the water's flow through the bed: fluidised, or a pocket of water,
/// a cell with no sand at or above the filter under its column's sand surface. When a pipe empties
/// the sand from its base the pocket is still the channel's foot (piping2D's left wall, 8 to
/// 11.5 s, was missed without it). The chamber below the filter and the free water above the
/// sand are not pockets.
bool isOpen(const SandCells& s, Index c) {
    if (s.state[c] == CellSand::Fluidised) return true;
    if (s.state[c] != CellSand::None) return false;
    const Index columns = s.columns(), row = c / columns;
    if (row < s.baseRow) return false;
    const Real top = s.surface.empty() ? Real(NAN) : s.surface[c % columns];
    const Real cellTop = (row + 1) * s.h;
    return std::isfinite(top) && cellTop <= top + 1e-9 * s.h;
}

/// Labels the open cells (isOpen) by connected region (face neighbours), -1 elsewhere; returns the
/// number of regions. An explicit stack, not recursion: a region may hold every cell of the grid.
Index labelRegions(const SandCells& s, std::vector<Index>& label) {
    const int D = s.dimension;
    const Index total = static_cast<Index>(s.state.size());
    label.assign(total, -1);
    std::vector<char> open(total);
    for (Index c = 0; c < total; ++c) open[c] = isOpen(s, c);
    Index stride[3] = {1, s.cells[0], D == 3 ? s.cells[0] * s.cells[1] : s.cells[0]};
    std::vector<Index> stack;
    Index regions = 0;
    for (Index start = 0; start < total; ++start) {
        if (!open[start] || label[start] >= 0) continue;
        label[start] = regions;
        stack.push_back(start);
        while (!stack.empty()) {
            const Index c = stack.back();
            stack.pop_back();
            Index rest = c;
            for (int d = 0; d < D; ++d) {
                const Index k = (d == D - 1) ? rest : rest % s.cells[d];
                if (d < D - 1) rest /= s.cells[d];
                for (int side : {-1, 1}) {
                    const Index kn = k + side;
                    if (kn < 0 || kn >= s.cells[d]) continue;
                    const Index n = c + side * stride[d];
                    if (open[n] && label[n] < 0) {
                        label[n] = regions;
                        stack.push_back(n);
                    }
                }
            }
        }
        ++regions;
    }
    return regions;
}

}  // namespace

PipeSurvey findPipes(const SandCells& s) {
    PipeSurvey survey;
    const int D = s.dimension;
    const Index columns = s.columns();
    std::vector<Index> label;
    const Index regions = labelRegions(s, label);

    // the base row: water through it, and whether any of it is still solid
    Real totalFlux = 0, fluidisedFlux = 0;
    bool solidAtBase = false;
    for (Index k = 0; k < columns; ++k) {
        const Index base = s.cell(k, s.baseRow);
        totalFlux += s.baseFlux[k];
        if (isOpen(s, base)) fluidisedFlux += s.baseFlux[k];
        if (s.state[base] == CellSand::Solid) solidAtBase = true;
    }
    auto share = [&](Real flux) { return totalFlux > 0 ? flux / totalFlux : Real(0); };
    survey.fluidisedFluxShare = share(fluidisedFlux);
    if (!solidAtBase || regions == 0) return survey;

    struct Tally {
        bool fromFilter = false, wall = false;
        Index count = 0, fluidised = 0, lowRow = -1, highRow = -1;
        Real sumX = 0, sumY = 0, baseFlux = 0;
    };
    std::vector<Tally> tally(regions);
    for (Index c = 0; c < static_cast<Index>(label.size()); ++c) {
        const Index r = label[c];
        if (r < 0) continue;
        Tally& t = tally[r];
        const Index column = c % columns, row = c / columns;
        const Index i = column % s.cells[0], j = D == 3 ? column / s.cells[0] : 0;
        ++t.count;
        if (s.state[c] == CellSand::Fluidised) ++t.fluidised;
        t.sumX += (i + 0.5) * s.h;
        t.sumY += (j + 0.5) * s.h;
        t.lowRow = t.lowRow < 0 ? row : std::min(t.lowRow, row);
        t.highRow = std::max(t.highRow, row);
        if ((i == 0 && !s.axisymmetric) || i == s.cells[0] - 1) t.wall = true;
        if (D == 3 && (j == 0 || j == s.cells[1] - 1)) t.wall = true;
        if (row == s.baseRow) {
            t.fromFilter = true;
            t.baseFlux += s.baseFlux[column];
        }
    }
    for (const Tally& t : tally) {
        const Index tall = t.highRow - s.baseRow + 1;
        // a pocket of water with no fluidised sand is a cavity under solid sand, not a pipe
        if (!t.fromFilter || tall < kMinimumPipeRows || t.fluidised == 0) continue;
        Pipe p;
        p.cellCount = t.count;
        p.x = t.sumX / t.count;
        p.y = D == 3 ? t.sumY / t.count : 0.0;
        const Real spanned = static_cast<Real>(t.highRow - t.lowRow + 1);
        p.width = D == 3 ? std::sqrt(4 * t.count * s.h * s.h / (kPi * spanned)) : t.count * s.h / spanned;
        p.height = (t.highRow + 1) * s.h - s.filterLevel;
        p.wall = t.wall;
        p.fluxShare = share(t.baseFlux);
        survey.pipes.push_back(p);
    }
    std::stable_sort(survey.pipes.begin(), survey.pipes.end(),
                     [](const Pipe& a, const Pipe& b) { return a.fluxShare > b.fluxShare; });
    return survey;
}

}  // namespace qs
