#include "parallel/DistributedPressureSolver.hpp"

#include <sstream>

#include <algorithm>
#include <string>

#include "core/Error.hpp"

#ifdef QUICKSAND_HAVE_HYPRE
#include <mpi.h>

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#endif

namespace qs {

#ifdef QUICKSAND_HAVE_HYPRE

bool distributedSolverAvailable() { return true; }

namespace {
/// hypre is initialised once per process, on first use (after MPI), and never finalised: its
/// objects are freed by their owners, and MPI_Finalize ends the rest.
void initialiseHypre() {
    static const bool done = [] {
        HYPRE_Init();
        return true;
    }();
    (void)done;
}
}  // namespace

struct DistributedPressureSolver::Hypre {
    HYPRE_BigInt first = 0, last = -1;  ///< this rank's rows [first, last]
    int dimension = 2;
    HYPRE_IJMatrix A = nullptr;
    HYPRE_IJVector b = nullptr, x = nullptr;
    HYPRE_ParCSRMatrix parA = nullptr;
    HYPRE_ParVector parB = nullptr, parX = nullptr;
    HYPRE_Solver amg = nullptr, pcg = nullptr;
    std::vector<HYPRE_BigInt> rows, cols;
    std::vector<HYPRE_Int> counts;
    bool setUp = false;  ///< the AMG hierarchy fit for the values (built for them, or kept)
    bool built = false;  ///< the solver objects hold a hierarchy (createSolvers makes them empty)
    int setUpIterations = 0;  ///< CG's iterations on the first solve after the hierarchy was built
    int lastIterations = 0;
    std::vector<double> guess;  ///< the caller's first guess, kept for a second attempt

    void freeSolvers() {
        if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
        if (amg) HYPRE_BoomerAMGDestroy(amg);
        pcg = amg = nullptr;
    }
    ~Hypre() {
        freeSolvers();
        if (x) HYPRE_IJVectorDestroy(x);
        if (b) HYPRE_IJVectorDestroy(b);
        if (A) HYPRE_IJMatrixDestroy(A);
    }
};

DistributedPressureSolver::DistributedPressureSolver(const Communicator& comm, Index firstRow, Index endRow,
                                                     int dimension)
    : hypre_(std::make_unique<Hypre>()) {
    (void)comm;  // hypre works on MPI_COMM_WORLD, the Communicator's ranks
    int initialized = 0;
    MPI_Initialized(&initialized);
    QS_CHECK(initialized, "the distributed pressure solve needs MPI initialised (quicksand's MpiSession)");
    initialiseHypre();
    Hypre& h = *hypre_;
    h.first = static_cast<HYPRE_BigInt>(firstRow);
    h.last = static_cast<HYPRE_BigInt>(endRow) - 1;
    h.dimension = dimension;
    h.rows.resize(static_cast<std::size_t>(endRow - firstRow));
    for (std::size_t i = 0; i < h.rows.size(); ++i) h.rows[i] = h.first + static_cast<HYPRE_BigInt>(i);
    for (HYPRE_IJVector* v : {&h.b, &h.x}) {
        HYPRE_IJVectorCreate(MPI_COMM_WORLD, h.first, h.last, v);
        HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
    }
}

DistributedPressureSolver::~DistributedPressureSolver() = default;


namespace {
/// CG with one BoomerAMG V-cycle a step: hypre's settings for 2D/3D Poisson-like systems, as the
/// one-rank benchmark (tools/benchmarks/bench_pressure_amg.cpp).
void createSolvers(DistributedPressureSolver::Hypre& h) {
    h.built = false;
    HYPRE_BoomerAMGCreate(&h.amg);
    HYPRE_BoomerAMGSetCoarsenType(h.amg, 10);
    HYPRE_BoomerAMGSetInterpType(h.amg, 6);
    HYPRE_BoomerAMGSetPMaxElmts(h.amg, 4);
    HYPRE_BoomerAMGSetStrongThreshold(h.amg, h.dimension == 3 ? 0.5 : 0.25);
    HYPRE_BoomerAMGSetRelaxType(h.amg, 6);
    HYPRE_BoomerAMGSetNumSweeps(h.amg, 1);
    HYPRE_BoomerAMGSetTol(h.amg, 0.0);
    HYPRE_BoomerAMGSetMaxIter(h.amg, 1);
    HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
    HYPRE_ParCSRPCGCreate(MPI_COMM_WORLD, &h.pcg);
    HYPRE_PCGSetMaxIter(h.pcg, 1000);
    HYPRE_PCGSetTwoNorm(h.pcg, 1);
    HYPRE_PCGSetPrintLevel(h.pcg, 0);
    HYPRE_PCGSetPrecond(h.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), h.amg);
}
}  // namespace

