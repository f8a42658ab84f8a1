#pragma once
// Full 3D symmetric tensors in Voigt order (xx, yy, zz, yz, xz, xy) and the embedding of a
// D-dimensional grid's strain increment into them. Grid axes map to 3D axes as
//   1D: (z),  2D: (x, z) with y out of plane,  3D: (x, y, z),
// so the vertical grid axis is always 3D z and a 1D column is an oedometer.
#include <Eigen/Eigenvalues>
#include <algorithm>

#include "core/Types.hpp"

namespace qs {

/// The 3D axis of grid axis a in a D-dimensional grid.
template <int D>
constexpr int axis3(int a) { return D == 1 ? 2 : (D == 2 ? (a == 0 ? 0 : 2) : a); }

/// Voigt slot of the symmetric pair (i, j) of 3D axes.
constexpr int voigt(int i, int j) {
    if (i == j) return i;
    const int s = i + j;  // (1,2) -> 3 yz, (0,2) -> 4 xz, (0,1) -> 5 xy
    return s == 3 ? 3 : (s == 2 ? 4 : 5);
}

/// Returns the stress to principal values <= 0 (the sand takes no tension: physics.md,
/// tension cut-off). Returns true if anything was cut.
inline bool tensionCutoff(Real* s) {
    const bool diagonal = s[3] == 0 && s[4] == 0 && s[5] == 0;
    if (diagonal) {
        bool cut = false;
        for (int i = 0; i < 3; ++i)
            if (s[i] > 0) { s[i] = 0; cut = true; }
        return cut;
    }
    // Plainly compressive, nothing to cut: -s positive definite (Sylvester: its leading minors
    // all > 0). Most points of a loaded column are, and skip the eigen-solve. A state on the
    // edge (a minor of 0) goes to the eigen-solve, as before.
    const Real a = -s[0], b = -s[1], c = -s[2], yz = -s[3], xz = -s[4], xy = -s[5];
    const Real minor2 = a * b - xy * xy;
    const Real det = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
    if (a > 0 && minor2 > 0 && det > 0) return false;
    Eigen::Matrix3d m;
    m << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
    Eigen::Vector3d l = eig.eigenvalues();
    if (l.maxCoeff() <= 0) return false;
    l = l.cwiseMin(0.0);
    m = eig.eigenvectors() * l.asDiagonal() * eig.eigenvectors().transpose();
    s[0] = m(0, 0); s[1] = m(1, 1); s[2] = m(2, 2);
    s[3] = m(1, 2); s[4] = m(0, 2); s[5] = m(0, 1);
    return true;
}

}  // namespace qs
