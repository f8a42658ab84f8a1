#include "solver/RunPreconditions.hpp"

#include <memory>

#include "core/Error.hpp"
#include "reservoir/ConstantHead.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/RunSize.hpp"

namespace qs {

namespace {

/// The reservoir the solver is built with here: the built-in one the run advances, or a constant
/// head in place of an OpenFOAM reservoir, which is a windowed model coupled to the solver only
/// once the run has started.
std::unique_ptr<ReservoirModel> reservoirForTheProbe(const CaseConfig& config) {
    if (config.reservoir.kind == ReservoirKind::OpenFoam)
        return std::make_unique<ConstantHead>(config.liquid.density, config.gravity, 0.0);
    return makeReservoirModel(config);
}

template <int D>
void buildSolverOnce(const CaseConfig& config, ReservoirModel& reservoir) {
    const DoublePointSolver<D> probe(config, reservoir);
}

}  // namespace

void validateRun(const CaseConfig& config) {
    requireStableTimeStep(config);
    // before anything is allocated: a case too big for the machine ends here, not in bad_alloc
    requireFitsMachine(config, estimateRunSize(config), machineMemory());
    const std::unique_ptr<ReservoirModel> reservoir = reservoirForTheProbe(config);
    switch (config.grid.dimension) {
        case 1: return buildSolverOnce<1>(config, *reservoir);
        case 2: return buildSolverOnce<2>(config, *reservoir);
        case 3: return buildSolverOnce<3>(config, *reservoir);
    }
    throw Error("grid.dimension must be 1, 2 or 3");
}

}  // namespace qs
