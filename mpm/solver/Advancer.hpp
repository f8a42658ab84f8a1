#pragma once
// Advancer: how a run moves its solver on. Either step by step (a built-in reservoir is advanced
// inside each MPM step) or window by window through a coupling scheme (a windowed model such as
// OpenFOAM), whose state is checkpointed with the solver's.
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

#include "coupling/CouplingInterface.hpp"
#include "coupling/CouplingScheme.hpp"
#include "coupling/WindowedModel.hpp"
#include "io/Checkpoint.hpp"
#include "solver/DoublePointSolver.hpp"

namespace qs {

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

}  // namespace qs
