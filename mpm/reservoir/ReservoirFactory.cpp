// makeReservoirModel: the one place that maps [reservoir] in a case to a ReservoirModel.
// The OpenFOAM model lives in foamCoupling/, which depends on mpm/ and not the other way round,
// so it is reached through a factory that foamCoupling registers at start-up.
#include "reservoir/ReservoirModel.hpp"

#include "core/Error.hpp"
#include "io/CaseConfig.hpp"
#include "reservoir/ConstantHead.hpp"
#include "reservoir/LumpedReservoir.hpp"

#include <utility>

namespace qs {

namespace {
// A function-local static: registration may run from another translation unit's static
// initialiser, before a namespace-scope object here would be constructed.
ReservoirFactory& openFoamFactory() {
    static ReservoirFactory factory;
    return factory;
}
}  // namespace

void registerOpenFoamReservoir(ReservoirFactory factory) { openFoamFactory() = std::move(factory); }

std::unique_ptr<ReservoirModel> makeReservoirModel(const CaseConfig& config) {
    const ReservoirConfig& r = config.reservoir;
    switch (r.kind) {
        case ReservoirKind::ConstantHead:
            return std::make_unique<ConstantHead>(config.liquid.density, config.gravity, r.head,
                                                  r.headRate);
        case ReservoirKind::Lumped: {
            LumpedReservoirParameters p;
            p.liquidDensity = config.liquid.density;
            p.gravity = config.gravity;
            p.viscosity = config.liquid.viscosity;
            p.area = r.area;
            p.initialHead = r.head;
            p.tubeDiameter = r.tubeDiameter;
            p.tubeLength = r.tubeLength;
            p.minorLoss = r.minorLoss;
            return std::make_unique<LumpedReservoir>(p);
        }
        case ReservoirKind::OpenFoam:
            if (openFoamFactory()) return openFoamFactory()(config);
            throw Error(
                "case.toml: key 'reservoir.model': \"openfoam\" needs a quicksand build with "
                "OpenFOAM; this build has none. Install it with tools/setup.sh --openfoam and "
                "rebuild, or use \"constant_head\" or \"lumped\".");
    }
    throw Error("makeReservoirModel: unknown reservoir kind");
}

}  // namespace qs
