// The reductions over ranks (parallel/Communicator.hpp), run under `mpirun -np 3`: every rank
// gets the same bits, and those are the sum in rank order, the same as a serial loop over the
// ranks' values (so two runs at the same N give the same bytes, issue 41).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "parallel/Communicator.hpp"

using namespace qs;

namespace {

/// Values whose sum depends on the order of the additions: 1e16 and -1e16 cancel exactly only
/// when added before the small ones.
double valueOf(int rank) {
    const double values[] = {1e16, 1.0, -1e16, 3.0, 0.1};
    return values[rank % 5] + 1e-3 * rank;
}

std::uint64_t bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

}  // namespace

TEST(Reductions, RunOnSeveralRanks) {
    EXPECT_GE(Communicator::world().size(), 2) << "this test runs under mpirun -np 2 or more";
}

TEST(Reductions, SumIsInRankOrderAndTheSameOnEveryRank) {
    const Communicator& w = Communicator::world();
    const double total = w.sum(valueOf(w.rank()));
    double serial = 0;
    for (int r = 0; r < w.size(); ++r) serial += valueOf(r);
    EXPECT_EQ(bits(total), bits(serial)) << total << " against " << serial;
    for (double other : w.allGather(total)) EXPECT_EQ(bits(other), bits(total));
}

TEST(Reductions, SumInPlaceIsInRankOrder) {
    const Communicator& w = Communicator::world();
    std::vector<double> v{valueOf(w.rank()), valueOf(w.rank() + 1), 1.0 * w.rank()};
    w.sumInPlace(v);
    std::vector<double> serial(3, 0.0);
    for (int r = 0; r < w.size(); ++r) {
        serial[0] += valueOf(r);
        serial[1] += valueOf(r + 1);
        serial[2] += 1.0 * r;
    }
    for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(v[k]), bits(serial[k])) << k;
}

TEST(Reductions, IntegersMaximaAndFlags) {
    const Communicator& w = Communicator::world();
    const int n = w.size();
    EXPECT_EQ(w.sum(static_cast<long long>(w.rank() + 1)), static_cast<long long>(n) * (n + 1) / 2);
    EXPECT_EQ(w.max(double(w.rank())), double(n - 1));
    EXPECT_EQ(w.min(double(w.rank())), 0.0);
    EXPECT_TRUE(w.any(w.rank() == n - 1));  // one rank's error reaches every rank
    EXPECT_FALSE(w.any(false));
}

TEST(Reductions, BroadcastFromAnyRank) {
    const Communicator& w = Communicator::world();
    const int root = w.size() - 1;
    const std::string mine = "rank " + std::to_string(w.rank()) + std::string(w.rank() * 100, '.');
    EXPECT_EQ(w.broadcast(mine, root), "rank " + std::to_string(root) + std::string(root * 100, '.'));
}
