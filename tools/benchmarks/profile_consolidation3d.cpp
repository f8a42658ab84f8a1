// A driver for instruction-count profiles of the 3D step (callgrind counts instructions, so the
// figures repeat on a busy machine): N steps (default 20) of cases/benchmark/consolidation3d.
//   g++ -O3 -DNDEBUG -std=c++17 -fopenmp -I mpm -I /usr/include/eigen3 -I/usr/include/hdf5/serial \
//       tools/benchmarks/profile_consolidation3d.cpp build/mpm/libquicksand_mpm.a -ltomlplusplus \
//       -L/usr/lib/x86_64-linux-gnu/hdf5/serial -lhdf5 -lz -o /tmp/profile3d
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind /tmp/profile3d 10; callgrind_annotate callgrind.out.*
// (run from the repository root)
#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include <cstdlib>
using namespace qs;
int main(int argc, char** argv) {
    CaseConfig c = loadCase("cases/benchmark/consolidation3d");
    auto r = makeReservoirModel(c); DoublePointSolver<3> s(c, *r);
    const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
    for (int k = 0; k < steps; ++k) s.step();
}
