#include "solver/RunSize.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "core/Error.hpp"
#include "materials/ConstitutiveModels.hpp"
#include "physics/WaveSpeeds.hpp"
#include "points/LiquidPoints.hpp"
#include "points/SolidPoints.hpp"
#include "solver/ColumnBuilder.hpp"
#include "solver/TimeLattice.hpp"

namespace qs {

namespace {

/// A count computed in double, as an integer; beyond what int64 holds it saturates (such a run is
/// then refused as too large) instead of overflowing (found by fuzzing the case loader).
std::int64_t saturatedCount(double x) {
    constexpr double kLargest = 9.0e18;  // below INT64_MAX = 9.22e18
    if (!(x < kLargest)) return static_cast<std::int64_t>(kLargest);
    return x > 0 ? static_cast<std::int64_t>(x) : 0;
}

std::int64_t cellsIn(double length, double h) { return saturatedCount(std::round(length / h)); }

// Bytes per point or per grid entity, from the fields the solver keeps (double = 8, Index = 8,
// int = 4, char = 1); D is the grid dimension.
/// The shape-function cache: the cell, and for uGIMP the stencil's start and w and dw (3 per axis);
/// linear weights are taken from the positions where they are used (solver/PointStencil.hpp).
double shapeBytes(int D, bool gimp) { return 8 + (gimp ? 8 + 8.0 * 6 * D : 0.0); }
/// The persistent state of a point, from the point sets' registries (points/PointSet.hpp);
/// `internal` is the constitutive state variables a solid point carries.
template <int D>
PointStateBytes registryBytes(int internal) {
    SolidPoints<D> solid;
    solid.internalCount = internal;
    return {bytesPerPoint(solid), bytesPerPoint(LiquidPoints<D>{})};
}
PointStateBytes pointStateBytesOf(int D, int internal) {
    switch (D) {
        case 1: return registryBytes<1>(internal);
        case 2: return registryBytes<2>(internal);
        default: return registryBytes<3>(internal);
    }
}
double solidBytes(int D, bool gimp, const PointStateBytes& state) {
    return state.solid + 4 + shapeBytes(D, gimp);  // the stress return's code: per-step scratch
}
double liquidBytes(int D, bool gimp, const PointStateBytes& state) {
    const double shape = shapeBytes(D, gimp);
    const double perStep = 8 + 8 + 1;                    // weight V*, strain increment, drop flag
    const double scratch = 8.0 * 6 + 4.0 * 6 + 8;        // reorder scratch (reals, ints, order)
    return state.liquid + shape + perStep + scratch;
}
// the field sets of solver/GridFields.hpp: per node 7 scalars, 3 transfer sums, 8 vectors, the
// diffusion flag and the boundary masks (2 per axis); per cell 3 indices, 6 flags, 8 scalars and
// the pressure gradient
double nodeBytes(int D) { return 8.0 * (7 + 3) + 8.0 * 8 * D + 1 + 2.0 * D; }
double cellBytes(int D) { return 8.0 * 3 + 6 + 8.0 * (8 + D); }

}  // namespace

PointStateBytes pointStateBytes(const CaseConfig& config) {
    int internal = 0;  // the most state variables any material's model carries (DoublePointSolver)
    for (const auto& m : config.materials) internal = std::max(internal, makeConstitutiveModel(m)->stateCount());
    return pointStateBytesOf(config.grid.dimension, internal);
}

EntityBytes entityBytes(const CaseConfig& config) {
    const int D = config.grid.dimension;
    const bool gimp = config.grid.shapeFunctions == ShapeFunctionKind::Gimp;
    const PointStateBytes state = pointStateBytes(config);
    return {solidBytes(D, gimp, state), liquidBytes(D, gimp, state), nodeBytes(D), cellBytes(D)};
}

std::int64_t liquidCapacity(const CaseConfig& config, std::int64_t cells, std::int64_t initialLiquid) {
    const int D = config.grid.dimension;
    const double perLayer = std::pow(double(config.points.liquidPerCell), D - 1);
    return saturatedCount(std::max(1.25 * double(cells) * freeWaterPointsPerCell(config) * perLayer, double(initialLiquid)));
}

double fastestWaveSpeed(const CaseConfig& config) {
    const double KL = config.liquid.bulkModulus, rhoL = config.liquid.density;
    double c = freeWaterWave(KL, rhoL);
    // the skeleton's stiffness from its constitutive model: a new model sizes the step itself
    for (const auto& m : config.materials) {
        const double Eoed = makeConstitutiveModel(m)->oedometricModulus();
        c = std::max(c, mixtureWaves(Eoed, KL, m.porosity, m.grainDensity, rhoL).fast);
    }
    return c;
}

double skeletonWaveSpeed(const CaseConfig& config) {
    double c = 0;
    for (const auto& m : config.materials) {
        const double Eoed = makeConstitutiveModel(m)->oedometricModulus();
        c = std::max(c, mixtureWaves(Eoed, config.liquid.bulkModulus, m.porosity, m.grainDensity,
                                     config.liquid.density).skeleton);
    }
    return c;
}

double schemeWaveSpeed(const CaseConfig& config) {
    return config.time.scheme == TimeScheme::SemiImplicit ? skeletonWaveSpeed(config) : fastestWaveSpeed(config);
}

double stableTimeStep(const CaseConfig& config) {
    if (config.time.dt) return *config.time.dt;
    return config.time.courant * config.grid.cellSize / schemeWaveSpeed(config);
}

double timeStep(const CaseConfig& config) { return timeLattice(config).dt; }

RunSize estimateRunSize(const CaseConfig& config) {
    const int D = config.grid.dimension;
    const double h = config.grid.cellSize;
    const int spc = config.points.solidPerCell, lpc = config.points.liquidPerCell;
    RunSize r;

    double horizontalCells = 1, horizontalNodes = 1;
    for (int d = 0; d < D - 1; ++d) {
        horizontalCells *= double(cellsIn(config.grid.width, h));
        horizontalNodes *= double(cellsIn(config.grid.width, h)) + 1;
    }
    const double rows = double(cellsIn(config.column.top, h));
    r.cells = saturatedCount(horizontalCells * rows);
    r.nodes = saturatedCount(horizontalNodes * (rows + 1));

    // the lattices of ColumnBuilder: per sand cell spc (solid) and lpc (liquid) per axis; free
    // water freeWaterPointsPerCell along the vertical, lpc per horizontal axis
    const double solidPerLayer = std::pow(double(spc), D - 1) * horizontalCells;
    const double liquidPerLayer = std::pow(double(lpc), D - 1) * horizontalCells;
    for (const auto& layer : config.layers) {
        const double c = double(cellsIn(layer.thickness, h));
        r.solidPoints = saturatedCount(double(r.solidPoints) + c * spc * solidPerLayer);
        r.liquidPoints = saturatedCount(double(r.liquidPoints) + c * lpc * liquidPerLayer);
    }
    const int nzFree = freeWaterPointsPerCell(config);
    auto freeWater = [&](double thickness) {
        const double nz = std::round(thickness / h * nzFree);
        if (nz > 0) r.liquidPoints = saturatedCount(double(r.liquidPoints) + nz * liquidPerLayer);
    };
    freeWater(config.filterLevel());
    if (config.column.waterLevel > config.sandTop() + 1e-12) freeWater(config.column.waterLevel - config.sandTop());
    r.liquidCapacity = liquidCapacity(config, r.cells, r.liquidPoints);

    r.dt = timeStep(config);
    r.steps = saturatedCount(std::ceil((config.time.end + std::max(0.0, config.initial.gravityStageDuration)) / r.dt));

    // The solver's arrays, and one more copy of the point state (a checkpoint being written, or
    // the rollback copy of an implicit coupling window).
    const PointStateBytes state = pointStateBytes(config);
    const double stateCopy = r.solidPoints * state.solid + r.liquidCapacity * state.liquid;
    const bool gimp = config.grid.shapeFunctions == ShapeFunctionKind::Gimp;
    r.peakBytes = r.solidPoints * solidBytes(D, gimp, state) + r.liquidCapacity * liquidBytes(D, gimp, state) +
                  r.nodes * nodeBytes(D) + r.cells * cellBytes(D) + stateCopy;

    const double updates = double(r.steps) * (double(r.solidPoints) + double(r.liquidPoints));  // both may saturate
    r.wallSeconds = updates / kThroughput[std::clamp(D, 1, 3) - 1];
    if (config.reservoir.kind == ReservoirKind::OpenFoam) r.wallSeconds *= 2;
    return r;
}

MachineMemory machineMemory() {
    MachineMemory m;
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0) m.total = double(pages) * double(pageSize);
    // a container's limit (cgroup v2, then v1) when it is below the machine's RAM
    for (const char* path : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
        std::ifstream in(path);
        double limit = 0;
        if (in >> limit && limit > 0 && (m.total == 0 || limit < m.total)) m.total = limit;
    }
    std::ifstream info("/proc/meminfo");
    std::string key;
    double value = 0;
    std::string unit;
    while (info >> key >> value >> unit) {
        if (key == "MemAvailable:") { m.available = value * 1024.0; break; }
    }
    return m;
}

