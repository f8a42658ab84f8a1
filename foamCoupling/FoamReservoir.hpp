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
//     OpenFOAM's own errors name the user's case, not the working copy;
//   - over MPI ranks, a case with system/decomposeParDict is decomposed as pimpleFoam's users
//     decompose it: rank 0 runs decomposePar on the working copy, each rank solves its
//     processorN/ through OpenFOAM's own Pstream (which joins quicksand's MPI), and the gate's
//     pressure is OpenFOAM's sum over the gate faces of every rank. Fields are written per
//     processor (reconstructPar -case OUTPUT/openfoam gives them as a serial run writes them). A
//     case without it runs on rank 0 alone, which hands its pressure to the others.
// No OpenFOAM header here: the OpenFOAM code is a plugin loaded at run time (FoamTube.hpp).
#include <memory>
#include <string>

#include "reservoir/ReservoirShape.hpp"
#include "FoamTube.hpp"
#include "coupling/WindowedModel.hpp"
#include "case/CaseConfig.hpp"
#include "parallel/Communicator.hpp"

namespace qs::foam {

class FoamReservoir final : public WindowedModel {
public:
    /// resume: keep OUTPUT/openfoam/ (a resumed run reads its fields from there). ranks: the
    /// run's MPI ranks, or null; made on every rank alike (collective).
    FoamReservoir(const CaseConfig& config, bool resume, const Communicator* ranks = nullptr);
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

    /// Whether the line runs decomposed over the ranks (false on one rank).
    bool decomposed() const { return decomposed_; }

private:
    /// Rank 0's part of the opening: the working copy, its mesh and its decomposition.
    void prepareWorkingCopy(const std::string& source, const std::string& out, bool resume);
    /// Opens the working copy with OpenFOAM, at the case's own start or (a resume) at startTime.
    void startTube(double startTime);
    /// Runs f where the line is solved; on ranks where rank 0 alone solves it, its errors are
    /// agreed (every rank throws them, said once).
    template <class F>
    void onLine(F&& f);
    /// OpenFOAM's message with the working copy's path replaced by the user's case.
    std::string userPaths(std::string text) const;

    std::string caseName_, gatePatch_, reservoirPatch_, workDir_, logFile_;
    double density_, gravity_;
    ReservoirShape shape_;  ///< the plan area by level: the level balance of the reservoir
    double head_ = 0, trialHead_ = 0;
    bool pending_ = false;      ///< a window was solved and not yet accepted
    const Communicator* ranks_ = nullptr;  ///< null on one rank
    bool decomposed_ = false;   ///< the line is solved on every rank, each its processor directory
    std::unique_ptr<Tube> tube_;  ///< where this rank solves the line (every rank, or rank 0 alone)
};

/// Makes OpenFOAM usable without a sourced environment: sets WM_PROJECT_DIR when absent.
void prepareEnvironment();
/// Loads the plugin (after prepareEnvironment); throws qs::Error naming what is missing. mpi:
/// the one on OpenFOAM's MPI Pstream, for a decomposed line (a process loads one or the other).
void loadPlugin(bool mpi = false);

}  // namespace qs::foam
