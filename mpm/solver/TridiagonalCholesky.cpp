#include "solver/TridiagonalCholesky.hpp"

#include <algorithm>

#include "core/Error.hpp"

// LAPACK (Fortran calling convention: every argument by address; no character arguments here)
extern "C" {
void dpttrf_(const int* n, double* d, double* e, int* info);
void dpttrs_(const int* n, const int* nrhs, const double* d, const double* e, double* b, const int* ldb, int* info);
}

namespace qs {

void TridiagonalCholesky::analyse(const Matrix& A) {
    QS_CHECK(A.rows() == A.cols() && A.isCompressed(),
             "TridiagonalCholesky: a compressed square matrix expected, got " << A.rows() << " x " << A.cols());
    const Index n = A.rows();
    diagonal_.assign(n, -1);
    for (Index c = 0; c < n; ++c)
        for (Index p = A.outerIndexPtr()[c]; p < A.outerIndexPtr()[c + 1]; ++p) {
            const Index r = A.innerIndexPtr()[p];
            QS_CHECK(r >= c - 1 && r <= c + 1, "TridiagonalCholesky: entry (" << r << ", " << c
                                                                              << ") lies off the three diagonals");
            if (r == c) diagonal_[c] = p;
        }
    for (Index c = 0; c < n; ++c)
        QS_CHECK(diagonal_[c] >= 0, "TridiagonalCholesky: column " << c << " has no diagonal entry");
    d_.resize(n);
    e_.resize(std::max<Index>(n - 1, 0));
    rows_ = n;
    nonZeros_ = A.nonZeros();
}

bool TridiagonalCholesky::factorize(const Matrix& A) {
    QS_CHECK(A.rows() == rows_ && A.nonZeros() == nonZeros_,
             "TridiagonalCholesky::factorize: a matrix of " << A.rows() << " rows and " << A.nonZeros()
                                                            << " entries, analysed with " << rows_ << " and " << nonZeros_);
    const double* value = A.valuePtr();
    const int* row = A.innerIndexPtr();
    for (Index c = 0; c < rows_; ++c) {
        const Index p = diagonal_[c];
        d_[c] = value[p];
        // the entry below the diagonal, (c + 1, c), follows it in the column when it is stored
        if (c + 1 < rows_) e_[c] = (p + 1 < A.outerIndexPtr()[c + 1] && row[p + 1] == c + 1) ? value[p + 1] : 0.0;
    }
    const int n = static_cast<int>(rows_);
    int info = 0;
    if (n > 0) dpttrf_(&n, d_.data(), e_.data(), &info);
    // dpttrf stops at a pivot d <= 0, which a NaN passes; an infinite one would solve to 0
    return info == 0 && (d_.array() > 0).all() && d_.allFinite() && e_.allFinite();
}

void TridiagonalCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    QS_CHECK(b.size() == rows_, "TridiagonalCholesky::solve: a right-hand side of " << b.size() << " rows, the matrix has "
                                                                                   << rows_);
    if (&b != &x) x = b;  // no allocation when x has the size already
    const int n = static_cast<int>(rows_), one = 1, ldb = std::max(n, 1);
    int info = 0;
    if (n > 0) dpttrs_(&n, &one, d_.data(), e_.data(), x.data(), &ldb, &info);
    QS_CHECK(info == 0, "TridiagonalCholesky::solve: dpttrs refused argument " << -info);
}

}  // namespace qs