void requireStableTimeStep(const CaseConfig& config) {
    if (!config.time.dt) return;
    const double c = schemeWaveSpeed(config), stable = 0.5 * config.grid.cellSize / c;
    if (*config.time.dt <= stable) return;
    const bool semi = config.time.scheme == TimeScheme::SemiImplicit;
    const char* wave = semi ? "c_skeleton" : "c_fast";
    std::ostringstream s;
    s << config.caseDirectory << "/case.toml: key 'time.dt': " << *config.time.dt
      << " s exceeds the stable step of the " << (semi ? "semi-implicit" : "explicit") << " scheme, 0.5 h / "
      << wave << " = " << stable << " s (" << wave << " = " << c
      << " m/s, h = " << config.grid.cellSize << " m): set time.dt <= " << stable
      << " s, or remove it so that the step follows time.courant";
    throw Error(s.str());
}

void requireFitsMachine(const CaseConfig& config, const RunSize& r, const MachineMemory& machine) {
    if (machine.total <= 0 || r.peakBytes <= machine.total) return;
    std::ostringstream s;
    s << config.caseDirectory << "/case.toml: the run does not fit this machine's memory: it needs about "
      << formatBytes(r.peakBytes) << " (" << r.cells << " cells, " << r.solidPoints << " solid and "
      << r.liquidPoints << " liquid points, room for " << r.liquidCapacity
      << " liquid points as the chamber refills), the machine has " << formatBytes(machine.total)
      << "; use a coarser key 'grid.cell_size' (now " << config.grid.cellSize
      << " m; memory scales with 1/cell_size^" << config.grid.dimension
      << ") or fewer points per cell ('points.solid_per_cell', 'points.liquid_per_cell')";
    throw Error(s.str());
}

std::string formatBytes(double bytes) {
    char buf[64];
    if (bytes >= 1024.0 * 1024 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f TiB", bytes / std::pow(1024.0, 4));
    else if (bytes >= 1024.0 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / std::pow(1024.0, 3));
    else if (bytes >= 1024.0 * 1024) std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1024.0 * 1024));
    else std::snprintf(buf, sizeof buf, "%.0f KiB", bytes / 1024.0);
    return buf;
}

std::string formatSeconds(double s) {
    char buf[64];
    if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    else if (s < 3 * 86400) std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    else std::snprintf(buf, sizeof buf, "%.3g days", s / 86400);
    return buf;
}

}  // namespace qs
