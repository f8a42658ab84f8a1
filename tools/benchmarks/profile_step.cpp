// A driver for instruction-count profiles of the step (callgrind counts instructions, so the
// figures repeat on a shared machine): 300 steps of the 8 000-point column of bench_step.cpp.
//   g++ -O2 -g -std=c++17 -fopenmp -I mpm -I /usr/include/eigen3 -I/usr/include/hdf5/serial \
//       tools/benchmarks/profile_step.cpp build/mpm/libquicksand_mpm.a -ltomlplusplus \
//       -L/usr/lib/x86_64-linux-gnu/hdf5/serial -lhdf5 -o /tmp/profile_step
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind /tmp/profile_step; callgrind_annotate callgrind.out.*
#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"
using namespace qs;
int main() {
    CaseConfig c = loadCase("cases/verification/critical_gradient");  // run from the repository root
    const double h = 1.0 / 10753; c.grid.cellSize = h; c.column.chamberHeight = 2*h;
    const int n = int(0.186/h+0.5); c.layers.front().thickness = n*h;
    c.column.waterLevel = c.column.chamberHeight + (n+2)*h; c.column.overflowLevel = c.column.waterLevel; c.column.top = c.column.waterLevel + 4*h;
    c.reservoir.head = c.column.waterLevel + 0.1; c.reservoir.headRate = 0;
    auto r = makeReservoirModel(c); DoublePointSolver<1> s(c, *r);
    for (int k = 0; k < 300; ++k) s.step();
}
