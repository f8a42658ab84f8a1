#pragma once
// forEachNodeOfPoint<Linear>(grid, points, p, f): f(node, N, gradN) for every node point p
// reaches, the one walk the transfers share whatever the shape functions:
// - linear: the 2^D nodes of the point's cell, weights from its position (grid/LinearStencil.hpp),
//   a fixed loop the compiler unrolls;
// - uGIMP: the per-axis weights cached by the step's first phase (computeWeights), up to 3 nodes
//   per axis, walked by forStencil (solver/Parallel.hpp).
// The positions do not change between the step's point-to-grid and grid-to-point phases, so both
// see the same weights.
#include "grid/LinearStencil.hpp"
#include "solver/Parallel.hpp"

namespace qs {

template <bool Linear, int D, class Set, class F>
inline void forEachNodeOfPoint(const Grid<D>& grid, const Set& points, Index p, F&& f) {
    if constexpr (Linear) {
        const LinearStencil<D> st = linearStencil(grid, &points.x[p * D]);
#pragma GCC unroll 8
        for (int k = 0; k < LinearStencil<D>::kNodes; ++k) f(st.node[k], st.N[k], st.grad[k]);
    } else {
        forStencil<D>(grid, points.shape.start[p], &points.shape.w[p * D * 3], &points.shape.dw[p * D * 3], f);
    }
}

}  // namespace qs
