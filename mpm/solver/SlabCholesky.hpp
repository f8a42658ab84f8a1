#pragma once
// SlabCholesky: the sparse Cholesky factorisation of the cells' pressure system, split into slabs
// of cells along the grid's longest axis so that each slab is factorised on its own thread.
//
// Why: in 2D the direct solve is serial and was half of piping2D's step on two cores, the other
// core waiting (docs/performance.md, "The semi-implicit step"). No Debian library factorises a
// system of a few thousand cells faster in parallel than Eigen does serially (CHOLMOD's
// supernodal factorisation is 5 times slower at this size; MUMPS and SuperLU_DIST are MPI codes).
// So the factorisations stay Eigen's (SimplicialLDLT, one per slab, and a dense LLT); what this
// class adds is the textbook top level of a nested dissection (George 1973), a substructuring:
//
//   A single layer of cells across the axis separates two slabs: with the cells' 3^D stencil no
//   cell of one slab couples to a cell of the next. Ordered [slab 0, slab 1, ..., separators],
//       A = [A_kk  A_ks]       x_s = S^-1 (b_s - sum_k A_sk A_kk^-1 b_k),
//           [A_sk  A_ss],      x_k = A_kk^-1 (b_k - A_ks x_s),
//   with the separators' Schur complement S = A_ss - sum_k A_sk A_kk^-1 A_ks (dense: a layer of
//   cells, 26 of them for piping2D on 3.1 mm).
//
// Each slab factorises M_k = A restricted to its own cells and its one or two separators, the
// separators ordered last: M_k is a principal submatrix of A, so it is positive definite whenever
// A is, and its factor's trailing block is M_k's own Schur complement T_k = A_ss - A_sk A_kk^-1 A_ks
// (over its separators). A separator lies between two slabs, so S = sum_k T_k - A_ss (once per
// separator). The factor also gives A_sk A_kk^-1 b_k = -L_ss y_s, y = L^-1 [b_k; 0], and the
// back substitution of x_k from [D^-1 y_k; L_ss^T x_s].
//
// The number of slabs is the caller's and does not depend on the threads: one thread or two, the
// arithmetic is the same and so are the results, to the bit. One slab is the plain factorisation
// with Eigen's AMD ordering. The orderings and the separators' places are chosen once (analyse),
// each factorisation writes the same arrays. Nothing is allocated in the time loop up to Eigen's
// stack limits: a slab of up to 16 384 cells (Eigen's factorisation keeps three work arrays of
// its size on the stack below 128 kB) and a separator of up to about 128 cells (the dense
// products' and LLT's blocks); beyond, Eigen takes those from the heap.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "core/Types.hpp"

namespace qs {

class SlabCholesky {
public:
    using Matrix = Eigen::SparseMatrix<double>;

    /// Eigen's LLT() leaves its info unset, and moving or assigning the object reads it (UBSan):
    /// an empty factorisation sets it
    SlabCholesky() { schur_.compute(Eigen::MatrixXd(0, 0)); }

    /// A's pattern (symmetric, both triangles stored, column-major), each cell's layer along the
    /// axis to split, in [0, layers), and the number of slabs asked for (fewer if the axis is too
    /// short for each slab to keep kMinLayers layers of its own).
    void analyse(const Matrix& A, const std::vector<int>& layer, int layers, int slabs);
    /// Factorises A's current values; false if A is not positive definite.
    bool factorize(const Matrix& A);
    /// x = A^-1 b with the last factorisation (x is sized as b; b may be x).
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

    int slabs() const { return static_cast<int>(slabs_.size()); }
    /// The separators' cells, separator by separator (none for one slab).
    const std::vector<Index>& separatorCells() const { return separatorCells_; }
    /// Operations of the largest slab's factorisation (which decides the parallel time): the sum
    /// over its factor's columns of their count squared.
    double largestSlabOperations() const;

    /// Layers a slab keeps of its own at least.
    static constexpr int kMinLayers = 4;

private:
    /// Eigen's SimplicialLDLT factorising a matrix that is already in its order and upper
    /// triangle where it is: its factorize() would allocate an empty copy's index array each call.
    class InPlaceLDLT : public Eigen::SimplicialLDLT<Matrix, Eigen::Upper, Eigen::NaturalOrdering<int>> {
    public:
        void factorizeInPlace(const Matrix& M) { this->template factorize_preordered<true>(M); }
    };

    struct Slab {
        std::vector<Index> cells;   ///< the rows of M: its own cells (ordered), then its separators'
        Index own = 0;              ///< how many of cells are its own
        Index firstSeparator = 0;   ///< where its separator cells start in the joint separator numbering
        Matrix M;                   ///< M's upper triangle, in that order
        std::vector<Index> source;  ///< for each of M's stored values, its place in A's values
        /// M = L D L^T; held by pointer because Eigen's factorisations cannot be moved
        std::unique_ptr<InPlaceLDLT> factor;
        Eigen::MatrixXd Lss, LD;    ///< the factor's separator block (unit lower) and Lss D_ss
        Eigen::MatrixXd T;          ///< Lss D_ss Lss^T = T_k
        Eigen::VectorXd y;          ///< the slab's forward and back substitutions
        Eigen::VectorXd c;          ///< Lss y_s = -A_sk A_kk^-1 b_k, its part of the separators' right-hand side
        bool ok = false;
    };

    /// The slab of `own` cells and the separators' cells, own ordered the cheaper of two ways.
    static Slab makeSlab(const Matrix& A, const std::vector<Index>& own, const std::vector<Index>& separators,
                         const std::vector<Index>& globalRank);
    /// M's pattern for the slab's cells as ordered; returns the operations of its factorisation.
    static double buildPattern(Slab& slab, const Matrix& A);
    /// The sum over the slab's factor's columns of their count squared.
    static double operationsOf(const Slab& slab);
    static void factorizeSlab(Slab& slab, const Matrix& A);

    std::vector<Slab> slabs_;
    std::vector<Index> separatorCells_;  ///< all separators' cells, separator by separator
    struct Entry {
        Index row, col, source;
    };
    std::vector<Entry> separatorEntries_;  ///< A_ss's entries, (row, col) in the joint numbering
    Eigen::MatrixXd S_;
    Eigen::LLT<Eigen::MatrixXd> schur_;
    Eigen::VectorXd r_;
    Index rows_ = 0, nonZeros_ = 0;  ///< A's as analysed: factorize checks that it is given the same
};

}  // namespace qs