void DistributedPressureSolver::setMatrix(const std::vector<Index>& start, const std::vector<Index>& columns,
                                          const std::vector<double>& values) {
    Hypre& h = *hypre_;
    const std::size_t n = h.rows.size();
    QS_CHECK(start.size() == n + 1 && columns.size() == values.size() &&
                 static_cast<std::size_t>(start.back()) == values.size(),
             "DistributedPressureSolver::setMatrix: " << start.size() << " row starts for " << n << " rows, "
                                                      << columns.size() << " columns, " << values.size() << " values");
    // The same pattern (a time step's new values): written into the matrix in place, and the
    // AMG hierarchy of earlier values kept as CG's preconditioner while it still works (its fine
    // level smooths with the new values; the coarse levels are a step or more old). It is built
    // anew when CG needs half as many iterations again as right after the last build (and two
    // more): the build is most of a solve's cost (docs/performance.md, "The semi-implicit step on
    // ranks"). Deterministic: the same values give the same builds on every run.
    bool samePattern = h.A && h.counts.size() == n && std::equal(columns.begin(), columns.end(), h.cols.begin(), h.cols.end());
    for (std::size_t i = 0; samePattern && i < n; ++i)
        samePattern = h.counts[i] == static_cast<HYPRE_Int>(start[i + 1] - start[i]);
    // the in-place update and the new matrix are each collective: every rank takes the same one
    const bool samePatternOnSomeRank = Communicator::world().any(samePattern);
    samePattern = !Communicator::world().any(!samePattern);
    if (samePattern) {
        HYPRE_IJMatrixInitialize(h.A);
        HYPRE_IJMatrixSetValues(h.A, static_cast<HYPRE_Int>(n), h.counts.data(), h.rows.data(), h.cols.data(), values.data());
        HYPRE_IJMatrixAssemble(h.A);
        HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&h.parA));
        if (h.setUp && h.lastIterations > (3 * h.setUpIterations) / 2 + 2) h.setUp = false;
        return;
    }
    QS_CHECK(!samePatternOnSomeRank, "DistributedPressureSolver::setMatrix: the matrix's pattern changed on some "
                                     "ranks and not on others");
    h.freeSolvers();
    if (h.A) HYPRE_IJMatrixDestroy(h.A);  // a new pattern: a new matrix
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, h.first, h.last, h.first, h.last, &h.A);
    HYPRE_IJMatrixSetObjectType(h.A, HYPRE_PARCSR);
    HYPRE_IJMatrixInitialize(h.A);
    h.counts.resize(n);
    h.cols.assign(columns.begin(), columns.end());
    for (std::size_t i = 0; i < n; ++i) h.counts[i] = static_cast<HYPRE_Int>(start[i + 1] - start[i]);
    HYPRE_IJMatrixSetValues(h.A, static_cast<HYPRE_Int>(n), h.counts.data(), h.rows.data(), h.cols.data(), values.data());
    HYPRE_IJMatrixAssemble(h.A);
    HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&h.parA));

    createSolvers(h);
    h.setUp = false;  // the hierarchy is built with the first right-hand side
}

void DistributedPressureSolver::rebuildPreconditioner() { hypre_->setUp = false; }

