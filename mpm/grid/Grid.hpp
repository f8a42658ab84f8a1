#pragma once
// Grid<D>: the structured background grid of square (cubic) cells of edge h.
//
// Nodes and cells are numbered lexicographically with axis 0 fastest. The last axis is vertical;
// its origin is the gate plane (z = 0). A cell's "footprint" is its horizontal face, which in 1D
// is the column's cross-section and in 2D the cell width times the out-of-plane thickness.
//
// Axisymmetric grids (2D, axis 0 the radius r >= 0, axis 1 the height z) stand for the solid of
// revolution: every volume and area is taken over the whole turn, dV = 2 pi r dr dz, so masses,
// fluxes and the ledger keep their 3D units. What changes with the radius is the extent normal to
// the grid, extentAt(r) = 2 pi r (the plane grid's out-of-plane thickness), and with it the
// cells' volumes and the nodes' shares of them (exact integrals of the bilinear shape functions
// times 2 pi r). The hoop terms of the physics live in the solver's phases.
#include <cmath>

#include "core/Error.hpp"
#include "core/Types.hpp"

namespace qs {

template <int D>
class Grid {
public:
    Grid() = default;
    /// cells: number of cells per axis (>= 2 each); h: cell edge (m); crossSection: column area (m2),
    /// used as the out-of-plane extent of 1D and 2D plane grids; axisymmetric: a 2D (r, z) grid.
    Grid(const IVec<D>& cells, Real h, Real crossSection, bool axisymmetric = false)
        : cells_(cells), h_(h), axisymmetric_(axisymmetric) {
        QS_CHECK(!axisymmetric || D == 2, "an axisymmetric grid is two-dimensional (r, z)");
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
        crossSection_ = axisymmetric ? kPi * horizontal * horizontal : horizontal * outOfPlane_;
    }

    Real h() const { return h_; }
    bool axisymmetric() const { return axisymmetric_; }
    Index numCells() const { return numCells_; }
    Index numNodes() const { return numNodes_; }
    Index cells(int d) const { return cells_[d]; }
    Index nodes(int d) const { return nodes_[d]; }
    Index cellStride(int d) const { return cellStride_[d]; }
    Index nodeStride(int d) const { return nodeStride_[d]; }
    /// m (2D), m2 (1D) or 1 (3D): the extent normal to the grid at radius r = x_0, by which a
    /// length (2D) or a point (1D) becomes an area and an area (2D) a volume: the out-of-plane
    /// thickness, the cross-section in 1D, 2 pi r in axisymmetry.
    Real extentAt(Real r) const { return axisymmetric_ ? 2 * kPi * r : outOfPlane_; }
    /// m2, the column's horizontal cross-section.
    Real crossSection() const { return crossSection_; }
    /// m3, volume of cell c (in axisymmetry the ring 2 pi r_c h^2).
    Real cellVolume(Index c) const {
        const Real v = std::pow(h_, D) * outOfPlane_;
        return axisymmetric_ ? 2 * kPi * cellCentre(c % cells_[0]) * h_ * h_ : v;
    }
    /// m3, the integral of a corner node's shape function over cell c: a 2^-D share of its volume
    /// on plane grids; in axisymmetry the node on the cell's inner radius carries less than the
    /// outer one, (pi h^2 / 2)(r_c -+ h/6), so that a uniform material sums to its true volume.
    Real cellShare(Index c, int corner) const {
        if (!axisymmetric_) return cellVolume(c) / (1 << D);
        const Real rc = cellCentre(c % cells_[0]);
        return 0.5 * kPi * h_ * h_ * (rc + ((corner & 1) ? h_ : -h_) / 6);
    }
    /// m2, the horizontal area a point at x stands for when `perCell` points share a cell's width
    /// along each horizontal axis (the whole cross-section in 1D).
    Real pointFootprint(const Real* x, int perCell) const {
        Real a = extentAt(D > 1 ? x[0] : 0.0);
        for (int d = 0; d < D - 1; ++d) a *= h_ / perCell;
        return a;
    }
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
    Real h_ = 0, outOfPlane_ = 1, crossSection_ = 0;
    bool axisymmetric_ = false;
};

}  // namespace qs
