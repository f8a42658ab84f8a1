#pragma once
// InertialTubeModel: a lumped reservoir + U-tube whose water has inertia, advanced in windows.
//
// The reservoir level h follows A_r dh/dt = -Q; the tube's water (length L_t, area A_t) obeys
//   rho (L_t / A_t) dQ/dt = rho g (h - z_gate) - p_gate - rho g R_t Q,
// so for a window with mean flux Q_n after Q_{n-1} the gate pressure at the window's end is
//   p_gate = rho g h - rho g R_t Q_n - rho (L_t / A_t) (Q_n - Q_{n-1}) / dt.
// The last term is the tube's added mass: the gate pressure answers flux acceleration at once,
// which is what makes explicit flux-pressure coupling unstable (physics.md section 3). It is the
// OpenFOAM tube's behaviour in lumped form, so the coupling schemes can be verified without
// OpenFOAM. Without inertia (inertialLength = 0) it is the LumpedReservoir without minor losses.
#include "coupling/WindowedModel.hpp"
#include "reservoir/LumpedReservoir.hpp"

namespace qs {

/// The lumped reservoir's parameters (minor losses not modelled here) and the length of water the
/// tube must accelerate.
struct InertialTubeParameters : LumpedReservoirParameters {
    double inertialLength = -1.0;  ///< m (< 0: the tube length; 0: no inertia)
};

class InertialTubeModel final : public WindowedModel {
public:
    explicit InertialTubeModel(const InertialTubeParameters& p);
    std::string name() const override { return "inertial lumped tube"; }
    double initialGatePressure() const override;
    double solveWindow(double t, double dt, double flux) override;
    void acceptWindow() override;
    double head() const override { return head_; }
    std::vector<double> saveState() const override { return {head_, flux_}; }
    void restoreState(const std::vector<double>& s) override;

private:
    InertialTubeParameters p_;
    double resistance_ = 0;  ///< s/m2, Hagen-Poiseuille head per flow rate
    double inertance_ = 0;   ///< 1/m, L_t / A_t
    double head_ = 0, flux_ = 0;                  // accepted state
    double trialHead_ = 0, trialFlux_ = 0;        // last solved window
};

}  // namespace qs
