#include "reservoir/LumpedReservoir.hpp"

#include "core/Constants.hpp"
#include "core/Error.hpp"
#include "physics/PipeFriction.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace qs {

LumpedReservoir::LumpedReservoir(const LumpedReservoirParameters& parameters)
    : p_(parameters),
      shape_(parameters.areaTable.empty() ? ReservoirShape::prismatic(parameters.area)
                                          : ReservoirShape::table(parameters.areaTable)),
      head_(parameters.initialHead) {
    QS_CHECK(p_.liquidDensity > 0.0 && p_.gravity > 0.0 && p_.viscosity > 0.0,
             "lumped reservoir: liquid density, gravity and viscosity must be > 0");
    QS_CHECK(p_.tubeDiameter >= 0.0 && p_.tubeLength >= 0.0 && p_.minorLoss >= 0.0,
             "lumped reservoir: tube diameter, tube length and minor-loss coefficient must be >= 0");
    QS_CHECK(p_.minorLoss == 0.0 || p_.tubeDiameter > 0.0,
             "lumped reservoir: a minor-loss coefficient needs a tube diameter (the loss is "
             "K rho/2 (Q/A_t)^2 with A_t the tube area)");
    if (p_.tubeDiameter > 0.0) {
        tubeArea_ = kPi * p_.tubeDiameter * p_.tubeDiameter / 4.0;
        tubeResistance_ = friction::laminarHeadPerFlow(p_.tubeDiameter, p_.tubeLength, p_.liquidDensity,
                                                       p_.gravity, p_.viscosity);
    }
}

GateLaw LumpedReservoir::gateLaw(double /*t*/) const {
    const double rhoG = p_.liquidDensity * p_.gravity;
    GateLaw law;
    law.staticPressure = rhoG * head_;
    law.resistance = rhoG * tubeResistance_;
    if (p_.smoothPipeFriction) law.resistance *= friction::frictionMultiplier(tubeReynolds());
    if (p_.minorLoss > 0.0)
        law.resistance += p_.minorLoss * p_.liquidDensity * std::abs(lastFlux_) /
                          (2.0 * tubeArea_ * tubeArea_);
    return law;
}

void LumpedReservoir::advance(double t, double dt, double gateFlux) {
    // Explicit in the flux, but Q is the end-of-step gate flux of an implicit gate update, so
    // the level balance is exact for the volume that actually crossed the gate.
    head_ = shape_.levelAfter(head_, gateFlux * dt);
    // below its lowest level (the table's first row, or the gate plane) the reservoir has run
    // empty, which it does not model: stop rather than hold negative water
    QS_CHECK(head_ >= shape_.lowestLevel(),
             "lumped reservoir: at t = " << t + dt << " s the level fell to " << head_ << " m, below the reservoir's "
             "lowest level " << shape_.lowestLevel() << " m (" << (shape_.isPrismatic() ? "the gate plane" : "reservoir.area_table's first row")
             << "): the reservoir ran empty, which quicksand does not model; extend area_table down to the tailwater "
                "or raise the head");
    lastFlux_ = gateFlux;
    meanFlux_ += (std::abs(gateFlux) - meanFlux_) * std::min(1.0, dt / kReynoldsAveraging);
    if (!p_.smoothPipeFriction && !reynoldsWarned_ && meanTubeReynolds() > kLaminarReynoldsLimit) {
        reynoldsWarned_ = true;
        std::cerr << "warning: lumped reservoir: at t = " << t + dt << " s the tube Reynolds number (mean over "
                  << kReynoldsAveraging << " s) is " << meanTubeReynolds() << ", above " << kLaminarReynoldsLimit
                  << "; the laminar Hagen-Poiseuille tube loss (reservoir.tube_friction = \"laminar\") "
                     "underestimates the real loss: use tube_friction = \"smooth_pipe\" (turbulent friction), "
                     "a wider tube or an OpenFOAM reservoir\n";
    }
}

double LumpedReservoir::tubeReynolds() const {
    if (p_.tubeDiameter <= 0.0) return 0.0;
    return 4.0 * p_.liquidDensity * std::abs(lastFlux_) / (kPi * p_.viscosity * p_.tubeDiameter);
}

double LumpedReservoir::meanTubeReynolds() const {
    if (p_.tubeDiameter <= 0.0) return 0.0;
    return 4.0 * p_.liquidDensity * meanFlux_ / (kPi * p_.viscosity * p_.tubeDiameter);
}

std::vector<double> LumpedReservoir::saveState() const { return {head_, lastFlux_, meanFlux_}; }

void LumpedReservoir::restoreState(const std::vector<double>& state) {
    QS_CHECK(state.size() == 3, "lumped reservoir: saved state has " << state.size()
                                                                     << " values, expected 3");
    head_ = state[0];
    lastFlux_ = state[1];
    meanFlux_ = state[2];
}

}  // namespace qs
