#pragma once
// Subdomain<D>: one rank's share of the grid, as the decomposition cut it (parallel/
// Decomposition.hpp), and the map between the global grid and the rank's local one.
//
//   Subdomain<2> mine(decomposition, world.rank());
//   mine.local()            -> the local grid's cells per axis: the rank's block and its ghost cells
//   mine.localNode(global)  -> the node's index in the local grid, -1 where the rank has none
//   mine.ownerOfCell(k)     -> the rank whose block holds global cell k
//
// The local grid is the block widened by ghostLayers cells beside each cut (not beyond the
// grid's walls), numbered as a Grid is: axis 0 fastest. A rank owns the points in its block's
// cells and the nodes at their lower corners (the grid's last nodes belong to the last block on
// each axis); the other nodes of its local grid are ghosts, which other ranks own.
#include <algorithm>
#include <array>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "parallel/Decomposition.hpp"

namespace qs {

template <int D>
class Subdomain {
public:
    Subdomain(const Decomposition& d, int rank) : parts_(d.parts), cuts_(d.cuts), rank_(rank) {
        QS_CHECK(d.dimension == D, "a " << d.dimension << "D decomposition for a " << D << "D grid");
        QS_CHECK(rank >= 0 && rank < d.ranks, "rank " << rank << " of a decomposition over " << d.ranks << " ranks");
        const DecompositionBlock& b = d.blocks[static_cast<std::size_t>(rank)];
        localCount_ = 1;
        for (int a = 0; a < D; ++a) {
            global_[a] = cuts_[a].back();
            begin_[a] = b.cellBegin[a];
            end_[a] = b.cellEnd[a];
            localBegin_[a] = std::max<Index>(0, begin_[a] - d.ghostLayers);
            localEnd_[a] = std::min<Index>(global_[a], end_[a] + d.ghostLayers);
            local_[a] = localEnd_[a] - localBegin_[a];
            localNodeStride_[a] = localCount_;
            localCount_ *= local_[a] + 1;
        }
    }

    int rank() const { return rank_; }
    const IVec<D>& globalCells() const { return global_; }
    const IVec<D>& local() const { return local_; }           ///< cells per axis of the local grid
    const IVec<D>& localBegin() const { return localBegin_; }  ///< its first cell in the global grid
    const IVec<D>& ownedBegin() const { return begin_; }
    const IVec<D>& ownedEnd() const { return end_; }
    Index localNodes() const { return localCount_; }

    bool ownsCell(const IVec<D>& k) const {
        for (int a = 0; a < D; ++a)
            if (k[a] < begin_[a] || k[a] >= end_[a]) return false;
        return true;
    }
    /// The rank owning global node n: the block holding the cell n is the lower corner of (the
    /// last cell along an axis for the grid's last node).
    int ownerOfNode(const IVec<D>& n) const {
        IVec<D> k;
        for (int a = 0; a < D; ++a) k[a] = std::min(n[a], global_[a] - 1);
        return ownerOfCell(k);
    }
    bool ownsNode(const IVec<D>& n) const { return ownerOfNode(n) == rank_; }
    int ownerOfCell(const IVec<D>& k) const {
        std::array<int, 3> b{0, 0, 0};
        for (int a = 0; a < D; ++a) {
            const auto& c = cuts_[a];  // parts + 1 ascending boundaries
            b[a] = static_cast<int>(std::upper_bound(c.begin() + 1, c.end() - 1, k[a]) - (c.begin() + 1));
        }
        return b[0] + parts_[0] * (b[1] + parts_[1] * b[2]);
    }
    /// The node's index in the local grid, or -1 where the local grid does not hold it.
    Index localNode(const IVec<D>& n) const {
        Index k = 0;
        for (int a = 0; a < D; ++a) {
            const Index u = n[a] - localBegin_[a];
            if (u < 0 || u > local_[a]) return -1;
            k += u * localNodeStride_[a];
        }
        return k;
    }
    IVec<D> globalNode(Index local) const {
        IVec<D> n;
        for (int a = 0; a < D; ++a) {
            n[a] = localBegin_[a] + local % (local_[a] + 1);
            local /= local_[a] + 1;
        }
        return n;
    }

private:
    std::array<int, 3> parts_;
    std::array<std::vector<Index>, 3> cuts_;
    int rank_;
    IVec<D> global_{}, begin_{}, end_{}, localBegin_{}, localEnd_{}, local_{}, localNodeStride_{};
    Index localCount_ = 0;
};

}  // namespace qs
