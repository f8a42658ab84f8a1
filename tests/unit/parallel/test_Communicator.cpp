// One rank (no mpirun, or a build without MPI): every reduction is its argument, so the serial
// path through the parallel code is the code that ran before MPI. The reductions over several
// ranks are tested under mpirun (tests/mpi/).
#include <gtest/gtest.h>

#include "parallel/Communicator.hpp"

using namespace qs;

TEST(Communicator, OneRankReducesToItsOwnValues) {
    const Communicator& w = Communicator::world();
    ASSERT_EQ(w.size(), 1);
    EXPECT_EQ(w.rank(), 0);
    EXPECT_FALSE(w.parallel());
    EXPECT_EQ(w.sum(0.1), 0.1);
    EXPECT_EQ(w.sum(7LL), 7LL);
    EXPECT_EQ(w.max(-2.0), -2.0);
    EXPECT_EQ(w.min(3.0), 3.0);
    EXPECT_TRUE(w.any(true));
    EXPECT_FALSE(w.any(false));
    std::vector<double> v{1, 2, 3};
    w.sumInPlace(v);
    EXPECT_EQ(v, (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(w.allGather(4.5), std::vector<double>{4.5});
    EXPECT_EQ(w.broadcast("text"), "text");
}
