#include "parallel/Decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/Error.hpp"
#include "parallel/DistributedPressureSolver.hpp"
#include "solver/ColumnBuilder.hpp"
#include "solver/RunSize.hpp"

namespace qs {

namespace {

/// The points per cell of each cell row (the vertical axis), solid and liquid, as the case lays
/// them out: the chamber's and the surface water's free-water lattice, the sand's lattices in
/// the layers; a row that a level crosses takes its share.
struct RowPoints {
    std::vector<double> solid, liquid;
};

RowPoints rowPoints(const CaseConfig& config, Index rows) {
    const int D = config.grid.dimension;
    const double h = config.grid.cellSize;
    const double spc = config.points.solidPerCell, lpc = config.points.liquidPerCell;
    const double horizontal = std::pow(lpc, D - 1);
    const double freeWater = freeWaterPointsPerCell(config) * horizontal;
    const double sand = std::pow(spc, D), sandWater = std::pow(lpc, D);
    RowPoints r{std::vector<double>(rows, 0.0), std::vector<double>(rows, 0.0)};
    auto add = [&](double z0, double z1, double solid, double liquid) {
        for (Index k = 0; k < rows; ++k) {
            const double share = std::max(0.0, std::min(z1, (k + 1) * h) - std::max(z0, k * h)) / h;
            r.solid[k] += share * solid;
            r.liquid[k] += share * liquid;
        }
    };
    add(0, config.filterLevel(), 0, freeWater);
    double z = config.filterLevel();
    for (const auto& layer : config.layers) {
        add(z, z + layer.thickness, sand, sandWater);
        z += layer.thickness;
    }
    if (config.column.waterLevel > z) add(z, config.column.waterLevel, 0, freeWater);
    return r;
}

/// Cuts [0, n) into `parts` pieces of about equal work (work[k] the k-th cell's), each at least
/// `least` cells long; empty when that cannot be done.
std::vector<Index> cutByWork(const std::vector<double>& work, int parts, Index least) {
    const Index n = static_cast<Index>(work.size());
    if (Index(parts) * least > n) return {};
    double total = 0;
    for (double w : work) total += w;
    std::vector<Index> cuts{0};
    double done = 0;
    Index k = 0;
    for (int p = 1; p < parts; ++p) {
        const double target = total * p / parts;
        // room for this part's least cells and the rest's
        const Index lowest = cuts.back() + least, highest = n - Index(parts - p) * least;
        k = std::max(k, cuts.back());
        while (k < lowest) done += work[k++];
        // stop at the face nearer the target
        while (k < highest && done + 0.5 * work[k] < target) done += work[k++];
        cuts.push_back(k);
    }
    cuts.push_back(n);
    return cuts;
}

std::vector<Index> evenCuts(Index n, int parts, Index least) {
    if (Index(parts) * least > n) return {};
    std::vector<Index> cuts;
    for (int p = 0; p <= parts; ++p) cuts.push_back(n * p / parts);
    return cuts;
}

/// The blocks of one process grid, or an empty decomposition when an axis cannot be cut so.
Decomposition blocksOf(const CaseConfig& config, const std::array<Index, 3>& cells, const std::array<int, 3>& parts,
                       int ghostLayers, const RowPoints& rows) {
    const int D = config.grid.dimension;
    Decomposition d;
    d.dimension = D;
    d.ghostLayers = ghostLayers;
    d.parts = parts;
    d.ranks = parts[0] * parts[1] * parts[2];
    const Index least = ghostLayers + 1;
    for (int a = 0; a < 3; ++a) {
        if (a >= D) {
            d.cuts[a] = {0, 1};
            continue;
        }
        if (a < D - 1) {
            d.cuts[a] = parts[a] == 1 ? std::vector<Index>{0, cells[a]} : evenCuts(cells[a], parts[a], least);
        } else {
            std::vector<double> work(cells[a]);
            for (Index k = 0; k < cells[a]; ++k) work[k] = rows.solid[k] + rows.liquid[k] + 1;  // + the node loop
            d.cuts[a] = parts[a] == 1 ? std::vector<Index>{0, cells[a]} : cutByWork(work, parts[a], least);
        }
        if (d.cuts[a].empty()) return Decomposition{};
    }
    const EntityBytes bytes = entityBytes(config);
    const Index windowLayers = ghostPointLayers(config);
    d.windowLayers = static_cast<int>(windowLayers);
    Index gridNodes = 1, gridCells = 1;
    for (int a = 0; a < D; ++a) gridNodes *= cells[a] + 1, gridCells *= cells[a];
    const double densest = 1.25 * freeWaterPointsPerCell(config) * std::pow(config.points.liquidPerCell, D - 1);
    for (int kz = 0; kz < parts[2]; ++kz)
        for (int ky = 0; ky < parts[1]; ++ky)
            for (int kx = 0; kx < parts[0]; ++kx) {
                const std::array<int, 3> k{kx, ky, kz};
                DecompositionBlock b;
                Index owned = 1, reach = 1, columns = 1;
                b.cells = 1;
                for (int a = 0; a < 3; ++a) {
                    b.cellBegin[a] = d.cuts[a][k[a]];
                    b.cellEnd[a] = d.cuts[a][k[a] + 1];
                    const Index extent = b.cellEnd[a] - b.cellBegin[a];
                    b.cells *= extent;
                    if (a >= D) continue;
                    const bool last = k[a] == parts[a] - 1;
                    owned *= extent + (last ? 1 : 0);
                    const Index lo = std::max<Index>(0, b.cellBegin[a] - ghostLayers);
                    const Index hi = std::min<Index>(cells[a], b.cellEnd[a] + ghostLayers);
                    reach *= hi - lo + 1;
                    if (a < D - 1) columns *= extent;
                }
                b.nodes = owned;
                b.ghostNodes = reach - owned;
                for (Index r = b.cellBegin[D - 1]; r < b.cellEnd[D - 1]; ++r) {
                    b.solidPoints += columns * rows.solid[r];
                    b.liquidPoints += columns * rows.liquid[r];
                }
                // the window of ghost points the step keeps: its columns beyond the block's, over
                // the block's rows, at the block's points per column
                Index windowColumns = 1;
                for (int a = 0; a < D - 1; ++a)
                    windowColumns *= std::min<Index>(cells[a], b.cellEnd[a] + windowLayers) -
                                     std::max<Index>(0, b.cellBegin[a] - windowLayers);
                const double points = b.solidPoints + b.liquidPoints;
                b.ghostPoints = columns > 0 ? points * double(windowColumns - columns) / double(columns) : 0.0;
                // today's step keeps the whole grid's node and cell arrays on every rank, and its
                // points with the window's copies (docs/parallel.md)
                const double windowCells = double(windowColumns) * double(b.cellEnd[D - 1] - b.cellBegin[D - 1]);
                const double liquidCapacity =
                    std::max(densest * windowCells, b.liquidPoints * double(windowColumns) / double(columns));
                b.bytes = b.solidPoints * double(windowColumns) / double(columns) * bytes.solid +
                          liquidCapacity * bytes.liquid + double(gridNodes) * bytes.node + double(gridCells) * bytes.cell;
                d.blocks.push_back(b);
            }
    return d;
}

/// The price of a decomposition: its busiest rank's points and node loop, and its ghost nodes
/// exchanged twice a step.
double price(const Decomposition& d) {
    double worst = 0;
    for (const auto& b : d.blocks)
        worst = std::max(worst, b.solidPoints + b.liquidPoints + double(b.cells) + 2 * kGhostNodeCost * double(b.ghostNodes));
    return worst;
}

}  // namespace

double Decomposition::imbalance() const {
    double most = 0, total = 0;
    for (const auto& b : blocks) {
        const double w = b.solidPoints + b.liquidPoints;
        most = std::max(most, w);
        total += w;
    }
    return total > 0 ? most * double(blocks.size()) / total : 1.0;
}

namespace {

std::array<Index, 3> gridCells(const CaseConfig& config) {
    const int D = config.grid.dimension;
    const double h = config.grid.cellSize;
    std::array<Index, 3> cells{1, 1, 1};
    for (int a = 0; a < D - 1; ++a) cells[a] = std::max<Index>(1, std::llround(config.grid.width / h));
    cells[D - 1] = std::max<Index>(1, std::llround(config.column.top / h));
    return cells;
}

int ghostLayersOf(const CaseConfig& config) {
    return config.grid.shapeFunctions == ShapeFunctionKind::Gimp ? 2 : 1;
}

[[noreturn]] void cannotCut(const CaseConfig& config, const std::array<Index, 3>& cells, const std::string& into) {
    const int D = config.grid.dimension, ghostLayers = ghostLayersOf(config);
    std::ostringstream m;
    m << config.caseDirectory << "/case.toml: the grid of ";
    for (int a = 0; a < D; ++a) m << (a ? " x " : "") << cells[a];
    m << " cells (grid.cell_size = " << config.grid.cellSize << " m) cannot be cut into " << into << " of at least "
      << ghostLayers + 1 << " cells along each cut axis (" << ghostLayers << " ghost layer" << (ghostLayers > 1 ? "s" : "")
      << " beside each cut): run on fewer ranks, or on a finer grid";
    throw Error(m.str());
}

}  // namespace

double decompositionPrice(const Decomposition& d) { return price(d); }

Decomposition decomposeAs(const CaseConfig& config, const std::array<int, 3>& parts) {
    const std::array<Index, 3> cells = gridCells(config);
    const int D = config.grid.dimension;
    for (int a = 0; a < 3; ++a)
        QS_CHECK(parts[a] >= 1 && (a < D || parts[a] == 1),
                 "blocks along axis " << a << ": " << parts[a] << ", expected 1 or more (1 beyond the grid's " << D << " axes)");
    Decomposition d = blocksOf(config, cells, parts, ghostLayersOf(config), rowPoints(config, cells[D - 1]));
    if (d.blocks.empty()) {
        std::ostringstream blocks;
        for (int a = 0; a < D; ++a) blocks << (a ? " x " : "") << parts[a];
        cannotCut(config, cells, blocks.str() + " blocks");
    }
    return d;
}

int ghostPointLayers(const CaseConfig& config) {
    return config.grid.shapeFunctions == ShapeFunctionKind::Gimp ? 4 : 2;
}

bool decomposable(const CaseConfig& config, int ranks) {
    try {
        decompose(config, ranks);
        return true;
    } catch (const std::exception&) {  // qs::Error, or a grid too large to price
        return false;
    }
}

bool cutBesideALine(const CaseConfig& config, int ranks) {
    return decomposable(config, ranks) &&
           (config.time.scheme == TimeScheme::Explicit || distributedSolverAvailable());
}

Decomposition decompose(const CaseConfig& config, int ranks) {
    QS_CHECK(ranks >= 1, "the number of ranks is " << ranks << ", expected 1 or more");
    const int D = config.grid.dimension;
    const std::array<Index, 3> cells = gridCells(config);
    const int ghostLayers = ghostLayersOf(config);
    const RowPoints rows = rowPoints(config, cells[D - 1]);

    if (D == 1 && ranks > 1)
        throw Error(config.caseDirectory + "/case.toml: a 1D column (grid.dimension = 1) cannot be cut over " +
                    std::to_string(ranks) + " ranks: its blocks would cut its only column across the height. Run it "
                    "on one rank (a 1D run takes seconds to minutes); 2D, axisymmetric and 3D grids are cut into "
                    "blocks of whole columns. Beside an OpenFOAM line (reservoir.model = \"openfoam\") a 1D column "
                    "does run on ranks: the line is decomposed and each rank steps the column whole");
    Decomposition best;
    double bestPrice = std::numeric_limits<double>::infinity();
    for (int px = 1; px <= ranks; ++px) {
        if (ranks % px) continue;
        const int py = ranks / px;
        if (D == 1 || (D == 2 && py > 1)) continue;
        Decomposition d = blocksOf(config, cells, {px, D == 3 ? py : 1, 1}, ghostLayers, rows);
        if (d.blocks.empty()) continue;
        const double p = price(d);
        if (p < bestPrice) {
            best = std::move(d);
            bestPrice = p;
        }
    }
    if (D == 1) best = blocksOf(config, cells, {1, 1, 1}, ghostLayers, rows);
    if (best.blocks.empty()) cannotCut(config, cells, std::to_string(ranks) + " blocks");
    return best;
}

std::string describe(const Decomposition& d) {
    std::ostringstream s;
    const char* axis[3] = {"x", "y", "z"};
    const int D = d.dimension;
    s << "decomposition: " << d.ranks << " rank" << (d.ranks > 1 ? "s" : "") << ", ";
    for (int a = 0; a < D; ++a) s << (a ? " x " : "") << d.parts[a];
    s << " blocks (" << (d.columnsWhole() ? "columns whole" : "columns cut across the vertical") << "), "
      << d.windowLayers << " cells of ghost points beside each cut, point imbalance "
      << std::round(1000 * d.imbalance()) / 1000 << "\n";
    s << "  rank  cells";
    for (int a = 0; a < D; ++a) s << "  " << axis[D == 1 ? 2 : (a == D - 1 ? 2 : a)] << "-range";
    s << "   nodes   solid pts  liquid pts  ghost pts   memory\n";
    char line[256];
    for (std::size_t r = 0; r < d.blocks.size(); ++r) {
        const auto& b = d.blocks[r];
        std::snprintf(line, sizeof line, "  %4zu  %5lld", r, static_cast<long long>(b.cells));
        s << line;
        for (int a = 0; a < D; ++a) {
            std::snprintf(line, sizeof line, "  %4lld-%-4lld", static_cast<long long>(b.cellBegin[a]),
                          static_cast<long long>(b.cellEnd[a]));
            s << line;
        }
        std::snprintf(line, sizeof line, " %7lld %11.0f %11.0f %10.0f   %s\n", static_cast<long long>(b.nodes),
                      b.solidPoints, b.liquidPoints, b.ghostPoints, formatBytes(b.bytes).c_str());
        s << line;
    }
    return s.str();
}

}  // namespace qs
