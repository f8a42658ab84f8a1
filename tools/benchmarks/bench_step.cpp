// Throughput of the double-point step (material-point updates per second).
//
//   build/tools/benchmarks/quicksand_benchmarks            (tools/benchmark.sh runs it and the
//                                                          longest verification case)
// BM_Step/<cells per metre>: one step of the coarse steady-seepage column (1D, rigid skeleton,
// inflow and outflow active) refined to the given cell size; items = points x steps.
// BM_Step2D/<columns>, BM_Step3D/<columns>: the same column (9.3 mm cells, deformable) made
// <columns> cells of the cross-section wide (2D: columns across; 3D: about sqrt(columns) by
// sqrt(columns)), about 200 points per column: 1e4 to 1e6 points. Counters: points, and
// bytes_per_point, the resident memory the solver added (grid included) per point.
// BM_StepSynchronisation/<0|1>: what synchronising the step's phases costs on this machine, with
// next to no work: kPhasesPerStep loops of 2048 items, each its own parallel region (/0: forAll, as the
// step runs today), or all in one region with a barrier after each loop (/1). On 2 threads its
// time less half its 1-thread time bounds the lateral benchmarks' speed-up (tools/benchmark.sh
// --lateral prints the bound).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <malloc.h>
#include <unistd.h>
#include <vector>

#include "core/ForAll.hpp"
#include "case/CaseLoader.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

namespace {

qs::CaseConfig benchmarkCase(double cellSize, bool rigid) {
    qs::CaseConfig c = qs::loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/critical_gradient");
    // keep the geometry a whole number of cells
    const double h = cellSize;
    c.grid.cellSize = h;
    c.column.chamberHeight = 2 * h;
    const int sandCells = static_cast<int>(0.186 / h + 0.5);
    c.layers.front().thickness = sandCells * h;
    c.column.waterLevel = c.column.chamberHeight + (sandCells + 2) * h;
    c.column.overflowLevel = c.column.waterLevel;
    c.column.top = c.column.waterLevel + 4 * h;
    c.reservoir.head = c.column.waterLevel + 0.1;
    c.reservoir.headRate = 0;
    c.initial.rigidSkeleton = rigid;
    return c;
}

void BM_Step(benchmark::State& state) {
    const double h = 1.0 / state.range(0);
    const qs::CaseConfig c = benchmarkCase(h, state.range(1) != 0);
    auto reservoir = qs::makeReservoirModel(c);
    qs::DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 100; ++k) solver.step();  // past the start-up transient
    std::size_t points = 0;
    for (auto _ : state) {
        solver.step();
        points += solver.solid().size() + solver.liquid().size();
    }
    state.SetItemsProcessed(static_cast<int64_t>(points));
    state.counters["points"] = static_cast<double>(solver.solid().size() + solver.liquid().size());
}
BENCHMARK(BM_Step)->ArgsProduct({{108, 1075, 10753}, {0, 1}})->Unit(benchmark::kMicrosecond);

/// Resident memory of this process (bytes), from /proc/self/statm.
double residentBytes() {
    std::ifstream statm("/proc/self/statm");
    double size = 0, resident = 0;
    statm >> size >> resident;
    return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

template <int D>
void BM_StepLateral(benchmark::State& state) {
    const long columns = state.range(0);
    qs::CaseConfig c = benchmarkCase(0.0093, false);
    const long across = D == 2 ? columns : std::max(1L, std::lround(std::sqrt(double(columns))));
    c.grid.dimension = D;
    c.grid.width = across * c.grid.cellSize;
    c.grid.crossSectionArea = D == 3 ? c.grid.width * c.grid.width : c.grid.crossSectionArea;
    // the memory an earlier, larger benchmark freed goes back to the system first: reused in
    // place, it added nothing to the resident size (BM_Step3D/49 after BM_Step2D/5000 read 0)
    malloc_trim(0);
    const double before = residentBytes();
    auto reservoir = qs::makeReservoirModel(c);
    qs::DoublePointSolver<D> solver(c, *reservoir);
    for (int k = 0; k < 5; ++k) solver.step();  // every array touched once
    const double points = static_cast<double>(solver.solid().size() + solver.liquid().size());
    const double added = residentBytes() - before;
    std::size_t updates = 0;
    for (auto _ : state) {
        solver.step();
        updates += solver.solid().size() + solver.liquid().size();
    }
    state.SetItemsProcessed(static_cast<int64_t>(updates));
    state.counters["points"] = points;
    state.counters["bytes_per_point"] = added / points;
}
BENCHMARK_TEMPLATE(BM_StepLateral, 2)->Name("BM_Step2D")->Arg(50)->Arg(500)->Arg(5000)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_StepLateral, 3)->Name("BM_Step3D")->Arg(49)->Arg(484)->Arg(5041)->Unit(benchmark::kMillisecond);

