#pragma once
// Simulation: one run of a case as an object, the seam that `quicksand run`, the ranks of an MPI
// run and a Python session (issue 43) drive alike.
//
//   Simulation sim(config, RunOptions{});   // open: the case resolved, the output directory
//                                           // rotated, the solver built, resumed or past its
//                                           // gravity stage, the first output written
//   sim.advanceTo(10.0);                    // s: steps, with the case's outputs, checkpoints
//                                           // and progress on the way
//   sim.writeCheckpoint();                  // now, whatever the interval
//   RunSummary s = sim.finish();            // the last checkpoint and the summary lines
//
// Ctrl-C or SIGTERM during advanceTo ends the step (or coupling window) in progress, writes a
// checkpoint and throws Interrupted, saying how to resume. An error inside a step throws with the
// time of the last good checkpoint named. What is written where: solver/Run.hpp.
#include <memory>
#include <string>
#include <vector>

#include "case/CaseConfig.hpp"
#include "solver/Run.hpp"

namespace qs {

/// One persistent point field of the registry (points/PointSet.hpp), copied out: `components`
/// values a point, point after point (integers as doubles).
struct PointFieldValues {
    std::string name;
    int components = 0;
    std::vector<double> values;
};

class Simulation {
public:
    /// Opens the run. Throws qs::Error, before the earlier output is touched, for a case that
    /// cannot run (validateRun) or a checkpoint that cannot be resumed from.
    Simulation(const CaseConfig& config, const RunOptions& options);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    double time() const;    ///< s
    double dt() const;      ///< s
    long steps() const;     ///< since t = 0, the gravity stage excluded
    int dimension() const;
    /// The column's measurements now (gate flux, surfaces, ledger...), as series.csv records them.
    ColumnState state() const;
    /// The cell-row profile of now (the rows' means along the vertical).
    std::vector<CellRow> profile() const;
    /// The registry's fields of the solid (or liquid) points of this rank (every point on one
    /// rank): what the Python binding hands out as arrays.
    std::vector<PointFieldValues> pointFields(bool solid) const;
    /// The grid's cells as the pipe survey reads them (physics/Pipes.hpp: the sand's state and
    /// porosity per cell, the water crossing the filter per column). 2D and 3D; a 1D column
    /// throws qs::Error (its cells are profile()'s rows).
    SandCells sandCells() const;

    /// Advances to time `end` (s; to the step nearest it), writing the outputs and checkpoints
    /// that fall due on the case's intervals.
    void advanceTo(double end);
    /// series.csv's row, the fields and the pipes of now.
    void writeOutput();
    /// The checkpoint of now (CASE/OUTPUT/checkpoint.h5), the outputs before it made durable.
    void writeCheckpoint();
    /// Writes the last checkpoint and returns (and unless quiet prints) the run's summary.
    RunSummary finish();

    struct Run;  ///< the run of one grid dimension (Simulation.cpp)

private:
    std::unique_ptr<Run> run_;
};

}  // namespace qs
