#pragma once
// FoamReservoir: the upstream reservoir and U-tube as an OpenFOAM model, a WindowedModel that a
// coupling scheme drives window by window (physics.md section 3).
//
//   - the OpenFOAM case named by reservoir.openfoam_case is copied to OUTPUT/openfoam/ (the
//     source case is never written to) and meshed with blockMesh when it has no mesh; a resumed
//     run keeps that copy and goes on from the fields written at the checkpoint;
//   - the reservoir level is a 0-D volume balance, A_r dh/dt = -Q, applied as the total pressure
//     g (h - z_gate) on the reservoir patch (kinematic, piezometric about the gate plane);
//   - the gate flux enters the tube's gate patch as the velocity Q / A_gate (out of the tube);
//   - the gate pressure returned is rho times the area-averaged kinematic p on the gate patch;
//   - OpenFOAM's own output goes to OUTPUT/openfoam.log; its fields are written at the output
//     times and checkpoints into OUTPUT/openfoam/<time>/ (every digit: a resume reopens the case
//     there), so ParaView opens the line beside the column; the case's function objects write
//     to OUTPUT/openfoam/postProcessing/ once per accepted window;
//   - a case quicksand cannot run is refused before OpenFOAM is loaded (FeedLineCase.hpp), and
//     OpenFOAM's own errors name the user's case, not the working copy.
// No OpenFOAM header here: the OpenFOAM code is a plugin loaded at run time (FoamTube.hpp).
#include <memory>
#include <string>

#include "reservoir/ReservoirShape.hpp"
#include "FoamTube.hpp"
#include "coupling/WindowedModel.hpp"
#include "io/CaseConfig.hpp"

namespace qs::foam {

class FoamReservoir final : public WindowedModel {
public:
    /// resume: keep OUTPUT/openfoam/ (a resumed run reads its fields from there).
    FoamReservoir(const CaseConfig& config, bool resume);
    ~FoamReservoir() override;

    std::string name() const override;
    double initialGatePressure() const override;
    double solveWindow(double t, double dt, double flux) override;
    void acceptWindow() override;
    double head() const override { return head_; }
    /// The level and the CFD time; the fields themselves are written at checkpoints
    /// (writeOutput) and restoreState reopens the case at OUTPUT/openfoam/<time>/.
    std::vector<double> saveState() const override;
    void restoreState(const std::vector<double>& state) override;
    void writeOutput(double t) override;

    const std::string& workDirectory() const { return workDir_; }
    /// One line: the algorithm and models OpenFOAM selected from the case.
    std::string description() const override;

private:
    /// Opens the working copy with OpenFOAM, at the case's own start or (a resume) at startTime.
    void startTube(double startTime);
    /// OpenFOAM's message with the working copy's path replaced by the user's case.
    std::string userPaths(std::string text) const;

    std::string caseName_, gatePatch_, reservoirPatch_, workDir_, logFile_;
    double density_, gravity_;
    ReservoirShape shape_;  ///< the plan area by level: the level balance of the reservoir
    double head_ = 0, trialHead_ = 0;
    bool pending_ = false;      ///< a window was solved and not yet accepted
    std::unique_ptr<Tube> tube_;
};

/// Makes OpenFOAM usable without a sourced environment: sets WM_PROJECT_DIR when absent.
void prepareEnvironment();
/// Loads the plugin (after prepareEnvironment); throws qs::Error naming what is missing.
void loadPlugin();

}  // namespace qs::foam
