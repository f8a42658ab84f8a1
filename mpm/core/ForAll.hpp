#pragma once
// The parallel loop over independent items, in one place (as MFEM's forall): forAll(n, f) calls
// f(i) for i in [0, n) with OpenMP's static schedule, where every i writes only its own outputs
// (nodes, cells, points reading the grid, the fields of a point set being reordered); anyOf is
// its parallel OR. The grid's scatter is solver/Parallel.hpp.
//
// Every loop over the points of a set splits them alike (staticShare), so each thread keeps
// working on the same points, and the same rows of the grid, from phase to phase, in its own
// core's cache: the project's machine gives its two cores no shared cache, and a point last
// written on the other core is fetched from there.
//
// Small problems (a 1D column of a few dozen cells) run serially: there the cost of waking
// threads exceeds the work.
#include <omp.h>

#include <algorithm>
#include <vector>

#include "core/Types.hpp"

namespace qs {

constexpr Index kMinParallelItems = 1024;  ///< below this many items a loop runs serially

/// The items [begin, end) of thread t of `threads` under OpenMP's static schedule without a
/// chunk size (the first n % threads threads take one item more).
struct Share {
    Index begin, end;
};
inline Share staticShare(Index n, Index t, Index threads) {
    const Index q = n / threads, r = n % threads;
    const Index begin = t * q + std::min(t, r);
    return {begin, begin + q + (t < r ? 1 : 0)};
}

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

/// f(c) for the cells c in [0, cells) of a set of points sorted by cell (cellStart[c]: the cell's
/// first point; cellStart[cells]: the count), each thread taking the cells whose points start in
/// its static share of the points: a loop over cells that reads or writes their points runs on
/// the core that updates those points (forAll over the points), not on whichever core the cell's
/// index falls to.
template <class F>
inline void forAllCells(Index cells, const std::vector<Index>& cellStart, F&& f) {
    const Index points = cellStart[cells];
    if (cells < kMinParallelItems && points < kMinParallelItems) {
        for (Index c = 0; c < cells; ++c) f(c);
        return;
    }
    // the first cell whose points start at or after a share's first point
    auto firstCell = [&](Index point) {
        return static_cast<Index>(std::lower_bound(cellStart.begin(), cellStart.begin() + cells, point) -
                                  cellStart.begin());
    };
#pragma omp parallel
    {
        const Index t = omp_get_thread_num(), threads = omp_get_num_threads();
        const Index begin = t == 0 ? 0 : firstCell(staticShare(points, t, threads).begin);
        const Index end = t + 1 == threads ? cells : firstCell(staticShare(points, t + 1, threads).begin);
        for (Index c = begin; c < end; ++c) f(c);
    }
}

/// The smallest i in [0, n) for which pred(i) holds, or n if none does (a parallel minimum).
template <class F>
inline Index firstOf(Index n, F&& pred) {
    if (n < kMinParallelItems) {
        for (Index i = 0; i < n; ++i)
            if (pred(i)) return i;
        return n;
    }
    Index first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
    for (Index i = 0; i < n; ++i)
        if (i < first && pred(i)) first = i;
    return first;
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

}  // namespace qs
