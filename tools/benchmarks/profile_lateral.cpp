// A driver for instruction-count profiles of the 2D lateral benchmark's column (BM_Step2D/<columns>
// in bench_step.cpp: the coarse seepage column, 9.3 mm cells, deformable, inflow and overflow
// active): 5 steps past the start, then N more (default 20). Callgrind counts instructions, so
// the figures repeat on a busy machine; with OMP_NUM_THREADS=1 everything outside GOMP_parallel
// in its inclusive costs is the step's serial part.
//   g++ -O3 -g -DNDEBUG -std=c++17 -fopenmp -I mpm -I /usr/include/eigen3 -I/usr/include/hdf5/serial \
//       tools/benchmarks/profile_lateral.cpp build/mpm/libquicksand_mpm.a -ltomlplusplus \
//       -L/usr/lib/x86_64-linux-gnu/hdf5/serial -lhdf5 -lz -o /tmp/profile2d
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind /tmp/profile2d 500 20; callgrind_annotate --inclusive=yes callgrind.out.*
// (run from the repository root; arguments: columns, steps)
#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include <cstdlib>
#include <string>
using namespace qs;
int main(int argc, char** argv) {
    const long columns = argc > 1 ? std::atol(argv[1]) : 500;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
    CaseConfig c = loadCase("cases/verification/critical_gradient");
    const double h = 0.0093;
    c.grid.cellSize = h; c.column.chamberHeight = 2 * h;
    const int sandCells = static_cast<int>(0.186 / h + 0.5);
    c.layers.front().thickness = sandCells * h;
    c.column.waterLevel = c.column.chamberHeight + (sandCells + 2) * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 4 * h;
    c.reservoir.head = c.column.waterLevel + 0.1; c.reservoir.headRate = 0;
    c.initial.rigidSkeleton = false;
    c.grid.dimension = 2; c.grid.width = columns * h;
    auto r = makeReservoirModel(c); DoublePointSolver<2> s(c, *r);
    for (int k = 0; k < 5 + steps; ++k) s.step();
}
