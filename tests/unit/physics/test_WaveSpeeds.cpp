// The solver's wave speeds (physics/WaveSpeeds, Eigen's generalised eigenproblem) against the
// closed forms (physics/ClosedForms, Biot's eigenvalues from trace and determinant) and physics.md's
// numbers: two implementations that must agree, so that neither checks itself.
#include "physics/WaveSpeeds.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/ClosedForms.hpp"

namespace qs {
namespace {

// physics.md section 4, parameter set P0 (E = 1 MPa, nu = 0.3, the paper's softened water)
constexpr double kRhoS = 2650, kRhoL = 998.2, kN = 0.38, kKL = 2.128e7;
const double kEoed = closed::oedometricModulus(1e6, 0.3);

TEST(MixtureWaves, AgreeWithTheClosedFormsBiotWaves) {
    for (double KL : {kKL, 2.2e9}) {        // the paper's water and real water
        for (double n : {0.3, 0.38, 0.45}) {
            const auto closedForm = closed::zeroDragWaveSpeeds(kEoed, KL, n, kRhoS, kRhoL);
            const MixtureWaves w = mixtureWaves(kEoed, KL, n, kRhoS, kRhoL);
            EXPECT_NEAR(w.fast / closedForm.fast, 1.0, 1e-12) << "K_L " << KL << ", n " << n;
            // the slow wave is the small eigenvalue: Eigen's absolute error ~ eps c_fast^2
            EXPECT_NEAR(w.slow / closedForm.slow, 1.0, 1e-9) << "K_L " << KL << ", n " << n;
        }
    }
}

TEST(MixtureWaves, ThePapersParametersGiveThePhysicsMdSpeeds) {
    // physics.md: c_fast = 186.4 m/s, slow 22.4 m/s, the skeleton's own about 29 m/s
    const MixtureWaves w = mixtureWaves(kEoed, kKL, kN, kRhoS, kRhoL);
    EXPECT_NEAR(w.fast, 186.4, 0.05);
    EXPECT_NEAR(w.slow, 22.4, 0.05);
    EXPECT_NEAR(w.skeleton, std::sqrt(kEoed / ((1 - kN) * kRhoS)), 1e-12);
    EXPECT_NEAR(w.skeleton, 28.6, 0.05);
}

TEST(MixtureWaves, FreeWaterIsSound) {
    EXPECT_NEAR(freeWaterWave(2.2e9, 1000), std::sqrt(2.2e6), 1e-9);
}

}  // namespace
}  // namespace qs
