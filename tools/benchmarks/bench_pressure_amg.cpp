// The pressure solve with hypre's algebraic multigrid (Debian's libhypre-dev), against Eigen's
// solvers in bench_pressure.cpp on the same system (SandSystem.hpp): conjugate gradients
// preconditioned by one BoomerAMG V-cycle, to the same relative residual (PressureSystem's
// kTolerance). Built only where hypre is found; the step itself does not use it (docs/
// performance.md, "The pressure solve alone", says why).
//
//   build/tools/benchmarks/quicksand_benchmarks --benchmark_filter=BM_PressureAMG
// BM_PressureAMG2D/<cells per axis>/<setup>, BM_PressureAMG3D/...:
//   setup 1: each iteration copies the values into hypre's matrix, builds the AMG hierarchy and
//            solves, what a step whose matrix changes would do;
//   setup 0: the hierarchy is built once and only the solve is timed (the bound for a
//            preconditioner kept over several steps).
// Counters: cells, iterations. One MPI rank (the benchmarks' main initialises MPI).
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>

#include <vector>

#include "SandSystem.hpp"

namespace {

/// hypre's objects for one system of n rows on one rank, freed on scope exit.
class AmgSystem {
public:
    explicit AmgSystem(HYPRE_Int n) : n_(n) {
        HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &A_);
        HYPRE_IJMatrixSetObjectType(A_, HYPRE_PARCSR);
        for (HYPRE_IJVector* v : {&b_, &x_}) {
            HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v);
            HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
        }
        rows_.resize(n);
        for (HYPRE_Int i = 0; i < n; ++i) rows_[i] = i;
    }
    ~AmgSystem() {
        if (pcg_) HYPRE_ParCSRPCGDestroy(pcg_);
        if (amg_) HYPRE_BoomerAMGDestroy(amg_);
        HYPRE_IJVectorDestroy(x_);
        HYPRE_IJVectorDestroy(b_);
        HYPRE_IJMatrixDestroy(A_);
    }
    AmgSystem(const AmgSystem&) = delete;
    AmgSystem& operator=(const AmgSystem&) = delete;

    /// Copies PressureSystem's values (its columns are its rows: the matrix is symmetric) and b.
    void load(qs::PressureSystem& system, const Eigen::VectorXd& b) {
        HYPRE_IJMatrixInitialize(A_);
        for (HYPRE_Int c = 0; c < n_; ++c) {
            HYPRE_Int row = c, count = static_cast<HYPRE_Int>(system.size(c));
            cols_.assign(system.rows(c), system.rows(c) + count);
            HYPRE_IJMatrixSetValues(A_, 1, &count, &row, cols_.data(), system.values(c));
        }
        HYPRE_IJMatrixAssemble(A_);
        HYPRE_IJMatrixGetObject(A_, reinterpret_cast<void**>(&parA_));
        zero_.assign(n_, 0.0);
        HYPRE_IJVectorInitialize(b_);
        HYPRE_IJVectorSetValues(b_, n_, rows_.data(), b.data());
        HYPRE_IJVectorAssemble(b_);
        HYPRE_IJVectorGetObject(b_, reinterpret_cast<void**>(&parB_));
        HYPRE_IJVectorInitialize(x_);
        HYPRE_IJVectorSetValues(x_, n_, rows_.data(), zero_.data());
        HYPRE_IJVectorAssemble(x_);
        HYPRE_IJVectorGetObject(x_, reinterpret_cast<void**>(&parX_));
    }

    /// A fresh CG + BoomerAMG for the loaded matrix: hypre's settings for 2D/3D Poisson-like
    /// systems (HMIS coarsening, extended+i interpolation truncated to 4, hybrid symmetric
    /// Gauss-Seidel, one V-cycle per CG iteration).
    void setup(int dimension) {
        if (pcg_) HYPRE_ParCSRPCGDestroy(pcg_);
        if (amg_) HYPRE_BoomerAMGDestroy(amg_);
        HYPRE_BoomerAMGCreate(&amg_);
        HYPRE_BoomerAMGSetCoarsenType(amg_, 10);
        HYPRE_BoomerAMGSetInterpType(amg_, 6);
        HYPRE_BoomerAMGSetPMaxElmts(amg_, 4);
        HYPRE_BoomerAMGSetStrongThreshold(amg_, dimension == 3 ? 0.5 : 0.25);
        HYPRE_BoomerAMGSetRelaxType(amg_, 6);
        HYPRE_BoomerAMGSetNumSweeps(amg_, 1);
        HYPRE_BoomerAMGSetTol(amg_, 0.0);
        HYPRE_BoomerAMGSetMaxIter(amg_, 1);
        HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
        HYPRE_ParCSRPCGCreate(MPI_COMM_WORLD, &pcg_);
        HYPRE_PCGSetTol(pcg_, qs::PressureSystem::kTolerance);
        HYPRE_PCGSetMaxIter(pcg_, 1000);
        HYPRE_PCGSetTwoNorm(pcg_, 1);
        HYPRE_PCGSetPrintLevel(pcg_, 0);
        HYPRE_PCGSetPrecond(pcg_, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                            reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg_);
        HYPRE_ParCSRPCGSetup(pcg_, parA_, parB_, parX_);
    }

    /// Solves from x = 0; false if CG did not reach its tolerance.
    bool solve() {
        HYPRE_ParVectorSetConstantValues(parX_, 0.0);
        HYPRE_ParCSRPCGSolve(pcg_, parA_, parB_, parX_);
        HYPRE_Int converged = 0;
        HYPRE_PCGGetConverged(pcg_, &converged);
        HYPRE_ClearAllErrors();
        return converged != 0;
    }
    int iterations() const {
        HYPRE_Int k = 0;
        HYPRE_PCGGetNumIterations(pcg_, &k);
        return static_cast<int>(k);
    }

