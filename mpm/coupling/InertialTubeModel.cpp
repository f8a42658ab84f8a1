#include "coupling/InertialTubeModel.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "core/Constants.hpp"
#include "physics/PipeFriction.hpp"

namespace qs {

InertialTubeModel::InertialTubeModel(const InertialTubeParameters& p) : p_(p) {
    QS_CHECK(p.area > 0 && p.tubeDiameter > 0 && p.tubeLength > 0,
             "inertial tube: reservoir area, tube diameter and length must be > 0");
    QS_CHECK(p.minorLoss == 0, "inertial tube: minor losses are not modelled; set them to 0");
    resistance_ = friction::laminarHeadPerFlow(p.tubeDiameter, p.tubeLength, p.liquidDensity, p.gravity, p.viscosity);
    const double length = p.inertialLength < 0 ? p.tubeLength : p.inertialLength;
    inertance_ = length / (kPi * p.tubeDiameter * p.tubeDiameter / 4);
    head_ = trialHead_ = p.initialHead;
}

double InertialTubeModel::initialGatePressure() const {
    return p_.liquidDensity * p_.gravity * p_.initialHead;
}

double InertialTubeModel::solveWindow(double /*t*/, double dt, double flux) {
    const double rho = p_.liquidDensity, g = p_.gravity;
    trialHead_ = head_ - flux * dt / p_.area;
    trialFlux_ = flux;
    // the level at the window's middle drives the window
    const double h = 0.5 * (head_ + trialHead_);
    return rho * g * h - rho * g * resistance_ * flux - rho * inertance_ * (flux - flux_) / dt;
}

void InertialTubeModel::acceptWindow() {
    head_ = trialHead_;
    flux_ = trialFlux_;
}

void InertialTubeModel::restoreState(const std::vector<double>& s) {
    QS_CHECK(s.size() == 2, "inertial tube: a checkpoint of another model");
    head_ = trialHead_ = s[0];
    flux_ = trialFlux_ = s[1];
}

}  // namespace qs
