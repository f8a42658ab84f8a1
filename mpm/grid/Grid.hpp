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
// cells' volumes, the nodes' shares of them and of the horizontal faces, and the divergence
// weights. The hoop terms of the physics live in the solver's phases.
//
// Those shares are integrals of N_i r over a cell, and the grid takes them with the rule the
// material points take them with: m points across a cell, each weighted by its own radius. The
// inner node of a cell then gets (h/2)(r_c - d) and the outer one (h/2)(r_c + d) of the cell's
// radial extent, d = (h/6)(1 - 1/m^2) (the exact integral is the limit d = h/6). The nodes' solid
// volumes, sums over the points, and their volumes then agree in a uniform bed: with the exact
// integral the node on the axis saw 12.5 % more solid than volume (n = 0.30 for 0.38, 2 points
// per cell), and a laterally uniform consolidation settled 10 um differently at the axis. Inside
// the grid the two rules agree (their errors cancel between a node's two cells).
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
    /// pointsPerCell: in axisymmetry, the solid points across a cell (the radial quadrature rule).
    Grid(const IVec<D>& cells, Real h, Real crossSection, bool axisymmetric = false, int pointsPerCell = 2)
        : cells_(cells), h_(h), invH_(1 / h), axisymmetric_(axisymmetric) {
        radialOffset_ = axisymmetric ? h / 6 * (1 - 1.0 / (pointsPerCell * pointsPerCell)) : 0.0;
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
        Real hD = 1;
        for (int d = 0; d < D; ++d) hD *= h;
        planeCellVolume_ = hD * outOfPlane_;
    }

    Real h() const { return h_; }
    bool axisymmetric() const { return axisymmetric_; }
    Index numCells() const { return numCells_; }
    Index numNodes() const { return numNodes_; }
    Index cells(int d) const { return cells_[d]; }
    Index nodes(int d) const { return nodes_[d]; }
    Index cellStride(int d) const { return cellStride_[d]; }
    /// The cells as columns along the vertical (the last axis): columns() of them, cells(D - 1)
    /// rows each; columnCell(k, row) is column k's cell in that row. The per-column scans (which
    /// cells' water is under the air, the sand's top cells and surface) run down one column at a
    /// time through these. Over MPI ranks each rank's block holds whole columns
    /// (parallel/Decomposition.hpp), so no scan crosses a rank.
    Index columns() const { return cellStride_[D - 1]; }
    Index columnCell(Index column, Index row) const { return column + row * cellStride_[D - 1]; }
    Index nodeStride(int d) const { return nodeStride_[d]; }
    /// m (2D), m2 (1D) or 1 (3D): the extent normal to the grid at radius r = x_0, by which a
    /// length (2D) or a point (1D) becomes an area and an area (2D) a volume: the out-of-plane
    /// thickness, the cross-section in 1D, 2 pi r in axisymmetry.
    Real extentAt(Real r) const { return axisymmetric_ ? 2 * kPi * r : outOfPlane_; }
    /// m2, the column's horizontal cross-section.
    Real crossSection() const { return crossSection_; }
    /// m3, volume of cell c (in axisymmetry the ring 2 pi r_c h^2).
    Real cellVolume(Index c) const {
        return axisymmetric_ ? 2 * kPi * cellCentre(c % cells_[0]) * h_ * h_ : planeCellVolume_;
    }
    /// m3, the integral of a corner node's shape function over cell c: a 2^-D share of its volume
    /// on plane grids; in axisymmetry the node on the cell's inner radius carries less than the
    /// outer one, (pi h^2 / 2)(r_c -+ d) (d: the radial rule above).
    Real cellShare(Index c, int corner) const {
        if (!axisymmetric_) return cellVolume(c) / (1 << D);
        const Real rc = cellCentre(c % cells_[0]);
        return 0.5 * kPi * h_ * h_ * (rc + ((corner & 1) ? radialOffset_ : -radialOffset_));
    }
    /// m2, the share of a horizontal plane carried by a node of it (the whole area in 1D): the
    /// integral of its shape function over the plane. In axisymmetry 2 pi h r_i inside,
    /// pi h (h/2 - d) on the axis and pi h (R - h/2 + d) at the wall (they add up to pi R^2).
    Real nodeFootprint(Index node) const {
        Index n[D];
        for (int d = 0; d < D; ++d) { n[d] = node % nodes_[d]; node /= nodes_[d]; }
        if (axisymmetric_) {
            const Real r = n[0] * h_;
            if (n[0] == 0) return kPi * h_ * (0.5 * h_ - radialOffset_);
            if (n[0] == nodes_[0] - 1) return kPi * h_ * (r - 0.5 * h_ + radialOffset_);
            return 2 * kPi * h_ * r;
        }
        Real a = outOfPlane_;
        for (int d = 0; d < D - 1; ++d) a *= (n[d] == 0 || n[d] == nodes_[d] - 1) ? 0.5 * h_ : h_;
        return a;
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
    /// 1/m, 1 / h: positions in cells are x * invH() wherever a cell is looked up (cellOf,
    /// LinearStencil), so that all agree on a point within an ulp of a node.
    Real invH() const { return invH_; }
    /// The cell along axis d at u = x invH() (x in m), clamped to the grid. Clamped before the
    /// conversion to an integer, so that a point gone to infinity or NaN (which the health check
    /// then reports) is in cell 0 or the last cell rather than undefined behaviour.
    Index cellAlong(int d, Real u) const {
        // for u >= 0 the conversion is the floor (std::floor is a library call without SSE4.1)
        return !(u >= 0) ? 0 : (u >= static_cast<Real>(cells_[d]) ? cells_[d] - 1 : static_cast<Index>(u));
    }
    /// m, the first coordinate from c h up that cellOf puts in cell c along axis d: c h itself,
    /// or the next doubles above it where fl(c h) (1/h) rounds below c (for h = 0.0062 that is 218
    /// of the rows 1 to 399). A point the solver holds on a node plane, the sand on the filter,
    /// is held here, so that it is in the cell above the plane and its slopes reach that cell's
    /// upper nodes (in the cell below, the sand's would reach only the chamber, where it leaves
    /// nothing, and the filter row: slopes summing to 1/h, a strain under a uniform velocity).
    Real firstInCell(int d, Index c) const {
        Real x = c * h_;
        while (cellAlong(d, x * invH_) < c) x = std::nextafter(x, HUGE_VAL);
        return x;
    }
    /// The cell holding x (clamped to the grid).
    Index cellOf(const Real* x) const {
        Index k = 0;
        for (int d = 0; d < D; ++d) k += cellAlong(d, x[d] * invH_) * cellStride_[d];
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
    /// 1/m, the weight of a corner node's velocity component a in the divergence of cell c:
    /// (1/V_c) times the integral over the cell of div(N_i e_a), so that
    ///   div_c = sum_i sum_a divergenceWeight(c, corner_i, a) v_i,a
    /// is the cell's mean divergence of the bilinear field, and its transpose (the pressure
    /// force, p_c V_c times the weight) is the integral of p_c div(N_i e_a). On plane grids it is
    /// grad N_i at the cell's centre. In axisymmetry the radial weight takes in the hoop part
    /// v_r / r and becomes (+r_out or -r_in) / (2 h r_c), the pressure on the cell's outer and
    /// inner cylinder faces; the vertical one weighs the inner node by r_c - d and the outer by
    /// r_c + d (their shares of the horizontal faces, the radial rule above), matching the nodes'
    /// volumes and the gate's footprints. (The centre rule there, +-1/(2h), left the nodes on the
    /// axis and at the wall out of hydrostatic balance: a geostatic cylinder leaked at 16 times
    /// the bound.)
    Real divergenceWeight(Index c, int corner, int a) const {
        if (!axisymmetric_) return centreGradient(corner, a);
        const Index i = c % cells_[0];
        const Real rc = cellCentre(i), outer = corner & 1;
        if (a == 0) return (outer ? rc + 0.5 * h_ : -(rc - 0.5 * h_)) / (2 * h_ * rc);
        const Real up = (corner >> 1) & 1 ? 1.0 : -1.0;
        return up * (rc + (outer ? radialOffset_ : -radialOffset_)) / (2 * h_ * rc);
    }
    Real nodePosition(Index nodeCoord) const { return nodeCoord * h_; }
    Real cellCentre(Index cellCoord) const { return (cellCoord + 0.5) * h_; }

private:
    IVec<D> cells_{}, nodes_{}, cellStride_{}, nodeStride_{};
    Index numCells_ = 0, numNodes_ = 0;
    Real h_ = 0, invH_ = 0, outOfPlane_ = 1, crossSection_ = 0, radialOffset_ = 0, planeCellVolume_ = 0;
    bool axisymmetric_ = false;
};

}  // namespace qs
