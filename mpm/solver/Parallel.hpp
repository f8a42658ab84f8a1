#pragma once
// The solver's parallel scatter to the grid, and the stencil walk of uGIMP (the loops over
// independent items, forAll and anyOf, are in core/ForAll.hpp).
//
// forEachPointColoured(grid, cellStart, rowsPerSlab, f): f(p) for every point, scattering to the
// grid without races or locks: the grid is cut into slabs of whole rows of cells along the
// vertical axis, and slabs of one colour (even or odd) never share a node. A slab of t rows
// starting at row tb touches node rows tb-1 .. tb+t+1 at most, and the next slab of its colour
// starts at row tb+2t, so t must exceed the reach beyond the slab's own rows:
// - uGIMP: a point in cell row r touches node rows r-1 .. r+2 (kStencil), so t = 3;
// - linear: a point in cell row r touches node rows r and r+1 only (grid/LinearStencil.hpp takes
//   the nodes of the very cell Grid::cellOf sorted the point into, even within an ulp of a node
//   row), so t = 1. (The walk over per-axis weights used before could start a node up within an
//   ulp of a node row and add zero to row r+2, which needed 2 rows; test_ColouredScatter puts
//   points within an ulp of every node row.)
// Every node then takes one slab's contributions per colour, each slab's points run in their
// sorted order, and the colours in turn, so the sums are the same whatever the number of
// threads: results are identical for 1 and 2 threads. The points are sorted by cell with the
// vertical axis slowest, so a slab's points are one contiguous range of memory, walked in order:
// the hardware prefetches it. (Blocks of 3 cells per axis in 2^D colours, the earlier scheme,
// jumped between runs of 3 cells' points, and the solid scatter missed the cache at every run:
// docs/performance.md.) A thread takes the slabs that start in its static share of the points,
// so it scatters the points it updates in forAll's loops. The price: a grid of fewer than
// 2 kMinParallelSlabs slabs (a shallow domain, under 4 rows linear or 6 uGIMP) scatters on one
// thread.
//
// Small problems (a 1D column of a few dozen cells) scatter serially: there the cost of waking
// threads exceeds the work.
#include <omp.h>

#include <algorithm>
#include <type_traits>

#include "core/ForAll.hpp"
#include "grid/Grid.hpp"

namespace qs {

constexpr Index kMinParallelSlabs = 2;     ///< below this many slabs per colour, serially
constexpr Index kLinearSlabRows = 1;       ///< rows of cells per slab of a linear scatter (below)
constexpr Index kGimpSlabRows = 3;         ///< rows of cells per slab of a uGIMP scatter

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
    // Each thread scatters the slabs that start in its share of the points, the share forAll's
    // static schedule gives it (staticShare): the points, and the rows of the grid, a thread
    // scatters are the ones it updates in the other phases, so they stay in its core's cache.
    // Handed out dynamically, the slabs of the scatter and the points of the gather fell to
    // different threads, and the gathers on 2 threads ran at 1.2 times the speed of 1 (the two
    // cores of the project's machine share no cache: each fetched the other's writes).
#pragma omp parallel
    {
        const Share mine = staticShare(points, omp_get_thread_num(), omp_get_num_threads());
        for (int colour = 0; colour < 2; ++colour) {
            for (Index k = colour; k < slabs; k += 2) {
                const Index begin = cellStart[k * rowsPerSlab * rowCells];
                if (begin >= mine.begin && begin < mine.end) slab(k);
            }
#pragma omp barrier
        }
    }
}

/// Calls f(node, N, gradN) for the kStencil^D stencil nodes of point p where N or gradN is not
/// zero, in the same order (axis 0 fastest): the uGIMP walk over the per-axis weights of
/// grid/ShapeFunctions.hpp (linear shape functions have their own, grid/LinearStencil.hpp). The
/// ends of each axis whose weight and slope are both zero are trimmed first, which only skips
/// nodes that were skipped anyway, so the calls, and the sums they make, are the same as without it.
/// The loops are nested per axis (no index arithmetic per node: the flat loop's divisions cost
/// more than the work in 3D), and the products keep the order of the tensor product
/// N = (w_0 w_1) w_2, dN/dx_a = dw_a times the other axes' w in ascending order.
/// forStencilOffsets calls f(node, N, gradN, offset) with the node's place in the stencil per
/// axis (offset[d] in 0..2, the node at start's coordinates + offset), for a transfer that needs
/// the node's position without dividing its index.
template <int D, class F>
inline void forStencilOffsets(const Grid<D>& grid, const Index start, const Real* w, const Real* dw, F&& f) {
    int lo[D], hi[D];
    for (int d = 0; d < D; ++d) {
        int first = 0, last = 2;
        while (first <= last && w[d * 3 + first] == 0 && dw[d * 3 + first] == 0) ++first;
        while (last >= first && w[d * 3 + last] == 0 && dw[d * 3 + last] == 0) --last;
        lo[d] = first;
        hi[d] = last;
    }
    if constexpr (D == 1) {
        for (int i = lo[0]; i <= hi[0]; ++i) {
            const Real N = w[i], grad[1] = {dw[i]};
            if (N == 0 && grad[0] == 0) continue;
            const int offset[1] = {i};
            f(start + i, N, grad, offset);
        }
    } else if constexpr (D == 2) {
        const Index sy = grid.nodeStride(1);
        for (int j = lo[1]; j <= hi[1]; ++j) {
            const Real wy = w[3 + j], dwy = dw[3 + j];
            const Index row = start + j * sy;
            for (int i = lo[0]; i <= hi[0]; ++i) {
                const Real wx = w[i], dwx = dw[i];
                const Real N = wx * wy, grad[2] = {dwx * wy, dwy * wx};
                if (N == 0 && grad[0] == 0 && grad[1] == 0) continue;
                const int offset[2] = {i, j};
                f(row + i, N, grad, offset);
            }
        }
    } else {
        const Index sy = grid.nodeStride(1), sz = grid.nodeStride(2);
        for (int k = lo[2]; k <= hi[2]; ++k) {
            const Real wz = w[6 + k], dwz = dw[6 + k];
            for (int j = lo[1]; j <= hi[1]; ++j) {
                const Real wy = w[3 + j], dwy = dw[3 + j];
                const Index row = start + k * sz + j * sy;
                for (int i = lo[0]; i <= hi[0]; ++i) {
                    const Real wx = w[i], dwx = dw[i];
                    const Real N = (wx * wy) * wz;
                    const Real grad[3] = {(dwx * wy) * wz, (dwy * wx) * wz, (dwz * wx) * wy};
                    if (N == 0 && grad[0] == 0 && grad[1] == 0 && grad[2] == 0) continue;
                    const int offset[3] = {i, j, k};
                    f(row + i, N, grad, offset);
                }
            }
        }
    }
}

template <int D, class F>
inline void forStencil(const Grid<D>& grid, const Index start, const Real* w, const Real* dw, F&& f) {
    forStencilOffsets<D>(grid, start, w, dw, [&](Index i, Real N, const Real* gradN, const int*) { f(i, N, gradN); });
}

/// Calls body(std::true_type) when the run's shape functions are linear, body(std::false_type)
/// otherwise: the transfers take the constant as forEachNodeOfPoint's Linear (PointStencil.hpp),
/// one branch per loop.
template <class F>
inline void withStencilKind(bool linear, F&& body) {
    if (linear) body(std::true_type{});
    else body(std::false_type{});
}

}  // namespace qs
