// Mohr-Coulomb return map (materials/MohrCoulomb): every return region against a hand-computed
// closed form with f = 0 after the return, a drained triaxial compression path that fails at
// q/p' = 6 sin(phi)/(3 - sin(phi)), and the plastic volume change (zero for psi = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "materials/ConstitutiveModels.hpp"
#include "materials/LinearElastic.hpp"
#include "materials/MohrCoulomb.hpp"
#include "materials/PrincipalStress.hpp"

using namespace qs;

namespace {

constexpr Real E = 1e6, nu = 0.3;

/// f of all six orderings of the principal stresses (the full Mohr-Coulomb hexagonal cone), with
/// the principal stresses from Eigen's iterative eigen-solver (independent of the model's own).
Real maxYield(const MohrCoulomb& mc, const Real* s) {
    Eigen::Matrix3d m;
    m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues();
    const Real sorted[3] = {l(2), l(1), l(0)};
    return mc.yield(sorted);
}

/// Applies one strain increment from a diagonal stress (principal axes = x, y, z).
StressReturn apply(const MohrCoulomb& mc, Real* stress, const Real* dEps, Real* state) {
    StressPoint sp{dEps, stress, state, 1e-3};
    return mc.update(sp);
}

/// The elastic trial stress of an increment.
void trialOf(const Real* s0, const Real* dEps, Real* trial) {
    const LinearElastic el = LinearElastic::fromYoung(E, nu);
    for (int k = 0; k < 6; ++k) trial[k] = s0[k];
    el.update(trial, dEps);
}

}  // namespace

TEST(MohrCoulomb, ElasticInsideTheSurface) {
    MohrCoulomb mc(E, nu, 30, 0);
    Real s[6] = {-500, -500, -1000, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, -1e-5, 0, 0, 0};
    Real trial[6];
    trialOf(s, dEps, trial);
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Elastic);
    for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(s[k], trial[k]);
    EXPECT_EQ(state[0], 0.0);
}

TEST(MohrCoulomb, PlaneReturnMatchesTheHandComputedClosedForm) {
    // phi = 30 deg, psi = 0, c = 0: sin phi = 1/2, a = (3/2, 0, -1/2), b = (1, 0, -1).
    // D b = 2G b (trace of b is zero), a.Db = 2G (3/2 + 1/2) = 4G, dlambda = f / 4G,
    // sigma = sigma_B - dlambda 2G (1, 0, -1) = sigma_B - (f/2)(1, 0, -1).
    MohrCoulomb mc(E, nu, 30, 0);
    const Real G = E / (2 * (1 + nu));
    Real s[6] = {-100, -300, -1000, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    // f(-100, -300, -1000) = 1.5 (-100) + 0.5 (1000) = 350 > 0: plastic already; sorted order kept
    const Real f = 1.5 * -100 - 0.5 * -1000;
    ASSERT_GT(f, 0);
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Plane);
    EXPECT_NEAR(s[0], -100 - f / 2, 1e-9);
    EXPECT_NEAR(s[1], -300, 1e-9);
    EXPECT_NEAR(s[2], -1000 + f / 2, 1e-9);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-9);
    // plastic strain dlambda b = (f/4G)(1, 0, -1): deviatoric, equivalent sqrt(2/3 * 2) dlambda
    EXPECT_NEAR(state[0], std::sqrt(4.0 / 3.0) * f / (4 * G), 1e-15);
    EXPECT_NEAR(state[1], 0.0, 1e-18);
}

TEST(MohrCoulomb, PlaneReturnWithDilatancyChangesVolume) {
    // psi = 10 deg: b = (1 + s, 0, -(1 - s)), tr b = 2 s; plastic volume 2 s dlambda > 0
    MohrCoulomb mc(E, nu, 30, 10);
    const LinearElastic el = LinearElastic::fromYoung(E, nu);
    const Real ss = std::sin(10 * kPi / 180);
    Real s[6] = {-100, -300, -1000, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    const Real a[3] = {1.5, 0, -0.5}, b[3] = {1 + ss, 0, -(1 - ss)};
    Real Db[3];
    for (int i = 0; i < 3; ++i) Db[i] = el.lambda * 2 * ss + 2 * el.shear * b[i];
    const Real f = 1.5 * -100 - 0.5 * -1000;
    const Real dl = f / (a[0] * Db[0] + a[2] * Db[2]);
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Plane);
    EXPECT_NEAR(s[0], -100 - dl * Db[0], 1e-9);
    EXPECT_NEAR(s[1], -300 - dl * Db[1], 1e-9);
    EXPECT_NEAR(s[2], -1000 - dl * Db[2], 1e-9);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-9);
    EXPECT_NEAR(state[1], 2 * ss * dl, 1e-15);
    EXPECT_GT(state[1], 1e-6);  // dilation: the volume grows
}

