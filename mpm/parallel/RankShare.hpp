#pragma once
// RankShare<D>: one MPI rank's share of a decomposed column run: the block of cells it owns
// (parallel/Decomposition.hpp), the window of ghost cells around it, and the points that move
// between ranks.
//
// How the step runs over ranks (docs/parallel.md): each rank steps the whole grid's numbering
// (its loops reach only the cells its points fill) with the points of its block plus copies of
// the neighbours' points in its window, the ghost points, layers() cells deep beside each cut.
// With them every phase of the step computes the nodes and cells of the block, and of the
// window's inner layers, exactly as one rank would: the scatter's sums, the cells' water and
// its gradient, the nodes' forces and velocities, the gather back to the points. The ghosts are
// then dropped; each point is advanced by the rank that owns it. This is Uintah's MPM: particles
// in ghost cells, the grid computed redundantly there, in place of ExaMPM's exchanges of node
// sums after every phase. The step has some twenty cell and node fields that cross a cut
// between its phases (the cells' fill, submersion and air, the water's state and gradient, the
// sand's state and porosity, the nodes' masses, porosities, forces and drag); one exchange of
// points a step replaces all of them, and no phase needs to know it runs on a rank.
//
//   RankShare<2> share(world, decompose(config, world.size()), grid);
//   share.keepOwned(solid);        // after building the column: each point on its owner only
//   share.exchange(solid);         // step start: migrants to their owners, copies to windows
//   ...the step's phases...
//   share.dropGhosts(solid, cellStart);  // the copies go; the cell lists stay the step's
//
// Between steps every point is on one rank, its owner at the step's start: the measurements
// add the ranks' points, and the per-column scans read the step's cell lists of the columns a
// rank owns, as one rank reads them.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/PointPacking.hpp"
#include "parallel/Subdomain.hpp"

namespace qs {

/// Cells of ghost points beside a cut: how far the step's phases reach from a point to the
/// points whose update it enters. A point's nodes (1 cell; 2 with uGIMP's wider support), the
/// cells around them whose water and pressure gradient act on them (1), the neighbour cells
/// those read (1), the front diffusion's neighbours (1): 4, and one more, measured. The ranks'
/// step is compared with one rank's (tests/mpi/test_ColumnOnRanks.cpp): with 5 layers the random
/// bed agrees within 2e-13 after 200 steps in plane strain, axisymmetry and 3D on 2, 3 and 4
/// ranks; with 4 the axisymmetric bed on 3 ranks was 3e-10 off, a dependency, not round-off
/// (uGIMP: 5 was measured to suffice, 6 are kept for its wider stencil).
inline int ghostPointLayers(const CaseConfig& config) {
    return config.grid.shapeFunctions == ShapeFunctionKind::Gimp ? 6 : 5;
}

template <int D>
class RankShare {
public:
    RankShare(const Communicator& comm, const Decomposition& d, const Grid<D>& grid, int layers)
        : comm_(comm), decomposition_(d), mine_(d, comm.rank()), layers_(layers) {
        QS_CHECK(d.ranks == comm.size(), "a decomposition over " << d.ranks << " ranks for a run on " << comm.size());
        const Index nc = grid.numCells();
        cellOwner_.resize(static_cast<std::size_t>(nc));
        for (Index c = 0; c < nc; ++c) cellOwner_[c] = mine_.ownerOfCell(grid.cellCoords(c));
        nodeOwned_.resize(static_cast<std::size_t>(grid.numNodes()));
        for (Index i = 0; i < grid.numNodes(); ++i) nodeOwned_[i] = mine_.ownsNode(grid.nodeCoords(i));
        // the neighbours: the ranks whose window holds a cell of this block (and so whose block
        // holds a cell of this window: windows widen blocks alike)
        for (int r = 0; r < d.ranks; ++r)
            if (r != comm.rank() && windowsMeet(d.blocks[r], d.blocks[comm.rank()])) neighbours_.push_back(r);
        QS_CHECK(neighbours_.size() <= 32, "rank " << comm.rank() << " has " << neighbours_.size()
                                                  << " neighbours; at most 32 are supported");
        // each owned cell: the neighbours whose windows hold it
        sendTo_.assign(static_cast<std::size_t>(nc), 0);
        for (Index c = 0; c < nc; ++c) {
            if (cellOwner_[c] != comm.rank()) continue;
            const IVec<D> k = grid.cellCoords(c);
            for (std::size_t n = 0; n < neighbours_.size(); ++n)
                if (inWindow(d.blocks[neighbours_[n]], k)) sendTo_[c] |= std::uint32_t(1) << n;
        }
        // a cell of this window, for the points that stay as ghosts
        inMyWindow_.resize(static_cast<std::size_t>(nc));
        for (Index c = 0; c < nc; ++c) inMyWindow_[c] = inWindow(d.blocks[comm.rank()], grid.cellCoords(c));
        for (Index col = 0; col < grid.columns(); ++col) columnOwned_.push_back(ownsCell(grid.columnCell(col, 0)));
        send_.resize(neighbours_.size());
        recv_.resize(neighbours_.size());
        countsOut_.assign(neighbours_.size(), std::vector<double>(1));
        countsIn_.assign(neighbours_.size(), std::vector<double>(1));
        invH_ = grid.invH();
        grid_ = &grid;
    }

