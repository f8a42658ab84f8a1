#pragma once
// TridiagonalCholesky: the 1D column's pressure system, symmetric positive definite and
// tridiagonal (each cell couples to the cells above and below it), factorised as L D L^T by
// LAPACK's dpttrf and solved by dpttrs.
//
// Why not Eigen's SimplicialLDLT, as in 2D and 3D: a 1D column has a few dozen cells, so the
// sparse factorisation's bookkeeping (its elimination tree, the column pointers, one sparse
// triangular solve per sweep) outweighs its arithmetic. On the Deltares column's 27 cells
// dpttrf and a dpttrs take 309 ns against SimplicialLDLT's 521 (BM_Column1D); in the step 316
// against 706 ns, of about 9 us (docs/performance.md, "The semi-implicit step").
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "core/Types.hpp"

namespace qs {

class TridiagonalCholesky {
public:
    using Matrix = Eigen::SparseMatrix<double>;

    /// A's pattern: square, column-major, both triangles stored, no entry beyond the first
    /// sub- and super-diagonal (checked).
    void analyse(const Matrix& A);
    /// Factorises A's current values; false if A is not positive definite (a pivot at or below
    /// zero, or not a number).
    bool factorize(const Matrix& A);
    /// x = A^-1 b with the last factorisation (x is sized as b; b may be x).
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

private:
    Eigen::VectorXd d_;  ///< A's diagonal, then D
    Eigen::VectorXd e_;  ///< A's sub-diagonal, then L's
    std::vector<Index> diagonal_;  ///< where each column's diagonal entry sits in A's values
    Index rows_ = 0, nonZeros_ = 0;  ///< A's as analysed: factorize checks that it is given the same
};

}  // namespace qs