TEST(MohrCoulomb, CompressionEdgeReturnMatchesTheHandComputedClosedForm) {
    // Trial (-100, -110, -1000): the plane return would give sigma_1 = -100 - f/2 < sigma_2, so the
    // return goes to the edge sigma_1 = sigma_2. With psi = 0 both corrections are deviatoric, so
    // the mean stress is kept: on the edge (s, s, t) with 1.5 s - 0.5 t = 0 (f = 0, c = 0) and
    // 2 s + t = 3 p: t = 3 s, s = 3 p / 5, t = 9 p / 5.
    MohrCoulomb mc(E, nu, 30, 0);
    Real s[6] = {-100, -110, -1000, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    const Real p = (-100 - 110 - 1000) / 3.0;
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Edge);
    EXPECT_NEAR(s[0], 3 * p / 5, 1e-9);
    EXPECT_NEAR(s[1], 3 * p / 5, 1e-9);
    EXPECT_NEAR(s[2], 9 * p / 5, 1e-9);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-9);
    EXPECT_NEAR(state[1], 0.0, 1e-18);
}

TEST(MohrCoulomb, ExtensionEdgeReturnMatchesTheHandComputedClosedForm) {
    // Trial (-100, -990, -1000): the plane return breaks sigma_2 >= sigma_3; edge sigma_2 = sigma_3:
    // (s, t, t) with 1.5 s - 0.5 t = 0 and s + 2 t = 3 p: t = 3 s, s = 3 p / 7, t = 9 p / 7.
    MohrCoulomb mc(E, nu, 30, 0);
    Real s[6] = {-100, -990, -1000, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    const Real p = (-100 - 990 - 1000) / 3.0;
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Edge);
    EXPECT_NEAR(s[0], 3 * p / 7, 1e-9);
    EXPECT_NEAR(s[1], 9 * p / 7, 1e-9);
    EXPECT_NEAR(s[2], 9 * p / 7, 1e-9);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-9);
}

TEST(MohrCoulomb, ApexReturnForATrialStressInTension) {
    // c = 0: the apex is the zero stress; a trial stress with tensile mean stress goes there, and
    // the stress-free flag of the liquid-state switch sees it
    MohrCoulomb mc(E, nu, 30, 0);
    Real s[6] = {50, 20, -30, 0, 0, 0}, state[2] = {0, 0};  // mean stress +13 Pa: beyond the apex
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::Apex);
    for (int k = 0; k < 6; ++k) EXPECT_EQ(s[k], 0.0);
    EXPECT_TRUE(isStressFree(s));
    // with cohesion the apex is c cot phi (tension), reached when no tension cut-off is lower
    MohrCoulomb cohesive(E, nu, 30, 0, 100, 100 / std::tan(30 * kPi / 180));
    Real t[6] = {400, 300, 200, 0, 0, 0}, st[2] = {0, 0};
    EXPECT_EQ(apply(cohesive, t, dEps, st), StressReturn::Apex);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k], 100 * std::sqrt(3.0), 1e-9);
}

TEST(MohrCoulomb, TensionCutOffWithCohesion) {
    // c = 100 Pa, sigma_t = 20 Pa: a uniaxial tensile trial stress is cut to sigma_t on the
    // Rankine plane, the other principal stresses taking the elastic coupling
    MohrCoulomb mc(E, nu, 30, 0, 100, 20);
    const LinearElastic el = LinearElastic::fromYoung(E, nu);
    Real s[6] = {80, 0, 0, 0, 0, 0}, state[2] = {0, 0};
    const Real dEps[6] = {0, 0, 0, 0, 0, 0};
    EXPECT_EQ(apply(mc, s, dEps, state), StressReturn::TensionCutoff);
    const Real dl = 60 / (el.lambda + 2 * el.shear);
    EXPECT_NEAR(s[0], 20, 1e-9);
    EXPECT_NEAR(s[1], -el.lambda * dl, 1e-9);
    EXPECT_NEAR(s[2], -el.lambda * dl, 1e-9);
    EXPECT_LE(maxYield(mc, s), 1e-9);
}

