// Piping: localised fluidisation in non-uniform beds (issue 23; docs/piping.md).
//   - a random bed and its mirror image give mirrored results: states, porosities, pipes, flux
//     shares (fails if a wall or a sweep direction is favoured);
//   - a loose stripe between dense sand, in the interior and against a wall: below onset each
//     zone carries its own Darcy-Forchheimer flux at every height (the head is linear in z in
//     both); raised slowly, the stripe heaves at its own i_c (within 3 %), fluidises first and
//     later (friction and the switch's wait for n_max: docs/piping.md says what is not yet
//     verified there), the dense sand stays solid until the stripe pipes, and the stripe's pipe
//     takes a larger share of the water.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"
#include "physics/Permeability.hpp"

using namespace qs;
using namespace qs::test;

namespace {

/// The cell mirrored across the column's mid-plane (2D plane grid).
Index mirrored(const SandCells& s, Index cell) {
    const Index columns = s.columns(), column = cell % columns, row = cell / columns;
    return row * columns + (columns - 1 - column);
}

}  // namespace

TEST(Piping, ARandomBedAndItsMirrorImageGiveMirroredResults) {
    const CaseRun run = runVerificationCase("random_bed");
    const CaseRun image = runVerificationCase("random_bed", [](CaseConfig& c) { c.initial.porosityField.mirror = true; });
    ASSERT_EQ(run.cells.size(), image.cells.size());
    const double width = run.config.grid.width;
    double worstPorosity = 0, worstX = 0, worstShare = 0;
    int stateDifferences = 0, fluidisedCells = 0, outputsWithPipes = 0;
    for (std::size_t k = 0; k < run.cells.size(); ++k) {
        const SandCells &a = run.cells[k], &b = image.cells[k];
        for (Index c = 0; c < static_cast<Index>(a.state.size()); ++c) {
            const Index m = mirrored(a, c);
            stateDifferences += a.state[c] != b.state[m];
            fluidisedCells += a.state[c] == CellSand::Fluidised;
            if (std::isfinite(a.porosity[c]) != std::isfinite(b.porosity[m])) ++stateDifferences;
            else if (std::isfinite(a.porosity[c]))
                worstPorosity = std::max(worstPorosity, std::abs(a.porosity[c] - b.porosity[m]));
        }
        const PipeSurvey &pa = run.pipes[k], &pb = image.pipes[k];
        ASSERT_EQ(pa.pipes.size(), pb.pipes.size()) << "at t = " << run.series[k].time;
        outputsWithPipes += !pa.pipes.empty();
        worstShare = std::max(worstShare, std::abs(pa.fluidisedFluxShare - pb.fluidisedFluxShare));
        for (const Pipe& p : pa.pipes) {
            // its mirror image: the image's pipe nearest to width - x (pipes of equal shares may be
            // listed in either order)
            const Pipe* q = &pb.pipes.front();
            for (const Pipe& r : pb.pipes)
                if (std::abs(r.x - (width - p.x)) < std::abs(q->x - (width - p.x))) q = &r;
            worstX = std::max(worstX, std::abs(p.x - (width - q->x)));
            worstShare = std::max(worstShare, std::abs(p.fluxShare - q->fluxShare));
            EXPECT_EQ(p.wall, q->wall);
            EXPECT_DOUBLE_EQ(p.height, q->height);
        }
    }
    // the test means something only if the bed fluidised unevenly and piped
    EXPECT_GT(fluidisedCells, 100);
    EXPECT_GE(outputsWithPipes, 3);
    // mirrored: every cell's state, the porosity to 1e-6, pipe positions to 1 um, shares to 1e-6
    EXPECT_EQ(stateDifferences, 0);
    EXPECT_LT(worstPorosity, 1e-6);
    EXPECT_LT(worstX, 1e-6);
    EXPECT_LT(worstShare, 1e-6);
    // guards near what is achieved (round-off only: 3.3e-13 in porosity over 4 s)
    EXPECT_LT(worstPorosity, 1e-10);
    EXPECT_LT(worstShare, 1e-10);
    std::printf("random bed and its mirror over %.1f s: %d state differences in %d fluidised cell-outputs, porosity "
                "within %.1e, pipe x within %.1e m, flux shares within %.1e (%d outputs with pipes)\n",
                run.series.back().time, stateDifferences, fluidisedCells, worstPorosity, worstX, worstShare,
                outputsWithPipes);
}

