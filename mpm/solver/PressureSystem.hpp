#pragma once
// PressureSystem: the semi-implicit step's linear system on the grid's cells,
//   (S + dt^2 D B D^T) dp = b,
// a symmetric positive definite matrix with one row per cell and the 3^D cells around it as its
// pattern (SemiImplicitIntegrator.cpp assembles it). The pattern is the whole grid's and fixed for
// the run: cells without water, or held at a known increment, keep their place as a row of the
// identity, so the symbolic work (the ordering, the fill of the factor) is done once, and each step
// writes values into the same arrays and factorises anew.
//
// The solvers are Eigen's (no hand-written linear algebra):
//   - Direct: SimplicialLDLT, a sparse Cholesky factorisation with an AMD ordering. The matrix
//     changes little from one step to the next (the points move a fraction of a cell), so a
//     factorisation is kept over steps as the preconditioner of CG on each later step's own
//     matrix (EarlierFactorisation), started from the caller's guess and taken to
//     kLaggedTolerance: a few triangular solves instead of a factorisation. It is made anew when
//     CG took more than kRefactorAbove iterations, at once when CG does not converge in
//     kLaggedIterations (that solve is then the direct one). The checkpoint keeps the values of
//     the matrix it was made of (factoredValues), and a resumed run factorises those again: the
//     same factorisation, so the same steps as the run that wrote it;
//   - ConjugateGradient: CG with an incomplete-Cholesky preconditioner (IncompleteCholesky),
//     started from the caller's guess (the semi-implicit step passes its last solution).
// docs/performance.md, "The pressure solve alone", measures both; PressureSolver::Automatic
// takes the direct one in 1D and 2D, and in 3D up to kDirectCellLimit3D cells, CG beyond.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "io/CaseConfig.hpp"

namespace qs {

class PressureSystem {
    using Matrix = Eigen::SparseMatrix<double>;  // column-major: Eigen's sparse solvers' own layout
    using Factor = Eigen::SimplicialLDLT<Matrix>;

public:
    /// CG's preconditioner for the direct solver's later steps: the LDL^T factorisation of an
    /// earlier step's matrix (Eigen's preconditioner interface; compute does nothing, the
    /// factorisation is PressureSystem's).
    class EarlierFactorisation {
    public:
        template <class M> EarlierFactorisation& analyzePattern(const M&) { return *this; }
        template <class M> EarlierFactorisation& factorize(const M&) { return *this; }
        template <class M> EarlierFactorisation& compute(const M&) { return *this; }
        template <class Rhs>
        Eigen::Solve<Factor, Rhs> solve(const Eigen::MatrixBase<Rhs>& b) const { return factor_->solve(b); }
        Eigen::ComputationInfo info() const { return Eigen::Success; }
        void use(const Factor* factor) { factor_ = factor; }

    private:
        const Factor* factor_ = nullptr;
    };

    /// 3D cells up to which Automatic takes the direct solver (the two are even at 1e3 cells).
    static constexpr Index kDirectCellLimit3D = 2000;
    /// CG's tolerance on |b - A x| / |b| (incomplete Cholesky).
    static constexpr Real kTolerance = 1e-10;
    /// The same, for CG with an earlier step's factorisation (Direct)
    static constexpr Real kLaggedTolerance = 1e-8;
    /// Direct: CG iterations with an earlier factorisation past which the next step factorises
    /// anew, and past which a solve gives up on it and factorises at once.
    static constexpr int kRefactorAbove = 3;
    static constexpr int kLaggedIterations = 10;

    /// The pattern: each cell and its in-grid neighbours across faces, edges and corners.
    template <int D>
    void build(const Grid<D>& grid, PressureSolver solver);

    /// The values of cell c's column (its row: the matrix is symmetric), in the order of rows(c).
    Real* values(Index c) { return A_.valuePtr() + A_.outerIndexPtr()[c]; }
    const int* rows(Index c) const { return A_.innerIndexPtr() + A_.outerIndexPtr()[c]; }
    Index size(Index c) const { return A_.outerIndexPtr()[c + 1] - A_.outerIndexPtr()[c]; }
    /// Where in column c the row of the cell at offset o from c sits, o in {-1, 0, 1}^D coded as
    /// sum_d (o_d + 1) 3^d.
    int slot(Index c, int offsetCode) const { return slots_[c * stencil_ + offsetCode]; }
    static int offsetCode(const int* offset, int D) {
        int code = 0;
        for (int d = D - 1; d >= 0; --d) code = code * 3 + offset[d] + 1;
        return code;
    }

    /// Prepares the values written for solve: factorises them (Direct, when the kept
    /// factorisation no longer serves) or preconditions them (CG). False if a factorisation fails
    /// (Direct: a pivot at or below zero).
    bool factorize();
    /// x = A^-1 b with the last factorisation; false if the solver fails or does not reach its
    /// tolerance. CG starts from x as it comes in (the caller's guess: the last step's solution,
    /// or zeros); a fresh factorisation does not read it.
    bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
    /// Direct: the values of the matrix the kept factorisation was made of (empty before the
    /// first, and for CG), for the checkpoint.
    const std::vector<double>& factoredValues() const { return factored_; }
    /// Direct: the next factorize() makes the kept factorisation of these values (a checkpoint's
    /// factoredValues), and serves the step's own matrix with it. False if they do not fit the
    /// pattern.
    bool restoreFactorisation(const std::vector<double>& values);
    Index nonZeros() const { return static_cast<Index>(A_.nonZeros()); }

    bool direct() const { return direct_; }
    int iterations() const { return iterations_; }   ///< CG's last (Direct: 0 after a fresh factorisation)
    long factorisations() const { return factorisations_; }  ///< Direct: how many, over the run
    Real error() const { return error_; }            ///< CG's last relative residual
    Index cells() const { return static_cast<Index>(A_.rows()); }

private:
    bool factorizeNow();

    Matrix A_;
    Factor ldlt_;
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, EarlierFactorisation> lagged_;
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> cg_;
    std::vector<signed char> slots_;  ///< [cell][3^D] place of each neighbour in the cell's column, -1 outside
    int stencil_ = 0;
    bool direct_ = true, analysed_ = false;
    bool refactor_ = true;          ///< Direct: the next factorize() factorises anew
    std::vector<double> factored_;  ///< Direct: the values the kept factorisation was made of
    std::vector<double> restored_;  ///< Direct: a checkpoint's factored_, to factorise next
    bool fresh_ = false;            ///< Direct: ldlt_ is this matrix's own factorisation
    int iterations_ = 0;
    Real error_ = 0;
    long factorisations_ = 0;
};

}  // namespace qs
