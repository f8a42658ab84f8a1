#include "solver/Simulation.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "io/Checkpoint.hpp"
#include "io/FieldWriter.hpp"
#include "io/OutputRotation.hpp"
#include "io/PipesTable.hpp"
#include "io/SeriesWriter.hpp"
#include "parallel/AgreeOnErrors.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedPressureSolver.hpp"
#include "parallel/GatherPoints.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/Advancer.hpp"
#include "solver/Interruption.hpp"
#include "solver/RunPreconditions.hpp"
#include "solver/RunSize.hpp"
#include "solver/TimeLattice.hpp"

namespace qs {

namespace fs = std::filesystem;

namespace {

std::vector<double> seriesRow(const ColumnState& s) {
    std::vector<double> r = {s.time,        s.gateFlux,  s.gatePressure,   s.reservoirHead,
                             s.sandSurface, s.bedHeight, s.fluidisedFront, s.fluidisedShare,
                             s.waterSurface, s.gradient};
    for (Real q : s.monitorFlux) r.push_back(q);
    for (double v : {s.cumulativeInflow, s.cumulativeOutflow, s.injectedVolume, s.ledgerResidual, s.solidMass,
                     s.liquidMass, double(s.solidPoints), double(s.liquidPoints), s.cumulativeSolidOutflow})
        r.push_back(v);
    return r;
}

/// The cells as a point set at their centres (2D, 3D): the sand's porosity and state per cell
/// (0 no sand, 1 solid, 2 fluidised), the frames' and the pipes' view of the bed.
template <int D>
void writeCells(FieldWriter& writer, const Grid<D>& grid, const SandCells& cells) {
    const Index count = grid.numCells();
    std::vector<double> centres(count * D), state(count), porosity(cells.porosity.begin(), cells.porosity.end());
    for (Index c = 0; c < count; ++c) {
        const IVec<D> k = grid.cellCoords(c);
        for (int d = 0; d < D; ++d) centres[c * D + d] = grid.cellCentre(k[d]);
        state[c] = static_cast<double>(cells.state[c]);
    }
    writer.writePointSet("cells", count, centres.data(), {{"porosity", porosity.data(), 1}, {"state", state.data(), 1}});
}

/// The registry's written fields of a point set (points/PointSet.hpp), under their names;
/// integer codes as doubles, through `scratch`.
template <class Set>
std::vector<PointField> writtenFields(const Set& set, std::vector<std::vector<double>>& scratch) {
    std::vector<PointField> list;
    set.forEachField([&](auto& field, const FieldSpec& f) {
        if (!f.written || f.components == 0) return;
        const FieldKind kind = f.vector ? FieldKind::Vector : FieldKind::Automatic;
        if constexpr (std::is_same_v<typename std::decay_t<decltype(field)>::value_type, double>) {
            list.push_back({f.name, field.data(), f.components, kind});
        } else {
            scratch.emplace_back(field.begin(), field.end());
            list.push_back({f.name, scratch.back().data(), f.components, kind});
        }
    });
    return list;
}

/// The points as one rank holds them, or over MPI ranks gathered on rank 0 (in rank order).
template <int D>
struct WrittenPoints {
    SolidPoints<D> solid;
    LiquidPoints<D> liquid;
    std::vector<int> stressReturn;
};

template <int D>
void writeFields(FieldWriter* writer, const DoublePointSolver<D>& solver, const SandCells* cells,
                 const Communicator* ranks) {
    std::optional<WrittenPoints<D>> gathered;
    if (ranks)  // collective: every rank sends, rank 0 (the one with a writer) writes
        gathered = WrittenPoints<D>{gatherPoints(solver.solid(), *ranks), gatherPoints(solver.liquid(), *ranks),
                                    gatherValues(solver.solid().stressReturn, *ranks)};
    if (!writer) return;
    const auto& s = gathered ? gathered->solid : solver.solid();
    const auto& l = gathered ? gathered->liquid : solver.liquid();
    const auto& stressReturn = gathered ? gathered->stressReturn : solver.solid().stressReturn;
    std::vector<std::vector<double>> scratch;
    scratch.reserve(8);  // the written integer fields: the pointers into it must stay put
    writer->beginStep(solver.time());
    std::vector<PointField> solidFields = writtenFields(s, scratch);
    // the one scratch field written: how the last step's stress update returned (a diagnostic)
    scratch.emplace_back(stressReturn.begin(), stressReturn.end());
    solidFields.push_back({"stress_return", scratch.back().data(), 1});
    writer->writePointSet("solid", s.size(), s.x.data(), solidFields);
    writer->writePointSet("liquid", l.size(), l.x.data(), writtenFields(l, scratch));
    if (cells) writeCells(*writer, solver.grid(), *cells);
    writer->endStep();
}

}  // namespace

/// What Simulation does, for any dimension; RunOf<D> does it for one.
struct Simulation::Run {
    virtual ~Run() = default;
    virtual double time() const = 0;
    virtual double dt() const = 0;
    virtual long steps() const = 0;
    virtual int dimension() const = 0;
    virtual ColumnState state() const = 0;
    virtual std::vector<CellRow> profile() const = 0;
    virtual std::vector<PointFieldValues> pointFields(bool solid) const = 0;
    virtual SandCells sandCells() const = 0;
    virtual void advanceTo(double end) = 0;
    virtual void writeOutput() = 0;
    virtual void writeCheckpoint() = 0;
    virtual RunSummary finish() = 0;
};

namespace {

using Clock = std::chrono::steady_clock;

template <int D>
class RunOf final : public Simulation::Run {
public:
    RunOf(const CaseConfig& config, const RunOptions& options)
        : config_(config), options_(options),
          plannedEnd_(options.endTime >= 0 ? options.endTime : config.time.end),
          outDir_(fs::path(config.caseDirectory) / config.output.directory),
          checkpointPath_(outDir_ / "checkpoint.h5"),
          windowed_(options.windowedModel || config.reservoir.kind == ReservoirKind::OpenFoam),
          ranks_(options.ranks && options.ranks->parallel() ? options.ranks : nullptr),
          // a column beside a line on ranks is cut as any other (implicit coupling repeats a
          // window from each rank's own points: DoublePointSolver::saveWindowStart) where it can
          // be; a 1D column, or one with too few columns for the ranks, is stepped whole on
          // every rank beside the decomposed line (it costs little beside the line)
          columnRanks_(ranks_ && (!windowed_ || cutBesideALine(config, ranks_->size())) ? ranks_ : nullptr),
          root_(!ranks_ || ranks_->rank() == 0) {
        open();
    }

