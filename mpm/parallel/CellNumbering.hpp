#pragma once
// CellNumbering: the cells numbered rank by rank, for a linear system over the ranks.
//
// A distributed solver (hypre's IJ interface, PETSc's MPIAIJ) wants each rank's rows contiguous:
// rank 0's cells first, then rank 1's, each rank's in the grid's own order (axis 0 fastest).
// A band of whole columns is not contiguous in the grid's numbering (a row of cells crosses every
// band), hence this map. It holds one index per cell of the global grid on every rank: 8 MB a
// million cells, small beside the points; a rank that must not hold it would ask its neighbours
// for the rows of its ghost cells instead.
#include <vector>

#include "core/Types.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/Subdomain.hpp"

namespace qs {

template <int D>
class CellNumbering {
public:
    explicit CellNumbering(const Decomposition& d) {
        IVec<D> cells;
        Index count = 1;
        for (int a = 0; a < D; ++a) {
            cells[a] = d.cuts[a].back();
            stride_[a] = count;
            count *= cells[a];
        }
        rowOf_.assign(static_cast<std::size_t>(count), -1);
        first_.assign(static_cast<std::size_t>(d.ranks) + 1, 0);
        Index next = 0;
        for (int r = 0; r < d.ranks; ++r) {
            first_[r] = next;
            const DecompositionBlock& b = d.blocks[static_cast<std::size_t>(r)];
            IVec<D> k;
            for (int a = 0; a < D; ++a) k[a] = b.cellBegin[a];
            if (b.cells == 0) continue;
            while (true) {  // the block's cells, axis 0 fastest
                rowOf_[static_cast<std::size_t>(cellIndex(k))] = next++;
                int a = 0;
                while (a < D && ++k[a] >= b.cellEnd[a]) k[a] = b.cellBegin[a], ++a;
                if (a == D) break;
            }
        }
        first_[d.ranks] = next;
    }

    /// The global row of the cell of global coordinates k.
    Index row(const IVec<D>& k) const { return rowOf_[static_cast<std::size_t>(cellIndex(k))]; }
    /// Rank r's rows are [firstRow(r), firstRow(r + 1)).
    Index firstRow(int r) const { return first_[static_cast<std::size_t>(r)]; }
    Index rows() const { return first_.back(); }

private:
    Index cellIndex(const IVec<D>& k) const {
        Index c = 0;
        for (int a = 0; a < D; ++a) c += k[a] * stride_[a];
        return c;
    }
    IVec<D> stride_{};
    std::vector<Index> rowOf_, first_;
};

}  // namespace qs
