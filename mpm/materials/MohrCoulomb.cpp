#include "materials/MohrCoulomb.hpp"

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "materials/PrincipalStress.hpp"

namespace qs {

namespace {

constexpr Real kDegree = kPi / 180.0;

/// y = D x with the principal elastic matrix D = lambda 1 1^T + 2 G I.
inline void applyElastic(const LinearElastic& e, const Real* x, Real* y) {
    const Real tr = x[0] + x[1] + x[2];
    for (int i = 0; i < 3; ++i) y[i] = e.lambda * tr + 2 * e.shear * x[i];
}

/// x = D^-1 y.
inline void applyCompliance(const LinearElastic& e, const Real* y, Real* x) {
    const Real tr = y[0] + y[1] + y[2];
    const Real c = e.lambda / (3 * e.lambda + 2 * e.shear);
    for (int i = 0; i < 3; ++i) x[i] = (y[i] - c * tr) / (2 * e.shear);
}

inline Real dot3(const Real* a, const Real* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Order of principal values within round-off of the stress level.
inline bool ordered(Real hi, Real lo, Real scale) { return hi >= lo - 1e-12 * scale; }

}  // namespace

MohrCoulomb::MohrCoulomb(Real E, Real nu, Real phi, Real psi, Real cohesion, Real tensileStrength)
    : elastic_(LinearElastic::fromYoung(E, nu)),
      sinPhi_(std::sin(phi * kDegree)),
      sinPsi_(std::sin(psi * kDegree)),
      cosPhi_(std::cos(phi * kDegree)),
      cohesion_(cohesion),
      tensile_(tensileStrength) {
    QS_CHECK(phi > 0 && phi < 90, "Mohr-Coulomb friction angle " << phi << " deg: expected (0, 90)");
    QS_CHECK(psi >= 0 && psi <= phi, "Mohr-Coulomb dilatancy angle " << psi << " deg: expected [0, phi]");
    QS_CHECK(cohesion >= 0, "Mohr-Coulomb cohesion " << cohesion << " Pa: expected >= 0");
    apex_ = cohesion_ * cosPhi_ / sinPhi_;  // c cot phi
    QS_CHECK(tensile_ >= 0 && tensile_ <= apex_ * (1 + 1e-12),
             "Mohr-Coulomb tensile strength " << tensileStrength << " Pa: expected [0, c cot phi = " << apex_ << "]");
    if (tensile_ >= apex_ * (1 - 1e-12)) tensile_ = apex_;  // at the apex: no cut-off of its own
}

std::string MohrCoulomb::stateName(int k) const {
    return k == 0 ? "equivalent_plastic_strain" : "plastic_volumetric_strain";
}

Real MohrCoulomb::yield(const Real* s) const {
    return (1 + sinPhi_) * s[0] - (1 - sinPhi_) * s[2] - 2 * cohesion_ * cosPhi_;
}

StressReturn MohrCoulomb::returnToSurface(Real* sigma, Real* plastic) const {
    const Real trial[3] = {sigma[0], sigma[1], sigma[2]};
    const Real scale = std::abs(trial[0]) + std::abs(trial[2]) + cohesion_;
    const Real f = yield(trial);
    StressReturn kind = StressReturn::Elastic;
    if (f <= 0) {
        plastic[0] = plastic[1] = plastic[2] = 0;
        return kind;
    }
    const Real sp = sinPhi_, ss = sinPsi_, k = 2 * cohesion_ * cosPhi_;
    // normals a of the yield planes and b of the potentials, in principal space
    const Real a1[3] = {1 + sp, 0, -(1 - sp)}, b1[3] = {1 + ss, 0, -(1 - ss)};
    Real Db1[3];
    applyElastic(elastic_, b1, Db1);

    // 1. the plane
    const Real dl = f / dot3(a1, Db1);
    for (int i = 0; i < 3; ++i) sigma[i] = trial[i] - dl * Db1[i];
    kind = StressReturn::Plane;
    const bool firstPair = ordered(sigma[0], sigma[1], scale);
    const bool secondPair = ordered(sigma[1], sigma[2], scale);
    if (!firstPair || !secondPair) {
        // 2. an edge: sigma_1 = sigma_2 (triaxial compression) or sigma_2 = sigma_3 (extension),
        // both planes active, a 2 x 2 system for the two multipliers
        auto edge = [&](bool compression, Real* out) {
            const Real a2c[3] = {0, 1 + sp, -(1 - sp)}, b2c[3] = {0, 1 + ss, -(1 - ss)};
            const Real a2e[3] = {1 + sp, -(1 - sp), 0}, b2e[3] = {1 + ss, -(1 - ss), 0};
            const Real* a2 = compression ? a2c : a2e;
            const Real* b2 = compression ? b2c : b2e;
            Real Db2[3];
            applyElastic(elastic_, b2, Db2);
            const Real m11 = dot3(a1, Db1), m12 = dot3(a1, Db2), m21 = dot3(a2, Db1), m22 = dot3(a2, Db2);
            const Real r1 = f, r2 = dot3(a2, trial) - k;
            const Real det = m11 * m22 - m12 * m21;
            const Real l1 = (r1 * m22 - m12 * r2) / det, l2 = (m11 * r2 - m21 * r1) / det;
            for (int i = 0; i < 3; ++i) out[i] = trial[i] - l1 * Db1[i] - l2 * Db2[i];
            // the two equal values exactly equal (round-off would otherwise break the order)
            if (compression) out[0] = out[1] = 0.5 * (out[0] + out[1]);
            else out[1] = out[2] = 0.5 * (out[1] + out[2]);
            // along the edge line the stress runs from the apex into compression; past the apex
            // the order of the two distinct values reverses
            const bool pastApex = out[2] > out[0];
            return !pastApex && l1 >= 0 && l2 >= 0;
        };
        Real onEdge[3];
        if (!firstPair && edge(true, onEdge)) kind = StressReturn::Edge;
        else if (!secondPair && edge(false, onEdge)) kind = StressReturn::Edge;
        else kind = StressReturn::Apex;  // 3. the apex
        for (int i = 0; i < 3; ++i) sigma[i] = kind == StressReturn::Edge ? onEdge[i] : apex_;
    }
    const Real correction[3] = {trial[0] - sigma[0], trial[1] - sigma[1], trial[2] - sigma[2]};
    applyCompliance(elastic_, correction, plastic);
    return kind;
}

StressReturn MohrCoulomb::tensionReturn(Real* sigma, Real* plastic) const {
    // Rankine return: the k largest principal stresses to sigma_t, with the elastic coupling of
    // the others; the smallest k for which the others stay below sigma_t.
    const Real G2 = 2 * elastic_.shear, lam = elastic_.lambda;
    for (int k = 1; k <= 3; ++k) {
        Real r[3] = {0, 0, 0}, sum = 0;
        for (int i = 0; i < k; ++i) { r[i] = sigma[i] - tensile_; sum += r[i]; }
        // (lambda 1 1^T + 2G I)_k dl = r  (Sherman-Morrison)
        Real dl[3] = {0, 0, 0}, dlSum = 0;
        for (int i = 0; i < k; ++i) { dl[i] = (r[i] - lam * sum / (G2 + k * lam)) / G2; dlSum += dl[i]; }
        bool ok = true;
        Real next[3];
        for (int i = 0; i < 3; ++i) {
            next[i] = i < k ? tensile_ : sigma[i] - lam * dlSum;
            if (i >= k && next[i] > tensile_) ok = false;
        }
        if (ok || k == 3) {
            for (int i = 0; i < 3; ++i) { plastic[i] += dl[i]; sigma[i] = next[i]; }
            return StressReturn::TensionCutoff;
        }
    }
    return StressReturn::TensionCutoff;
}

StressReturn MohrCoulomb::update(const StressPoint& point) const {
    Real* s = point.stress;
    elastic_.update(s, point.strainIncrement);  // elastic trial stress
    // most points stay elastic: the trial's principal values decide, the axes only for a return
    Real trial[3];
    principalValues(s, trial);
    const bool tensionActive = tensile_ < apex_;
    if (yield(trial) <= 0 && (!tensionActive || trial[0] <= tensile_)) return StressReturn::Elastic;

    PrincipalStress ps(s);
    Real sigma[3] = {ps.value[0], ps.value[1], ps.value[2]};

    Real plastic[3] = {0, 0, 0};
    StressReturn kind = returnToSurface(sigma, plastic);
    if (tensionActive && sigma[0] > tensile_) {
        // alternate the two returns until both surfaces hold (the corner between them)
        for (int pass = 0; pass < 20; ++pass) {
            kind = tensionReturn(sigma, plastic);
            if (yield(sigma) <= 1e-12 * (std::abs(sigma[2]) + cohesion_)) break;
            Real more[3];
            returnToSurface(sigma, more);
            for (int i = 0; i < 3; ++i) plastic[i] += more[i];
            if (sigma[0] <= tensile_) break;
        }
    }
    ps.assemble(sigma, s);

    // state: equivalent plastic strain of the deviator, plastic volumetric strain
    const Real vol = plastic[0] + plastic[1] + plastic[2];
    Real dev2 = 0;
    for (int i = 0; i < 3; ++i) dev2 += (plastic[i] - vol / 3) * (plastic[i] - vol / 3);
    point.state[0] += std::sqrt(2.0 / 3.0 * dev2);
    point.state[1] += vol;
    return kind;
}

}  // namespace qs
