// Laterally non-uniform 2D columns (issue 7): tests that fail when the lateral physics is broken,
// which laterally uniform columns cannot do (they reduce to 1D exactly).
//   - two gravels side by side at rest stay at rest: the pressure forces are the transpose of
//     the storage equation's divergence (with the centre-rule forms the nodes beside the
//     interface moved at up to 7.7e-4 m/s, 3.5 % of the coarse half's conductivity);
//   - the same two gravels in seepage for 15 s: each half carries its own Darcy-Forchheimer flux
//     within 1 % the whole time, the liquid ledger closes to 1e-6 of the inflow and the liquid
//     points stay bounded (with the centre-rule pressure forces the halves were 3 % and 1 % off;
//     with the overflow's top cells decided by their points, both fell by 13 % within 3 s);
//   - a 2D column on a pressure gate has no growing lateral mode: the gate moves its water at
//     one velocity (held node by node, the chamber water was Rayleigh-Taylor unstable and broke
//     the 2D case B after 2.3 s).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>
#include <vector>

#include "VerificationCase.hpp"
#include "io/Checkpoint.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/Permeability.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;
using namespace qs::test;

namespace {

MonitorConfig nodeMonitor(const std::string& name, double z, double x, double halfWidth) {
    MonitorConfig m;
    m.name = name;
    m.elevation = z;
    m.x = HorizontalRange{std::max(0.0, x - halfWidth), x + halfWidth};
    return m;
}

/// The largest relative difference, over the outputs from t0 on, between the water crossing the
/// filter summed over the columns of cells (SandCells::baseFlux, what pipes.csv's shares divide)
/// and the gate's flux: in steady seepage they are the same water.
double worstColumnSum(const CaseRun& run, double t0) {
    double worst = 0;
    for (std::size_t k = 0; k < run.series.size(); ++k) {
        if (run.series[k].time < t0) continue;
        double sum = 0;
        for (double q : run.cells.at(k).baseFlux) sum += q;
        worst = std::max(worst, std::abs(sum / run.series[k].gateFlux - 1));
    }
    return worst;
}

}  // namespace

TEST(SideBySide, TwoGravelsAtRestStayAtRest) {
    const CaseRun run = runVerificationCase("side_by_side", [](CaseConfig& c) {
        c.reservoir.head = c.column.waterLevel;  // no head difference
        c.time.end = 1.0;
        c.time.outputInterval = 0.1;
        // every node of three rows: the two halves, the interface, the walls
        c.monitors.clear();
        for (double z : {0.045, 0.072, 0.099})  // the sand's lower, middle and upper rows
            for (int j = 0; j <= 4; ++j) c.monitors.push_back(nodeMonitor("n" + std::to_string(j), z, 0.009 * j, 1e-3));
    });
    const auto& fine = run.config.material("fine");
    const double K = PermeabilityLaw::from(fine).kappa(fine.porosity) * run.config.liquid.density * run.config.gravity /
                     run.config.liquid.viscosity;
    double worst = 0;
    for (const auto& s : run.series) {
        for (double q : s.monitorFlux) worst = std::max(worst, std::abs(q));
        worst = std::max(worst, std::abs(s.gateFlux / run.config.grid.crossSectionArea));
    }
    EXPECT_LT(worst, 1e-3 * K);  // the geostatic test's bound
    EXPECT_LT(worst, 1e-10);     // guard: 5e-9 K (4e-17 m/s is achieved)
    std::printf("two gravels at rest: largest spurious filter velocity %.2e m/s (K of the fine half %.3e m/s)\n", worst,
                K);
}

TEST(PressureGate, A2DColumnAtRestGrowsNoLateralMode) {
    // the paper's case B in 2D, 8 cells wide, at rest on a constant head, seeded by round-off:
    // the liquid's vertical velocity one cell above the gate must stay the same at the wall and
    // in the middle. The gate's own row moves as one by construction, so it is not what is
    // watched. Held node by node, the Rayleigh-Taylor mode grew here at about 20 /s: from 1e-17
    // to 1.4e-13 m/s by 1.65 s one cell above the gate; with the uniform gate it stays at 6e-17.
    const CaseRun run = runVerificationCase("steady_seepage_B", [](CaseConfig& c) {
        c.grid.dimension = 2;
        c.grid.width = 0.072;
        c.reservoir.kind = ReservoirKind::ConstantHead;
        c.reservoir.head = c.column.waterLevel;
        c.time.end = 2.0;
        c.time.outputInterval = 0.1;
        const double h = c.grid.cellSize;
        c.monitors = {nodeMonitor("wall", h, 0.0, 1e-3), nodeMonitor("middle", h, 0.036, 1e-3)};
    });
    double worst = 0;
    for (const auto& s : run.series) worst = std::max(worst, std::abs(s.monitorFlux.at(0) - s.monitorFlux.at(1)));
    EXPECT_LT(worst, 1e-14);
    std::printf("2D column at rest on a pressure gate: largest lateral difference of the filter velocity one cell above "
                "the gate %.1e m/s\n",
                worst);
}

