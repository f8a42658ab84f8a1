#pragma once
// Principal values and axes of a symmetric 3D stress (Voigt order xx, yy, zz, yz, xz, xy), for
// returns in principal stress space: decompose, return the three values, reassemble with the same
// axes (an isotropic return does not rotate them).
//
//   PrincipalStress ps(stress);        // ps.value[0] >= ps.value[1] >= ps.value[2]
//   Real v[3] = {...};                 // returned principal values, same order
//   ps.assemble(v, stress);
//
// A stress without shear components (every 1D column, and the initial K0 states) is already
// principal: its values are only sorted, and reassembly writes the diagonal back exactly, with
// no round-off from eigenvectors.
#include <Eigen/Eigenvalues>
#include <cmath>
#include <utility>

#include "core/Types.hpp"

namespace qs {

/// The radius of Mohr's circle of the x-z plane. A plain square root: std::hypot's care for
/// overflow cost 4 % of piping2D's step, and a stress squared is far from overflowing.
inline Real mohrRadius(const Real* s) {
    const Real half = 0.5 * (s[0] - s[2]);
    return std::sqrt(half * half + s[4] * s[4]);
}

/// The principal values alone, largest first: what a yield check needs, without the axes that
/// only a return uses. A stress without shear is only sorted; one whose shear lies in the x-z
/// plane (every point of a 2D plane-strain grid, whose out-of-plane axis is y) takes the 2 x 2
/// closed form, a square root; any other, Eigen's closed form for the values only. In piping2D the
/// full decomposition of every point, elastic or not, was 26 % of the step (docs/performance.md).
inline void principalValues(const Real* s, Real* v) {
    if (s[3] == 0 && s[5] == 0) {
        const Real mean = 0.5 * (s[0] + s[2]), radius = mohrRadius(s);
        v[0] = mean + radius;
        v[1] = s[1];
        v[2] = mean - radius;
        // y lies anywhere among the in-plane pair
        if (v[1] > v[0]) std::swap(v[0], v[1]);
        if (v[2] > v[1]) std::swap(v[1], v[2]);
        return;
    }
    Eigen::Matrix3d m;
    m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(m, Eigen::EigenvaluesOnly);  // ascending
    for (int k = 0; k < 3; ++k) v[k] = eig.eigenvalues()(2 - k);
}

class PrincipalStress {
public:
    explicit PrincipalStress(const Real* s) {
        diagonal_ = s[3] == 0 && s[4] == 0 && s[5] == 0;
        if (diagonal_) {
            int order[3] = {0, 1, 2};
            // sort the three diagonal entries, largest first (a stable three-element sort)
            if (s[order[0]] < s[order[1]]) std::swap(order[0], order[1]);
            if (s[order[1]] < s[order[2]]) std::swap(order[1], order[2]);
            if (s[order[0]] < s[order[1]]) std::swap(order[0], order[1]);
            for (int k = 0; k < 3; ++k) { axis_[k] = order[k]; value[k] = s[order[k]]; }
            return;
        }
        if (s[3] == 0 && s[5] == 0) {
            inPlane(s);
            return;
        }
        Eigen::Matrix3d m;
        m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
        eig.computeDirect(m);  // closed form for 3x3: ascending eigenvalues
        for (int k = 0; k < 3; ++k) {
            value[k] = eig.eigenvalues()(2 - k);
            axes_.col(k) = eig.eigenvectors().col(2 - k);
        }
    }

    /// Writes the stress with principal values v (same order as value[]) and the original axes.
    void assemble(const Real* v, Real* s) const {
        if (diagonal_) {
            for (int k = 0; k < 3; ++k) s[axis_[k]] = v[k];
            return;
        }
        const Eigen::Matrix3d m = axes_ * Eigen::Vector3d(v[0], v[1], v[2]).asDiagonal() * axes_.transpose();
        s[0] = m(0, 0); s[1] = m(1, 1); s[2] = m(2, 2);
        s[3] = m(1, 2); s[4] = m(0, 2); s[5] = m(0, 1);
    }

    Real value[3];  ///< Pa, principal stresses, largest (least compressive) first

private:
    /// Shear in the x-z plane only (plane strain, axisymmetry): y is a principal axis, and the
    /// in-plane pair lies at the angle theta with cos 2 theta = (s_xx - s_zz) / 2r and
    /// sin 2 theta = s_xz / r (Mohr's circle, radius r). cos theta and sin theta follow from the
    /// half-angle formulas, no trigonometry: Eigen's 3 x 3 closed form (acos, sin, cos) for every
    /// yielding point was 19 % of piping2D's step once its bed fluidised (docs/performance.md).
    void inPlane(const Real* s) {
        const Real radius = mohrRadius(s);  // > 0: s_xz != 0 here
        const Real cos2 = 0.5 * (s[0] - s[2]) / radius, sin2 = s[4] / radius;
        Real c, sn;  // the larger of the two from its half-angle formula, the other from sin 2 theta
        if (cos2 >= 0) { c = std::sqrt(0.5 * (1 + cos2)); sn = sin2 / (2 * c); }
        else { sn = std::sqrt(0.5 * (1 - cos2)); c = sin2 / (2 * sn); }
        const Real mean = 0.5 * (s[0] + s[2]);
        Real v[3] = {mean + radius, s[1], mean - radius};
        Eigen::Vector3d a[3] = {{c, 0, sn}, {0, 1, 0}, {-sn, 0, c}};
        // y lies anywhere among the in-plane pair: sort, largest first
        if (v[1] > v[0]) { std::swap(v[0], v[1]); std::swap(a[0], a[1]); }
        if (v[2] > v[1]) { std::swap(v[1], v[2]); std::swap(a[1], a[2]); }
        for (int k = 0; k < 3; ++k) { value[k] = v[k]; axes_.col(k) = a[k]; }
    }

    bool diagonal_ = false;
    int axis_[3] = {0, 1, 2};  ///< diagonal case: the Voigt slot of each principal value
    Eigen::Matrix3d axes_;     ///< general case: columns are the principal directions
};

}  // namespace qs
