#include "solver/Run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/Error.hpp"
#include "io/Checkpoint.hpp"
#include "io/FieldWriter.hpp"
#include "io/SeriesWriter.hpp"
#include "reservoir/ReservoirModel.hpp"

namespace qs {

namespace fs = std::filesystem;

std::vector<std::string> seriesColumns(const CaseConfig& config) {
    std::vector<std::string> c = {"time", "gate_flux", "gate_pressure", "reservoir_head",
                                  "sand_surface", "water_surface", "gradient"};
    for (const auto& m : config.monitors) c.push_back("q_" + m.name);
    for (const char* k : {"cumulative_inflow", "cumulative_outflow", "injected_volume", "ledger_residual",
                          "solid_mass", "liquid_mass", "solid_points", "liquid_points"})
        c.push_back(k);
    return c;
}

namespace {

std::vector<double> seriesRow(const ColumnState& s) {
    std::vector<double> r = {s.time, s.gateFlux, s.gatePressure, s.reservoirHead, s.sandSurface,
                             s.waterSurface, s.gradient};
    for (Real q : s.monitorFlux) r.push_back(q);
    for (double v : {s.cumulativeInflow, s.cumulativeOutflow, s.injectedVolume, s.ledgerResidual, s.solidMass,
                     s.liquidMass, double(s.solidPoints), double(s.liquidPoints)})
        r.push_back(v);
    return r;
}

template <int D>
void writeFields(FieldWriter& writer, const DoublePointSolver<D>& solver) {
    const auto& s = solver.solid();
    const auto& l = solver.liquid();
    std::vector<double> sState(s.state.begin(), s.state.end());
    std::vector<double> lState(l.state.begin(), l.state.end());
    writer.beginStep(solver.time());
    writer.writePointSet("solid", s.size(), s.x.data(),
                         {{"velocity", s.v.data(), D, FieldKind::Vector},
                          {"porosity", s.porosity.data(), 1},
                          {"effective_stress", s.stress.data(), 6},
                          {"volume", s.volume.data(), 1},
                          {"state", sState.data(), 1}});
    writer.writePointSet("liquid", l.size(), l.x.data(),
                         {{"velocity", l.v.data(), D, FieldKind::Vector},
                          {"pore_pressure", l.pressure.data(), 1},
                          {"volume", l.volume.data(), 1},
                          {"state", lState.data(), 1}});
    writer.endStep();
}

std::string formatDuration(double s) {
    char buf[64];
    if (s < 120) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else if (s < 7200) std::snprintf(buf, sizeof buf, "%.1f min", s / 60);
    else std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
    return buf;
}

template <int D>
RunSummary runColumn(const CaseConfig& config, const RunOptions& options) {
    using Clock = std::chrono::steady_clock;
    auto reservoir = makeReservoirModel(config);
    DoublePointSolver<D> solver(config, *reservoir);  // validates the geometry before any output

    const double end = options.endTime >= 0 ? options.endTime : config.time.end;
    const fs::path outDir = fs::path(config.caseDirectory) / config.output.directory;
    const fs::path checkpointPath = outDir / "checkpoint.h5";
    std::unique_ptr<SeriesWriter> series;
    std::unique_ptr<FieldWriter> fields;

    if (options.resume) {
        QS_CHECK(fs::exists(checkpointPath),
                 "cannot resume: no checkpoint at " << checkpointPath.string()
                                                    << " (run without --resume first)");
        solver.loadState(readCheckpoint(checkpointPath.string()));
    } else {
        solver.runGravityStage();
    }
    if (options.writeFiles) {
        if (!options.resume) {
            // keep the previous results instead of overwriting them
            if (fs::exists(outDir)) {
                const fs::path previous = outDir.string() + ".previous";
                fs::remove_all(previous);
                fs::rename(outDir, previous);
            }
            fs::create_directories(outDir);
        }
        series = std::make_unique<SeriesWriter>((outDir / "series.csv").string(),
                                                seriesColumns(config), options.resume,
                                                solver.time());
        // fields.h5 is rewritten on resume from the checkpoint time on
        if (config.output.fields) fields = std::make_unique<FieldWriter>(outDir.string(), D);
    }

    const double interval = config.time.outputInterval;
    // outputs stay on the grid k * interval, also after a resume
    double nextOutput = options.resume ? (std::floor(solver.time() / interval + 0.5) + 1) * interval : 0.0;
    double nextCheckpoint = config.time.checkpointInterval > 0
                                ? solver.time() + config.time.checkpointInterval
                                : 1e300;
    auto output = [&]() {
        const ColumnState s = solver.columnState();
        if (series) series->write(seriesRow(s));
        if (fields) writeFields(*fields, solver);
        reservoir->writeOutput(s.time);
        if (options.onOutput) options.onOutput(s, solver.profile());
    };
    auto checkpoint = [&]() {
        if (!options.writeFiles) return;
        CheckpointData data;
        solver.saveState(data);
        writeCheckpoint(checkpointPath.string(), data);
    };

    if (!options.resume) { output(); nextOutput = interval; }
    const auto wall0 = Clock::now();
    auto lastProgress = wall0;
    const long steps0 = solver.stepCount();
    double pointSteps = 0;
    const double half = 0.5 * solver.dt();
    if (!options.quiet)
        std::printf("quicksand: %dD, dt = %.3g s (c_fast = %.1f m/s), %zu solid + %zu liquid points, "
                    "t = %.4g -> %.4g s\n",
                    D, solver.dt(), solver.waveSpeed(), solver.solid().size(),
                    solver.liquid().size(), solver.time(), end);
    while (solver.time() < end - half) {
        solver.step();
        pointSteps += double(solver.solid().size() + solver.liquid().size());
        if (solver.time() >= nextOutput - half) {
            output();
            nextOutput += interval;
        }
        if (solver.time() >= nextCheckpoint - half) {
            checkpoint();
            nextCheckpoint += config.time.checkpointInterval;
        }
        const auto now = Clock::now();
        if (!options.quiet &&
            std::chrono::duration<double>(now - lastProgress).count() >= config.output.progressInterval) {
            lastProgress = now;
            const double wall = std::chrono::duration<double>(now - wall0).count();
            const double rate = (solver.stepCount() - steps0) / wall;
            const double eta = (end - solver.time()) / solver.dt() / rate;
            const ColumnState s = solver.columnState();
            std::printf("  t = %.4g s (%.1f %%)  %.0f steps/s  ETA %s  gate flux %.4g m3/s  i = %.3f\n",
                        solver.time(), 100 * solver.time() / end, rate, formatDuration(eta).c_str(),
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
    r.outputDirectory = outDir.string();
    if (!options.quiet)
        std::printf("quicksand: done, %ld steps in %s (%.3g point updates/s); results in %s\n",
                    r.steps, formatDuration(r.wallSeconds).c_str(), r.pointUpdatesPerSecond,
                    options.writeFiles ? outDir.string().c_str() : "(memory)");
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
