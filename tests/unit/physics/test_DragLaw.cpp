// The drag law's one home (physics/DragLaw.hpp) against the closed forms the tests check with
// (physics/ClosedForms.hpp, physics/DriftFlux.hpp): two implementations of Darcy-Forchheimer that
// must agree, so that neither checks itself; and the nodal coefficient the solver lumps is the
// law itself, per node.
#include "physics/DragLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "physics/ClosedForms.hpp"
#include "physics/DriftFlux.hpp"
#include "physics/FrontDiffusion.hpp"

namespace qs {
namespace {

constexpr double kMu = 8.91e-4, kRhoL = 998.2, kRhoS = 2650, kG = 9.81;

PermeabilityLaw scaledLaw(double ergunB) {
    PermeabilityLaw law;
    law.mode = PermeabilityMode::KozenyCarmanScaled;
    law.value = 1.49e-10;
    law.n0 = 0.38;
    law.B = ergunB;
    return law;
}

TEST(DragLaw, FluxAgreesWithTheClosedFormAndInvertsTheGradient) {
    const DragLaw drag{kMu, kRhoL};
    for (double B : {0.0, 1.75}) {  // pure Darcy, and with Ergun's Forchheimer term
        const PermeabilityLaw law = scaledLaw(B);
        for (double n : {0.32, 0.38, 0.45, 0.6}) {
            const double kappa = law.kappa(n), F = law.ergunFactor(n);
            for (double i : {-3.0, -0.2, 1e-6, 0.5, 1.0, 2.5, 40.0}) {
                const double q = drag.flux(kappa, F, i * kRhoL * kG);
                const double closedForm = closed::darcyForchheimerFlux(i, kappa, F, kRhoL, kG, kMu);
                EXPECT_NEAR(q / closedForm, 1.0, 1e-12) << "B " << B << ", n " << n << ", i " << i;
                EXPECT_NEAR(drag.gradient(kappa, F, q) / (i * kRhoL * kG), 1.0, 1e-12);
            }
        }
    }
}

// Q_i w = n V i(q = n w) gamma_w: the nodal coefficient, with the node's sums of one point's
// shares, is the law's drag on the water of the point's volume at the relative velocity w
TEST(DragLaw, TheNodalCoefficientIsTheLawAtTheNode) {
    const DragLaw drag{kMu, kRhoL};
    const PermeabilityLaw law = scaledLaw(1.75);
    for (double n : {0.35, 0.41, 0.5}) {
        const double kappa = law.kappa(n), F = law.ergunFactor(n), V = 2.7e-7;
        const DragLaw::Shares s = DragLaw::pointShares(kappa, F, V);
        for (double w : {-0.02, 1e-5, 3e-3, 0.1}) {
            const double Q = drag.nodal(n, s.darcy, s.forchheimer, std::abs(w));
            EXPECT_NEAR(Q * w / (n * V * drag.gradient(kappa, F, n * w)), 1.0, 1e-13) << "n " << n << ", w " << w;
        }
    }
}

// The front diffusion's equilibrium suspension (solver side) against the drift-flux closed form
// (test side), and physics/FrontDiffusion.hpp's numbers for the paper's sand
TEST(DragLaw, TheEquilibriumSuspensionAgreesWithTheDriftFluxClosedForm) {
    const DragLaw drag{kMu, kRhoL};
    closed::SuspensionFlux closedForm;
    closedForm.law = scaledLaw(1.75);
    closedForm.grainDensity = kRhoS;
    closedForm.liquidDensity = kRhoL;
    closedForm.gravity = kG;
    closedForm.viscosity = kMu;
    for (double n : {0.36, 0.41, 0.5, 0.7})
        EXPECT_NEAR(equilibriumSuspensionFlux(drag, closedForm.law, kRhoS, kG, n) / closedForm.equilibriumFlux(n), 1.0,
                    1e-12)
            << "n " << n;
    // D = alpha h c, c = (1 - n) dq/dn = 1.1317e-2 m/s at n_max = 0.41 (by hand: the same
    // quadratic in Python, central differences of 1e-4): 1.6976e-5 m2/s on 6 mm cells
    const double D = frontDiffusivity(drag, closedForm.law, kRhoS, kG, 0.41, 0.006);
    EXPECT_NEAR(D / (kFrontDiffusionAlpha * 0.006), 1.1317e-2, 1e-6);
    EXPECT_NEAR(D, 1.6976e-5, 1e-9);
}

}  // namespace
}  // namespace qs
