// GoogleTest's main inside an MPI session: every rank runs every test; mpirun's exit code is
// non-zero when any rank's test failed. Each rank prints its report (a failure on rank 2 is
// seen where it happened).
#include <gtest/gtest.h>

#include "parallel/Communicator.hpp"

int main(int argc, char** argv) {
    qs::MpiSession mpi(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    // every rank's result: one that failed fails the whole run
    return qs::Communicator::world().any(failed != 0) ? 1 : 0;
}
