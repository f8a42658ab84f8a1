#pragma once
// RunSize: what a case will take before it runs (cells, points, steps, memory, wall time), from
// the case alone: nothing is allocated, so `quicksand check` can refuse a case that would not fit
// the machine instead of `run` ending in std::bad_alloc.
//
//   const RunSize size = estimateRunSize(config);
//   if (size.peakBytes > machineMemory().usable) ...refuse...
//
// The point counts follow solver/ColumnBuilder's lattices exactly; the liquid capacity is the one
// DoublePointSolver reserves up front (liquidCapacity), so the memory figure is that of the
// solver's own arrays (points, shape-function caches, scratch, nodes, cells) plus one copy of the
// point state for checkpoints and coupling rollbacks. HDF5's buffers and the OpenFOAM tube are
// small beside it and left out.
//
// The wall-time estimate divides point updates (points x steps) by a measured throughput per
// dimension (kThroughput below, docs/performance.md says how it was measured); OpenFOAM-coupled
// runs take about twice as long (the tube's share of the main job is about half).
#include <cstddef>
#include <cstdint>
#include <string>

#include "case/CaseConfig.hpp"

namespace qs {

/// Material-point updates per second of whole runs on the project's machine (1 thread, Release;
/// docs/performance.md, "Throughput used by quicksand check").
constexpr double kThroughput[3] = {1.0e7, 4.0e6, 1.5e6};

struct RunSize {
    std::int64_t cells = 0, nodes = 0;
    std::int64_t solidPoints = 0;
    std::int64_t liquidPoints = 0;     ///< at the start
    std::int64_t liquidCapacity = 0;   ///< reserved for the densest filling (injection included)
    std::int64_t steps = 0;            ///< gravity stage and dynamic stage
    double dt = 0;                     ///< s
    double peakBytes = 0;              ///< estimated peak memory
    double wallSeconds = 0;            ///< estimated wall time on one thread
};

/// Bytes of one point's persistent state, solid and liquid: what the point sets' registries
/// list (points/PointSet.hpp), as a checkpoint holds it and a point that changes rank carries it.
struct PointStateBytes {
    double solid = 0, liquid = 0;
};
PointStateBytes pointStateBytes(const CaseConfig& config);

/// Bytes the solver keeps per solid point, liquid point (of the reserved capacity), node and
/// cell: its arrays, shape-function caches and scratch (estimateRunSize's terms; the
/// decomposition's memory per rank, parallel/Decomposition.hpp).
struct EntityBytes {
    double solid = 0, liquid = 0, node = 0, cell = 0;
};
EntityBytes entityBytes(const CaseConfig& config);

/// Liquid points the solver reserves room for: every cell of the grid at the free water's lattice
/// density (the densest the injected points reach, in the sand as in free water), a quarter more
/// for points bunching, or the initial points if more. Beyond it the point arrays grow (a
/// reallocation, not an error). Four fillings plus the initial points, reserved until 2026-12-02,
/// came to 304 MiB for the 3D consolidation benchmark, which peaks at 53 MiB.
std::int64_t liquidCapacity(const CaseConfig& config, std::int64_t cells, std::int64_t initialLiquid);

RunSize estimateRunSize(const CaseConfig& config);

/// m/s, the fastest explicit wave: the zero-drag fast wave of each material, or free water's
/// sqrt(K_L / rho_L) (physics.md, time step).
double fastestWaveSpeed(const CaseConfig& config);
/// m/s, the fastest skeleton wave of the materials, sqrt(E_oed / ((1 - n) rho_s)): what bounds
/// the semi-implicit step, whose pore pressure and drag are implicit and whose stress is not.
double skeletonWaveSpeed(const CaseConfig& config);
/// m/s, the wave that bounds the step of config.time.scheme: fastestWaveSpeed (explicit) or
/// skeletonWaveSpeed (semi-implicit).
double schemeWaveSpeed(const CaseConfig& config);
/// s, the bound of the step: time.dt if given, else courant h / c, c = schemeWaveSpeed.
double stableTimeStep(const CaseConfig& config);
/// s, the step a run takes: stableTimeStep fitted down to the output interval (and an OpenFOAM
/// line's coupling window), solver/TimeLattice.hpp.
double timeStep(const CaseConfig& config);

struct MachineMemory {
    double total = 0;      ///< bytes of RAM (or the cgroup's limit, if lower)
    double available = 0;  ///< bytes available now (MemAvailable), 0 if unknown
};
MachineMemory machineMemory();

/// Throws qs::Error naming the file and key when time.dt exceeds the stable step 0.5 h / c, c the
/// scheme's wave (schemeWaveSpeed).
/// One of the preconditions of a run that `quicksand check` and `run` share (validateRun,
/// solver/RunPreconditions.hpp).
void requireStableTimeStep(const CaseConfig& config);

/// Throws qs::Error, with the numbers, when the estimated peak memory exceeds the machine's
/// (validateRun calls it before anything is allocated).
void requireFitsMachine(const CaseConfig& config, const RunSize& size, const MachineMemory& machine);

/// "1.2 GiB", "350 MiB", ...
std::string formatBytes(double bytes);
/// "40 s", "3.5 min", "2.1 h", "12 days"
std::string formatSeconds(double seconds);

}  // namespace qs
