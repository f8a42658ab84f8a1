#pragma once
// LumpedReservoir: the upstream reservoir and its U-tube as one ODE (physics.md section 3).
//
//   A_r(h) dh/dt = -Q                                (level balance, h above the gate plane;
//                                                     A_r by level: reservoir/ReservoirShape.hpp)
//   p_gate = rho g h - phi(Re) rho g R_t Q - K rho/2 (Q/A_t)^2
//            (static head, wall friction, minor losses: a valve, bends, the exit's kinetic energy)
//
// R_t is Hagen-Poiseuille's resistance; phi(Re) = f Re / 64 carries it into turbulent flow with
// a smooth pipe's friction factor f (Churchill's all-regime law, physics/PipeFriction.hpp: 1 in
// laminar flow, Colebrook's f in turbulent), so the loss is f (L/d) rho U^2 / 2 in every regime.
// tube_friction = "laminar" keeps phi = 1 (Hagen-Poiseuille alone, as before 2026-12-04).
// The gate law hands the solver the slope -dp/dQ so it can treat the tube loss implicitly in the
// gate node update; lagged, the loss is unstable for realistic tubes. The turbulent friction and
// the minor loss are quadratic, so they enter as secant slopes about the last flux:
// phi(Re_last) rho g R_t and K rho |Q_last| / (2 A_t^2).
// With laminar friction tubeReynolds() reports the regime, and advance() warns once on
// std::cerr when its mean over the last half second (meanTubeReynolds) exceeds 2000. The mean,
// not the step's flux: when the valve opens, the compressible chamber takes in water for a few
// steps at several times the flow the tube's water column could carry (the lumped tube has no
// inertia), and that spike says nothing about the tube's flow regime.
#include "reservoir/ReservoirModel.hpp"
#include "reservoir/ReservoirShape.hpp"

namespace qs {

struct LumpedReservoirParameters {
    double liquidDensity = 998.2;  ///< kg/m3
    double gravity = 9.81;         ///< m/s2
    double viscosity = 8.91e-4;    ///< Pa s
    double area = 0.0;             ///< m2, reservoir plan area A_r (> 0), unless areaTable is given
    /// (level m, plan area m2): a reservoir whose area changes with its level (ReservoirShape)
    PiecewiseLinear::Points areaTable;
    double initialHead = 0.0;      ///< m, reservoir level above the gate plane at t = 0
    double tubeDiameter = 0.0;     ///< m (0: no tube, no losses)
    double tubeLength = 0.0;       ///< m
    double minorLoss = 0.0;        ///< -, sum of minor-loss coefficients K (needs a tube)
    /// the tube's wall friction: a smooth pipe in every regime (Churchill), else Hagen-Poiseuille
    bool smoothPipeFriction = false;
};

class LumpedReservoir final : public ReservoirModel {
public:
    /// Above this tube Reynolds number the laminar (Hagen-Poiseuille) loss is no longer valid.
    static constexpr double kLaminarReynoldsLimit = 2000.0;
    /// s, the time over which the Reynolds number of the warning is averaged.
    static constexpr double kReynoldsAveraging = 0.5;

    explicit LumpedReservoir(const LumpedReservoirParameters& parameters);

    std::string name() const override { return "lumped"; }
    GateLaw gateLaw(double t) const override;
    /// h falls by Q dt over the plan area (the flux of the step, measured after the gate update); remembers Q for
    /// the minor-loss slope and the Reynolds check.
    void advance(double t, double dt, double gateFlux) override;
    double head() const override { return head_; }
    /// {h, Q_last, mean |Q|}
    std::vector<double> saveState() const override;
    void restoreState(const std::vector<double>& state) override;

    /// s/m2, Hagen-Poiseuille tube resistance R_t (head per flow rate); 0 without a tube.
    double tubeResistance() const { return tubeResistance_; }
    /// Re = 4 rho |Q_last| / (pi mu d) of the flow in the tube; 0 without a tube.
    double tubeReynolds() const;
    /// Re of the mean |Q| over about kReynoldsAveraging (an exponential mean); what warns.
    double meanTubeReynolds() const;
    /// True once advance() has warned that the tube flow left the laminar range.
    bool reynoldsWarningIssued() const { return reynoldsWarned_; }

private:
    LumpedReservoirParameters p_;
    ReservoirShape shape_;
    double tubeArea_ = 0.0;        ///< m2, A_t
    double tubeResistance_ = 0.0;  ///< s/m2
    double head_ = 0.0;            ///< m
    double lastFlux_ = 0.0;        ///< m3/s, the gate flux of the last advanced step
    double meanFlux_ = 0.0;        ///< m3/s, exponential mean of |Q| over kReynoldsAveraging
    bool reynoldsWarned_ = false;  ///< not part of the saved state: warn once per run
};

}  // namespace qs
