#pragma once
// Grid<D>: the structured background grid of square (cubic) cells of edge h.
//
// Nodes and cells are numbered lexicographically with axis 0 fastest. The last axis is vertical;
// its origin is the gate plane (z = 0). A cell's "footprint" is its horizontal face, which in 1D
// is the column's cross-section and in 2D the cell width times the out-of-plane thickness.
#include <cmath>

#include "core/Error.hpp"
#include "core/Types.hpp"

namespace qs {

template <int D>
class Grid {
public:
    Grid() = default;
    /// cells: number of cells per axis (>= 2 each); h: cell edge (m); crossSection: column area (m2),
    /// used as the out-of-plane extent of 1D and 2D grids.
    Grid(const IVec<D>& cells, Real h, Real crossSection) : cells_(cells), h_(h) {
        numCells_ = 1;
        numNodes_ = 1;
        for (int d = 0; d < D; ++d) {
            QS_CHECK(cells[d] >= 2, "the grid needs at least 2 cells along axis " << d);
            nodes_[d] = cells[d] + 1;
            cellStride_[d] = numCells_;
            nodeStride_[d] = numNodes_;
            numCells_ *= cells[d];
            numNodes_ *= nodes_[d];
        }
        // The horizontal extent that one cell column stands for.
        Real horizontal = 1.0;
        for (int d = 0; d < D - 1; ++d) horizontal *= cells[d] * h;
        outOfPlane_ = (D == 3) ? 1.0 : crossSection / (D == 1 ? 1.0 : horizontal);
        footprint_ = std::pow(h, D - 1) * outOfPlane_;
        cellVolume_ = footprint_ * h;
    }

    Real h() const { return h_; }
    Index numCells() const { return numCells_; }
    Index numNodes() const { return numNodes_; }
    Index cells(int d) const { return cells_[d]; }
    Index nodes(int d) const { return nodes_[d]; }
    Index cellStride(int d) const { return cellStride_[d]; }
    Index nodeStride(int d) const { return nodeStride_[d]; }
    Real cellVolume() const { return cellVolume_; }
    /// m2, horizontal face of one cell (the whole cross-section in 1D).
    Real footprint() const { return footprint_; }
    /// m, extent normal to the grid for D < 3 (1D: area in m2, 2D: thickness in m).
    Real outOfPlane() const { return outOfPlane_; }
    Real top() const { return cells_[D - 1] * h_; }

    Index cellIndex(const IVec<D>& c) const {
        Index k = 0;
        for (int d = 0; d < D; ++d) k += c[d] * cellStride_[d];
        return k;
    }
    Index nodeIndex(const IVec<D>& n) const {
        Index k = 0;
        for (int d = 0; d < D; ++d) k += n[d] * nodeStride_[d];
        return k;
    }
    IVec<D> cellCoords(Index k) const {
        IVec<D> c;
        for (int d = 0; d < D; ++d) { c[d] = k % cells_[d]; k /= cells_[d]; }
        return c;
    }
    IVec<D> nodeCoords(Index k) const {
        IVec<D> n;
        for (int d = 0; d < D; ++d) { n[d] = k % nodes_[d]; k /= nodes_[d]; }
        return n;
    }
    /// The cell holding x (clamped to the grid). Clamped before the conversion to an integer, so
    /// that a point gone to infinity or NaN (which the health check then reports) is in cell 0 or
    /// the last cell rather than undefined behaviour.
    Index cellOf(const Real* x) const {
        Index k = 0;
        for (int d = 0; d < D; ++d) {
            const Real s = std::floor(x[d] / h_);
            const Index c = !(s >= 0) ? 0 : (s >= static_cast<Real>(cells_[d]) ? cells_[d] - 1 : static_cast<Index>(s));
            k += c * cellStride_[d];
        }
        return k;
    }
    /// Calls f(cell, corner) for each existing cell around a node; `corner` is the node's corner
    /// in that cell (bit d set: the node is the cell's upper node along axis d).
    template <class F>
    void forEachCellOfNode(Index node, F&& f) const {
        const IVec<D> n = nodeCoords(node);
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> c;
            bool inside = true;
            for (int d = 0; d < D; ++d) {
                c[d] = n[d] - 1 + ((k >> d) & 1);
                if (c[d] < 0 || c[d] >= cells_[d]) inside = false;
            }
            if (inside) f(cellIndex(c), ~k & ((1 << D) - 1));
        }
    }
    /// Calls f(node, corner) for the 2^D nodes of a cell (corner as in forEachCellOfNode).
    template <class F>
    void forEachNodeOfCell(Index cell, F&& f) const {
        const IVec<D> c = cellCoords(cell);
        for (int k = 0; k < (1 << D); ++k) {
            IVec<D> n;
            for (int d = 0; d < D; ++d) n[d] = c[d] + ((k >> d) & 1);
            f(nodeIndex(n), k);
        }
    }
    /// dN/dx_a of the linear shape function of a cell's `corner` node, at the cell's centre.
    Real centreGradient(int corner, int a) const {
        Real g = (((corner >> a) & 1) ? 1.0 : -1.0) / h_;
        for (int d = 0; d < D; ++d)
            if (d != a) g *= 0.5;
        return g;
    }
    Real nodePosition(Index nodeCoord) const { return nodeCoord * h_; }
    Real cellCentre(Index cellCoord) const { return (cellCoord + 0.5) * h_; }

private:
    IVec<D> cells_{}, nodes_{}, cellStride_{}, nodeStride_{};
    Index numCells_ = 0, numNodes_ = 0;
    Real h_ = 0, outOfPlane_ = 1, footprint_ = 0, cellVolume_ = 0;
};

}  // namespace qs
