#pragma once
// The two parallel loop shapes of the solver, in one place (as MFEM's forall).
//
// forAll(n, f): f(i) for i in [0, n), OpenMP static schedule. Use it where every i writes only
// its own outputs (nodes, cells, points reading the grid).
//
// forEachPointColoured(grid, cellStart, rowsPerSlab, f): f(p) for every point, scattering to the
// grid without races or locks: the grid is cut into slabs of whole rows of cells along the
// vertical axis, and slabs of one colour (even or odd) never share a node. A slab of t rows
// starting at row tb touches node rows tb-1 .. tb+t+1 at most, and the next slab of its colour
// starts at row tb+2t, so t must exceed the reach beyond the slab's own rows:
// - uGIMP: a point in cell row r touches node rows r-1 .. r+2 (kStencil), so t = 3;
// - linear: a point in row r touches node rows r and r+1, but the linear walk writes 2 nodes per
//   axis, starting one node up when the first stencil node's weight is zero. Within an ulp of
//   the node row above its cell a point can have a zero weight at its cell's bottom node (the
//   cell is floor(fl(x/h)), the weight 1 - fl(x - fl(r h))/h), and the walk then adds zero to node
//   row r+2; a non-atomic += 0 can still lose another thread's sum. So t = 2, one row to spare
//   (test_ColouredScatter puts points within an ulp of every node row; 1-row slabs fail it).
// Every node then takes one slab's contributions per colour, each slab's points run in their
// sorted order, and the colours in turn, so the sums are the same whatever the number of
// threads: results are identical for 1 and 2 threads. The points are sorted by cell with the
// vertical axis slowest, so a slab's points are one contiguous range of memory, walked in order:
// the hardware prefetches it. (Blocks of 3 cells per axis in 2^D colours, the earlier scheme,
// jumped between runs of 3 cells' points, and the solid scatter missed the cache at every run:
// docs/performance.md.) The price: a grid of fewer than 2 kMinParallelSlabs slabs (a shallow
// domain, under 4 rows linear or 6 uGIMP) scatters on one thread.
//
// Small problems (a 1D column of a few dozen cells) run serially: there the cost of waking
// threads exceeds the work.
#include <algorithm>
#include <type_traits>

#include "grid/Grid.hpp"

namespace qs {

constexpr Index kMinParallelItems = 4096;  ///< below this many items a loop runs serially
constexpr Index kMinParallelSlabs = 2;     ///< below this many slabs per colour, serially
constexpr Index kLinearSlabRows = 2;       ///< rows of cells per slab of a linear scatter (below)
constexpr Index kGimpSlabRows = 3;         ///< rows of cells per slab of a uGIMP scatter

template <class F>
inline void forAll(Index n, F&& f) {
    // Below the threshold the loop does not enter OpenMP at all: even a region whose `if` is
    // false wakes the runtime's barrier with a futex system call, which cost a quarter of the wall
    // time of a 1D column (21 loops a step).
    if (n < kMinParallelItems) {
        for (Index i = 0; i < n; ++i) f(i);
        return;
    }
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) f(i);
}

/// Whether pred(i) holds for any i in [0, n) (a parallel OR; which i is the caller's to find).
template <class F>
inline bool anyOf(Index n, F&& pred) {
    bool any = false;
    if (n < kMinParallelItems) {
        for (Index i = 0; i < n && !any; ++i) any = pred(i);
        return any;
    }
#pragma omp parallel for schedule(static) reduction(|| : any)
    for (Index i = 0; i < n; ++i) any = any || pred(i);
    return any;
}

/// The rows of cells a slab of forEachPointColoured holds for points of the given shape functions.
inline Index slabRows(bool linearShapes) { return linearShapes ? kLinearSlabRows : kGimpSlabRows; }

template <int D, class F>
void forEachPointColoured(const Grid<D>& grid, const std::vector<Index>& cellStart, Index rowsPerSlab, F&& f) {
    const Index rows = grid.cells(D - 1), rowCells = grid.cellStride(D - 1);
    const Index slabs = (rows + rowsPerSlab - 1) / rowsPerSlab;
    auto slab = [&](Index k) {
        const Index begin = cellStart[k * rowsPerSlab * rowCells];
        const Index end = cellStart[std::min(rows, (k + 1) * rowsPerSlab) * rowCells];
        for (Index p = begin; p < end; ++p) f(p);
    };
    const Index points = cellStart.back();
    if (points < kMinParallelItems || slabs < 2 * kMinParallelSlabs) {  // serially, outside OpenMP (see forAll)
        for (int colour = 0; colour < 2; ++colour)
            for (Index k = colour; k < slabs; k += 2) slab(k);
        return;
    }
    // dynamic: the points are not spread evenly over the rows (the sand lies below the water)
    const Index perColour = slabs / 2, chunk = std::max<Index>(1, perColour / 64);
    for (int colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, chunk)
        for (Index j = 0; j < (slabs - colour + 1) / 2; ++j) slab(colour + 2 * j);
    }
}