TEST(Piping, AUniformBedUnderTheSameHeadStaysLaterallyUniformAndDoesNotPipe) {
    QS_SEMI_IMPLICIT_ONLY();  // explicit: the random bed's mirror test pipes
    // the random bed's case with standard deviation 0: every row of cells stays in one state
    // and at one porosity, and no pipe is found, while the bed fluidises from the filter
    const CaseRun run = runVerificationCase("random_bed", [](CaseConfig& c) { c.initial.porosityField.enabled = false; });
    double worstSpread = 0;
    int mixedRows = 0, fluidisedCells = 0;
    std::size_t pipes = 0;
    for (std::size_t k = 0; k < run.cells.size(); ++k) {
        const SandCells& cells = run.cells[k];
        pipes += run.pipes[k].pipes.size();
        for (Index row = 0; row < cells.rows(); ++row) {
            double lo = 1, hi = 0;
            bool mixed = false;
            for (Index col = 0; col < cells.columns(); ++col) {
                const Index c = cells.cell(col, row);
                mixed |= cells.state[c] != cells.state[cells.cell(0, row)];
                fluidisedCells += cells.state[c] == CellSand::Fluidised;
                if (std::isfinite(cells.porosity[c])) {
                    lo = std::min(lo, cells.porosity[c]);
                    hi = std::max(hi, cells.porosity[c]);
                }
            }
            mixedRows += mixed;
            // the top sand row may be partly filled: its porosity is the corrected one, still uniform
            if (hi >= lo) worstSpread = std::max(worstSpread, hi - lo);
        }
    }
    EXPECT_GT(fluidisedCells, 100);
    EXPECT_EQ(pipes, 0u);
    EXPECT_EQ(mixedRows, 0);
    EXPECT_LT(worstSpread, 1e-6);
    EXPECT_LT(worstSpread, 1e-10);  // guard: round-off, 1.6e-13 achieved
    std::printf("uniform bed over %.1f s: %d fluidised cell-outputs, %zu pipes, %d rows of mixed state, lateral "
                "porosity spread %.1e\n",
                run.series.back().time, fluidisedCells, pipes, mixedRows, worstSpread);
}

