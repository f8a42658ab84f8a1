// core/ForAll.hpp: the parallel loops. Every item once, whatever the thread count; forAllCells
// gives each thread the cells whose points start in its static share of the points (the share
// forAll's static schedule gives it), for point layouts skewed, empty at either end, with no
// points, and with one cell holding most of them; firstOf and anyOf agree with a serial scan.
#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

#include "core/ForAll.hpp"

using namespace qs;

namespace {

/// cellStart for the given number of points per cell (each cell's first point, then the count).
std::vector<Index> startsOf(const std::vector<Index>& perCell) {
    std::vector<Index> start(perCell.size() + 1, 0);
    for (std::size_t c = 0; c < perCell.size(); ++c) start[c + 1] = start[c] + perCell[c];
    return start;
}

/// Runs f with `threads` OpenMP threads, then restores the count.
template <class F>
void withThreads(int threads, F&& f) {
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    f();
    omp_set_num_threads(before);
}

}  // namespace

TEST(ForAll, StaticSharesPartitionTheItemsLikeOpenMPsStaticSchedule) {
    for (Index n : {0, 1, 2, 3, 7, 1000, 1001, 4097})
        for (Index threads : {1, 2, 3, 4}) {
            Index next = 0;
            for (Index t = 0; t < threads; ++t) {
                const Share s = staticShare(n, t, threads);
                EXPECT_EQ(s.begin, next) << "n " << n << ", thread " << t << " of " << threads;
                EXPECT_GE(s.end, s.begin);
                EXPECT_LE(s.end - s.begin, n / threads + 1);
                next = s.end;
            }
            EXPECT_EQ(next, n);
            // and forAll's loop gives thread t exactly that share
            if (n >= kMinParallelItems)
                withThreads(static_cast<int>(threads), [&] {
                    std::vector<int> owner(n, -1);
                    forAll(n, [&](Index i) { owner[i] = omp_get_thread_num(); });
                    for (Index t = 0; t < threads; ++t) {
                        const Share s = staticShare(n, t, threads);
                        for (Index i = s.begin; i < s.end; ++i) ASSERT_EQ(owner[i], t) << "item " << i;
                    }
                });
        }
}

TEST(ForAll, CellLoopsVisitEveryCellOnceOnTheThreadOfItsPoints) {
    const Index many = 4 * kMinParallelItems;
    std::vector<std::vector<Index>> layouts;
    layouts.push_back(std::vector<Index>(3000, 5));  // uniform
    std::vector<Index> skewed(3000, 0);
    for (Index c = 100; c < 2000; ++c) skewed[c] = c % 7 == 0 ? 40 : 1;  // empty at both ends
    layouts.push_back(skewed);
    std::vector<Index> oneBig(3000, 1);
    oneBig[1500] = many;  // most points in one cell
    layouts.push_back(oneBig);
    layouts.push_back(std::vector<Index>(5000, 0));  // no points (cells above the threshold)
    std::vector<Index> few(50, 0);
    few[10] = many;  // few cells, many points
    layouts.push_back(few);
    for (std::size_t l = 0; l < layouts.size(); ++l)
        for (int threads : {1, 2, 3, 4}) {
            SCOPED_TRACE(testing::Message() << "layout " << l << ", " << threads << " threads");
            const std::vector<Index> start = startsOf(layouts[l]);
            const Index cells = static_cast<Index>(layouts[l].size()), points = start.back();
            std::vector<int> visits(cells, 0), owner(cells, -1);
            withThreads(threads, [&] {
                forAllCells(cells, start, [&](Index c) {
                    ++visits[c];
                    owner[c] = omp_get_thread_num();
                });
            });
            for (Index c = 0; c < cells; ++c) ASSERT_EQ(visits[c], 1) << "cell " << c;
            // a cell with points runs on the thread whose share holds its first point
            const bool parallel = !(cells < kMinParallelItems && points < kMinParallelItems);
            if (!parallel) continue;
            for (Index c = 0; c < cells; ++c) {
                if (layouts[l][c] == 0) continue;
                const Share s = staticShare(points, owner[c], threads);
                EXPECT_TRUE(start[c] >= s.begin && start[c] < s.end)
                    << "cell " << c << " (first point " << start[c] << ") ran on thread " << owner[c];
            }
        }
}

TEST(ForAll, FirstOfAndAnyOfAgreeWithASerialScan) {
    for (Index n : {Index(10), Index(3 * kMinParallelItems)})
        for (int threads : {1, 2, 3})
            for (Index hit : {Index(-1), Index(0), n / 3, n - 1}) {
                SCOPED_TRACE(testing::Message() << "n " << n << ", hit " << hit << ", " << threads << " threads");
                // every item from `hit` on matches, and one more early item in the last third
                auto pred = [&](Index i) { return hit >= 0 && (i == hit || i > (2 * n) / 3 + hit % 5); };
                Index serial = n;
                for (Index i = n - 1; i >= 0; --i)
                    if (pred(i)) serial = i;
                withThreads(threads, [&] {
                    EXPECT_EQ(firstOf(n, pred), serial);
                    EXPECT_EQ(anyOf(n, pred), serial < n);
                });
            }
}