private:
    HYPRE_Int n_;
    HYPRE_IJMatrix A_ = nullptr;
    HYPRE_IJVector b_ = nullptr, x_ = nullptr;
    HYPRE_ParCSRMatrix parA_ = nullptr;
    HYPRE_ParVector parB_ = nullptr, parX_ = nullptr;
    HYPRE_Solver amg_ = nullptr, pcg_ = nullptr;
    std::vector<HYPRE_Int> rows_, cols_;
    std::vector<double> zero_;
};

template <int D>
void BM_PressureAMG(benchmark::State& state) {
    qs::bench::SandSquare<D> square(state.range(0), qs::PressureSolver::ConjugateGradient);
    const qs::Grid<D>& grid = square.grid;
    AmgSystem amg(static_cast<HYPRE_Int>(grid.numCells()));
    const bool everyStep = state.range(1) == 1;
    amg.load(square.system, square.b);
    amg.setup(D);
    for (auto _ : state) {
        if (everyStep) {
            amg.load(square.system, square.b);
            amg.setup(D);
        }
        if (!amg.solve()) state.SkipWithError("CG with BoomerAMG did not reach its tolerance");
    }
    state.counters["cells"] = static_cast<double>(grid.numCells());
    state.counters["iterations"] = amg.iterations();
    state.SetItemsProcessed(state.iterations() * grid.numCells());
}

}  // namespace

// the sizes of BM_Pressure2D/3D, and 1e6 cells, where Eigen's solvers are out of reach
BENCHMARK_TEMPLATE(BM_PressureAMG, 2)->Name("BM_PressureAMG2D")
    ->ArgsProduct({{32, 100, 316, 1000}, {1, 0}})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_PressureAMG, 3)->Name("BM_PressureAMG3D")
    ->ArgsProduct({{10, 22, 46, 100}, {1, 0}})->Unit(benchmark::kMillisecond);