TEST(MohrCoulomb, ReturnsOfRotatedStressesKeepTheAxesAndReachTheSurface) {
    // a general (non-diagonal) trial stress: after the return f = 0 and the principal axes are
    // those of the trial stress (the stress commutes with the trial stress)
    MohrCoulomb mc(E, nu, 30, 5);
    Real s[6] = {-300, -200, -900, 150, -80, 60}, state[2] = {0, 0};
    const Real dEps[6] = {1e-4, -2e-4, 3e-4, 1e-4, 2e-4, -1e-4};
    Real trial[6];
    trialOf(s, dEps, trial);
    const StressReturn r = apply(mc, s, dEps, state);
    EXPECT_NE(r, StressReturn::Elastic);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-8);
    Eigen::Matrix3d a, b;
    a << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    b << trial[0], trial[5], trial[4], trial[5], trial[1], trial[3], trial[4], trial[3], trial[2];
    EXPECT_LT((a * b - b * a).norm(), 1e-9 * b.squaredNorm());
}

TEST(MohrCoulomb, EveryTrialStressReturnsOntoOrInsideTheCone) {
    // a sweep of random trial stresses: after any return f <= 0 for every ordering, and f = 0
    // when the trial was outside
    MohrCoulomb mc(E, nu, 30, 0);
    unsigned seed = 12345;
    auto uniform = [&]() { seed = seed * 1664525u + 1013904223u; return Real(seed) / 4294967296.0; };
    int regions[5] = {0, 0, 0, 0, 0};
    for (int trial = 0; trial < 2000; ++trial) {
        Real s[6], state[2] = {0, 0};
        for (int k = 0; k < 3; ++k) s[k] = -1000 + 1200 * uniform();
        for (int k = 3; k < 6; ++k) s[k] = -300 + 600 * uniform();
        const Real zero[6] = {0, 0, 0, 0, 0, 0};
        const Real f0 = maxYield(mc, s);
        const StressReturn r = apply(mc, s, zero, state);
        ++regions[static_cast<int>(r)];
        const Real f = maxYield(mc, s);
        // round-off of the closed-form 3 x 3 eigen-solve, twice: 1e-9 of the stress level
        const Real tol = 1e-9 * (std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]) + 1000);
        EXPECT_LE(f, tol) << "trial " << trial;
        if (f0 > 0) {
            EXPECT_NEAR(f, 0.0, tol) << "trial " << trial;
        }
    }
    // the sweep reaches all four Mohr-Coulomb regions
    EXPECT_GT(regions[static_cast<int>(StressReturn::Elastic)], 0);
    EXPECT_GT(regions[static_cast<int>(StressReturn::Plane)], 0);
    EXPECT_GT(regions[static_cast<int>(StressReturn::Edge)], 0);
    EXPECT_GT(regions[static_cast<int>(StressReturn::Apex)], 0);
}

namespace {
/// Drained triaxial compression: cell pressure p0 held on x and y, axial compression on z in
/// `steps` increments of 2e-5. Strain-driven: each axial increment, the lateral strain is iterated
/// until the lateral stresses are back at -p0. Returns the largest q seen.
Real drainedTriaxial(const MohrCoulomb& mc, Real p0, int steps, Real* s, Real* state) {
    const LinearElastic el = LinearElastic::fromYoung(E, nu);
    for (int k = 0; k < 6; ++k) s[k] = k < 3 ? -p0 : 0;
    state[0] = state[1] = 0;
    Real qMax = 0;
    for (int step = 0; step < steps; ++step) {
        Real dEps[6] = {0, 0, -2e-5, 0, 0, 0};
        Real lateral = el.lambda * 2e-5 / (2 * (el.lambda + el.shear));  // elastic guess
        for (int it = 0; it < 100; ++it) {
            dEps[0] = dEps[1] = lateral;
            Real trial[6], st[2] = {state[0], state[1]};
            for (int k = 0; k < 6; ++k) trial[k] = s[k];
            apply(mc, trial, dEps, st);
            const Real err = trial[0] + p0;
            if (std::abs(err) < 1e-11 * p0) break;
            lateral -= err / (2 * (el.lambda + el.shear));  // secant on the elastic stiffness
        }
        apply(mc, s, dEps, state);
        qMax = std::max(qMax, s[0] - s[2]);
    }
    return qMax;
}
}  // namespace