    double time() const override { return solver_->time(); }
    double dt() const override { return solver_->dt(); }
    long steps() const override { return solver_->stepCount(); }
    int dimension() const override { return D; }
    ColumnState state() const override { return solver_->columnState(); }
    std::vector<CellRow> profile() const override { return solver_->profile(); }
    SandCells sandCells() const override {
        if constexpr (D == 1) {
            throw Error("a 1D column's cells are its rows: read them from profile()");
        } else {
            return solver_->sandCells();
        }
    }
    std::vector<PointFieldValues> pointFields(bool solid) const override {
        std::vector<PointFieldValues> out;
        const auto copy = [&](const auto& values, const FieldSpec& spec) {
            if (spec.components > 0) out.push_back({spec.name, spec.components, {values.begin(), values.end()}});
        };
        if (solid) solver_->solid().forEachField(copy);
        else solver_->liquid().forEachField(copy);
        return out;
    }

    void advanceTo(double end) override;
    void writeOutput() override;
    void writeCheckpoint() override;
    RunSummary finish() override;

private:
    void open();
    void printHeader();
    void reportProgress(Clock::time_point now);
    /// A signal received and whether progress is due, agreed over the ranks (collective, once
    /// a step): every rank checkpoints, stops and reports at the same step.
    std::pair<int, bool> poll(Clock::time_point now) const;

    const CaseConfig config_;      ///< a copy: the run may outlive its caller's (a Python session)
    const RunOptions options_;
    const double plannedEnd_;       ///< s, time.end or the caller's: the progress lines' 100 %
    const fs::path outDir_, checkpointPath_;
    const bool windowed_;
    /// over MPI ranks, all of them (null on one); rank 0 is the root, which writes the files
    const Communicator* ranks_ = nullptr;
    /// the ranks the column is cut over: ranks_, or null where every rank steps it whole
    const Communicator* columnRanks_ = nullptr;
    bool root_ = true;

