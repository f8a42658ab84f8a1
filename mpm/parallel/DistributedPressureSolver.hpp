#pragma once
// DistributedPressureSolver: a symmetric positive definite system whose rows are spread over the
// ranks, solved by conjugate gradients preconditioned with one BoomerAMG V-cycle (hypre,
// Debian's libhypre-dev, on the run's MPI ranks). For the semi-implicit step's cell pressure
// over ranks (issue 41); one rank keeps PressureSystem's own solvers (docs/performance.md, "The
// pressure solve alone": BoomerAMG pays on one rank only in 2D beyond about 3e4 cells).
//
//   CellNumbering<2> numbering(decomposition);       // each rank's cells, contiguous rows
//   DistributedPressureSolver solver(world, numbering.firstRow(r), numbering.firstRow(r + 1), 2);
//   solver.setMatrix(start, columns, values);        // this rank's rows, CSR, global columns
//   int iterations = solver.solve(b, x, 1e-10);      // x holds the guess, then the solution
//
// Built where hypre and MPI are found (distributedSolverAvailable()); elsewhere constructing one
// throws, saying what the build lacks.
#include <memory>
#include <vector>

#include "core/Types.hpp"
#include "parallel/Communicator.hpp"

namespace qs {

/// Whether this build has hypre (and MPI) for the distributed solve.
bool distributedSolverAvailable();

class DistributedPressureSolver {
public:
    /// This rank's rows are [firstRow, endRow) of the global system; dimension sets BoomerAMG's
    /// strength threshold (0.25 in 2D, 0.5 in 3D: hypre's advice for Poisson-like systems).
    DistributedPressureSolver(const Communicator& comm, Index firstRow, Index endRow, int dimension);
    ~DistributedPressureSolver();
    DistributedPressureSolver(const DistributedPressureSolver&) = delete;
    DistributedPressureSolver& operator=(const DistributedPressureSolver&) = delete;

    /// This rank's rows in compressed sparse rows: row firstRow + i holds the entries
    /// [start[i], start[i + 1]) of columns (global rows) and values. The preconditioner is
    /// rebuilt for it.
    void setMatrix(const std::vector<Index>& start, const std::vector<Index>& columns, const std::vector<double>& values);
    /// The next solve builds the AMG hierarchy anew for the matrix's values (as it does by itself
    /// when CG slows): after a change that alters the matrix much (the semi-implicit step's held
    /// cells), and at a checkpoint, so that a resumed run builds where the run it continues did.
    void rebuildPreconditioner();
    /// Solves A x = b for this rank's rows, from x as the first guess, to a relative residual of
    /// `tolerance` (two-norm); returns CG's iterations. A kept hierarchy that fails is built anew
    /// and the solve tried once more. Throws qs::SharedError (alike on every rank) if it does not
    /// get there.
    int solve(const std::vector<double>& b, std::vector<double>& x, double tolerance);

    struct Hypre;  ///< hypre's objects (DistributedPressureSolver.cpp; opaque here)

private:
    std::unique_ptr<Hypre> hypre_;
};

}  // namespace qs
