// The linear stability of a uniformly fluidised bed (physics/FluidisedBedStability.hpp,
// physics.md section 7): the eigenproblem against its vertical quadratic and its limits, on the
// P0 sand (Kozeny-Carman, D = 0.261 mm) expanded to n = 0.452 (problem 7's expanded bed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/Constants.hpp"
#include "P0Sand.hpp"
#include "physics/FluidisedBedStability.hpp"
#include "physics/ParticlePhase.hpp"

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

namespace {
/// The P0 sand's Foscolo-Gibilaro modulus at n (physics/ParticlePhase.hpp)
FoscoloGibilaro p0ElasticForce() {
    const auto s = test::p0Sand();
    return {s.law.grainSize, s.grainDensity, s.liquidDensity, s.gravity};
}
}  // namespace

TEST(FluidisedBedStability, AParticlePhaseExchangeForceEntersTheQuadraticAsKk2) {
    // the eigenproblem, which carries -K grad(phi) and +K grad(phi) in the two momentum
    // balances, against the quadratic with + K k^2, and its first order: Re s = k^2 (D_i - D - K / B)
    for (double K : {1.0, 7.4, 50.0}) {
        closed::FluidisedBed bed = p0Bed();
        bed.particleModulus = K;
        const auto b = bed.base();
        for (double lambda : kWavelengths) {
            const double k = 2 * kPi / lambda;
            const auto quadratic = bed.verticalGrowth(k), eigen = bed.growth(0, k);
            EXPECT_NEAR(eigen.real(), quadratic.real(), 1e-7 * std::abs(quadratic)) << "lambda " << lambda << " K " << K;
            EXPECT_NEAR(eigen.imag(), quadratic.imag(), 1e-7 * std::abs(quadratic)) << "lambda " << lambda << " K " << K;
            EXPECT_NEAR(quadratic.real(), k * k * (b.inertialDiffusivity - K / b.dragCoefficient),
                        0.02 * k * k * (b.inertialDiffusivity + K / b.dragCoefficient))
                << "lambda " << lambda << " K " << K;
            EXPECT_LT(quadratic.real(), 0) << "particulate: every vertical mode decays";
        }
    }
}

TEST(FluidisedBedStability, AParticlePhaseDampsLateralModesToo) {
    // the exchange force pushes the grains down the porosity's lateral gradient against the slip's
    // drag: a lateral mode decays at about K k^2 n0 phi0 / beta, where without it it is neutral
    closed::FluidisedBed bed = p0Bed();
    bed.particleModulus = 7.4;
    const auto b = bed.base();
    for (double lambda : kWavelengths) {
        const double k = 2 * kPi / lambda;
        const auto s = bed.growth(k, 0);
        const double rate = bed.particleModulus * k * k * bed.porosity * (1 - bed.porosity) / b.secantDrag;
        EXPECT_NEAR(s.real(), -rate, 0.02 * rate) << "lambda " << lambda;
    }
}

TEST(FluidisedBedStability, FoscoloGibilarosCriterionIsQuicksandsWithoutTheWatersInertia) {
    // K = n rho_s u_e^2: the vertical modes' first order, rho_s n0 c^2 + rho_L phi0 (V0 - c)^2 < K,
    // without the water's inertia is FG's c < u_e
    const FoscoloGibilaro fg = p0ElasticForce();
    const double n = 0.452;
    EXPECT_NEAR(fg.modulus(n), n * fg.grainDensity * fg.elasticWaveSpeed(n) * fg.elasticWaveSpeed(n), 1e-12);
    closed::FluidisedBed bed = p0Bed();
    bed.particleModulus = fg.modulus(n);
    const auto b = bed.base();
    std::printf("P0 at n = 0.452: K = %.3f Pa, u_e = %.4f m/s against c = %.4e m/s; K / B = %.3e m2/s\n",
                fg.modulus(n), fg.elasticWaveSpeed(n), b.kinematicSpeed, bed.particleModulus / b.dragCoefficient);
    EXPECT_GT(fg.elasticWaveSpeed(n), b.kinematicSpeed);  // FG: this sand fluidises particulately
    EXPECT_LT(bed.verticalGrowth(2 * kPi / 0.05).real(), 0);
}

namespace {
/// A bed of spheres of `d` (m) and density rho_s fluidised in water at porosity n, with
/// quicksand's drag (Kozeny-Carman and Ergun, A = 150, B = 1.75), and its FG modulus.
closed::FluidisedBed sphereBed(double d, double rhoS, double n) {
    closed::FluidisedBed bed;
    bed.suspension = test::p0Sand();
    bed.suspension.law.grainSize = d;
    bed.suspension.grainDensity = rhoS;
    bed.porosity = n;
    bed.maxPacking = 0.64;
    bed.particleModulus = FoscoloGibilaro{d, rhoS, bed.suspension.liquidDensity, bed.suspension.gravity}.modulus(n);
    return bed;
}
}  // namespace

TEST(FluidisedBedStability, FoscoloGibilaroCallLeadShotAggregativeAndFineSandParticulate) {
    // the literature's examples of the two regimes of liquid fluidisation: lead shot of 3 mm in
    // water fluidises aggregatively (Wilhelm and Kwauk 1948; FG 1984), fine sand and 1 mm glass
    // particulately. quicksand's drag and FG's modulus, at n = 0.5: the vertical mode of 50 mm
    // grows for lead and decays for the others
    struct Case { const char* name; double d, rhoS; bool aggregative; };
    for (const Case& m : {Case{"lead shot 3 mm", 3e-3, 11340, true}, Case{"glass 1 mm", 1e-3, 2500, false},
                          Case{"P0 sand 0.261 mm", 2.61e-4, 2650, false}}) {
        const closed::FluidisedBed bed = sphereBed(m.d, m.rhoS, 0.5);
        const auto b = bed.base();
        const FoscoloGibilaro fg{m.d, m.rhoS, 998.2, 9.81};
        const double s = bed.verticalGrowth(2 * kPi / 0.05).real();
        std::printf("%s at n = 0.5: U = %.4e m/s, c = %.4e m/s, u_e = %.4e m/s, K = %.2f Pa, D_i = %.3e, K/B = %.3e "
                    "m2/s; the 50 mm mode's growth %.4e 1/s\n",
                    m.name, b.filterVelocity, b.kinematicSpeed, fg.elasticWaveSpeed(0.5), bed.particleModulus,
                    b.inertialDiffusivity, bed.particleModulus / b.dragCoefficient, s);
        EXPECT_EQ(fg.elasticWaveSpeed(0.5) < b.kinematicSpeed, m.aggregative) << m.name;
        EXPECT_EQ(s > 0, m.aggregative) << m.name;
    }
}
