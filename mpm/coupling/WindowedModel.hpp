#pragma once
// WindowedModel: a reservoir model advanced in coupling windows, which can repeat a window (a
// CFD model of the U-tube, or the lumped tube with inertia below). A coupling scheme drives it:
//
//   p0 = model.initialGatePressure();
//   for each window [t, t + dt]:
//       p = model.solveWindow(t, dt, Q);   // from the last accepted state, with the window's
//                                          // mean gate flux Q; may be called again (iteration)
//       ...
//       model.acceptWindow();              // the last solved window becomes the state
//
// Pressures are gauge pressures in Pa at the gate plane (z = 0); fluxes in m3/s into the column.
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace qs {

struct CaseConfig;
class Communicator;

class WindowedModel {
public:
    virtual ~WindowedModel() = default;
    virtual std::string name() const = 0;
    /// Pa, the gate pressure of the initial state (before any flow).
    virtual double initialGatePressure() const = 0;
    /// Solves [t, t+dt] from the last accepted state with mean gate flux Q; returns the gate
    /// pressure at t + dt (Pa). Throws qs::Error when the model fails.
    virtual double solveWindow(double t, double dt, double flux) = 0;
    virtual void acceptWindow() = 0;
    /// m, reservoir level above the gate plane (accepted state).
    virtual double head() const = 0;
    virtual std::vector<double> saveState() const = 0;
    virtual void restoreState(const std::vector<double>& state) = 0;
    /// Called at output times; a CFD model writes its fields here.
    virtual void writeOutput(double /*t*/) {}
    /// One line on what the model runs (for the run's first line and coupling.log).
    virtual std::string description() const { return ""; }
};

/// foamCoupling/ registers the OpenFOAM model here at start-up (mpm/ never depends on it).
/// `resume`: the run continues from a checkpoint (the model keeps its working files). `ranks`:
/// the run's MPI ranks (null on one); the model is made on every rank, collectively, and each
/// rank's solveWindow returns the same pressure.
using WindowedModelFactory =
    std::function<std::unique_ptr<WindowedModel>(const CaseConfig&, bool resume, const Communicator* ranks)>;
void registerOpenFoamModel(WindowedModelFactory factory);
/// The model of reservoir.model = "openfoam"; throws qs::Error naming the key when this build
/// has no OpenFOAM.
std::unique_ptr<WindowedModel> makeOpenFoamModel(const CaseConfig& config, bool resume = false,
                                                 const Communicator* ranks = nullptr);

/// `quicksand check` of an OpenFOAM reservoir: foamCoupling/ registers a checker that refuses a
/// case quicksand cannot run (throws qs::Error) and describes the one it can, a line each.
using OpenFoamCaseCheck = std::function<std::vector<std::string>(const CaseConfig&)>;
void registerOpenFoamCaseCheck(OpenFoamCaseCheck check);
/// The registered checker's lines; none where this build has no OpenFOAM.
std::vector<std::string> checkOpenFoamCase(const CaseConfig& config);

}  // namespace qs