namespace {

struct StripeRun {
    CaseRun run;
    double from = 0, to = 0;  ///< m, the stripe's x range
    int sides = 2;            ///< sides of the stripe against dense sand (1 at a wall)
};

StripeRun runStripe(bool atWall) {
    StripeRun s;
    s.run = runVerificationCase("loose_stripe", [&](CaseConfig& c) {
        if (atWall) {
            auto& zone = c.layers.at(0).zones.at(0);
            zone.x = HorizontalRange{c.grid.width - 0.0186, c.grid.width};
            // the "loose" monitors follow the stripe to its middle node, one cell from the wall
            for (auto& m : c.monitors)
                if (m.name.rfind("loose", 0) == 0) m.x = HorizontalRange{c.grid.width - 0.0140, c.grid.width - 0.0046};
        }
    });
    const auto& zone = s.run.config.layers.at(0).zones.at(0);
    s.from = zone.x.from;
    s.to = zone.x.to;
    s.sides = atWall ? 1 : 2;
    return s;
}

double criticalGradient(const MaterialConfig& m, const CaseConfig& c) {
    return (1 - m.porosity) * (m.grainDensity - c.liquid.density) / c.liquid.density;
}

/// The Darcy-Forchheimer filter velocity of a material at gradient i (the closed form).
double ownFlux(const CaseConfig& c, const MaterialConfig& m, double i) {
    const auto law = PermeabilityLaw::from(m);
    return closed::darcyForchheimerFlux(i, law.kappa(m.porosity), law.ergunFactor(m.porosity), c.liquid.density,
                                        c.gravity, c.liquid.viscosity);
}

/// The gradient at which shear on its sides can no longer hold the stripe as a block
/// (docs/piping.md, "The stripe's onset, derived"): (i - i_cs) b = lambda (i_cd - i),
/// lambda = sides tan(phi) H / (2 b), with the most shear a vertical plane in the dense sand can
/// carry, tan(phi) sigma'_v. A slice of the stripe's top of height z lifts when the same balance
/// holds with z for H, so the top heaves just past i_cs; the whole stripe, from the filter up,
/// lifts here. A pipe rises from the filter, so this is its onset. Plane strain only.
double blockBound(const StripeRun& s) {
    const CaseConfig& c = s.run.config;
    const auto& dense = c.material("dense");
    const auto& loose = c.material("loose");
    const double phi = dense.frictionAngle * kPi / 180;
    const double H = c.layers.at(0).thickness, b = s.to - s.from;
    const double lambda = s.sides * std::tan(phi) * H / (2 * b);
    return (criticalGradient(loose, c) + lambda * criticalGradient(dense, c)) / (1 + lambda);
}

/// The whole bed's critical gradient between smooth walls: the width-weighted mean of the zones'.
double bedCriticalGradient(const StripeRun& s) {
    const CaseConfig& c = s.run.config;
    const double b = s.to - s.from, W = c.grid.width;
    return (b * criticalGradient(c.material("loose"), c) + (W - b) * criticalGradient(c.material("dense"), c)) / W;
}

void checkStripe(const StripeRun& s, const char* where) {
    const CaseRun& run = s.run;
    const CaseConfig& c = run.config;
    const double H = c.layers.at(0).thickness, overflow = *c.column.overflowLevel;
    const auto& dense = c.material("dense");
    const auto& loose = c.material("loose");
    auto gradientAt = [&](std::size_t k) { return (run.series[k].reservoirHead - overflow) / H; };
    auto inStripe = [&](const SandCells& cells, Index cell) {  // a cell, or a column of cells
        const double x = (cell % cells.columns() + 0.5) * cells.h;
        return x > s.from && x < s.to;
    };

    // 1. Below onset (i = 0.90 from 1.5 s to 3 s): each zone's own Darcy-Forchheimer flux at each
    //    of three heights, so the head is linear in z in both; the stripe's share of the water
    //    crossing the filter as the grid carries it: the nodes on the stripe's edges hold the mean
    //    of the two zones' filter velocities (linear hats sample the step there), and a column's
    //    flux is the mean over its lower nodes
    const double i0 = 0.90;
    const double qDense = ownFlux(c, dense, i0), qLoose = ownFlux(c, loose, i0);
    const SandCells& grid = run.cells.front();
    const Index columns = grid.columns();
    auto nodeFlux = [&](Index node) {
        const double x = node * grid.h;
        const bool edge = std::abs(x - s.from) < 1e-9 || std::abs(x - s.to) < 1e-9;
        const bool wall = node == 0 || node == columns;
        if (edge && !wall) return 0.5 * (qDense + qLoose);
        return (x > s.from - 1e-9 && x < s.to + 1e-9) ? qLoose : qDense;
    };
    double stripeExpected = 0, allExpected = 0;
    for (Index col = 0; col < columns; ++col) {
        const double q = 0.5 * (nodeFlux(col) + nodeFlux(col + 1));
        allExpected += q;
        if (inStripe(grid, col)) stripeExpected += q;
    }
    const double shareBefore = stripeExpected / allExpected;
    auto stripeShare = [&](std::size_t k) {
        const SandCells& cells = run.cells[k];
        double stripe = 0, all = 0;
        for (Index col = 0; col < columns; ++col) {
            all += cells.baseFlux[col];
            if (inStripe(cells, col)) stripe += cells.baseFlux[col];
        }
        return stripe / all;
    };
    double worst = 0, worstShare = 0;
    for (std::size_t k = 0; k < run.series.size(); ++k) {
        const double t = run.series[k].time;
        if (t < 1.5 || t > 3.0) continue;
        const auto& q = run.series[k].monitorFlux;  // dense/loose at low, mid, high
        for (int level = 0; level < 3; ++level) {
            worst = std::max(worst, std::abs(q.at(2 * level) / qDense - 1));
            worst = std::max(worst, std::abs(q.at(2 * level + 1) / qLoose - 1));
        }
        worstShare = std::max(worstShare, std::abs(stripeShare(k) / shareBefore - 1));
    }
    EXPECT_LT(worst, 0.01) << where;
    EXPECT_LT(worstShare, 0.03) << where;
    // guards near what is achieved: 0.37 % and 1.7 %
    EXPECT_LT(worst, 0.005) << where;
    EXPECT_LT(worstShare, 0.022) << where;

    // 2. Raised in steps of 0.01 to 1.10 and held there, below the dense sand's i_c: the first
    //    fluidised cells are the stripe's, on the filter (it lifts off it), and the dense sand stays
    //    solid until the stripe has piped (then the pipe spreads into it)
    std::size_t onset = run.series.size(), piped = run.series.size();
    int denseFluidised = 0;
    Index lowestRow = -1, highestRow = -1;
    for (std::size_t k = 0; k < run.series.size() && piped == run.series.size(); ++k) {
        const SandCells& cells = run.cells[k];
        for (Index cell = 0; cell < static_cast<Index>(cells.state.size()); ++cell) {
            if (cells.state[cell] != CellSand::Fluidised) continue;
            if (onset == run.series.size() || onset == k) {
                onset = k;
                const Index row = cell / cells.columns();
                lowestRow = lowestRow < 0 ? row : std::min(lowestRow, row);
                highestRow = std::max(highestRow, row);
            }
            if (!inStripe(cells, cell)) ++denseFluidised;
        }
        if (!run.pipes[k].pipes.empty()) piped = k;
    }
    EXPECT_EQ(denseFluidised, 0) << where << ": dense cells fluidised before the stripe piped";
    ASSERT_LT(onset, run.series.size()) << where << ": the stripe never fluidised";
    ASSERT_LT(piped, run.series.size()) << where << ": the stripe never piped";
    const double iOnset = gradientAt(onset), iBlock = blockBound(s), iBed = bedCriticalGradient(s);
    const double iOwn = criticalGradient(loose, c), iDense = criticalGradient(dense, c);
    // friction with the dense sand holds its body past its own i_c: the stripe fluidises from the
    // filter up when the block lifts, within 3 % of the block's bound, the step's upper end taken
    // (achieved +2.0 % interior, -0.1 % wall; docs/piping.md). Below the bound, the wait for n_max
    // under a step held 0.5 s and the edge nodes' blend put it at most a step or two late
    EXPECT_GT(iOnset, iOwn) << where;
    EXPECT_LT(std::abs(iOnset / iBlock - 1), 0.03) << where;
    EXPECT_LT(iOnset, iDense) << where;  // and before the dense sand's own i_c
    // it lifts off the filter: the first fluidised cells stand on it (rows 4 to 4 both ways)
    EXPECT_EQ(lowestRow, run.cells[onset].baseRow) << where;
    // friction, not the whole bed lifting: the bed's mean i_c is the ceiling for the whole bed
    // lifting between smooth walls, so a stripe that fluidises at a step whose upper end lies
    // below it did so on its own. Against the wall i_block lies well below it (1.0613 against
    // 1.0797), and the onset must be there: (1.05, 1.06]. In the interior the two coincide
    // (1.0789 against 1.0797) and the 3 % check above is all the test can say
    if (s.sides == 1) {
        ASSERT_GT(iBed - iBlock, 0.01) << where << ": this stripe cannot tell friction from the bed lifting";
        EXPECT_LT(iOnset, iBed) << where;
        EXPECT_LT(std::abs(iOnset - iBlock), std::abs(iOnset - iBed)) << where;
    }

    // 2b. Its heave: the stripe's top rising against the dense sand's, the lab's criterion. Over
    //     each hold, the rise of the stripe's mean surface less the dense sand's; the stripe heaves
    //     when it exceeds 5 um, about 15 times the elastic swelling one step of 0.01 causes
    //     (0.01 gamma_w H / 2 over E_oed, times H: 0.3 um). Its top carries no overburden, so no
    //     friction holds it: it heaves at its own i_c
    // the mean sand surface over the stripe's columns and over the dense sand's, at output k
    auto tops = [&](std::size_t k) {
        const SandCells& cells = run.cells[k];
        double stripe = 0, dense = 0;
        int ns = 0, nd = 0;
        for (Index col = 0; col < cells.columns(); ++col) {
            if (inStripe(cells, col)) { stripe += cells.surface[col]; ++ns; }
            else { dense += cells.surface[col]; ++nd; }
        }
        return std::make_pair(stripe / ns, dense / nd);
    };
    auto relativeTop = [&](std::size_t k) { const auto t = tops(k); return t.first - t.second; };
    auto denseTop = [&](std::size_t k) { return tops(k).second; };
    double iHeave = 0, iHeld = 0, heaveRise = 0, denseRise = 0;
    for (std::size_t first = 0; first < run.series.size();) {
        std::size_t last = first;
        while (last + 1 < run.series.size() && run.series[last + 1].reservoirHead == run.series[first].reservoirHead) ++last;
        if (run.series[first].time >= 3.0 && last > first) {
            const double rise = relativeTop(last) - relativeTop(first);
            if (rise > 5e-6) {
                iHeave = gradientAt(first);
                heaveRise = rise;
                denseRise = denseTop(last) - denseTop(first);
                break;
            }
            iHeld = gradientAt(first);
        }
        first = last + 1;
    }
    ASSERT_GT(iHeave, 0) << where << ": the stripe never heaved";
    EXPECT_LT(std::abs(iHeave / iOwn - 1), 0.03) << where;
    EXPECT_LT(iHeld, iOwn) << where;      // it held at the step below its own i_c
    EXPECT_LT(denseRise, 5e-6) << where;  // the dense sand did not heave with it
    EXPECT_LT(iHeave, iOnset) << where;   // it heaves before the switch sees it fluidised

    // 3. The pipe: where the stripe is, interior or at the wall; its share of the water rises
    const Pipe& pipe = run.pipes[piped].pipes.front();
    EXPECT_GT(pipe.x, s.from) << where;
    EXPECT_LT(pipe.x, s.to) << where;
    EXPECT_EQ(pipe.wall, s.sides == 1) << where;
    double shareAfter = 0;
    for (std::size_t k = piped; k < run.series.size() && run.series[k].time <= run.series[piped].time + 1.0; ++k)
        shareAfter = std::max(shareAfter, stripeShare(k));
    EXPECT_GT(shareAfter, 1.2 * shareBefore) << where;  // 1.31 (interior) and 1.52 (wall) achieved
    const double b = s.to - s.from, W = c.grid.width;
    std::printf("loose stripe (%s): below onset each zone within %.2f %% of its own flux (dense %.3e, loose %.3e m/s), "
                "stripe's share within %.2f %% of %.3f (the true share %.3f); held at i = %.2f, heaves at i = %.2f (%.1f um in the "
                "hold, the dense sand %.1f um: %+.2f %% of its own i_c); first fluidised at i = %.2f (t = %.2f s, "
                "rows %lld to %lld), own i_c %.3f, dense i_c %.3f, the bed's %.4f, the block's bound %.4f; piped at t = "
                "%.2f s, share %.3f = %.2f x before\n",
                where, 100 * worst, qDense, qLoose, 100 * worstShare, shareBefore,
                qLoose * b / (qLoose * b + qDense * (W - b)), iHeld, iHeave, 1e6 * heaveRise, 1e6 * denseRise,
                100 * (iHeave / iOwn - 1), iOnset, run.series[onset].time,
                static_cast<long long>(lowestRow), static_cast<long long>(highestRow), iOwn, iDense, iBed, iBlock,
                run.series[piped].time, shareAfter, shareAfter / shareBefore);
}

}  // namespace

