#pragma once
// Decomposition: the grid cut into one block of cells per MPI rank.
//
//   const Decomposition d = decompose(config, 4);   // from the case alone, nothing allocated
//   d.parts        -> {4, 1}: four blocks side by side, each a band of whole columns
//   d.blocks[r]    -> rank r's cells, nodes, ghost nodes, points and memory
//
// The ranks form a process grid, parts[d] blocks along axis d, and each axis is cut at cell
// faces so that the blocks carry equal work: material points, as the case lays them out
// (ColumnBuilder's lattices, RunSize's counts). Along a horizontal axis the columns are alike
// and the cuts are even; along the vertical the rows are not (sand holds more points than free
// water, the air above none), and the cuts follow the points.
//
// A block owns the nodes at its cells' lower corners, and the last block on an axis the grid's
// last nodes too. It keeps ghost layers beyond each cut: ghostLayers cells (1 for linear shape
// functions, 2 for uGIMP, whose support reaches a cell further) and their nodes, the ghost nodes
// (below a cut the cut's node layer, owned above it, is one of them). What a step exchanges is the ghost nodes' sums after the
// scatter and their velocities before the gather (ExaMPM's scatter and gather halos).
//
// Which process grid: the columns stay whole. A run's blocks are cut only across the horizontal
// axes (bands of columns in 2D and axisymmetry, a px x py grid of them in 3D), because the
// step's per-column scans (which cells' water is under the air, the sand's top two cells, the
// bed's top, the pipes) run down each column carrying what lies above; cut across the height,
// each would wait for the rank above it, pz ranks in a row, several times a step. Among the
// horizontal process grids the cheapest is taken: the busiest rank's points plus its ghost
// nodes, exchanged twice a step and each worth about a point's update (kGhostNodeCost, a model,
// not a measurement). decomposeAs prices any grid, vertical cuts too, for the scaling model
// (docs/performance.md). A 1D column has no horizontal axis and runs on one rank. A block must
// hold at least one cell more than its ghost layers along a cut axis; a decomposition that
// cannot is refused (more ranks than the grid can be cut into).
#include <array>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "case/CaseConfig.hpp"

namespace qs {

/// What a ghost node costs beside a point update in the price of a decomposition (a model, not
/// a measurement: docs/performance.md).
constexpr double kGhostNodeCost = 1.0;

struct DecompositionBlock {
    std::array<Index, 3> cellBegin{0, 0, 0}, cellEnd{1, 1, 1};  ///< the cells [begin, end) per axis
    Index cells = 0;
    Index nodes = 0;        ///< owned
    Index ghostNodes = 0;   ///< the halo's nodes (other ranks own them)
    double solidPoints = 0, liquidPoints = 0;  ///< at the start (estimated from the case)
    /// The neighbours' points copied into the window of ghost cells (ghostPointLayers deep beside
    /// each cut: parallel/RankShare.hpp) each step, at the start (estimated from the case)
    double ghostPoints = 0;
    /// estimated memory of the rank's step: its points with the window's ghosts, the whole
    /// grid's arrays. Not counted: implicit coupling's copy of the window's start (a coupled run),
    /// and rank 0's gathered copy of every point while it writes a checkpoint or fields.h5
    double bytes = 0;
};

struct Decomposition {
    int ranks = 1;
    int dimension = 1;
    int ghostLayers = 1;   ///< the node halo of the thin design (the price, the least block)
    int windowLayers = 2;  ///< cells of ghost points the step keeps beside each cut (ghostPointLayers)
    std::array<int, 3> parts{1, 1, 1};          ///< blocks along each axis (the last one vertical)
    std::array<std::vector<Index>, 3> cuts;     ///< per axis parts + 1 cell indices, 0 .. cells
    std::vector<DecompositionBlock> blocks;     ///< one per rank; rank = lexicographic, axis 0 fastest

    bool columnsWhole() const { return parts[dimension - 1] == 1; }
    /// The rank that owns the block of process-grid coordinates k.
    int rankOf(const std::array<int, 3>& k) const { return k[0] + parts[0] * (k[1] + parts[1] * k[2]); }
    /// The block with the most points, and its share beside a perfect split (1 = perfect).
    double imbalance() const;
};

/// Cells of ghost points beside a cut: how far a step's phases reach from a point to the points
/// whose update it enters, within one step (what the step carries to the next, the cells'
/// pressure gradient and the nodes' relative speed, is the owners', RankShare::shareCarried).
/// Measured by the comparison with one rank (tests/mpi/test_ColumnOnRanks.cpp, 200 steps of the
/// random bed on 2, 3 and 4 ranks): linear shape functions agree to round-off (1e-13) from 1
/// layer, uGIMP from 3 (with 2 it was 2.4e-11 off; with no ghosts the gate flux is 50 % off). So
/// does a fluidised bed, its front diffusion acting: the 16-column random bed run to 3 s on one
/// rank (17 % of its sand fluidised), then 200 steps from that checkpoint on 2 and 3 ranks, agree
/// to 1e-12 with 1 layer and fail with none (2026-12-07, fourth session; an experiment, not a test:
/// the state takes 75 s to reach). One layer more than that is kept for linear, for what neither
/// exercised (cavities), and one for uGIMP. A layer costs: piping3D at 6.2 mm on 2 ranks stepped
/// 75 % of the serial points a rank with 3 layers, 67 % with 2. Before the carried state was
/// shared, 4 layers left the axisymmetric bed on 3 ranks 3e-10 off: an error carried from the
/// window's edge one cell inwards a step. The particle phase (solver/ParticlePhase.cpp) uses the
/// spare linear layer: a node on the cut reads the particle pressure of window cells one out,
/// which read the nodal porosity of cells two out (a review's count; not yet run on ranks).
int ghostPointLayers(const CaseConfig& config);

/// Cuts the case's grid into `ranks` blocks of whole columns (see above). Throws qs::Error
/// naming the case file when the grid cannot be cut that finely, or is 1D and ranks > 1.
Decomposition decompose(const CaseConfig& config, int ranks);

/// Whether decompose(config, ranks) would cut the grid. A column beside an OpenFOAM line that
/// cannot be cut (1D, or fewer columns than the ranks need) is stepped whole on every rank, the
/// line decomposed; any other column that cannot be cut is refused, with decompose's reason.
bool decomposable(const CaseConfig& config, int ranks);

/// Whether a column beside an OpenFOAM line is cut over `ranks` (else stepped whole on every
/// rank): where it is decomposable and its time scheme steps on ranks in this build (the
/// semi-implicit one needs hypre).
bool cutBesideALine(const CaseConfig& config, int ranks);

/// The blocks of one process grid (parts[d] blocks along axis d; 1 beyond the grid's axes),
/// whatever its price: to compare cuts by measurement (benchmarks), or to force one.
Decomposition decomposeAs(const CaseConfig& config, const std::array<int, 3>& parts);

/// What decompose minimises: the busiest rank's points and cells plus its ghost nodes, twice.
double decompositionPrice(const Decomposition& d);

/// The decomposition as `quicksand check` prints it: the process grid, then a line per rank.
std::string describe(const Decomposition& d);

}  // namespace qs