TEST(SideBySide, TwoGravelsInSeepageEachCarryTheirOwnFluxFor15Seconds) {
    const CaseRun run = runVerificationCase("side_by_side", [](CaseConfig& c) { c.time.outputInterval = 0.5; });
    const auto& c = run.config;
    const double i = (c.reservoir.head - *c.column.overflowLevel) / (c.sandTop() - c.filterLevel());
    auto closedForm = [&](const char* name) {
        const auto& m = c.material(name);
        const auto law = PermeabilityLaw::from(m);
        return closed::darcyForchheimerFlux(i, law.kappa(m.porosity), law.ergunFactor(m.porosity), c.liquid.density,
                                            c.gravity, c.liquid.viscosity);
    };
    const double qFine = closedForm("fine"), qCoarse = closedForm("coarse");
    ASSERT_NEAR(qFine, 9.08e-3, 1e-3 * qFine);
    ASSERT_NEAR(qCoarse, 1.553e-2, 1e-3 * qCoarse);
    double worstFine = 0, worstCoarse = 0;
    std::size_t fewest = run.series.front().liquidPoints, most = fewest;
    for (const auto& s : run.series) {
        if (s.time < 1.0) continue;  // the seepage starts from rest
        fewest = std::min(fewest, s.liquidPoints);
        most = std::max(most, s.liquidPoints);
        worstFine = std::max(worstFine, std::abs(s.monitorFlux.at(0) / qFine - 1));
        worstCoarse = std::max(worstCoarse, std::abs(s.monitorFlux.at(1) / qCoarse - 1));
    }
    EXPECT_LT(worstFine, 0.01);
    EXPECT_LT(worstCoarse, 0.01);
    const auto& last = run.series.back();
    EXPECT_GE(last.time, 15.0 - 1e-9);
    EXPECT_LT(std::abs(last.ledgerResidual), 1e-6 * last.cumulativeInflow);
    // the points: the column fills to its steady sampling within the first flushes, then holds
    EXPECT_LT(most - fewest, run.series.front().liquidPoints / 4);
    // guards near what is achieved: 0.54 %, 0.30 % and 2.3e-7
    EXPECT_LT(worstFine, 0.008);
    EXPECT_LT(worstCoarse, 0.005);
    EXPECT_LT(std::abs(last.ledgerResidual), 5e-7 * last.cumulativeInflow);
    const double columns = worstColumnSum(run, 1.0);
    EXPECT_LT(columns, 0.01);
    std::printf("the columns' flux through the filter sums to the gate's within %.2e\n", columns);
    std::printf("two gravels in seepage over 15 s: fine within %.2f %%, coarse within %.2f %% of their own "
                "Darcy-Forchheimer fluxes (%.4e, %.4e m/s); ledger %.1e of the inflow; liquid points %zu..%zu\n",
                100 * worstFine, 100 * worstCoarse, qFine, qCoarse, std::abs(last.ledgerResidual) / last.cumulativeInflow,
                fewest, most);
}