TEST(Piping, ALooseStripeInTheInteriorFluidisesFirstAndMakesAnInteriorPipe) {
    QS_SEMI_IMPLICIT_ONLY();
    checkStripe(runStripe(false), "interior");
}

TEST(Piping, ALooseStripeAgainstTheWallFluidisesFirstAndMakesAWallPipe) {
    QS_SEMI_IMPLICIT_ONLY();
    checkStripe(runStripe(true), "wall");
}

namespace {

/// The loose stripe made small enough to refine (docs/piping.md, "Convergence"): 55.8 mm wide and
/// tall, the stripe 18.6 mm wide in the middle, a chamber and free water 18.6 mm each, so that
/// every edge lies on a cell face at 9.3, 6.2 and 4.65 mm. The head rises at 0.02 per second from
/// i = 1.04; the onset is the time the first cell fluidises, read as a gradient.
struct StripeOnset {
    double gradient = 0, block = 0, bed = 0, own = 0;
    bool dense = false;  ///< a dense cell fluidised first
};

/// The small stripe's case on cells of h.
CaseConfig smallStripe(double h) {
    CaseConfig c = loadVerificationCase("loose_stripe");
    const double u = 0.0186;
    c.grid.cellSize = h;
    c.grid.width = 3 * u;
    c.grid.crossSectionArea = c.grid.width * c.grid.width;
    c.column.chamberHeight = u;
    c.layers.at(0).thickness = 3 * u;
    c.layers.at(0).zones.at(0).x = HorizontalRange{u, 2 * u};
    c.column.waterLevel = 5 * u;
    c.column.overflowLevel = 5 * u;
    c.column.top = 6 * u;
    const double H = 3 * u, over = 5 * u;
    c.reservoir.headSchedule = {{0.0, over},           {1.0, over + 0.90 * H}, {1.5, over + 0.90 * H},
                                {2.0, over + 1.04 * H}, {5.0, over + 1.10 * H}};
    c.time.end = 5.0;
    c.time.outputInterval = 0.01;
    c.monitors.clear();
    return c;
}

StripeOnset stripeOnsetAt(double h) {
    StripeOnset out;
    // watched to the first fluidised cell: the pipe that follows blows the bed out over the rim
    // (4.65 mm cells, semi-implicit: sand carried out from 4.68 s, the water below the rim at 4.87 s)
    const CaseRun run = runConfigUntil(smallStripe(h), [](const SandCells& cells) {
        return std::find(cells.state.begin(), cells.state.end(), CellSand::Fluidised) != cells.state.end();
    });
    const CaseConfig& c = run.config;
    const double H = c.layers.at(0).thickness, over = *c.column.overflowLevel;
    for (std::size_t k = 0; k < run.cells.size(); ++k) {
        const SandCells& cells = run.cells[k];
        bool any = false;
        for (Index cell = 0; cell < static_cast<Index>(cells.state.size()); ++cell) {
            if (cells.state[cell] != CellSand::Fluidised) continue;
            const double x = (cell % cells.columns() + 0.5) * cells.h;
            any = true;
            out.dense |= x < 0.0186 || x > 0.0372;
        }
        if (any) {
            out.gradient = (run.series[k].reservoirHead - over) / H;
            break;
        }
    }
    StripeRun s;
    s.run = run;
    s.from = 0.0186;
    s.to = 0.0372;
    out.block = blockBound(s);
    out.bed = bedCriticalGradient(s);
    out.own = criticalGradient(c.material("loose"), c);
    return out;
}

}  // namespace

