// points/PointSet.hpp: reordering and compacting a point set's fields. The reorder runs in
// parallel and must give what the serial definition gives (new point k is old point order[k]),
// for fields of D, 1 and 0 components, reals and ints; compacting from a first index keeps the
// points before it as they were and removes the flagged ones after it, in order.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "core/ForAll.hpp"
#include "points/SolidPoints.hpp"

using namespace qs;

namespace {

/// A solid point set whose every field holds values that name the point and the component.
SolidPoints<2> labelled(std::size_t n) {
    SolidPoints<2> s;
    s.internalCount = 0;  // a field of no components
    resizePoints(s, n);
    for (std::size_t p = 0; p < n; ++p) {
        for (int d = 0; d < 2; ++d) {
            s.x[p * 2 + d] = p + 0.1 * d;
            s.v[p * 2 + d] = -double(p) - 0.1 * d;
        }
        s.mass[p] = 1000.0 + p;
        s.volume[p] = 2000.0 + p;
        s.porosity[p] = 3000.0 + p;
        for (int k = 0; k < 6; ++k) s.stress[p * 6 + k] = 10.0 * p + k;
        s.state[p] = static_cast<int>(p % 2);
        s.material[p] = static_cast<int>(p);
        for (int k = 0; k < 4; ++k) s.velocityGradient[p * 4 + k] = 100.0 * p + k;
    }
    return s;
}

/// Whether point k of `s` holds what point `from` of labelled() held.
void expectPoint(const SolidPoints<2>& s, std::size_t k, std::size_t from) {
    EXPECT_EQ(s.x[k * 2 + 1], from + 0.1) << "point " << k;
    EXPECT_EQ(s.v[k * 2], -double(from));
    EXPECT_EQ(s.mass[k], 1000.0 + from);
    EXPECT_EQ(s.volume[k], 2000.0 + from);
    EXPECT_EQ(s.porosity[k], 3000.0 + from);
    EXPECT_EQ(s.stress[k * 6 + 5], 10.0 * from + 5);
    EXPECT_EQ(s.state[k], static_cast<int>(from % 2));
    EXPECT_EQ(s.material[k], static_cast<int>(from));
    EXPECT_EQ(s.velocityGradient[k * 4 + 3], 100.0 * from + 3);
}

}  // namespace

TEST(PointSet, AParallelReorderMovesEveryFieldAsTheSerialDefinition) {
    const std::size_t n = 3 * kMinParallelItems + 7;
    std::vector<Index> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    for (int threads : {1, 2, 3}) {
        SCOPED_TRACE(testing::Message() << threads << " threads");
        SolidPoints<2> s = labelled(n);
        ReorderScratch scratch;
        const int before = omp_get_max_threads();
        omp_set_num_threads(threads);
        reorderPoints(s, order, scratch);
        omp_set_num_threads(before);
        for (std::size_t k = 0; k < n; ++k) {
            expectPoint(s, k, order[k]);
            if (testing::Test::HasFailure()) return;
        }
    }
}

TEST(PointSet, CompactingFromAFirstIndexKeepsThePointsBeforeIt) {
    const std::size_t n = 50, first = 30;
    SolidPoints<2> s = labelled(n);
    std::vector<char> drop(n, 7);  // before `first` the flags are not read: anything there
    std::vector<std::size_t> kept;
    for (std::size_t p = 0; p < first; ++p) kept.push_back(p);
    for (std::size_t p = first; p < n; ++p) {
        drop[p] = (p % 3 == 0) || p == first;  // the first point itself is removed
        if (!drop[p]) kept.push_back(p);
    }
    EXPECT_EQ(compactPoints(s, drop, first), n - kept.size());
    ASSERT_EQ(s.size(), kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k) expectPoint(s, k, kept[k]);
    // and from 0, nothing flagged: nothing moves
    SolidPoints<2> t = labelled(n);
    EXPECT_EQ(compactPoints(t, std::vector<char>(n, 0)), 0u);
    for (std::size_t k = 0; k < n; ++k) expectPoint(t, k, k);
}