    const Communicator& comm() const { return comm_; }
    const Decomposition& decomposition() const { return decomposition_; }
    int rank() const { return comm_.rank(); }
    int layers() const { return layers_; }
    const std::vector<int>& neighbours() const { return neighbours_; }
    bool ownsCell(Index c) const { return cellOwner_[c] == comm_.rank(); }
    int ownerOfCell(Index c) const { return cellOwner_[c]; }
    bool ownsNode(Index i) const { return nodeOwned_[i] != 0; }
    bool ownsColumn(Index column) const { return columnOwned_[column] != 0; }
    /// Points sent and received by the last exchange, and the values sent (for the figures of
    /// docs/performance.md: what crosses a cut per step).
    std::size_t sentPoints() const { return sent_; }
    std::size_t sentValues() const { return sentValues_; }

    /// Keeps the points of the block (after the column is built on every rank alike).
    template <class Set>
    void keepOwned(Set& set) {
        drop_.assign(set.size(), 0);
        for (std::size_t p = 0; p < set.size(); ++p) drop_[p] = !ownsCell(cellOf(&set.x[p * D]));
        compactPoints(set, drop_);
    }

    /// The step's start: a point that moved into another block goes to its owner, and every point
    /// is copied to the neighbours whose window holds it (the ghost points). A point leaves this
    /// rank when its cell is neither in the block nor in the window; the others stay, as owned
    /// points or ghosts. Arrivals are appended in the neighbours' rank order, each sender's in its
    /// own order: the same N gives the same order, run after run. Collective.
    template <class Set>
    void exchange(Set& set) {
        const std::size_t n = set.size(), width = packedWidth(set);
        drop_.assign(n, 0);
        for (auto& s : send_) s.clear();
        sent_ = 0;
        for (std::size_t p = 0; p < n; ++p) {
            const Index c = cellOf(&set.x[p * D]);
            std::uint32_t to = sendToOf(c);
            for (std::size_t k = 0; to != 0; ++k, to >>= 1)
                if (to & 1) {
                    packPoint(set, p, send_[k]);
                    ++sent_;
                }
            drop_[p] = !inMyWindow_[c];
        }
        sentValues_ = 0;
        for (std::size_t k = 0; k < neighbours_.size(); ++k) {
            countsOut_[k][0] = double(send_[k].size() / width);
            sentValues_ += send_[k].size();
        }
        comm_.exchange(neighbours_, countsOut_, countsIn_);
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
            recv_[k].resize(static_cast<std::size_t>(countsIn_[k][0]) * width);
        comm_.exchange(neighbours_, send_, recv_);
        compactPoints(set, drop_);
        for (std::size_t k = 0; k < neighbours_.size(); ++k) unpackPoints(set, recv_[k], width);
    }