    // in the order they are made (and unmade in reverse): the solver holds the reservoir, the
    // gate its model
    std::unique_ptr<ReservoirModel> builtIn_;
    std::optional<OutputRotation> rotation_;
    std::unique_ptr<WindowedModel> ownedModel_;
    WindowedModel* model_ = nullptr;
    std::unique_ptr<CouplingInterface> gate_;
    ReservoirModel* reservoir_ = nullptr;
    std::unique_ptr<DoublePointSolver<D>> solver_;
    std::ofstream couplingLog_;
    std::unique_ptr<Advancer> advancer_;
    WindowAdvancer<D>* windowAdvancer_ = nullptr;
    std::unique_ptr<SeriesWriter> series_, pipes_;
    std::unique_ptr<FieldWriter> fields_;

    double nextOutput_ = 0, nextCheckpoint_ = 1e300, lastCheckpoint_ = -1;
    Clock::time_point wall0_, lastProgress_;
    long steps0_ = 0;
    IntegratorStats integrator0_;  ///< the integrator's counts at the timed start (the gravity stage's)
    double pointSteps_ = 0;
};

template <int D>
void RunOf<D>::open() {
    const CaseConfig& config = config_;
    agreeOnErrors(ranks_, [&] {
        // Validate everything that can be validated before touching an earlier output directory:
        // what `quicksand check` validates too (solver/RunPreconditions.hpp).
        validateRun(config);
        if (!windowed_) builtIn_ = makeReservoirModel(config);
        if (options_.resume)
            QS_CHECK(fs::exists(checkpointPath_),
                     "cannot resume: no checkpoint at " << checkpointPath_.string() << " (run without --resume first)");
        // rank 0 alone writes the files: it rotates the earlier output
        if (root_ && options_.writeFiles && !options_.resume) rotation_.emplace(outDir_, config.caseDirectory + "/case.toml");
    });
    // A windowed model (OpenFOAM) works in the output directory. Its own opening is collective
    // (a decomposed line), in stages agreed over the ranks: a stage of its own here.
    agreeOnErrors(ranks_, [&] {
        model_ = options_.windowedModel;
        if (windowed_ && !model_) {
            ownedModel_ = makeOpenFoamModel(config, options_.resume, ranks_);
            model_ = ownedModel_.get();
        }
        if (windowed_) gate_ = std::make_unique<CouplingInterface>(*model_);
        reservoir_ = windowed_ ? static_cast<ReservoirModel*>(gate_.get()) : builtIn_.get();
    });
    // over MPI ranks the constructor cuts the grid (decompose: a 1D column, or more ranks than
    // the grid can be cut into, is refused alike on every rank) and exchanges the ghost points
    agreeOnErrors(ranks_, [&] {
        if (!columnRanks_) return;
        decompose(config, ranks_->size());
        QS_CHECK(config.time.scheme == TimeScheme::Explicit || distributedSolverAvailable(),
                 config.caseDirectory << "/case.toml: time.scheme = \"semi_implicit\" on MPI ranks needs the pressure "
                                         "solve over the ranks (hypre, Debian's libhypre-dev: bash tools/setup.sh --mpi), "
                                         "which this build lacks; run it on one rank, or with time.scheme = \"explicit\"");
    });
    solver_ = std::make_unique<DoublePointSolver<D>>(config, *reservoir_, columnRanks_);
    if (rotation_) rotation_->commit();  // everything loaded: the earlier output becomes .previous

    if (windowed_ && options_.writeFiles && root_)
        couplingLog_.open(outDir_ / "coupling.log", options_.resume ? std::ios::app : std::ios::trunc);
    if (windowed_) {
        // an OpenFOAM line's window is fitted into the output interval (solver/TimeLattice.hpp);
        // a model the caller gives keeps the case's
        CouplingConfig coupling = config.coupling;
        if (config.reservoir.kind == ReservoirKind::OpenFoam) coupling.window = timeLattice(config).window;
        auto w = std::make_unique<WindowAdvancer<D>>(*solver_, *model_, *gate_, coupling,
                                                     couplingLog_.is_open() ? &couplingLog_ : nullptr);
        // the chamber water's acoustic impedance rho c / A damps its ringing between windows
        const double c = std::sqrt(config.liquid.bulkModulus / config.liquid.density);
        w->setGateImpedance(config.liquid.density * c / config.grid.crossSectionArea);
        windowAdvancer_ = w.get();
        advancer_ = std::move(w);
    } else {
        advancer_ = std::make_unique<StepAdvancer<D>>(*solver_);
    }

    if (options_.resume) {
        // every rank reads the whole checkpoint (it resumes on any number of ranks) and keeps its
        // block's points; a checkpoint that cannot be read fails alike on every rank. The model's
        // state (an OpenFOAM line reopened at the checkpoint's time, in agreed stages of its own)
        // is a stage of its own after that: every rank enters it, or none
        CheckpointData data;
        const auto refused = [&](const Error& e) {
            std::string what = e.what();
            if (what.rfind(checkpointPath_.string(), 0) != 0) what = checkpointPath_.string() + ": " + what;
            return what + ". This checkpoint cannot be resumed from; run without --resume to start again (the "
                          "results now in " + outDir_.string() + " are then kept as " + outDir_.string() + ".previous)";
        };
        agreeOnErrors(ranks_, [&] {
            try {
                data = readCheckpoint(checkpointPath_.string());
                solver_->loadState(data);
            } catch (const Error& e) {
                throw Error(refused(e));
            }
        });
        agreeOnErrors(ranks_, [&] {
            try {
                advancer_->load(data);
            } catch (const SharedError& e) {
                throw SharedError(refused(e));
            } catch (const Error& e) {
                throw Error(refused(e));
            }
        });
    } else {
        solver_->runGravityStage();
    }
    // the case as run: the file, or with the command line's overrides marked
    // (case/CaseOverride.hpp). Written once the checkpoint has loaded: a resume that is refused
    // (another scheme's checkpoint, say, with --set overrides) leaves the earlier one as it was
    if (root_ && options_.writeFiles && !config.effectiveCase.empty()) {
        std::ofstream effective(outDir_ / "case.effective.toml", std::ios::trunc);
        effective << config.effectiveCase;
        QS_CHECK(effective.good(), "cannot write " << (outDir_ / "case.effective.toml").string());
    }

    if (root_ && options_.writeFiles) {
        series_ = std::make_unique<SeriesWriter>((outDir_ / "series.csv").string(), seriesColumns(config),
                                                 options_.resume, solver_->time());
        if (D > 1)
            pipes_ = std::make_unique<SeriesWriter>((outDir_ / "pipes.csv").string(), pipesColumns(D), options_.resume,
                                                    solver_->time());
    }

    const double interval = config.time.outputInterval;
    // outputs stay on the grid k * interval, also after a resume: the first one after the
    // checkpoint's time (an interruption checkpoints between outputs, not only on one)
    const double halfStep = 0.5 * solver_->dt();
    nextOutput_ = options_.resume ? (std::floor((solver_->time() + halfStep) / interval) + 1) * interval : 0.0;
    // a resumed run keeps the field steps written before its first new output
    if (root_ && options_.writeFiles && config.output.fields)
        fields_ = std::make_unique<FieldWriter>(outDir_.string(), D, options_.resume ? nextOutput_ - halfStep : -1e300);
    // fields.h5 and fields.xdmf list new outputs once a second: a 1D column writes its outputs
    // many to the second, and each listing rewrites both files
    if (fields_) fields_->setListingInterval(1.0);
    nextCheckpoint_ = config.time.checkpointInterval > 0 ? solver_->time() + config.time.checkpointInterval : 1e300;
    lastCheckpoint_ = options_.resume ? solver_->time() : -1.0;

    if (!options_.resume) {
        writeOutput();
        nextOutput_ = interval;
    }
    wall0_ = lastProgress_ = Clock::now();
    steps0_ = solver_->stepCount();
    integrator0_ = solver_->integratorStats();
    printHeader();
}

template <int D>
void RunOf<D>::printHeader() {
    if (couplingLog_.is_open())
        couplingLog_ << "# " << model_->name() << (model_->description().empty() ? "" : ": " + model_->description())
                     << (options_.resume ? " (resumed)" : "") << "\n";
    if (options_.quiet) return;
    const DoublePointSolver<D>& s = *solver_;
    const ColumnState now = s.columnState();  // collective over ranks: the points of all of them
    if (!root_) return;
    std::printf("%s\n", buildLine().c_str());
    const bool semi = s.scheme() == TimeScheme::SemiImplicit;
    std::printf("quicksand: %dD, %s, dt = %.3g s (%s = %.1f m/s), %zu solid + %zu liquid points, t = %.4g -> %.4g s%s\n",
                D, semi ? "semi-implicit" : "explicit", s.dt(), semi ? "c_skeleton" : "c_fast", s.waveSpeed(),
                now.solidPoints, now.liquidPoints, s.time(), plannedEnd_,
                windowed_ ? (", coupled to " + model_->name()).c_str() : "");
    if (ranks_ && !columnRanks_)
        std::printf("quicksand: %d MPI ranks: the column is stepped whole on each, beside the line\n", ranks_->size());
    if (columnRanks_) {
        const Decomposition& d = s.rankShare()->decomposition();
        std::printf("quicksand: %d MPI ranks, blocks of whole columns %d x %d, %d cells of ghost points beside each "
                    "cut, point imbalance %.3f (quicksand check --ranks %d shows the blocks)\n",
                    ranks_->size(), d.parts[0], D == 3 ? d.parts[1] : 1, s.rankShare()->layers(), d.imbalance(),
                    ranks_->size());
    }
    if (!config_.liquid.bulkModulusGiven)
        std::printf("quicksand: water K_L = %.4g Pa (liquid.bulk_modulus not given: %s)\n", config_.liquid.bulkModulus,
                    config_.liquid.defaultWaterName());
    if (windowed_ && !model_->description().empty())
        std::printf("quicksand: %s: %s\n", model_->name().c_str(), model_->description().c_str());
}

template <int D>
void RunOf<D>::writeOutput() {
    // every call below that measures is collective over ranks: each rank makes the same ones,
    // decided from what all know alike (the case and the options, not which rank writes)
    const ColumnState s = solver_->columnState();
    if (series_) series_->write(seriesRow(s));
    const bool fields = options_.writeFiles && config_.output.fields;
    // 2D, 3D: the cells' sand state, once, for the fields, pipes.csv and the caller
    std::optional<SandCells> cells;
    if constexpr (D > 1)
        if (options_.writeFiles || options_.onPipes) cells = solver_->sandCells();
    if (fields) writeFields(fields_.get(), *solver_, cells ? &*cells : nullptr, columnRanks_);
    if (cells && (pipes_ || options_.onPipes)) {
        const PipeSurvey survey = findPipes(*cells);
        if (pipes_)
            for (const auto& row : pipesRows(s.time, D, survey)) pipes_->write(row);
        if (options_.onPipes) options_.onPipes(s.time, *cells, survey);
    }
    reservoir_->writeOutput(s.time);  // every rank: a decomposed line writes each rank's part
    if (options_.onOutput) options_.onOutput(s, solver_->profile());
}

template <int D>
void RunOf<D>::writeCheckpoint() {
    if (!options_.writeFiles) return;
    if (fields_) fields_->makeDurable();  // the outputs before the checkpoint that counts on them
    CheckpointData data;
    solver_->saveState(data);  // collective over ranks: rank 0 gathers every rank's points
    advancer_->save(data);
    if (root_) qs::writeCheckpoint(checkpointPath_.string(), data);
    lastCheckpoint_ = solver_->time();
}

template <int D>
void RunOf<D>::reportProgress(Clock::time_point now) {
    lastProgress_ = now;
    const double wall = std::chrono::duration<double>(now - wall0_).count();
    const double rate = (solver_->stepCount() - steps0_) / wall;
    const double eta = (plannedEnd_ - solver_->time()) / solver_->dt() / rate;
    const ColumnState s = solver_->columnState();  // collective over ranks
    if (!root_) return;
    std::printf("  t = %.4g s (%.1f %%)  %.0f steps/s  ETA %s  gate flux %.4g m3/s  i = %.3f\n", solver_->time(),
                100 * solver_->time() / plannedEnd_, rate, formatSeconds(eta).c_str(), s.gateFlux, s.gradient);
    std::fflush(stdout);
}

template <int D>
std::pair<int, bool> RunOf<D>::poll(Clock::time_point now) const {
    int sig = interruptionRequested();
    // progress by rank 0's clock
    bool due = !options_.quiet && root_ &&
               std::chrono::duration<double>(now - lastProgress_).count() >= config_.output.progressInterval;
    if (ranks_) {
        std::vector<double> flags{double(sig), due ? 1.0 : 0.0};
        ranks_->maxInPlace(flags);
        sig = static_cast<int>(flags[0]);
        due = flags[1] != 0;
    }
    return {sig, due};
}

template <int D>
void RunOf<D>::advanceTo(double end) {
    DoublePointSolver<D>& solver = *solver_;
    const double half = 0.5 * solver.dt();
    const double interval = config_.time.outputInterval;
    // Ctrl-C or SIGTERM: the step (or coupling window) in progress ends, a checkpoint is
    // written, and the run stops saying how to resume (solver/Interruption.hpp)
    InterruptionGuard interruption;
    bool progressDue = false;
    while (solver.time() < end - half) {
        const auto [sig, due] = poll(Clock::now());
        progressDue = due;
        if (sig) {
            writeCheckpoint();
            std::ostringstream m;
            m << "interrupted by " << signalName(sig) << " at t = " << solver.time() << " s (step "
              << solver.stepCount() << ")";
            if (options_.writeFiles)
                m << "; checkpoint written to " << checkpointPath_.string() << "; continue with: quicksand run "
                  << config_.caseDirectory << " --resume";
            throw Interrupted(sig, m.str());
        }
        const long before = solver.stepCount();
        try {
            advancer_->advance(end);
        } catch (const Interrupted&) {
            throw;
        } catch (const Error& e) {
            // the failed state is not written; the last good checkpoint stays as it was
            if (!options_.writeFiles || lastCheckpoint_ < 0) throw;
            std::ostringstream m;
            m << e.what() << ". The last good checkpoint, at t = " << lastCheckpoint_ << " s, is "
              << checkpointPath_.string();
            // one that every rank met alike stays said once (SharedError)
            if (dynamic_cast<const SharedError*>(&e)) throw SharedError(m.str());
            throw Error(m.str());
        }
        pointSteps_ += double(solver.stepCount() - before) * double(solver.solid().size() + solver.liquid().size());
        if (solver.time() >= nextOutput_ - half) {
            writeOutput();
            while (nextOutput_ <= solver.time() + half) nextOutput_ += interval;
        }
        if (solver.time() >= nextCheckpoint_ - half) {
            writeCheckpoint();
            nextCheckpoint_ += config_.time.checkpointInterval;
        }
        const auto now = Clock::now();
        if (fields_) fields_->listIfDue(now);
        if (progressDue) reportProgress(now);
    }
}

template <int D>
RunSummary RunOf<D>::finish() {
    writeCheckpoint();
    const DoublePointSolver<D>& solver = *solver_;
    RunSummary r;
    r.final = solver.columnState();
    r.profile = solver.profile();
    r.steps = solver.stepCount() - steps0_;
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - wall0_).count();
    const double pointSteps = columnRanks_ ? columnRanks_->sum(pointSteps_) : pointSteps_;
    r.pointUpdatesPerSecond = r.wallSeconds > 0 ? pointSteps / r.wallSeconds : 0;
    r.dt = solver.dt();
    // the timed part's: the gravity stage's solves are not in the wall time
    r.integrator = solver.integratorStats();
    r.integrator.steps -= integrator0_.steps;
    r.integrator.solves -= integrator0_.solves;
    r.integrator.cappedSteps -= integrator0_.cappedSteps;
    r.integrator.wallPasses -= integrator0_.wallPasses;
    r.integrator.iterations -= integrator0_.iterations;
    r.integrator.seconds -= integrator0_.seconds;
    r.outputDirectory = outDir_.string();
    if (windowAdvancer_) {
        r.coupling = windowAdvancer_->stats();
        r.couplingSummary = windowAdvancer_->summary();
    }
    // what crosses the cuts: each rank's bytes sent a step, the busiest rank's and the mean
    double sentMax = 0, sentMean = 0;
    if (columnRanks_) {
        const RankShare<D>& share = *solver.rankShare();
        const double perStep = share.stepsExchanged() > 0 ? 8 * share.valuesSentInAll() / share.stepsExchanged() : 0.0;
        sentMax = columnRanks_->max(perStep);
        sentMean = columnRanks_->sum(perStep) / columnRanks_->size();
    }
    if (options_.quiet || !root_) return r;
    std::printf("quicksand: done, %ld steps in %s (%.3g point updates/s); results in %s\n", r.steps,
                formatSeconds(r.wallSeconds).c_str(), r.pointUpdatesPerSecond,
                options_.writeFiles ? outDir_.string().c_str() : "(memory)");
    if (columnRanks_)
        std::printf("quicksand: sent to neighbouring ranks per step (points and grid values; not hypre's solves "
                    "nor the reductions): %s a rank on average, %s from the busiest\n",
                    formatBytes(sentMean).c_str(), formatBytes(sentMax).c_str());
    if (!r.couplingSummary.empty()) std::printf("quicksand: %s\n", r.couplingSummary.c_str());
    const IntegratorStats& i = r.integrator;
    if (i.steps > 0) {
        std::printf("quicksand: semi-implicit step, dt = %.3g s: the pressure solve took %.1f %% of the wall time, "
                    "%.3f solves per step (%s%s",
                    r.dt, r.wallSeconds > 0 ? 100 * i.seconds / r.wallSeconds : 0.0, double(i.solves) / double(i.steps),
                    i.solver, i.iterations > 0 ? ", " : "");
        if (i.iterations > 0) std::printf("%.1f iterations per solve", double(i.iterations) / double(i.solves));
        std::printf(")\n");
        if (i.cappedSteps > 0)
            std::printf("quicksand: %ld steps ended their active set (the water's bound%s) unsettled\n", i.cappedSteps,
                        i.wallPasses > 0 ? ", or a rough wall's stick or slip" : "");
        if (i.wallPasses > 0)
            std::printf("quicksand: %ld passes (%.3g %% of the solves) were taken again because the pressure increment "
                        "overturned a rough wall's stick or slip\n", i.wallPasses, 100.0 * double(i.wallPasses) / double(i.solves));
    }
    return r;
}

std::unique_ptr<Simulation::Run> openRun(const CaseConfig& config, const RunOptions& options) {
    switch (config.grid.dimension) {
        case 1: return std::make_unique<RunOf<1>>(config, options);
        case 2: return std::make_unique<RunOf<2>>(config, options);
        case 3: return std::make_unique<RunOf<3>>(config, options);
    }
    throw Error("grid.dimension must be 1, 2 or 3");
}

}  // namespace

Simulation::Simulation(const CaseConfig& config, const RunOptions& options) : run_(openRun(config, options)) {}
Simulation::~Simulation() = default;
double Simulation::time() const { return run_->time(); }
double Simulation::dt() const { return run_->dt(); }
long Simulation::steps() const { return run_->steps(); }
int Simulation::dimension() const { return run_->dimension(); }
ColumnState Simulation::state() const { return run_->state(); }
std::vector<CellRow> Simulation::profile() const { return run_->profile(); }
std::vector<PointFieldValues> Simulation::pointFields(bool solid) const { return run_->pointFields(solid); }
SandCells Simulation::sandCells() const { return run_->sandCells(); }
void Simulation::advanceTo(double end) { run_->advanceTo(end); }
void Simulation::writeOutput() { run_->writeOutput(); }
void Simulation::writeCheckpoint() { run_->writeCheckpoint(); }
RunSummary Simulation::finish() { return run_->finish(); }

}  // namespace qs