TEST(MohrCoulomb, DrainedTriaxialCompressionFailsAtTheMohrCoulombStressRatio) {
    // at failure q/p' = 6 sin phi / (3 - sin phi), and with psi = 0 no plastic volume change
    for (const Real phi : {25.0, 30.0, 35.0}) {
        MohrCoulomb mc(E, nu, phi, 0);
        const Real p0 = 1000;
        Real s[6], state[2];
        const Real qMax = drainedTriaxial(mc, p0, 400, s, state);
        const Real q = s[0] - s[2], p = -(s[0] + s[1] + s[2]) / 3;
        const Real sp = std::sin(phi * kPi / 180);
        EXPECT_NEAR(s[0], -p0, 1e-6 * p0);
        EXPECT_NEAR(q / p, 6 * sp / (3 - sp), 1e-9) << "phi = " << phi;
        EXPECT_NEAR(qMax / p, 6 * sp / (3 - sp), 1e-9) << "perfect plasticity: no overshoot";
        EXPECT_NEAR(state[1], 0.0, 1e-15) << "psi = 0: no plastic volume change";
        EXPECT_GT(state[0], 1e-3) << "the path went well into plastic flow";
    }
}

TEST(MohrCoulomb, TriaxialFlowDilatesWithPsiAboveZero) {
    // the same path with psi = 10 deg: the plastic volumetric strain grows as 2 sin(psi) dlambda,
    // i.e. d eps_v^p / d eps_q^p stays at the ratio the potential prescribes on the edge
    MohrCoulomb mc(E, nu, 30, 10);
    Real s[6], state[2];
    drainedTriaxial(mc, 1000, 400, s, state);
    EXPECT_GT(state[1], 1e-3);
    EXPECT_NEAR(maxYield(mc, s), 0.0, 1e-8);
    MohrCoulomb moreDilatant(E, nu, 30, 20);
    Real s2[6], state2[2];
    drainedTriaxial(moreDilatant, 1000, 400, s2, state2);
    EXPECT_GT(state2[1], 1.5 * state[1]);
}

TEST(ConstitutiveModels, MadeFromTheCaseByName) {
    MaterialConfig m;
    m.model = ConstitutiveModelKind::MohrCoulomb;
    m.frictionAngle = 30;
    EXPECT_EQ(makeConstitutiveModel(m)->name(), "mohr_coulomb");
    EXPECT_EQ(makeConstitutiveModel(m)->stateCount(), 2);
    m.model = ConstitutiveModelKind::LinearElastic;
    EXPECT_EQ(makeConstitutiveModel(m)->name(), "linear_elastic");
    EXPECT_NEAR(makeConstitutiveModel(m)->oedometricModulus(), 1.3462e6, 1e2);
}

TEST(MohrCoulomb, NonAssociatedReturnsWithATensionCutOffStayAdmissibleAndNeverCompact) {
    // psi = 10 deg, c = 200 Pa, sigma_t = 50 Pa: random trial stresses across every region (plane,
    // both edges, apex, the Rankine planes and their corners). After each return: f <= 0 for
    // every ordering, sigma_1 <= sigma_t, f = 0 or sigma_1 = sigma_t when the trial was outside,
    // and the plastic volume never shrinks (psi >= 0 and the Rankine flow both dilate), so no
    // multiplier came out negative
    MohrCoulomb mc(E, nu, 30, 10, 200, 50);
    unsigned seed = 2024;
    auto uniform = [&]() { seed = seed * 1664525u + 1013904223u; return Real(seed) / 4294967296.0; };
    int regions[5] = {0, 0, 0, 0, 0};
    for (int trial = 0; trial < 4000; ++trial) {
        Real s[6], state[2] = {0, 0};
        for (int k = 0; k < 3; ++k) s[k] = -1500 + 1800 * uniform();
        for (int k = 3; k < 6; ++k) s[k] = -300 + 600 * uniform();
        const Real zero[6] = {0, 0, 0, 0, 0, 0};
        Eigen::Matrix3d m;
        m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
        const Real largest0 = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues()(2);
        const bool outside = maxYield(mc, s) > 0 || largest0 > 50;
        const StressReturn r = apply(mc, s, zero, state);
        ++regions[static_cast<int>(r)];
        m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
        const Real largest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m).eigenvalues()(2);
        const Real tol = 1e-9 * (std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]) + 1500);
        const Real f = maxYield(mc, s);
        EXPECT_LE(f, tol) << "trial " << trial;
        EXPECT_LE(largest, 50 + tol) << "trial " << trial;
        if (outside) {
            EXPECT_LT(std::min(-f, 50 - largest), tol) << "trial " << trial << ": on one surface";
        } else {
            EXPECT_EQ(r, StressReturn::Elastic);
        }
        EXPECT_GE(state[1], -1e-15) << "trial " << trial << ": plastic compaction";
        EXPECT_GE(state[0], 0.0);
    }
    EXPECT_GT(regions[static_cast<int>(StressReturn::Plane)], 0);
    EXPECT_GT(regions[static_cast<int>(StressReturn::Edge)], 0);
    EXPECT_GT(regions[static_cast<int>(StressReturn::TensionCutoff)], 0);
}

