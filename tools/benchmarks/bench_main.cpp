// The benchmarks' main: Google Benchmark's, inside MPI when hypre's benchmark is built (hypre's
// objects live on an MPI communicator; here one rank, without mpirun).
#include <benchmark/benchmark.h>

#ifdef QUICKSAND_HAVE_HYPRE
#include <HYPRE_utilities.h>
#include <mpi.h>
#endif

int main(int argc, char** argv) {
#ifdef QUICKSAND_HAVE_HYPRE
    MPI_Init(&argc, &argv);
    HYPRE_Init();
#endif
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
#ifdef QUICKSAND_HAVE_HYPRE
    HYPRE_Finalize();
    MPI_Finalize();
#endif
    return 0;
}
