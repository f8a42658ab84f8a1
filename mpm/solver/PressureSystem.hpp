#pragma once
// PressureSystem: the semi-implicit step's linear system on the grid's cells,
//   (S + dt^2 D B D^T) dp = b,
// a symmetric positive definite matrix with one row per cell and the 3^D cells around it as its
// pattern (SemiImplicitIntegrator.cpp assembles it). The pattern is the whole grid's and fixed for
// the run: cells without water, or held at a known increment, keep their place as a row of the
// identity, so the symbolic work (the ordering, the fill of the factor) is done once, and each step
// writes values into the same arrays and factorises anew.
//
// The solvers:
//   - Direct: in 1D the tridiagonal L D L^T of LAPACK (TridiagonalCholesky.hpp); in 2D and 3D
//     Eigen's SimplicialLDLT, a sparse Cholesky factorisation with an AMD ordering, in 2D from
//     kMinParallelItems cells split into kSlabs slabs, factorised side by side (SlabCholesky.hpp);
//   - ConjugateGradient: Eigen's CG with an incomplete-Cholesky preconditioner (IncompleteCholesky),
//     started from the caller's guess (the semi-implicit step passes its last solution).
// docs/performance.md, "The pressure solve alone", measures both; PressureSolver::Automatic
// takes the direct one in 1D and 2D, and in 3D up to kDirectCellLimit3D cells, CG beyond.
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

#include "core/Types.hpp"
#include "grid/Grid.hpp"
#include "case/CaseConfig.hpp"
#include "solver/SlabCholesky.hpp"
#include "solver/TridiagonalCholesky.hpp"

namespace qs {

class PressureSystem {
public:
    /// 3D cells up to which Automatic takes the direct solver (the two are even at 1e3 cells).
    static constexpr Index kDirectCellLimit3D = 2000;
    /// Slabs of the 2D direct solve: the project's machine's two cores. A fixed number, not the
    /// threads', so that one thread and two give the same results; more slabs add separators
    /// and fill (docs/performance.md, "The direct solve in slabs").
    static constexpr int kSlabs = 2;
    /// CG's tolerance on |b - A x| / |b|.
    static constexpr Real kTolerance = 1e-10;

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

    /// Factorises (Direct) or preconditions (CG) the values written. False if it fails.
    bool factorize();
    /// x = A^-1 b with the last factorisation; false if the solver fails or does not reach its
    /// tolerance. CG starts from x as it comes in (the caller's guess: the last step's solution,
    /// or zeros); the direct solver does not read it.
    bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

    bool direct() const { return direct_; }
    int iterations() const { return iterations_; }   ///< CG's last, 0 for Direct
    Real error() const { return error_; }            ///< CG's last relative residual
    Index cells() const { return static_cast<Index>(A_.rows()); }
    int slabs() const { return direct_ && !tridiagonal_ ? ldlt_.slabs() : 1; }
    /// The solver as the run's summary names it.
    const char* solverName() const;
    /// The matrix as assembled (cell order, both triangles): for the benchmarks and tests.
    const Eigen::SparseMatrix<double>& matrix() const { return A_; }

private:
    using Matrix = Eigen::SparseMatrix<double>;  // column-major: Eigen's sparse solvers' own layout
    Matrix A_;
    SlabCholesky ldlt_;
    TridiagonalCholesky tridiagonalLdlt_;
    /// The incomplete Cholesky in the cells' own order: AMD's order (Eigen's default, made to
    /// limit a complete factorisation's fill) took 61.4 CG iterations a solve on piping3D where
    /// the grid's order takes 42.1 (docs/performance.md, "The pressure solve alone")
    using Preconditioner = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>;
    Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Preconditioner> cg_;
    std::vector<signed char> slots_;  ///< [cell][3^D] place of each neighbour in the cell's column, -1 outside
    int stencil_ = 0;
    bool direct_ = true, tridiagonal_ = false, analysed_ = false;  ///< analysed_: CG's pattern (the direct one is analysed in build)
    int iterations_ = 0;
    Real error_ = 0;
};

}  // namespace qs