    /// The step's end: drops the ghosts, the points whose cell at the step's start (set.shape.cell,
    /// the step's sort) another rank owns, and rebuilds cellStart, the step's cell lists, for the
    /// points kept (they stay sorted by those cells). `extra` (per-point scratch beside the
    /// registry, kept in step) is compacted with them.
    template <class Set, class... Extra>
    void dropGhosts(Set& set, std::vector<Index>& cellStart, Extra&... extra) {
        // the points appended since the sort (the chamber's new water, in this rank's slots) stay
        const std::size_t n = set.size();
        auto& cell = set.shape.cell;
        const std::size_t sorted = std::min(cell.size(), n);
        drop_.assign(n, 0);
        std::size_t kept = 0;
        for (std::size_t p = 0; p < sorted; ++p) {
            drop_[p] = !ownsCell(cell[p]);
            if (!drop_[p]) cell[kept++] = cell[p];
        }
        (compactScratch(extra, kept), ...);
        compactPoints(set, drop_);
        cell.resize(kept);
        // the lists: each cell's first point, from the kept points' cells (ascending); the new
        // points after them, in no cell's list (as on one rank)
        const Index nc = static_cast<Index>(cellStart.size()) - 1;
        Index p = 0;
        for (Index c = 0; c <= nc; ++c) {
            while (p < static_cast<Index>(kept) && cell[p] < c) ++p;
            cellStart[c] = p;
        }
    }

private:
    template <class T>
    void compactScratch(std::vector<T>& v, std::size_t kept) {
        std::size_t out = 0;
        for (std::size_t p = 0; p < drop_.size() && p < v.size(); ++p)
            if (!drop_[p]) v[out++] = v[p];
        v.resize(kept);
    }
    std::uint32_t sendToOf(Index c) const {
        // an owned cell's neighbours; a cell this rank does not own (a point that left the block)
        // goes to its owner and to the windows that hold it, this rank's aside
        if (ownsCell(c)) return sendTo_[c];
        std::uint32_t to = 0;
        const IVec<D> k = grid_->cellCoords(c);
        for (std::size_t n = 0; n < neighbours_.size(); ++n)
            if (neighbours_[n] == cellOwner_[c] || inWindow(decomposition_.blocks[neighbours_[n]], k))
                to |= std::uint32_t(1) << n;
        QS_CHECK(std::find(neighbours_.begin(), neighbours_.end(), cellOwner_[c]) != neighbours_.end(),
                 "rank " << comm_.rank() << ": a point in cell " << c << " belongs to rank " << cellOwner_[c]
                         << ", which is not a neighbour: it moved past the ghost cells in one step");
        return to;
    }
    Index cellOf(const Real* x) const { return grid_->cellOf(x); }
    bool inWindow(const DecompositionBlock& b, const IVec<D>& k) const {
        for (int a = 0; a < D; ++a)
            if (k[a] < b.cellBegin[a] - layers_ || k[a] >= b.cellEnd[a] + layers_) return false;
        return true;
    }
    bool windowsMeet(const DecompositionBlock& a, const DecompositionBlock& b) const {
        for (int d = 0; d < D; ++d)
            if (a.cellEnd[d] + layers_ <= b.cellBegin[d] || b.cellEnd[d] + layers_ <= a.cellBegin[d]) return false;
        return true;
    }

    const Communicator& comm_;
    Decomposition decomposition_;
    Subdomain<D> mine_;
    int layers_;
    const Grid<D>* grid_ = nullptr;
    Real invH_ = 0;
    std::vector<int> cellOwner_;
    std::vector<char> nodeOwned_, inMyWindow_, columnOwned_;
    std::vector<std::uint32_t> sendTo_;
    std::vector<int> neighbours_;
    std::vector<std::vector<double>> send_, recv_, countsOut_, countsIn_;
    std::vector<char> drop_;
    std::size_t sent_ = 0, sentValues_ = 0;
};

}  // namespace qs
