#include "solver/PressureSystem.hpp"

#include <algorithm>

#include "core/ForAll.hpp"

namespace qs {

template <int D>
void PressureSystem::build(const Grid<D>& grid, PressureSolver solver) {
    const Index nc = grid.numCells();
    // docs/performance.md, "The pressure solve alone": in 1D and 2D the sparse Cholesky is 3 to 6
    // times faster than CG up to 1e5 cells; in 3D its fill grows as n^(4/3), and from 1e4 cells
    // CG is 5 times faster
    const bool directFits = D < 3 || nc <= kDirectCellLimit3D;
    direct_ = solver == PressureSolver::Direct || (solver == PressureSolver::Automatic && directFits);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(nc) * (D == 1 ? 3 : D == 2 ? 9 : 27));
    for (Index c = 0; c < nc; ++c) {
        const IVec<D> cc = grid.cellCoords(c);
        for (int k = 0; k < (D == 1 ? 3 : D == 2 ? 9 : 27); ++k) {
            IVec<D> n;
            bool inside = true;
            int code = k;
            for (int d = 0; d < D; ++d) {
                n[d] = cc[d] + code % 3 - 1;
                code /= 3;
                if (n[d] < 0 || n[d] >= grid.cells(d)) inside = false;
            }
            if (inside) entries.emplace_back(static_cast<int>(grid.cellIndex(n)), static_cast<int>(c), 0.0);
        }
    }
    A_.resize(nc, nc);
    A_.setFromTriplets(entries.begin(), entries.end());
    A_.makeCompressed();
    analysed_ = false;
    tridiagonal_ = direct_ && D == 1;
    if (tridiagonal_) {
        tridiagonalLdlt_.analyse(A_);
    } else if (direct_) {
        // the slabs across the longest axis (a column's height)
        int axis = 0;
        for (int d = 1; d < D; ++d)
            if (grid.cells(d) >= grid.cells(axis)) axis = d;
        std::vector<int> layer(nc);
        for (Index c = 0; c < nc; ++c) layer[c] = static_cast<int>(grid.cellCoords(c)[axis]);
        const bool split = D == 2 && nc >= kMinParallelItems;
        ldlt_.analyse(A_, layer, static_cast<int>(grid.cells(axis)), split ? kSlabs : 1);
    }
    // the neighbours' places, in the order the triplets above came: within a column Eigen sorts
    // the rows, which is the order of the offsets' codes (axis 0 fastest in both)
    stencil_ = D == 1 ? 3 : D == 2 ? 9 : 27;
    slots_.assign(static_cast<std::size_t>(nc) * stencil_, -1);
    for (Index c = 0; c < nc; ++c) {
        const IVec<D> cc = grid.cellCoords(c);
        const int* r = rows(c);
        for (Index k = 0; k < size(c); ++k) {
            const IVec<D> rc = grid.cellCoords(r[k]);
            int offset[D];
            for (int d = 0; d < D; ++d) offset[d] = static_cast<int>(rc[d] - cc[d]);
            slots_[c * stencil_ + offsetCode(offset, D)] = static_cast<signed char>(k);
        }
    }
}

bool PressureSystem::factorize() {
    if (tridiagonal_) return tridiagonalLdlt_.factorize(A_);  // false if a pivot is at or below zero
    if (direct_) return ldlt_.factorize(A_);
    // the preconditioner's ordering once, its incomplete factorisation each step
    cg_.setTolerance(kTolerance);
    if (!analysed_) { cg_.analyzePattern(A_); analysed_ = true; }
    cg_.factorize(A_);
    return cg_.info() == Eigen::Success;
}

bool PressureSystem::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    if (direct_) {
        if (tridiagonal_) tridiagonalLdlt_.solve(b, x);
        else ldlt_.solve(b, x);
        iterations_ = 0;
        return x.allFinite();
    }
    x = cg_.solveWithGuess(b, x);
    iterations_ = static_cast<int>(cg_.iterations());
    error_ = cg_.error();
    return cg_.info() == Eigen::Success && x.allFinite();
}

const char* PressureSystem::solverName() const {
    if (tridiagonal_) return "tridiagonal Cholesky (LAPACK dpttrf)";
    if (!direct_) return "conjugate gradients, incomplete Cholesky (Eigen)";
    return slabs() == 1 ? "sparse Cholesky (Eigen SimplicialLDLT)"
                        : "sparse Cholesky (Eigen SimplicialLDLT), slabs side by side";
}

template void PressureSystem::build<1>(const Grid<1>&, PressureSolver);
template void PressureSystem::build<2>(const Grid<2>&, PressureSolver);
template void PressureSystem::build<3>(const Grid<3>&, PressureSolver);

}  // namespace qs
