// Verification problem 10 (physics.md section 4): conservation. Solid and liquid mass to
// round-off (liquid: initial + injected - removed), and the ledger: liquid in through the gate
// (grid flux integrated in time) minus out over the top minus stored = 0. Run on the coarse
// seepage case, which pushes many cells' worth of water through the column.
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"

using namespace qs;
using namespace qs::test;

TEST(Conservation, MassAndLiquidLedger) {
    const CaseRun run = runVerificationCase("steady_seepage_coarse");
    const auto& c = run.config;
    const double rho = c.liquid.density;
    const auto& first = run.series.front();
    const auto& last = run.series.back();
    // the run must exercise inflow and outflow: several cells' worth of water through the column
    const double cellVolume = c.grid.cellSize * c.grid.crossSectionArea;
    ASSERT_GT(last.injectedVolume, 4 * cellVolume);
    ASSERT_GT(last.cumulativeOutflow, 4 * cellVolume);
    for (const auto& s : run.series) {
        EXPECT_NEAR(s.solidMass, first.solidMass, 1e-12 * first.solidMass);
        const double expected = first.liquidMass + rho * (s.injectedVolume - s.cumulativeOutflow);
        EXPECT_NEAR(s.liquidMass, expected, 1e-12 * first.liquidMass);
        EXPECT_LE(std::abs(s.ledgerResidual), 1e-3 * std::max(s.cumulativeInflow, cellVolume))
            << "t = " << s.time;
    }
    std::printf("conservation: inflow %.4g m3, outflow %.4g m3, ledger residual %.3g m3 (%.2g of inflow)\n",
                last.cumulativeInflow, last.cumulativeOutflow, last.ledgerResidual,
                last.ledgerResidual / last.cumulativeInflow);
}