/// The piping cases as shipped (cases/piping2D, cases/piping3D: random beds, Mohr-Coulomb, the
/// lumped feed at i0 = 1.5), from their first steps. Counter sim_seconds_per_hour: the simulated
/// time one hour of wall time reaches at this speed, the figure the step-size work is measured by
/// (docs/performance.md, "Piping"). /0 as shipped (smooth walls), /1 with rough walls
/// (column.wall_friction_angle = 30 deg, boundary/RoughWalls.hpp): the walls' share of the step.
template <int D>
void BM_Piping(benchmark::State& state) {
    qs::CaseConfig c =
        qs::loadCase(std::string(QUICKSAND_SOURCE_DIR) + (D == 2 ? "/cases/piping2D" : "/cases/piping3D"));
    if (state.range(0) == 1) c.column.wallFrictionAngle = 30;
    auto reservoir = qs::makeReservoirModel(c);
    qs::DoublePointSolver<D> solver(c, *reservoir);
    for (int k = 0; k < 20; ++k) solver.step();
    double simulated = 0;
    std::size_t updates = 0;
    for (auto _ : state) {
        solver.step();
        simulated += solver.dt();
        updates += solver.solid().size() + solver.liquid().size();
    }
    state.SetItemsProcessed(static_cast<int64_t>(updates));
    state.counters["points"] = static_cast<double>(solver.solid().size() + solver.liquid().size());
    state.counters["sim_seconds_per_hour"] = benchmark::Counter(3600 * simulated, benchmark::Counter::kIsRate);
}
BENCHMARK_TEMPLATE(BM_Piping, 2)->Name("BM_Piping2D")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->MinTime(2.0);
BENCHMARK_TEMPLATE(BM_Piping, 3)->Name("BM_Piping3D")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

/// A fluidised bed in 2D, the P0 sand of problem 7 held at n = 0.452 by its equilibrium flux on
/// 6.2 mm cells, 24 across: every cell is stress-free sand, so the particle phase and the front
/// diffusion act everywhere. /0 as shipped (no particle phase), /1 with Foscolo and Gibilaro's
/// force and the front diffusion at fronts only (front_threshold = 0.01): their share of the step
/// where they act (physics/ParticlePhase.hpp).
void BM_FluidisedBed2D(benchmark::State& state) {
    qs::CaseConfig c = qs::loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/bed_expansion");
    c.grid.dimension = 2;
    c.grid.width = 24 * c.grid.cellSize;
    auto& m = c.materials.front();
    m.porosity = 0.452;
    m.maxPorosity = 0.41;
    c.initial.state = qs::InitialState::Fluidised;
    c.initial.filterVelocity = 1.380e-3;
    c.gate.flux = 1.380e-3;
    c.monitors.clear();
    if (state.range(0) == 1) {
        m.particlePhase = qs::ParticlePhaseModel::FoscoloGibilaro;
        m.particleGrainSize = m.permeability.grainSize;
        m.frontThreshold = 0.01;
    }
    auto reservoir = qs::makeReservoirModel(c);
    qs::DoublePointSolver<2> solver(c, *reservoir);
    for (int k = 0; k < 20; ++k) solver.step();
    std::size_t updates = 0;
    for (auto _ : state) {
        solver.step();
        updates += solver.solid().size() + solver.liquid().size();
    }
    state.SetItemsProcessed(static_cast<int64_t>(updates));
    state.counters["points"] = static_cast<double>(solver.solid().size() + solver.liquid().size());
}
BENCHMARK(BM_FluidisedBed2D)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond)->MinTime(2.0);

/// The parallel regions of one step of BM_Step2D/50 and BM_Step3D/49 (callgrind's count of calls
/// to GOMP_parallel over 60 steps: 1605, with the set-up's).
constexpr int kPhasesPerStep = 26;

void BM_StepSynchronisation(benchmark::State& state) {
    const bool oneRegion = state.range(0) == 1;
    std::vector<double> a(2 * qs::kMinParallelItems, 1.0);
    const long n = static_cast<long>(a.size());
    for (auto _ : state) {
        if (oneRegion) {
#pragma omp parallel
            for (int phase = 0; phase < kPhasesPerStep; ++phase) {
#pragma omp for schedule(static)
                for (long i = 0; i < n; ++i) a[i] += 1e-9;
            }
        } else {  // the step's own loop, above its serial threshold
            for (int phase = 0; phase < kPhasesPerStep; ++phase) qs::forAll(n, [&](qs::Index i) { a[i] += 1e-9; });
        }
        benchmark::DoNotOptimize(a.data());
    }
    state.counters["phases"] = kPhasesPerStep;
}
BENCHMARK(BM_StepSynchronisation)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
