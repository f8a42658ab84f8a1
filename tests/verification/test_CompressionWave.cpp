// Verification problem 5 (physics.md section 4), undrained part: a step load on a nearly
// impermeable column (k = 1e-9 m/s) sends a compression wave down at
// c_u = sqrt((E_oed + K_L/n) / rho_sat) = 168.4 m/s. The front's arrival at a cell row is the
// moment its pore pressure passes half the plateau u0 = q m_v / (m_v + n/K_L) (interpolated
// between outputs). Arrival within 5 %: both the time at mid-depth and the speed between two
// depths (which cancels the front's half-width at the loaded surface).
#include <gtest/gtest.h>

#include <cmath>

#include "VerificationCase.hpp"
#include "physics/ClosedForms.hpp"

using namespace qs;
using namespace qs::test;

namespace {

/// Time at which the row nearest to z first passes `level` (linear between outputs), or -1.
double arrival(const CaseRun& run, double z, double level) {
    for (std::size_t k = 1; k < run.series.size(); ++k) {
        auto at = [&](std::size_t j) {
            double best = 1e9, p = 0;
            for (const auto& r : run.profiles[j])
                if (std::abs(r.z - z) < best) { best = std::abs(r.z - z); p = r.porePressure; }
            return p;
        };
        const double a = at(k - 1), b = at(k);
        if (a < level && b >= level) {
            const double w = (level - a) / (b - a);
            return run.series[k - 1].time + w * (run.series[k].time - run.series[k - 1].time);
        }
    }
    return -1;
}

}  // namespace

TEST(CompressionWave, UndrainedWaveTravelsAtTheUndrainedSpeed) {
    const CaseRun run = runVerificationCase("undrained_wave");
    const auto& c = run.config;
    const auto& sand = c.material("sand");
    const double Eoed = closed::oedometricModulus(sand.youngsModulus, sand.poissonRatio);
    const double cu = closed::undrainedWaveSpeed(Eoed, c.liquid.bulkModulus, sand.porosity,
                                                 sand.grainDensity, c.liquid.density);
    ASSERT_NEAR(cu, 168.4, 0.05);
    const double u0 = c.loads.surcharge * closed::undrainedPressureRatio(Eoed, sand.porosity, c.liquid.bulkModulus);
    const double top = c.sandTop();
    const double zShallow = top - 0.047, zMid = top - 0.093, zDeep = top - 0.139;
    const double tShallow = arrival(run, zShallow, 0.5 * u0), tMid = arrival(run, zMid, 0.5 * u0),
                 tDeep = arrival(run, zDeep, 0.5 * u0);
    ASSERT_GT(tShallow, 0);
    ASSERT_GT(tMid, 0);
    ASSERT_GT(tDeep, 0);
    const double expectedMid = (top - zMid) / cu;
    EXPECT_NEAR(tMid, expectedMid, 0.05 * expectedMid);
    const double speed = (zShallow - zDeep) / (tDeep - tShallow);
    EXPECT_NEAR(speed, cu, 0.05 * cu);
    std::printf("undrained wave: arrival at 93 mm depth %.4e s vs %.4e s (%+.2f %%); speed %.1f m/s vs %.1f (%+.2f %%)\n",
                tMid, expectedMid, 100 * (tMid / expectedMid - 1), speed, cu, 100 * (speed / cu - 1));
}