/// Calls f(node, N, gradN) for the kStencil^D stencil nodes of point p where N or gradN is not
/// zero, in the same order (axis 0 fastest). The ends of each axis whose weight and slope are
/// both zero are trimmed first: a linear shape function touches 2 of its 3 stencil nodes per
/// axis, so a 3D point visits 8 nodes, not 27. Trimming only skips nodes that were skipped
/// anyway, so the calls, and the sums they make, are the same as without it.
/// The loops are nested per axis (no index arithmetic per node: the flat loop's divisions cost
/// more than the work in 3D), and the products keep the order of the tensor product
/// N = (w_0 w_1) w_2, dN/dx_a = dw_a times the other axes' w in ascending order.
/// forStencilOffsets calls f(node, N, gradN, offset) with the node's place in the stencil per
/// axis (offset[d] in 0..2, the node at start's coordinates + offset), for a transfer that needs
/// the node's position without dividing its index.
///
/// Linear = true is the same walk for linear hats, which reach exactly 2 consecutive nodes of
/// the 3 per axis (they overlap 2h, and the nodes are h apart): the first of them is the first
/// stencil node unless that one is zero (axisWeights zeroes the node outside the point's cell),
/// and the loops have a fixed trip count of 2 with no zero tests (those tests alone were 7 % of
/// the instructions of a 3D step). The only nodes it adds to the trimmed walk are those of a
/// point exactly on a node, whose N and gradN are exactly 0 there: their contributions add
/// zeros, and the sums are the same bit for bit. (For a point at
/// a non-finite position, which the health check reports, the two walks may differ: the zero
/// weights then multiply the point's values, which may be non-finite too.)
template <int D, bool Linear = false, class F>
inline void forStencilOffsets(const Grid<D>& grid, const Index start, const Real* w, const Real* dw, F&& f) {
    constexpr int width = Linear ? 2 : 3;
    int lo[D], hi[D];
    for (int d = 0; d < D; ++d) {
        if constexpr (Linear) {
            lo[d] = (w[d * 3] == 0 && dw[d * 3] == 0) ? 1 : 0;
            continue;  // its trip count is fixed (count below)
        }
        int first = 0, last = 2;
        while (first <= last && w[d * 3 + first] == 0 && dw[d * 3 + first] == 0) ++first;
        while (last >= first && w[d * 3 + last] == 0 && dw[d * 3 + last] == 0) --last;
        lo[d] = first;
        hi[d] = last;
    }
    // Linear: the trip counts are fixed (width), so the compiler unrolls the loops
    auto count = [&](int d) { return Linear ? width : hi[d] - lo[d] + 1; };
    if constexpr (D == 1) {
        for (int a = 0; a < count(0); ++a) {
            const int i = lo[0] + a;
            const Real N = w[i], grad[1] = {dw[i]};
            if (!Linear && N == 0 && grad[0] == 0) continue;
            const int offset[1] = {i};
            f(start + i, N, grad, offset);
        }
    } else if constexpr (D == 2) {
        const Index sy = grid.nodeStride(1);
        for (int b = 0; b < count(1); ++b) {
            const int j = lo[1] + b;
            const Real wy = w[3 + j], dwy = dw[3 + j];
            const Index row = start + j * sy;
            for (int a = 0; a < count(0); ++a) {
                const int i = lo[0] + a;
                const Real wx = w[i], dwx = dw[i];
                const Real N = wx * wy, grad[2] = {dwx * wy, dwy * wx};
                if (!Linear && N == 0 && grad[0] == 0 && grad[1] == 0) continue;
                const int offset[2] = {i, j};
                f(row + i, N, grad, offset);
            }
        }
    } else {
        const Index sy = grid.nodeStride(1), sz = grid.nodeStride(2);
        for (int c = 0; c < count(2); ++c) {
            const int k = lo[2] + c;
            const Real wz = w[6 + k], dwz = dw[6 + k];
            for (int b = 0; b < count(1); ++b) {
                const int j = lo[1] + b;
                const Real wy = w[3 + j], dwy = dw[3 + j];
                const Index row = start + k * sz + j * sy;
                for (int a = 0; a < count(0); ++a) {
                    const int i = lo[0] + a;
                    const Real wx = w[i], dwx = dw[i];
                    const Real N = (wx * wy) * wz;
                    const Real grad[3] = {(dwx * wy) * wz, (dwy * wx) * wz, (dwz * wx) * wy};
                    if (!Linear && N == 0 && grad[0] == 0 && grad[1] == 0 && grad[2] == 0) continue;
                    const int offset[3] = {i, j, k};
                    f(row + i, N, grad, offset);
                }
            }
        }
    }
}

template <int D, bool Linear = false, class F>
inline void forStencil(const Grid<D>& grid, const Index start, const Real* w, const Real* dw, F&& f) {
    forStencilOffsets<D, Linear>(grid, start, w, dw, [&](Index i, Real N, const Real* gradN, const int*) { f(i, N, gradN); });
}

/// Calls body(std::true_type) when the run's shape functions are linear, body(std::false_type)
/// otherwise: the transfers take the constant as forStencil's Linear, one branch per loop.
template <class F>
inline void withStencilKind(bool linear, F&& body) {
    if (linear) body(std::true_type{});
    else body(std::false_type{});
}

}  // namespace qs
