// The benchmarks' main: Google Benchmark's, inside MPI when hypre's benchmark is built (hypre's
// objects live on an MPI communicator; here one rank, without mpirun). hypre itself is
// initialised by DistributedPressureSolver on first use.
#include <benchmark/benchmark.h>

#ifdef QUICKSAND_HAVE_HYPRE
#include <mpi.h>
#endif

int main(int argc, char** argv) {
#ifdef QUICKSAND_HAVE_HYPRE
    MPI_Init(&argc, &argv);
#endif
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
#ifdef QUICKSAND_HAVE_HYPRE
    MPI_Finalize();
#endif
    return 0;
}