int DistributedPressureSolver::solve(const std::vector<double>& b, std::vector<double>& x, double tolerance) {
    Hypre& h = *hypre_;
    const std::size_t n = h.rows.size();
    QS_CHECK(h.A, "DistributedPressureSolver::solve before setMatrix");
    QS_CHECK(b.size() == n && x.size() == n,
             "DistributedPressureSolver::solve: " << b.size() << " and " << x.size() << " values for " << n << " rows");
    // b = 0: x = 0 exactly (hypre's PCG would stop at once and say it had not converged)
    double bb = 0;
    for (double v : b) bb += v * v;
    if (Communicator::world().sum(bb) == 0) {
        std::fill(x.begin(), x.end(), 0.0);
        return 0;
    }
    h.guess.assign(x.begin(), x.end());
    HYPRE_Int converged = 0, iterations = 0;
    HYPRE_Real residual = 0;
    for (;;) {
        HYPRE_IJVectorInitialize(h.b);
        HYPRE_IJVectorSetValues(h.b, static_cast<HYPRE_Int>(n), h.rows.data(), b.data());
        HYPRE_IJVectorAssemble(h.b);
        HYPRE_IJVectorGetObject(h.b, reinterpret_cast<void**>(&h.parB));
        HYPRE_IJVectorInitialize(h.x);
        HYPRE_IJVectorSetValues(h.x, static_cast<HYPRE_Int>(n), h.rows.data(), h.guess.data());
        HYPRE_IJVectorAssemble(h.x);
        HYPRE_IJVectorGetObject(h.x, reinterpret_cast<void**>(&h.parX));
        const bool fresh = !h.setUp;
        if (fresh) {
            if (h.built) {  // a hierarchy of earlier values: new solver objects, built for these
                h.freeSolvers();
                createSolvers(h);
            }
            HYPRE_PCGSetTol(h.pcg, tolerance);
            HYPRE_ParCSRPCGSetup(h.pcg, h.parA, h.parB, h.parX);
            h.setUp = h.built = true;
        }
        HYPRE_PCGSetTol(h.pcg, tolerance);
        HYPRE_ParCSRPCGSolve(h.pcg, h.parA, h.parB, h.parX);
        HYPRE_PCGGetConverged(h.pcg, &converged);
        HYPRE_PCGGetNumIterations(h.pcg, &iterations);
        HYPRE_PCGGetFinalRelativeResidualNorm(h.pcg, &residual);
        h.lastIterations = static_cast<int>(iterations);
        if (fresh) h.setUpIterations = static_cast<int>(iterations);
        HYPRE_ClearAllErrors();
        // a guess that is already the solution stops CG before its first step, unconverged by
        // its flag and at a residual of zero. PCG's verdict is the same on every rank.
        if (converged || residual <= tolerance || fresh) break;
        h.setUp = false;  // a kept hierarchy that no longer fits the values: built anew, solved again
    }
    HYPRE_IJVectorGetValues(h.x, static_cast<HYPRE_Int>(n), h.rows.data(), x.data());
    if (!(converged || residual <= tolerance)) {
        std::ostringstream m;
        m << "the distributed pressure solve (CG with BoomerAMG) did not reach a relative residual of " << tolerance
          << " in " << iterations << " iterations (" << residual << ")";
        throw SharedError(m.str());  // every rank meets it alike: said once
    }
    return static_cast<int>(iterations);
}

#else  // no hypre

bool distributedSolverAvailable() { return false; }
struct DistributedPressureSolver::Hypre {};
DistributedPressureSolver::DistributedPressureSolver(const Communicator&, Index, Index, int) {
    throw Error("this build has no distributed pressure solve: it needs hypre and MPI (bash tools/setup.sh --mpi "
                "installs Open MPI; libhypre-dev comes with tools/setup.sh), then a fresh cmake");
}
DistributedPressureSolver::~DistributedPressureSolver() = default;
void DistributedPressureSolver::setMatrix(const std::vector<Index>&, const std::vector<Index>&,
                                          const std::vector<double>&) {}
void DistributedPressureSolver::rebuildPreconditioner() {}
int DistributedPressureSolver::solve(const std::vector<double>&, std::vector<double>&, double) { return 0; }

#endif

}  // namespace qs
