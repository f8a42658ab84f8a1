// makeReservoirModel: the one place that maps a built-in [reservoir] to a ReservoirModel. The
// OpenFOAM model is a WindowedModel driven by a coupling scheme (coupling/WindowedModel.hpp:
// makeOpenFoamModel, registered by foamCoupling/), not a per-step ReservoirModel.
#include "reservoir/ReservoirModel.hpp"

#include "core/Error.hpp"
#include "case/CaseConfig.hpp"
#include "reservoir/ConstantHead.hpp"
#include "reservoir/LumpedReservoir.hpp"

namespace qs {

std::unique_ptr<ReservoirModel> makeReservoirModel(const CaseConfig& config) {
    const ReservoirConfig& r = config.reservoir;
    switch (r.kind) {
        case ReservoirKind::ConstantHead:
            if (!r.headSchedule.empty())
                return std::make_unique<ConstantHead>(config.liquid.density, config.gravity, r.headSchedule);
            return std::make_unique<ConstantHead>(config.liquid.density, config.gravity, r.head,
                                                  r.headRate);
        case ReservoirKind::Lumped: {
            LumpedReservoirParameters p;
            p.liquidDensity = config.liquid.density;
            p.gravity = config.gravity;
            p.viscosity = config.liquid.viscosity;
            p.area = r.area;
            p.areaTable = r.areaTable;
            p.initialHead = r.head;
            p.tubeDiameter = r.tubeDiameter;
            p.tubeLength = r.tubeLength;
            p.minorLoss = r.minorLoss;
            p.smoothPipeFriction = r.tubeFriction == TubeFriction::SmoothPipe;
            return std::make_unique<LumpedReservoir>(p);
        }
        case ReservoirKind::OpenFoam:
            throw Error(
                "reservoir.model = \"openfoam\" is coupled window by window: make it with "
                "makeOpenFoamModel and drive it with a coupling scheme (runCase does both)");
    }
    throw Error("makeReservoirModel: unknown reservoir kind");
}

}  // namespace qs