TEST(PipingConvergence, TheLooseStripesOnsetAtThreeCellSizes) {
    // The grid convergence of the onset is the continuum's, not the time scheme's: it runs with the
    // semi-implicit step (issue 42 asks convergence of it), where 4.65 mm cells cost a sixth of
    // the explicit step's (explicit: 162 s and 140 s of CI's 45 minutes).
    QS_SEMI_IMPLICIT_ONLY();
    // the onset falls as the cells shrink, each refinement moving it less, towards the block's
    // friction bound (docs/piping.md): within 3 % of it on every grid, the finest within 1.5 %
    // (achieved +2.6 %, -0.1 %, -0.7 %), and well above the stripe's own i_c (7.4 % below)
    const StripeOnset coarse = stripeOnsetAt(0.0093), middle = stripeOnsetAt(0.0062), fine = stripeOnsetAt(0.00465);
    const double own = fine.own;  // the loose sand's i_c
    for (const StripeOnset* o : {&coarse, &middle, &fine}) {
        EXPECT_GT(o->gradient, own) << "the stripe never fluidised, or below its own i_c";
        EXPECT_FALSE(o->dense) << "a dense cell fluidised first";
    }
    EXPECT_LT(middle.gradient, coarse.gradient);
    EXPECT_LT(fine.gradient, middle.gradient);
    EXPECT_LT(middle.gradient - fine.gradient, 0.5 * (coarse.gradient - middle.gradient));
    for (const StripeOnset* o : {&coarse, &middle, &fine}) EXPECT_LT(std::abs(o->gradient / o->block - 1), 0.03);
    EXPECT_LT(std::abs(fine.gradient / fine.block - 1), 0.015);  // guard
    std::printf("stripe onset: %.4f at 9.3 mm, %.4f at 6.2 mm, %.4f at 4.65 mm; own i_c %.4f, the bed's %.4f, the "
                "block's bound %.4f\n",
                coarse.gradient, middle.gradient, fine.gradient, own, fine.bed, fine.block);
}