TEST(SideBySide, ACoreAndAnAnnulusOfTwoGravelsInSeepageCarryTheirOwnFluxes) {
    // the two gravels as a cylinder: the fine one a core of 18 mm radius, the coarse one the
    // annulus around it to 36 mm (the zone's x range is the radius). Each carries its own
    // Darcy-Forchheimer flux as in plane strain; the water crossing between them under the filter
    // and above the sand does so through the hoop terms of the divergence and its transpose
    const CaseRun run = runVerificationCase("side_by_side", [](CaseConfig& c) {
        c.grid.geometry = GridGeometry::Axisymmetric;
        c.grid.crossSectionArea = kPi * c.grid.width * c.grid.width;
        c.time.end = 8.0;
        c.time.outputInterval = 0.5;
    });
    const auto& c = run.config;
    const double i = (c.reservoir.head - *c.column.overflowLevel) / (c.sandTop() - c.filterLevel());
    auto closedForm = [&](const char* name) {
        const auto& m = c.material(name);
        const auto law = PermeabilityLaw::from(m);
        return closed::darcyForchheimerFlux(i, law.kappa(m.porosity), law.ergunFactor(m.porosity), c.liquid.density,
                                            c.gravity, c.liquid.viscosity);
    };
    const double qFine = closedForm("fine"), qCoarse = closedForm("coarse");
    double worstFine = 0, worstCoarse = 0;
    for (const auto& s : run.series) {
        if (s.time < 1.0) continue;
        worstFine = std::max(worstFine, std::abs(s.monitorFlux.at(0) / qFine - 1));
        worstCoarse = std::max(worstCoarse, std::abs(s.monitorFlux.at(1) / qCoarse - 1));
    }
    EXPECT_LT(worstFine, 0.01);
    EXPECT_LT(worstCoarse, 0.01);
    const auto& last = run.series.back();
    EXPECT_LT(std::abs(last.ledgerResidual), 1e-6 * last.cumulativeInflow);
    // guards near what is achieved: 0.37 %, 0.19 %, 5.7e-8
    EXPECT_LT(worstFine, 0.006);
    EXPECT_LT(worstCoarse, 0.004);
    EXPECT_LT(std::abs(last.ledgerResidual), 2e-7 * last.cumulativeInflow);
    // in axisymmetry each column is a ring: its lower nodes weighted by their shares of its face
    const double columns = worstColumnSum(run, 1.0);
    EXPECT_LT(columns, 0.01);
    std::printf("the rings' flux through the filter sums to the gate's within %.2e\n", columns);
    std::printf("a core and an annulus in seepage over 8 s (axisymmetric): core within %.2f %%, annulus within %.2f %% "
                "of their own fluxes; ledger %.1e of the inflow\n",
                100 * worstFine, 100 * worstCoarse, std::abs(last.ledgerResidual) / last.cumulativeInflow);
}

TEST(BedExpansion2D, TheBedStaysLaterallyUniformAsTheFrontClimbs) {
    // Problem 7's bed, 4 cells wide in 2D (12.4 mm cells): while the front climbs, every cell row
    // stays laterally uniform, wall columns included, for 10 s. Two defects broke this:
    // - the front diffusion stopped at the side walls (it stopped wherever a node held a
    //   component, which in 1D is only the filter): the wall columns expanded differently, 0.467
    //   against 0.456 behind the front at 5 s;
    // - FLIP velocities of the solid: in the stress-free sand above the front the points kept
    //   velocities of their own that the grid cannot see, and an odd-even mode across the columns
    //   of cells grew from round-off at 3 /s (spread 2e-12 at 3 s, 6e-4 at 10 s, 0.04 by 12 s). With
    //   APIC (the point takes the grid's velocity and gradient) it stays at 7e-9 (1e-14 until a
    //   state switch at 5.5 s leaves that step). The points' lateral velocities are watched as
    //   well: the porosity of stress-free points comes from the nodes, which average neighbouring
    //   columns, so the mode shows in the velocities first (FLIP: 1e-5 m/s at 9 s).
    CaseConfig c = loadVerificationCase("bed_expansion");
    c.grid.cellSize = 0.0124;
    c.column.chamberHeight = 0.0248;
    c.column.waterLevel = 0.2728;
    c.column.overflowLevel = 0.2728;
    c.column.top = 0.2852;
    c.time.end = 10.0;
    inGeometry(c, Geometry::Plane2D, 4);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<2> solver(c, *reservoir);
    while (solver.time() < c.time.end) solver.step();
    const double h = c.grid.cellSize;
    const auto& s = solver.solid();
    // the mean porosity of the solid points of every cell, row by row
    std::map<std::pair<long, long>, std::pair<double, int>> cells;
    for (std::size_t p = 0; p < s.size(); ++p) {
        auto& cell = cells[{std::lround(std::floor(s.x[p * 2 + 1] / h)), std::lround(std::floor(s.x[p * 2] / h))}];
        cell.first += s.porosity[p];
        ++cell.second;
    }
    std::map<long, std::pair<double, double>> rows;  // row -> (lowest, highest) cell mean
    double expanded = 0;
    for (const auto& [key, sum] : cells) {
        const double n = sum.first / sum.second;
        auto it = rows.find(key.first);
        if (it == rows.end()) rows[key.first] = {n, n};
        else it->second = {std::min(it->second.first, n), std::max(it->second.second, n)};
        expanded = std::max(expanded, n);
    }
    double spread = 0;
    for (const auto& [row, range] : rows) spread = std::max(spread, range.second - range.first);
    ASSERT_GT(expanded, 0.44) << "the bed has not started to expand";
    EXPECT_LT(spread, 1e-7);  // FLIP: 6e-4
    EXPECT_LT(spread, 2e-8);  // achieved 7.4e-9
    double lateral = 0;
    for (std::size_t p = 0; p < s.size(); ++p) lateral = std::max(lateral, std::abs(s.v[p * 2]));
    EXPECT_LT(lateral, 1e-9);   // m/s (FLIP: 1e-5 at 9 s)
    EXPECT_LT(lateral, 1e-11);  // achieved 2.8e-13
    std::printf("2D bed expansion at 10 s: loosest cell n = %.4f, largest lateral spread of a row's cells %.1e, "
                "fastest lateral point %.1e m/s\n", expanded, spread, lateral);
}

