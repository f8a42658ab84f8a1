#include "solver/Run.hpp"
#include "solver/Interruption.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "core/Error.hpp"
#include "io/Checkpoint.hpp"
#include "io/FieldWriter.hpp"
#include "io/PipesTable.hpp"
#include "io/SeriesWriter.hpp"
#include "coupling/CouplingScheme.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/RunPreconditions.hpp"
#include "solver/RunSize.hpp"

namespace qs {

namespace fs = std::filesystem;

std::vector<std::string> seriesColumns(const CaseConfig& config) {
    std::vector<std::string> c = {"time",         "gate_flux",  "gate_pressure",   "reservoir_head",
                                  "sand_surface", "bed_height", "fluidised_front", "fluidised_share",
                                  "water_surface", "gradient"};
    for (const auto& m : config.monitors) c.push_back("q_" + m.name);
    for (const char* k : {"cumulative_inflow", "cumulative_outflow", "injected_volume", "ledger_residual",
                          "solid_mass", "liquid_mass", "solid_points", "liquid_points", "cumulative_solid_outflow"})
        c.push_back(k);
    return c;
}

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

template <int D>
void writeFields(FieldWriter& writer, const DoublePointSolver<D>& solver, const SandCells* cells) {
    const auto& s = solver.solid();
    const auto& l = solver.liquid();
    std::vector<double> sState(s.state.begin(), s.state.end());
    std::vector<double> sReturn(s.stressReturn.begin(), s.stressReturn.end());
    std::vector<double> lState(l.state.begin(), l.state.end());
    writer.beginStep(solver.time());
    std::vector<PointField> solidFields = {{"velocity", s.v.data(), D, FieldKind::Vector},
                                           {"porosity", s.porosity.data(), 1},
                                           {"effective_stress", s.stress.data(), 6},
                                           {"volume", s.volume.data(), 1},
                                           {"mass", s.mass.data(), 1},
                                           {"state", sState.data(), 1},
                                           {"stress_return", sReturn.data(), 1}};
    // the constitutive models' state variables (Mohr-Coulomb: equivalent plastic strain,
    // plastic volumetric strain)
    if (s.internalCount > 0) solidFields.push_back({"state_variables", s.internal.data(), s.internalCount});
    writer.writePointSet("solid", s.size(), s.x.data(), solidFields);
    writer.writePointSet("liquid", l.size(), l.x.data(),
                         {{"velocity", l.v.data(), D, FieldKind::Vector},
                          {"pore_pressure", l.pressure.data(), 1},
                          {"volume", l.volume.data(), 1},
                          {"mass", l.mass.data(), 1},
                          {"cavity", l.cavity.data(), 1},
                          {"state", lState.data(), 1}});
    if (cells) writeCells(writer, solver.grid(), *cells);
    writer.endStep();
}

/// A fresh output directory, with the earlier one kept: it is moved aside at once and becomes
/// output.previous only when the run has started (commit()); a run that fails before that
/// (an OpenFOAM case that does not load) puts it back, so earlier results are never lost.
class OutputRotation {
public:
    explicit OutputRotation(fs::path outDir, const std::string& caseFile) : outDir_(std::move(outDir)) {
        // a file (not a directory) where the output should go is the user's, not old output
        std::error_code ec;
        if (fs::exists(outDir_, ec) && !fs::is_directory(outDir_, ec))
            throw Error(caseFile + ": key 'output.directory': " + outDir_.string() +
                        " is a file, not a directory; choose another output.directory or move the file");
        aside_ = outDir_.string() + ".moving-aside";
        fs::remove_all(aside_);
        if (fs::exists(outDir_)) fs::rename(outDir_, aside_);
        fs::create_directories(outDir_);
        active_ = true;
    }
    void commit() {
        if (!active_) return;
        const fs::path previous = outDir_.string() + ".previous";
        if (fs::exists(aside_)) {
            fs::remove_all(previous);
            fs::rename(aside_, previous);
        }
        active_ = false;
    }
    ~OutputRotation() {
        if (!active_) return;
        std::error_code ignored;  // a destructor must not throw: best effort
        fs::remove_all(outDir_, ignored);
        if (fs::exists(aside_, ignored)) fs::rename(aside_, outDir_, ignored);
    }

private:
    fs::path outDir_, aside_;
    bool active_ = false;
};

/// Advances the solver, either step by step (built-in reservoirs, advanced inside each step) or
/// window by window through a coupling scheme (windowed models such as OpenFOAM).
class Advancer {
public:
    virtual ~Advancer() = default;
    virtual void advance(double end) = 0;
    virtual void save(CheckpointData&) const {}
    virtual void load(const CheckpointData&) {}
    virtual std::string summary() const { return ""; }
};

template <int D>
class StepAdvancer final : public Advancer {
public:
    explicit StepAdvancer(DoublePointSolver<D>& s) : s_(s) {}
    void advance(double) override { s_.step(); }

private:
    DoublePointSolver<D>& s_;
};

template <int D>
class WindowAdvancer final : public Advancer {
public:
    WindowAdvancer(DoublePointSolver<D>& s, WindowedModel& model, CouplingInterface& gate,
                   const CouplingConfig& config, std::ostream* log)
        : mpm_(s), model_(model), scheme_(makeCouplingScheme(config, model, gate, log)) {}
    void setGateImpedance(double z) { scheme_->setGateImpedance(z); }
    void advance(double end) override { scheme_->advanceWindow(mpm_, end); }
    void save(CheckpointData& d) const override {
        model_.writeOutput(mpm_.time());  // a CFD model's fields, to resume from
        d.put("coupling_scheme", scheme_->saveState());
        d.put("coupling_model", model_.saveState());
    }
    void load(const CheckpointData& d) override {
        scheme_->restoreState(d.doubles("coupling_scheme"));
        model_.restoreState(d.doubles("coupling_model"));
    }
    std::string summary() const override {
        const auto& st = scheme_->stats();
        char buf[320];
        const double total = st.modelSeconds + st.mpmSeconds;
        std::snprintf(buf, sizeof buf,
                      "coupling: %ld windows, %ld model solves, %.2f iterations/window, %ld "
                      "unconverged; model %.3g s (%.1f %% of coupled time), MPM %.3g s",
                      st.windows, st.modelSolves,
                      st.windows > 0 ? double(st.modelSolves) / st.windows : 0.0, st.unconverged,
                      st.modelSeconds, total > 0 ? 100 * st.modelSeconds / total : 0.0, st.mpmSeconds);
        return buf;
    }
    const CouplingStats& stats() const { return scheme_->stats(); }

private:
    MpmAdapter<DoublePointSolver<D>> mpm_;
    WindowedModel& model_;
    std::unique_ptr<CouplingScheme> scheme_;
};

template <int D>
RunSummary runColumn(const CaseConfig& config, const RunOptions& options) {
    using Clock = std::chrono::steady_clock;
    const double end = options.endTime >= 0 ? options.endTime : config.time.end;
    const fs::path outDir = fs::path(config.caseDirectory) / config.output.directory;
    const fs::path checkpointPath = outDir / "checkpoint.h5";
    const bool windowed = options.windowedModel || config.reservoir.kind == ReservoirKind::OpenFoam;

    // Validate everything that can be validated before touching an earlier output directory:
    // what `quicksand check` validates too (solver/RunPreconditions.hpp).
    validateRun(config);
    std::unique_ptr<ReservoirModel> builtIn;
    if (!windowed) builtIn = makeReservoirModel(config);
    if (options.resume)
        QS_CHECK(fs::exists(checkpointPath),
                 "cannot resume: no checkpoint at " << checkpointPath.string()
                                                    << " (run without --resume first)");
    std::optional<OutputRotation> rotation;
    if (options.writeFiles && !options.resume) rotation.emplace(outDir, config.caseDirectory + "/case.toml");

    // A windowed model (OpenFOAM) works in the output directory.
    std::unique_ptr<WindowedModel> ownedModel;
    WindowedModel* model = options.windowedModel;
    if (windowed && !model) {
        ownedModel = makeOpenFoamModel(config, options.resume);
        model = ownedModel.get();
    }
    std::unique_ptr<CouplingInterface> gate;
    if (windowed) gate = std::make_unique<CouplingInterface>(*model);
    ReservoirModel& reservoir = windowed ? static_cast<ReservoirModel&>(*gate) : *builtIn;
    DoublePointSolver<D> solver(config, reservoir);
    if (rotation) rotation->commit();  // everything loaded: the earlier output becomes .previous

    std::ofstream couplingLog;
    if (windowed && options.writeFiles)
        couplingLog.open(outDir / "coupling.log", options.resume ? std::ios::app : std::ios::trunc);
    std::unique_ptr<Advancer> advancer;
    WindowAdvancer<D>* windowAdvancer = nullptr;
    if (windowed) {
        auto w = std::make_unique<WindowAdvancer<D>>(solver, *model, *gate, config.coupling,
                                                     couplingLog.is_open() ? &couplingLog : nullptr);
        // the chamber water's acoustic impedance rho c / A damps its ringing between windows
        const double c = std::sqrt(config.liquid.bulkModulus / config.liquid.density);
        w->setGateImpedance(config.liquid.density * c / config.grid.crossSectionArea);
        windowAdvancer = w.get();
        advancer = std::move(w);
    } else {
        advancer = std::make_unique<StepAdvancer<D>>(solver);
    }

    if (options.resume) {
        try {
            const CheckpointData data = readCheckpoint(checkpointPath.string());
            solver.loadState(data);
            advancer->load(data);
        } catch (const Error& e) {
            std::string what = e.what();
            if (what.rfind(checkpointPath.string(), 0) != 0) what = checkpointPath.string() + ": " + what;
            throw Error(what + ". This checkpoint cannot be resumed from; run without --resume to start again (the "
                               "results now in " + outDir.string() + " are then kept as " + outDir.string() +
                        ".previous)");
        }
    } else {
        solver.runGravityStage();
    }
    // the case as run: the file, or with the command line's overrides marked
    // (io/CaseOverride.hpp). Written once the checkpoint has loaded: a resume that is refused
    // (another scheme's checkpoint, say, with --set overrides) leaves the earlier one as it was
    if (options.writeFiles && !config.effectiveCase.empty()) {
        std::ofstream effective(outDir / "case.effective.toml", std::ios::trunc);
        effective << config.effectiveCase;
        QS_CHECK(effective.good(), "cannot write " << (outDir / "case.effective.toml").string());
    }

    std::unique_ptr<SeriesWriter> series;
    std::unique_ptr<FieldWriter> fields;
    std::unique_ptr<SeriesWriter> pipes;
    if (options.writeFiles) {
        series = std::make_unique<SeriesWriter>((outDir / "series.csv").string(),
                                                seriesColumns(config), options.resume,
                                                solver.time());
        if (D > 1)
            pipes = std::make_unique<SeriesWriter>((outDir / "pipes.csv").string(), pipesColumns(D), options.resume,
                                                   solver.time());
    }

    const double interval = config.time.outputInterval;
    // outputs stay on the grid k * interval, also after a resume: the first one after the
    // checkpoint's time (an interruption checkpoints between outputs, not only on one)
    const double halfStep = 0.5 * solver.dt();
    double nextOutput =
        options.resume ? (std::floor((solver.time() + halfStep) / interval) + 1) * interval : 0.0;
    // a resumed run keeps the field steps written before its first new output
    if (options.writeFiles && config.output.fields)
        fields = std::make_unique<FieldWriter>(outDir.string(), D, options.resume ? nextOutput - halfStep : -1e300);
    // fields.h5 and fields.xdmf list new outputs once a second: a 1D column writes its outputs
    // many to the second, and each listing rewrites both files
    if (fields) fields->setListingInterval(1.0);
    double nextCheckpoint = config.time.checkpointInterval > 0
                                ? solver.time() + config.time.checkpointInterval
                                : 1e300;
    auto output = [&]() {
        const ColumnState s = solver.columnState();
        if (series) series->write(seriesRow(s));
        // 2D, 3D: the cells' sand state, once, for the fields, pipes.csv and the caller
        std::optional<SandCells> cells;
        if constexpr (D > 1)
            if (fields || pipes || options.onPipes) cells = solver.sandCells();
        if (fields) writeFields(*fields, solver, cells ? &*cells : nullptr);
        if (cells && (pipes || options.onPipes)) {
            const PipeSurvey survey = findPipes(*cells);
            if (pipes)
                for (const auto& row : pipesRows(s.time, D, survey)) pipes->write(row);
            if (options.onPipes) options.onPipes(s.time, *cells, survey);
        }
        reservoir.writeOutput(s.time);
        if (options.onOutput) options.onOutput(s, solver.profile());
    };
    double lastCheckpoint = options.resume ? solver.time() : -1.0;
    auto checkpoint = [&]() {
        if (!options.writeFiles) return;
        if (fields) fields->makeDurable();  // the outputs before the checkpoint that counts on them
        CheckpointData data;
        solver.saveState(data);
        advancer->save(data);
        writeCheckpoint(checkpointPath.string(), data);
        lastCheckpoint = solver.time();
    };

    if (!options.resume) { output(); nextOutput = interval; }
    const auto wall0 = Clock::now();
    auto lastProgress = wall0;
    const long steps0 = solver.stepCount();
    double pointSteps = 0;
    const double half = 0.5 * solver.dt();
    if (!options.quiet)
        std::printf("quicksand: %dD, %s, dt = %.3g s (%s = %.1f m/s), %zu solid + %zu liquid points, "
                    "t = %.4g -> %.4g s%s\n",
                    D, solver.scheme() == TimeScheme::SemiImplicit ? "semi-implicit" : "explicit", solver.dt(),
                    solver.scheme() == TimeScheme::SemiImplicit ? "c_skeleton" : "c_fast", solver.waveSpeed(),
                    solver.solid().size(),
                    solver.liquid().size(), solver.time(), end,
                    windowed ? (", coupled to " + model->name()).c_str() : "");
    if (!options.quiet && !config.liquid.bulkModulusGiven)
        std::printf("quicksand: water K_L = %.4g Pa (liquid.bulk_modulus not given: %s)\n",
                    config.liquid.bulkModulus, config.liquid.defaultWaterName());
    if (!options.quiet && windowed && !model->description().empty())
        std::printf("quicksand: %s: %s\n", model->name().c_str(), model->description().c_str());
    if (couplingLog.is_open() && windowed)
        couplingLog << "# " << model->name() << (model->description().empty() ? "" : ": " + model->description())
                    << (options.resume ? " (resumed)" : "") << "\n";
    // Ctrl-C or SIGTERM: the step (or coupling window) in progress ends, a checkpoint is
    // written, and the run stops saying how to resume (solver/Interruption.hpp)
    InterruptionGuard interruption;
    while (solver.time() < end - half) {
        if (const int sig = interruptionRequested()) {
            checkpoint();
            std::ostringstream m;
            m << "interrupted by " << signalName(sig) << " at t = " << solver.time() << " s (step "
              << solver.stepCount() << ")";
            if (options.writeFiles)
                m << "; checkpoint written to " << checkpointPath.string() << "; continue with: quicksand run "
                  << config.caseDirectory << " --resume";
            throw Interrupted(sig, m.str());
        }
        const long before = solver.stepCount();
        try {
            advancer->advance(end);
        } catch (const Interrupted&) {
            throw;
        } catch (const Error& e) {
            // the failed state is not written; the last good checkpoint stays as it was
            if (!options.writeFiles || lastCheckpoint < 0) throw;
            std::ostringstream m;
            m << e.what() << ". The last good checkpoint, at t = " << lastCheckpoint << " s, is "
              << checkpointPath.string();
            throw Error(m.str());
        }
        pointSteps += double(solver.stepCount() - before) * double(solver.solid().size() + solver.liquid().size());
        if (solver.time() >= nextOutput - half) {
            output();
            while (nextOutput <= solver.time() + half) nextOutput += interval;
        }
        if (solver.time() >= nextCheckpoint - half) {
            checkpoint();
            nextCheckpoint += config.time.checkpointInterval;
        }
        const auto now = Clock::now();
        if (fields) fields->listIfDue(now);
        if (!options.quiet &&
            std::chrono::duration<double>(now - lastProgress).count() >= config.output.progressInterval) {
            lastProgress = now;
            const double wall = std::chrono::duration<double>(now - wall0).count();
            const double rate = (solver.stepCount() - steps0) / wall;
            const double eta = (end - solver.time()) / solver.dt() / rate;
            const ColumnState s = solver.columnState();
            std::printf("  t = %.4g s (%.1f %%)  %.0f steps/s  ETA %s  gate flux %.4g m3/s  i = %.3f\n",
                        solver.time(), 100 * solver.time() / end, rate, formatSeconds(eta).c_str(),
                        s.gateFlux, s.gradient);
            std::fflush(stdout);
        }
    }
    checkpoint();

    RunSummary r;
    r.final = solver.columnState();
    r.profile = solver.profile();
    r.steps = solver.stepCount() - steps0;
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - wall0).count();
    r.pointUpdatesPerSecond = r.wallSeconds > 0 ? pointSteps / r.wallSeconds : 0;
    r.dt = solver.dt();
    r.integrator = solver.integratorStats();
    r.outputDirectory = outDir.string();
    if (windowAdvancer) {
        r.coupling = windowAdvancer->stats();
        r.couplingSummary = windowAdvancer->summary();
    }
    if (!options.quiet) {
        std::printf("quicksand: done, %ld steps in %s (%.3g point updates/s); results in %s\n",
                    r.steps, formatSeconds(r.wallSeconds).c_str(), r.pointUpdatesPerSecond,
                    options.writeFiles ? outDir.string().c_str() : "(memory)");
        if (!r.couplingSummary.empty()) std::printf("quicksand: %s\n", r.couplingSummary.c_str());
        const IntegratorStats& i = r.integrator;
        if (i.steps > 0) {
            std::printf("quicksand: semi-implicit step, dt = %.3g s: the pressure solve took %.1f %% of the wall time, "
                        "%.3f solves per step (%s%s",
                        r.dt, r.wallSeconds > 0 ? 100 * i.seconds / r.wallSeconds : 0.0,
                        double(i.solves) / double(i.steps), i.solver, i.iterations > 0 ? ", " : "");
            if (i.iterations > 0) std::printf("%.1f iterations per solve", double(i.iterations) / double(i.solves));
            std::printf(")\n");
            if (i.cappedSteps > 0)
                std::printf("quicksand: %ld steps ended their active set (the water's bound) unsettled\n", i.cappedSteps);
        }
    }
    return r;
}

}  // namespace

RunSummary runCase(const CaseConfig& config, const RunOptions& options) {
    switch (config.grid.dimension) {
        case 1: return runColumn<1>(config, options);
        case 2: return runColumn<2>(config, options);
        case 3: return runColumn<3>(config, options);
    }
    throw Error("grid.dimension must be 1, 2 or 3");
}

}  // namespace qs
