// Verification problem 2 (physics.md section 4): critical gradient under upward seepage.
// The head rises slowly; sigma'_v(z) = gamma_w (i_c - i) z (z from the sand top) and the base's
// effective stress vanishes at i_c = (Gs - 1)(1 - n0) = 1.026: onset within 3 %.
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"

using namespace qs;
using namespace qs::test;

TEST(CriticalGradient, BaseEffectiveStressVanishesAtTheCriticalGradient) {
    const CaseRun run = runVerificationCase("critical_gradient");
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double g = c.gravity, rhoL = c.liquid.density, gammaW = rhoL * g;
    const double ic = closed::criticalGradient(sand.grainDensity, rhoL, sand.porosity);
    ASSERT_NEAR(ic, 1.026, 5e-4);
    const double H = c.sandTop() - c.filterLevel();
    const double sBase = ic * gammaW * H;

    double onset = -1;
    bool profileChecked = false;
    for (std::size_t k = 0; k < run.series.size(); ++k) {
        const auto rows = sandRows(run.profiles[k]);
        const double i = run.series[k].gradient;
        // the profile while the gradient passes 0.5: sigma'_v = gamma_w (i_c - i) depth
        if (!profileChecked && i > 0.5) {
            for (const auto& r : rows) {
                const double depth = c.sandTop() - r.z;
                EXPECT_NEAR(-r.verticalStress, gammaW * (ic - i) * depth, 0.03 * sBase) << "z = " << r.z;
            }
            profileChecked = true;
        }
        if (onset < 0 && -rows.front().verticalStress <= 0.002 * sBase) onset = i;
    }
    ASSERT_TRUE(profileChecked);
    ASSERT_GT(onset, 0) << "the base never reached zero effective stress";
    EXPECT_NEAR(onset, ic, 0.03 * ic);
    RecordProperty("onset_gradient", std::to_string(onset));
    std::printf("critical gradient: onset at i = %.4f, closed form %.4f (%+.2f %%)\n", onset, ic,
                100 * (onset - ic) / ic);
}
