#include "physics/Pipes.hpp"

#include <algorithm>
#include <cmath>

#include "core/Constants.hpp"

namespace qs {

namespace {

/// Labels the cells for which `member(c)` holds by connected region (face neighbours), -1
/// elsewhere; returns the number of regions. An explicit stack, not recursion: a region may hold
/// every cell of the grid.
template <class Member>
Index labelRegions(const SandCells& s, std::vector<Index>& label, Member&& member) {
    const int D = s.dimension;
    const Index total = static_cast<Index>(s.state.size());
    label.assign(total, -1);
    std::vector<char> in(total);
    for (Index c = 0; c < total; ++c) in[c] = member(c);
    Index stride[3] = {1, s.cells[0], D == 3 ? s.cells[0] * s.cells[1] : s.cells[0]};
    std::vector<Index> stack;
    Index regions = 0;
    for (Index start = 0; start < total; ++start) {
        if (!in[start] || label[start] >= 0) continue;
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
                    if (in[n] && label[n] < 0) {
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

/// Per column, the highest row of the bed's sand: the sand (solid or fluidised) connected to the
/// lowest sand in the grid, on the filter or, for a plug lifted off it, above; -1 where a column
/// has none. Sand thrown up and floating apart from the bed is not its roof, so the free water
/// under it is not a pocket.
std::vector<Index> bedTops(const SandCells& s) {
    std::vector<Index> label;
    const Index regions = labelRegions(s, label, [&](Index c) { return s.state[c] != CellSand::None; });
    std::vector<char> bed(regions, 0);
    const Index columns = s.columns();
    Index lowest = -1;
    for (Index c = 0; c < static_cast<Index>(label.size()) && lowest < 0; ++c)
        if (label[c] >= 0) lowest = c / columns;
    if (lowest >= 0)
        for (Index k = 0; k < columns; ++k) {
            const Index c = s.cell(k, lowest);
            if (label[c] >= 0) bed[label[c]] = 1;
        }
    std::vector<Index> top(columns, -1);
    for (Index c = 0; c < static_cast<Index>(label.size()); ++c)
        if (label[c] >= 0 && bed[label[c]]) top[c % columns] = std::max(top[c % columns], c / columns);
    return top;
}

/// Whether a cell is open to the water's flow through the bed: fluidised, or a pocket of water,
/// a cell with no sand at or above the filter under the bed's sand in its column (and under the
/// column's sand surface). When a pipe empties the sand from its base the pocket is still the
/// channel's foot (piping2D's left wall, 8 to 11.5 s, was missed without it). The chamber below
/// the filter, the free water above the sand and under sand afloat apart from the bed are not
/// pockets; without the columns' surfaces nothing is.
bool isOpen(const SandCells& s, const std::vector<Index>& bedTop, Index c) {
    if (s.state[c] == CellSand::Fluidised) return true;
    if (s.state[c] != CellSand::None || s.surface.empty()) return false;
    const Index columns = s.columns(), row = c / columns;
    if (row < s.baseRow || row >= bedTop[c % columns]) return false;
    const Real top = s.surface[c % columns];
    return std::isfinite(top) && (row + 1) * s.h <= top + 1e-9 * s.h;
}

}  // namespace

PipeSurvey findPipes(const SandCells& s) {
    PipeSurvey survey;
    const int D = s.dimension;
    const Index columns = s.columns();
    const std::vector<Index> bedTop = bedTops(s);
    std::vector<Index> label;
    const Index regions = labelRegions(s, label, [&](Index c) { return isOpen(s, bedTop, c); });
    // a region of open cells without fluidised sand is a cavity under solid sand: it neither pipes
    // nor counts as the fluidised sand's share of the water
    std::vector<Index> fluidisedIn(regions, 0);
    for (Index c = 0; c < static_cast<Index>(label.size()); ++c)
        if (label[c] >= 0 && s.state[c] == CellSand::Fluidised) ++fluidisedIn[label[c]];

    // the base row: water through it, and whether any of it is still solid
    Real totalFlux = 0, fluidisedFlux = 0;
    bool solidAtBase = false;
    for (Index k = 0; k < columns; ++k) {
        const Index base = s.cell(k, s.baseRow);
        totalFlux += s.baseFlux[k];
        if (label[base] >= 0 && fluidisedIn[label[base]] > 0) fluidisedFlux += s.baseFlux[k];
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
