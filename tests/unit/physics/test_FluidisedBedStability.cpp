// The linear stability of a uniformly fluidised bed (physics/FluidisedBedStability.hpp,
// physics.md section 7): the eigenproblem against its vertical quadratic and its limits, on the
// P0 sand (Kozeny-Carman, D = 0.261 mm) expanded to n = 0.452 (problem 7's expanded bed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/Constants.hpp"
#include "P0Sand.hpp"
#include "physics/FluidisedBedStability.hpp"

using namespace qs;

namespace {
closed::FluidisedBed p0Bed(double diffusivity = 0, bool viscous = true) {
    closed::FluidisedBed bed;
    bed.suspension = test::p0Sand();
    bed.porosity = 0.452;
    bed.maxPacking = 1 - 0.32;
    bed.diffusivity = diffusivity;
    bed.viscous = viscous;
    return bed;
}

const double kWavelengths[] = {0.01, 0.05, 0.1, 0.3};  // m
}  // namespace

TEST(FluidisedBedStability, TheKinematicSpeedIsKynchs) {
    // c = phi0 dq/dn of the equilibrium suspension, from the drift-flux closed form
    const closed::FluidisedBed bed = p0Bed();
    const double n = bed.porosity, dn = 1e-5;
    const double kynch = (1 - n) * (bed.suspension.equilibriumFlux(n + dn) - bed.suspension.equilibriumFlux(n - dn)) / (2 * dn);
    const auto b = bed.base();
    EXPECT_NEAR(b.kinematicSpeed, kynch, 1e-6 * kynch);
    EXPECT_NEAR(b.filterVelocity, 1.380e-3, 0.002e-3);  // problem 7's U2
    std::printf("n = 0.452: U = %.4e m/s, c = %.4e m/s, B = %.3e kg/m3/s, mu_s = %.4f Pa s, D_i = %.3e m2/s\n",
                b.filterVelocity, b.kinematicSpeed, b.dragCoefficient, b.suspensionViscosity, b.inertialDiffusivity);
}

TEST(FluidisedBedStability, TheEigenproblemMatchesTheVerticalQuadratic) {
    for (double D : {0.0, 1.7e-5})
        for (bool viscous : {true, false}) {
            const closed::FluidisedBed bed = p0Bed(D, viscous);
            for (double lambda : kWavelengths) {
                const double k = 2 * kPi / lambda;
                const auto quadratic = bed.verticalGrowth(k), eigen = bed.growth(0, k);
                EXPECT_NEAR(eigen.real(), quadratic.real(), 1e-7 * std::abs(quadratic)) << "lambda " << lambda << " D " << D;
                EXPECT_NEAR(eigen.imag(), quadratic.imag(), 1e-7 * std::abs(quadratic)) << "lambda " << lambda << " D " << D;
            }
        }
}

TEST(FluidisedBedStability, VerticalModesAreKinematicWavesGrowingByInertiaAndDampedByTheDiffusion) {
    // to the first order in the inertia: Re s = k^2 (D_i - D), -Im s / k = c
    for (double D : {0.0, 1.7e-5}) {
        const closed::FluidisedBed bed = p0Bed(D);
        const auto b = bed.base();
        for (double lambda : kWavelengths) {
            const double k = 2 * kPi / lambda;
            const auto s = bed.verticalGrowth(k);
            EXPECT_NEAR(s.real(), k * k * (b.inertialDiffusivity - D), 0.01 * k * k * (b.inertialDiffusivity + D))
                << "lambda " << lambda << " D " << D;
            // and the phase to the same order: viscosity and diffusion slow it
            const double speed = b.kinematicSpeed -
                                 4.0 / 3.0 * bed.porosity / (1 - bed.porosity) * b.suspensionViscosity * k * k *
                                     b.kinematicSpeed / b.dragCoefficient +
                                 D * k * k *
                                     (bed.suspension.grainDensity * bed.porosity * b.kinematicSpeed -
                                      bed.suspension.liquidDensity * (1 - bed.porosity) *
                                          (b.waterVelocity - b.kinematicSpeed)) /
                                     b.dragCoefficient;
            EXPECT_NEAR(-s.imag() / k, speed, 1e-5 * b.kinematicSpeed) << "lambda " << lambda;
            if (D == 0) EXPECT_GT(s.real(), 0) << "without a particle stress every vertical mode grows";
            else EXPECT_LT(s.real(), 0) << "the grid's diffusion damps it";
        }
    }
    // the finding (physics.md section 7): on 6.2 mm cells the front diffusion (7.9e-6 m2/s for
    // this sand) is some 780 times the inertia's anti-diffusion
    const auto b = p0Bed().base();
    EXPECT_NEAR(b.inertialDiffusivity, 1.0e-8, 0.05e-8);
    EXPECT_GT(7.9e-6 / b.inertialDiffusivity, 500.0);
}

TEST(FluidisedBedStability, LateralModesAreNeutralButForTheDiffusion) {
    for (double D : {0.0, 1.7e-5}) {
        const closed::FluidisedBed bed = p0Bed(D);
        for (double lambda : kWavelengths) {
            const double k = 2 * kPi / lambda;
            const auto s = bed.growth(k, 0);
            EXPECT_NEAR(s.real(), -D * k * k, 1e-9 * (1 + D * k * k)) << "lambda " << lambda;
            EXPECT_NEAR(s.imag(), 0, 1e-9) << "lambda " << lambda;
        }
    }
}

TEST(FluidisedBedStability, ObliqueModesRiseAtTheKinematicSpeedAndGrowLessThanVerticalOnes) {
    // the growth of a mode at 45 degrees to the flow, without the diffusion: its vertical
    // wavenumber's kinematic wave grows as a vertical mode of that wavenumber would, roughly
    const closed::FluidisedBed bed = p0Bed();
    const double k = 2 * kPi / 0.05;
    const auto oblique = bed.growth(k / std::sqrt(2.0), k / std::sqrt(2.0));
    const auto vertical = bed.verticalGrowth(k / std::sqrt(2.0));
    EXPECT_GT(oblique.real(), 0);
    EXPECT_LT(oblique.real(), bed.verticalGrowth(k).real());  // below the vertical mode of the whole k
    EXPECT_NEAR(-oblique.imag(), -vertical.imag(), 0.01 * std::abs(vertical.imag()));  // rises at c
    std::printf("lambda 50 mm at 45 deg: Re s = %.3e 1/s (a vertical mode of the same k_z: %.3e)\n", oblique.real(),
                vertical.real());
}
