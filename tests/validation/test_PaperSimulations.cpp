// Validation against the paper (fluidisation-column-paper.md; physics.md section 5), label
// `validation`: the shipped cases cases/paperSimulationA (coarsened to 12.4 mm cells to keep the
// suite short; the shipped 6.2 mm run is in docs/validation.md) and cases/paperSimulationB.
//
// A (Mohr-Coulomb, i0 = 1.5, finite reservoir, laminar tube) must show the whole cycle:
//   - onset: sand turns fluidised at the filter once the gradient across the bed passes i_c;
//   - a porosity wave running up from the filter at a near-constant speed: a linear fit of the
//     front against time with r^2 >= 0.98, its speed within 15 % of the drift-flux shock speed
//     s = (1-n0)(U2-U1)/(n2-n0) for the measured flux U2 (U1 = U_mf, n2 the equilibrium porosity
//     of U2);
//   - the bed expanding while fluidised;
//   - the gate flux falling as the reservoir's head decays;
//   - the bed resettling once the head is below critical: no fluidised sand, a still bed.
// B (rigid bed at n = 0.452, H = 90 mm, i = 1.32, a finite reservoir): the filter velocity within
// 2 % of the quasi-steady Darcy-Forchheimer value for the head of the moment, drifting down with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "case/CaseLoader.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/DriftFlux.hpp"
#include "solver/Run.hpp"

using namespace qs;

namespace {

struct Series {
    CaseConfig config;
    std::vector<ColumnState> states;
};

Series runPaperCase(const std::string& name, const std::function<void(CaseConfig&)>& edit = {}) {
    Series s;
    s.config = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/" + name);
    if (edit) edit(s.config);
    RunOptions o;
    o.quiet = true;
    o.writeFiles = false;
    o.onOutput = [&](const ColumnState& st, const std::vector<CellRow>&) { s.states.push_back(st); };
    runCase(s.config, o);
    return s;
}

closed::SuspensionFlux fluxOf(const CaseConfig& c) { return closed::SuspensionFlux::of(c, c.materials.front()); }

}  // namespace

TEST(PaperSimulationA, FluidisesExpandsAndResettlesAsTheHeadDecays) {
    const Series run = runPaperCase("paperSimulationA", [](CaseConfig& c) {
        c.grid.cellSize = 0.0124;
        c.column.chamberHeight = 0.0124;
    });
    const auto& c = run.config;
    const auto& sand = c.materials.front();
    const double A = c.grid.crossSectionArea, H = c.sandTop() - c.filterLevel();
    const double ic = closed::criticalGradient(sand.grainDensity, c.liquid.density, sand.porosity);
    const auto flux = fluxOf(c);
    const double Umf = flux.equilibriumFlux(sand.porosity);

    // onset: the first fluidised sand, once the bed's gradient has reached i_c
    std::size_t onset = 0;
    while (onset < run.states.size() && run.states[onset].fluidisedShare == 0) ++onset;
    ASSERT_LT(onset, run.states.size()) << "the bed never fluidised";
    EXPECT_GE(run.states[onset].gradient, 0.97 * ic) << "fluidised below the critical gradient";

    // the front climbs from the filter: fit while it rises (until it nears the top)
    double tEnd = run.states[onset].time;
    std::size_t k = onset;
    while (k < run.states.size() && run.states[k].fluidisedFront < c.filterLevel() + 0.85 * H) tEnd = run.states[k++].time;
    double st = 0, sy = 0, stt = 0, sty = 0, syy = 0, n = 0, U2 = 0;
    for (std::size_t j = onset; j < run.states.size() && run.states[j].time <= tEnd; ++j) {
        const auto& s = run.states[j];
        st += s.time; sy += s.fluidisedFront; stt += s.time * s.time; sty += s.time * s.fluidisedFront;
        syy += s.fluidisedFront * s.fluidisedFront;
        U2 += s.gateFlux / A;
        n += 1;
    }
    ASSERT_GE(n, 5);
    U2 /= n;
    const double slope = (n * sty - st * sy) / (n * stt - st * st);
    const double intercept = (sy - slope * st) / n;
    const double r2 = 1 - (syy - intercept * sy - slope * sty) / (syy - sy * sy / n);
    const double n2 = flux.equilibriumPorosity(U2);
    const double shock = (1 - sand.porosity) * (U2 - Umf) / (n2 - sand.porosity);
    EXPECT_GE(r2, 0.98);
    EXPECT_NEAR(slope, shock, 0.15 * shock);

    // the bed expands while fluidised, by most of what drift flux gives for U2
    double highest = 0, tHighest = 0;
    for (const auto& s : run.states)
        if (s.bedHeight > highest) { highest = s.bedHeight; tHighest = s.time; }
    const double expanded = H * (1 - sand.porosity) / (1 - n2);
    EXPECT_GT(highest - H, 0.6 * (expanded - H));
    // the gate flux falls as the head decays
    EXPECT_LT(run.states.back().gateFlux, 0.8 * run.states[onset + 5].gateFlux);
    EXPECT_LT(run.states.back().reservoirHead, run.states.front().reservoirHead);
    // and the bed resettles: nothing fluidised, the bed still and lower than at its highest
    const auto& last = run.states.back();
    EXPECT_EQ(last.fluidisedShare, 0.0);
    EXPECT_LT(last.bedHeight, highest - 0.3 * (highest - H));
    EXPECT_NEAR(run.states[run.states.size() - 10].bedHeight, last.bedHeight, 1e-4);
    std::printf("simulation A: onset at t = %.2f s, i = %.3f (i_c %.3f); front %.2f mm/s, r2 %.4f, drift-flux shock "
                "%.2f mm/s for U2 = %.3e m/s (%+.1f %%); highest bed %.1f mm at %.1f s (drift flux %.1f mm); final "
                "%.1f mm, gate flux %.3e -> %.3e m3/s\n",
                run.states[onset].time, run.states[onset].gradient, ic, 1000 * slope, r2, 1000 * shock, U2,
                100 * (slope / shock - 1), 1000 * highest, tHighest, 1000 * expanded, 1000 * last.bedHeight,
                run.states[onset + 5].gateFlux, last.gateFlux);
}

TEST(PaperSimulationB, SteadyFilterVelocityFollowsDarcyForchheimerAsTheHeadDecays) {
    const Series run = runPaperCase("paperSimulationB");
    const auto& c = run.config;
    const auto& sand = c.materials.front();
    const auto law = PermeabilityLaw::from(sand);
    const double H = c.sandTop() - c.filterLevel(), tail = *c.column.overflowLevel;
    double worst = 0;
    for (const auto& s : run.states) {
        if (s.time < 2.0) continue;
        const double i = (s.reservoirHead - tail) / H;
        const double q = closed::darcyForchheimerFlux(i, law.kappa(sand.porosity), law.ergunFactor(sand.porosity),
                                                      c.liquid.density, c.gravity, c.liquid.viscosity);
        worst = std::max(worst, std::abs(s.monitorFlux.at(0) / q - 1));
        EXPECT_NEAR(s.monitorFlux.at(0), q, 0.02 * q) << "t = " << s.time;
    }
    // it drifts down with the head
    EXPECT_LT(run.states.back().monitorFlux.at(0), 0.97 * run.states[10].monitorFlux.at(0));
    EXPECT_LT(worst, 0.01);  // guard: within a per cent is achieved
    std::printf("simulation B: filter velocity within %.2f %% of Darcy-Forchheimer for the head, %.4e -> %.4e m/s\n",
                100 * worst, run.states[10].monitorFlux.at(0), run.states.back().monitorFlux.at(0));
}