TEST(PipingConvergence, TheFirstPipeOfOneRandomBedAtTwoCellSizes) {
    QS_SEMI_IMPLICIT_ONLY();  // as above
    // cases/verification/random_bed (seed 3, correlation length 10 mm) at 9.3 and 6.2 mm: the
    // field is the same function of position, sampled by more points. The bed's gradient when the
    // first pipe forms agrees within 3 %, as the onset criteria of the other problems do
    struct FirstPipe { double time = -1, gradient = 0, x = 0; bool wall = false; };
    auto firstPipe = [](double h) {
        CaseConfig config = loadVerificationCase("random_bed");
        config.grid.cellSize = h;
        config.time.end = 5.0;
        // watched to the first pipe and no further (at 3.25 s on 9.3 mm, 1.75 s on 6.2 mm)
        const CaseRun run = runConfigWhile(config, [](const CaseRun& r) {
            return !r.pipes.empty() && !r.pipes.back().pipes.empty();
        });
        FirstPipe f;
        for (std::size_t k = 0; k < run.pipes.size(); ++k) {
            if (run.pipes[k].pipes.empty()) continue;
            const Pipe& p = run.pipes[k].pipes.front();
            f = FirstPipe{run.series[k].time, run.series[k].gradient, p.x, p.wall};
            break;
        }
        return f;
    };
    const FirstPipe coarse = firstPipe(0.0093), fine = firstPipe(0.0062);
    ASSERT_GT(coarse.time, 0) << "no pipe on 9.3 mm cells";
    ASSERT_GT(fine.time, 0) << "no pipe on 6.2 mm cells";
    EXPECT_LT(std::abs(fine.gradient / coarse.gradient - 1), 0.03);
    EXPECT_LT(std::abs(fine.gradient / coarse.gradient - 1), 0.015);  // guard: +0.78 % achieved
    std::printf("first pipe of the random bed: 9.3 mm at t = %.2f s, i = %.4f, x = %.1f mm%s; 6.2 mm at t = %.2f s, "
                "i = %.4f, x = %.1f mm%s (%+.2f %%)\n",
                coarse.time, coarse.gradient, 1e3 * coarse.x, coarse.wall ? " (wall)" : "", fine.time, fine.gradient,
                1e3 * fine.x, fine.wall ? " (wall)" : "", 100 * (fine.gradient / coarse.gradient - 1));
}