TEST(PrincipalStress, TheValuesAloneAreThoseOfTheFullDecomposition) {
    // the yield check takes principalValues (a sort, the 2 x 2 closed form of plane strain, or
    // Eigen's values only); the return takes PrincipalStress. They must agree, or a point would be
    // judged on one stress and returned on another: random stresses with no shear, with the x-z
    // shear of plane strain (y anywhere in the order), and general
    std::uint32_t state = 2024;
    auto next = [&]() { state = state * 1664525u + 1013904223u; return state / 4294967296.0 - 0.5; };
    double worst = 0;
    for (int k = 0; k < 3000; ++k) {
        const int kind = k % 3;
        Real s[6];
        for (int i = 0; i < 3; ++i) s[i] = -2000 * (next() + 0.5) + (i == 1 ? 500 * next() : 0);
        s[3] = kind == 2 ? 400 * next() : 0;
        s[4] = kind >= 1 ? 800 * next() : 0;
        s[5] = kind == 2 ? 600 * next() : 0;
        Real v[3];
        principalValues(s, v);
        const PrincipalStress ps(s);
        for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(v[i] - ps.value[i]));
        EXPECT_GE(v[0], v[1]);
        EXPECT_GE(v[1], v[2]);
    }
    EXPECT_LT(worst, 1e-9);  // Pa, at stresses of kPa: round-off
}

TEST(PrincipalStress, ThePlaneDecompositionIsEigensWithoutTheTrigonometry) {
    // With shear in the x-z plane only, PrincipalStress takes the half-angle formulas of Mohr's
    // circle instead of Eigen's 3 x 3 closed form. Against Eigen's iterative solver on random plane
    // stresses, including near-isotropic ones and s_xx < s_zz (the half angle's other branch): the
    // same values, and any returned values reassembled on the same axes (the axes' signs do not
    // matter there, so the stress is compared, not the vectors)
    std::uint32_t state = 99;
    auto next = [&]() { state = state * 1664525u + 1013904223u; return state / 4294967296.0 - 0.5; };
    double worstValue = 0, worstStress = 0, worstSame = 0;
    for (int k = 0; k < 3000; ++k) {
        const double scale = k % 4 == 0 ? 1e-3 : 1.0;  // a quarter nearly isotropic in the plane
        Real s[6] = {-1000 + 800 * scale * next(), -1000 + 900 * next(), -1000 + 800 * scale * next(), 0,
                     400 * scale * next(), 0};
        const PrincipalStress ps(s);
        Eigen::Matrix3d m;
        m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);  // iterative QL, ascending
        for (int i = 0; i < 3; ++i) worstValue = std::max(worstValue, std::abs(ps.value[i] - eig.eigenvalues()(2 - i)));
        // returned values: each principal value moved by its own amount
        const Real v[3] = {ps.value[0] + 300 * next(), ps.value[1] + 300 * next(), ps.value[2] + 300 * next()};
        Real back[6];
        ps.assemble(v, back);
        const Eigen::Matrix3d ref =
            eig.eigenvectors() * Eigen::Vector3d(v[2], v[1], v[0]).asDiagonal() * eig.eigenvectors().transpose();
        const Real want[6] = {ref(0, 0), ref(1, 1), ref(2, 2), ref(1, 2), ref(0, 2), ref(0, 1)};
        for (int i = 0; i < 6; ++i) worstStress = std::max(worstStress, std::abs(back[i] - want[i]));
        EXPECT_EQ(back[3], 0.0);  // the out-of-plane shears stay exactly zero
        EXPECT_EQ(back[5], 0.0);
        // unchanged values give the stress back
        Real same[6];
        ps.assemble(ps.value, same);
        for (int i = 0; i < 6; ++i) worstSame = std::max(worstSame, std::abs(same[i] - s[i]));
    }
    std::printf("plane decomposition against Eigen's solver: values %.2e Pa, returned stresses %.2e Pa, "
                "the stress itself %.2e Pa\n", worstValue, worstStress, worstSame);
    EXPECT_LT(worstValue, 1e-9);  // Pa, at stresses of kPa: round-off
    EXPECT_LT(worstStress, 1e-9);
    EXPECT_LT(worstSame, 1e-9);
}
