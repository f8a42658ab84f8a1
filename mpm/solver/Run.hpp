#pragma once
// Running a case: the time loop around DoublePointSolver with output, progress and checkpoints.
//
//   CaseConfig config = loadCase("cases/verification/geostatic");
//   RunSummary s = runCase(config, RunOptions{});   // a Simulation opened, advanced to
//                                                   // time.end and finished (solver/Simulation.hpp)
//
// A built-in reservoir (constant head, lumped) is advanced inside every MPM step; a windowed
// model (OpenFOAM) through the coupling scheme of [coupling], window by window, with the
// iterations logged to output/coupling.log.
//
// Output goes to CASE/output (case key output.directory): series.csv every output interval,
// fields.h5 + fields.xdmf, in 2D and 3D pipes.csv, checkpoint.h5 at every checkpoint interval and at the end. A previous
// output directory is kept as output.previous; a run that fails before its first step (bad
// input) never touches it. With resume = true the run continues from output/checkpoint.h5.
#include <functional>
#include <string>

#include "coupling/CouplingScheme.hpp"
#include "coupling/WindowedModel.hpp"
#include "case/CaseConfig.hpp"
#include "solver/DoublePointSolver.hpp"

namespace qs {

class Communicator;

struct RunOptions {
    bool resume = false;          ///< continue from OUTPUT/checkpoint.h5
    bool quiet = false;           ///< no progress lines
    bool writeFiles = true;       ///< false: run in memory only (tests)
    double endTime = -1;          ///< s, overrides time.end when >= 0
    /// Called at every output time with the column's state and cell-row profile (tests watch a
    /// run through it).
    std::function<void(const ColumnState&, const std::vector<CellRow>&)> onOutput;
    /// 2D and 3D: called at every output time with the cells' sand state and the pipes found in
    /// it (physics/Pipes.hpp), as pipes.csv records them.
    std::function<void(double time, const SandCells&, const PipeSurvey&)> onPipes;
    /// A windowed reservoir model to couple to instead of the case's reservoir (not owned; tests
    /// couple the InertialTubeModel this way). reservoir.model = "openfoam" makes one itself.
    WindowedModel* windowedModel = nullptr;
    /// The MPI ranks to run over (mpirun; parallel/RankShare.hpp): every rank opens the same
    /// Simulation and makes the same calls; rank 0 writes the files, and onOutput and onPipes see
    /// the whole column on every rank. Null, or one rank: the run is serial.
    const Communicator* ranks = nullptr;
};

struct RunSummary {
    ColumnState final;
    std::vector<CellRow> profile;
    long steps = 0;
    double wallSeconds = 0;
    double pointUpdatesPerSecond = 0;  ///< (solid + liquid points) x steps / wall time
    double dt = 0;
    std::string outputDirectory;
    IntegratorStats integrator;   ///< the time scheme's own work (semi-implicit: the pressure solve)
    CouplingStats coupling;       ///< windowed models only
    std::string couplingSummary;  ///< one line: windows, iterations, share of the model's time
};

RunSummary runCase(const CaseConfig& config, const RunOptions& options);

/// The column names of series.csv for a case (time first).
std::vector<std::string> seriesColumns(const CaseConfig& config);

}  // namespace qs
