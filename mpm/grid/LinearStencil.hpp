#pragma once
// LinearStencil<D>: the 2^D nodes a material point reaches with linear shape functions, and the
// weights it gives them, taken straight from the point's position.
//
// A linear hat reaches exactly the nodes of the point's own cell. With the point's place in its
// cell xi_d = x_d / h - c_d (0..1 along each axis), the two hats along axis d are 1 - xi_d at the
// cell's lower node and xi_d at its upper one, with slopes -1/h and +1/h, and a node's weight is
// their tensor product:
//   N_k = prod_d w_d(k_d),   dN_k/dx_a = w'_a(k_a) prod_{d != a} w_d(k_d),
// corner k numbered as in Grid::forEachNodeOfCell (bit d set: the cell's upper node along axis
// d). The weights sum to 1 and their gradients to 0 by construction, and sum_k N_k x_k = x_p
// exactly in exact arithmetic, so the APIC offsets x_k - x_p are (k_d - xi_d) h: no node
// coordinates are needed (and no integer division to find them).
//
// The transfers build one stencil per point in registers; nothing is stored between the
// point-to-grid and the grid-to-point phases (the positions do not change in between). uGIMP,
// whose weights depend on the point's domain and its cuts, keeps the cached per-axis weights
// (grid/ShapeFunctions.hpp, PointsToGrid.cpp).
#include <algorithm>

#include "grid/Grid.hpp"

namespace qs {

template <int D>
struct LinearStencil {
    static constexpr int kNodes = 1 << D;
    Index node[kNodes];       ///< flat node index of corner k
    Real N[kNodes];           ///< N_k(x_p)
    Real grad[kNodes][D];     ///< dN_k/dx_a (1/m)
    Real xi[D];               ///< the point's place in its cell per axis (0..1)

    /// 0 or 1: corner k's node along axis d.
    static constexpr int bit(int k, int d) { return (k >> d) & 1; }
};

/// The stencil of a point at x (m from the grid's origin; inside the grid, where the solver keeps
/// its points): the nodes of the cell Grid::cellOf gives. A point on the grid's far boundary
/// belongs to the last cell (xi = 1).
template <int D>
inline LinearStencil<D> linearStencil(const Grid<D>& grid, const Real* x) {
    LinearStencil<D> s;
    const Real invH = grid.invH();
    Real w[D][2], dw[D][2];
    Index first = 0;
    for (int d = 0; d < D; ++d) {
        // the cell is the one Grid::cellOf finds, which sorted the point: with that of x / h
        // instead, a point within an ulp of a node could reach a node row its scatter slab does
        // not own (solver/Parallel.hpp)
        const Real u = x[d] * invH;
        const Index c = grid.cellAlong(d, u);
        // inside the grid u - c is in [0, 1) exactly; on the far boundary fl(x (1/h)) can exceed
        // the cell count by an ulp, and a point outside (from a checkpoint) would extrapolate:
        // both keep the nearest face's weights instead, none negative
        s.xi[d] = std::min(std::max(u - static_cast<Real>(c), Real(0)), Real(1));
        w[d][0] = 1 - s.xi[d];
        w[d][1] = s.xi[d];
        dw[d][0] = -invH;
        dw[d][1] = invH;
        first += c * grid.nodeStride(d);
    }
#pragma GCC unroll 8
    for (int k = 0; k < LinearStencil<D>::kNodes; ++k) {
        Index node = first;
        Real N = 1;
        for (int d = 0; d < D; ++d) {
            const int b = LinearStencil<D>::bit(k, d);
            node += b * grid.nodeStride(d);
            N *= w[d][b];
        }
        s.node[k] = node;
        s.N[k] = N;
        for (int a = 0; a < D; ++a) {
            Real g = dw[a][LinearStencil<D>::bit(k, a)];
            for (int d = 0; d < D; ++d)
                if (d != a) g *= w[d][LinearStencil<D>::bit(k, d)];
            s.grad[k][a] = g;
        }
    }
    return s;
}

}  // namespace qs