TEST(PressureCheckerboard, ACheckerboardOfCellPressuresDies) {
    // One pore pressure per cell and bilinear velocities (Q1-P0): a pressure alternating from cell
    // to cell in both directions pushes no interior node. A 2D geostatic column 4 cells wide, at
    // rest, gets +-100 Pa in such a checkerboard on every sand cell but the lowest and the highest
    // row. The mode must die (to a tenth within 0.3 s) instead of staying: where it meets a wall or
    // its own edge it does push, and the waves from there (180 m/s) break it up, after which drag
    // damps them. Measured: 2.5 % left after 1 ms, nothing after 30 ms. On wider columns it lasts
    // as long as those waves take to cross (16 cells: 11 % after 1 ms; 64 cells: 45 % after 1 ms,
    // 8 % after 3 ms, 0.08 % after 0.1 s), so in the interior of a very wide bed it would live
    // longer; the columns of this project are a few to a few tens of cells wide.
    CaseConfig c = loadVerificationCase("geostatic");
    inGeometry(c, Geometry::Plane2D, 4);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<2> solver(c, *reservoir);
    const double h = c.grid.cellSize, rho = c.liquid.density, g = c.gravity, zw = c.column.waterLevel;
    const double delta = 100.0;
    auto colour = [&](const double* x) {
        const long i = std::lround(std::floor(x[0] / h)), j = std::lround(std::floor(x[1] / h));
        return ((i + j) % 2 == 0) ? 1.0 : -1.0;
    };
    auto inSand = [&](const double* x) { return x[1] > c.filterLevel() + h && x[1] < c.sandTop() - h; };
    auto amplitude = [&]() {
        const auto& l = solver.liquid();
        double sum = 0;
        int n = 0;
        for (std::size_t p = 0; p < l.size(); ++p) {
            if (!inSand(&l.x[p * 2])) continue;
            sum += colour(&l.x[p * 2]) * (l.pressure[p] - rho * g * (zw - l.x[p * 2 + 1]));
            ++n;
        }
        return sum / n;
    };
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> pressure(solver.liquid().pressure.begin(), solver.liquid().pressure.end());
    const auto& l = solver.liquid();
    for (std::size_t p = 0; p < l.size(); ++p)
        if (inSand(&l.x[p * 2])) pressure[p] += delta * colour(&l.x[p * 2]);
    data.put("liquid/pore_pressure", pressure);  // x, v, mass, volume, pressure
    solver.loadState(data);
    const double start = amplitude();
    ASSERT_NEAR(start, delta, 0.05 * delta);
    while (solver.time() < 0.001) solver.step();
    const double early = amplitude();
    while (solver.time() < 0.3) solver.step();
    const double end = amplitude();
    EXPECT_LT(std::abs(end), 0.1 * start);
    EXPECT_LT(std::abs(early), 0.1 * start);  // guard: 2.5 % after 1 ms is achieved
    EXPECT_LT(std::abs(end), 1e-3);           // guard: round-off after 0.3 s
    std::printf("pressure checkerboard: amplitude %.1f Pa at the start, %.2f Pa after 1 ms, %.1e Pa after 0.3 s\n",
                start, early, end);
}
