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
#include <type_traits>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/PointPacking.hpp"
#include "parallel/Subdomain.hpp"

namespace qs {

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
        // the neighbours: the ranks whose window holds a cell within one cell of this block (a
        // point of this block moves at most a cell in a step: one that crossed into a third
        // block may lie in a window that does not reach this one), and so whose block lies
        // within one cell of this window (windows widen blocks alike)
        for (int r = 0; r < d.ranks; ++r)
            if (r != comm.rank() && windowsMeet(d.blocks[r], d.blocks[comm.rank()], layers_ + 1)) neighbours_.push_back(r);
        // each owned cell: the neighbours whose windows hold it (a list per cell, CSR)
        sendStart_.assign(static_cast<std::size_t>(nc) + 1, 0);
        for (Index c = 0; c < nc; ++c) {
            sendStart_[c + 1] = sendStart_[c];
            if (cellOwner_[c] != comm.rank()) continue;
            const IVec<D> k = grid.cellCoords(c);
            for (std::size_t n = 0; n < neighbours_.size(); ++n)
                if (inWindow(d.blocks[neighbours_[n]], k)) {
                    sendList_.push_back(static_cast<int>(n));
                    ++sendStart_[c + 1];
                }
        }
        // a cell of this window, for the points that stay as ghosts
        inMyWindow_.resize(static_cast<std::size_t>(nc));
        for (Index c = 0; c < nc; ++c) inMyWindow_[c] = inWindow(d.blocks[comm.rank()], grid.cellCoords(c));
        for (Index col = 0; col < grid.columns(); ++col) columnOwned_.push_back(ownsCell(grid.columnCell(col, 0)));
        listCarried(grid, d);
        send_.resize(neighbours_.size());
        sendIndex_.resize(neighbours_.size());
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
    /// Cells of the block and its window: where this rank's points, owned and ghosts, can be.
    Index windowCells() const { return static_cast<Index>(std::count(inMyWindow_.begin(), inMyWindow_.end(), 1)); }
    /// Cells of the block.
    Index ownedCells() const { return static_cast<Index>(std::count(cellOwner_.begin(), cellOwner_.end(), comm_.rank())); }
    /// Points sent and received by the last exchange, and the values sent (for the figures of
    /// docs/performance.md: what crosses a cut per step).
    std::size_t sentPoints() const { return sent_; }
    std::size_t sentValues() const { return sentValues_; }
    /// Values (8 B each) this rank has sent its neighbours since it was made, over every
    /// exchange: the points with their ghost copies, the carried state, the cell values of the
    /// semi-implicit step. Over the steps taken, the traffic of docs/performance.md's model.
    double valuesSentInAll() const { return valuesSentInAll_; }
    /// Steps this rank has exchanged points for (a coupling window's repeats included).
    long stepsExchanged() const { return stepsExchanged_; }

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
        for (auto& s : sendIndex_) s.clear();
        sent_ = 0;
        std::size_t firstDropped = n;
        for (std::size_t p = 0; p < n; ++p) {
            const Index c = cellOf(&set.x[p * D]);
            destinationsOf(c, to_);
            for (int k : to_) sendIndex_[static_cast<std::size_t>(k)].push_back(static_cast<Index>(p));
            sent_ += to_.size();
            drop_[p] = !inMyWindow_[c];
            if (drop_[p] && firstDropped == n) firstDropped = p;
        }
        // field by field: each field's values of a neighbour's points in one sweep
        for (std::size_t k = 0; k < neighbours_.size(); ++k) packPointsByField(set, sendIndex_[k], send_[k]);
        sentValues_ = 0;
        for (std::size_t k = 0; k < neighbours_.size(); ++k) {
            countsOut_[k][0] = double(send_[k].size() / width);
            sentValues_ += send_[k].size();
        }
        comm_.exchange(neighbours_, countsOut_, countsIn_);
        valuesSentInAll_ += double(sentValues_ + neighbours_.size());
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
            recv_[k].resize(static_cast<std::size_t>(countsIn_[k][0]) * width);
        comm_.exchange(neighbours_, send_, recv_);
        // few points leave the window in a step: the set is rewritten from the first one only
        if (firstDropped < n) compactPoints(set, drop_, firstDropped);
        for (std::size_t k = 0; k < neighbours_.size(); ++k) unpackPointsByField(set, recv_[k], width);
    }

    /// The grid's carried state (the last step's fields that this step reads: the cells' pressure
    /// gradient, the nodes' relative speed; GridFields.hpp, forEachStateField) in the window's
    /// cells and nodes, from their owners. Each rank computes these for its window too, but near
    /// the window's edge without the points beyond it, and a cell's water is centred with its
    /// gradient next step: a cell's error there would creep one cell inwards a step. Collective.
    template <class CellFields, class NodeFields>
    void shareCarried(CellFields& cells, NodeFields& nodes) {
        const std::size_t n = neighbours_.size();
        carriedOut_.resize(n);
        carriedIn_.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            carriedOut_[k].clear();
            cells.forEachStateField([&](const std::vector<Real>& f, const FieldSpec& spec) {
                for (Index c : cellsOut_[k])
                    for (int a = 0; a < spec.components; ++a) carriedOut_[k].push_back(f[c * spec.components + a]);
            });
            nodes.forEachStateField([&](const std::vector<Real>& f, const FieldSpec& spec) {
                for (Index i : nodesOut_[k])
                    for (int a = 0; a < spec.components; ++a) carriedOut_[k].push_back(f[i * spec.components + a]);
            });
            std::size_t in = 0;
            cells.forEachStateField([&](const std::vector<Real>&, const FieldSpec& spec) { in += cellsIn_[k].size() * spec.components; });
            nodes.forEachStateField([&](const std::vector<Real>&, const FieldSpec& spec) { in += nodesIn_[k].size() * spec.components; });
            carriedIn_[k].resize(in);
        }
        comm_.exchange(neighbours_, carriedOut_, carriedIn_);
        ++stepsExchanged_;
        for (const auto& out : carriedOut_) valuesSentInAll_ += double(out.size());
        for (std::size_t k = 0; k < n; ++k) {
            std::size_t at = 0;
            cells.forEachStateField([&](std::vector<Real>& f, const FieldSpec& spec) {
                for (Index c : cellsIn_[k])
                    for (int a = 0; a < spec.components; ++a) f[c * spec.components + a] = carriedIn_[k][at++];
            });
            nodes.forEachStateField([&](std::vector<Real>& f, const FieldSpec& spec) {
                for (Index i : nodesIn_[k])
                    for (int a = 0; a < spec.components; ++a) f[i * spec.components + a] = carriedIn_[k][at++];
            });
        }
    }

    /// Per-cell arrays (one value a cell, indexed by the grid's cells: Eigen vectors, std::vector)
    /// in the window's cells, from their owners: the semi-implicit step's pressure increment and
    /// its held cells, which a rank solves for its own cells only. Collective.
    template <class... Arrays>
    void shareCellValues(Arrays&... arrays) const {
        const std::size_t n = neighbours_.size();
        valuesOut_.resize(n);
        valuesIn_.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
            valuesOut_[k].clear();
            for (Index c : cellsOut_[k]) (valuesOut_[k].push_back(static_cast<Real>(arrays[c])), ...);
            valuesIn_[k].resize(cellsIn_[k].size() * sizeof...(Arrays));
        }
        comm_.exchange(neighbours_, valuesOut_, valuesIn_);
        for (const auto& out : valuesOut_) valuesSentInAll_ += double(out.size());
        for (std::size_t k = 0; k < n; ++k) {
            std::size_t at = 0;
            for (Index c : cellsIn_[k])
                ((arrays[c] = static_cast<std::decay_t<decltype(arrays[c])>>(valuesIn_[k][at++])), ...);
        }
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
    /// The neighbours (slots) a point in cell c goes to: an owned cell's list; a cell this rank
    /// does not own (a point that left the block) its owner and the windows that hold it, this
    /// rank's aside. Into `to`, cleared first.
    void destinationsOf(Index c, std::vector<int>& to) const {
        to.clear();
        if (ownsCell(c)) {
            to.assign(sendList_.begin() + sendStart_[c], sendList_.begin() + sendStart_[c + 1]);
            return;
        }
        const IVec<D> k = grid_->cellCoords(c);
        for (std::size_t n = 0; n < neighbours_.size(); ++n)
            if (neighbours_[n] == cellOwner_[c] || inWindow(decomposition_.blocks[neighbours_[n]], k))
                to.push_back(static_cast<int>(n));
        QS_CHECK(std::find(neighbours_.begin(), neighbours_.end(), cellOwner_[c]) != neighbours_.end(),
                 "rank " << comm_.rank() << ": a point in cell " << c << " belongs to rank " << cellOwner_[c]
                         << ", which is not a neighbour: it moved past the ghost cells in one step");
    }
    Index cellOf(const Real* x) const { return grid_->cellOf(x); }
    bool inWindow(const DecompositionBlock& b, const IVec<D>& k) const {
        for (int a = 0; a < D; ++a)
            if (k[a] < Index(b.cellBegin[a]) - layers_ || k[a] >= Index(b.cellEnd[a]) + layers_) return false;
        return true;
    }
    static bool windowsMeet(const DecompositionBlock& a, const DecompositionBlock& b, Index reach) {
        for (int d = 0; d < D; ++d)
            if (a.cellEnd[d] + reach <= b.cellBegin[d] || b.cellEnd[d] + reach <= a.cellBegin[d]) return false;
        return true;
    }
    /// The carried grid state's entries each neighbour needs of this rank's (its owned cells and
    /// nodes in the neighbour's window) and this rank needs of it (the neighbour's owned ones in
    /// this window), both ascending: the two sides list the same entries in the same order.
    void listCarried(const Grid<D>& grid, const Decomposition& d) {
        const std::size_t n = neighbours_.size();
        cellsOut_.assign(n, {});
        cellsIn_.assign(n, {});
        nodesOut_.assign(n, {});
        nodesIn_.assign(n, {});
        auto nodeInWindow = [&](Index i, const DecompositionBlock& b) {
            bool in = false;
            grid.forEachCellOfNode(i, [&](Index c, int) { in = in || inWindow(b, grid.cellCoords(c)); });
            return in;
        };
        const DecompositionBlock& mine = d.blocks[comm_.rank()];
        for (std::size_t k = 0; k < n; ++k) {
            const DecompositionBlock& theirs = d.blocks[neighbours_[k]];
            const Subdomain<D> their(d, neighbours_[k]);
            for (Index c = 0; c < grid.numCells(); ++c) {
                const IVec<D> cc = grid.cellCoords(c);
                if (ownsCell(c) && inWindow(theirs, cc)) cellsOut_[k].push_back(c);
                if (cellOwner_[c] == neighbours_[k] && inWindow(mine, cc)) cellsIn_[k].push_back(c);
            }
            for (Index i = 0; i < grid.numNodes(); ++i) {
                if (ownsNode(i) && nodeInWindow(i, theirs)) nodesOut_[k].push_back(i);
                if (!ownsNode(i) && their.ownsNode(grid.nodeCoords(i)) && nodeInWindow(i, mine))
                    nodesIn_[k].push_back(i);
            }
        }
    }

    const Communicator& comm_;
    Decomposition decomposition_;
    Subdomain<D> mine_;
    int layers_;
    const Grid<D>* grid_ = nullptr;
    Real invH_ = 0;
    std::vector<int> cellOwner_;
    std::vector<char> nodeOwned_, inMyWindow_, columnOwned_;
    std::vector<Index> sendStart_;  ///< per cell, its neighbours in sendList_ (CSR)
    mutable std::vector<std::vector<Real>> valuesOut_, valuesIn_;  ///< shareCellValues' buffers
    std::vector<int> sendList_, to_;
    std::vector<std::vector<Index>> cellsOut_, cellsIn_, nodesOut_, nodesIn_;
    std::vector<std::vector<double>> carriedOut_, carriedIn_;
    std::vector<int> neighbours_;
    std::vector<std::vector<Index>> sendIndex_;  ///< per neighbour, the points the exchange sends it
    std::vector<std::vector<double>> send_, recv_, countsOut_, countsIn_;
    std::vector<char> drop_;
    std::size_t sent_ = 0, sentValues_ = 0;
    mutable double valuesSentInAll_ = 0;
    long stepsExchanged_ = 0;
};

}  // namespace qs
